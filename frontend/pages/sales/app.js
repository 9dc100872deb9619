// The sales engineer's page: quotes from stored selections.
// Every figure comes from the API (prices, totals, verdicts); money stays the
// decimal text the API sends and is never turned into a float. Text from the
// server is put into the page with textContent only, never as markup.
// Labels come from i18n.js in the language chosen on either page; messages of
// the API are shown as they come (English, marked lang="en").

import { createClient, encodePath } from "../../lib/api.js";
import { openCheckLines } from "../../lib/checks.js";
import { $$as, byId, byIdAs, h, said } from "../../lib/dom.js";
import { appendSymbols, dateTime, localeOf, qty } from "../../lib/format.js";
import { LANGS, applyStaticTexts, initialLang, rememberLang, translate } from "../../lib/i18n.js";
import { fieldRefusal, isNumberField, readField, showReading, showReadings } from "../../lib/numbers.js";

const KEY_STORAGE = "actuatorSelection.salesApiKey";
const PAGE_SIZE = 20;
const QUOTE_STATUSES = ["draft", "sent", "accepted", "rejected", "expired"];
const VERDICTS = ["suitable", "unconfirmed", "unsuitable"];

const state = {
  lang: "en",
  selection: null,
  /** a machine project being quoted (a line per axis) instead of a selection */
  project: null,
  idempotencyKey: newIdempotencyKey(),
  priceLists: [],
  /** the quotes listed, in the order shown */
  quotes: [],
  offset: 0,
  /** what the list's status line says after the next search instead of the count */
  listNote: null,
};

const t = (key, params) => translate(state.lang, key, params);

function apiKey() {
  return sessionStorage.getItem(KEY_STORAGE);
}

// The one API client of both pages, with this page's key; a 401 (unknown, revoked or
// malformed key) sends the engineer back to the key prompt.
const api = createClient({
  headers: () => {
    const key = apiKey();
    // the page's language as Accept-Language: the server's messages come in it
    return { "Accept-Language": state.lang, ...(key ? { Authorization: `Bearer ${key}` } : {}) };
  },
  onError: (error) => {
    if (error.status === 401) signedOut(() => t("sales.key.rejected"));
  },
});

/** What to show for a failed request: our words when the server was not reached, else its own. */
function errorText(error) {
  return error.status === 0 ? t("sales.network") : said(error.message, error.lang);
}

// Every text the page writes is given as a function of the language, so that a
// switch of language rewrites it in place: node → () => its children.
const localized = new Map();

function children(render) {
  return [render()].flat(Infinity).filter((c) => c !== null && c !== undefined && c !== false);
}

/** Fill ``node`` with ``render()`` now, and again whenever the language changes. */
function show(node, render) {
  localized.set(node, render);
  node.replaceChildren(...children(render));
}

function clear(node) {
  localized.delete(node);
  node.replaceChildren();
}

/** ``t(key, params)`` with the placeholders named in ``nodes`` filled by DOM nodes. */
function withNodes(key, nodes, params = {}) {
  return t(key, params)
    .split(/\{(\w+)\}/)
    .map((part, i) => (i % 2 ? (nodes[part] ?? `{${part}}`) : part));
}

// --- numbers, money and dates in the page's language -----------------------------------

/** The group and decimal marks of the page's locale, as Intl writes them. */
function separators() {
  const parts = new Intl.NumberFormat(localeOf(state.lang)).formatToParts(1234567.5);
  const mark = (type, fallback) => parts.find((p) => p.type === type)?.value ?? fallback;
  return { group: mark("group", ","), decimal: mark("decimal", ".") };
}

/** "8861.50", "EUR" → "8,861.50 EUR" or "8.861,50 EUR", by string (no float on the way). */
function money(amount, currency) {
  const { group, decimal } = separators();
  const [whole, cents = "00"] = String(amount).split(".");
  const sign = whole.startsWith("-") ? "−" : "";
  const digits = whole.replace("-", "").replace(/\B(?=(\d{3})+(?!\d))/g, group);
  return `${sign}${digits}${decimal}${cents} ${currency}`;
}

function count(n) {
  return new Intl.NumberFormat(localeOf(state.lang)).format(n);
}

/** A calendar day of the API ("2025-07-31") as "31.07.2025" or "31 Jul 2025". */
function day(iso) {
  const date = new Date(`${iso}T00:00:00Z`);
  if (Number.isNaN(date.getTime())) return iso;
  /** @type {Intl.DateTimeFormatOptions} */
  const options = { dateStyle: "medium", timeZone: "UTC" };
  return new Intl.DateTimeFormat(localeOf(state.lang), options).format(date);
}

/** A moment of the API, in the browser's time zone, as the engineer's page shows it. */
function moment(iso) {
  return dateTime(iso, state.lang) ?? iso;
}

/** A number field's number ("1,3" and "1.3" alike, lib/numbers.js); null when blank. */
function numberOf(id) {
  return readField(byId(id)).value;
}

function isoDate(daysFromToday) {
  const d = new Date();
  d.setDate(d.getDate() + daysFromToday);
  return d.toISOString().slice(0, 10);
}

function newIdempotencyKey() {
  if (globalThis.crypto && typeof crypto.randomUUID === "function") return crypto.randomUUID();
  return `q-${Date.now().toString(36)}-${Math.random().toString(36).slice(2)}`;
}

function statusName(status) {
  return QUOTE_STATUSES.includes(status) ? t(`quote.status.${status}`) : status;
}

function verdictName(verdict) {
  return VERDICTS.includes(verdict) ? t(`verdict.${verdict}`) : verdict;
}

// --- sign in ----------------------------------------------------------------------------

/** Back to the key prompt; ``message`` renders why (or null for none). */
function signedOut(message) {
  sessionStorage.removeItem(KEY_STORAGE);
  for (const id of ["create-panel", "list-panel", "who", "sign-out"]) byId(id).hidden = true;
  byId("key-panel").hidden = false;
  const error = byId("key-error");
  if (message) show(error, message);
  else clear(error);
  error.hidden = !message;
  byIdAs("api-key", HTMLInputElement).focus();
}

async function signIn(key) {
  sessionStorage.setItem(KEY_STORAGE, key);
  let me;
  try {
    me = await api.get("/auth/me");
  } catch (error) {
    if (error.status !== 401) signedOut(() => [t("sales.key.unchecked"), errorText(error)]);
    return false;
  }
  if (me.role !== "sales") {
    signedOut(() =>
      me.authenticated ? t("sales.key.wrong_role", { role: me.role }) : t("sales.key.anonymous"),
    );
    return false;
  }
  byId("key-panel").hidden = true;
  show(byId("who"), () => t("sales.who", { name: me.name, key: me.key_id }));
  byId("who").hidden = false;
  byId("sign-out").hidden = false;
  byId("create-panel").hidden = false;
  byId("list-panel").hidden = false;
  return true;
}

// --- the selection and the form ---------------------------------------------------------

function showFieldError(id, render) {
  const node = byId(id);
  if (!node) return false;
  show(node, render);
  node.hidden = false;
  const input = document.querySelector(`[aria-describedby~="${id}"]`);
  if (input) input.setAttribute("aria-invalid", "true");
  return true;
}

function clearErrors() {
  for (const node of $$as(".field-error", HTMLElement)) {
    node.hidden = true;
    clear(node);
  }
  for (const node of document.querySelectorAll("[aria-invalid]")) node.removeAttribute("aria-invalid");
  clear(byId("form-status"));
  byId("form-status").className = "form-status";
}

function formStatus(render, kind = "error") {
  const node = byId("form-status");
  show(node, render);
  node.className = `form-status notice notice-${kind}`;
  node.focus();
}

function summary(selection) {
  const { load, cycle } = selection;
  const lang = state.lang;
  const counts = { suitable: 0, unconfirmed: 0, unsuitable: 0 };
  for (const c of selection.candidates) counts[c.verdict] += 1;
  const seconds = (value) => qty(value, "s", lang);
  return h(
    "dl",
    { class: "facts" },
    h("dt", {}, t("sales.summary.load")),
    appendSymbols(
      h("dd"),
      `n_2 = ${qty(load.speed_rpm, "rpm", lang)}, T_L = ${qty(load.torque_nm, "Nm", lang)}, ` +
        `J_L = ${qty(load.inertia_kgm2, "kgm²", lang)}`,
    ),
    h("dt", {}, t("sales.summary.cycle")),
    appendSymbols(
      h("dd"),
      `t_1 = ${seconds(cycle.accel_s)}, t_2 = ${seconds(cycle.constant_s)}, ` +
        `t_3 = ${seconds(cycle.decel_s)}, t_p = ${seconds(cycle.pause_s)} — ` +
        `${t("summary.duty")} ${qty(selection.duty_cycle_percent, "%", lang)}`,
    ),
    h("dt", {}, t("sales.summary.candidates")),
    h("dd", {}, VERDICTS.map((v) => `${counts[v]} ${verdictName(v)}`).join(", ")),
    h("dt", {}, t("sales.summary.catalogue")),
    h(
      "dd",
      {},
      t("sales.summary.catalogue.value", {
        version: selection.catalogue_version,
        date: moment(selection.created_at),
      }),
    ),
  );
}

const quotable = (candidate) => candidate.verdict !== "unsuitable";

/** The selection's candidates as options, in the page's language; keeps the choice. */
function renderCandidates() {
  const select = byIdAs("f-model", HTMLSelectElement);
  const chosen = select.value;
  select.replaceChildren(
    ...state.selection.candidates.map((c) =>
      h(
        "option",
        { value: c.model, disabled: !quotable(c) },
        quotable(c)
          ? `${c.model} — ${verdictName(c.verdict)}`
          : t("sales.actuator.option.unsuitable", { model: c.model }),
      ),
    ),
  );
  if (chosen) select.value = chosen;
}

function fillCandidates(selection, preferred = null) {
  byIdAs("f-model", HTMLSelectElement).value = "";
  renderCandidates();
  const wanted = selection.candidates.find((c) => c.model === preferred && quotable(c));
  const first = wanted ?? selection.candidates.find(quotable);
  if (first) byIdAs("f-model", HTMLSelectElement).value = first.model;
  describeCandidate();
  return Boolean(first);
}

function describeCandidate() {
  const model = byIdAs("f-model", HTMLSelectElement).value;
  const candidate = state.selection?.candidates.find((c) => c.model === model);
  const hint = byId("hint-model");
  hint.className = candidate?.verdict === "unconfirmed" ? "hint hint-warn" : "hint";
  if (!candidate) {
    clear(hint);
  } else if (candidate.verdict === "unconfirmed") {
    // the checks that did not pass, each with its label and what it found
    const selection = state.selection;
    show(hint, () => [
      t("sales.actuator.unconfirmed"),
      openCheckLines(selection, candidate, state.lang).flatMap((line, i) => (i ? ["; ", line] : [line])),
    ]);
  } else {
    show(hint, () =>
      appendSymbols(
        h("span"),
        t("sales.actuator.suitable", { trms: qty(candidate.rms_torque_nm, "Nm", state.lang) }),
      ),
    );
  }
}

/**
 * The selection id in what was typed or pasted: the id itself, or a link from the
 * selection page (its ``selection`` parameter, and its ``model`` if it names one).
 */
function selectionReference(text) {
  try {
    const url = new URL(text);
    const id = url.searchParams.get("selection");
    if (id) return { id, model: url.searchParams.get("model") };
  } catch {
    // not a link: the id itself
  }
  return { id: text, model: null };
}

/** Show the quote form for a selection (one actuator and controller) or a project (a line
 * per axis). @param {boolean} project */
function formFor(project) {
  byId("actuator-fields").hidden = project;
  byId("controller-fields").hidden = project;
  byId("project-axes").hidden = !project;
  if (!project) byId("project-axes").replaceChildren();
}

/** One axis of a project on the quote form: its quantity and its controller line. */
function axisFields(axis, k) {
  const id = (what) => `f-axis-${k}-${what}`;
  const err = (what) => `err-axis-${k}-${what}`;
  const field = (what, label, attrs, narrow = false) =>
    h(
      "div",
      { class: narrow ? "field narrow" : "field" },
      h("label", { for: id(what) }, t(label)),
      h("input", { id: id(what), "aria-describedby": err(what), ...attrs }),
      h("p", { class: "field-error", id: err(what), hidden: true }),
    );
  const controller = axis.controller;
  return h(
    "fieldset",
    { class: "project-axis", dataset: { axis: String(k) } },
    h("legend", {}, t("sales.project.axis", { name: axis.name || String(k + 1), model: axis.model })),
    field("qty", "sales.quantity", { type: "text", inputmode: "numeric", "data-number": true, value: "1" }, true),
    controller ? h("p", { class: "hint" }, t("sales.project.controller", { name: controller.name, row: controller.source_row })) : null,
    field("ctrl-name", "sales.controller.type", { maxlength: 200, value: controller ? controller.name : "" }),
    field("ctrl-code", "sales.controller.code", { maxlength: 80, list: "controller-codes", spellcheck: "false" }),
  );
}

/** A stored machine project to quote: a line per axis. */
async function loadProject(id) {
  clearErrors();
  byId("created").hidden = true;
  byId("selection-summary").hidden = true;
  let project;
  try {
    project = await api.get(encodePath`/projects/${id}`);
  } catch (error) {
    showFieldError("err-selection_id", () => errorText(error));
    return;
  }
  state.project = project;
  state.selection = null;
  const box = byId("selection-summary");
  show(box, () => [h("h3", {}, t("sales.project.heading", { name: project.request.name, n: project.axes.length }))]);
  box.hidden = false;
  formFor(true);
  byId("project-axes").replaceChildren(...project.axes.map(axisFields));
  const form = byId("quote-form");
  const create = byIdAs("create-quote", HTMLButtonElement);
  form.hidden = false;
  form.setAttribute("aria-busy", "true");
  create.disabled = true;
  try {
    await loadPriceLists();
  } finally {
    form.removeAttribute("aria-busy");
    create.disabled = false;
  }
}

async function loadSelection(id, model = null) {
  clearErrors();
  state.project = null;
  formFor(false);
  byId("created").hidden = true;
  byId("selection-summary").hidden = true;
  byId("quote-form").hidden = true;
  let selection;
  try {
    selection = await api.get(encodePath`/selections/${id}`);
    // any candidate may be quoted: the ranking whole, page by page after the answer's own
    while (selection.next_cursor) {
      const page = await api.get(
        encodePath`/selections/${id}/candidates?cursor=${selection.next_cursor}&limit=${"1000"}`,
      );
      selection.candidates.push(...page.candidates);
      selection.next_cursor = page.next_cursor;
    }
  } catch (error) {
    showFieldError("err-selection_id", () =>
      error.status === 404 ? t("sales.selection.missing", { id }) : errorText(error),
    );
    return;
  }
  state.selection = selection;
  const url = new URL(location.href);
  url.searchParams.set("selection", selection.id);
  history.replaceState(null, "", url);
  byIdAs("engineer-link", HTMLAnchorElement).href = `/?selection=${encodeURIComponent(selection.id)}`;
  const canQuote = fillCandidates(selection, model);
  const box = byId("selection-summary");
  show(box, () => [
    h("h3", {}, t("sales.selection.heading", { id: selection.id })),
    summary(selection),
    canQuote ? null : h("p", { class: "notice notice-error" }, t("sales.selection.none_quotable")),
  ]);
  box.hidden = false;
  if (!canQuote) return;
  // The form shows at once, but takes a quote only once its price lists are in: a quote
  // asked for before that would be refused for the empty list.
  const form = byId("quote-form");
  const create = byIdAs("create-quote", HTMLButtonElement);
  form.hidden = false;
  form.setAttribute("aria-busy", "true");
  create.disabled = true;
  try {
    await loadPriceLists();
  } finally {
    form.removeAttribute("aria-busy");
    create.disabled = false;
  }
}

/** The price lists as options, in the page's language; keeps the choice. */
function renderPriceLists() {
  const select = byIdAs("f-price-list", HTMLSelectElement);
  const chosen = select.value;
  select.replaceChildren(
    ...state.priceLists.map((list) => {
      const name = list.is_example ? t("sales.price_list.example", { name: list.name }) : list.name;
      return h("option", { value: list.name }, `${name} — ${list.currencies.join(", ")}`);
    }),
  );
  if (chosen) select.value = chosen;
}

async function loadPriceLists() {
  if (!state.priceLists.length) {
    try {
      state.priceLists = await api.get("/price-lists");
    } catch (error) {
      formStatus(() => [t("sales.price_list.unavailable"), errorText(error)]);
      return;
    }
  }
  const select = byIdAs("f-price-list", HTMLSelectElement);
  const chosen = select.value;
  renderPriceLists();
  if (!state.priceLists.length) formStatus(() => t("sales.price_list.none"));
  if (!chosen) {
    const real = state.priceLists.find((l) => !l.is_example);
    if (real) select.value = real.name;
  }
  await priceListChanged();
}

async function priceListChanged() {
  const name = byIdAs("f-price-list", HTMLSelectElement).value;
  const list = state.priceLists.find((l) => l.name === name);
  byId("example-warning").hidden = !(list && list.is_example);
  const codes = byId("controller-codes");
  codes.replaceChildren();
  if (!name) return;
  try {
    const detail = await api.get(encodePath`/price-lists/${name}`);
    const seen = new Set();
    for (const price of detail.prices) {
      if (price.item_kind !== "controller" || seen.has(price.item_code)) continue;
      seen.add(price.item_code);
      codes.append(h("option", { value: price.item_code, translate: "no" }, price.description || price.item_code));
    }
  } catch {
    // the datalist is a convenience; typing the code works without it
  }
}

/** A text field's text, trimmed. @param {string} id an input's or a textarea's */
function text(id) {
  const el = byId(id);
  return el instanceof HTMLInputElement || el instanceof HTMLTextAreaElement ? el.value.trim() : "";
}

/** The project's axes as the quote request takes them: a quantity and, where a code is
 * given, a controller line. */
function axesBody() {
  return state.project.axes.map((_, k) => {
    const f = (what) => `f-axis-${k}-${what}`;
    const axis = { quantity: numberOf(f("qty")) };
    if (text(f("ctrl-code"))) axis.controller = { type_name: text(f("ctrl-name")), item_code: text(f("ctrl-code")) };
    return axis;
  });
}

function requestBody() {
  const source = state.project
    ? { project_id: state.project.id, axes: axesBody() }
    : {
        selection_id: state.selection.id,
        actuator: { model: byIdAs("f-model", HTMLSelectElement).value, quantity: numberOf("f-qty") },
      };
  /** @type {Record<string, any>} */
  const body = {
    ...source,
    customer: { name: text("f-customer") },
    price_list: byIdAs("f-price-list", HTMLSelectElement).value,
    // a decimal as the API reads it ("7,5" → "7.5"), kept as text: money is never a float
    discount_percent: readField(byId("f-discount")).decimal || "0",
    valid_until: byIdAs("f-valid", HTMLInputElement).value,
  };
  if (text("f-address")) body.customer.address = byIdAs("f-address", HTMLTextAreaElement).value;
  if (text("f-reference")) body.customer.reference = text("f-reference");
  if (!state.project && (text("f-ctrl-name") || text("f-ctrl-code"))) {
    body.controller = {
      type_name: text("f-ctrl-name"),
      item_code: text("f-ctrl-code"),
      quantity: numberOf("f-ctrl-qty"),
    };
  }
  if (text("f-currency")) body.currency = text("f-currency").toUpperCase();
  if (text("f-notes")) body.notes = byIdAs("f-notes", HTMLTextAreaElement).value;
  return body;
}

function showErrors(error) {
  let shown = 0;
  const other = [];
  for (const e of error.fieldErrors) {
    const loc = e.loc || [];
    const id =
      loc[0] === "body" ? `err-${loc.slice(1).filter((p) => typeof p === "string").join("-")}` : "";
    if (id && showFieldError(id, () => said(e.msg, e.lang))) shown += 1;
    else other.push(e.msg);
  }
  formStatus(() => {
    if (!shown && !other.length) return errorText(error);
    return [shown ? `${t("sales.form.correct")} ` : null, other.length ? said(other.join(" "), error.lang) : null];
  });
}

/** Name at ``input`` the page's refusal of its text ("1.300,5"); whether there was one. */
function refuseNumber(input) {
  const key = fieldRefusal(input);
  return Boolean(key && showFieldError(errorId(input), () => t(key)));
}

/** The id of ``input``'s message element (its aria-describedby's "err-…"). */
function errorId(input) {
  return (input.getAttribute("aria-describedby") ?? "").split(/\s+/).find((id) => id.startsWith("err-")) ?? "";
}

async function createQuote(event) {
  event.preventDefault();
  clearErrors();
  const controller = !state.project && Boolean(text("f-ctrl-name") || text("f-ctrl-code"));
  const quantities = state.project ? state.project.axes.map((_, k) => `f-axis-${k}-qty`) : ["f-qty"];
  const numbers = [...quantities, "f-discount", ...(controller ? ["f-ctrl-qty"] : [])].map(byId);
  // every refusal is named at once; nothing is sent while one stands
  const refused = numbers.filter(refuseNumber).length > 0;
  if (!text("f-customer") || refused) {
    if (!text("f-customer")) showFieldError("err-customer-name", () => t("sales.customer.name.required"));
    formStatus(() => t("sales.form.correct"));
    return;
  }
  const button = byIdAs("create-quote", HTMLButtonElement);
  button.disabled = true;
  try {
    const quote = await api.post("/quotes", requestBody(), {
      headers: { "Idempotency-Key": state.idempotencyKey },
    });
    state.idempotencyKey = newIdempotencyKey();
    showCreated(quote);
    await search();
  } catch (error) {
    if (error.status === 0) {
      // Unknown whether it arrived: sending again with the same key cannot make a second quote.
      formStatus(() => t("sales.form.unreached"));
    } else if (error.status !== 401) {
      showErrors(error);
    }
  } finally {
    button.disabled = false;
  }
}

function showCreated(quote) {
  const box = byId("created");
  show(box, () => {
    const flags = [];
    if (quote.price_list.is_example) flags.push(t("sales.created.example"));
    if (quote.unconfirmed) flags.push(t("sales.created.unconfirmed"));
    const number = h("strong", { class: "quote-number" }, quote.number);
    return [
      h(
        "p",
        {},
        ...withNodes("sales.created", { number }, { total: money(quote.net_total, quote.currency) }),
        flags.length ? ` (${flags.join("; ")})` : "",
        ". ",
      ),
      documentButton(quote.number),
      " ",
      pdfButton(quote.number),
    ];
  });
  box.hidden = false;
  box.focus?.();
}

// --- the list ---------------------------------------------------------------------------

function documentButton(number) {
  return h(
    "button",
    { type: "button", class: "document-button", onclick: () => openDocument(number) },
    t("sales.document.open"),
  );
}

function pdfButton(number) {
  return h(
    "button",
    {
      type: "button",
      class: "pdf-button",
      onclick: () => downloadPdf(number),
      "aria-label": t("sales.document.pdf.label", { number }),
    },
    t("sales.document.pdf"),
  );
}

/**
 * Download the quote document as PDF in the page's language: a signed, short-lived link
 * (as for the HTML document; the PDF route takes the same token) that the browser
 * fetches itself as a file (Content-Disposition: attachment).
 */
async function downloadPdf(number) {
  try {
    const link = await api.post(`${encodePath`/quotes/${number}/document-link`}?lang=${state.lang}`);
    const anchor = h("a", { href: link.url.replace("/document?", "/document.pdf?"), download: `${number}.pdf`, hidden: true });
    document.body.append(anchor);
    anchor.click();
    anchor.remove();
  } catch (error) {
    if (error.status !== 401) show(byId("list-status"), () => [`${number}: `, errorText(error)]);
  }
}

async function openDocument(number) {
  // Opened now, inside the click, so that a popup blocker lets it through; filled below.
  // The document itself is English; only the words around it follow the page.
  const win = window.open("", "_blank");
  if (!win) {
    show(byId("list-status"), () => t("sales.document.blocked"));
    return;
  }
  win.document.title = t("sales.document.title", { number });
  win.document.body.textContent = t("sales.document.loading");
  try {
    // A signed, short-lived link: the window loads the document from the server itself,
    // with the document's own Content-Security-Policy (never written into the window).
    // The document in the page's language (the link carries it as &lang=).
    const link = await api.post(`${encodePath`/quotes/${number}/document-link`}?lang=${state.lang}`);
    win.location.replace(link.url);
  } catch (error) {
    win.document.body.textContent = `${t("sales.document.failed")}${error.message}`;
  }
}

async function move(number, status) {
  try {
    await api.post(encodePath`/quotes/${number}/status`, { status });
    state.listNote = () => t("sales.list.moved", { number, status: statusName(status) });
  } catch (error) {
    if (error.status !== 401) state.listNote = () => [`${number}: `, errorText(error)];
  }
  await search({ keepOffset: true });
}

const ACTION_KEYS = {
  sent: "sales.action.sent",
  accepted: "sales.action.accepted",
  rejected: "sales.action.rejected",
};

function row(quote) {
  const actions = h("div", { class: "actions-cell" }, documentButton(quote.number), " ", pdfButton(quote.number));
  for (const status of quote.allowed_transitions) {
    actions.append(
      h(
        "button",
        { type: "button", class: `move move-${status}`, onclick: () => move(quote.number, status) },
        ACTION_KEYS[status] ? t(ACTION_KEYS[status]) : status,
      ),
    );
  }
  const tag = (kind, key) => h("span", { class: `tag tag-${kind}` }, t(key));
  const flags = [
    quote.price_list.is_example ? tag("example", "sales.tag.example") : null,
    quote.unconfirmed ? tag("warn", "sales.tag.unconfirmed") : null,
  ];
  const reference = quote.customer.reference;
  return h(
    "tr",
    { dataset: { number: quote.number } },
    h("td", { class: "mono" }, quote.number),
    h("td", {}, quote.customer.name, reference ? h("div", { class: "hint" }, reference) : null),
    // a project's quote has an actuator per axis, none of its own (actuator_model null)
    h(
      "td",
      {},
      quote.actuator_model ?? quote.axes.map((a) => a.actuator_model).join(", "),
      " ",
      ...flags,
    ),
    h("td", { class: "num" }, money(quote.net_total, quote.currency)),
    h(
      "td",
      {},
      h(
        "span",
        { class: `status status-${quote.status}`, dataset: { status: quote.status } },
        statusName(quote.status),
      ),
    ),
    h("td", { class: "date" }, h("time", { datetime: quote.valid_until }, day(quote.valid_until))),
    h("td", {}, actions),
  );
}

function listCount(total, filtered) {
  if (!total) return t(filtered ? "sales.list.no_match" : "sales.list.none");
  const form = new Intl.PluralRules(localeOf(state.lang)).select(total) === "one" ? "one" : "other";
  return t(`sales.list.count.${form}`, { n: count(total) });
}

async function search({ append = false, keepOffset = false } = {}) {
  if (!append && !keepOffset) state.offset = 0;
  const params = new URLSearchParams({ limit: String(append ? PAGE_SIZE : state.offset + PAGE_SIZE) });
  if (append) params.set("offset", String(state.offset));
  const q = byIdAs("q", HTMLInputElement).value.trim();
  const status = byIdAs("status-filter", HTMLSelectElement).value;
  if (q) params.set("q", q);
  if (status) params.set("status", status);
  const note = state.listNote;
  state.listNote = null;
  let page;
  try {
    page = await api.get(`/quotes?${params}`);
  } catch (error) {
    if (error.status !== 401) show(byId("list-status"), () => errorText(error));
    return;
  }
  state.quotes = append ? [...state.quotes, ...page.quotes] : page.quotes;
  show(byIdAs("quotes", HTMLTableElement).tBodies[0], () => state.quotes.map(row));
  state.offset = state.quotes.length;
  byId("more").hidden = state.offset >= page.total;
  show(byId("list-status"), note ?? (() => listCount(page.total, Boolean(q || status))));
}

// --- language ---------------------------------------------------------------------------

function applyLang(lang) {
  state.lang = LANGS.includes(lang) ? lang : "de";
  document.documentElement.lang = state.lang;
  applyStaticTexts(document, state.lang);
  for (const button of $$as(".lang-button", HTMLButtonElement)) {
    button.setAttribute("aria-pressed", String(button.dataset.lang === state.lang));
  }
  document.title = `${t("sales.title")} · ${t("app.title")}`;
  for (const [node, render] of localized) node.replaceChildren(...children(render));
  showReadings(byId("quote-form"), state.lang);
  if (state.selection) renderCandidates();
  renderPriceLists();
}

// --- start ------------------------------------------------------------------------------

async function start() {
  applyLang(initialLang());
  for (const button of $$as(".lang-button", HTMLButtonElement)) {
    button.addEventListener("click", () => {
      rememberLang(button.dataset.lang);
      applyLang(button.dataset.lang);
    });
  }
  byIdAs("f-valid", HTMLInputElement).value = isoDate(30);
  byId("key-form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const key = byIdAs("api-key", HTMLInputElement).value.trim();
    byIdAs("api-key", HTMLInputElement).value = "";
    if (key && (await signIn(key))) await afterSignIn();
  });
  byId("sign-out").addEventListener("click", () => signedOut(null));
  byId("selection-form").addEventListener("submit", (event) => {
    event.preventDefault();
    const { id, model } = selectionReference(byIdAs("selection-id", HTMLInputElement).value.trim());
    if (id) {
      byIdAs("selection-id", HTMLInputElement).value = id;
      loadSelection(id, model);
    }
  });
  byIdAs("f-model", HTMLSelectElement).addEventListener("change", describeCandidate);
  byIdAs("f-price-list", HTMLSelectElement).addEventListener("change", priceListChanged);
  byId("quote-form").addEventListener("submit", createQuote);
  byId("quote-form").addEventListener("input", (event) => showReading(event.target, state.lang));
  byId("quote-form").addEventListener("change", (event) => {
    // a number the page cannot read is named when the field is left; a corrected one is not
    const target = event.target;
    if (!(target instanceof HTMLInputElement) || !isNumberField(target)) return;
    const error = byId(errorId(target));
    if (error) {
      error.hidden = true;
      clear(error);
    }
    target.removeAttribute("aria-invalid");
    refuseNumber(target);
  });
  byId("search-form").addEventListener("submit", (event) => {
    event.preventDefault();
    search();
  });
  byId("more").addEventListener("click", () => search({ append: true }));

  const stored = apiKey();
  if (stored && (await signIn(stored))) await afterSignIn();
  else if (!stored) signedOut(null);
}

async function afterSignIn() {
  const params = new URLSearchParams(location.search);
  const selection = params.get("selection");
  const project = params.get("project");
  if (project) await loadProject(project);
  else if (selection) {
    byIdAs("selection-id", HTMLInputElement).value = selection;
    await loadSelection(selection, params.get("model"));
  }
  await search();
}

start();
