// The cycle chart of a chosen candidate as a plotly {data, layout} object, and the
// speed/torque diagram as the API defines it (api/figures.py, the figure the quote and the
// report print), fitted to the chart's width. Pure functions: every number drawn comes
// from the API's answer (the selection, its candidate); nothing engineering is computed
// here. Polylines are only the chapter's shapes (Fig. 516.2 steps and ramps) laid through
// those numbers.
//
// Trace uids name what a trace is, so tests and readers can find it:
//   cycle:   "cycle-speed", "cycle-torque" (per segment once the detail is there), "cycle-rms"
//   diagram (the API's): "zone" | "zone-approx", "t-max", "n-max", "operating-point",
//            "peak-accel", "peak-decel"

import { PLOTLY_NUMBER, plotlySeparators, plotlySymbols, qty } from "../../lib/format.js";
import { translate, unitText } from "../../lib/i18n.js";

const COLORS = {
  speed: "#1f5f99",
  torque: "#b3471d",
  rms: "#6b4fa0",
  zone: "rgba(46, 139, 87, 0.22)",
  zoneLine: "#2e8b57",
  limit: "#444",
  pass: "#1e7b3c",
  fail: "#c0262d",
  other: "#7a6a00",
  grid: "#e4e6ea",
};

const FONT = { family: "system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif", size: 12 };

function isNum(x) {
  return typeof x === "number" && Number.isFinite(x);
}

/** A chart narrower than this (a phone) lists its legend one entry a line below the plot. */
export const NARROW_CHART_PX = 560;

/**
 * The legend below the plot: side by side where there is room, else one entry a line, so
 * that no entry is cut at a phone's width (issue 29 item 5).
 */
function legendBelow(narrow, y) {
  return narrow
    ? { orientation: "v", x: 0, xanchor: "left", y, yanchor: "top" }
    : { orientation: "h", x: 0, xanchor: "left", y, yanchor: "top" };
}

/** Longest legend line (visible characters) on a narrow chart. */
const NARROW_LEGEND_CHARS = 30;

/**
 * ``data`` with each trace's legend name broken into lines at spaces where the chart is
 * narrow (plotly.js does not wrap a legend entry: a long one is cut at a phone's width).
 */
function legendNames(data, narrow) {
  if (!narrow) return data;
  return data.map((trace) => (typeof trace.name === "string" ? { ...trace, name: wrapName(trace.name) } : trace));
}

function wrapName(name) {
  const visible = (text) => text.replace(/<[^>]*>/g, "").length;
  const lines = [];
  let line = "";
  for (const word of name.split(" ")) {
    if (line && visible(`${line} ${word}`) > NARROW_LEGEND_CHARS) {
      lines.push(line);
      line = word;
    } else {
      line = line ? `${line} ${word}` : word;
    }
  }
  lines.push(line);
  return lines.join("<br>");
}

function baseLayout(lang, narrow = false) {
  return {
    separators: plotlySeparators(lang),
    font: FONT,
    margin: { l: 64, r: 16, t: 28, b: 48 },
    paper_bgcolor: "#fff",
    plot_bgcolor: "#fff",
    showlegend: true,
    legend: legendBelow(narrow, -0.2),
    hovermode: "closest",
    annotations: [],
    shapes: [],
  };
}

function axis(title, extra = {}) {
  return {
    title: { text: plotlySymbols(title), standoff: 6 },
    zeroline: true,
    zerolinecolor: "#999",
    gridcolor: COLORS.grid,
    linecolor: "#999",
    ticks: "outside",
    rangemode: "tozero",
    ...extra,
  };
}

function hover(lang, xUnit, yUnit) {
  return (
    `%{fullData.name}<br>` +
    `%{x:${PLOTLY_NUMBER}} ${unitText(lang, xUnit)} · %{y:${PLOTLY_NUMBER}} ${unitText(lang, yUnit)}` +
    "<extra></extra>"
  );
}

/** The cycle's segments at the output as the API answers them, or null (an answer without). */
function answerSegments(selection) {
  const segs = Array.isArray(selection.segments) ? selection.segments : [];
  const ok = segs.every(
    (seg) => seg && isNum(seg.start_s) && isNum(seg.duration_s) && isNum(seg.start_rpm) && isNum(seg.end_rpm),
  );
  return ok && segs.length ? segs : null;
}

/** Whether the request gave the chapter's t_1…t_p (its four segments are t_1, t_2, t_3, t_p). */
function isTrapezoid(selection) {
  return isNum(selection.cycle?.accel_s);
}

/** The detail's torque along each segment, joined into one polyline, or null. */
function segmentTorqueLine(detail) {
  const parts = Array.isArray(detail?.segment_torques) ? detail.segment_torques : [];
  if (!parts.length) return null;
  const x = [];
  const y = [];
  for (const part of parts) {
    const times = Array.isArray(part?.times_s) ? part.times_s : [];
    const torques = Array.isArray(part?.torques_nm) ? part.torques_nm : [];
    if (times.length !== torques.length || !times.every(isNum) || !torques.every(isNum)) return null;
    x.push(...times);
    y.push(...torques);
  }
  return { x, y };
}

/**
 * Fig. 516.2, generalised to segments: speed n(t) and torque T(t) over one period.
 *
 * Speeds from the answer's ``selection.segments`` (output speed at each segment's start
 * and end; straight between them, also for an S-curve segment, whose share is in the
 * segment table), else from the request echo ``selection.cycle`` and n_2. Torque from the
 * candidate's ``detail.segment_torques`` (the API's points, straight between them) once
 * it is there; before (``detail`` undefined) or without it, the chapter's steps T_1, T_2,
 * T_3 of ``candidate`` for the t_1…t_p form, and for segments a note. ``detail`` null: it
 * failed.
 */
export function cycleFigure(selection, candidate, lang, detail = undefined, { narrow = false } = {}) {
  const t = (key) => translate(lang, key);
  const segments = answerSegments(selection);
  const trapezoid = isTrapezoid(selection);
  const end = selection.cycle_time_s;
  let speedX;
  let speedY;
  let bounds; // [label, from, to] per phase or segment
  if (segments) {
    // each segment starts at the speed the one before ends at: one point per boundary
    const last = segments[segments.length - 1];
    speedX = [...segments.map((seg) => seg.start_s), isNum(end) ? end : last.start_s + last.duration_s];
    speedY = [...segments.map((seg) => seg.start_rpm), last.end_rpm];
    const names = trapezoid && segments.length === 4 ? ["t_1", "t_2", "t_3", "t_p"] : null;
    bounds = segments.map((seg, k) => [names ? names[k] : String(k + 1), seg.start_s, seg.start_s + seg.duration_s]);
  } else {
    const { accel_s: t1, constant_s: t2, decel_s: t3 } = selection.cycle;
    const n2 = selection.load.speed_rpm;
    const a = t1;
    const b = t1 + t2;
    const c = t1 + t2 + t3;
    speedX = [0, a, b, c, end];
    speedY = [0, n2, n2, 0, 0];
    bounds = [
      ["t_1", 0, a],
      ["t_2", a, b],
      ["t_3", b, c],
      ["t_p", c, end],
    ];
  }

  const layout = baseLayout(lang, narrow);
  layout.margin = { l: 64, r: 16, t: 24, b: 48 };
  layout.xaxis = axis(t("fig.time"), { anchor: "y2", range: [0, end], rangemode: "normal" });
  layout.yaxis = axis(t("fig.speed"), { domain: [0.58, 1], anchor: "x" });
  layout.yaxis2 = axis(t("fig.torque"), { domain: [0, 0.46], anchor: "x", rangemode: "normal" });
  layout.legend.y = -0.22;

  const data = [
    {
      uid: "cycle-speed",
      name: plotlySymbols(t("fig.speed_trace")),
      type: "scatter",
      mode: "lines",
      x: speedX,
      y: speedY,
      xaxis: "x",
      yaxis: "y",
      line: { color: COLORS.speed, width: 2.5 },
      hovertemplate: hover(lang, "s", "rpm"),
    },
  ];

  const T1 = candidate.accel_torque_nm;
  const T2 = candidate.constant_torque_nm;
  const T3 = candidate.decel_torque_nm;
  const Trms = candidate.rms_torque_nm;
  const perSegment = segmentTorqueLine(detail);
  const torqueTrace = (x, y) => ({
    uid: "cycle-torque",
    name: plotlySymbols(t(perSegment ? "fig.torque_segments" : "fig.torque_trace")),
    type: "scatter",
    mode: "lines",
    x,
    y,
    xaxis: "x",
    yaxis: "y2",
    line: { color: COLORS.torque, width: 2.5 },
    hovertemplate: hover(lang, "s", "Nm"),
  });
  let drawn = false;
  if (perSegment) {
    data.push(torqueTrace(perSegment.x, perSegment.y));
    drawn = true;
  } else if (trapezoid && isNum(T1) && isNum(T2) && isNum(T3)) {
    const [[, , a], [, , b], [, , c]] = bounds;
    data.push(torqueTrace([0, 0, a, a, b, b, c, c, end], [0, T1, T1, T2, T2, T3, T3, 0, 0]));
    // Short labels centred on their phase; the values are in hover and caption.
    const label = (x, y, symbol, yshift) => ({
      x,
      y,
      xref: "x",
      yref: "y2",
      text: plotlySymbols(symbol),
      showarrow: false,
      yshift,
      font: { size: 12, color: COLORS.torque },
    });
    layout.annotations.push(
      label(a / 2, T1, "T_1", 10),
      label((a + b) / 2, T2, "T_2", T2 >= 0 ? 10 : -10),
      label((b + c) / 2, T3, "T_3", -10),
    );
    drawn = true;
  }
  if (drawn && isNum(Trms)) {
    data.push({
      uid: "cycle-rms",
      name: plotlySymbols(t("fig.rms_trace")),
      type: "scatter",
      mode: "lines",
      x: [0, end],
      y: [Trms, Trms],
      xaxis: "x",
      yaxis: "y2",
      line: { color: COLORS.rms, width: 1.5, dash: "dash" },
      hovertemplate: hover(lang, "s", "Nm"),
    });
  }
  if (!drawn) {
    // before the detail, a segment cycle has no torque to draw yet; after it, none means no J_A
    const key = detail === undefined && segments && !trapezoid ? "fig.torques_loading" : "fig.torques_nodata";
    layout.annotations.push({
      xref: "paper",
      yref: "y2 domain",
      x: 0.5,
      y: 0.5,
      text: plotlySymbols(t(key)),
      showarrow: false,
      font: { size: 14, color: key === "fig.torques_nodata" ? COLORS.fail : "#555" },
    });
    layout.yaxis2.range = [-1, 1];
  }

  // The phases (t_1 … t_p) or segments (1 … n) named above the speed panel, split by thin lines.
  for (const [symbol, from, to] of bounds) {
    if (to > from) {
      layout.annotations.push({
        x: (from + to) / 2,
        y: 1,
        xref: "x",
        yref: "paper",
        yanchor: "bottom",
        text: plotlySymbols(symbol),
        showarrow: false,
        font: { size: 11, color: "#555" },
      });
    }
  }
  for (const [, , to] of bounds.slice(0, -1)) {
    layout.shapes.push({
      type: "line",
      xref: "x",
      yref: "paper",
      x0: to,
      x1: to,
      y0: 0,
      y1: 1,
      line: { color: "#bbb", width: 1, dash: "dot" },
    });
  }
  return { data: legendNames(data, narrow), layout };
}

/**
 * The speed/torque diagram as the API defines it (``GET …/candidates/{model}/diagram``, the
 * figure the quote and the report print, from ``api/figures.py``), fitted to the chart's
 * width: a narrow chart lists its legend one entry a line below the plot, names broken
 * into lines. ``figure`` is left unchanged.
 */
export function fitDiagram(figure, { narrow = false } = {}) {
  const layout = { ...figure.layout, legend: legendBelow(narrow, -0.2) };
  return { data: legendNames(figure.data, narrow), layout };
}

/** A text alternative of the cycle chart, for the figure's caption. */
export function cycleCaption(selection, candidate, lang) {
  const q = (v, u) => qty(v, u, lang);
  if (!isTrapezoid(selection)) {
    return translate(lang, "fig.caption.segments", {
      count: Array.isArray(selection.segments) ? selection.segments.length : "–",
      n2: q(selection.load.speed_rpm, "rpm"),
      t1: q(candidate.accel_torque_nm, "Nm"),
      t3: q(candidate.decel_torque_nm, "Nm"),
      trms: q(candidate.rms_torque_nm, "Nm"),
      t0: q(selection.cycle_time_s, "s"),
    });
  }
  return translate(lang, "fig.caption.cycle", {
    n2: q(selection.load.speed_rpm, "rpm"),
    t1: q(candidate.accel_torque_nm, "Nm"),
    t2: q(candidate.constant_torque_nm, "Nm"),
    t3: q(candidate.decel_torque_nm, "Nm"),
    trms: q(candidate.rms_torque_nm, "Nm"),
    a: q(selection.cycle.accel_s, "s"),
    c: q(selection.cycle.constant_s, "s"),
    d: q(selection.cycle.decel_s, "s"),
    p: q(selection.cycle.pause_s, "s"),
    t0: q(selection.cycle_time_s, "s"),
  });
}

/**
 * A text alternative of the speed/torque diagram, for the figure's caption: the candidate's
 * numbers, and the zone the API's figure drew (its ``layout.meta.zone``; ``figure`` null
 * before it is there).
 */
export function diagramCaption(selection, candidate, actuator, figure, lang) {
  const q = (v, u) => qty(v, u, lang);
  const meta = figure?.layout?.meta?.zone === undefined ? null : figure.layout.meta;
  let zone;
  if (meta?.zone === "catalogue") zone = translate(lang, "fig.caption.zone");
  else if (meta?.zone === "approximate") {
    zone = translate(lang, "fig.caption.approx", {
      what: meta.what,
      value: q(meta.torque, "Nm"),
      speed: meta.speed_what,
      speedValue: q(meta.speed, "rpm"),
    });
  } else zone = translate(lang, "fig.caption.nodata");
  const t3 = candidate.decel_torque_nm;
  return translate(lang, "fig.caption.diagram", {
    nav: q(selection.mean_speed_rpm, "rpm"),
    trms: q(candidate.rms_torque_nm, "Nm"),
    n2: q(selection.load.speed_rpm, "rpm"),
    t1: q(candidate.accel_torque_nm, "Nm"),
    t3: q(isNum(t3) ? Math.abs(t3) : null, "Nm"),
    tmax: q(actuator?.max_torque_nm, "Nm"),
    nmax: q(actuator?.max_speed_rpm, "rpm"),
    zone,
  });
}
