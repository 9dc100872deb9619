// Candidates side by side: the marks in the ranking and the comparison table below it.
//
// Everything shown is the selection's answer as it came: the figures of each candidate
// and its checks as numbers, with unit and reference from ``check_rules``. The margin is
// (limit − value)/limit of those numbers (lib/checks.js ``marginPercent``), as the
// chosen candidate's checks table shows it; nothing else is computed here.

import { checkLabel, checkRule, marginPercent, shortCheckLabel } from "../../lib/checks.js";
import { h, sym } from "../../lib/dom.js";
import { num, plainSymbols } from "../../lib/format.js";
import { translate, translateReference } from "../../lib/i18n.js";
import { statusBadge, valueCell, verdictBadge } from "./results.js";

/** At most this many candidates are compared at once. */
export const MAX_COMPARED = 4;

/** The marks that name a candidate of ``sel``, in their order, without repeats, at most four. */
export function validMarks(sel, models) {
  const known = new Set((sel?.candidates ?? []).map((c) => c.model));
  const out = [];
  for (const m of Array.isArray(models) ? models : []) {
    if (known.has(m) && !out.includes(m) && out.length < MAX_COMPARED) out.push(m);
  }
  return out;
}

/** The checkbox that marks ``model`` for comparison, named by the model. */
export function compareToggle(model, marked, lang, onToggle) {
  return h(
    "label",
    { class: "compare-mark" },
    h("input", {
      type: "checkbox",
      class: "compare-toggle",
      "data-model": model,
      checked: marked,
      "aria-describedby": "compare-status",
      onchange: (event) => onToggle(model, event.target),
    }),
    h("span", { class: "visually-hidden" }, translate(lang, "compare.mark", { model })),
  );
}

/** What the marks come to, politely announced: how many, or why a fifth was refused. */
export function compareStatusText(marks, lang, refused = null) {
  if (refused) return translate(lang, "compare.full", { model: refused, max: MAX_COMPARED });
  if (!marks.length) return translate(lang, "compare.hint", { max: MAX_COMPARED });
  return translate(lang, "compare.count", { n: marks.length, max: MAX_COMPARED });
}

/** The checks of the compared candidates, in the order of ``check_rules`` then as they come. */
function checkNames(sel, candidates) {
  const names = (Array.isArray(sel.check_rules) ? sel.check_rules : []).map((r) => r?.name).filter(Boolean);
  for (const c of candidates) {
    for (const check of Array.isArray(c.checks) ? c.checks : []) {
      if (check && !names.includes(check.name)) names.push(check.name);
    }
  }
  return names.filter((name) => candidates.some((c) => (c.checks ?? []).some((k) => k?.name === name)));
}

/**
 * The comparison of the marked candidates (``models``), one column each: family, ratio,
 * verdict, T_1…T_rms, and per check its value, limit, margin (the largest highlighted)
 * and status. With fewer than two marks, a line asking for more; with none, nothing.
 */
export function renderCompare(sel, models, lang, { onRemove, onClear }) {
  const t = (k, p) => translate(lang, k, p);
  const candidates = models.map((m) => sel.candidates.find((c) => c.model === m)).filter(Boolean);
  if (!candidates.length) return null;
  const heading = h("h3", { id: "compare-heading" }, t("compare.heading"));
  const clear = h(
    "button",
    { type: "button", class: "secondary compare-clear", id: "compare-clear", onclick: onClear },
    t("compare.clear"),
  );
  if (candidates.length < 2) {
    return h(
      "section",
      { class: "card compare", id: "compare", "aria-labelledby": "compare-heading", "data-count": "1" },
      h("div", { class: "compare-head" }, heading, clear),
      h("p", { class: "muted", id: "compare-more" }, t("compare.more", { model: candidates[0].model })),
    );
  }

  const rowHeader = (...content) => h("th", { scope: "row", role: "rowheader" }, ...content);
  const figureRow = (field, label, cell) =>
    h("tr", { role: "row", "data-row": field }, rowHeader(label), candidates.map((c) => h("td", { role: "cell", "data-model": c.model, class: cell.numeric ? "num" : null }, cell.of(c))));
  const torque = (field, symbol) =>
    figureRow(field, [sym(symbol, { class: "sym" }), h("span", { class: "unit" }, " [Nm]")], {
      numeric: true,
      of: (c) => valueCell(c[field], null, lang),
    });

  const figures = h(
    "tbody",
    { role: "rowgroup" },
    figureRow("family", t("detail.family"), { of: (c) => c.family }),
    figureRow("gear_ratio", [t("detail.ratio"), " ", h("span", { class: "sym" }, h("var", {}, "i"))], {
      numeric: true,
      of: (c) => h("span", { class: "value", "data-value": typeof c.gear_ratio === "number" ? String(c.gear_ratio) : null }, num(c.gear_ratio, lang)),
    }),
    figureRow("verdict", t("table.verdict"), { of: (c) => verdictBadge(c.verdict, lang) }),
    torque("accel_torque_nm", "T_1"),
    torque("constant_torque_nm", "T_2"),
    torque("decel_torque_nm", "T_3"),
    torque("rms_torque_nm", "T_rms"),
  );

  const checkGroup = (name) => {
    const rule = checkRule(sel, name);
    const unit = rule?.unit ?? null;
    const found = candidates.map((c) => (c.checks ?? []).find((k) => k?.name === name) ?? null);
    const margins = found.map((k) => (k ? marginPercent(k) : null));
    const numeric = margins.filter((m) => typeof m === "number");
    const best = numeric.length > 1 ? Math.max(...numeric) : null;
    const short = plainSymbols(shortCheckLabel(name, lang));
    const subRow = (part, label, cellOf) =>
      h(
        "tr",
        { role: "row", "data-check": name, "data-part": part },
        rowHeader(h("span", { class: "visually-hidden" }, `${short}: `), label),
        found.map((k, i) => {
          const { children, ...props } = cellOf(k, i);
          return h("td", { role: "cell", "data-model": candidates[i].model, ...props }, children);
        }),
      );
    const missing = () => h("span", { class: "muted" }, "–");
    return h(
      "tbody",
      { role: "rowgroup", class: "compare-check", "data-check": name },
      h(
        "tr",
        { role: "row", class: "compare-check-head" },
        h(
          "th",
          { scope: "colgroup", role: "columnheader", colspan: String(candidates.length + 1) },
          sym(checkLabel(name, lang)),
          rule?.reference ? h("span", { class: "ref" }, ` (${translateReference(lang, rule.reference)})`) : null,
        ),
      ),
      subRow("value", t("detail.value"), (k) => ({
        class: "num",
        children: k ? valueCell(k.value, unit, lang, { "data-field": "value" }) : missing(),
      })),
      subRow("limit", t("detail.limit"), (k) => ({
        class: "num",
        children: k
          ? [
              k.approximate && typeof k.limit === "number" ? h("span", { "aria-hidden": "true" }, "≈ ") : null,
              valueCell(k.limit, unit, lang, { "data-field": "limit" }),
            ]
          : missing(),
      })),
      subRow("margin", t("detail.margin"), (k, i) => {
        const isBest = best !== null && margins[i] === best;
        return {
          class: `num${isBest ? " best" : ""}`,
          "data-best": isBest ? "true" : null,
          children: k
            ? [
                isBest ? h("span", { class: "best-mark", "aria-hidden": "true" }, "▲ ") : null,
                valueCell(margins[i], "%", lang, { "data-field": "margin" }),
                isBest ? h("span", { class: "visually-hidden" }, ` (${t("compare.best")})`) : null,
              ]
            : missing(),
        };
      }),
      subRow("status", t("detail.status"), (k) => ({
        "data-status": k?.status ?? null,
        children: k ? statusBadge(k.status, lang) : missing(),
      })),
    );
  };

  const table = h(
    "table",
    { class: "compare-table", id: "compare-table", role: "table" },
    h("caption", {}, t("compare.caption")),
    h(
      "thead",
      { role: "rowgroup" },
      h(
        "tr",
        { role: "row" },
        h("th", { scope: "col", role: "columnheader" }, t("compare.quantity")),
        candidates.map((c) =>
          h(
            "th",
            { scope: "col", role: "columnheader", "data-model": c.model, class: "compare-model" },
            h("span", { class: "compare-model-name" }, c.model),
            " ",
            h(
              "button",
              {
                type: "button",
                class: "compare-remove",
                "aria-label": t("compare.remove", { model: c.model }),
                title: t("compare.remove", { model: c.model }),
                onclick: () => onRemove(c.model),
              },
              h("span", { "aria-hidden": "true" }, "×"),
            ),
          ),
        ),
      ),
    ),
    figures,
    checkNames(sel, candidates).map(checkGroup),
  );
  return h(
    "section",
    {
      class: "card compare",
      id: "compare",
      "aria-labelledby": "compare-heading",
      "data-count": String(candidates.length),
    },
    h("div", { class: "compare-head" }, heading, clear),
    h("div", { class: "table-scroll", tabindex: "0", role: "region", "aria-label": t("compare.heading") }, table),
  );
}
