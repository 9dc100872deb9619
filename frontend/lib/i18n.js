import { PLOTLY_WORDS, REFERENCE_PATTERN, WORDS } from "./messages.js";
import { appendSymbols, plainSymbols } from "./symbols.js";

// The page's words in German and English come from the gettext catalogue of the server
// (backend/actuator_selection/i18n/locale), exported by `make messages` to ./messages.js
// (docs/i18n.md): add or change a word there, never here. API messages come in the
// language the page asks for (Accept-Language).

export const LANGS = ["de", "en"];
const STORAGE_KEY = "actuator-selection.lang";

/** plotly.js's own words (its mode bar's tooltips) in German, for its ``locales`` config. */
export const PLOTLY_LOCALES = {
  de: { dictionary: PLOTLY_WORDS.de },
};

/** The text for ``key`` in ``lang`` with ``{name}`` placeholders filled (pure). */
export function translate(lang, key, params = {}) {
  const table = WORDS[lang] ?? WORDS.en;
  const text = table[key] ?? WORDS.en[key] ?? key;
  return text.replace(/\{(\w+)\}/g, (whole, name) =>
    Object.hasOwn(params, name) ? String(params[name]) : whole,
  );
}

const REFERENCE_WORDS = new RegExp(REFERENCE_PATTERN, "g");

/** The chapter's reference ("Table 515.1") in ``lang`` ("Tabelle 515.1"). */
export function translateReference(lang, reference) {
  if (typeof reference !== "string") return "";
  // the catalogue's reference words, one rule with the documents' (i18n/localize.py)
  return reference.replace(REFERENCE_WORDS, (word) => refWord(lang, word));
}

/**
 * Words the API sends as they are (English: a check's ``missing`` catalogue value) in
 * ``lang``: ``{ text, lang }``, the words and the language they are in (English where the
 * page has no translation).
 */
export function translateWords(lang, english) {
  const text = WORDS[lang]?.[`words.${english}`];
  return typeof text === "string" ? { text, lang } : { text: english, lang: "en" };
}

/** A word of a reference in ``lang``; the word itself where the catalogue has none. */
function refWord(lang, word) {
  const key = `ref.${word}`;
  const text = translate(lang, key);
  return text === key ? word : text;
}

/** The language remembered in localStorage, else the browser's, else German. */
export function initialLang() {
  try {
    const stored = window.localStorage.getItem(STORAGE_KEY);
    if (LANGS.includes(stored)) return stored;
  } catch {
    // storage may be disabled; fall through to the browser's language
  }
  const preferred = (navigator.languages ?? [navigator.language ?? ""]).map((l) => l.slice(0, 2));
  return preferred.find((l) => LANGS.includes(l)) ?? "de";
}

/** Remember ``lang`` for the next visit. */
export function rememberLang(lang) {
  try {
    window.localStorage.setItem(STORAGE_KEY, lang);
  } catch {
    // not remembered; the page still works
  }
}

/** Fill every [data-i18n] element's text and [data-i18n-attr="attr:key;…"] attributes. */
export function applyStaticTexts(root, lang) {
  for (const el of root.querySelectorAll("[data-i18n]")) {
    el.replaceChildren();
    appendSymbols(el, translate(lang, el.dataset.i18n));
  }
  for (const el of root.querySelectorAll("[data-i18n-attr]")) {
    for (const pair of el.dataset.i18nAttr.split(";")) {
      const [attr, key] = pair.split(":").map((s) => s.trim());
      if (attr && key) el.setAttribute(attr, plainSymbols(translate(lang, key)));
    }
  }
  for (const el of root.querySelectorAll("[data-unit]")) {
    el.textContent = unitText(lang, el.dataset.unit);
  }
}

/** A unit as written in ``lang``: rpm is min⁻¹ in German, as in the chapter. */
export function unitText(lang, unit) {
  if (typeof unit === "string" && unit.startsWith("rpm")) return translate(lang, "unit.rpm") + unit.slice(3);
  return unit ?? "";
}
