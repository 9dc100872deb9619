// The result as DOM: summary of the load case, the permalink, the ranked
// candidates and the chosen candidate's checks, controllers and chart frames.
// API text is only ever set as text (never parsed as HTML).
//
// The ranking renders from the selection's lean answer (checks as numbers, units and
// references once in ``check_rules``). The chosen candidate's panel renders from it
// too until the candidate's detail arrives (the server's messages, every controller
// with its criteria); then from the detail. A detail "view" is
// ``{status: "loading" | "ready" | "failed", detail, error}``.

import {
  checkFinding,
  checkLabel,
  checkRule,
  marginPercent,
  openChecks,
  shortCheckLabel,
  statusText,
} from "../../lib/checks.js";
import { answerLanguage } from "../../lib/api.js";
import { h, notice, sym } from "../../lib/dom.js";
import { dateTime, num, plainSymbols, qty } from "../../lib/format.js";
import { translate, translateReference, unitText } from "../../lib/i18n.js";
import { appendSymbols } from "../../lib/symbols.js";

export const VERDICTS = ["suitable", "unconfirmed", "unsuitable"];
const STATUS_MARK = { pass: "✓", fail: "✗", warn: "!", no_data: "?", not_applicable: "–" };

export function statusBadge(status, lang) {
  return h(
    "span",
    { class: `badge status-${status}` },
    h("span", { "aria-hidden": "true" }, STATUS_MARK[status] ?? "·"),
    " ",
    statusText(status, lang),
  );
}

export function verdictBadge(verdict, lang) {
  return h("span", { class: `badge verdict-${verdict}` }, translate(lang, `verdict.${verdict}`));
}

function approxBadge(lang) {
  return h(
    "span",
    { class: "badge approx", title: translate(lang, "detail.approximate.long") },
    h("span", { "aria-hidden": "true" }, "≈ "),
    translate(lang, "detail.approximate"),
  );
}

/** A value with its unit; the number keeps the API's full value in data-value. */
export function valueCell(value, unit, lang, props = {}) {
  return h(
    "span",
    { class: "value", "data-value": typeof value === "number" ? String(value) : null, ...props },
    qty(value, unit, lang),
  );
}

function definition(term, value, props = {}) {
  return h("div", { class: "kv", ...props }, h("dt", {}, term), h("dd", {}, value));
}

/**
 * The load case as the API resolved it, and the cycle figures of Eq. 514.3/514.4.
 * @param {import("../../lib/api.js").SelectionOut} sel
 * @param {string} lang
 */
export function renderSummary(sel, lang) {
  const t = (k) => translate(lang, k);
  const termWithSym = (key, symbol) => [t(key), " ", sym(symbol, { class: "sym" })];
  const mech = sel.mechanism && typeof sel.mechanism === "object" ? sel.mechanism.type : null;
  return h(
    "section",
    { class: "card summary", "aria-labelledby": "summary-heading" },
    h("h3", { id: "summary-heading" }, t("summary.heading")),
    h(
      "dl",
      { class: "kv-grid" },
      definition(termWithSym("summary.speed", "n_2"), valueCell(sel.load.speed_rpm, "rpm", lang), {
        id: "sum-speed",
      }),
      definition(termWithSym("summary.torque", "T_L"), valueCell(sel.load.torque_nm, "Nm", lang), {
        id: "sum-torque",
      }),
      definition(
        termWithSym("summary.inertia", "J_L"),
        valueCell(sel.load.inertia_kgm2, "kgm²", lang),
        { id: "sum-inertia" },
      ),
      definition(
        termWithSym("summary.gravity", "T_G"),
        valueCell(sel.load.gravity_torque_nm, "Nm", lang),
        { id: "sum-gravity" },
      ),
      definition(termWithSym("summary.efficiency", "η"), valueCell(sel.load.efficiency, null, lang), {
        id: "sum-efficiency",
      }),
      definition(
        termWithSym("summary.cycle_time", "t_0"),
        valueCell(sel.cycle_time_s, "s", lang),
        { id: "sum-cycle-time" },
      ),
      definition(
        termWithSym("summary.mean_speed", "n_av"),
        valueCell(sel.mean_speed_rpm, "rpm", lang),
        { id: "sum-mean-speed" },
      ),
      definition(termWithSym("summary.duty", "ED"), valueCell(sel.duty_cycle_percent, "%", lang), {
        id: "sum-duty",
      }),
      definition(t("summary.high_dynamics"), t(sel.high_dynamics ? "summary.yes" : "summary.no"), {
        id: "sum-high-dynamics",
      }),
      definition(t("summary.drive"), t(sel.drive ? "summary.yes" : "summary.no"), { id: "sum-drive" }),
      sel.output_load && typeof sel.output_load === "object"
        ? definition(t("summary.output_bearing"), t(outputBearingKey(sel)), { id: "sum-output-bearing" })
        : null,
      mech
        ? definition(t("summary.mechanism"), t(`load.${mech}`), { id: "sum-mechanism" })
        : null,
      typeof sel.catalogue_version === "number"
        ? definition(t("summary.catalogue"), String(sel.catalogue_version), {
            id: "sum-catalogue",
            class: "kv meta",
          })
        : null,
      dateTime(sel.created_at, lang)
        ? definition(t("summary.created"), dateTime(sel.created_at, lang), {
            id: "sum-created",
            class: "kv meta",
          })
        : null,
    ),
    typeof sel.ranking === "string"
      ? h(
          "details",
          { class: "ranking-rule" },
          h("summary", {}, t("summary.ranking")),
          // the page's own words for the rule the answer states (in English) in `ranking`
          sym(t("summary.ranking_rule")),
        )
      : null,
  );
}

/** The link that reopens this selection, with a copy button. */
export function renderPermalink(url, lang, onCopy) {
  const t = (k) => translate(lang, k);
  return h(
    "div",
    { class: "permalink" },
    h("label", { for: "permalink" }, t("permalink.label")),
    h(
      "div",
      { class: "permalink-row" },
      h("input", { id: "permalink", type: "text", readonly: true, value: url, spellcheck: "false" }),
      h("button", { type: "button", class: "secondary", id: "copy-link", onclick: onCopy }, t("permalink.copy")),
    ),
    h("p", { id: "copy-status", class: "hint", role: "status", "aria-live": "polite" }),
  );
}

/**
 * The whole ranking's candidates by verdict: the answer's ``verdict_counts`` (it lists only
 * the ranking's first candidates), else counted from the candidates listed.
 * @param {import("../../lib/api.js").SelectionOut} sel
 */
function countVerdicts(sel) {
  if (sel.verdict_counts) return { ...sel.verdict_counts };
  const counts = { suitable: 0, unconfirmed: 0, unsuitable: 0 };
  for (const c of sel.candidates) if (Object.hasOwn(counts, c.verdict)) counts[c.verdict] += 1;
  return counts;
}

/** How many candidates the whole ranking holds (the answer lists its first ones). */
const totalCandidates = (sel) => sel.total_candidates ?? sel.candidates.length;

/** One check that did not pass: status, label, approximation mark, then what was found. */
function reasonItem(check, lang, label, separator, finding) {
  return h(
    "li",
    { "data-check": check.name },
    statusBadge(check.status, lang),
    " ",
    sym(label, { class: "reason-check" }),
    check.approximate ? [" ", approxBadge(lang)] : null,
    separator,
    finding,
  );
}

/** The checks that did not pass, from the lean answer: label, then value against limit or what is missing. */
function reasonList(sel, candidate, lang, { short = false } = {}) {
  const open = openChecks(candidate);
  if (open.length === 0) {
    return h("span", { class: "muted" }, translate(lang, "table.reason.none"));
  }
  return h(
    "ul",
    { class: "reasons" },
    open.map((c) =>
      reasonItem(
        c,
        lang,
        short ? shortCheckLabel(c.name, lang) : checkLabel(c.name, lang),
        short ? " – " : h("br"),
        checkFinding(c, checkRule(sel, c.name)?.unit, lang),
      ),
    ),
  );
}

/** The checks that did not pass in the server's words (the detail's), and any further reason it gives. */
function detailReasonList(detail, lang) {
  const said = answerLanguage(detail);
  const open = openChecks(detail);
  const messages = new Set(open.map((c) => c.message));
  const further = (Array.isArray(detail.reasons) ? detail.reasons : []).filter(
    (r) => typeof r === "string" && !messages.has(r),
  );
  return h(
    "ul",
    { class: "reasons" },
    open.map((c) =>
      reasonItem(c, lang, checkLabel(c.name, lang), h("br"), sym(c.message, { class: "api-message", lang: said })),
    ),
    further.map((r) => h("li", {}, sym(r, { class: "api-message", lang: said }))),
  );
}

/**
 * A row's checks as marks (✓ ✗ ?), each with its finding as a tooltip. One image to a
 * screen reader, named by every check's finding: a row is one element per mark, the
 * fewest a table of 64 candidates can lay out (a list with hidden text per mark cost
 * three, and a third of the results' first layout).
 */
function checkMarks(sel, candidate, lang) {
  const checks = Array.isArray(candidate.checks) ? candidate.checks : [];
  const texts = checks.map((c) => {
    const unit = checkRule(sel, c.name)?.unit;
    const against =
      typeof c.value === "number" && typeof c.limit === "number"
        ? ` (${qty(c.value, unit, lang)} / ${c.approximate ? "≈ " : ""}${qty(c.limit, unit, lang)})`
        : "";
    return `${plainSymbols(shortCheckLabel(c.name, lang))}: ${statusText(c.status, lang)}${against}`;
  });
  return h(
    "span",
    { class: "marks", role: "img", "aria-label": texts.join("; ") },
    checks.map((c, i) =>
      h("span", { class: `mark status-${c.status}`, title: texts[i] }, STATUS_MARK[c.status] ?? "·"),
    ),
  );
}

/** Rows a ranking is drawn with at once: its box shows about six, the rest can follow. */
export const FIRST_ROWS = 12;

/** One candidate's row of the ranking, as chosen, filtered and marked now. */
function rankingRow(sel, c, i, chosenModel, filter, lang, { onChoose, compareCell }) {
  const t = (k, p) => translate(lang, k, p);
  const chosen = c.model === chosenModel;
  return h(
    "tr",
    {
      role: "row",
      class: `verdict-row verdict-${c.verdict}${chosen ? " chosen" : ""}`,
      "data-model": c.model,
      "data-verdict": c.verdict,
      "aria-current": chosen ? "true" : null,
      hidden: !shownBy(filter, c),
    },
    h("td", { role: "cell", class: "num rank", "data-label": t("table.rank") }, String(i + 1)),
    compareCell
      ? h("td", { role: "cell", class: "compare-cell", "data-label": t("compare.column") }, compareCell(c.model))
      : null,
    h(
      "th",
      { role: "rowheader", scope: "row", class: "model", "data-label": t("table.model") },
      h(
        "button",
        {
          type: "button",
          class: "model-button",
          "aria-pressed": String(chosen),
          "aria-label": t("table.select", { model: c.model }),
          onclick: () => onChoose(c.model),
        },
        c.model,
      ),
    ),
    h(
      "td",
      { role: "cell", class: "verdict", "data-label": t("table.verdict") },
      verdictBadge(c.verdict, lang),
      checkMarks(sel, c, lang),
    ),
    h(
      "td",
      { role: "cell", class: "num", "data-label": plainSymbols("T_1 [Nm]"), "data-field": "accel" },
      valueCell(c.accel_torque_nm, null, lang),
    ),
    h(
      "td",
      { role: "cell", class: "num", "data-label": plainSymbols("T_3 [Nm]"), "data-field": "decel" },
      valueCell(c.decel_torque_nm, null, lang),
    ),
    h(
      "td",
      { role: "cell", class: "num", "data-label": plainSymbols("T_rms [Nm]"), "data-field": "rms" },
      valueCell(c.rms_torque_nm, null, lang),
    ),
    h("td", { role: "cell", class: "reason", "data-label": t("table.reason") }, reasonList(sel, c, lang, { short: true })),
  );
}

const shownBy = (filter, candidate) => filter === "all" || filter === candidate.verdict;

/** How many of the first candidates to draw so that ``FIRST_ROWS`` of them show under ``filter``. */
function firstRows(candidates, filter) {
  let shown = 0;
  for (const [i, c] of candidates.entries()) {
    if (shownBy(filter, c)) shown += 1;
    if (shown === FIRST_ROWS) return i + 1;
  }
  return candidates.length;
}

/**
 * The ranked candidates with a verdict filter; ``onChoose(model)`` when a row is picked.
 * ``compareCell(model)`` gives a row's mark for the comparison, ``compareStatus`` the
 * line that says how many are marked (or why a mark was refused).
 *
 * With ``{rows: "first"}`` only the first rows are drawn (``FIRST_ROWS`` shown under the
 * filter), the table says ``data-rows="partial"`` and ``drawRemainingRows`` adds the rest:
 * the whole catalogue's 64 rows were half the results' first layout, and all but a few
 * are below the fold of their scroll box.
 * @param {import("../../lib/api.js").SelectionOut} sel
 */
export function renderRanking(sel, chosenModel, filter, lang, options, { rows = "all" } = {}) {
  const { onFilter, compareCell, compareStatus } = options;
  const t = (k, p) => translate(lang, k, p);
  const counts = countVerdicts(sel);
  const filters = h(
    "div",
    { class: "filter", role: "group", "aria-label": t("filter.label") },
    h("span", { class: "filter-label", "aria-hidden": "true" }, `${t("filter.label")}:`),
    ["all", ...VERDICTS].map((v) =>
      h(
        "button",
        {
          type: "button",
          class: `filter-button${v === "all" ? "" : ` verdict-${v}`}`,
          "aria-pressed": String(filter === v),
          "data-filter": v,
          onclick: () => onFilter(v),
        },
        v === "all" ? t("filter.all") : t(`verdict.${v}`),
        " ",
        h("span", { class: "count" }, `(${v === "all" ? totalCandidates(sel) : counts[v]})`),
      ),
    ),
  );

  const header = (key, symbol, unit) =>
    h(
      "th",
      { scope: "col", role: "columnheader", class: unit ? "num" : null },
      key ? t(key) : null,
      symbol ? sym(symbol, { class: "sym" }) : null,
      unit ? h("span", { class: "unit" }, ` [${unitText(lang, unit)}]`) : null,
    );

  const drawn = rows === "first" ? firstRows(sel.candidates, filter) : sel.candidates.length;
  const table = h(
    "table",
    {
      class: "ranking",
      id: "ranking-table",
      role: "table",
      "data-selection": sel.id,
      "data-rows": drawn < sel.candidates.length ? "partial" : "complete",
    },
    h("caption", {}, t("table.caption")),
    h(
      "thead",
      { role: "rowgroup" },
      h(
        "tr",
        { role: "row" },
        header("table.rank"),
        compareCell ? header("compare.column") : null,
        header("table.model"),
        h("th", { scope: "col", role: "columnheader" }, `${t("table.verdict")} · ${t("table.checks")}`),
        header(null, "T_1", "Nm"),
        header(null, "T_3", "Nm"),
        header(null, "T_rms", "Nm"),
        header("table.reason"),
      ),
    ),
    h(
      "tbody",
      {
        role: "rowgroup",
        // a click anywhere on a row chooses it; the model button serves the keyboard
        onclick: (event) => {
          if (event.target.closest("button, a, summary, input, label")) return;
          const row = event.target.closest("tr[data-model]");
          if (row) options.onChoose(row.dataset.model);
        },
      },
      sel.candidates.slice(0, drawn).map((c, i) => rankingRow(sel, c, i, chosenModel, filter, lang, options)),
    ),
  );
  return h(
    "section",
    { class: "card ranking-card", "aria-labelledby": "ranking-heading" },
    h("h3", { id: "ranking-heading", class: "visually-hidden" }, t("table.caption")),
    filters,
    compareCell
      ? h("p", { id: "compare-status", class: "compare-status hint", role: "status", "aria-live": "polite" }, compareStatus ?? "")
      : null,
    h(
      "div",
      { class: "table-scroll", tabindex: "0", role: "region", "aria-label": t("table.caption") },
      table,
    ),
    moreRow(sel, lang, options.onMore),
  );
}

/**
 * Below the ranking while the answer has not listed it whole: how many rows of the whole
 * ranking are listed, and a button that reads the next page (``onMore``, by the answer's
 * ``next_cursor``). Redrawn by ``updateMoreRow`` when a page has come.
 * @param {import("../../lib/api.js").SelectionOut} sel
 */
function moreRow(sel, lang, onMore) {
  const t = (k, p) => translate(lang, k, p);
  const total = totalCandidates(sel);
  const shown = sel.candidates.length;
  if (!sel.next_cursor || !onMore) return h("p", { id: "ranking-more", class: "hint", hidden: true });
  return h(
    "p",
    { id: "ranking-more", class: "ranking-more hint", "data-shown": String(shown), "data-total": String(total) },
    h("span", { role: "status", "aria-live": "polite" }, t("ranking.shown", { shown, total }), " "),
    h(
      "button",
      { type: "button", class: "secondary", id: "ranking-more-button", onclick: onMore },
      t("ranking.more", { count: Math.min(MORE_ROWS, total - shown) }),
    ),
  );
}

/** Candidates read per "show more" (GET …/candidates?limit=). */
export const MORE_ROWS = 25;

/** The "show more" row of the ranking as ``sel`` stands now (after a page came). */
export function updateMoreRow(sel, lang, onMore) {
  document.querySelector("#ranking-more")?.replaceWith(moreRow(sel, lang, onMore));
}

/**
 * When nothing fits: what binds across the catalogue and what would change it, in words,
 * from the answer's ``binding`` (counted and solved by the server; null when something
 * fits, absent from answers stored before it existed). Null when there is nothing to say.
 * @param {import("../../lib/api.js").SelectionOut} sel
 * @param {string} lang
 */
export function renderBinding(sel, lang) {
  const binding = sel.binding;
  if (!binding || typeof binding !== "object" || !Array.isArray(binding.checks)) return null;
  const t = (k, p) => translate(lang, k, p);
  const units = Object.fromEntries((sel.check_rules ?? []).map((r) => [r.name, r.unit]));
  const said = (text) => appendSymbols(h("li"), text);
  const checks = binding.checks.map((k) => {
    const unit = units[k.name] ?? "";
    const params = {
      check: checkLabel(k.name, lang),
      failing: k.failing,
      candidates: binding.candidates,
      value: qty(k.value, unit, lang),
      limit: qty(k.limit, unit, lang),
      model: k.model,
    };
    const every = k.failing === binding.candidates;
    if (typeof k.value !== "number" || typeof k.limit !== "number") return said(t("binding.no_value", params));
    if (every && k.name === "max_speed") return said(t("binding.speed_every", params));
    return said(t(every ? "binding.every" : "binding.some", params));
  });
  const changes = (Array.isArray(binding.changes) ? binding.changes : []).map((c) => {
    if (typeof c.value === "number") {
      return said(t(`binding.change.${c.quantity}`, { value: qty(c.value, c.unit, lang), model: c.model }));
    }
    if (c.reason_code === "limit.accel_no_ramp") return said(t("binding.nochange.accel_no_ramp"));
    const names = (c.limiting_checks ?? []).map((name) => checkLabel(name, lang)).join("; ");
    return said(t(`binding.nochange.${c.quantity}`, { checks: names }));
  });
  // The ratio study's leads or diameters that make an actuator fit (binding.transmissions).
  const found = Array.isArray(binding.transmissions) ? binding.transmissions : [];
  const transmissions = found.length
    ? found.map((g) =>
        said(
          t("binding.transmission", {
            variable: t(`binding.variable.${g.variable}`),
            low: qty(g.low, g.unit, lang),
            high: qty(g.high, g.unit, lang),
            best: qty(g.best, g.unit, lang),
            model: g.model,
          }),
        ),
      )
    : [said(t("binding.ratio"))];
  const model = binding.changes?.[0]?.model ?? sel.candidates?.[0]?.model ?? "–";
  return h(
    "section",
    { class: "card binding", id: "binding", "aria-labelledby": "binding-heading" },
    h("h3", { id: "binding-heading" }, t("binding.heading")),
    h("p", {}, t("binding.intro", { candidates: binding.candidates })),
    h("ul", { class: "binding-checks" }, ...checks),
    h("p", {}, t("binding.changes", { model })),
    h("ul", { class: "binding-changes" }, ...changes, ...transmissions),
  );
}

/**
 * The rest of ``sel``'s listed candidates drawn after the table's rows, as chosen, filtered
 * and marked now: the rows a table drawn with its first rows lacks, or (``more``) the
 * candidates a page of the ranking has added.
 */
export function drawRemainingRows(table, sel, chosenModel, filter, lang, options, { more = false } = {}) {
  if ((table.dataset.rows !== "partial" && !more) || table.dataset.selection !== String(sel.id)) return;
  const body = table.tBodies[0];
  const start = body.rows.length;
  body.append(
    ...sel.candidates.slice(start).map((c, i) => rankingRow(sel, c, start + i, chosenModel, filter, lang, options)),
  );
  table.dataset.rows = "complete";
}

const LEVEL_MARK = { tested: "●", possible: "○", unconfirmed: "?", excluded: "✗", no_data: "?" };
const CRITERIA = ["family", "bus_class", "temperature_sensor", "feedback_system"];

function levelBadge(level, lang) {
  const known = Object.hasOwn(LEVEL_MARK, level);
  return h(
    "span",
    { class: `badge level-${known ? level : "unknown"}` },
    h("span", { "aria-hidden": "true" }, `${LEVEL_MARK[level] ?? "·"} `),
    known ? translate(lang, `controller.${level}`) : String(level ?? ""),
  );
}

function criteriaMarks(criteria, lang) {
  if (!criteria.length) return null;
  const order = (c) => {
    const i = CRITERIA.indexOf(c.criterion);
    return i < 0 ? CRITERIA.length : i;
  };
  return h(
    "ul",
    { class: "criteria" },
    [...criteria]
      .sort((a, b) => order(a) - order(b))
      .map((c) => {
        const key = `criterion.${c.criterion}`;
        const label = translate(lang, key) === key ? String(c.criterion) : translate(lang, key);
        const status = Object.hasOwn(LEVEL_MARK, c.status) ? c.status : "no_data";
        return h(
          "li",
          { class: `criterion criterion-${status}`, title: c.message ?? null },
          h("span", { class: "criterion-mark", "aria-hidden": "true" }, LEVEL_MARK[status]),
          " ",
          label,
          h("span", { class: "visually-hidden" }, `: ${translate(lang, `controller.${status}`)}`),
        );
      }),
  );
}

/** Criteria of Table 521.1: all of them from the detail, else those the actuator lacks data for. */
function criteriaCell(controller, lang) {
  if (Array.isArray(controller.criteria)) {
    return criteriaMarks(controller.criteria.filter((c) => c && typeof c === "object"), lang);
  }
  const missing = Array.isArray(controller.missing) ? controller.missing : [];
  return criteriaMarks(
    missing.map((criterion) => ({ criterion, status: "no_data" })),
    lang,
  );
}

/**
 * What the answer's ``output_bearing`` says, in the page's words: by its code
 * (``output_bearing_code``; an answer stored before it had one: from the output load sent).
 */
function outputBearingKey(sel) {
  const sent = typeof sel.output_load.required_life_h === "number" ? "checked" : "no_life";
  return `summary.${sel.output_bearing_code ?? `output_bearing.${sent}`}`;
}

/** A controller's name; the "row N" the catalogue gives a variant whose name the source lost, in ``lang``. */
function controllerName(c, lang) {
  const row = typeof c.variant === "string" ? /^row (\d+)$/.exec(c.variant) : null;
  const variant = row ? translate(lang, "controller.row", { n: row[1] }) : c.variant;
  return [c.manufacturer, c.type, variant].filter((x) => typeof x === "string" && x).join(" ");
}

function voltageCell(check, lang, said = "en") {
  if (!check || typeof check !== "object") return h("span", { class: "muted" }, "–");
  const unit = check.unit ?? "V";
  const against =
    typeof check.value === "number" && typeof check.limit === "number"
      ? [" ", valueCell(check.value, unit, lang), " / ", valueCell(check.limit, unit, lang)]
      : null;
  return [
    statusBadge(check.status, lang),
    against,
    check.status === "pass" || typeof check.message !== "string"
      ? null
      : sym(check.message, { class: "api-message block", lang: said }),
  ];
}

/**
 * The candidate's controllers of Table 521.1: from the detail (each with its criteria
 * and voltage check in words), else the lean answer's drive options, each group's
 * controllers looked up in the selection's ``controllers``. Null when neither lists any.
 */
function controllerEntries(sel, candidate, detail) {
  if (detail) {
    if (!Array.isArray(detail.controllers)) return null;
    return {
      controllers: detail.controllers.filter((c) => c && typeof c === "object"),
      excluded: detail.controllers_excluded,
      note: detail.controllers_note,
      said: answerLanguage(detail),
    };
  }
  if (!Array.isArray(candidate.drive_options)) return null;
  const refs = Array.isArray(sel.controllers) ? sel.controllers : [];
  const controllers = [];
  for (const group of candidate.drive_options) {
    if (!group || typeof group !== "object" || !Array.isArray(group.controllers)) continue;
    for (const index of group.controllers) {
      const ref = refs[index];
      if (!ref || typeof ref !== "object") continue;
      controllers.push({ ...ref, level: group.level, missing: group.missing, voltage: group.voltage });
    }
  }
  return { controllers, excluded: candidate.controllers_excluded, note: null, said: "en" };
}

/** Controllers of Table 521.1 for the candidate, when the API lists them (else nothing). */
function controllerList(sel, candidate, detail, lang) {
  const entries = controllerEntries(sel, candidate, detail);
  if (!entries) return null;
  const t = (k, p) => translate(lang, k, p);
  const { controllers } = entries;
  const excluded = Number.isInteger(entries.excluded) ? entries.excluded : null;
  const summary = t("detail.controllers.count", { n: controllers.length });
  const col = (key, extra) => h("th", { scope: "col", role: "columnheader" }, t(key), extra ?? null);
  return h(
    "section",
    { class: "controllers", "aria-labelledby": "controllers-heading" },
    h("h4", { id: "controllers-heading" }, t("detail.controllers")),
    h(
      "p",
      { class: "controllers-summary" },
      summary,
      excluded !== null ? `, ${t("detail.controllers.excluded", { n: excluded })}` : "",
      ". ",
      h("span", { class: "legend" }, `● ${t("controller.tested")} · ○ ${t("controller.possible")} · ? ${t("controller.no_data")}`),
    ),
    typeof entries.note === "string" ? sym(entries.note, { class: "api-message block", lang: entries.said }) : null,
    controllers.length
      ? h(
          "div",
          { class: "table-scroll", tabindex: "0", role: "region", "aria-label": t("detail.controllers") },
          h(
            "table",
            { class: "controller-table", id: "controllers-table", role: "table" },
            h(
              "thead",
              { role: "rowgroup" },
              h(
                "tr",
                { role: "row" },
                col("controller.name"),
                col("controller.level"),
                col("controller.criteria"),
                h("th", { scope: "col", role: "columnheader" }, sym(t("controller.voltage"))),
              ),
            ),
            h(
              "tbody",
              { role: "rowgroup" },
              controllers.map((c) =>
                h(
                  "tr",
                  { role: "row", class: "controller", "data-level": c.level ?? "" },
                  h(
                    "th",
                    { scope: "row", role: "rowheader", class: "controller-name", "data-label": t("controller.name") },
                    h("span", { translate: "no" }, controllerName(c, lang)),
                  ),
                  h("td", { role: "cell", "data-label": t("controller.level") }, levelBadge(c.level, lang)),
                  h("td", { role: "cell", "data-label": t("controller.criteria") }, criteriaCell(c, lang)),
                  h(
                    "td",
                    { role: "cell", class: "voltage", "data-label": plainSymbols(t("controller.voltage")) },
                    voltageCell(c.voltage, lang, entries.said),
                  ),
                ),
              ),
            ),
          ),
        )
      : h("p", { class: "muted" }, t("detail.controllers.none")),
  );
}

/** The checks as the table shows them: the detail's, else the lean ones with the rule's unit and reference. */
function checkRows(sel, candidate, detail) {
  if (detail && Array.isArray(detail.checks)) return detail.checks.filter((c) => c && typeof c === "object");
  return (Array.isArray(candidate.checks) ? candidate.checks : []).map((c) => {
    const rule = checkRule(sel, c.name);
    return { ...c, unit: rule?.unit ?? null, reference: rule?.reference ?? null, margin_percent: marginPercent(c) };
  });
}

function messageCell(check, view, lang) {
  if (typeof check.message === "string") return sym(check.message, { lang: answerLanguage(readyDetail(view)) });
  if (check.status === "no_data") return checkFinding(check, check.unit, lang);
  if (view?.status === "loading") {
    return h(
      "span",
      { class: "muted pending" },
      h("span", { "aria-hidden": "true" }, "…"),
      h("span", { class: "visually-hidden" }, translate(lang, "detail.pending")),
    );
  }
  return h("span", { class: "muted" }, "–");
}

function checksTable(sel, candidate, view, lang) {
  const t = (k) => translate(lang, k);
  const checks = checkRows(sel, candidate, readyDetail(view));
  const col = (key) => h("th", { scope: "col", role: "columnheader" }, t(key));
  return h(
    "div",
    { class: "table-scroll", tabindex: "0", role: "region", "aria-label": t("detail.checks") },
    h(
      "table",
      { class: "checks", id: "checks-table", role: "table" },
      h("caption", {}, t("detail.checks")),
      h(
        "thead",
        { role: "rowgroup" },
        h(
          "tr",
          { role: "row" },
          col("detail.check"),
          col("detail.value"),
          col("detail.limit"),
          col("detail.status"),
          col("detail.margin"),
          col("detail.message"),
        ),
      ),
      h(
        "tbody",
        { role: "rowgroup" },
        checks.map((c) =>
          h(
            "tr",
            { role: "row", "data-check": c.name, "data-status": c.status, class: `status-row-${c.status}` },
            h(
              "th",
              { scope: "row", role: "rowheader", "data-label": t("detail.check") },
              sym(checkLabel(c.name, lang)),
              h("span", { class: "ref" }, translateReference(lang, c.reference)),
            ),
            h("td", { role: "cell", class: "num", "data-label": t("detail.value") }, valueCell(c.value, c.unit, lang)),
            h(
              "td",
              { role: "cell", class: "num", "data-label": t("detail.limit") },
              c.approximate && typeof c.limit === "number" ? h("span", { "aria-hidden": "true" }, "≈ ") : null,
              valueCell(c.limit, c.unit, lang),
            ),
            h(
              "td",
              { role: "cell", class: "status-cell", "data-label": t("detail.status") },
              statusBadge(c.status, lang),
              c.approximate ? [" ", approxBadge(lang)] : null,
            ),
            h(
              "td",
              { role: "cell", class: "num", "data-label": t("detail.margin") },
              valueCell(c.margin_percent, "%", lang),
            ),
            h("td", { role: "cell", class: "message", "data-label": t("detail.message") }, messageCell(c, view, lang)),
          ),
        ),
      ),
    ),
  );
}

function readyDetail(view) {
  return view?.status === "ready" && view.detail && typeof view.detail === "object" ? view.detail : null;
}

/** Why the detail is missing, in a few words of ``lang``. */
function detailFailure(error, lang) {
  const t = (k) => translate(lang, k);
  if (error?.status === 409) return t("detail.failed.changed");
  if (error?.status === 404) return t("detail.failed.notfound");
  if (error?.kind === "network") return t("detail.failed.network");
  if (error?.kind === "bad_response" || !error?.status) return t("detail.failed.bad");
  return `HTTP ${error.status}`;
}

function detailStatus(view, lang) {
  if (view?.status === "loading") {
    return notice("info", h("p", { class: "loading" }, translate(lang, "detail.loading")));
  }
  if (view?.status === "failed") {
    const said = view.error?.kind === "http" && typeof view.error.detail === "string" ? view.error.detail : null;
    return notice(
      "warn",
      h(
        "p",
        {},
        translate(lang, "detail.failed", { why: detailFailure(view.error, lang) }),
        said ? sym(said, { class: "api-message block", lang: "en" }) : null,
      ),
    );
  }
  return null;
}

/**
 * Fill the parts of the chosen candidate's panel that the detail adds to: the
 * status line, the checks, the reasons and the controllers. The charts are left alone;
 * so are the parts below them while the panel waits for its charts (``renderDetail``'s
 * ``belowCharts: false``: ``fillBelowCharts`` fills them once the charts are drawn).
 */
export function fillDetail(panel, sel, candidate, view, lang) {
  const slot = (name) => panel.querySelector(`[data-slot="${name}"]`);
  const detail = readyDetail(view);
  panel.dataset.detail = view?.status ?? "none";
  slot("status").replaceChildren(...[detailStatus(view, lang)].filter(Boolean));
  slot("checks").replaceChildren(checksTable(sel, candidate, view, lang));
  const reasons = detail ? detailReasonList(detail, lang) : reasonList(sel, candidate, lang);
  const anyReason = openChecks(candidate).length > 0 || (detail !== null && reasons.childElementCount > 0);
  slot("reasons").replaceChildren(
    ...(anyReason
      ? [
          h(
            "section",
            { class: "detail-reasons", "aria-labelledby": "detail-reasons-heading" },
            h("h4", { id: "detail-reasons-heading" }, translate(lang, "detail.reasons")),
            reasons,
          ),
        ]
      : []),
  );
  if (panel.dataset.below !== "later") fillBelowCharts(panel, sel, candidate, view, lang);
}

/**
 * The panel's parts below its charts (the segments' table and the controllers): on a new
 * answer a third of the results' elements, built and laid out after the charts, as the
 * ranking's other rows are; below the charts, they move nothing drawn before them.
 */
export function fillBelowCharts(panel, sel, candidate, view, lang) {
  const slot = (name) => panel.querySelector(`[data-slot="${name}"]`);
  const detail = readyDetail(view);
  delete panel.dataset.below;
  slot("controllers").replaceChildren(...[controllerList(sel, candidate, detail, lang)].filter(Boolean));
  slot("segments").replaceChildren(...[segmentTable(sel, detail, view, lang)].filter(Boolean));
}

/** The torque at a segment's ends and its largest magnitude, from the detail's points. */
function segmentTorqueEnds(detail, index) {
  const parts = Array.isArray(detail?.segment_torques) ? detail.segment_torques : [];
  const part = parts.find((p) => p && p.segment === index);
  const torques = Array.isArray(part?.torques_nm) ? part.torques_nm.filter((x) => typeof x === "number") : [];
  if (!torques.length) return null;
  const peak = torques.reduce((a, b) => (Math.abs(b) > Math.abs(a) ? b : a));
  return { start: torques[0], end: torques[torques.length - 1], peak };
}

/**
 * The cycle segment by segment at the actuator output (the answer's ``segments``), with
 * the torque at each segment's ends from the candidate's detail (``segment_torques``).
 */
function segmentTable(sel, detail, view, lang) {
  const segments = Array.isArray(sel.segments) ? sel.segments.filter((s) => s && typeof s === "object") : [];
  if (!segments.length) return null;
  const t = (k) => translate(lang, k);
  const col = (key, symbol, unit) =>
    h(
      "th",
      { scope: "col", role: "columnheader", class: "num" },
      key ? t(key) : null,
      symbol ? [" ", sym(symbol, { class: "sym" })] : null,
      unit ? h("span", { class: "unit" }, ` [${unitText(lang, unit)}]`) : null,
    );
  const pending = view?.status === "loading";
  const torqueCell = (value, label) =>
    h(
      "td",
      { role: "cell", class: "num", "data-label": label },
      typeof value === "number"
        ? valueCell(value, null, lang)
        : h("span", { class: "muted" }, pending ? "…" : "–"),
    );
  const trapezoid = typeof sel.cycle?.accel_s === "number" && segments.length === 4;
  const names = ["t_1", "t_2", "t_3", "t_p"];
  return h(
    "section",
    { class: "segments-result", "aria-labelledby": "segments-heading" },
    h("h4", { id: "segments-heading" }, t("segtable.heading")),
    h(
      "div",
      { class: "table-scroll", tabindex: "0", role: "region", "aria-label": t("segtable.heading") },
      h(
        "table",
        { class: "segment-table", id: "segment-table", role: "table" },
        h(
          "thead",
          { role: "rowgroup" },
          h(
            "tr",
            { role: "row" },
            h("th", { scope: "col", role: "columnheader" }, t("segtable.segment")),
            col("segtable.start", null, "s"),
            col("segtable.duration", null, "s"),
            col(null, t("sym.n_start"), "rpm"),
            col(null, t("sym.n_end"), "rpm"),
            col("segtable.jerk", null, null),
            col(null, t("sym.T_process"), "Nm"),
            col(null, t("sym.T_start"), "Nm"),
            col(null, t("sym.T_end"), "Nm"),
            col("segtable.peak", null, "Nm"),
          ),
        ),
        h(
          "tbody",
          { role: "rowgroup" },
          segments.map((seg, k) => {
            const ends = segmentTorqueEnds(detail, k);
            return h(
              "tr",
              { role: "row", "data-segment": String(k) },
              h("th", { scope: "row", role: "rowheader", "data-label": t("segtable.segment") }, trapezoid ? sym(names[k]) : String(k + 1)),
              h("td", { role: "cell", class: "num", "data-label": t("segtable.start") }, valueCell(seg.start_s, "s", lang)),
              h("td", { role: "cell", class: "num", "data-label": t("segtable.duration") }, valueCell(seg.duration_s, "s", lang)),
              h("td", { role: "cell", class: "num", "data-label": "n start", "data-field": "start_rpm" }, valueCell(seg.start_rpm, null, lang)),
              h("td", { role: "cell", class: "num", "data-label": "n end", "data-field": "end_rpm" }, valueCell(seg.end_rpm, null, lang)),
              h("td", { role: "cell", class: "num", "data-label": t("segtable.jerk") }, valueCell(seg.jerk_share, null, lang)),
              h("td", { role: "cell", class: "num", "data-label": "T process" }, valueCell(seg.process_torque_nm, null, lang)),
              torqueCell(ends?.start, "T start"),
              torqueCell(ends?.end, "T end"),
              torqueCell(ends?.peak, t("segtable.peak")),
            );
          }),
        ),
      ),
    ),
  );
}

/** Links to the selection's engineering report (PDF) and its candidates (CSV). */
export function renderReports(sel, lang) {
  const t = (k) => translate(lang, k);
  const base = `/api/v1/selections/${encodeURIComponent(sel.id)}`;
  return h(
    "p",
    { class: "reports" },
    h("span", { class: "reports-label" }, `${t("reports.label")}: `),
    h("a", { id: "report-pdf", href: `${base}/report.pdf`, download: "" }, t("reports.pdf")),
    " · ",
    h("a", { id: "report-csv", href: `${base}/report.csv`, download: "" }, t("reports.csv")),
    " · ",
    h("a", { id: "report-aas", href: `${base}/aas.aasx`, download: "" }, t("reports.aas")),
  );
}

/**
 * The limits of the load case for the chosen actuator (GET …/candidates/{model}/limits):
 * a button until asked, then each quantity's limit and the check that sets it.
 * ``view`` is ``null`` | ``{status: "loading" | "ready" | "failed", limits, error}``.
 */
export function renderLimits(view, lang) {
  const t = (k, p) => translate(lang, k, p);
  const heading = h("h4", { id: "limits-heading" }, t("limits.heading"));
  if (!view) {
    return h(
      "section",
      { class: "limits", "aria-labelledby": "limits-heading" },
      heading,
      h("button", { type: "button", id: "limits-button", class: "secondary" }, t("limits.button")),
    );
  }
  if (view.status === "loading") {
    return h("section", { class: "limits", "aria-labelledby": "limits-heading", "aria-busy": "true" }, heading, h("p", { class: "muted" }, t("limits.loading")));
  }
  if (view.status === "failed") {
    return h("section", { class: "limits", "aria-labelledby": "limits-heading" }, heading, notice("warn", h("p", {}, t("limits.failed", { why: view.error?.message ?? "" }))));
  }
  const rows = (Array.isArray(view.limits?.limits) ? view.limits.limits : []).map((limit) => {
    const by = Array.isArray(limit.limiting_checks) ? limit.limiting_checks : [];
    const value =
      typeof limit.value === "number"
        ? valueCell(limit.value, limit.unit === "kgm²" ? "kgm²" : limit.unit, lang)
        : limit.reason_code === "limit.accel_no_ramp"
          ? "–"
          : t("limits.none");
    const checks = by.length
      ? by.map((c) => `${checkLabel(c.name, lang)} (${translateReference(lang, c.reference)})`).join("; ")
      : t("limits.free");
    // why there is no value, in the server's words (in the page's language)
    const reason =
      typeof limit.value !== "number" && typeof limit.reason === "string" && limit.reason
        ? [by.length ? [checks, h("br")] : null, h("span", { class: "limit-reason" }, t("limits.reason", { reason: limit.reason }))]
        : checks;
    return h(
      "tr",
      { "data-quantity": limit.quantity },
      h("th", { scope: "row" }, plainSymbols(t(`limits.quantity.${limit.quantity}`))),
      h("td", { class: "num" }, value),
      h("td", {}, reason),
    );
  });
  return h(
    "section",
    { class: "limits", "aria-labelledby": "limits-heading" },
    heading,
    h(
      "div",
      { class: "table-scroll", tabindex: "0", role: "region", "aria-label": t("limits.heading") },
      h(
        "table",
        { id: "limits-table" },
        h("thead", {}, h("tr", {}, h("th", { scope: "col" }, ""), h("th", { scope: "col" }, t("limits.value")), h("th", { scope: "col" }, t("limits.by")))),
        h("tbody", {}, ...rows),
      ),
    ),
  );
}

/**
 * The chosen candidate: key figures, every check, reasons, controllers, chart frames. With
 * ``belowCharts: false`` the parts below the charts are left for ``fillBelowCharts``.
 */
export function renderDetail(sel, candidate, view, lang, { belowCharts = true } = {}) {
  const t = (k) => translate(lang, k);
  const termWithSym = (symbol, extra) => [sym(symbol, { class: "sym" }), extra ? ` ${extra}` : ""];
  const panel = h(
    "section",
    { class: "card detail", id: "detail", "aria-labelledby": "detail-heading", "data-model": candidate.model },
    h(
      "h3",
      { id: "detail-heading" },
      h("span", { class: "detail-kicker" }, `${t("detail.heading")}: `),
      h("span", { class: "detail-model" }, candidate.model),
      " ",
      verdictBadge(candidate.verdict, lang),
    ),
    h(
      "dl",
      { class: "kv-grid key-figures" },
      definition(t("detail.family"), candidate.family),
      definition([t("detail.ratio"), " ", h("span", { class: "sym" }, h("var", {}, "i"))], num(candidate.gear_ratio, lang)),
      definition(termWithSym("T_1", `(${translateReference(lang, "Eq. 514.1")})`), valueCell(candidate.accel_torque_nm, "Nm", lang), { id: "fig-t1" }),
      definition(termWithSym("T_2"), valueCell(candidate.constant_torque_nm, "Nm", lang), { id: "fig-t2" }),
      definition(termWithSym("T_3"), valueCell(candidate.decel_torque_nm, "Nm", lang), { id: "fig-t3" }),
      definition(termWithSym("T_rms", `(${translateReference(lang, "Eq. 514.2")})`), valueCell(candidate.rms_torque_nm, "Nm", lang), { id: "fig-trms" }),
      definition(termWithSym("n_av", `(${translateReference(lang, "Eq. 514.3")})`), valueCell(sel.mean_speed_rpm, "rpm", lang), { id: "fig-nav" }),
      definition(termWithSym("ED", `(${translateReference(lang, "Eq. 514.4")})`), valueCell(sel.duty_cycle_percent, "%", lang), { id: "fig-ed" }),
    ),
    h("div", { class: "detail-status", id: "detail-status", role: "status", "data-slot": "status" }),
    h("div", { "data-slot": "checks" }),
    h("div", { "data-slot": "reasons" }),
    h(
      "div",
      { class: "charts" },
      h(
        "figure",
        { class: "chart-figure" },
        h("figcaption", {}, h("strong", {}, t("charts.cycle")), h("span", { class: "chart-text", id: "cycle-caption" })),
        h("div", { class: "chart", id: "chart-cycle", "data-state": "loading" }, h("p", { class: "chart-placeholder" }, t("charts.loading"))),
      ),
      h(
        "figure",
        { class: "chart-figure" },
        h("figcaption", {}, h("strong", {}, t("charts.diagram")), h("span", { class: "chart-text", id: "diagram-caption" })),
        h("div", { class: "chart", id: "chart-diagram", "data-state": "loading" }, h("p", { class: "chart-placeholder" }, t("charts.loading"))),
      ),
    ),
    h("div", { "data-slot": "segments" }),
    h("div", { "data-slot": "limits" }, renderLimits(null, lang)),
    h("div", { "data-slot": "controllers" }),
  );
  if (!belowCharts) panel.dataset.below = "later";
  fillDetail(panel, sel, candidate, view, lang);
  return panel;
}

/** The summary sentence announced to screen readers after a result arrives. */
export function resultSentence(sel, chosenModel, lang) {
  const counts = countVerdicts(sel);
  return translate(lang, "results.done", { ...counts, model: chosenModel ?? "–" });
}
