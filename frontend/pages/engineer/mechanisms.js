// The mechanisms of the API's `load.type` beyond the chapter's two (schemas/mechanisms.py):
// their inputs with symbols and units, a small line sketch each, and an optional
// transmission between the actuator output and the mechanism. Built once into the form;
// texts carry data-i18n keys, so the language switch relabels them like the static page.
// Nothing is converted here: numbers (or text with a unit, "0.5 in") go to the API as typed,
// read by lib/numbers.js (a decimal comma as a point: "0,5 in" goes as "0.5 in").

import { h } from "../../lib/dom.js";

/** A field: request name, symbol, unit as shown, i18n key, required or optional. */
const f = (name, symbol, unit, key, required = false) => ({ name, symbol, unit, key, required });

const MASS = (name = "mass_kg", key = "mech.mass") => f(name, "m", "kg", key, true);
const FRICTION = f("friction_coefficient", "μ", "–", "load.friction", true);
const EFFICIENCY = f("efficiency", "η", "–", "load.efficiency", true);
const INCLINE = f("incline_deg", "θ", "°", "mech.incline");
const COUNTERWEIGHT = f("counterweight_kg", "m_c", "kg", "mech.counterweight");
const FRICTION_FORCE = f("friction_force_n", "F_R", "N", "mech.friction_force");

/** Every mechanism: `linear` ones take their speed in mm/s, the rotary one in rpm. */
export const MECHANISMS = {
  belt: {
    linear: true,
    fields: [
      MASS(),
      f("pulley_diameter_mm", "D", "mm", "mech.pulley_diameter", true),
      FRICTION,
      EFFICIENCY,
      INCLINE,
      f("belt_mass_kg", "m_B", "kg", "mech.belt_mass"),
      f("pulley_inertia_kgm2", "J_D", "kgm²", "mech.pulley_inertia"),
      f("idler_inertia_kgm2", "J_I", "kgm²", "mech.idler_inertia"),
      f("idler_diameter_mm", "D_I", "mm", "mech.idler_diameter"),
      COUNTERWEIGHT,
      FRICTION_FORCE,
    ],
  },
  rack_pinion: {
    linear: true,
    fields: [
      MASS(),
      f("pinion_diameter_mm", "d", "mm", "mech.pinion_diameter", true),
      FRICTION,
      EFFICIENCY,
      INCLINE,
      f("pinion_inertia_kgm2", "J_P", "kgm²", "mech.pinion_inertia"),
      COUNTERWEIGHT,
      FRICTION_FORCE,
    ],
  },
  ball_screw_incline: {
    linear: true,
    fields: [
      MASS(),
      f("lead_mm", "P", "mm", "load.lead", true),
      FRICTION,
      EFFICIENCY,
      INCLINE,
      f("screw_inertia_kgm2", "J_S", "kgm²", "load.screw_inertia"),
      COUNTERWEIGHT,
      FRICTION_FORCE,
    ],
  },
  lift: {
    linear: true,
    fields: [
      MASS("load_mass_kg", "mech.lift_mass"),
      f("drum_diameter_mm", "D", "mm", "mech.drum_diameter", true),
      EFFICIENCY,
      COUNTERWEIGHT,
      f("drum_inertia_kgm2", "J_D", "kgm²", "mech.drum_inertia"),
      FRICTION_FORCE,
    ],
  },
  conveyor: {
    linear: true,
    fields: [
      MASS("load_mass_kg", "mech.conveyor_load"),
      f("belt_mass_kg", "m_B", "kg", "mech.belt_mass", true),
      f("roller_diameter_mm", "D", "mm", "mech.roller_diameter", true),
      FRICTION,
      EFFICIENCY,
      INCLINE,
      f("drive_roller_inertia_kgm2", "J_D", "kgm²", "mech.drive_roller_inertia"),
      f("tail_roller_inertia_kgm2", "J_T", "kgm²", "mech.tail_roller_inertia"),
      f("tail_roller_diameter_mm", "D_T", "mm", "mech.tail_roller_diameter"),
      FRICTION_FORCE,
    ],
  },
  rotary: {
    linear: false,
    fields: [
      f("inertia_kgm2", "J", "kgm²", "load.inertia", true),
      f("friction_torque_nm", "T_F", "Nm", "mech.friction_torque"),
      f("gravity_torque_nm", "T_G", "Nm", "mech.gravity_torque"),
      f("efficiency", "η", "–", "load.efficiency"),
    ],
  },
};

export const MECHANISM_KINDS = Object.keys(MECHANISMS);

export const TRANSMISSION_FIELDS = [
  f("ratio", "i", "–", "mech.tr.ratio", true),
  f("inertia_kgm2", "J_tr", "kgm²", "mech.tr.inertia"),
  f("efficiency", "η_tr", "–", "mech.tr.efficiency"),
];

// ---------------------------------------------------------------- sketches

const SVG = "http://www.w3.org/2000/svg";

function s(tag, attrs = {}, ...children) {
  const el = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, String(v));
  for (const c of children.flat()) el.append(c instanceof Node ? c : document.createTextNode(String(c)));
  return el;
}

const line = (x1, y1, x2, y2, extra = {}) => s("line", { x1, y1, x2, y2, ...extra });
const circle = (cx, cy, r, extra = {}) => s("circle", { cx, cy, r, ...extra });
const rect = (x, y, width, height, extra = {}) => s("rect", { x, y, width, height, ...extra });
const text = (x, y, t, extra = {}) => s("text", { x, y, ...extra }, t);
// the arrowhead marker's id, one per sketch (ids are unique in the page)
let arrowId = "sk-arrow";
const arrow = (x1, y1, x2, y2) => line(x1, y1, x2, y2, { "marker-end": `url(#${arrowId})` });
const motor = (x, y) => [rect(x, y, 14, 12, { class: "sk-motor" }), text(x + 7, y + 9, "M", { "text-anchor": "middle" })];
const gear = (cx, cy, r) => [circle(cx, cy, r), circle(cx, cy, 1.5, { class: "sk-fill" })];

/** Simple line drawings, one per mechanism (no external asset, no script). */
const SKETCHES = {
  belt: () => [
    ...gear(20, 34, 9),
    ...gear(104, 34, 9),
    line(20, 25, 104, 25),
    line(20, 43, 104, 43),
    rect(50, 14, 22, 11, { class: "sk-mass" }),
    text(61, 22, "m", { "text-anchor": "middle" }),
    arrow(76, 10, 96, 10),
    text(98, 12, "v"),
    text(20, 58, "D", { "text-anchor": "middle" }),
  ],
  rack_pinion: () => [
    line(6, 44, 114, 44),
    s("polyline", { points: "6,44 10,40 14,44 18,40 22,44 26,40 30,44 34,40 38,44 42,40 46,44 50,40 54,44 58,40 62,44 66,40 70,44 74,40 78,44 82,40 86,44 90,40 94,44 98,40 102,44 106,40 110,44" }),
    ...gear(44, 29, 10),
    rect(32, 8, 24, 10, { class: "sk-mass" }),
    text(44, 16, "m", { "text-anchor": "middle" }),
    arrow(64, 12, 84, 12),
    text(86, 14, "v"),
    text(60, 32, "d"),
  ],
  ball_screw_incline: () => [
    ...motor(4, 24),
    line(18, 30, 114, 30),
    s("polyline", { points: "22,27 26,33 30,27 34,33 38,27 42,33 46,27 50,33 54,27 58,33 62,27 66,33 70,27 74,33 78,27 82,33 86,27 90,33 94,27 98,33 102,27 106,33 110,27" }),
    rect(56, 18, 22, 24, { class: "sk-mass" }),
    text(67, 15, "m", { "text-anchor": "middle" }),
    arrow(84, 50, 104, 50),
    text(106, 52, "v"),
    text(30, 50, "P"),
  ],
  lift: () => [
    line(30, 6, 90, 6),
    ...gear(60, 16, 9),
    line(51, 16, 51, 40),
    line(69, 16, 69, 30),
    rect(41, 40, 20, 14, { class: "sk-mass" }),
    text(51, 50, "m", { "text-anchor": "middle" }),
    rect(63, 30, 12, 10),
    text(80, 38, "m"),
    text(86, 40, "c", { "font-size": 6 }),
    arrow(34, 48, 34, 30),
    text(26, 40, "v"),
    text(60, 32, "D", { "text-anchor": "middle" }),
  ],
  conveyor: () => [
    ...gear(16, 38, 8),
    ...gear(104, 38, 8),
    line(16, 30, 104, 30),
    line(16, 46, 104, 46),
    rect(36, 20, 12, 10, { class: "sk-mass" }),
    rect(62, 20, 12, 10, { class: "sk-mass" }),
    text(56, 16, "m", { "text-anchor": "middle" }),
    text(60, 16, "L", { "font-size": 6 }),
    arrow(80, 12, 100, 12),
    text(102, 14, "v"),
    text(16, 58, "D", { "text-anchor": "middle" }),
  ],
  rotary: () => [
    s("ellipse", { cx: 60, cy: 24, rx: 40, ry: 10 }),
    line(60, 24, 60, 52),
    ...motor(53, 44),
    s("path", { d: "M 86 36 A 34 9 0 0 1 40 35", "marker-end": `url(#${arrowId})` }),
    text(104, 26, "J"),
  ],
};

/** The mechanism's sketch: an inline SVG with a text alternative from the i18n catalogue. */
export function sketch(kind) {
  const draw = SKETCHES[kind];
  if (!draw) return null;
  arrowId = `sk-arrow-${kind}`;
  const svg = s(
    "svg",
    {
      class: "sketch",
      viewBox: "0 0 120 60",
      width: 120,
      height: 60,
      role: "img",
      "data-i18n-attr": `aria-label:sketch.${kind}`,
      "data-sketch": kind,
    },
    s(
      "defs",
      {},
      s(
        "marker",
        { id: arrowId, viewBox: "0 0 6 6", refX: 5, refY: 3, markerWidth: 5, markerHeight: 5, orient: "auto" },
        s("path", { d: "M0,0 L6,3 L0,6 z", class: "sk-fill" }),
      ),
    ),
    draw(),
  );
  return svg;
}

// ---------------------------------------------------------------- fields

/** One input row as the page's static fields are built: label with symbol, input, unit, error. */
export function quantityField({ id, path, symbol, unit, key, required, optional = !required }) {
  const [letter, sub] = symbol.split("_");
  return h(
    "div",
    { class: "field" },
    h(
      "label",
      { for: id },
      h("span", { "data-i18n": key }),
      optional ? [" ", h("span", { class: "optional", "data-i18n": "mech.optional" })] : null,
      " ",
      h("span", { class: "sym" }, h("var", {}, letter), sub ? h("sub", {}, sub) : null),
    ),
    h(
      "div",
      { class: "input-unit" },
      h("input", {
        id,
        "data-path": path,
        "data-quantity": "",
        // a number, or text with a unit ("0.5 in"), read by lib/numbers.js
        "data-number": "units",
        type: "text",
        inputmode: "decimal",
        spellcheck: "false",
        autocomplete: "off",
        "aria-describedby": `u-${id} err-${id}`,
      }),
      h("span", { class: "unit", id: `u-${id}` }, unit),
    ),
    h("p", { class: "field-error", id: `err-${id}`, hidden: true }),
  );
}

/** The fieldset of one mechanism: sketch, required fields, optional ones, transmission. */
function mechanismFieldset(kind) {
  const spec = MECHANISMS[kind];
  const fields = spec.fields.map((field) =>
    quantityField({ id: `f-${kind}-${field.name}`, path: `load.${field.name}`, ...field }),
  );
  const transmission = h(
    "fieldset",
    { class: "transmission", "data-path": "load.transmission", disabled: true, hidden: true },
    h("legend", { class: "visually-hidden", "data-i18n": "mech.tr.legend" }),
    TRANSMISSION_FIELDS.map((field) =>
      quantityField({ id: `f-${kind}-tr-${field.name}`, path: `load.transmission.${field.name}`, ...field }),
    ),
  );
  const toggle = h(
    "div",
    { class: "field check-field" },
    h("input", { id: `f-${kind}-tr`, type: "checkbox", class: "transmission-toggle" }),
    h("label", { for: `f-${kind}-tr`, "data-i18n": "mech.tr.legend" }),
  );
  return h(
    "fieldset",
    { class: "mechanism generated", id: `mech-${kind}`, "data-kind": kind, hidden: true, disabled: true },
    h(
      "legend",
      { class: "sub-legend" },
      h("span", { "data-i18n": `load.${kind}` }),
    ),
    h("div", { class: "sketch-box" }, sketch(kind), h("p", { class: "hint", "data-i18n": `mech.${kind}.hint` })),
    fields,
    toggle,
    transmission,
    h(
      "div",
      { class: "resolved", "aria-live": "polite" },
      h("span", { class: "resolved-label", "data-i18n": "resolved.label" }),
      h("span", { class: "resolved-values" }),
    ),
  );
}

/** Build every mechanism's fieldset after ``anchor``; transmission checkboxes wired. */
export function renderMechanisms(anchor) {
  const sets = MECHANISM_KINDS.map(mechanismFieldset);
  anchor.after(...sets);
  for (const fs of sets) {
    const toggle = fs.querySelector(".transmission-toggle");
    toggle.addEventListener("change", () => setTransmission(fs, toggle.checked));
  }
  return sets;
}

/** Show (and send) a mechanism's transmission, or not. */
export function setTransmission(fs, on) {
  const toggle = fs.querySelector(".transmission-toggle");
  const box = fs.querySelector("fieldset.transmission");
  if (!toggle || !box) return;
  toggle.checked = on;
  box.hidden = !on;
  box.disabled = !on;
}
