// The segment editor: the cycle as the API's list of segments (schemas/selections.py,
// SegmentsCycleIn) — end speed, duration or acceleration, S-curve share, process load —
// one row per segment, added, removed and moved. Speeds and loads are in the chosen
// load's units (rpm and Nm, or mm/s and N on a linear axis). Each input's data-path names
// the request field (cycle.segments.<k>.speed …), so the API's 422 lands at the field.
// No number is computed here: the rows are read and sent as typed.

import { $as, $$as, byIdAs, h } from "../../lib/dom.js";
import { translate, unitText } from "../../lib/i18n.js";
import { numberText, readField, showReading } from "../../lib/numbers.js";

const list = () => document.getElementById("segment-list");
let units = { speed: "rpm", accel: "rpm/s", load: "Nm" };
let lang = "de";
let changed = () => {};

function input(kind, extra = {}) {
  return h("input", {
    type: "text",
    inputmode: "decimal",
    "data-number": "",
    "data-seg": kind,
    ...extra,
  });
}

function cell(kind, control) {
  return h(
    "div",
    { class: "seg-field", "data-seg-field": kind },
    h("label", { "data-seg-label": kind }),
    h("div", { class: "input-unit" }, control, h("span", { class: "unit", "data-seg-unit": kind })),
    h("p", { class: "field-error", hidden: true }),
  );
}

function button(action, symbol) {
  return h("button", { type: "button", class: "seg-button", "data-action": action }, h("span", { "aria-hidden": "true" }, symbol));
}

/** A new row; ``values`` as the API's segment ({speed, duration_s | accel, jerk_share, process_load}). */
function row(values = {}) {
  const mode = h(
    "select",
    { "data-seg": "mode" },
    h("option", { value: "duration_s" }),
    h("option", { value: "accel" }),
  );
  const li = h(
    "li",
    { class: "segment" },
    h(
      "div",
      { class: "segment-head" },
      h("span", { class: "segment-title" }),
      h("span", { class: "segment-buttons" }, button("up", "↑"), button("down", "↓"), button("remove", "✕")),
    ),
    h(
      "div",
      { class: "segment-fields" },
      cell("speed", input("speed")),
      h(
        "div",
        { class: "seg-field seg-time", "data-seg-field": "time" },
        h("label", { "data-seg-label": "mode" }),
        mode,
        h("label", { "data-seg-label": "time", class: "visually-hidden" }),
        h("div", { class: "input-unit" }, input("time"), h("span", { class: "unit", "data-seg-unit": "time" })),
        h("p", { class: "field-error", hidden: true }),
      ),
      cell("jerk_share", input("jerk_share", { placeholder: "0" })),
      cell("process_load", input("process_load", { placeholder: "0" })),
    ),
  );
  const set = (kind, value) => {
    const el = li.querySelector(`[data-seg="${kind}"]`);
    el.value = numberText(value, lang);
  };
  set("speed", values.speed);
  const byAccel = typeof values.accel === "number";
  mode.value = byAccel ? "accel" : "duration_s";
  set("time", byAccel ? values.accel : values.duration_s);
  set("jerk_share", values.jerk_share || null);
  set("process_load", values.process_load || null);
  return li;
}

/** Ids, request paths, labels and units of every row after a change (index k = position). */
function relabel() {
  const t = (key, params) => translate(lang, key, params);
  const rows = $$as(":scope > li", HTMLLIElement, list());
  rows.forEach((li, k) => {
    const n = k + 1;
    li.dataset.index = String(k);
    li.querySelector(".segment-title").textContent = t("seg.title", { n });
    const mode = $as('[data-seg="mode"]', HTMLSelectElement, li);
    const paths = {
      speed: "speed",
      time: mode.value,
      jerk_share: "jerk_share",
      process_load: "process_load",
    };
    for (const [kind, field] of Object.entries(paths)) {
      const el = $as(`[data-seg="${kind}"]`, HTMLInputElement, li);
      const id = `seg-${k}-${kind}`;
      const box = el.closest(".seg-field");
      const error = box.querySelector(".field-error");
      el.id = id;
      el.dataset.path = `cycle.segments.${k}.${field}`;
      error.id = `err-${id}`;
      el.setAttribute("aria-describedby", `u-${id} err-${id}`);
      box.querySelector(`[data-seg-unit="${kind}"]`).id = `u-${id}`;
      box.querySelector(`[data-seg-label="${kind}"]`).setAttribute("for", id);
      showReading(el, lang); // what a comma or point was read as, under the new id
    }
    mode.id = `seg-${k}-mode`;
    li.querySelector('[data-seg-label="mode"]').setAttribute("for", mode.id);
    li.querySelector('[data-seg-label="mode"]').textContent = t("seg.mode");
    mode.options[0].textContent = t("seg.mode.duration");
    mode.options[1].textContent = t("seg.mode.accel");
    li.querySelector('[data-seg-label="speed"]').textContent = t("seg.speed");
    li.querySelector('[data-seg-label="time"]').textContent = t(mode.value === "accel" ? "seg.accel" : "seg.duration");
    li.querySelector('[data-seg-label="jerk_share"]').textContent = t("seg.jerk_share");
    li.querySelector('[data-seg-label="process_load"]').textContent = t("seg.process_load");
    $as('[data-seg="speed"]', HTMLInputElement, li).placeholder = t("seg.speed.same");
    li.querySelector('[data-seg-unit="speed"]').textContent = unitText(lang, units.speed);
    li.querySelector('[data-seg-unit="time"]').textContent = mode.value === "accel" ? unitText(lang, units.accel) : "s";
    li.querySelector('[data-seg-unit="jerk_share"]').textContent = "–";
    li.querySelector('[data-seg-unit="process_load"]').textContent = units.load;
    for (const [action, key] of [["up", "seg.up"], ["down", "seg.down"], ["remove", "seg.remove"]]) {
      const b = $as(`[data-action="${action}"]`, HTMLButtonElement, li);
      b.setAttribute("aria-label", t(key, { n }));
      b.title = t(key, { n });
    }
    $as('[data-action="up"]', HTMLButtonElement, li).disabled = k === 0;
    $as('[data-action="down"]', HTMLButtonElement, li).disabled = k === rows.length - 1;
    $as('[data-action="remove"]', HTMLButtonElement, li).disabled = rows.length === 1;
  });
  const start = document.getElementById("u-seg-start");
  if (start) start.textContent = unitText(lang, units.speed);
}

/** Add a row at the end (or after ``after``); focus its first input. */
export function addSegment(values = {}, { focus = false } = {}) {
  const li = row(values);
  list().append(li);
  relabel();
  if (focus) li.querySelector('[data-seg="speed"]').focus();
  return li;
}

/** Replace every row (a permalink's stored cycle, or the trapezoid's four phases). */
export function fillSegments(segments, startSpeed = 0) {
  list().replaceChildren();
  for (const seg of segments) list().append(row(seg));
  const start = byIdAs("f-seg-start", HTMLInputElement);
  if (start) start.value = startSpeed !== 0 ? numberText(startSpeed, lang) : "";
  relabel();
}

export function segmentCount() {
  return list().children.length;
}

/** @param {HTMLInputElement | null} el */
function numberOrNull(el) {
  return el ? readField(el).value : null;
}

/** The request's cycle: ``{start_speed, segments}``; blank optional inputs are left out. */
export function readSegments() {
  const start = numberOrNull(byIdAs("f-seg-start", HTMLInputElement));
  const segments = [...list().children].map((li) => {
    const get = (kind) => numberOrNull($as(`[data-seg="${kind}"]`, HTMLInputElement, li));
    const seg = {};
    const speed = get("speed");
    if (speed !== null) seg.speed = speed;
    // the chosen one of duration_s / accel always goes, null when blank: the API names it
    seg[$as('[data-seg="mode"]', HTMLSelectElement, li).value] = get("time");
    const jerk = get("jerk_share");
    if (jerk !== null) seg.jerk_share = jerk;
    const load = get("process_load");
    if (load !== null) seg.process_load = load;
    return seg;
  });
  return { start_speed: start ?? 0, segments };
}

/** The units of the chosen load: speed (rpm | mm/s), acceleration and process load (Nm | N). */
export function setSegmentUnits(next) {
  units = next;
  relabel();
}

export function setSegmentLang(next) {
  lang = next;
  relabel();
}

/** Wire the add button and the row buttons; ``onChange`` after any structural change. */
export function initSegments({ onChange }) {
  changed = onChange;
  document.getElementById("seg-add").addEventListener("click", () => {
    addSegment({}, { focus: true });
    changed();
  });
  list().addEventListener("click", (event) => {
    const b = event.target instanceof Element ? event.target.closest("button[data-action]") : null;
    if (!(b instanceof HTMLButtonElement)) return;
    const li = b.closest("li.segment");
    const action = b.dataset.action;
    if (action === "up" && li.previousElementSibling) li.previousElementSibling.before(li);
    else if (action === "down" && li.nextElementSibling) li.nextElementSibling.after(li);
    else if (action === "remove" && list().children.length > 1) {
      const next = li.nextElementSibling ?? li.previousElementSibling;
      li.remove();
      (next && $as("button[data-action]", HTMLButtonElement, next))?.focus();
    } else return;
    relabel();
    if (action !== "remove") b.focus();
    changed();
  });
  list().addEventListener("change", (event) => {
    if (event.target instanceof Element && event.target.matches('[data-seg="mode"]')) {
      relabel();
      changed();
    }
  });
}
