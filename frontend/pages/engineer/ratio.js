// The ratio study of the request on the form (POST /selections/ratio-study, issue 31 part
// 1): the free value and its range asked, the answer's intervals as a table and its chart
// as the API defines it (documents/figures.py: ratio_figure), drawn with plotly.js. Nothing
// engineering is computed here.

import { h, notice } from "../../lib/dom.js";
import { num } from "../../lib/format.js";
import { translate } from "../../lib/i18n.js";

/** @typedef {import("../../lib/api.js").Schemas["RatioStudyOut"]} RatioStudyOut */

/** The free values and the range asked where the form gives none (schemas/ratio.py). */
export const RATIO_VARIABLES = {
  ratio: [1, 20],
  lead_mm: [5, 50],
  pulley_diameter_mm: [20, 200],
  pinion_diameter_mm: [20, 200],
  drum_diameter_mm: [20, 200],
  roller_diameter_mm: [20, 200],
};

/** How many actuators the table lists (those with a curve first: the chart's). */
const LISTED = 10;

/** The free values the request's load allows: an external ratio, and the load's own lead or diameter. */
export function ratioVariables(body) {
  const load = body?.load ?? {};
  return Object.keys(RATIO_VARIABLES).filter((v) => v === "ratio" || Object.hasOwn(load, v));
}

/**
 * The study's section: the free value and its range, a button; below it ``view``'s state
 * (``null`` | ``{status: "loading" | "ready" | "failed", answer, error}``). ``onRun`` is
 * called with ``{variable, min, max}``.
 */
export function renderRatioStudy(variables, view, lang, onRun) {
  const t = (k, p) => translate(lang, k, p);
  const select = h(
    "select",
    { id: "ratio-variable", name: "ratio-variable" },
    variables.map((v) => h("option", { value: v }, t(`fig.ratio.${v}`))),
  );
  const [low, high] = RATIO_VARIABLES[variables[0]];
  const min = h("input", { id: "ratio-min", type: "number", min: "0", step: "any", value: String(low) });
  const max = h("input", { id: "ratio-max", type: "number", min: "0", step: "any", value: String(high) });
  if (view?.asked) {
    select.value = view.asked.variable;
    min.value = String(view.asked.min);
    max.value = String(view.asked.max);
  }
  select.addEventListener("change", () => {
    const [a, b] = RATIO_VARIABLES[select.value];
    min.value = String(a);
    max.value = String(b);
  });
  const run = h(
    "button",
    {
      type: "button",
      id: "ratio-run",
      onclick: () => onRun({ variable: select.value, min: Number(min.value), max: Number(max.value) }),
    },
    t("ratio.run"),
  );
  return h(
    "section",
    { class: "card ratio-study", id: "ratio-study", "aria-labelledby": "ratio-heading", "aria-busy": String(view?.status === "loading") },
    h("h2", { id: "ratio-heading" }, t("ratio.heading")),
    h("p", { class: "muted" }, t("ratio.intro")),
    h(
      "div",
      { class: "ratio-ask" },
      h("label", { for: "ratio-variable" }, t("ratio.variable")),
      select,
      h("label", { for: "ratio-min" }, t("ratio.min")),
      min,
      h("label", { for: "ratio-max" }, t("ratio.max")),
      max,
      run,
    ),
    renderAnswer(view, lang),
  );
}

function renderAnswer(view, lang) {
  const t = (k, p) => translate(lang, k, p);
  if (!view) return null;
  if (view.status === "loading") return h("p", { class: "muted loading" }, t("ratio.running"));
  if (view.status === "failed") return notice("warn", h("p", {}, view.error?.message ?? t("ratio.failed")));
  /** @type {RatioStudyOut} */
  const answer = view.answer;
  const fitting = answer.actuators.filter((a) => a.intervals.length);
  if (!fitting.length) return notice("info", h("p", {}, t("ratio.none")));
  const unit = answer.unit === "-" ? "" : ` ${answer.unit}`;
  const value = (x) => `${num(x, lang)}${unit}`;
  const rows = fitting.slice(0, LISTED).map((a) =>
    h(
      "tr",
      { dataset: { model: a.model } },
      h("th", { scope: "row", translate: "no" }, a.model),
      h("td", {}, a.intervals.map((i) => `${value(i.low)} – ${value(i.high)}`).join("; ")),
      h("td", {}, a.best === null ? "–" : value(a.best)),
      h("td", {}, a.best_utilisation === null ? "–" : num(a.best_utilisation, lang)),
      h("td", {}, a.best_binding === null ? "–" : t(`check.${a.best_binding}`)),
    ),
  );
  return h(
    "div",
    { class: "ratio-answer" },
    h(
      "div",
      { class: "table-scroll" },
      h(
        "table",
        { id: "ratio-table" },
        h(
          "thead",
          {},
          h(
            "tr",
            {},
            ["ratio.col.model", "ratio.col.intervals", "ratio.col.best", "ratio.col.utilisation", "ratio.col.binding"].map((k) =>
              h("th", { scope: "col" }, t(k)),
            ),
          ),
        ),
        h("tbody", {}, rows),
      ),
    ),
    h(
      "figure",
      { class: "chart-figure" },
      h("figcaption", {}, h("strong", {}, t("ratio.chart"))),
      h("div", { class: "chart", id: "chart-ratio", "data-state": "loading" }),
    ),
  );
}
