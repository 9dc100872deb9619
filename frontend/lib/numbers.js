// Numbers as people type them, read the same on both pages and in every browser locale.
//
// The fields are text inputs (inputmode="decimal"), not <input type="number">: Chromium's
// number input reads "1,3" as 13 in a German (and an English) locale. Here one decimal
// mark is accepted, a comma or a point alike ("1,3" and "1.3" are 1.3), with a leading
// sign and an exponent as the number inputs took them ("-40", "1e-3"). Text with both
// marks, or with a mark twice ("1.300,5", "1,300.5", "1.000.000"), is refused: it is a
// number with thousands separators, and which mark is the decimal one cannot be told.
// What was typed is never rewritten; what was understood is shown beside the field when
// the text's mark is not the page's own (the "1.300" a German reader may mean as 1300).

import { translate } from "./i18n.js";

/** A number: sign, digits with at most one mark, then an exponent; the rest is the unit. */
const NUMBER = /^([+-]?)(\d*)([.,]?)(\d*)([eE][+-]?\d+)?(?![\d.,])(.*)$/s;
/** Any run of digits and marks, for telling "1.300,5" (ambiguous) from "abc" (no number). */
const MARKED = /^[+-]?[\d.,]*\d[\d.,]*/;

/**
 * What ``text`` says as a number: ``{ state, value, decimal, rest, mark }``.
 *
 * ``state`` is "empty" (blank), "number" (``value`` the number, ``decimal`` the text the
 * API reads: the typed text with its comma as a point), "quantity" (only with ``units``:
 * a number and then more text, e.g. "0,5 in", ``decimal`` "0.5 in" for the API to read
 * with its unit), "ambiguous" (more than one mark) or "invalid" (no number at all; with
 * ``units`` such text goes to the API as typed, which names what is wrong with it).
 * ``mark`` is the decimal mark typed ("," or "." or "").
 */
export function readNumber(text, { units = false } = {}) {
  const trimmed = String(text ?? "").trim();
  if (trimmed === "") return { state: "empty", value: null, decimal: "", rest: "", mark: "" };
  const marked = MARKED.exec(trimmed)?.[0] ?? "";
  if ((marked.match(/[.,]/g) ?? []).length > 1) {
    return { state: "ambiguous", value: null, decimal: trimmed, rest: "", mark: "" };
  }
  const match = NUMBER.exec(trimmed);
  const [, sign, whole, mark, fraction, exponent = "", rest] = match ?? [];
  const digits = Boolean(whole || fraction);
  const rawRest = rest ?? "";
  if (!match || !digits || (rawRest.trim() !== "" && !units)) {
    return { state: "invalid", value: null, decimal: trimmed, rest: "", mark: "" };
  }
  const plain = `${sign}${whole}${mark ? "." : ""}${fraction}${exponent}`;
  const value = Number(plain);
  if (!Number.isFinite(value)) return { state: "invalid", value: null, decimal: trimmed, rest: "", mark };
  if (rawRest.trim() !== "") {
    return { state: "quantity", value, decimal: `${plain}${rawRest}`, rest: rawRest, mark };
  }
  return { state: "number", value, decimal: plain, rest: "", mark };
}

/** The i18n key of the message for a refused reading, or null when it is accepted. */
export function refusalKey(reading, { units = false } = {}) {
  if (reading.state === "ambiguous") return "number.ambiguous";
  if (reading.state === "invalid" && !units) return "number.invalid";
  return null;
}

/** ``lang``'s decimal mark: "," in German, "." in English. */
export const decimalMark = (lang) => (lang === "de" ? "," : ".");

/**
 * What was understood, in ``lang``'s way of writing it ("1,3" or "0.5 in"): only when the
 * typed mark is not ``lang``'s own (else the text already says it); "" otherwise. Every
 * digit is kept: the number itself, not a rounded echo.
 */
export function readingText(reading, lang) {
  if (!["number", "quantity"].includes(reading.state) || !reading.mark) return "";
  if (reading.mark === decimalMark(lang)) return "";
  const number = String(reading.value).replace(".", decimalMark(lang)).replaceAll("-", "\u2212");
  return `${number}${reading.rest}`;
}

/**
 * A number the page writes into a field (the example, a stored selection), in ``lang``'s
 * way ("1,3" in German): read back as the same number, with no reading to show.
 */
export function numberText(value, lang) {
  return typeof value === "number" && Number.isFinite(value) ? String(value).replace(".", decimalMark(lang)) : "";
}

/** Whether ``el`` is one of the number fields (data-number; "units" when it takes a unit). */
export const isNumberField = (el) => el instanceof HTMLInputElement && el.dataset.number !== undefined;

/** The reading of a number field as it stands. */
export function readField(input) {
  return readNumber(input.value, { units: input.dataset.number === "units" });
}

/** The i18n key of the message refusing a number field's text, or null when it reads. */
export function fieldRefusal(input) {
  return refusalKey(readField(input), { units: input.dataset.number === "units" });
}

/**
 * Show beside ``input`` what it was read as, in ``lang``: a quiet line after the input
 * (and its unit), named by the input's aria-describedby; made on first use, hidden when
 * there is nothing to add.
 */
export function showReading(input, lang) {
  if (!isNumberField(input) || !input.id) return;
  const text = readingText(readField(input), lang);
  const box = input.parentElement?.classList.contains("input-unit") ? input.parentElement : input;
  let el = box.nextElementSibling?.classList.contains("number-reading") ? box.nextElementSibling : null;
  if (!el && !text) return;
  if (!el) {
    el = document.createElement("p");
    el.className = "number-reading";
    box.after(el);
  }
  el.id = `read-${input.id}`;
  const ids = (input.getAttribute("aria-describedby") ?? "").split(/\s+/).filter(Boolean);
  if (!ids.includes(el.id)) input.setAttribute("aria-describedby", [...ids, el.id].join(" "));
  el.textContent = text ? translate(lang, "number.read", { value: text }) : "";
  el.hidden = !text;
}

/** ``showReading`` for every number field under ``root``. */
export function showReadings(root, lang) {
  for (const input of root.querySelectorAll("input[data-number]")) showReading(input, lang);
}
