// A check of a selection's answer in the page's words, for both pages.
//
// The selection answers each check lean, as numbers: name, status, value, limit, and
// for no_data the catalogue value that is missing (English words). Unit and reference
// are the rule's, listed once per selection in ``check_rules``; the check in words
// (the server's message) comes with a candidate's detail only.

import { h, sym } from "./dom.js";
import { qty } from "./format.js";
import { translate, translateWords } from "./i18n.js";

/** The check's label in ``lang`` ("Acceleration torque T_1 ≤ T_max"); its name if unknown. */
export function checkLabel(name, lang) {
  const key = `check.${name}`;
  const text = translate(lang, key);
  return text === key ? String(name) : text;
}

/** The check's short label ("T_1 ≤ T_max"); else its label. */
export function shortCheckLabel(name, lang) {
  const key = `check.short.${name}`;
  const text = translate(lang, key);
  return text === key ? checkLabel(name, lang) : text;
}

/**
 * A check's status in ``lang`` ("pass" → "erfüllt"); a status the page has no word for
 * (one the API added since) as the API names it, without its underscores.
 */
export function statusText(status, lang) {
  const key = `status.${status}`;
  const text = translate(lang, key);
  return text === key ? String(status).replaceAll("_", " ") : text;
}

/** The selection's rule of a check, ``{name, reference, unit}``, or null. */
export function checkRule(selection, name) {
  const rules = Array.isArray(selection?.check_rules) ? selection.check_rules : [];
  return rules.find((r) => r && r.name === name) ?? null;
}

/** Headroom (limit − value)/limit · 100 [%] as the API defines it; null without a positive limit. */
export function marginPercent(check) {
  const { value, limit } = check ?? {};
  if (typeof value !== "number" || typeof limit !== "number" || !(limit > 0)) return null;
  return ((limit - value) / limit) * 100;
}

/**
 * What a check found, as nodes: for no_data the missing catalogue value (the API's
 * English words, in ``lang`` where the page has them: ``words.…`` of i18n.js), else the value against the limit in the rule's ``unit``
 * ("95.48 Nm, limit 151 Nm"; "≈" before an approximate limit); for a fail on a lower
 * bound (a fail with ``missing``) the least value over every value of what is missing.
 */
export function checkFinding(check, unit, lang) {
  if (check.status === "no_data") {
    const words = typeof check.missing === "string" && check.missing ? translateWords(lang, check.missing) : null;
    const what = words ? sym(words.text, { lang: words.lang }) : "–";
    const [before, after = ""] = translate(lang, "check.finding.missing").split("{what}");
    return h("span", { class: "finding" }, before, what, after);
  }
  const approx = check.approximate && typeof check.limit === "number" ? "≈ " : "";
  if (check.status === "fail" && typeof check.missing === "string" && check.missing) {
    // a lower bound: the check fails whatever the missing value (J_A) is
    return h(
      "span",
      { class: "finding" },
      translate(lang, "check.finding.floor", {
        value: qty(check.value, unit, lang),
        limit: `${approx}${qty(check.limit, unit, lang)}`,
        what: translateWords(lang, check.missing).text,
      }),
    );
  }
  return h(
    "span",
    { class: "finding" },
    translate(lang, "check.finding.against", {
      value: qty(check.value, unit, lang),
      limit: `${approx}${qty(check.limit, unit, lang)}`,
    }),
  );
}

/** The statuses that make a check one of a candidate's reasons (neither pass nor not_applicable). */
const OPEN = new Set(["fail", "warn", "no_data"]);

/** The checks that did not pass (failed, warned or lacked data), in the selection's order;
 * a check that does not apply is none of them. */
export function openChecks(candidate) {
  return (Array.isArray(candidate?.checks) ? candidate.checks : []).filter((c) => c && OPEN.has(c.status));
}

/** One line per check that did not pass, "label (status) – finding", in ``lang``. */
export function openCheckLines(selection, candidate, lang) {
  return openChecks(candidate).map((c) =>
    h(
      "span",
      { class: "open-check", "data-check": c.name },
      sym(checkLabel(c.name, lang)),
      ` (${statusText(c.status, lang)}) – `,
      checkFinding(c, checkRule(selection, c.name)?.unit, lang),
    ),
  );
}
