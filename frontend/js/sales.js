// The sales engineer's page: quotes from stored selections.
// Every figure comes from the API (prices, totals, verdicts); money stays the
// decimal text the API sends and is never turned into a float. Text from the
// server is put into the page with textContent only, never as markup.
// Labels come from i18n.js in the language chosen on either page; messages of
// the API are shown as they come (English, marked lang="en").

import { appendSymbols, localeOf, qty } from "./format.js";
import { LANGS, applyStaticTexts, initialLang, rememberLang, translate } from "./i18n.js";

const API = "/api/v1";
const KEY_STORAGE = "actuatorSelection.salesApiKey";
const PAGE_SIZE = 20;
const QUOTE_STATUSES = ["draft", "sent", "accepted", "rejected", "expired"];
const VERDICTS = ["suitable", "unconfirmed", "unsuitable"];

const $ = (id) => document.getElementById(id);

const state = {
  lang: "en",
  selection: null,
  idempotencyKey: newIdempotencyKey(),
  priceLists: [],
  /** the quotes listed, in the order shown */
  quotes: [],
  offset: 0,
  /** what the list's status line says after the next search instead of the count */
  listNote: null,
};

const t = (key, params) => translate(state.lang, key, params);

/** A failed request: status (0: server not reached), field errors of a 422, or a message. */
class ApiError extends Error {
  constructor(status, detail) {
    const fieldErrors = Array.isArray(detail) ? detail : [];
    const message =
      typeof detail === "string"
        ? detail
        : fieldErrors.map((e) => e.msg).join("; ") || `HTTP ${status}`;
    super(message);
    this.status = status;
    this.fieldErrors = fieldErrors;
  }
}

function apiKey() {
  return sessionStorage.getItem(KEY_STORAGE);
}

async function call(method, path, { body, headers = {} } = {}) {
  const init = { method, headers: { Accept: "application/json", ...headers } };
  const key = apiKey();
  if (key) init.headers.Authorization = `Bearer ${key}`;
  if (body !== undefined) {
    init.headers["Content-Type"] = "application/json";
    init.body = JSON.stringify(body);
  }
  let response;
  try {
    response = await fetch(`${API}${path}`, init);
  } catch {
    throw new ApiError(0, null);
  }
  let data = null;
  try {
    const text = await response.text();
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) {
    if (response.status === 401) signedOut(() => t("sales.key.rejected"));
    throw new ApiError(response.status, data && data.detail);
  }
  return data;
}

// --- small DOM helpers ------------------------------------------------------------------

function el(tag, props = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(props)) {
    if (name === "dataset") Object.assign(node.dataset, value);
    else if (name in node) node[name] = value;
    else node.setAttribute(name, value);
  }
  for (const child of children) {
    if (child === null || child === undefined) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

/** Text as the API wrote it: English whatever the page's language. */
function english(text) {
  return el("span", { lang: "en" }, text);
}

/** What to show for a failed request: our words when the server was not reached, else its own. */
function errorText(error) {
  return error.status === 0 ? t("sales.network") : english(error.message);
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
  const options = { dateStyle: "medium", timeZone: "UTC" };
  return new Intl.DateTimeFormat(localeOf(state.lang), options).format(date);
}

/** A moment of the API, in the browser's time zone, as the engineer's page shows it. */
function moment(iso) {
  const date = new Date(iso);
  if (Number.isNaN(date.getTime())) return iso;
  const options = { dateStyle: "medium", timeStyle: "short" };
  return new Intl.DateTimeFormat(localeOf(state.lang), options).format(date);
}

/** A decimal as typed: "7,5" (German) → "7.5", as the API reads decimals. */
function decimalText(value) {
  return /^\d+,\d+$/.test(value) ? value.replace(",", ".") : value;
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
  for (const id of ["create-panel", "list-panel", "who", "sign-out"]) $(id).hidden = true;
  $("key-panel").hidden = false;
  const error = $("key-error");
  if (message) show(error, message);
  else clear(error);
  error.hidden = !message;
  $("api-key").focus();
}

async function signIn(key) {
  sessionStorage.setItem(KEY_STORAGE, key);
  let me;
  try {
    me = await call("GET", "/auth/me");
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
  $("key-panel").hidden = true;
  show($("who"), () => t("sales.who", { name: me.name, key: me.key_id }));
  $("who").hidden = false;
  $("sign-out").hidden = false;
  $("create-panel").hidden = false;
  $("list-panel").hidden = false;
  return true;
}

// --- the selection and the form ---------------------------------------------------------

function showFieldError(id, render) {
  const node = $(id);
  if (!node) return false;
  show(node, render);
  node.hidden = false;
  const input = document.querySelector(`[aria-describedby~="${id}"]`);
  if (input) input.setAttribute("aria-invalid", "true");
  return true;
}

function clearErrors() {
  for (const node of document.querySelectorAll(".field-error")) {
    node.hidden = true;
    clear(node);
  }
  for (const node of document.querySelectorAll("[aria-invalid]")) node.removeAttribute("aria-invalid");
  clear($("form-status"));
  $("form-status").className = "form-status";
}

function formStatus(render, kind = "error") {
  const node = $("form-status");
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
  return el(
    "dl",
    { className: "facts" },
    el("dt", {}, t("sales.summary.load")),
    appendSymbols(
      el("dd"),
      `n_2 = ${qty(load.speed_rpm, "rpm", lang)}, T_L = ${qty(load.torque_nm, "Nm", lang)}, ` +
        `J_L = ${qty(load.inertia_kgm2, "kgm²", lang)}`,
    ),
    el("dt", {}, t("sales.summary.cycle")),
    appendSymbols(
      el("dd"),
      `t_1 = ${seconds(cycle.accel_s)}, t_2 = ${seconds(cycle.constant_s)}, ` +
        `t_3 = ${seconds(cycle.decel_s)}, t_p = ${seconds(cycle.pause_s)} — ` +
        `${t("summary.duty")} ${qty(selection.duty_cycle_percent, "%", lang)}`,
    ),
    el("dt", {}, t("sales.summary.candidates")),
    el("dd", {}, VERDICTS.map((v) => `${counts[v]} ${verdictName(v)}`).join(", ")),
    el("dt", {}, t("sales.summary.catalogue")),
    el(
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
  const select = $("f-model");
  const chosen = select.value;
  select.replaceChildren(
    ...state.selection.candidates.map((c) =>
      el(
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

function fillCandidates(selection) {
  $("f-model").value = "";
  renderCandidates();
  const first = selection.candidates.find(quotable);
  if (first) $("f-model").value = first.model;
  describeCandidate();
  return Boolean(first);
}

function describeCandidate() {
  const model = $("f-model").value;
  const candidate = state.selection?.candidates.find((c) => c.model === model);
  const hint = $("hint-model");
  hint.className = candidate?.verdict === "unconfirmed" ? "hint hint-warn" : "hint";
  if (!candidate) {
    clear(hint);
  } else if (candidate.verdict === "unconfirmed") {
    show(hint, () => [t("sales.actuator.unconfirmed"), english(candidate.reasons.join("; "))]);
  } else {
    show(hint, () =>
      appendSymbols(
        el("span"),
        t("sales.actuator.suitable", { trms: qty(candidate.rms_torque_nm, "Nm", state.lang) }),
      ),
    );
  }
}

async function loadSelection(id) {
  clearErrors();
  $("created").hidden = true;
  $("selection-summary").hidden = true;
  $("quote-form").hidden = true;
  let selection;
  try {
    selection = await call("GET", `/selections/${encodeURIComponent(id)}`);
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
  $("engineer-link").href = `/?selection=${encodeURIComponent(selection.id)}`;
  const canQuote = fillCandidates(selection);
  const box = $("selection-summary");
  show(box, () => [
    el("h3", {}, t("sales.selection.heading", { id: selection.id })),
    summary(selection),
    canQuote ? null : el("p", { className: "notice notice-error" }, t("sales.selection.none_quotable")),
  ]);
  box.hidden = false;
  if (!canQuote) return;
  $("quote-form").hidden = false;
  await loadPriceLists();
}

/** The price lists as options, in the page's language; keeps the choice. */
function renderPriceLists() {
  const select = $("f-price-list");
  const chosen = select.value;
  select.replaceChildren(
    ...state.priceLists.map((list) => {
      const name = list.is_example ? t("sales.price_list.example", { name: list.name }) : list.name;
      return el("option", { value: list.name }, `${name} — ${list.currencies.join(", ")}`);
    }),
  );
  if (chosen) select.value = chosen;
}

async function loadPriceLists() {
  if (!state.priceLists.length) {
    try {
      state.priceLists = await call("GET", "/price-lists");
    } catch (error) {
      formStatus(() => [t("sales.price_list.unavailable"), errorText(error)]);
      return;
    }
  }
  const select = $("f-price-list");
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
  const name = $("f-price-list").value;
  const list = state.priceLists.find((l) => l.name === name);
  $("example-warning").hidden = !(list && list.is_example);
  const codes = $("controller-codes");
  codes.replaceChildren();
  if (!name) return;
  try {
    const detail = await call("GET", `/price-lists/${encodeURIComponent(name)}`);
    const seen = new Set();
    for (const price of detail.prices) {
      if (price.item_kind !== "controller" || seen.has(price.item_code)) continue;
      seen.add(price.item_code);
      codes.append(el("option", { value: price.item_code }, price.description || price.item_code));
    }
  } catch {
    // the datalist is a convenience; typing the code works without it
  }
}

function text(id) {
  return $(id).value.trim();
}

function requestBody() {
  const body = {
    selection_id: state.selection.id,
    customer: { name: text("f-customer") },
    actuator: { model: $("f-model").value, quantity: Number($("f-qty").value) },
    price_list: $("f-price-list").value,
    discount_percent: decimalText(text("f-discount")) || "0",
    valid_until: $("f-valid").value,
  };
  if (text("f-address")) body.customer.address = $("f-address").value;
  if (text("f-reference")) body.customer.reference = text("f-reference");
  if (text("f-ctrl-name") || text("f-ctrl-code")) {
    body.controller = {
      type_name: text("f-ctrl-name"),
      item_code: text("f-ctrl-code"),
      quantity: Number($("f-ctrl-qty").value),
    };
  }
  if (text("f-currency")) body.currency = text("f-currency").toUpperCase();
  if (text("f-notes")) body.notes = $("f-notes").value;
  return body;
}

function showErrors(error) {
  let shown = 0;
  const other = [];
  for (const e of error.fieldErrors) {
    const loc = e.loc || [];
    const id =
      loc[0] === "body" ? `err-${loc.slice(1).filter((p) => typeof p === "string").join("-")}` : "";
    if (id && showFieldError(id, () => english(e.msg))) shown += 1;
    else other.push(e.msg);
  }
  formStatus(() => {
    if (!shown && !other.length) return errorText(error);
    return [shown ? `${t("sales.form.correct")} ` : null, other.length ? english(other.join(" ")) : null];
  });
}

async function createQuote(event) {
  event.preventDefault();
  clearErrors();
  if (!text("f-customer")) {
    showFieldError("err-customer-name", () => t("sales.customer.name.required"));
    formStatus(() => t("sales.form.correct"));
    return;
  }
  const button = $("create-quote");
  button.disabled = true;
  try {
    const quote = await call("POST", "/quotes", {
      body: requestBody(),
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
  const box = $("created");
  show(box, () => {
    const flags = [];
    if (quote.price_list.is_example) flags.push(t("sales.created.example"));
    if (quote.unconfirmed) flags.push(t("sales.created.unconfirmed"));
    const number = el("strong", { className: "quote-number" }, quote.number);
    return [
      el(
        "p",
        {},
        ...withNodes("sales.created", { number }, { total: money(quote.total, quote.currency) }),
        flags.length ? ` (${flags.join("; ")})` : "",
        ". ",
      ),
      documentButton(quote.number),
    ];
  });
  box.hidden = false;
  box.focus?.();
}

// --- the list ---------------------------------------------------------------------------

function documentButton(number) {
  return el(
    "button",
    { type: "button", className: "document-button", onclick: () => openDocument(number) },
    t("sales.document.open"),
  );
}

async function openDocument(number) {
  // Opened now, inside the click, so that a popup blocker lets it through; filled below.
  // The document itself is English; only the words around it follow the page.
  const win = window.open("", "_blank");
  if (!win) {
    show($("list-status"), () => t("sales.document.blocked"));
    return;
  }
  win.document.title = t("sales.document.title", { number });
  win.document.body.textContent = t("sales.document.loading");
  try {
    // A signed, short-lived link: the window loads the document from the server itself,
    // with the document's own Content-Security-Policy (never written into the window).
    const link = await call("POST", `/quotes/${encodeURIComponent(number)}/document-link`);
    win.location.replace(link.url);
  } catch (error) {
    win.document.body.textContent = `${t("sales.document.failed")}${error.message}`;
  }
}

async function move(number, status) {
  try {
    await call("POST", `/quotes/${encodeURIComponent(number)}/status`, { body: { status } });
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
  const actions = el("div", { className: "actions-cell" }, documentButton(quote.number));
  for (const status of quote.allowed_transitions) {
    actions.append(
      el(
        "button",
        { type: "button", className: `move move-${status}`, onclick: () => move(quote.number, status) },
        ACTION_KEYS[status] ? t(ACTION_KEYS[status]) : status,
      ),
    );
  }
  const tag = (kind, key) => el("span", { className: `tag tag-${kind}` }, t(key));
  const flags = [
    quote.price_list.is_example ? tag("example", "sales.tag.example") : null,
    quote.unconfirmed ? tag("warn", "sales.tag.unconfirmed") : null,
  ];
  const reference = quote.customer.reference;
  return el(
    "tr",
    { dataset: { number: quote.number } },
    el("td", { className: "mono" }, quote.number),
    el("td", {}, quote.customer.name, reference ? el("div", { className: "hint" }, reference) : null),
    el("td", {}, quote.actuator_model, " ", ...flags),
    el("td", { className: "num" }, money(quote.total, quote.currency)),
    el(
      "td",
      {},
      el(
        "span",
        { className: `status status-${quote.status}`, dataset: { status: quote.status } },
        statusName(quote.status),
      ),
    ),
    el("td", { className: "date" }, el("time", { dateTime: quote.valid_until }, day(quote.valid_until))),
    el("td", {}, actions),
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
  const q = $("q").value.trim();
  const status = $("status-filter").value;
  if (q) params.set("q", q);
  if (status) params.set("status", status);
  const note = state.listNote;
  state.listNote = null;
  let page;
  try {
    page = await call("GET", `/quotes?${params}`);
  } catch (error) {
    if (error.status !== 401) show($("list-status"), () => errorText(error));
    return;
  }
  state.quotes = append ? [...state.quotes, ...page.quotes] : page.quotes;
  show($("quotes").tBodies[0], () => state.quotes.map(row));
  state.offset = state.quotes.length;
  $("more").hidden = state.offset >= page.total;
  show($("list-status"), note ?? (() => listCount(page.total, Boolean(q || status))));
}

// --- language ---------------------------------------------------------------------------

function applyLang(lang) {
  state.lang = LANGS.includes(lang) ? lang : "de";
  document.documentElement.lang = state.lang;
  applyStaticTexts(document, state.lang);
  for (const button of document.querySelectorAll(".lang-button")) {
    button.setAttribute("aria-pressed", String(button.dataset.lang === state.lang));
  }
  document.title = `${t("sales.title")} · ${t("app.title")}`;
  for (const [node, render] of localized) node.replaceChildren(...children(render));
  if (state.selection) renderCandidates();
  renderPriceLists();
}

// --- start ------------------------------------------------------------------------------

async function start() {
  applyLang(initialLang());
  for (const button of document.querySelectorAll(".lang-button")) {
    button.addEventListener("click", () => {
      rememberLang(button.dataset.lang);
      applyLang(button.dataset.lang);
    });
  }
  $("f-valid").value = isoDate(30);
  $("key-form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const key = $("api-key").value.trim();
    $("api-key").value = "";
    if (key && (await signIn(key))) await afterSignIn();
  });
  $("sign-out").addEventListener("click", () => signedOut(null));
  $("selection-form").addEventListener("submit", (event) => {
    event.preventDefault();
    const id = $("selection-id").value.trim();
    if (id) loadSelection(id);
  });
  $("f-model").addEventListener("change", describeCandidate);
  $("f-price-list").addEventListener("change", priceListChanged);
  $("quote-form").addEventListener("submit", createQuote);
  $("search-form").addEventListener("submit", (event) => {
    event.preventDefault();
    search();
  });
  $("more").addEventListener("click", () => search({ append: true }));

  const stored = apiKey();
  if (stored && (await signIn(stored))) await afterSignIn();
  else if (!stored) signedOut(null);
}

async function afterSignIn() {
  const selection = new URLSearchParams(location.search).get("selection");
  if (selection) {
    $("selection-id").value = selection;
    await loadSelection(selection);
  }
  await search();
}

start();
