import { appendSymbols, plainSymbols } from "./symbols.js";

// Bilingual texts, German first as in the manufacturer's chapter.
// The API answers in English; check names, statuses, verdicts and references
// are translated here, API messages are shown as they come (marked lang="en").

export const LANGS = ["de", "en"];
const STORAGE_KEY = "actuator-selection.lang";

const TEXTS = {
  de: {
    "app.title": "Antriebsauslegung",
    "app.sales": "Angebote (Vertrieb)",
    "app.subtitle": "Harmonic Drive Servoantriebe · Flussdiagramm, Gl. 514.1–514.4, Abb. 516.2 und 517.1",
    "lang.group": "Sprache",
    "skip": "Zum Ergebnis springen",

    "form.heading": "Belastungsdaten",
    "load.legend": "Last",
    "load.kind": "Art der Last",
    "load.direct": "Direkt am Abtrieb",
    "load.ball_screw": "Lineare Horizontalbewegung (Kugelgewindetrieb)",
    "load.rotary_table": "Rotationsbewegung (Drehtisch)",
    "load.speed": "Drehzahl der Last",
    "load.torque": "Lastdrehmoment (z. B. Reibung)",
    "load.inertia": "Trägheitsmoment der Last",
    "load.mass": "Masse",
    "load.lead": "Spindelsteigung",
    "load.friction": "Reibungskoeffizient",
    "load.efficiency": "Wirkungsgrad",
    "load.screw_inertia": "Trägheitsmoment der Spindel",
    "load.diameter": "Durchmesser des Tisches",
    "load.friction_radius": "Radius der Reibung",
    "load.ball_screw.eq": "Gl. 515.4, Abb. 515.2",
    "load.rotary_table.eq": "Gl. 515.6, Abb. 515.3/515.5",
    "resolved.label": "Umgerechnet vom Server",
    "resolved.pending": "T_L und J_L erscheinen nach der Berechnung.",
    "resolved.stale": "(für die vorige Eingabe)",

    "cycle.legend": "Zykluszeiten (Abb. 516.2)",
    "cycle.accel": "Beschleunigen",
    "cycle.constant": "Fahren mit Arbeitsdrehzahl",
    "cycle.decel": "Bremsen",
    "cycle.pause": "Stillstand",
    "cycle.sum": "Summe der Eingaben",
    "cycle.sum.note": "Eingabe-Echo; maßgeblich ist t_0 aus dem Ergebnis",

    "options.legend": "Optionen",
    "options.high_dynamics": "Hochdynamischer Einsatzfall: J_L ≤ 3·J_A ist bindend (Tabelle 515.1, Fußnote 1)",
    "options.models": "Nur diese Antriebe (optional)",
    "options.models.hint": "Modellnamen durch Komma getrennt, z. B. FHA-25C-50-L, CHA-25A-50",

    "form.submit": "Antriebe auswählen",
    "form.running": "Berechnung läuft …",
    "form.example": "Beispiel Tabelle 516.1 einsetzen",
    "form.errors": "Die Eingabe wurde abgelehnt. Bitte die markierten Felder prüfen.",
    "form.error.count": "{n} Eingabe(n) abgelehnt",

    "results.heading": "Ergebnis",
    "results.empty": "Noch keine Berechnung. Last und Zyklus eingeben und „Antriebe auswählen“ drücken – oder das Beispiel aus Tabelle 516.1 einsetzen.",
    "results.loading": "Berechnung läuft …",
    "results.loading.permalink": "Gespeicherte Auswahl wird geladen …",
    "results.stale": "Die Eingaben wurden geändert; das Ergebnis gilt für die vorige Eingabe.",
    "results.none": "Kein Antrieb im Katalog.",
    "results.notfound": "Gespeicherte Auswahl nicht gefunden",
    "results.network": "Der Server ist nicht erreichbar. Bitte später erneut versuchen.",
    "results.server": "Der Server konnte die Anfrage nicht bearbeiten",
    "results.badresponse": "Unerwartete Antwort vom Server.",
    "results.done": "{suitable} geeignet, {unconfirmed} nicht bestätigt, {unsuitable} ungeeignet. Gewählt: {model}.",

    "summary.heading": "Lastfall",
    "summary.cycle_time": "Gesamtzykluszeit",
    "summary.mean_speed": "Mittlere Drehzahl",
    "summary.duty": "Einschaltdauer",
    "summary.speed": "Drehzahl der Last",
    "summary.torque": "Lastdrehmoment",
    "summary.inertia": "Trägheitsmoment der Last",
    "summary.high_dynamics": "Hochdynamisch",
    "summary.yes": "ja",
    "summary.no": "nein",
    "summary.mechanism": "Mechanik",
    "summary.ranking": "Reihenfolge (Text des Servers)",
    "summary.created": "Berechnet am",
    "summary.catalogue": "Katalogversion",

    "permalink.label": "Link zu diesem Ergebnis",
    "permalink.copy": "Link kopieren",
    "permalink.copied": "Link kopiert.",
    "permalink.copyfail": "Kopieren nicht möglich – Link markieren und manuell kopieren.",

    "filter.label": "Anzeigen",
    "filter.all": "alle",

    "table.caption": "Antriebe in Rangfolge: geeignet, nicht bestätigt, ungeeignet; jeweils der kleinste zuerst. Zeile oder Modell wählen, um Prüfungen und Diagramme zu sehen.",
    "table.rank": "Rang",
    "table.model": "Antrieb",
    "table.verdict": "Ergebnis",
    "table.checks": "Prüfungen",
    "table.reason": "Begründung",
    "table.reason.none": "alle Prüfungen erfüllt",
    "table.select": "{model} wählen",

    "detail.heading": "Gewählter Antrieb",
    "detail.family": "Baureihe",
    "detail.ratio": "Untersetzung",
    "detail.checks": "Prüfungen nach dem Flussdiagramm",
    "detail.check": "Prüfung",
    "detail.value": "Wert",
    "detail.limit": "Grenze",
    "detail.status": "Status",
    "detail.margin": "Reserve",
    "detail.reference": "Quelle",
    "detail.message": "Meldung des Servers",
    "detail.reasons": "Begründung",
    "detail.controllers": "Passende Servoregler (Tabelle 521.1)",
    "detail.controllers.none": "Kein Regler aus Tabelle 521.1 passt zu diesem Antrieb.",
    "detail.approximate": "näherungsweise",
    "detail.approximate.long": "näherungsweise: vereinfachte Grenze statt Dauerbetriebsbereich",

    "controller.tested": "praktisch erprobt",
    "controller.possible": "theoretisch machbar",
    "controller.unconfirmed": "nicht bestätigt",
    "controller.excluded": "ausgeschlossen",
    "controller.no_data": "keine Daten",
    "controller.name": "Servoregler",
    "controller.level": "Einstufung",
    "controller.criteria": "Kriterien (Tabelle 521.1)",
    "controller.voltage": "Reglerausgangsspannung U_OUT (Gl. 521.2), Wert / verfügbar",
    "detail.controllers.count": "{n} nicht ausgeschlossen",
    "detail.controllers.excluded": "{n} ausgeschlossen",
    "criterion.family": "Baureihe",
    "criterion.bus_class": "Zwischenkreis",
    "criterion.temperature_sensor": "Temperatursensor",
    "criterion.feedback_system": "Motorfeedback",

    "verdict.suitable": "geeignet",
    "verdict.unconfirmed": "nicht bestätigt",
    "verdict.unsuitable": "ungeeignet",

    "status.pass": "erfüllt",
    "status.fail": "nicht erfüllt",
    "status.warn": "Warnung",
    "status.no_data": "keine Daten",

    "check.max_speed": "Max. Drehzahl n_2 ≤ n_max",
    "check.inertia_ratio": "Trägheitsverhältnis J_L ≤ 3·J_A",
    "check.peak_torque": "Beschleunigungsmoment T_1 ≤ T_max",
    "check.decel_torque": "Bremsmoment |T_3| ≤ T_max",
    "check.continuous_duty": "Dauerbetrieb (n_av, T_rms) im Dauerbetriebsbereich",

    "check.short.max_speed": "n_2 ≤ n_max",
    "check.short.inertia_ratio": "J_L ≤ 3·J_A",
    "check.short.peak_torque": "T_1 ≤ T_max",
    "check.short.decel_torque": "|T_3| ≤ T_max",
    "check.short.continuous_duty": "Dauerbetrieb",

    "ref.Table": "Tabelle",
    "ref.Eq.": "Gl.",
    "ref.Fig.": "Abb.",

    "charts.cycle": "Zyklus: Drehzahl und Drehmoment (wie Abb. 516.2)",
    "charts.diagram": "Drehzahl/Drehmoment-Diagramm (wie Abb. 517.1)",
    "charts.loading": "Diagramm wird gezeichnet …",
    "charts.unavailable": "Diagramm nicht verfügbar: plotly.js konnte nicht geladen werden.",
    "charts.catalogue_missing": "Katalogdaten des Antriebs nicht verfügbar",

    "fig.time": "Zeit t [s]",
    "fig.speed": "Drehzahl n [min⁻¹]",
    "fig.torque": "Drehmoment T [Nm]",
    "fig.speed_trace": "Drehzahl n(t)",
    "fig.torque_trace": "Drehmoment T(t)",
    "fig.rms_trace": "T_rms (Effektivwert)",
    "fig.zone": "Dauerbetriebsbereich",
    "fig.zone_approx": "≈ Dauerbetrieb bis {what} (näherungsweise)",
    "fig.zone_nodata": "Dauerbetriebsbereich: keine Daten",
    "fig.t_max": "T_max",
    "fig.n_max": "n_max",
    "fig.operating": "Betriebspunkt (n_av, T_rms)",
    "fig.peak_accel": "Spitze (n_2, T_1)",
    "fig.peak_decel": "Spitze (n_2, |T_3|)",
    "fig.torques_nodata": "keine Daten: T_1, T_3 brauchen J_A",
    "fig.stall": "T_0",
    "fig.continuous": "zul. Dauerdrehmoment",
    "fig.caption.cycle": "n_2 = {n2}; T_1 = {t1}, T_2 = {t2}, T_3 = {t3}, T_rms = {trms}; t_1 = {a}, t_2 = {c}, t_3 = {d}, t_p = {p}; t_0 = {t0}.",
    "fig.caption.diagram": "Betriebspunkt n_av = {nav}, T_rms = {trms}; Spitzen bei n_2 = {n2}: T_1 = {t1}, |T_3| = {t3}; T_max = {tmax}, n_max = {nmax}; {zone}.",
    "fig.caption.zone": "Dauerbetriebsbereich aus dem Katalog",
    "fig.caption.approx": "Dauerbetrieb näherungsweise bis {what} = {value}",
    "fig.caption.nodata": "Dauerbetriebsbereich: keine Daten",

    "unit.rpm": "min⁻¹",
    "noscript": "Diese Seite braucht JavaScript.",
  },
  en: {
    "app.title": "Actuator selection",
    "app.sales": "Quotes (sales)",
    "app.subtitle": "Harmonic Drive servo actuators · flowchart, Eq. 514.1–514.4, Fig. 516.2 and 517.1",
    "lang.group": "Language",
    "skip": "Skip to results",

    "form.heading": "Load conditions",
    "load.legend": "Load",
    "load.kind": "Kind of load",
    "load.direct": "Direct, at the output",
    "load.ball_screw": "Linear horizontal motion (ball screw)",
    "load.rotary_table": "Rotary motion (rotary table)",
    "load.speed": "Load rotation speed",
    "load.torque": "Load torque (e.g. friction)",
    "load.inertia": "Load inertia",
    "load.mass": "Mass",
    "load.lead": "Screw lead",
    "load.friction": "Coefficient of friction",
    "load.efficiency": "Efficiency",
    "load.screw_inertia": "Screw inertia",
    "load.diameter": "Table diameter",
    "load.friction_radius": "Friction radius",
    "load.ball_screw.eq": "Eq. 515.4, Fig. 515.2",
    "load.rotary_table.eq": "Eq. 515.6, Fig. 515.3/515.5",
    "resolved.label": "Converted by the server",
    "resolved.pending": "T_L and J_L appear after the calculation.",
    "resolved.stale": "(for the previous input)",

    "cycle.legend": "Speed pattern (Fig. 516.2)",
    "cycle.accel": "Acceleration",
    "cycle.constant": "Operate with rated speed",
    "cycle.decel": "Deceleration",
    "cycle.pause": "Stand still",
    "cycle.sum": "Sum of the inputs",
    "cycle.sum.note": "input echo; the result's t_0 is authoritative",

    "options.legend": "Options",
    "options.high_dynamics": "Highly dynamic application: J_L ≤ 3·J_A is binding (Table 515.1, footnote 1)",
    "options.models": "Only these actuators (optional)",
    "options.models.hint": "model names separated by commas, e.g. FHA-25C-50-L, CHA-25A-50",

    "form.submit": "Select actuators",
    "form.running": "Calculating …",
    "form.example": "Use the example of Table 516.1",
    "form.errors": "The input was rejected. Please check the marked fields.",
    "form.error.count": "{n} input(s) rejected",

    "results.heading": "Result",
    "results.empty": "No calculation yet. Enter the load and the cycle and press “Select actuators” – or use the example of Table 516.1.",
    "results.loading": "Calculating …",
    "results.loading.permalink": "Loading the stored selection …",
    "results.stale": "The inputs have changed; this result is for the previous input.",
    "results.none": "No actuator in the catalogue.",
    "results.notfound": "Stored selection not found",
    "results.network": "The server cannot be reached. Please try again later.",
    "results.server": "The server could not process the request",
    "results.badresponse": "Unexpected answer from the server.",
    "results.done": "{suitable} suitable, {unconfirmed} unconfirmed, {unsuitable} unsuitable. Chosen: {model}.",

    "summary.heading": "Load case",
    "summary.cycle_time": "Total cycle time",
    "summary.mean_speed": "Average speed",
    "summary.duty": "Duty cycle",
    "summary.speed": "Load rotation speed",
    "summary.torque": "Load torque",
    "summary.inertia": "Load inertia",
    "summary.high_dynamics": "Highly dynamic",
    "summary.yes": "yes",
    "summary.no": "no",
    "summary.mechanism": "Mechanism",
    "summary.ranking": "Ranking (server's text)",
    "summary.created": "Calculated at",
    "summary.catalogue": "Catalogue version",

    "permalink.label": "Link to this result",
    "permalink.copy": "Copy link",
    "permalink.copied": "Link copied.",
    "permalink.copyfail": "Cannot copy – select the link and copy it by hand.",

    "filter.label": "Show",
    "filter.all": "all",

    "table.caption": "Actuators ranked: suitable, unconfirmed, unsuitable; the smallest first within each. Choose a row or model to see its checks and charts.",
    "table.rank": "Rank",
    "table.model": "Actuator",
    "table.verdict": "Verdict",
    "table.checks": "Checks",
    "table.reason": "Reason",
    "table.reason.none": "all checks passed",
    "table.select": "Choose {model}",

    "detail.heading": "Chosen actuator",
    "detail.family": "Family",
    "detail.ratio": "Gear ratio",
    "detail.checks": "Checks of the flowchart",
    "detail.check": "Check",
    "detail.value": "Value",
    "detail.limit": "Limit",
    "detail.status": "Status",
    "detail.margin": "Margin",
    "detail.reference": "Reference",
    "detail.message": "Server's message",
    "detail.reasons": "Reason",
    "detail.controllers": "Compatible servo controllers (Table 521.1)",
    "detail.controllers.none": "No controller of Table 521.1 fits this actuator.",
    "detail.approximate": "approximate",
    "detail.approximate.long": "approximate: a simplified limit stands in for the continuous-duty zone",

    "controller.tested": "tested",
    "controller.possible": "possible",
    "controller.unconfirmed": "unconfirmed",
    "controller.excluded": "excluded",
    "controller.no_data": "no data",
    "controller.name": "Servo controller",
    "controller.level": "Rating",
    "controller.criteria": "Criteria (Table 521.1)",
    "controller.voltage": "Controller output voltage U_OUT (Eq. 521.2), value / available",
    "detail.controllers.count": "{n} not excluded",
    "detail.controllers.excluded": "{n} excluded",
    "criterion.family": "family",
    "criterion.bus_class": "DC bus",
    "criterion.temperature_sensor": "temperature sensor",
    "criterion.feedback_system": "motor feedback",

    "verdict.suitable": "suitable",
    "verdict.unconfirmed": "unconfirmed",
    "verdict.unsuitable": "unsuitable",

    "status.pass": "pass",
    "status.fail": "fail",
    "status.warn": "warning",
    "status.no_data": "no data",

    "check.max_speed": "Max. speed n_2 ≤ n_max",
    "check.inertia_ratio": "Inertia ratio J_L ≤ 3·J_A",
    "check.peak_torque": "Acceleration torque T_1 ≤ T_max",
    "check.decel_torque": "Deceleration torque |T_3| ≤ T_max",
    "check.continuous_duty": "Continuous duty (n_av, T_rms) in the continuous-duty zone",

    "check.short.max_speed": "n_2 ≤ n_max",
    "check.short.inertia_ratio": "J_L ≤ 3·J_A",
    "check.short.peak_torque": "T_1 ≤ T_max",
    "check.short.decel_torque": "|T_3| ≤ T_max",
    "check.short.continuous_duty": "continuous duty",

    "ref.Table": "Table",
    "ref.Eq.": "Eq.",
    "ref.Fig.": "Fig.",

    "charts.cycle": "Cycle: speed and torque (as Fig. 516.2)",
    "charts.diagram": "Speed/torque diagram (as Fig. 517.1)",
    "charts.loading": "Drawing the chart …",
    "charts.unavailable": "Chart unavailable: plotly.js could not be loaded.",
    "charts.catalogue_missing": "catalogue data of the actuator unavailable",

    "fig.time": "Time t [s]",
    "fig.speed": "Speed n [rpm]",
    "fig.torque": "Torque T [Nm]",
    "fig.speed_trace": "Speed n(t)",
    "fig.torque_trace": "Torque T(t)",
    "fig.rms_trace": "T_rms (root mean square)",
    "fig.zone": "Continuous-duty zone",
    "fig.zone_approx": "≈ continuous duty up to {what} (approximate)",
    "fig.zone_nodata": "Continuous-duty zone: no data",
    "fig.t_max": "T_max",
    "fig.n_max": "n_max",
    "fig.operating": "Operating point (n_av, T_rms)",
    "fig.peak_accel": "Peak (n_2, T_1)",
    "fig.peak_decel": "Peak (n_2, |T_3|)",
    "fig.torques_nodata": "no data: T_1, T_3 need J_A",
    "fig.stall": "T_0",
    "fig.continuous": "allowable continuous torque",
    "fig.caption.cycle": "n_2 = {n2}; T_1 = {t1}, T_2 = {t2}, T_3 = {t3}, T_rms = {trms}; t_1 = {a}, t_2 = {c}, t_3 = {d}, t_p = {p}; t_0 = {t0}.",
    "fig.caption.diagram": "Operating point n_av = {nav}, T_rms = {trms}; peaks at n_2 = {n2}: T_1 = {t1}, |T_3| = {t3}; T_max = {tmax}, n_max = {nmax}; {zone}.",
    "fig.caption.zone": "continuous-duty zone from the catalogue",
    "fig.caption.approx": "continuous duty approximately up to {what} = {value}",
    "fig.caption.nodata": "continuous-duty zone: no data",

    "unit.rpm": "rpm",
    "noscript": "This page needs JavaScript.",
  },
};

/** The text for ``key`` in ``lang`` with ``{name}`` placeholders filled (pure). */
export function translate(lang, key, params = {}) {
  const table = TEXTS[lang] ?? TEXTS.en;
  const text = table[key] ?? TEXTS.en[key] ?? key;
  return text.replace(/\{(\w+)\}/g, (whole, name) =>
    Object.hasOwn(params, name) ? String(params[name]) : whole,
  );
}

/** The chapter's reference ("Table 515.1") in ``lang`` ("Tabelle 515.1"). */
export function translateReference(lang, reference) {
  if (typeof reference !== "string") return "";
  return reference.replace(/^(Table|Eq\.|Fig\.)/, (word) => translate(lang, `ref.${word}`));
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
  if (unit === "rpm") return translate(lang, "unit.rpm");
  return unit ?? "";
}
