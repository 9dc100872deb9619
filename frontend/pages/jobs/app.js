// The batch jobs page: submit load cases as a job, follow its progress bar, download
// or cancel it. Every figure (cases done, ETA) is the job resource's, as the API
// answers it (GET /batch-jobs/{id}); the page polls it once a second until the job ends.

import { API, createClient, errorFromBody } from "../../lib/api.js";
import { byId, h, notice, said } from "../../lib/dom.js";
import { LANGS, applyStaticTexts, initialLang, rememberLang, translate } from "../../lib/i18n.js";

const POLL_MS = 1000;
const ENDED = ["done", "failed", "cancelled"];

/** @type {{lang: string, location: string | null, job: any, timer: number | null}} */
const state = { lang: "en", location: null, job: null, timer: null };

const t = (/** @type {string} */ key, /** @type {Record<string, unknown>} */ params = {}) =>
  translate(state.lang, key, params);

const api = createClient({ base: "", headers: () => ({ "Accept-Language": state.lang }) });

/** The element of ``id``, typed as the caller needs it. */
function el(/** @type {string} */ id) {
  return /** @type {any} */ (byId(id));
}

/** The worked example of Table 516.1 at ``n`` load speeds (10…59 min⁻¹), as JSON lines. */
function exampleCases(/** @type {number} */ n) {
  const lines = [];
  for (let i = 0; i < n; i += 1) {
    lines.push(
      JSON.stringify({
        case_id: `example-${i + 1}`,
        load: { speed_rpm: 10 + (i % 50), torque_nm: 5, inertia_kgm2: 1.3 },
        cycle: { accel_s: 0.1, constant_s: 0.1, decel_s: 0.1, pause_s: 1.0 },
      }),
    );
  }
  return lines.join("\n");
}

function showError(/** @type {any} */ error) {
  const box = el("job-error");
  const text = error?.detail ?? t("jobs.error.network");
  box.replaceChildren(notice("error", said(text, error?.lang ?? "en")));
}

async function submit(/** @type {Event} */ event) {
  event.preventDefault();
  el("job-error").replaceChildren();
  const params = new URLSearchParams({
    top: String(el("job-top").value || 3),
    include_checks: String(el("job-checks").checked),
  });
  el("job-submit").disabled = true;
  try {
    const response = await fetch(`${API}/batch-jobs?${params}`, {
      method: "POST",
      headers: { "Content-Type": "application/x-ndjson", "Accept-Language": state.lang },
      body: el("job-cases").value,
    });
    const data = await response.json().catch(() => null);
    if (response.status !== 202) {
      const lang = response.headers.get("Content-Language") ?? "en";
      showError(errorFromBody(response.status, data, lang));
      return;
    }
    state.location = response.headers.get("Location");
    show(data);
    schedule();
  } catch {
    showError(null);
  } finally {
    el("job-submit").disabled = false;
  }
}

function schedule() {
  if (state.timer !== null) window.clearTimeout(state.timer);
  state.timer = window.setTimeout(poll, POLL_MS);
}

async function poll() {
  state.timer = null;
  if (!state.location) return;
  try {
    show(await api.get(state.location));
  } catch (error) {
    showError(error);
  }
  if (state.job && !ENDED.includes(state.job.state)) schedule();
}

function show(/** @type {any} */ job) {
  state.job = job;
  el("job-section").hidden = false;
  const bar = el("job-progress");
  bar.value = job.progress;
  bar.setAttribute("aria-valuetext", `${Math.round(job.progress * 100)} %`);
  const parts = [
    t(`jobs.state.${job.state}`),
    t("jobs.counts", { done: job.cases_done, cases: job.cases, percent: Math.round(job.progress * 100) }),
  ];
  if (job.eta_s !== null && job.state === "running") parts.push(t("jobs.eta", { s: Math.ceil(job.eta_s) }));
  const status = el("job-status");
  status.replaceChildren(parts.join(" · "));
  if (job.error) status.append(" ", h("span", { lang: "en" }, job.error));
  el("job-cancel").hidden = ENDED.includes(job.state);
  for (const [id, query] of [["job-results", ""], ["job-results-csv", "?format=csv"]]) {
    const link = el(id);
    link.hidden = job.state !== "done";
    if (job.state === "done" && state.location) link.href = `${state.location}/results${query}`;
  }
}

async function cancel() {
  if (!state.location) return;
  try {
    show(await api.post(`${state.location}/cancel`, undefined));
  } catch (error) {
    showError(error);
  }
}

function applyLang(/** @type {string} */ lang) {
  state.lang = LANGS.includes(lang) ? lang : "de";
  document.documentElement.lang = state.lang;
  applyStaticTexts(document, state.lang);
  for (const button of document.querySelectorAll(".lang-button")) {
    button.setAttribute("aria-pressed", String(/** @type {HTMLElement} */ (button).dataset.lang === state.lang));
  }
  document.title = `${t("jobs.title")} · ${t("app.title")}`;
  if (state.job) show(state.job);
}

function start() {
  applyLang(initialLang());
  for (const button of document.querySelectorAll(".lang-button")) {
    button.addEventListener("click", () => {
      const lang = /** @type {HTMLElement} */ (button).dataset.lang ?? "en";
      rememberLang(lang);
      applyLang(lang);
    });
  }
  el("job-example").addEventListener("click", () => {
    el("job-cases").value = exampleCases(Math.max(1, Number(el("job-example-count").value) || 1));
  });
  el("job-form").addEventListener("submit", submit);
  el("job-cancel").addEventListener("click", cancel);
}

start();
