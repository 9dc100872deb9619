// The chapter's symbols in text: X_sub → X with a subscript.
// Kept apart so that both i18n.js and format.js can use it without a cycle.

// The chapter's symbols are written X_sub in texts and in the API's messages
// (n_2, T_rms, J_A, n_max). A lone letter, then "_", then the subscript.
const SYMBOL = /(^|[^A-Za-z0-9_])([A-Za-z])_([A-Za-z0-9]+)/g;

/** Append ``text`` to ``el`` with X_sub written as X<sub>sub</sub> (no HTML parsing). */
export function appendSymbols(el, text) {
  const source = String(text ?? "");
  let last = 0;
  for (const m of source.matchAll(SYMBOL)) {
    const start = m.index + m[1].length;
    el.append(source.slice(last, start) + m[2]);
    const sub = document.createElement("sub");
    sub.textContent = m[3];
    el.append(sub);
    last = m.index + m[0].length;
  }
  el.append(source.slice(last));
  return el;
}

/** ``text`` with X_sub as plain "Xsub", for attributes read aloud by screen readers. */
export function plainSymbols(text) {
  return String(text ?? "").replace(SYMBOL, (_, before, letter, sub) => `${before}${letter}${sub}`);
}
