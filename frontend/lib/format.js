// Number and symbol display. Precision rule, everywhere on the page and in the
// charts' hover labels: 4 significant digits, trailing zeros dropped, no digit
// grouping, a true minus sign (−), the decimal comma in German. This is the
// precision of the API's own messages (Python's "{:.4g}"), so a value in a table
// cell reads the same as in the message next to it.

import { unitText } from "./i18n.js";

const MINUS = "\u2212";
const NARROW_NBSP = "\u202f";
const formatters = new Map();
const dateFormatters = new Map();

export function localeOf(lang) {
  return lang === "de" ? "de-DE" : "en-GB";
}

function formatter(lang) {
  let f = formatters.get(lang);
  if (!f) {
    f = new Intl.NumberFormat(localeOf(lang), { maximumSignificantDigits: 4, useGrouping: false });
    formatters.set(lang, f);
  }
  return f;
}

/**
 * ``lang``'s number format set up ahead of its first number: the first
 * ``Intl.NumberFormat`` of a page loads ICU's locale data, 15–25 ms of the main thread
 * here, which would otherwise fall on the user's first input (or the example's click).
 */
export function prepareNumbers(lang) {
  formatter(lang);
}

/** ``value`` with 4 significant digits in ``lang``; "–" for a missing value. */
export function num(value, lang) {
  if (typeof value !== "number" || !Number.isFinite(value)) return "–";
  const text = formatter(lang).format(value === 0 ? 0 : value);
  return text.replace("-", MINUS);
}

/** ``value`` and its unit, e.g. "95,48 Nm" or "40 min⁻¹". */
export function qty(value, unit, lang) {
  const n = num(value, lang);
  if (n === "–" || !unit) return n;
  return `${n}${NARROW_NBSP}${unitText(lang, unit)}`;
}

/** A moment of the API (ISO 8601) in the browser's time zone, e.g. "12 Mar 2025, 14:05"; null if unreadable. */
export function dateTime(iso, lang) {
  const date = typeof iso === "string" ? new Date(iso) : null;
  if (!date || Number.isNaN(date.getTime())) return null;
  let f = dateFormatters.get(lang);
  if (!f) {
    f = new Intl.DateTimeFormat(localeOf(lang), { dateStyle: "medium", timeStyle: "short" });
    dateFormatters.set(lang, f);
  }
  return f.format(date);
}

export { appendSymbols, plainSymbols } from "./symbols.js";
