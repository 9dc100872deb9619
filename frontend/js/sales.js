// The sales engineer's page: quotes from stored selections.
// Every figure comes from the API (prices, totals, verdicts); money stays the
// decimal text the API sends and is never turned into a float. Text from the
// server is put into the page with textContent only, never as markup.

const API = "/api/v1";
const KEY_STORAGE = "actuatorSelection.salesApiKey";
const PAGE_SIZE = 20;

const $ = (id) => document.getElementById(id);

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

async function call(method, path, { body, headers = {}, accept = "application/json" } = {}) {
  const init = { method, headers: { Accept: accept, ...headers } };
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
    throw new ApiError(0, "the server cannot be reached");
  }
  if (accept === "text/html" && response.ok) return response.text();
  let data = null;
  try {
    const text = await response.text();
    data = text ? JSON.parse(text) : null;
  } catch {
    data = null;
  }
  if (!response.ok) {
    if (response.status === 401) signedOut("The API key was not accepted. Enter a valid key.");
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

/** "8861.50", "EUR" → "8,861.50 EUR", by string (no float on the way). */
function money(amount, currency) {
  const [whole, cents = "00"] = String(amount).split(".");
  const sign = whole.startsWith("-") ? "−" : "";
  const digits = whole.replace("-", "").replace(/\B(?=(\d{3})+(?!\d))/g, ",");
  return `${sign}${digits}.${cents} ${currency}`;
}

function number(value, unit) {
  if (typeof value !== "number" || !Number.isFinite(value)) return "—";
  const text = Math.abs(value) >= 100 ? value.toFixed(1) : value.toFixed(2);
  return unit ? `${text} ${unit}` : text;
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

// --- sign in ----------------------------------------------------------------------------

function signedOut(message) {
  sessionStorage.removeItem(KEY_STORAGE);
  for (const id of ["create-panel", "list-panel", "who", "sign-out"]) $(id).hidden = true;
  $("key-panel").hidden = false;
  const error = $("key-error");
  error.textContent = message || "";
  error.hidden = !message;
  $("api-key").focus();
}

async function signIn(key) {
  sessionStorage.setItem(KEY_STORAGE, key);
  let me;
  try {
    me = await call("GET", "/auth/me");
  } catch (error) {
    if (error.status !== 401) signedOut(`The key could not be checked: ${error.message}`);
    return false;
  }
  if (me.role !== "sales") {
    signedOut(
      me.authenticated
        ? `This is a${me.role === "admin" ? "n" : ""} ${me.role} key; quotes need a sales key.`
        : "Enter a sales API key.",
    );
    return false;
  }
  $("key-panel").hidden = true;
  $("who").textContent = `${me.name} (sales key ${me.key_id})`;
  $("who").hidden = false;
  $("sign-out").hidden = false;
  $("create-panel").hidden = false;
  $("list-panel").hidden = false;
  return true;
}

// --- the selection and the form ---------------------------------------------------------

const state = {
  selection: null,
  idempotencyKey: newIdempotencyKey(),
  priceLists: [],
  offset: 0,
};

function showFieldError(id, message) {
  const node = $(id);
  if (!node) return false;
  node.textContent = message;
  node.hidden = false;
  const input = document.querySelector(`[aria-describedby~="${id}"]`);
  if (input) input.setAttribute("aria-invalid", "true");
  return true;
}

function clearErrors() {
  for (const node of document.querySelectorAll(".field-error")) {
    node.hidden = true;
    node.textContent = "";
  }
  for (const node of document.querySelectorAll("[aria-invalid]")) node.removeAttribute("aria-invalid");
  $("form-status").textContent = "";
  $("form-status").className = "form-status";
}

function formStatus(message, kind = "error") {
  const node = $("form-status");
  node.textContent = message;
  node.className = `form-status notice notice-${kind}`;
  node.focus();
}

function summary(selection) {
  const { load, cycle } = selection;
  const counts = { suitable: 0, unconfirmed: 0, unsuitable: 0 };
  for (const c of selection.candidates) counts[c.verdict] += 1;
  return el(
    "dl",
    { className: "facts" },
    el("dt", {}, "Load"),
    el(
      "dd",
      {},
      `n₂ ${number(load.speed_rpm, "rpm")}, T_L ${number(load.torque_nm, "Nm")}, J_L ${number(load.inertia_kgm2, "kgm²")}`,
    ),
    el("dt", {}, "Cycle"),
    el(
      "dd",
      {},
      `t₁ ${cycle.accel_s} s, t₂ ${cycle.constant_s} s, t₃ ${cycle.decel_s} s, t_p ${cycle.pause_s} s — ED ${number(selection.duty_cycle_percent, "%")}`,
    ),
    el("dt", {}, "Candidates"),
    el(
      "dd",
      {},
      `${counts.suitable} suitable, ${counts.unconfirmed} unconfirmed, ${counts.unsuitable} unsuitable`,
    ),
    el("dt", {}, "Catalogue"),
    el("dd", {}, `version ${selection.catalogue_version}, selection of ${selection.created_at.slice(0, 16).replace("T", " ")} UTC`),
  );
}

function fillCandidates(selection) {
  const select = $("f-model");
  select.replaceChildren();
  for (const c of selection.candidates) {
    const label =
      c.verdict === "unsuitable"
        ? `${c.model} — unsuitable, cannot be quoted`
        : `${c.model} — ${c.verdict}`;
    select.append(el("option", { value: c.model, disabled: c.verdict === "unsuitable" }, label));
  }
  const first = selection.candidates.find((c) => c.verdict !== "unsuitable");
  if (first) select.value = first.model;
  describeCandidate();
  return Boolean(first);
}

function describeCandidate() {
  const model = $("f-model").value;
  const candidate = state.selection?.candidates.find((c) => c.model === model);
  const hint = $("hint-model");
  hint.className = "hint";
  if (!candidate) {
    hint.textContent = "";
    return;
  }
  if (candidate.verdict === "unconfirmed") {
    hint.textContent = `Unconfirmed — the quote will say so: ${candidate.reasons.join("; ")}`;
    hint.className = "hint hint-warn";
  } else {
    hint.textContent = `Suitable: every check of the flowchart passed (T_rms ${number(candidate.rms_torque_nm, "Nm")}).`;
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
    showFieldError(
      "err-selection_id",
      error.status === 404 ? `There is no stored selection “${id}”.` : error.message,
    );
    return;
  }
  state.selection = selection;
  const url = new URL(location.href);
  url.searchParams.set("selection", selection.id);
  history.replaceState(null, "", url);
  $("engineer-link").href = `/?selection=${encodeURIComponent(selection.id)}`;
  const box = $("selection-summary");
  box.replaceChildren(el("h3", {}, `Selection ${selection.id}`), summary(selection));
  box.hidden = false;
  if (!fillCandidates(selection)) {
    box.append(el("p", { className: "notice notice-error" }, "No candidate of this selection can be quoted: all are unsuitable."));
    return;
  }
  $("quote-form").hidden = false;
  await loadPriceLists();
}

async function loadPriceLists() {
  if (!state.priceLists.length) {
    try {
      state.priceLists = await call("GET", "/price-lists");
    } catch (error) {
      formStatus(`Price lists could not be loaded: ${error.message}`);
      return;
    }
  }
  const select = $("f-price-list");
  const chosen = select.value;
  select.replaceChildren();
  for (const list of state.priceLists) {
    const label = list.is_example ? `${list.name} (example prices)` : list.name;
    select.append(el("option", { value: list.name }, `${label} — ${list.currencies.join(", ")}`));
  }
  if (!state.priceLists.length) {
    formStatus("There is no price list yet: an administrator imports one first.");
  }
  if (chosen) select.value = chosen;
  else {
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
    discount_percent: text("f-discount") || "0",
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
    if (id && showFieldError(id, e.msg)) shown += 1;
    else other.push(e.msg);
  }
  const lead = shown ? "Please correct the marked fields." : "";
  formStatus([lead, ...other].filter(Boolean).join(" ") || error.message);
}

async function createQuote(event) {
  event.preventDefault();
  clearErrors();
  if (!text("f-customer")) {
    showFieldError("err-customer-name", "The customer's name is required.");
    formStatus("Please correct the marked fields.");
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
      formStatus("The server could not be reached. Send again: the quote will not be created twice.");
    } else if (error.status !== 401) {
      showErrors(error);
    }
  } finally {
    button.disabled = false;
  }
}

function showCreated(quote) {
  const box = $("created");
  const flags = [];
  if (quote.price_list.is_example) flags.push("example prices, not real ones");
  if (quote.unconfirmed) flags.push("suitability unconfirmed");
  box.replaceChildren(
    el(
      "p",
      {},
      "Quote ",
      el("strong", { className: "quote-number" }, quote.number),
      ` created: total ${money(quote.total, quote.currency)}`,
      flags.length ? ` (${flags.join("; ")})` : "",
      ". ",
    ),
    documentButton(quote.number),
  );
  box.hidden = false;
  box.focus?.();
}

// --- the list ---------------------------------------------------------------------------

function documentButton(number) {
  return el(
    "button",
    { type: "button", className: "document-button", onclick: () => openDocument(number) },
    "Open document",
  );
}

async function openDocument(number) {
  // Opened now, inside the click, so that a popup blocker lets it through; filled below.
  const win = window.open("", "_blank");
  if (!win) {
    $("list-status").textContent = "The browser blocked the new window; allow pop-ups for this page.";
    return;
  }
  win.document.title = `Quote ${number}`;
  win.document.body.textContent = "Loading the quote …";
  try {
    const html = await call("GET", `/quotes/${encodeURIComponent(number)}/document`, {
      accept: "text/html",
    });
    win.document.open();
    win.document.write(html);
    win.document.close();
  } catch (error) {
    win.document.body.textContent = `The document could not be loaded: ${error.message}`;
  }
}

async function move(number, status) {
  try {
    await call("POST", `/quotes/${encodeURIComponent(number)}/status`, { body: { status } });
    $("list-status").textContent = `${number} is now ${status}.`;
  } catch (error) {
    if (error.status !== 401) $("list-status").textContent = `${number}: ${error.message}`;
  }
  await search({ keepOffset: true });
}

const ACTION_LABELS = { sent: "Mark sent", accepted: "Accepted", rejected: "Rejected" };

function row(quote) {
  const actions = el("div", { className: "actions-cell" }, documentButton(quote.number));
  for (const status of quote.allowed_transitions) {
    actions.append(
      el(
        "button",
        { type: "button", className: `move move-${status}`, onclick: () => move(quote.number, status) },
        ACTION_LABELS[status] || status,
      ),
    );
  }
  const flags = [];
  if (quote.price_list.is_example) flags.push(el("span", { className: "tag tag-example" }, "example prices"));
  if (quote.unconfirmed) flags.push(el("span", { className: "tag tag-warn" }, "unconfirmed"));
  return el(
    "tr",
    { dataset: { number: quote.number } },
    el("td", { className: "mono" }, quote.number),
    el("td", {}, quote.customer.name, quote.customer.reference ? el("div", { className: "hint" }, quote.customer.reference) : null),
    el("td", {}, quote.actuator_model, " ", ...flags),
    el("td", { className: "num" }, money(quote.total, quote.currency)),
    el("td", {}, el("span", { className: `status status-${quote.status}` }, quote.status)),
    el("td", { className: "date" }, quote.valid_until),
    el("td", {}, actions),
  );
}

async function search({ append = false, keepOffset = false } = {}) {
  if (!append && !keepOffset) state.offset = 0;
  const params = new URLSearchParams({ limit: String(append ? PAGE_SIZE : state.offset + PAGE_SIZE) });
  if (append) params.set("offset", String(state.offset));
  const q = $("q").value.trim();
  const status = $("status-filter").value;
  if (q) params.set("q", q);
  if (status) params.set("status", status);
  let page;
  try {
    page = await call("GET", `/quotes?${params}`);
  } catch (error) {
    if (error.status !== 401) $("list-status").textContent = error.message;
    return;
  }
  const body = $("quotes").tBodies[0];
  if (!append) body.replaceChildren();
  for (const quote of page.quotes) body.append(row(quote));
  state.offset = body.rows.length;
  $("more").hidden = state.offset >= page.total;
  if (!page.total) $("list-status").textContent = q || status ? "No quote matches." : "No quotes yet.";
  else if (!$("list-status").textContent.includes(" is now ")) {
    $("list-status").textContent = `${page.total} quote${page.total === 1 ? "" : "s"}.`;
  }
}

// --- start ------------------------------------------------------------------------------

async function start() {
  $("f-valid").value = isoDate(30);
  $("key-form").addEventListener("submit", async (event) => {
    event.preventDefault();
    const key = $("api-key").value.trim();
    $("api-key").value = "";
    if (key && (await signIn(key))) await afterSignIn();
  });
  $("sign-out").addEventListener("click", () => signedOut(""));
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
    $("list-status").textContent = "";
    search();
  });
  $("more").addEventListener("click", () => search({ append: true }));

  const stored = apiKey();
  if (stored && (await signIn(stored))) await afterSignIn();
  else if (!stored) signedOut("");
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
