// Files on the form: a measured motion profile (CSV: a PLC trace, a CAM table, the IDTA
// 02021 motion file) read by POST /profiles into the segments the flowchart sizes, its
// cycle chart shown before sizing and its segments put into the segment editor; and an
// IDTA 02021 sizing record (AASX or AAS JSON) sized by POST /selections/from-aas, which
// then opens as a stored selection. Every number comes from the server
// (docs/profiles.md, docs/aas.md); this module only shows them.

import { createClient } from "../../lib/api.js";
import { $$as, $as, h } from "../../lib/dom.js";
import { num } from "../../lib/format.js";
import { translate } from "../../lib/i18n.js";
import { loadPlotly } from "../../lib/plotly.js";
import { fillSegments } from "./segments.js";

const lang = () => (document.documentElement.lang === "en" ? "en" : "de");
const t = (key, params) => translate(lang(), key, params);
const api = createClient({ headers: () => ({ "Accept-Language": lang() }) });

/** Units a heading may lack, chosen on upload (pint's spelling; "" = from the heading). */
const UNIT_CHOICES = {
  velocity_unit: ["", "rpm", "rad/s", "deg/s", "mm/s", "m/s"],
  position_unit: ["", "deg", "rad", "turn", "mm", "m"],
  load_unit: ["", "N*m", "N"],
};

let profile = null; // the last answer of POST /profiles

function unitSelect(name) {
  const id = `profile-${name.replace("_", "-")}`;
  return h(
    "div",
    { class: "field" },
    h("label", { for: id, "data-i18n": `profile.${name}` }),
    h(
      "select",
      { id, "data-profile-unit": name },
      ...UNIT_CHOICES[name].map((u) => h("option", { value: u }, u || "–")),
    ),
  );
}

function build(slot) {
  slot.replaceChildren(
    h(
      "fieldset",
      { class: "profile-upload", id: "profile-fieldset" },
      h("legend", { class: "sub-legend", "data-i18n": "profile.legend" }),
      h("p", { class: "hint", id: "profile-hint", "data-i18n": "profile.hint" }),
      h(
        "div",
        { class: "field" },
        h("label", { for: "profile-file", "data-i18n": "profile.file" }),
        h("input", {
          id: "profile-file",
          type: "file",
          accept: ".csv,.txt,.tsv,text/csv,text/plain",
          "aria-describedby": "profile-hint err-profile",
        }),
      ),
      h("div", { class: "profile-units" }, ...Object.keys(UNIT_CHOICES).map(unitSelect)),
      h("p", { class: "field-error", id: "err-profile", role: "alert", hidden: true }),
      h("div", { id: "profile-summary", "aria-live": "polite" }),
      h("div", { id: "profile-chart", class: "chart" }),
    ),
    h(
      "fieldset",
      { class: "profile-upload", id: "aas-fieldset" },
      h("legend", { class: "sub-legend", "data-i18n": "aas.legend" }),
      h("p", { class: "hint", id: "aas-hint", "data-i18n": "aas.hint" }),
      h(
        "div",
        { class: "field" },
        h("label", { for: "aas-file", "data-i18n": "aas.file" }),
        h("input", {
          id: "aas-file",
          type: "file",
          accept: ".aasx,.json,application/json",
          "aria-describedby": "aas-hint err-aas",
        }),
      ),
      h("p", { class: "field-error", id: "err-aas", role: "alert", hidden: true }),
    ),
  );
  for (const el of slot.querySelectorAll("[data-i18n]")) el.textContent = t(el.dataset.i18n);
}

function showError(id, error) {
  const el = document.getElementById(id);
  el.hidden = !error;
  el.textContent = error ? error.detail ?? error.message : "";
  if (error?.lang) el.lang = error.lang;
}

function summary() {
  const box = document.getElementById("profile-summary");
  if (!profile) return box.replaceChildren();
  const f = profile.figures.samples;
  const s = profile.figures.segments;
  const u = profile.speed_unit;
  const items = [
    t("profile.read", { samples: profile.samples, segments: profile.cycle.segments.length }),
    `t_0 = ${num(f.cycle_time_s, lang())} s`,
    `n_av = ${num(f.mean_speed, lang())} ${u} (${t("profile.segments")}: ${num(s.mean_speed, lang())})`,
    `ED = ${num(f.duty_cycle_percent, lang())} % (${t("profile.segments")}: ${num(s.duty_cycle_percent, lang())})`,
    `|v|max = ${num(f.peak_speed, lang())} ${u}`,
    profile.fit.exact
      ? t("profile.exact", { tolerance: num(profile.fit.tolerance_percent, lang()) })
      : t("profile.approx", { deviation: num(profile.fit.speed_deviation, lang()), unit: u }),
  ];
  box.replaceChildren(
    h("ul", { class: "profile-figures" }, ...items.map((text) => h("li", {}, text))),
    ...profile.notes.map((n) => h("p", { class: "notice notice-warn", lang: "en" }, n.msg)),
  );
}

async function chart() {
  const el = document.getElementById("profile-chart");
  if (!profile) return el.replaceChildren();
  let Plotly;
  try {
    Plotly = await loadPlotly();
  } catch {
    return; // the figures above stand without the chart
  }
  const x = [0];
  const y = [profile.cycle.start_speed];
  for (const seg of profile.cycle.segments) {
    x.push(x[x.length - 1] + seg.duration_s);
    y.push(seg.speed);
  }
  const start = profile.preview.time_s[0] ?? 0;
  Plotly.react(
    el,
    [
      {
        x: profile.preview.time_s.map((v) => v - start),
        y: profile.preview.speed,
        name: t("profile.samples"),
        mode: "lines",
        line: { width: 1, color: "#9aa5b1" },
      },
      { x, y, name: t("profile.segments"), mode: "lines", line: { width: 2, color: "#0b5cad" } },
    ],
    {
      title: { text: t("profile.chart") },
      xaxis: { title: { text: "t [s]" } },
      yaxis: { title: { text: `v [${profile.speed_unit}]` } },
      margin: { t: 40, r: 10, b: 50, l: 60 },
      height: 260,
      showlegend: true,
      legend: { orientation: "h" },
    },
    { displayModeBar: false, responsive: true },
  );
}

function useProfile() {
  fillSegments(profile.cycle.segments, profile.cycle.start_speed);
  const radio = $as('input[name="cycle-mode"][value="segments"]', HTMLInputElement);
  if (radio && !radio.checked) {
    radio.checked = true;
    radio.dispatchEvent(new Event("change", { bubbles: true }));
  }
}

async function uploadProfile(file) {
  const params = new URLSearchParams();
  for (const el of $$as("[data-profile-unit]", HTMLSelectElement)) {
    if (el.value) params.set(el.dataset.profileUnit, el.value);
  }
  const query = params.toString() ? `?${params}` : "";
  showError("err-profile", null);
  try {
    profile = await api.upload(`/profiles${query}`, file, "text/csv");
  } catch (error) {
    profile = null;
    showError("err-profile", error);
  }
  summary();
  await chart();
  if (profile) useProfile();
}

async function uploadRecord(file) {
  showError("err-aas", null);
  const type = file.name.toLowerCase().endsWith(".json")
    ? "application/json"
    : "application/asset-administration-shell-package";
  try {
    const selection = await api.upload("/selections/from-aas", file, type);
    window.location.assign(`/?selection=${encodeURIComponent(selection.id)}`);
  } catch (error) {
    showError("err-aas", error);
  }
}

/** The file a file input's ``change`` event chose, if any. @param {Event} event */
function chosenFile(event) {
  return event.target instanceof HTMLInputElement ? event.target.files?.[0] : undefined;
}

/** Build the uploads into ``#profile-slot`` and wire them (called once by app.js). */
export function initProfile() {
  const slot = document.getElementById("profile-slot");
  if (!slot) return;
  build(slot);
  // not fields of the request: the form's handlers stay out of their events
  for (const id of ["profile-file", "aas-file", ...Object.keys(UNIT_CHOICES).map((n) => `profile-${n.replace("_", "-")}`)]) {
    for (const type of ["input", "change"]) {
      document.getElementById(id).addEventListener(type, (event) => event.stopPropagation());
    }
  }
  document.getElementById("profile-file").addEventListener("change", (event) => {
    const file = chosenFile(event);
    if (file) uploadProfile(file);
  });
  document.getElementById("aas-file").addEventListener("change", (event) => {
    const file = chosenFile(event);
    if (file) uploadRecord(file);
  });
  // the words follow the page's language (app.js sets <html lang>)
  new MutationObserver(() => {
    for (const el of $$as("[data-i18n]", HTMLElement, slot)) el.textContent = t(el.dataset.i18n);
    summary();
    chart();
  }).observe(document.documentElement, { attributes: true, attributeFilter: ["lang"] });
}
