// The kinds of load and their inputs, as the API declares them (mechanism-spec.js, made by
// `make mechanisms` from the request models; GET /api/v1/mechanisms answers the same):
// the choice of kind, each kind's fieldset with its fields' symbols and units, a line sketch
// per mechanism and, where the kind takes one, an optional transmission between the
// actuator output and the mechanism. Each kind's fieldset is built into the form when first
// chosen; texts carry data-i18n keys, so the language switch relabels them like the static
// page.
// Nothing is converted here: numbers (or, where the API takes it, text with a unit,
// "0.5 in") go to the API as typed, read by lib/numbers.js (a decimal comma as a point:
// "0,5 in" goes as "0.5 in").

import { h } from "../../lib/dom.js";
import { SPEC } from "./mechanism-spec.js";

/** @typedef {import("./mechanism-spec.js").FieldSpec} FieldSpec */
/** @typedef {import("./mechanism-spec.js").MechanismSpec} MechanismSpec */

/** Every kind of load, in the API's order; the first is the default. */
export const KINDS = SPEC.kinds;

/** Every kind's ``type`` (``load.type``). */
export const LOAD_KINDS = KINDS.map((kind) => kind.type);

/** The fields of ``load.transmission``. */
export const TRANSMISSION_FIELDS = SPEC.transmission;

/**
 * The spec of load kind ``type``, or undefined.
 * @param {string} type
 * @returns {MechanismSpec | undefined}
 */
export const kindSpec = (type) => KINDS.find((kind) => kind.type === type);

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

/**
 * One input row as the page's static fields are built: label with symbol, input, unit, error.
 * ``units``: the input also takes text with a unit ("0.5 in"), which goes to the API as typed;
 * ``placeholder``: what a blank optional field stands for (the API's default). A blank
 * required field is sent as null, and the API's answer names it at the field.
 * @param {{ id: string, path: string, symbol: string, unit: string, key: string,
 *   required?: boolean, optional?: boolean, units?: boolean, placeholder?: string }} field
 */
export function quantityField({
  id,
  path,
  symbol,
  unit,
  key,
  required = false,
  optional = !required,
  units = true,
  placeholder = undefined,
}) {
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
        "data-quantity": units ? "" : null,
        // a number, or (units) text with a unit ("0.5 in"), read by lib/numbers.js
        "data-number": units ? "units" : "",
        type: "text",
        inputmode: "decimal",
        spellcheck: "false",
        autocomplete: "off",
        placeholder: placeholder ?? null,
        "aria-describedby": `u-${id} err-${id}`,
      }),
      h("span", { class: "unit", id: `u-${id}` }, unit),
    ),
    h("p", { class: "field-error", id: `err-${id}`, hidden: true }),
  );
}

/**
 * The input row of a field of the spec, under ``prefix`` (its id ``f-<kind>-<name>``).
 * @param {FieldSpec} field
 * @param {string} id
 * @param {string} prefix
 */
function specField(field, id, prefix) {
  return quantityField({
    id,
    path: `${prefix}.${field.name}`,
    symbol: field.symbol,
    unit: field.unit,
    key: field.label,
    required: field.required,
    units: field.units,
    placeholder: !field.required && typeof field.default === "number" ? String(field.default) : undefined,
  });
}

/**
 * The fieldset of one kind of load: its fields and, for a mechanism, its sketch, hint and
 * transmission. The first kind (the default, T_L and J_L as they are) is shown without a
 * heading of its own or a server echo; the others start hidden and disabled.
 * @param {MechanismSpec} spec
 * @param {boolean} first
 */
function mechanismFieldset(spec, first) {
  const active = first;
  const kind = spec.type;
  const fields = spec.fields.map((field) => specField(field, `f-${kind}-${field.name}`, "load"));
  const transmission = spec.transmission
    ? [
        h(
          "div",
          { class: "field check-field" },
          h("input", { id: `f-${kind}-tr`, type: "checkbox", class: "transmission-toggle" }),
          h("label", { for: `f-${kind}-tr`, "data-i18n": "mech.tr.legend" }),
        ),
        h(
          "fieldset",
          { class: "transmission", "data-path": "load.transmission", disabled: true, hidden: true },
          h("legend", { class: "visually-hidden", "data-i18n": "mech.tr.legend" }),
          TRANSMISSION_FIELDS.map((field) => specField(field, `f-${kind}-tr-${field.name}`, "load.transmission")),
        ),
      ]
    : [];
  const legend = active
    ? h("legend", { class: "visually-hidden", "data-i18n": spec.label })
    : h(
        "legend",
        { class: "sub-legend" },
        h("span", { "data-i18n": spec.label }),
        spec.equation ? [" · ", h("span", { "data-i18n": spec.equation })] : null,
      );
  const drawing = spec.hint ? sketch(kind) : null;
  return h(
    "fieldset",
    {
      class: first ? "mechanism" : "mechanism generated",
      id: `mech-${kind}`,
      "data-kind": kind,
      hidden: !active,
      disabled: !active,
    },
    legend,
    drawing || spec.hint
      ? h("div", { class: "sketch-box" }, drawing, spec.hint ? h("p", { class: "hint", "data-i18n": spec.hint }) : null)
      : null,
    fields,
    transmission,
    active
      ? null
      : h(
          "div",
          { class: "resolved", "aria-live": "polite" },
          h("span", { class: "resolved-label", "data-i18n": "resolved.label" }),
          h("span", { class: "resolved-values" }),
        ),
  );
}

/** Where the kinds' fieldsets go (``renderMechanisms``), and what follows a new one's build. */
let placement = null;

/**
 * The choice of kind (radio buttons named ``load-kind``, the first checked) into ``choices``,
 * and the first kind's fieldset after ``anchor``; the others are built when first chosen
 * (``kindFieldset``): two thirds of the form's fields are in kinds a user may never choose,
 * and the page's start, its first layout and the browser's own look at the form's fields
 * (autofill) would pay for them.
 * @param {HTMLElement} choices
 * @param {Element} anchor
 * @param {(fieldset: HTMLFieldSetElement) => void} onBuilt what a fieldset built later needs
 *   (its texts in the page's language)
 */
export function renderMechanisms(choices, anchor, onBuilt) {
  choices.append(
    ...KINDS.map((spec, k) =>
      h(
        "label",
        { class: "choice" },
        h("input", { type: "radio", name: "load-kind", value: spec.type, checked: k === 0 }),
        " ",
        h("span", { "data-i18n": spec.label }),
      ),
    ),
  );
  placement = { anchor, onBuilt: null };
  kindFieldset(KINDS[0].type);
  placement.onBuilt = onBuilt;
}

/**
 * The fieldset of load kind ``type`` (null for none), built the first time it is asked for,
 * after the ones built before, transmission checkbox wired.
 * @param {string} type
 * @returns {HTMLFieldSetElement | null}
 */
export function kindFieldset(type) {
  const built = document.getElementById(`mech-${type}`);
  if (built instanceof HTMLFieldSetElement) return built;
  const spec = kindSpec(type);
  if (!spec || !placement) return null;
  const fs = /** @type {HTMLFieldSetElement} */ (mechanismFieldset(spec, spec === KINDS[0]));
  const sets = document.querySelectorAll("fieldset.mechanism");
  (sets.length ? sets[sets.length - 1] : placement.anchor).after(fs);
  const toggle = fs.querySelector(".transmission-toggle");
  if (toggle instanceof HTMLInputElement) {
    toggle.addEventListener("change", () => setTransmission(fs, toggle.checked));
  }
  placement.onBuilt?.(fs);
  return fs;
}

/**
 * Show (and send) a mechanism's transmission, or not.
 * @param {Element} fs
 * @param {boolean} on
 */
export function setTransmission(fs, on) {
  const toggle = fs.querySelector(".transmission-toggle");
  const box = fs.querySelector("fieldset.transmission");
  if (!(toggle instanceof HTMLInputElement) || !(box instanceof HTMLFieldSetElement)) return;
  toggle.checked = on;
  box.hidden = !on;
  box.disabled = !on;
}
