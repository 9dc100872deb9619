// DOM helpers shared by both pages. Text from the server only ever goes into the page
// as text nodes or attribute values, never parsed as HTML.

import { appendSymbols } from "./symbols.js";

/**
 * The first element matching ``selector`` under ``root``.
 * @param {string} selector
 * @param {ParentNode} [root]
 */
export const $ = (selector, root = document) => root.querySelector(selector);

/** The element with this id. */
export const byId = (id) => document.getElementById(id);

/**
 * The first element matching ``selector`` under ``root`` if it is a ``type``, else null: a
 * lookup whose kind the type checker knows (``$as("#f-hd", HTMLInputElement).checked``).
 * @template {Element} T
 * @param {string} selector
 * @param {{ new (): T }} type an element class: HTMLInputElement, HTMLSelectElement, …
 * @param {ParentNode} [root]
 * @returns {T | null}
 */
export function $as(selector, type, root = document) {
  const el = root.querySelector(selector);
  return el instanceof type ? el : null;
}

/**
 * Every element matching ``selector`` under ``root`` that is a ``type``, in document order.
 * @template {Element} T
 * @param {string} selector
 * @param {{ new (): T }} type
 * @param {ParentNode} [root]
 * @returns {T[]}
 */
export function $$as(selector, type, root = document) {
  /** @type {T[]} */
  const out = [];
  for (const el of root.querySelectorAll(selector)) if (el instanceof type) out.push(el);
  return out;
}

/**
 * The element with this id if it is a ``type``, else null (``byIdAs("f-qty", HTMLInputElement)``).
 * @template {Element} T
 * @param {string} id
 * @param {{ new (): T }} type
 * @returns {T | null}
 */
export function byIdAs(id, type) {
  const el = document.getElementById(id);
  return el instanceof type ? el : null;
}

/**
 * A DOM element: ``h("td", {class: "num", dataset: {model}, onclick: f}, "1", child)``.
 *
 * Props: ``class``; ``dataset`` (an object); ``on<event>`` functions become listeners;
 * anything else is an attribute (``true`` → present and empty; ``null``, ``undefined``
 * and ``false`` → left out). Children may be nested arrays; ``null``, ``undefined``
 * and ``false`` are skipped, anything that is not a node is added as text.
 */
export function h(tag, props = {}, ...children) {
  const el = document.createElement(tag);
  for (const [key, value] of Object.entries(props)) {
    if (value === undefined || value === null || value === false) continue;
    if (key === "class") el.className = value;
    else if (key === "dataset") Object.assign(el.dataset, value);
    else if (key.startsWith("on") && typeof value === "function") {
      el.addEventListener(key.slice(2), value);
    } else el.setAttribute(key, value === true ? "" : String(value));
  }
  for (const child of children.flat(Infinity)) {
    if (child === null || child === undefined || child === false) continue;
    el.append(child instanceof Node ? child : String(child));
  }
  return el;
}

/** A span whose X_sub symbols are typeset as subscripts. */
export function sym(text, props = {}) {
  return appendSymbols(h("span", props), text);
}

/** Text as the API wrote it, marked with the language it came in (its Content-Language). */
export function said(text, lang = "en") {
  return h("span", { lang }, text);
}

/** A notice box: ``kind`` is "info", "error" or "warn". */
export function notice(kind, ...children) {
  return h("div", { class: `notice notice-${kind}` }, ...children);
}
