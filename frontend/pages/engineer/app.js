// The engineer's page: reads the form, asks the API, shows what it answers.
// No engineering is computed here; see figures.js for how answers become charts,
// results.js for the result as DOM.

import { ApiError, createClient, encodePath } from "../../lib/api.js";
import { $, $$as, $as, h, notice } from "../../lib/dom.js";
import { appendSymbols, num, prepareNumbers, qty } from "../../lib/format.js";
import { LANGS, PLOTLY_LOCALES, applyStaticTexts, initialLang, rememberLang, translate, unitText } from "../../lib/i18n.js";
import { fieldRefusal, isNumberField, numberText, readField, showReading, showReadings } from "../../lib/numbers.js";
import { loadPlotly } from "../../lib/plotly.js";
import { MAX_COMPARED, compareStatusText, compareToggle, renderCompare, validMarks } from "./compare.js";
import { initProfile } from "./profile.js";
import { ratioVariables, renderRatioStudy } from "./ratio.js";
import { NARROW_CHART_PX, WARM_FIGURES, cycleCaption, diagramCaption, fitFigure } from "./figures.js";
import {
  LOAD_KINDS,
  TRANSMISSION_FIELDS,
  kindFieldset,
  kindSpec,
  quantityField,
  renderMechanisms,
  setTransmission,
} from "./mechanisms.js";
import {
  drawRemainingRows,
  MORE_ROWS,
  updateMoreRow,
  renderBinding,
  fillBelowCharts,
  fillDetail,
  renderDetail,
  renderLimits,
  renderPermalink,
  renderRanking,
  renderReports,
  renderSummary,
  resultSentence,
} from "./results.js";
import {
  fillSegments,
  initSegments,
  readSegments,
  segmentCount,
  setSegmentLang,
  setSegmentUnits,
} from "./segments.js";

/** The optional load on the output flange (schemas/output_load.py). */
const OUTPUT_LOAD_FIELDS = [
  { name: "radial_force_n", symbol: "F_r", unit: "N", key: "ol.radial_force", required: true },
  { name: "axial_force_n", symbol: "F_a", unit: "N", key: "ol.axial_force", required: true },
  { name: "radial_lever_m", symbol: "L_r", unit: "m", key: "ol.radial_lever", required: true },
  { name: "axial_lever_m", symbol: "L_a", unit: "m", key: "ol.axial_lever", required: true },
  { name: "load_factor", symbol: "f_w", unit: "–", key: "ol.load_factor" },
  { name: "static_safety_min", symbol: "f_s", unit: "–", key: "ol.static_safety" },
  { name: "required_life_h", symbol: "L_10", unit: "h", key: "ol.required_life" },
];
/**
 * The gear's own limits, checked when asked (schemas/selections/request.py, GearIn;
 * docs/decisions/0024): a blank field is not asked and not sent.
 */
const GEAR_FIELDS = [
  { name: "required_life_h", symbol: "L_h", unit: "h", key: "gear.required_life" },
  { name: "momentary_torque_nm", symbol: "T_M", unit: "Nm", key: "gear.momentary_torque" },
  { name: "momentary_count", symbol: "N_M", unit: "–", key: "gear.momentary_count" },
];
/** The holding brake's safety factor and emergency stops, sent with the brake ticked. */
const BRAKE_FIELDS = [
  { name: "brake_safety_factor", symbol: "S", unit: "–", key: "brake.safety_factor", placeholder: "1" },
  { name: "emergency_stops", symbol: "N_E", unit: "–", key: "brake.emergency_stops" },
];
/** Options of the request's top level, each a number sent when given; ``slot``: where it stands. */
const OPTION_FIELDS = [
  { name: "thermal_time_constant_s", symbol: "τ_th", unit: "s", key: "options.thermal_time_constant", slot: "#thermal-slot" },
  { name: "min_natural_frequency_hz", symbol: "f_n", unit: "Hz", key: "options.min_natural_frequency", slot: "#stiffness-slot" },
];
/** Table 516.1, the chapter's worked example. */
const EXAMPLE = {
  kind: "direct",
  "load.speed_rpm": 40,
  "load.torque_nm": 5,
  "load.inertia_kgm2": 1.3,
  "cycle.accel_s": 0.1,
  "cycle.constant_s": 0.1,
  "cycle.decel_s": 0.1,
  "cycle.pause_s": 1,
};

const state = {
  lang: "de",
  selection: null,
  chosen: null,
  filter: "all",
  /** models marked for the side-by-side comparison, in the order marked (at most four) */
  compare: [],
  /** the model whose mark was refused last (a fifth), for the status line */
  compareRefused: null,
  stale: false,
  busy: false,
  /** the last thing the results area should say when there is no selection */
  message: null,
  /** the ratio study of the request on the form: null | {status, asked, answer, error} */
  ratio: null,
};

const form = () => $("#selection-form");
/** The input ``selector`` names (a text field, a checkbox, a radio button), or null. */
const input = (selector) => $as(selector, HTMLInputElement);
/** The HTML element ``selector`` names (for its dataset, hidden, focus), or null. */
const html = (selector) => $as(selector, HTMLElement);
const t = (key, params) => translate(state.lang, key, params);

// ---------------------------------------------------------------- API

// The page's language travels as Accept-Language: the server's error messages come in it.
const api = createClient({ headers: () => ({ "Accept-Language": state.lang }) });

/** POST /api/v1/selections: run and store a selection; the answer lists the ranking's first
 * ``PAGE_TOP`` candidates, "show more" reads the rest page by page. */
const createSelection = (body) => api.post(`/selections?top=${PAGE_TOP}`, body);

/** Candidates the page asks a selection's answer to list: two screens of the ranking. */
const PAGE_TOP = 25;

/** GET /api/v1/selections/{id}/candidates: a page of a stored selection's ranking. */
const getCandidatePage = (id, cursor, limit) =>
  api.get(encodePath`/selections/${id}/candidates?cursor=${cursor}&limit=${String(limit)}`);

/** GET /api/v1/selections/{id}: a stored selection. */
const getSelection = (id) => api.get(encodePath`/selections/${id}`);

/** GET /api/v1/selections/{id}/request: the load case as it was asked (the checks asked for too). */
const getSelectionRequest = (id) => api.get(encodePath`/selections/${id}/request`);

/** GET /api/v1/selections/{id}/candidates/{model}: one candidate in full, with its catalogue data. */
const getCandidateDetail = (id, model) => api.get(encodePath`/selections/${id}/candidates/${model}`);

/**
 * GET …/candidates/{model}/diagram or …/cycle: the speed/torque diagram or the cycle chart
 * as plotly JSON in ``lang``, the figures the quote and the report print. ``flag``: the
 * diagram with the catalogue's limits (false where its record could not be read); the
 * cycle with the torque along each segment (false: the stored T_1…T_3, also after a
 * catalogue change).
 */
const getCandidateFigure = (kind, id, model, lang, flag) =>
  kind === "diagram"
    ? api.get(encodePath`/selections/${id}/candidates/${model}/diagram?lang=${lang}&catalogue=${String(flag)}`)
    : api.get(encodePath`/selections/${id}/candidates/${model}/cycle?lang=${lang}&torques=${String(flag)}`);

/** Figures asked for, by kind, selection, model, language and flag: a promise each. */
const figures = new Map();

/** The API's figure ("diagram" or "cycle"), asked once per selection, model, language and flag. */
function candidateFigure(kind, sel, model, lang, flag) {
  const key = JSON.stringify([kind, sel.id, model, lang, flag]);
  if (!figures.has(key)) {
    const pending = getCandidateFigure(kind, sel.id, model, lang, flag);
    pending.catch(() => figures.delete(key)); // a failure is asked again next time
    figures.set(key, pending);
  }
  return figures.get(key);
}

/** POST /api/v1/selections/ratio-study: the free value's intervals per actuator, with its chart in ``lang``. */
const createRatioStudy = (body, lang) => api.post(encodePath`/selections/ratio-study?figure=true&lang=${lang}`, body);

/** GET …/candidates/{model}/limits: the shortest pause and t_1, the largest J_L (inverse solve). */
const getCandidateLimits = (id, model) => api.get(encodePath`/selections/${id}/candidates/${model}/limits`);

/** Ask for the chosen candidate's limits and show them in its panel (once it still shows it). */
async function showLimits() {
  const sel = state.selection;
  const model = chosenCandidate()?.model;
  const slot = document.querySelector('#detail [data-slot="limits"]');
  if (!sel || !model || !slot) return;
  const still = () => sel === state.selection && html("#detail")?.dataset.model === model;
  slot.replaceChildren(renderLimits({ status: "loading" }, state.lang));
  let view;
  try {
    view = { status: "ready", limits: await getCandidateLimits(sel.id, model) };
  } catch (error) {
    view = { status: "failed", error };
  }
  if (still()) slot.replaceChildren(renderLimits(view, state.lang));
}

/**
 * Candidates' details asked for, by selection id and model, for the page's lifetime:
 * ``{status: "loading" | "ready" | "failed", detail, error, settled}``, ``settled`` a
 * promise of the detail or null.
 */
const details = new Map();

/** A failure that may pass: the server not reached, or an error of its own (5xx). */
function transient(error) {
  return !(error instanceof ApiError) || error.status === 0 || error.status >= 500 || error.kind !== "http";
}

/**
 * The detail of ``model`` in ``sel``: asked once, then remembered. ``retry`` asks again
 * after a failure that may pass (a 404 or 409 stays as it is).
 */
function candidateDetail(sel, model, { retry = false } = {}) {
  const key = JSON.stringify([sel.id, model]);
  const known = details.get(key);
  if (known && !(retry && known.status === "failed" && transient(known.error))) return known;
  const entry = { status: "loading", detail: null, error: null, settled: null };
  entry.settled = getCandidateDetail(sel.id, model)
    .then((detail) => {
      if (!Array.isArray(detail.checks) || detail.model !== model) {
        throw new ApiError({ status: 200, kind: "bad_response" });
      }
      entry.status = "ready";
      entry.detail = detail;
      return detail;
    })
    .catch((error) => {
      entry.status = "failed";
      entry.error = error;
      return null;
    })
    .then((detail) => {
      detailSettled(sel, model);
      return detail;
    });
  details.set(key, entry);
  return entry;
}

// ---------------------------------------------------------------- form

function loadKind() {
  const checked = input('input[name="load-kind"]:checked');
  return LOAD_KINDS.includes(checked?.value) ? checked.value : LOAD_KINDS[0];
}

function cycleMode() {
  return input('input[name="cycle-mode"]:checked')?.value === "segments" ? "segments" : "trapezoid";
}

/** Whether ``kind`` is a linear axis: speeds in mm/s, process loads in N. */
const isLinear = (kind) => Boolean(kindSpec(kind)?.linear);

/** The request field of the trapezoid's load speed for ``kind``: "speed_rpm" or "speed". */
const speedField = (kind) => kindSpec(kind)?.speed_field ?? "speed_rpm";

/** The speed field as the load kind asks for it: n_2 [rpm] (speed_rpm or speed) or v [mm/s]. */
function updateSpeedField(kind) {
  const speed = input("#f-speed");
  const linear = isLinear(kind);
  speed.dataset.path = `load.${speedField(kind)}`;
  const label = html("#speed-label");
  label.dataset.i18n = linear ? "load.speed.linear" : "load.speed";
  label.textContent = t(label.dataset.i18n);
  $("#speed-sym").replaceChildren(...(linear ? [h("var", {}, "v")] : [h("var", {}, "n"), h("sub", {}, "2")]));
  const unit = html("#u-speed");
  unit.dataset.unit = linear ? "mm/s" : "rpm";
  unit.textContent = unitText(state.lang, unit.dataset.unit);
  setSegmentUnits(
    linear
      ? { speed: "mm/s", accel: "mm/s²", load: "N" }
      : { speed: "rpm", accel: "rpm/s", load: "Nm" },
  );
}

function setLoadKind(kind) {
  kindFieldset(kind); // built when first chosen
  for (const radio of $$as('input[name="load-kind"]', HTMLInputElement)) {
    radio.checked = radio.value === kind;
  }
  for (const fs of $$as("fieldset.mechanism", HTMLFieldSetElement)) {
    const active = fs.dataset.kind === kind;
    fs.hidden = !active;
    fs.disabled = !active; // inactive fields are neither validated nor sent
  }
  updateSpeedField(kind);
}

/** t_1…t_p or segments; switching to segments with none yet starts from the t_1…t_p inputs. */
function setCycleMode(mode) {
  const prefill = mode === "segments" && segmentCount() === 0;
  const [t1, t2, t3, tp] = ["cycle.accel_s", "cycle.constant_s", "cycle.decel_s", "cycle.pause_s"].map(
    (path) => readNumber(path, { any: true }),
  );
  const n = readNumber("load.speed_rpm", { any: true }) ?? readNumber("load.speed", { any: true });
  for (const radio of $$as('input[name="cycle-mode"]', HTMLInputElement)) {
    radio.checked = radio.value === mode;
  }
  for (const fs of $$as("fieldset.cycle-form", HTMLFieldSetElement)) {
    const active = fs.dataset.mode === mode;
    fs.hidden = !active;
    fs.disabled = !active;
  }
  // segments give their own speeds: the load speed is left out of the request
  html("#speed-field").hidden = mode === "segments";
  input("#f-speed").disabled = mode === "segments";
  if (prefill) {
    // the chapter's four phases restated as segments: the same inputs, nothing computed
    fillSegments([
      { speed: n, duration_s: t1 },
      { duration_s: t2 },
      { speed: 0, duration_s: t3 },
      { duration_s: tp },
    ]);
  }
}

/**
 * The control for an API path among the active fields ("load.mass_kg" →
 * #f-rotary_table-mass_kg …): an input, or a group (fieldset) that stands for its fields.
 * @param {string} path
 * @param {{ any?: boolean }} [options] ``any``: among the inactive fields too
 * @returns {HTMLElement | null}
 */
function fieldFor(path, { any = false } = {}) {
  for (const el of $$as(`[data-path="${CSS.escape(path)}"]`, HTMLElement, form())) {
    if (any || !el.closest("fieldset[disabled]")) return el;
  }
  return null;
}

/**
 * The input for an API path among the active fields, or null (none, or a group).
 * @param {string} path
 * @param {{ any?: boolean }} [options]
 */
function inputFor(path, options) {
  const el = fieldFor(path, options);
  return el instanceof HTMLInputElement ? el : null;
}

/** A number field's number ("1,3" and "1.3" alike, lib/numbers.js); null when blank or refused. */
function readNumber(path, options) {
  const el = inputFor(path, options);
  return el && !el.disabled ? readField(el).value : null;
}

/**
 * A quantity as typed: a number ("0,5" read as 0.5), else the text for the API to read
 * with its unit ("0,5 in" sent as "0.5 in") or to refuse at the field; null when blank.
 */
function readQuantity(path) {
  const el = inputFor(path);
  if (!el) return null;
  const reading = readField(el);
  if (reading.state === "empty") return null;
  if (reading.state === "number") return reading.value;
  return el.dataset.number === "units" ? reading.decimal : null;
}

/**
 * The fields of ``specs`` under ``prefix`` ("" for the request's top level): required ones
 * always (null when blank), others when given.
 */
function readQuantities(prefix, specs) {
  const out = {};
  for (const spec of specs) {
    const value = readQuantity(prefix ? `${prefix}.${spec.name}` : spec.name);
    if (value !== null || spec.required) out[spec.name] = value;
  }
  return out;
}

/**
 * The ``load`` of the request: the kind's fields as its spec lists them (required ones
 * always, others when given), the trapezoid's speed, a mechanism's transmission when
 * ticked. The default kind goes without its ``type`` (the API's default).
 */
function readLoad(kind, segments) {
  const spec = kindSpec(kind);
  const load = kind === LOAD_KINDS[0] ? {} : { type: kind };
  if (!segments) load[spec.speed_field] = readNumber(`load.${spec.speed_field}`);
  Object.assign(load, readQuantities("load", spec.fields));
  const fs = $(`#mech-${kind}`);
  if (spec.transmission && (fs && $as(".transmission-toggle", HTMLInputElement, fs))?.checked) {
    load.transmission = readQuantities("load.transmission", TRANSMISSION_FIELDS);
  }
  return load;
}

/** The request body; empty fields go as null so that the API names them. */
function readForm() {
  const segments = cycleMode() === "segments";
  const body = {
    load: readLoad(loadKind(), segments),
    cycle: segments
      ? readSegments()
      : {
          accel_s: readNumber("cycle.accel_s"),
          constant_s: readNumber("cycle.constant_s"),
          decel_s: readNumber("cycle.decel_s"),
          pause_s: readNumber("cycle.pause_s"),
        },
    high_dynamics: input("#f-hd").checked,
    brake: input("#f-brake").checked,
  };
  if (input("#f-drive").checked) body.drive = true;
  if (input("#f-ol").checked) body.output_load = readQuantities("output_load", OUTPUT_LOAD_FIELDS);
  if (input("#f-gear").checked) body.gear = readQuantities("gear", GEAR_FIELDS);
  // blank: not asked (the API's default); the brake's fields go only with the brake ticked
  Object.assign(body, readQuantities("", [...OPTION_FIELDS, ...BRAKE_FIELDS]));
  const models = input("#f-models")
    .value.split(/[,;\s]+/)
    .map((m) => m.trim())
    .filter(Boolean);
  if (models.length) body.models = models;
  return body;
}

function setField(path, value) {
  const el = inputFor(path);
  if (el) {
    el.value = typeof value === "string" && el.dataset.quantity !== undefined ? value : numberText(value, state.lang);
  }
}

/** Tick or untick ``checkbox`` and show (and send) the fieldset ``fieldset`` it opens, or not. */
function setToggled(checkbox, fieldset, on) {
  input(checkbox).checked = on;
  const fs = $as(fieldset, HTMLFieldSetElement);
  fs.hidden = !on;
  fs.disabled = !on;
}

const setOutputLoad = (on) => setToggled("#f-ol", "#output-load", on);
const setBrake = (on) => setToggled("#f-brake", "#brake-options", on);
const setGear = (on) => setToggled("#f-gear", "#gear-options", on);

/**
 * Refill the form from a stored selection's echo (load, mechanism, cycle, options) and
 * its stored ``request`` where the page could read it (the checks asked for).
 */
function fillForm(sel, request = null) {
  const mech = sel.mechanism && typeof sel.mechanism === "object" ? sel.mechanism : null;
  const kind = mech && LOAD_KINDS.includes(mech.type) ? mech.type : LOAD_KINDS[0];
  const spec = kindSpec(kind);
  const segments = Array.isArray(sel.cycle?.segments);
  setLoadKind(kind);
  // the default kind is the answer's load itself; its blank optional fields stay blank
  const given = kind === LOAD_KINDS[0] ? sel.load : mech;
  const defaulted = (field) => kind === LOAD_KINDS[0] && !field.required && given[field.name] === field.default;
  setField(`load.${spec.speed_field}`, segments ? null : given[spec.speed_field]);
  for (const field of spec.fields) setField(`load.${field.name}`, defaulted(field) ? null : given[field.name]);
  if (spec.transmission) {
    const tr = mech.transmission && typeof mech.transmission === "object" ? mech.transmission : null;
    setTransmission($(`#mech-${kind}`), Boolean(tr));
    if (tr) for (const field of TRANSMISSION_FIELDS) setField(`load.transmission.${field.name}`, tr[field.name]);
  }
  if (segments) {
    fillSegments(sel.cycle.segments, sel.cycle.start_speed);
    setCycleMode("segments");
  } else {
    setCycleMode("trapezoid");
    setField("cycle.accel_s", sel.cycle.accel_s);
    setField("cycle.constant_s", sel.cycle.constant_s);
    setField("cycle.decel_s", sel.cycle.decel_s);
    setField("cycle.pause_s", sel.cycle.pause_s);
  }
  input("#f-hd").checked = Boolean(sel.high_dynamics);
  setBrake(Boolean(sel.brake));
  input("#f-drive").checked = Boolean(sel.drive);
  const ol = sel.output_load && typeof sel.output_load === "object" ? sel.output_load : null;
  setOutputLoad(Boolean(ol));
  if (ol) for (const field of OUTPUT_LOAD_FIELDS) setField(`output_load.${field.name}`, ol[field.name]);
  fillAskedChecks(request);
  updateCycleSum();
  showReadings(form(), state.lang);
}

/**
 * The checks asked for beyond the answer's echo (the gear, the stiffness, the brake's
 * factor and stops, τ_th), from the stored ``request`` (GET …/request); without it
 * (an older server) they are left blank. A default (S = 1) stays blank as typed.
 */
function fillAskedChecks(request) {
  const asked = request && typeof request === "object" ? request : {};
  const gear = asked.gear && typeof asked.gear === "object" ? asked.gear : null;
  setGear(Boolean(gear));
  for (const field of GEAR_FIELDS) setField(`gear.${field.name}`, gear?.[field.name] ?? null);
  for (const field of [...OPTION_FIELDS, ...BRAKE_FIELDS]) {
    const value = asked[field.name];
    setField(field.name, typeof value === "number" && String(value) !== field.placeholder ? value : null);
  }
  const details = $as("#more-checks", HTMLDetailsElement);
  if (gear || typeof asked.min_natural_frequency_hz === "number") details.open = true;
}

function fillExample() {
  setLoadKind(EXAMPLE.kind);
  setCycleMode("trapezoid");
  for (const [path, value] of Object.entries(EXAMPLE)) if (path !== "kind") setField(path, value);
  input("#f-hd").checked = true;
  input("#f-models").value = "";
  clearErrors();
  onFormEdited();
  updateCycleSum();
  showReadings(form(), state.lang);
}

/** t_1 + t_2 + t_3 + t_p of the inputs as typed: an echo, not a result. */
function updateCycleSum() {
  const parts = ["cycle.accel_s", "cycle.constant_s", "cycle.decel_s", "cycle.pause_s"].map(readNumber);
  const out = $("#cycle-sum");
  out.textContent = parts.every((p) => p !== null) ? num(parts.reduce((a, b) => a + b, 0), state.lang) : "–";
}

/** The server's T_L and J_L for a mechanism, shown inside its fieldset. */
function updateResolved() {
  for (const fs of $$as("fieldset.mechanism[data-kind]", HTMLFieldSetElement)) {
    const box = $(".resolved-values", fs);
    if (!box) continue;
    box.replaceChildren();
    const sel = state.selection;
    const mech = sel?.mechanism && typeof sel.mechanism === "object" ? sel.mechanism : null;
    if (!sel || mech?.type !== fs.dataset.kind) {
      appendSymbols(box, t("resolved.pending"));
      box.parentElement.classList.add("pending");
      continue;
    }
    box.parentElement.classList.remove("pending");
    const item = (symbol, value, unit, id) =>
      h(
        "span",
        { class: "resolved-item" },
        appendSymbols(h("span", { class: "sym" }), symbol),
        " = ",
        h("output", { id, "data-value": String(value) }, qty(value, unit, state.lang)),
      );
    const kind = fs.dataset.kind;
    // a mechanism also has a speed at the output, a weight and losses (the answer's load block)
    const more = speedField(kind) === "speed_rpm"
      ? []
      : [
          " ",
          item("n_2", sel.load.speed_rpm, "rpm", `resolved-${kind}-speed`),
          " ",
          item("T_G", sel.load.gravity_torque_nm, "Nm", `resolved-${kind}-gravity`),
          " ",
          item("η", sel.load.efficiency, null, `resolved-${kind}-efficiency`),
        ];
    box.append(
      item("T_L", sel.load.torque_nm, "Nm", `resolved-${kind}-torque`),
      " ",
      item("J_L", sel.load.inertia_kgm2, "kgm²", `resolved-${kind}-inertia`),
      ...more,
      // DOM append writes null as the text "null": an empty string adds nothing
      state.stale ? h("span", { class: "muted" }, ` ${t("resolved.stale")}`) : "",
    );
  }
}

// ---------------------------------------------------------------- errors

function clearErrors() {
  $("#form-status").replaceChildren();
  for (const el of $$as(".field-error", HTMLElement, form())) {
    el.hidden = true;
    el.replaceChildren();
  }
  for (const el of form().querySelectorAll("[aria-invalid]")) el.removeAttribute("aria-invalid");
  for (const el of form().querySelectorAll(".has-error")) el.classList.remove("has-error");
}

/** A group (fieldset, the segment list) rather than one input. */
const isGroup = (control) => control.matches("fieldset, ol");

function errorElementFor(control) {
  if (isGroup(control)) {
    const id = control.getAttribute("aria-describedby");
    return id ? document.getElementById(id) : null;
  }
  const ids = (control.getAttribute("aria-describedby") ?? "").split(/\s+/);
  return ids.map((id) => document.getElementById(id)).find((el) => el?.classList.contains("field-error"));
}

/** The control an error location names: ["body", "load", "ball_screw", "lead_m"] → lead field. */
function controlForLoc(loc) {
  const parts = loc.filter((p, i) => !(i === 0 && p === "body"));
  // the union tag of a mechanism load is not a field
  if (parts[0] === "load" && LOAD_KINDS.includes(parts[1])) parts.splice(1, 1);
  // segment indexes stay: ["cycle", "segments", 1, "speed"] → cycle.segments.1.speed
  const names = parts.map(String);
  for (let n = names.length; n > 0; n -= 1) {
    const path = names.slice(0, n).join(".");
    const group = `:is(fieldset, ol)[data-path="${CSS.escape(path)}"]`;
    const control = fieldFor(path) ?? [...form().querySelectorAll(group)].find((el) => !el.closest("fieldset[disabled]"));
    if (control) return control;
  }
  return null;
}

/** Mark ``control`` refused with ``line`` (an error line) in its message element; false if it has none. */
function placeError(control, line) {
  const target = control && errorElementFor(control);
  if (!target) return false;
  target.append(line);
  target.hidden = false;
  if (!isGroup(control)) control.setAttribute("aria-invalid", "true");
  control.closest(".field, .seg-field")?.classList.add("has-error");
  return true;
}

/** The page's own refusal of a number field ("1.300,5"), in the page's language (and after a switch). */
function numberError(control, key) {
  const target = errorElementFor(control);
  target?.replaceChildren();
  return placeError(control, h("span", { class: "error-line", "data-i18n": key }, t(key)));
}

/** The active number fields whose text is refused (lib/numbers.js), each with its message's key. */
function refusedNumbers() {
  return [...form().querySelectorAll("input[data-number]")]
    .filter((el) => !el.matches(":disabled"))
    .map((control) => ({ control, key: fieldRefusal(control) }))
    .filter((refusal) => refusal.key !== null);
}

/**
 * The errors of an answer (``{loc, msg, lang}``) or of the page's own reading
 * (``{control, key}``) at their fields; the form's status counts them.
 */
function showFieldErrors(errors) {
  const unplaced = [];
  let first = null;
  for (const error of errors) {
    const control = error.control ?? controlForLoc(error.loc);
    let placed;
    if (error.key) placed = numberError(control, error.key);
    else {
      const index = error.loc.at(-1);
      const prefix = typeof index === "number" && error.loc.includes("models") ? `#${index + 1}: ` : "";
      const line = appendSymbols(h("span", { class: "error-line", lang: error.lang ?? "en" }), `${prefix}${error.msg}`);
      placed = placeError(control, line);
    }
    if (!placed) {
      unplaced.push(error);
      continue;
    }
    first ??= control;
  }
  const status = $("#form-status");
  status.replaceChildren(
    h("p", {}, t("form.errors"), " ", h("strong", {}, t("form.error.count", { n: errors.length }))),
  );
  if (unplaced.length) {
    status.append(
      h(
        "ul",
        {},
        unplaced.map((e) => h("li", { lang: e.lang ?? "en" }, `${e.loc.join(" › ")}: ${e.msg}`)),
      ),
    );
  }
  status.classList.add("is-error");
  (first && !isGroup(first) ? first : status).focus?.();
}

function describeFailure(error) {
  if (!(error instanceof ApiError)) return t("results.badresponse");
  if (error.kind === "network") return t("results.network");
  if (error.kind === "bad_response") return t("results.badresponse");
  const detail = error.detail ? `: ${error.detail}` : "";
  if (error.status === 404) return `${t("results.notfound")}${detail}`;
  return `${t("results.server")} (HTTP ${error.status})${detail}`;
}

// ---------------------------------------------------------------- results

function chosenCandidate() {
  const list = state.selection?.candidates ?? [];
  return list.find((c) => c.model === state.chosen) ?? list[0] ?? null;
}

function permalinkUrl() {
  const url = new URL(window.location.href);
  url.search = "";
  url.hash = "";
  url.searchParams.set("selection", state.selection.id);
  if (state.chosen && state.chosen !== state.selection.candidates[0]?.model) {
    url.searchParams.set("model", state.chosen);
  }
  if (state.compare.length) url.searchParams.set("compare", state.compare.join(","));
  return url.toString();
}

function updateUrl() {
  if (!state.selection) return;
  const url = permalinkUrl();
  window.history.replaceState({ selection: state.selection.id }, "", url);
  const permalink = input("#permalink");
  if (permalink) permalink.value = url;
  // the quotes page opens on this selection and the chosen actuator: one click to a quote
  const sales = $as(".sales-link", HTMLAnchorElement);
  if (sales) {
    const target = new URL("/sales.html", window.location.href);
    target.searchParams.set("selection", state.selection.id);
    if (state.chosen) target.searchParams.set("model", state.chosen);
    sales.href = `${target.pathname}${target.search}`;
  }
}

async function copyLink() {
  const permalink = input("#permalink");
  const status = $("#copy-status");
  if (!permalink) return;
  let ok;
  try {
    await navigator.clipboard.writeText(permalink.value);
    ok = true;
  } catch {
    permalink.focus();
    permalink.select();
    try {
      ok = document.execCommand("copy");
    } catch {
      ok = false;
    }
  }
  if (status) status.textContent = t(ok ? "permalink.copied" : "permalink.copyfail");
}

function renderResults() {
  const body = $("#results-body");
  purgeCharts();
  body.replaceChildren();
  const results = $("#results");
  results.classList.toggle("is-stale", state.stale);
  results.setAttribute("aria-busy", String(state.busy));
  const sel = state.selection;
  if (!sel) {
    body.append(
      state.busy
        ? notice("info", h("p", { class: "loading" }, t(state.message ?? "results.loading")))
        : notice("info", appendSymbols(h("p"), t("results.empty"))),
    );
    updateResolved();
    return;
  }
  if (state.stale) body.append(notice("warn", h("p", {}, t("results.stale"))));
  body.append(
    renderSummary(sel, state.lang),
    renderPermalink(permalinkUrl(), state.lang, copyLink),
    renderReports(sel, state.lang),
  );
  if (!sel.candidates.length) {
    body.append(notice("info", h("p", {}, t("results.none"))));
    updateResolved();
    return;
  }
  body.append(
    renderBinding(sel, state.lang) ?? "",
    renderRanking(sel, chosenCandidate().model, state.filter, state.lang, rankingOptions(), { rows: "first" }),
    h("div", { id: "compare-slot" }),
    h("div", { id: "detail-slot" }),
    h("div", { id: "ratio-slot" }),
  );
  renderComparison();
  renderRatio();
  const drawn = renderChosen();
  updateResolved();
  // the ranking's other rows follow the charts, or come as soon as the user reaches for them
  drawn.finally(completeRanking);
  const box = $(".ranking-card .table-scroll");
  for (const type of ["pointerenter", "focusin", "scroll"]) {
    box?.addEventListener(type, completeRanking, { once: true, passive: true });
  }
}

/** What the ranking's rows do: choose, filter, mark for comparison. */
function rankingOptions() {
  return {
    onChoose: choose,
    onFilter: (f) => {
      state.filter = f;
      applyFilter();
    },
    compareCell: (model) => compareToggle(model, state.compare.includes(model), state.lang, toggleCompare),
    compareStatus: compareStatusText(state.compare, state.lang, state.compareRefused),
    onMore: showMore,
  };
}

/** "Show more": the ranking's next page added to the selection and drawn below its rows. */
async function showMore() {
  const sel = state.selection;
  const button = $as("#ranking-more-button", HTMLButtonElement);
  if (!sel?.next_cursor) return;
  if (button) button.disabled = true;
  try {
    await readMore(sel, MORE_ROWS);
  } catch (error) {
    if (button) button.disabled = false;
    announce(describeFailure(error));
    return;
  }
  if (state.selection !== sel) return;
  completeRanking();
  const table = $("#ranking-table");
  const candidate = chosenCandidate();
  if (table && candidate) {
    drawRemainingRows(table, sel, candidate.model, state.filter, state.lang, rankingOptions(), { more: true });
  }
  updateMoreRow(sel, state.lang, showMore);
  $as("#ranking-more-button", HTMLButtonElement)?.focus();
}

/**
 * The next ``limit`` candidates of ``sel``'s ranking (all of them: ``Infinity``) added to
 * ``sel.candidates``, by its ``next_cursor``.
 * @param {import("../../lib/api.js").SelectionOut} sel
 */
async function readMore(sel, limit) {
  let wanted = limit;
  while (sel.next_cursor && wanted > 0) {
    const page = await getCandidatePage(sel.id, sel.next_cursor, Math.min(wanted, 1000));
    sel.candidates.push(...page.candidates);
    sel.next_cursor = page.next_cursor;
    wanted -= page.candidates.length;
  }
}

/** The rows a ranking drawn with its first rows still lacks, drawn as things stand now. */
function completeRanking() {
  const table = $("#ranking-table");
  const candidate = chosenCandidate();
  if (!table || !candidate) return;
  drawRemainingRows(table, state.selection, candidate.model, state.filter, state.lang, rankingOptions());
}

// ---------------------------------------------------------------- ratio study

/** The ratio study's section below the results, for the request on the form. */
function renderRatio() {
  const slot = $("#ratio-slot");
  if (!slot) return;
  slot.replaceChildren(renderRatioStudy(ratioVariables(readForm()), state.ratio, state.lang, runRatio));
  if (state.ratio?.status === "ready") drawRatioChart(state.ratio.answer.figure);
}

/** Ask for the ratio study of the request on the form, then show its table and chart. */
async function runRatio(asked) {
  const body = { ...readForm(), ratio_study: asked };
  state.ratio = { status: "loading", asked };
  renderRatio();
  try {
    const answer = await createRatioStudy(body, state.lang);
    state.ratio = { status: "ready", asked, answer };
  } catch (error) {
    state.ratio = { status: "failed", asked, error };
  }
  renderRatio();
}

async function drawRatioChart(figure) {
  const div = html("#chart-ratio");
  if (!div || !figure) return;
  let Plotly;
  try {
    Plotly = await loadPlotly();
  } catch {
    chartUnavailable(div, t("charts.unavailable"));
    return;
  }
  const fitted = fitFigure(figure, chartSize(div));
  await Plotly.react(div, fitted.data, fitted.layout, { ...PLOT_CONFIG, locale: state.lang });
  div.dataset.state = "ready";
}

// ---------------------------------------------------------------- comparison

/** The comparison below the ranking, from the marks; the ranking's boxes and status follow them. */
function renderComparison() {
  const slot = $("#compare-slot");
  if (!slot || !state.selection) return;
  const section = renderCompare(state.selection, state.compare, state.lang, {
    onRemove: (model) => unmark(model, { focusBox: true }),
    onClear: clearMarks,
  });
  slot.replaceChildren(...(section ? [section] : []));
  for (const box of $$as("#ranking-table .compare-toggle", HTMLInputElement)) {
    const marked = state.compare.includes(box.dataset.model);
    box.checked = marked;
    box.closest("tr")?.classList.toggle("compared", marked);
  }
  const status = $("#compare-status");
  if (status) status.textContent = compareStatusText(state.compare, state.lang, state.compareRefused);
}

/** A box in the ranking was ticked or cleared: mark or unmark, a fifth mark refused. */
function toggleCompare(model, box) {
  if (box.checked && !state.compare.includes(model)) {
    if (state.compare.length >= MAX_COMPARED) {
      box.checked = false;
      state.compareRefused = model;
      renderComparison();
      return;
    }
    state.compare = [...state.compare, model];
  } else if (!box.checked) {
    state.compare = state.compare.filter((m) => m !== model);
  }
  state.compareRefused = null;
  renderComparison();
  updateUrl();
}

function unmark(model, { focusBox = false } = {}) {
  state.compare = state.compare.filter((m) => m !== model);
  state.compareRefused = null;
  renderComparison();
  updateUrl();
  if (focusBox) {
    const box = $as(`#ranking-table .compare-toggle[data-model="${CSS.escape(model)}"]`, HTMLInputElement);
    if (box && !box.closest("tr")?.hidden) box.focus();
    else html("#compare-status")?.focus();
  }
}

function clearMarks() {
  state.compare = [];
  state.compareRefused = null;
  renderComparison();
  updateUrl();
  input("#ranking-table .compare-toggle")?.focus();
}

function applyFilter() {
  completeRanking();
  for (const row of $$as("#ranking-table tbody tr[data-model]", HTMLTableRowElement)) {
    row.hidden = state.filter !== "all" && row.dataset.verdict !== state.filter;
  }
  for (const button of $$as(".filter-button", HTMLButtonElement)) {
    button.setAttribute("aria-pressed", String(button.dataset.filter === state.filter));
  }
}

function renderChosen() {
  const slot = $("#detail-slot");
  const candidate = chosenCandidate();
  if (!slot || !candidate) return;
  purgeCharts();
  const view = candidateDetail(state.selection, candidate.model);
  // the parts below the charts come after them (results.js ``fillBelowCharts``)
  slot.replaceChildren(renderDetail(state.selection, candidate, view, state.lang, { belowCharts: false }));
  for (const row of $$as("#ranking-table tbody tr[data-model]", HTMLTableRowElement)) {
    const chosen = row.dataset.model === candidate.model;
    row.classList.toggle("chosen", chosen);
    if (chosen) row.setAttribute("aria-current", "true");
    else row.removeAttribute("aria-current");
    row.querySelector(".model-button")?.setAttribute("aria-pressed", String(chosen));
  }
  const drawn = drawCharts();
  drawn.finally(fillBelowChartsNow);
  return drawn;
}

/** The chosen panel's parts below its charts, where they still wait (results.js ``fillBelowCharts``). */
function fillBelowChartsNow() {
  const panel = html("#detail");
  const sel = state.selection;
  const candidate = chosenCandidate();
  if (!panel || !sel || !candidate || panel.dataset.below !== "later" || panel.dataset.model !== candidate.model) return;
  fillBelowCharts(panel, sel, candidate, candidateDetail(sel, candidate.model), state.lang);
}

/** A detail has arrived (or failed): the panel shows it if its candidate is still the chosen one. */
function detailSettled(sel, model) {
  const panel = html("#detail");
  const candidate = chosenCandidate();
  if (sel !== state.selection || candidate?.model !== model || panel?.dataset.model !== model) return;
  fillDetail(panel, sel, candidate, candidateDetail(sel, model), state.lang);
}

function choose(model) {
  if (!state.selection?.candidates.some((c) => c.model === model)) return;
  state.chosen = model;
  candidateDetail(state.selection, model, { retry: true });
  renderChosen();
  updateUrl();
  announce(resultSentence(state.selection, model, state.lang));
}

function announce(text) {
  const status = $("#results-status");
  status.textContent = "";
  // a fresh text node makes screen readers announce even an identical sentence
  window.setTimeout(() => {
    status.textContent = text;
  }, 30);
}

function showAlert(text) {
  const alert = $("#results-alert");
  alert.replaceChildren(text ? notice("error", h("p", {}, text)) : "");
}

// ---------------------------------------------------------------- charts

let drawToken = 0;
const PLOT_CONFIG = {
  responsive: true,
  displaylogo: false,
  // "Share chart…" would send the data to a site outside the app
  modeBarButtonsToRemove: ["select2d", "lasso2d", "autoScale2d", "sendChartToCloud"],
  locales: PLOTLY_LOCALES,
};

function purgeCharts() {
  if (!window.Plotly) return;
  for (const div of document.querySelectorAll(".chart.js-plotly-plot")) window.Plotly.purge(div);
}

/**
 * What ``fitFigure`` needs of a chart's box: whether it is narrow (a phone's chart lists its
 * legend one entry a line) and its height as plotly.js reads it (its computed style), so
 * that the figure's margins are given up front (figures.js).
 */
function chartSize(div) {
  const width = div.clientWidth;
  return {
    narrow: width > 0 && width < NARROW_CHART_PX,
    height: Number.parseFloat(window.getComputedStyle(div).height),
  };
}

function chartUnavailable(div, text) {
  div.dataset.state = "error";
  div.replaceChildren(h("p", { class: "chart-placeholder chart-error" }, text));
}

/**
 * The chosen candidate's detail and both figures asked for at once, before the results are
 * drawn: the server answers them while the page lays the results out, and the charts are
 * drawn as soon as that is done (``drawCharts`` takes them from the same caches).
 */
function askChartData(sel, model, lang) {
  if (!model) return;
  candidateDetail(sel, model);
  candidateFigure("diagram", sel, model, lang, true).catch(() => {});
  candidateFigure("cycle", sel, model, lang, true).catch(() => {});
}

/** How long a new answer's results wait for its best candidate's detail before they are drawn. */
const DETAIL_WAIT_MS = 250;

/**
 * The best candidate's detail and figures asked for as soon as a selection answers, and its
 * detail awaited (for at most ``DETAIL_WAIT_MS``): the results are then laid out once, with
 * the detail's checks, instead of once without and again when the detail comes.
 */
async function chartDataAsked(sel) {
  const model = Array.isArray(sel?.candidates) ? sel.candidates[0]?.model : undefined;
  if (typeof sel?.id !== "string" || !model) return;
  askChartData(sel, model, state.lang);
  await Promise.race([
    candidateDetail(sel, model).settled,
    new Promise((resolve) => window.setTimeout(resolve, DETAIL_WAIT_MS)),
  ]);
}

async function drawCharts() {
  const token = ++drawToken;
  const sel = state.selection;
  const candidate = chosenCandidate();
  const lang = state.lang;
  const cycleDiv = html("#chart-cycle");
  const diagramDiv = html("#chart-diagram");
  if (!sel || !candidate || !cycleDiv || !diagramDiv) return;
  $("#cycle-caption").replaceChildren(appendSymbols(h("span"), cycleCaption(sel, candidate, lang)));
  // the detail is on its way (asked when the panel was drawn) while plotly.js loads and the
  // cycle is drawn; without it the diagram is drawn without catalogue limits, and says so
  const detailPending = candidateDetail(sel, candidate.model).settled;
  // the API's figures are asked at once, beside the detail: the diagram with the
  // catalogue's limits (a failure is asked again, or without the catalogue, once the detail
  // says which) and the cycle with the torque along each segment
  candidateFigure("diagram", sel, candidate.model, lang, true).catch(() => {});
  const cyclePending = candidateFigure("cycle", sel, candidate.model, lang, true).catch(() =>
    // the catalogue has changed since (409) or the server failed: the stored T_1…T_3
    candidateFigure("cycle", sel, candidate.model, lang, false).catch(() => null),
  );

  let Plotly;
  try {
    Plotly = await loadPlotly();
  } catch {
    if (token !== drawToken) return;
    chartUnavailable(cycleDiv, t("charts.unavailable"));
    chartUnavailable(diagramDiv, t("charts.unavailable"));
    return;
  }
  if (token !== drawToken) return;
  const config = (name) => ({
    ...PLOT_CONFIG,
    locale: lang, // plotly's own tooltips (the mode bar) in the page's language
    toImageButtonOptions: { filename: `${candidate.model}-${name}` },
  });
  const drawn = (figure) => figure && Array.isArray(figure.data) && figure.layout;

  const cycle = await cyclePending;
  if (token !== drawToken) return;
  if (!drawn(cycle)) {
    chartUnavailable(cycleDiv, t("charts.unavailable"));
  } else {
    const fitted = fitFigure(cycle, chartSize(cycleDiv));
    cycleDiv.replaceChildren();
    await Plotly.react(cycleDiv, fitted.data, fitted.layout, config("cycle"));
    if (token !== drawToken) return;
    cycleDiv.dataset.model = candidate.model;
    cycleDiv.dataset.state = "ready";
    // "detail": the torque along each segment (as the detail gives it), "lean": without
    cycleDiv.dataset.torques = cycle.layout.meta?.torques === "segments" ? "detail" : "lean";
  }

  // the diagram waits for the detail: meanwhile the parts below the charts
  if (candidateDetail(sel, candidate.model).status === "loading") fillBelowChartsNow();
  const detail = await detailPending;
  const actuator = detail?.actuator ?? null;
  if (token !== drawToken) return;
  // the API's figure (the one the documents print), with the catalogue's limits where the
  // detail could read them
  let figure;
  try {
    figure = await candidateFigure("diagram", sel, candidate.model, lang, Boolean(actuator));
  } catch {
    figure = null;
  }
  if (token !== drawToken) return;
  $("#diagram-caption").replaceChildren(
    appendSymbols(h("span"), diagramCaption(sel, candidate, actuator, figure, lang)),
  );
  if (!drawn(figure)) {
    chartUnavailable(diagramDiv, t("charts.unavailable"));
  } else {
    const diagram = fitFigure(figure, chartSize(diagramDiv));
    diagramDiv.replaceChildren();
    await Plotly.react(diagramDiv, diagram.data, diagram.layout, config("speed-torque"));
    diagramDiv.dataset.model = candidate.model;
    diagramDiv.dataset.state = "ready";
  }
}

/**
 * The warm-up's second figure waits until the page has been quiet this long: no move of
 * the pointer, wheel or scroll (a user about to click).
 */
const WARM_AFTER_MS = 400;

/** Whether the user has pressed a key or a pointer, or put something in, since the page loaded. */
let touched = false;

/** When the pointer last moved, or the page was scrolled (``performance.now()``). */
let lastMoved = -Infinity;

/** Whether input is waiting for the page (a click on its way). */
function inputPending() {
  const scheduling = /** @type {{ isInputPending?: (options?: object) => boolean } | undefined} */ (
    /** @type {any} */ (navigator).scheduling
  );
  return scheduling?.isInputPending?.({ includeContinuous: true }) ?? false;
}

/** ``WARM_AFTER_MS`` from now, and as much longer as the pointer keeps moving. */
async function quietPeriod() {
  let wait = WARM_AFTER_MS;
  while (wait > 0) {
    await new Promise((resolve) => window.setTimeout(resolve, wait));
    wait = touched ? 0 : WARM_AFTER_MS - (performance.now() - lastMoved);
  }
}

/**
 * Made-up charts (``WARM_FIGURES``) drawn off screen and thrown away, while the page waits
 * for its first input. plotly.js sets itself up and compiles its drawing code on first use:
 * a first chart took 100–130 ms here and a warmed-up one 35 ms, so the user's first charts
 * come that much sooner. The small figure as soon as plotly.js has run (it takes the
 * first-use costs, which the user's first chart would pay otherwise), the other one a task
 * of its own once the page has been quiet (``quietPeriod``), so that a click waits for the
 * small one at most. Each is skipped once the user has started (clicked or typed, or input
 * is waiting), or a permalink is opened. Says what it did in ``<html data-charts-warm>``:
 * "done", "partial" (the user started in between), "skipped" or "failed" (a warm-up only).
 */
async function warmCharts(Plotly) {
  let drawn = 0;
  for (const figure of WARM_FIGURES) {
    if (drawn) await quietPeriod();
    if (touched || state.busy || state.selection || inputPending()) break;
    try {
      await drawOutOfSight(Plotly, figure);
      drawn += 1;
    } catch {
      document.documentElement.dataset.chartsWarm = "failed";
      return;
    }
  }
  const all = drawn === WARM_FIGURES.length;
  document.documentElement.dataset.chartsWarm = all ? "done" : drawn ? "partial" : "skipped";
}

/** Whether plotly.js has drawn a warm-up figure on this page: its first-use costs are paid. */
let warmedUp = false;

/** ``figure`` drawn off screen and thrown away (a warm-up). */
async function drawOutOfSight(Plotly, figure) {
  const host = h("div", { class: "chart chart-warmup", "aria-hidden": "true", inert: true });
  document.body.append(host);
  try {
    await Plotly.newPlot(host, figure.data, figure.layout, { ...PLOT_CONFIG, locale: state.lang });
    Plotly.purge(host);
    warmedUp = true;
  } finally {
    host.remove();
  }
}

/**
 * The small warm-up figure drawn while the page waits for its first answer, when the user
 * has submitted before ``warmCharts`` could draw it (it gives way to the user's first
 * input): the page is idle until the answer comes, and plotly.js's first-use costs (a
 * first chart's 100–130 ms here, four times that on a CPU slowed 4×) are then paid by
 * the time the charts are drawn, not by the first of them. A task of its own, skipped
 * once the answer is in (``state.busy`` cleared) or a chart is drawn. Says so in
 * ``<html data-charts-warm-submit>``: "done", "skipped", "failed".
 */
function warmWhileWaiting() {
  const root = document.documentElement;
  const skip = () => warmedUp || !state.busy || document.querySelector(".chart.js-plotly-plot") !== null;
  if (skip()) return;
  loadPlotly().then(
    (Plotly) =>
      window.setTimeout(() => {
        if (skip()) {
          root.dataset.chartsWarmSubmit = "skipped";
          return;
        }
        drawOutOfSight(Plotly, WARM_FIGURES[0]).then(
          () => (root.dataset.chartsWarmSubmit = "done"),
          () => (root.dataset.chartsWarmSubmit = "failed"),
        );
      }),
    () => {}, // the charts say so when they are drawn
  );
}

// ---------------------------------------------------------------- flow

function setBusy(busy, messageKey = "results.loading") {
  state.busy = busy;
  state.message = messageKey;
  const submit = $as("#submit", HTMLButtonElement);
  submit.disabled = busy;
  submit.textContent = t(busy ? "form.running" : "form.submit");
  $("#results").setAttribute("aria-busy", String(busy));
}

function acceptSelection(sel, preferredModel, marks = []) {
  if (!sel || !Array.isArray(sel.candidates) || !sel.load || !sel.cycle) {
    throw new ApiError({ status: 200, kind: "bad_response" });
  }
  state.selection = sel;
  state.ratio = null; // asked of another request
  state.stale = false;
  state.filter = "all";
  // a new selection starts without marks; a permalink brings its own
  state.compare = validMarks(sel, marks);
  state.compareRefused = null;
  const models = sel.candidates.map((c) => c.model);
  state.chosen = models.includes(preferredModel) ? preferredModel : (models[0] ?? null);
  askChartData(sel, state.chosen, state.lang);
  renderResults();
  updateUrl();
  announce(resultSentence(sel, state.chosen, state.lang));
}

/**
 * After a submit, the results where the eye and the screen reader are: focus on their
 * heading, scrolled to the top of the viewport (smoothly, unless reduced motion is asked for).
 */
function bringResultsIntoView() {
  const heading = html("#results-heading");
  if (!heading) return;
  heading.setAttribute("tabindex", "-1");
  heading.focus({ preventScroll: true });
  const reduced = window.matchMedia("(prefers-reduced-motion: reduce)").matches;
  heading.scrollIntoView({ behavior: reduced ? "auto" : "smooth", block: "start" });
}

async function onSubmit(event) {
  event.preventDefault();
  if (state.busy) return;
  clearErrors();
  showAlert(null);
  // text the page cannot read as one number ("1.300,5") is named at its field, and nothing is sent
  const refused = refusedNumbers();
  if (refused.length) {
    showFieldErrors(refused);
    return;
  }
  const body = readForm();
  setBusy(true);
  if (!state.selection) renderResults();
  try {
    const asked = createSelection(body);
    warmWhileWaiting();
    const sel = await asked;
    await chartDataAsked(sel);
    setBusy(false);
    acceptSelection(sel);
    bringResultsIntoView();
  } catch (error) {
    setBusy(false);
    if (error instanceof ApiError && error.fieldErrors.length && error.status === 422) {
      showFieldErrors(error.fieldErrors);
      showAlert(t("form.errors"));
    } else {
      showAlert(describeFailure(error));
    }
    if (state.selection) $("#results").setAttribute("aria-busy", "false");
    else renderResults();
  }
}

async function openPermalink(id, model, marks) {
  setBusy(true, "results.loading.permalink");
  renderResults();
  try {
    // the request refills what the answer does not echo; without it those stay blank
    const [sel, request] = await Promise.all([getSelection(id), getSelectionRequest(id).catch(() => null)]);
    // a permalink's actuator or marks beyond the candidates listed: read the ranking whole
    const listed = new Set((sel?.candidates ?? []).map((c) => c.model));
    if (sel?.next_cursor && [model, ...marks].some((m) => m && !listed.has(m))) {
      await readMore(sel, Infinity);
    }
    setBusy(false);
    fillForm(sel, request);
    acceptSelection(sel, model, marks);
  } catch (error) {
    setBusy(false);
    showAlert(describeFailure(error));
    renderResults();
  }
}

function onFormEdited() {
  if (state.selection && !state.stale) {
    state.stale = true;
    $("#results").classList.add("is-stale");
    const body = $("#results-body");
    body.prepend(notice("warn", h("p", {}, t("results.stale"))));
    updateResolved();
  }
}

function applyLang(lang) {
  state.lang = LANGS.includes(lang) ? lang : "de";
  document.documentElement.lang = state.lang;
  applyStaticTexts(document, state.lang);
  setSegmentLang(state.lang);
  for (const button of $$as(".lang-button", HTMLButtonElement)) {
    button.setAttribute("aria-pressed", String(button.dataset.lang === state.lang));
  }
  document.title = `${t("app.title")} · Harmonic Drive`;
  $("#submit").textContent = t(state.busy ? "form.running" : "form.submit");
  updateCycleSum();
  showReadings(form(), state.lang);
  renderResults();
  if (state.selection) {
    updateUrl();
    // the screen reader's last result sentence follows the language, not only the page
    const status = $("#results-status");
    if (status.textContent) status.textContent = resultSentence(state.selection, state.chosen, state.lang);
  }
}

/** The generated parts of the form: the mechanisms' fieldsets and the output load's fields. */
function buildForm() {
  renderMechanisms(html("#load-kind"), $("#speed-field"), (fieldset) => {
    applyStaticTexts(fieldset, state.lang);
    showReadings(fieldset, state.lang);
    updateResolved();
  });
  $("#output-load").append(
    ...OUTPUT_LOAD_FIELDS.map((field) =>
      quantityField({ id: `f-ol-${field.name}`, path: `output_load.${field.name}`, ...field }),
    ),
  );
  const field = (prefix, spec) =>
    quantityField({
      id: `f-${prefix ? `${prefix}-` : ""}${spec.name}`,
      path: prefix ? `${prefix}.${spec.name}` : spec.name,
      units: false, // plain numbers: the API takes these without a unit
      ...spec,
    });
  $("#gear-options").append(...GEAR_FIELDS.map((spec) => field("gear", spec)));
  $("#brake-options").append(...BRAKE_FIELDS.map((spec) => field("", spec)));
  for (const spec of OPTION_FIELDS) $(spec.slot).append(field("", spec));
  initSegments({ onChange: onFormEdited });
}

function init() {
  buildForm();
  applyLang(initialLang());
  setLoadKind(loadKind());
  setCycleMode(cycleMode());
  setBrake(input("#f-brake").checked);
  setGear(input("#f-gear").checked);
  const f = form();
  f.addEventListener("submit", onSubmit);
  f.addEventListener("input", (event) => {
    const target = event.target;
    if (!(target instanceof HTMLElement)) return;
    const field = target.closest(".field, .seg-field");
    if (field?.classList.contains("has-error")) {
      field.classList.remove("has-error");
      target.removeAttribute("aria-invalid");
      const err = errorElementFor(target);
      if (err) err.hidden = true;
    }
    if (target.matches('[data-path^="cycle."]')) updateCycleSum();
    showReading(target, state.lang);
    onFormEdited();
  });
  f.addEventListener("change", (event) => {
    const target = event.target;
    if (!(target instanceof HTMLInputElement || target instanceof HTMLSelectElement)) return;
    if (isNumberField(target)) {
      // a number the page cannot read is named when the field is left, not only at submit
      const key = fieldRefusal(target);
      if (key) numberError(target, key);
    }
    if (target.name === "load-kind") {
      setLoadKind(loadKind());
      onFormEdited();
    } else if (target.name === "cycle-mode") {
      setCycleMode(cycleMode());
      onFormEdited();
    } else if (target instanceof HTMLInputElement && target.id === "f-ol") {
      setOutputLoad(target.checked);
      onFormEdited();
    } else if (target instanceof HTMLInputElement && target.id === "f-brake") {
      setBrake(target.checked);
      onFormEdited();
    } else if (target instanceof HTMLInputElement && target.id === "f-gear") {
      setGear(target.checked);
      onFormEdited();
    } else if (target.matches(".transmission-toggle")) {
      onFormEdited();
    }
  });
  $("#example").addEventListener("click", fillExample);
  initProfile(); // the profile and AAS uploads on the form
  $("#results").addEventListener("click", (event) => {
    if (event.target instanceof Element && event.target.closest("#limits-button")) showLimits();
  });
  for (const button of $$as(".lang-button", HTMLButtonElement)) {
    button.addEventListener("click", () => {
      rememberLang(button.dataset.lang);
      applyLang(button.dataset.lang);
    });
  }
  // the number format's set-up in the first idle moment, not at the first number typed
  const idle = window.requestIdleCallback ?? ((run) => window.setTimeout(run, 0));
  idle(() => prepareNumbers(state.lang));
  const params = new URLSearchParams(window.location.search);
  const id = params.get("selection");
  if (id) openPermalink(id, params.get("model"), (params.get("compare") ?? "").split(",").filter(Boolean));
  else {
    // the page's own <script> loads plotly.js (else it asks where it is); then, while
    // the user has not started, plotly.js is warmed up
    for (const type of ["pointerdown", "keydown", "input"]) {
      document.addEventListener(type, () => (touched = true), { capture: true, once: true });
    }
    for (const type of ["pointermove", "wheel", "scroll"]) {
      document.addEventListener(type, () => (lastMoved = performance.now()), { capture: true, passive: true });
    }
    loadPlotly().then(
      (Plotly) => window.setTimeout(() => warmCharts(Plotly)), // a task of its own: input first
      () => {},
    );
  }
}

init();
