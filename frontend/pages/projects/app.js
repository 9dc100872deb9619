// Machine projects (issue 31): several axes on one DC bus. The page sends the axes and
// the bus to POST /api/v1/projects (PUT to edit a stored one), and draws what the answer
// holds: each axis's electrical power stacked over the machine cycle and the bus's
// figures. It computes no engineering result.

import { API, createClient, encodePath } from "../../lib/api.js";
import { byId, h } from "../../lib/dom.js";
import { qty } from "../../lib/format.js";
import { LANGS, applyStaticTexts, initialLang, rememberLang, translate } from "../../lib/i18n.js";
import { loadPlotly } from "../../lib/plotly.js";

const state = { lang: "de", project: null };
const t = (key, params = {}) => translate(state.lang, key, params);
const api = createClient({ headers: () => ({ "Accept-Language": state.lang }) });

/** A load case of three axes: a vertical belt, a horizontal rack, a rotary wrist (2.4 s). */
const EXAMPLE = {
  name: "Pick-and-place",
  bus: { bus_class: "560vdc", chopper_voltage_v: 780 },
  axes: [
    {
      name: "Z",
      offset_s: 0,
      case: {
        load: {
          type: "belt",
          mass_kg: 4,
          pulley_diameter_mm: 50,
          friction_coefficient: 0,
          efficiency: 0.9,
          incline_deg: 90,
          transmission: { ratio: 1.5, efficiency: 1 },
        },
        cycle: {
          segments: [
            { speed: -300, duration_s: 0.2 },
            { duration_s: 0.4 },
            { speed: 0, duration_s: 0.2 },
            { duration_s: 0.3 },
            { speed: 300, duration_s: 0.2, jerk_share: 0.5 },
            { duration_s: 0.4 },
            { speed: 0, duration_s: 0.2, jerk_share: 0.5 },
            { duration_s: 0.5 },
          ],
        },
        brake: true,
      },
    },
    {
      name: "X",
      offset_s: 0.9,
      case: {
        load: { type: "rack_pinion", mass_kg: 12, pinion_diameter_mm: 80, friction_coefficient: 0.05, efficiency: 0.95 },
        cycle: {
          segments: [
            { speed: 600, duration_s: 0.2 },
            { duration_s: 0.3 },
            { speed: 0, duration_s: 0.2 },
            { duration_s: 0.5 },
            { speed: -600, duration_s: 0.2 },
            { duration_s: 0.3 },
            { speed: 0, duration_s: 0.2 },
            { duration_s: 0.5 },
          ],
        },
      },
    },
    {
      name: "C",
      offset_s: 1.1,
      case: {
        load: { type: "rotary", inertia_kgm2: 0.08, friction_torque_nm: 0.5 },
        cycle: {
          segments: [
            { speed: 60, duration_s: 0.1 },
            { duration_s: 0.15 },
            { speed: 0, duration_s: 0.1 },
            { duration_s: 0.85 },
            { speed: -60, duration_s: 0.1 },
            { duration_s: 0.15 },
            { speed: 0, duration_s: 0.1 },
            { duration_s: 0.85 },
          ],
        },
      },
    },
  ],
};

const AXIS_FIELDS = new Set(["name", "offset_s", "model", "controller"]);

/** An input (or select, textarea) of the page by its id. */
const input = (id) => /** @type {HTMLInputElement} */ (byId(id));
/** A table of the page by its id. */
const table = (id) => /** @type {HTMLTableElement} */ (byId(id));
/** An axis row's field (``data-field``). */
const axisField = (row, what) => /** @type {HTMLInputElement} */ (row.querySelector(`[data-field="${what}"]`));
/** The language buttons. */
const langButtons = () => /** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll(".lang-button"));

// --- the form ---------------------------------------------------------------------------

/** @param {{name?: string, offset_s?: number, model?: string, controller?: number, case?: object}} [axis] */
function axisRow(axis = { name: "", offset_s: 0, case: { load: {}, cycle: {} } }) {
  const k = byId("axes").children.length;
  const id = (what) => `axis-${k}-${what}`;
  const field = (what, label, value, attrs = {}) =>
    h(
      "p",
      {},
      h("label", { for: id(what), dataset: { i18n: label } }, t(label)),
      h("input", { id: id(what), value: value ?? "", dataset: { field: what }, ...attrs }),
    );
  const remove = h("button", { type: "button", class: "link-button", dataset: { i18n: "projects.axis.remove" } }, t("projects.axis.remove"));
  const row = h(
    "fieldset",
    { class: "axis" },
    h("legend", {}, t("projects.axis", { n: k + 1 })),
    field("name", "projects.axis.name", axis.name, { maxLength: 80 }),
    field("offset_s", "projects.axis.offset", String(axis.offset_s ?? 0), { inputMode: "decimal" }),
    field("model", "projects.axis.model", axis.model ?? "", { spellcheck: false }),
    h(
      "p",
      {},
      h("label", { for: id("controller"), dataset: { i18n: "projects.axis.controller" } }, t("projects.axis.controller")),
      h(
        "select",
        { id: id("controller"), dataset: { field: "controller" } },
        h("option", { value: "" }, t("projects.axis.no_controller")),
        ...(axis.controller ? [h("option", { value: String(axis.controller), selected: true }, t("controller.row", { n: axis.controller }))] : []),
      ),
    ),
    h(
      "p",
      {},
      h("label", { for: id("case"), dataset: { i18n: "projects.axis.case" } }, t("projects.axis.case")),
      h("textarea", { id: id("case"), rows: 8, cols: 60, spellcheck: false, dataset: { field: "case" } }, JSON.stringify(axis.case, null, 1)),
    ),
    h("p", {}, remove),
  );
  remove.addEventListener("click", () => row.remove());
  byId("axes").append(row);
}

function fill(request) {
  input("p-name").value = request.name ?? "";
  input("p-bus-class").value = request.bus?.bus_class ?? "560vdc";
  input("p-capacitance").value = request.bus?.capacitance_uf ?? "";
  input("p-max-voltage").value = request.bus?.max_voltage_v ?? "";
  input("p-chopper").value = request.bus?.chopper_voltage_v ?? "";
  byId("axes").replaceChildren();
  for (const axis of request.axes ?? []) {
    const own = Object.fromEntries(Object.entries(axis).filter(([key]) => AXIS_FIELDS.has(key)));
    const rest = axis.case ?? Object.fromEntries(Object.entries(axis).filter(([key]) => !AXIS_FIELDS.has(key)));
    axisRow({ ...own, case: rest });
  }
}

/** A number field's value, or undefined when empty; the text itself when not a number. */
function numberOf(field) {
  const text = field.value.trim().replace(",", ".");
  if (text === "") return undefined;
  const value = Number(text);
  return Number.isFinite(value) ? value : field.value;
}

/** The request from the form; null (with the field marked) where a case is not JSON. */
function request() {
  const bus = { bus_class: input("p-bus-class").value };
  for (const [key, id] of [
    ["capacitance_uf", "p-capacitance"],
    ["max_voltage_v", "p-max-voltage"],
    ["chopper_voltage_v", "p-chopper"],
  ]) {
    const value = numberOf(input(id));
    if (value !== undefined) bus[key] = value;
  }
  const axes = [];
  for (const [k, row] of [...byId("axes").children].entries()) {
    const get = (what) => axisField(row, what);
    let loadCase;
    try {
      loadCase = JSON.parse(get("case").value);
    } catch {
      markError(get("case"), t("projects.error.json", { n: k + 1 }));
      return null;
    }
    const axis = { ...loadCase, name: get("name").value.trim(), offset_s: numberOf(get("offset_s")) ?? 0 };
    const model = get("model").value.trim();
    if (model) axis.model = model;
    const controller = get("controller").value;
    if (controller) axis.controller = Number(controller);
    axes.push(axis);
  }
  return { name: input("p-name").value.trim(), bus, axes };
}

function markError(field, text) {
  field.setAttribute("aria-invalid", "true");
  say(text, true);
  field.focus();
}

function say(text, error = false) {
  const status = byId("status");
  status.textContent = text;
  status.className = error ? "notice notice-error" : "";
}

/** The form's input that a 422's ``loc`` names, if any. */
function inputAt(loc) {
  const [where, ...path] = loc;
  if (where !== "body") return null;
  if (path[0] === "axes" && path.length > 1) {
    const row = byId("axes").children[Number(path[1])];
    if (!row) return null;
    const own = AXIS_FIELDS.has(String(path[2])) ? String(path[2]) : "case";
    return axisField(row, own);
  }
  return document.querySelector(`[data-path="${path.join(".")}"]`);
}

async function submit(event) {
  event.preventDefault();
  for (const el of document.querySelectorAll("[aria-invalid]")) el.removeAttribute("aria-invalid");
  const body = request();
  if (!body) return;
  say(t("projects.running"));
  input("size").disabled = true;
  try {
    const answer = state.project
      ? await api.request("PUT", encodePath`/projects/${state.project.id}`, { body })
      : await api.post("/projects", body);
    state.project = answer;
    history.replaceState(null, "", `?id=${encodeURIComponent(answer.id)}`);
    say(t("projects.sized", { n: answer.axes.length }));
    await render();
  } catch (error) {
    const errors = error.fieldErrors ?? [];
    for (const e of errors) inputAt(e.loc)?.setAttribute("aria-invalid", "true");
    const where = errors.map((e) => `${e.loc.slice(1).join(".")}: ${e.msg}`).join("; ");
    say(t("projects.refused", { detail: where || error.message }), true);
  } finally {
    input("size").disabled = false;
  }
}

// --- the answer -------------------------------------------------------------------------

const W = (value) => qty(value, "W", state.lang);
const J = (value) => qty(value, "J", state.lang);

function summaryRows(project) {
  const bus = project.bus;
  const p = bus.power;
  const cap = bus.capacitor;
  const r = bus.braking_resistor;
  const ph = bus.random_phasing;
  const noData = t("projects.no_data");
  return [
    ["projects.sum.cycle", qty(project.cycle_time_s, "s", state.lang)],
    ["projects.sum.nominal", qty(bus.nominal_voltage_v, "V", state.lang)],
    ["projects.sum.controllers_bus", bus.controllers_bus_mark === null ? t("projects.no_controller") : t(`controller.${bus.controllers_bus_mark}`)],
    ["projects.sum.voltage", bus.voltage_status === null ? t("projects.no_controller") : t(`status.${bus.voltage_status}`)],
    ["projects.sum.peak", W(p.peak_w)],
    ["projects.sum.mean", W(p.mean_w)],
    ["projects.sum.mean_supply", W(p.mean_supply_w)],
    ["projects.sum.regen_energy", J(p.regen_energy_j)],
    ["projects.sum.regen_peak", W(p.regen_peak_w)],
    ["projects.sum.regen_pulse", J(p.regen_pulse_energy_j)],
    ["projects.sum.capacitor", cap.energy_j === null ? noData : J(cap.energy_j)],
    ["projects.sum.resistor", r.needed ? t("projects.resistor.needed") : t("projects.resistor.not_needed")],
    ["projects.sum.resistor_peak", W(r.peak_power_w)],
    ["projects.sum.resistor_continuous", W(r.continuous_power_w)],
    ["projects.sum.resistor_pulse", J(r.pulse_energy_j)],
    ["projects.sum.resistance", r.max_resistance_ohm === null ? noData : `≤ ${qty(r.max_resistance_ohm, "Ω", state.lang)}`],
    ["projects.sum.worst_peak", W(ph.worst_peak_w)],
    ["projects.sum.statistical_peak", W(ph.statistical_peak_w)],
  ];
}

function renderTables(project) {
  table("bus-summary").tBodies[0].replaceChildren(
    ...summaryRows(project).map(([key, value]) =>
      h("tr", { dataset: { row: key.replace("projects.sum.", "") } }, h("th", { scope: "row" }, t(key)), h("td", {}, value)),
    ),
  );
  table("axes-table").tBodies[0].replaceChildren(
    ...project.axes.map((a) =>
      h(
        "tr",
        {},
        h("td", { translate: "no" }, a.name),
        h("td", { translate: "no" }, a.model),
        h("td", {}, t(`verdict.${a.verdict}`)),
        h("td", {}, a.controller ? controllerText(a.controller) : t("projects.no_controller")),
        h("td", {}, W(a.power.peak_w)),
        h("td", {}, W(a.power.mean_w)),
        h("td", {}, J(a.power.regen_energy_j)),
        h("td", {}, J(a.energies.copper_j + a.energies.no_load_j)),
      ),
    ),
  );
}

/** A controller of Table 521.1 as the page names it: its name, row and match. */
function controllerText(c) {
  return t("projects.controller.choice", { name: c.name, row: c.source_row, level: t(`controller.${c.level}`) });
}

/** Each axis's choice of controller: those the answer lists for it on the bus. */
function offerControllers(project) {
  for (const [k, row] of [...byId("axes").children].entries()) {
    const axis = project.axes[k];
    const select = axisField(row, "controller");
    if (!axis || !select) continue;
    const kept = select.value;
    select.replaceChildren(
      h("option", { value: "" }, t(axis.controllers.length ? "projects.axis.no_controller" : "projects.axis.none_on_bus")),
      ...axis.controllers.map((c) => h("option", { value: String(c.source_row) }, controllerText(c))),
    );
    select.value = axis.controllers.some((c) => String(c.source_row) === kept) ? kept : "";
  }
}

async function renderChart(project) {
  const chart = byId("power-chart");
  let Plotly;
  try {
    Plotly = await loadPlotly();
  } catch {
    chart.replaceChildren(h("p", { class: "notice" }, t("charts.unavailable")));
    return;
  }
  const x = project.curve.times_s;
  const traces = project.axes.map((a, k) => ({
    type: "scatter",
    mode: "lines",
    stackgroup: "axes",
    name: `${a.name || k + 1} · ${a.model}`,
    x,
    y: project.curve.axes_w[k],
  }));
  const layout = {
    margin: { t: 30, r: 10, b: 50, l: 60 },
    xaxis: { title: { text: t("projects.chart.time") } },
    yaxis: { title: { text: t("projects.chart.power") } },
    legend: { orientation: "h" },
    title: { text: t("projects.chart") },
  };
  await Plotly.react(chart, traces, layout, { displaylogo: false, responsive: true });
  chart.dataset.traces = String(traces.length);
}

async function render() {
  const project = state.project;
  if (!project) return;
  byId("results").hidden = false;
  /** @type {HTMLAnchorElement} */ (byId("permalink")).href = `/projects.html?id=${encodeURIComponent(project.id)}`;
  /** @type {HTMLAnchorElement} */ (byId("quote-link")).href = `/sales.html?project=${encodeURIComponent(project.id)}`;
  /** @type {HTMLAnchorElement} */ (byId("aas-link")).href = `${API}/projects/${encodeURIComponent(project.id)}/aas.aasx`;
  renderTables(project);
  offerControllers(project);
  await renderChart(project);
}

// --- language and start -----------------------------------------------------------------

function applyLang(lang) {
  state.lang = LANGS.includes(lang) ? lang : "de";
  document.documentElement.lang = state.lang;
  applyStaticTexts(document, state.lang);
  for (const button of langButtons()) {
    button.setAttribute("aria-pressed", String(button.dataset.lang === state.lang));
  }
  for (const [k, legend] of [...document.querySelectorAll("#axes legend")].entries()) {
    legend.textContent = t("projects.axis", { n: k + 1 });
  }
  document.title = `${t("projects.title")} · ${t("app.title")}`;
  if (state.project) render();
}

async function start() {
  applyLang(initialLang());
  for (const button of langButtons()) {
    button.addEventListener("click", () => {
      rememberLang(button.dataset.lang);
      applyLang(button.dataset.lang);
    });
  }
  byId("add-axis").addEventListener("click", () => axisRow());
  byId("example").addEventListener("click", () => {
    state.project = null;
    fill(EXAMPLE);
  });
  byId("project-form").addEventListener("submit", submit);
  const id = new URLSearchParams(location.search).get("id");
  if (id) {
    try {
      state.project = await api.get(encodePath`/projects/${id}`);
      fill(state.project.request);
      await render();
    } catch (error) {
      say(t("projects.refused", { detail: error.message }), true);
    }
  } else {
    axisRow();
  }
  document.documentElement.dataset.ready = "true";
}

start();
