// The page's charts are the API's figures (documents/figures.py: the cycle chart and the
// speed/torque diagram, the figures the quote and the report print), fitted here to the
// chart's width, and their text alternatives. Pure functions: nothing engineering is
// computed or drawn here.

import { qty } from "../../lib/format.js";
import { translate } from "../../lib/i18n.js";

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

/** Whether the request gave the chapter's t_1…t_p (its four segments are t_1, t_2, t_3, t_p). */
function isTrapezoid(selection) {
  return isNum(selection.cycle?.accel_s);
}

// plotly.js 4's sizes a legend's height is made of (its legend/constants.js and draw.js):
// an entry is max(lines · 1.3 · font size, 16) + 3 px high, not measured, the legend's
// inside has itemGap (5 px) above and below, and a margin pushed is the pushed size
// plus a pad of 12 px (``Plots.autoMargin``, margins of 12 px and more).
const LEGEND_LINE_SPACING = 1.3;
const LEGEND_ENTRY_MIN_PX = 16;
const LEGEND_ENTRY_EXTRA_PX = 3;
const LEGEND_ITEM_GAP_PX = 5;
const AUTOMARGIN_PAD_PX = 12;
/** plotly.js's least plot height (``minreducedheight``): no margin given that leaves less. */
const MIN_PLOT_PX = 64;

/** How many lines plotly.js writes ``name`` in (a ``<br>`` breaks a line). */
function lineCount(name) {
  return typeof name === "string" ? (name.match(/<br\s*\/?>/gi)?.length ?? 0) + 1 : 1;
}

/**
 * The bottom margin plotly.js pushes the legend below the plot to, given up front: plotly.js
 * draws the plot with the figure's margin, finds the legend does not fit below it, moves the
 * margin and draws the legend and the layout's styles again (a fifth of a chart's drawing
 * here). Its formula (``Plots.doAutoMargin``), for a legend anchored at its top at paper
 * height ``y`` < 0 and ``h`` high: b = (h + pad + (t − height) · y) / (1 − y), rounded as
 * plotly.js rounds its margins, so that the chart is the same, the margin not moved.
 * A vertical legend's height is its entries'; a horizontal one's is at least one row's,
 * so ``b`` is then the least plotly.js can push to (a legend of more rows is pushed
 * further by plotly.js, as before). Undefined where the figure is not of that form.
 */
function legendMargin(data, layout, legend, height) {
  const margin = layout.margin;
  const font = legend.font?.size ?? layout.font?.size;
  const sides = [margin?.l, margin?.r, margin?.t, margin?.b];
  if (!isNum(height) || height <= 0 || !sides.every(isNum) || !isNum(font) || !isNum(legend.y)) return undefined;
  if (layout.showlegend !== true || legend.y >= 0 || legend.yanchor !== "top") return undefined;
  if (legend.title !== undefined || legend.maxheight !== undefined || legend.borderwidth !== undefined) return undefined;
  if (legend.yref !== undefined && legend.yref !== "paper") return undefined;
  if (!Array.isArray(data) || !data.every((trace) => (trace.type ?? "scatter") === "scatter")) return undefined;
  const entries = data
    .filter((trace) => trace.showlegend !== false && trace.visible !== false)
    .map((trace) => Math.max(lineCount(trace.name) * LEGEND_LINE_SPACING * font, LEGEND_ENTRY_MIN_PX) + LEGEND_ENTRY_EXTRA_PX);
  if (!entries.length) return undefined;
  const inside = legend.orientation === "v" ? entries.reduce((a, b) => a + b, 0) : Math.max(...entries);
  const legendPx = Math.min(Math.ceil(inside + 2 * LEGEND_ITEM_GAP_PX), Math.max(height / 2, 30));
  const pad = Math.min(AUTOMARGIN_PAD_PX, margin.l, margin.r, margin.t, margin.b);
  const b = Math.round((legendPx + pad + (margin.t - height) * legend.y) / (1 - legend.y));
  return b > margin.b && b + margin.t <= height - MIN_PLOT_PX ? b : undefined;
}

/**
 * A figure as the API defines it (``GET …/candidates/{model}/cycle`` and ``…/diagram``, the
 * figures the quote and the report print, from ``documents/figures.py``), fitted to the chart's
 * width: a narrow chart lists its legend one entry a line below the plot, names broken
 * into lines. Given the chart's ``height`` (px, as its style has it), the figure's bottom
 * margin is the one plotly.js would push the legend to (``legendMargin``): the same chart,
 * drawn in one pass. ``figure`` is left unchanged.
 */
export function fitFigure(figure, { narrow = false, height = undefined } = {}) {
  const legend = legendBelow(narrow, figure.layout?.legend?.y ?? -0.2);
  const data = legendNames(figure.data, narrow);
  const layout = { ...figure.layout, legend };
  const b = legendMargin(data, layout, { ...figure.layout?.legend, ...legend }, height);
  if (b !== undefined) layout.margin = { ...layout.margin, b };
  return { data, layout };
}

/**
 * Made-up figures of what the API's figures draw, drawn off screen one a task to warm
 * plotly.js up; never shown. The first is small (one panel, a line, the legend below, as
 * the API's, two tick labels an axis): it takes plotly.js's first-use costs, and as
 * plotly.js measures each text in the page (a layout each), no more texts than it takes
 * to run that code once. The second has the rest (two panels of lines, a filled area,
 * markers, a shape and labels as text, as the API's figures label their phases).
 */
export const WARM_FIGURES = [
  {
    data: [{ type: "scatter", mode: "lines", x: [0, 1], y: [0, 1], name: "n<sub>2</sub>" }],
    layout: {
      showlegend: true,
      legend: { orientation: "h", x: 0, xanchor: "left", y: -0.2, yanchor: "top" },
      margin: { l: 64, r: 16, t: 24, b: 48 },
      xaxis: { nticks: 2 },
      yaxis: { nticks: 2 },
    },
  },
  {
    data: [
      { type: "scatter", mode: "lines", x: [0, 1, 2], y: [0, 1, 0], fill: "toself", yaxis: "y" },
      { type: "scatter", mode: "lines", x: [0, 1, 2], y: [1, -1, 0], line: { dash: "dash" }, yaxis: "y2" },
      { type: "scatter", mode: "markers", x: [1], y: [0.5], marker: { symbol: "triangle-up" }, yaxis: "y" },
      {
        type: "scatter",
        mode: "text",
        x: [1],
        y: [1],
        text: ["t<sub>1</sub>"],
        textposition: ["top center"],
        cliponaxis: false,
        showlegend: false,
        hoverinfo: "skip",
        yaxis: "y",
      },
    ],
    layout: {
      xaxis: { anchor: "y2" },
      yaxis: { domain: [0.58, 1], anchor: "x" },
      yaxis2: { domain: [0, 0.46], anchor: "x" },
      shapes: [{ type: "line", xref: "x", yref: "paper", x0: 1, x1: 1, y0: 0, y1: 1 }],
    },
  },
];

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
