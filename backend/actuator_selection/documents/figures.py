"""The cycle chart (Fig. 516.2) and the speed/torque diagram (Fig. 517.1), each defined
once for the page, the quote document and the selection report.

:func:`cycle_figure` gives the cycle as a plotly figure of two panels sharing the time
axis: the speed n(t) above, the torque T(t) below (``GET
/selections/{id}/candidates/{model}/cycle``; the report PDF draws it with its own lines).
Its trace uids: "cycle-speed", "cycle-torque", "cycle-rms", and "cycle-phases" (text, no
legend: t_1 … t_p or the segments' numbers above the speed panel); ``layout.meta.torques`` says
what the torque panel holds ("segments": the torque along each segment, "steps": the
chapter's T_1, T_2, T_3, "none": a note why not).

:func:`diagram_figure` gives a plotly figure as JSON (``data`` and ``layout``): the page
draws it with its plotly.js (``GET /selections/{id}/candidates/{model}/diagram``, with
hover and zoom), the quote's HTML with the same plotly.js, and the PDFs with their own
lines (``documents/pdf.py``: ``FigurePdf.figure``). Every number drawn comes from the
answer: the candidate's torques and checks, the selection's speeds, the actuator's
catalogue entry; the only shapes laid through them are the chapter's (the rectangle of an
approximate zone).

Trace uids name what a trace is, so that tests and readers can find it: "zone" |
"zone-approx", "zone-label" (the approximate zone's value, text), "t-max", "n-max",
"operating-point", "peak-accel", "peak-decel".

:func:`ratio_figure` gives the ratio study's chart (``POST /selections/ratio-study`` with
``figure=true``): for each actuator that carries its curve (the best ones), the binding
utilisation against the free value ("ratio-curve-<model>"), its feasible intervals shaded
("ratio-band-<model>", from 0 to the limit 1) and its best value ("ratio-best-<model>");
the limit ("ratio-limit"). Every number is the study's.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

from actuator_selection.documents.quote_document_text import DocumentText
from actuator_selection.documents.symbols import symbols
from actuator_selection.schemas.quotes import StoredSelection
from actuator_selection.schemas.ratio import RatioStudyOut
from actuator_selection.schemas.selections import CandidateFigures

COLORS = {
    "speed": "#1f5f99",
    "torque": "#b3471d",
    "rms": "#6b4fa0",
    "zone": "rgba(46, 139, 87, 0.22)",
    "zone_line": "#2e8b57",
    "limit": "#444",
    "pass": "#1e7b3c",
    "fail": "#c0262d",
    "other": "#7a6a00",
    "grid": "#e4e6ea",
}
FONT = {"family": "system-ui, -apple-system, 'Segoe UI', Roboto, sans-serif", "size": 12}
HOVER_NUMBER = ".4~g"
"""Plotly's d3 format of hover numbers: 4 significant digits, as the page's numbers."""


@dataclass(frozen=True, slots=True)
class DiagramPoints:
    """What the diagram draws of a load case and a candidate: n_2 and n_av of the selection,
    T_1, T_3 and T_rms of the candidate, and the status of its checks by name."""

    n2: float | None
    n_av: float | None
    t1: float | None
    t3: float | None
    trms: float | None
    statuses: Mapping[str, str]


def _num(x: object) -> float | None:
    """``x`` if it is a finite number (not a bool), else None."""
    if isinstance(x, int | float) and not isinstance(x, bool) and math.isfinite(x):
        return float(x)
    return None


def _sym(text: str) -> str:
    """Symbols subscripted as plotly.js writes them (``T_max`` → ``T<sub>max</sub>``)."""
    return str(symbols(text))


def separators(t: DocumentText) -> str:
    """Plotly's decimal and thousands marks in the document's locale (",." in German)."""
    sample = t.number(1000.5, "#,##0.0")
    return sample[-2] + sample[1]


def _hover(t: DocumentText, x_unit: str, y_unit: str) -> str:
    return (
        "%{fullData.name}<br>"
        f"%{{x:{HOVER_NUMBER}}} {t.unit(x_unit)} · %{{y:{HOVER_NUMBER}}} {t.unit(y_unit)}"
        "<extra></extra>"
    )


def _axis(title: str, **extra: Any) -> dict[str, Any]:
    return {
        "title": {"text": _sym(title), "standoff": 6},
        "zeroline": True,
        "zerolinecolor": "#999",
        "gridcolor": COLORS["grid"],
        "linecolor": "#999",
        "ticks": "outside",
        "rangemode": "tozero",
        **extra,
    }


def approximate_zone(actuator: Mapping[str, Any] | None, t: DocumentText) -> dict[str, Any]:
    """The zone that stands for the continuous-duty zone where the catalogue has none, as
    the continuous_duty and continuous_speed checks bound it (``sizing/checks``
    ``_continuous_limit``, ``_speed_limit``): T_0, else the allowable continuous torque; up
    to the allowable continuous speed, else the rated speed (never n_max, a peak speed).
    Where k_T and K_INL are published with T_0, the edge falls with speed as the winding
    current does, T_0 − k_T·K_INL·n (K_INL at 80 °C, else at 30 °C; ``sizing/electrical.py``
    ``no_load_torque_slope_nm_per_rpm``): ``slope`` is k_T·K_INL, else 0.

    >>> zone = approximate_zone({"continuous_torque_nm": 2.9, "rated_speed_rpm": 60}, EN)
    >>> zone["torque"], zone["speed"], zone["what"], zone["speed_what"], zone["slope"]
    (2.9, 60.0, 'allowable continuous torque', 'rated speed', 0.0)
    """
    a = actuator or {}
    stall = _num(a.get("stall_torque_nm"))
    continuous_speed = _num(a.get("continuous_speed_rpm"))
    k_t = _num(a.get("torque_constant_nm_per_a"))
    hot = _num(a.get("no_load_current_constant_80c_a_per_rpm"))
    k_inl = hot if hot is not None else _num(a.get("no_load_current_constant_30c_a_per_rpm"))
    return {
        "torque": stall if stall is not None else _num(a.get("continuous_torque_nm")),
        "what": t("fig_stall") if stall is not None else t("fig_continuous"),
        "speed": continuous_speed
        if continuous_speed is not None
        else _num(a.get("rated_speed_rpm")),
        "speed_what": t("fig_continuous_speed")
        if continuous_speed is not None
        else t("fig_rated_speed"),
        "slope": k_t * k_inl
        if stall is not None and k_t is not None and k_inl is not None
        else 0.0,
    }


def _zone_points(actuator: Mapping[str, Any] | None) -> list[tuple[float, float]]:
    """The catalogue's continuous-duty zone, sorted by speed (points without numbers left
    out)."""
    zone = (actuator or {}).get("continuous_duty_zone")
    if not isinstance(zone, list):
        return []
    points = [
        (s, q)
        for p in zone
        if isinstance(p, Mapping)
        and (s := _num(p.get("speed_rpm"))) is not None
        and (q := _num(p.get("torque_nm"))) is not None
    ]
    return sorted(points)


def diagram_figure(
    points: DiagramPoints, actuator: Mapping[str, Any] | None, t: DocumentText
) -> dict[str, Any]:
    """Fig. 517.1: the speed/torque diagram of ``actuator`` with the candidate's points.

    The continuous-duty zone from the catalogue's ``continuous_duty_zone`` where it has one
    (a closed area down to T = 0); else the approximate rectangle of
    :func:`approximate_zone`, marked approximate; else "no data" above the plot, as the
    check says. T_max and n_max as limit lines; the operating point (n_av, T_rms) and the
    peaks (n_2, T_1), (n_2, |T_3|), coloured by their checks' status. ``actuator`` may be
    None when the catalogue record could not be read. ``layout.meta.zone`` says which zone
    is drawn ("catalogue", "approximate" with its numbers and words, or "none"), for a
    text alternative beside the chart.
    """
    a = actuator or {}
    n_max, t_max = _num(a.get("max_speed_rpm")), _num(a.get("max_torque_nm"))
    n2, n_av = _num(points.n2), _num(points.n_av)
    t1, t3, trms = _num(points.t1), _num(points.t3), _num(points.trms)
    hover = _hover(t, "rpm", "Nm")
    number = "#,##0.###"
    layout = _base_layout(t)
    layout["xaxis"] = _axis(t("axis_speed", rpm=t.unit("rpm")))
    layout["yaxis"] = _axis(t("axis_torque"))
    data: list[dict[str, Any]] = []
    xs = [x for x in (n2, n_av, n_max) if x is not None]
    ys = [y for y in (t1, abs(t3) if t3 is not None else None, trms, t_max) if y is not None]

    zone = _zone_points(actuator)
    approx = approximate_zone(actuator, t)
    labels: list[tuple[float, float, str, str]] = []
    if len(zone) >= 2:
        (first_speed, _), (last_speed, _) = zone[0], zone[-1]
        data.append(
            {
                "uid": "zone",
                "name": _sym(t("zone")),
                "type": "scatter",
                "mode": "lines",
                # closed down to T = 0 at both ends, an area the PDF fills as plotly.js does
                "x": [first_speed, *(s for s, _ in zone), last_speed, first_speed],
                "y": [0.0, *(q for _, q in zone), 0.0, 0.0],
                "fill": "toself",
                "fillcolor": COLORS["zone"],
                "line": {"color": COLORS["zone_line"], "width": 2},
                "hovertemplate": hover,
            }
        )
        xs.append(last_speed)
        ys.extend(q for _, q in zone)
        layout["meta"] = {"zone": "catalogue"}
    elif approx["torque"] is not None and approx["speed"] is not None:
        torque, speed = approx["torque"], approx["speed"]
        data.append(
            {
                "uid": "zone-approx",
                "name": _sym(t("fig_zone_approx", what=approx["what"], speed=approx["speed_what"])),
                "type": "scatter",
                "mode": "lines",
                "x": [0.0, 0.0, speed, speed, 0.0],
                "y": [0.0, torque, max(torque - approx["slope"] * speed, 0.0), 0.0, 0.0],
                "fill": "toself",
                "fillcolor": COLORS["zone"],
                "line": {"color": COLORS["zone_line"], "width": 2, "dash": "dash"},
                "hovertemplate": hover,
            }
        )
        xs.append(speed)
        ys.append(torque)
        layout["meta"] = {"zone": "approximate", **approx}
        zone_label = f"≈ {approx['what']} = {t.number(torque, number)} Nm ({t('fig_approximate')})"
        # below the zone's upper edge, halfway along it (where the edge falls with speed)
        edge = max(torque - approx["slope"] * speed / 2, 0.0)
        labels.append((speed / 2, edge, zone_label, "bottom center"))
    else:
        # above the plot area, where it can never hide a point; two lines without the
        # catalogue, so that the box fits a narrow chart
        layout["margin"] = {**layout["margin"], "t": 44 if actuator else 62}
        layout["meta"] = {"zone": "none"}
        text = _sym(t("fig_zone_nodata"))
        if not actuator:
            text += "<br>" + _sym(t("fig_catalogue_missing"))
        layout["annotations"].append(
            {
                "xref": "paper",
                "yref": "paper",
                "x": 0,
                "y": 1,
                "xanchor": "left",
                "yanchor": "bottom",
                "yshift": 8,
                "align": "left",
                "text": text,
                "showarrow": False,
                "bgcolor": "#f0f2f5",
                "bordercolor": "#999",
                "borderwidth": 1,
                "borderpad": 4,
                "font": {"size": 13, "color": "#333"},
            }
        )

    # the axes frame what is drawn, with some room for labels
    x_top = max([*xs, 1.0]) * 1.1
    y_top = max([*ys, 1.0]) * 1.15
    layout["xaxis"]["range"] = [0, x_top]
    layout["yaxis"]["range"] = [0, y_top]

    if t_max is not None:
        data.append(
            {
                "uid": "t-max",
                "name": _sym(f"T_max = {t.number(t_max, number)} Nm"),
                "type": "scatter",
                "mode": "lines",
                "x": [0.0, n_max if n_max is not None else x_top],
                "y": [t_max, t_max],
                "line": {"color": COLORS["limit"], "width": 2},
                "hovertemplate": hover,
            }
        )
    if n_max is not None:
        data.append(
            {
                "uid": "n-max",
                "name": _sym(f"n_max = {t.number(n_max, number)} {t.unit('rpm')}"),
                "type": "scatter",
                "mode": "lines",
                "x": [n_max, n_max],
                "y": [0.0, t_max if t_max is not None else y_top],
                "line": {"color": COLORS["limit"], "width": 2, "dash": "dot"},
                "hovertemplate": hover,
            }
        )

    def point(uid: str, label: str, x: float, y: float, check: str, marker: str) -> None:
        status = points.statuses.get(check, "no_data")
        color = COLORS.get(status, COLORS["other"]) if status in {"pass", "fail"} else None
        data.append(
            {
                "uid": uid,
                "name": _sym(label),
                "type": "scatter",
                "mode": "markers",
                "x": [x],
                "y": [y],
                "marker": {
                    "size": 12,
                    "symbol": marker,
                    "color": color or COLORS["other"],
                    "line": {"color": "#000", "width": 1},
                },
                "hovertemplate": hover,
            }
        )

    if labels:
        data.append(_labels("zone-label", labels, color=COLORS["zone_line"]))
    if trms is not None and n_av is not None:
        point("operating-point", t("point_rms"), n_av, trms, "continuous_duty", "circle")
    if t1 is not None and n2 is not None:
        point("peak-accel", t("point_accel"), n2, t1, "peak_torque", "triangle-up")
    if t3 is not None and n2 is not None:
        point("peak-decel", t("point_decel"), n2, abs(t3), "decel_torque", "triangle-down")
    return {"data": data, "layout": layout}


def _base_layout(t: DocumentText) -> dict[str, Any]:
    return {
        "separators": separators(t),
        "font": FONT,
        "margin": {"l": 64, "r": 16, "t": 28, "b": 48},
        "paper_bgcolor": "#fff",
        "plot_bgcolor": "#fff",
        "showlegend": True,
        "legend": {"orientation": "h", "x": 0, "xanchor": "left", "y": -0.2, "yanchor": "top"},
        "hovermode": "closest",
        "annotations": [],
        "shapes": [],
    }


LINE_PAD = 0.06
"""Room beyond the lines of a panel whose range is given, a share of the values' span (plotly.js's
autorange leaves 5 % of the axis's length to a line)."""
LABEL_PAD = 0.25
"""The same where the panel's highest and lowest values have a label above or below them (T_1
and T_3 of the cycle's steps, 10 px off their line)."""


def _panel_range(values: Sequence[float], pad: float) -> list[float]:
    """A panel's range from 0 and ``values``, ``pad`` × their span beyond any end that is not 0
    (a panel of speeds or torques starts at 0, as plotly.js's ``rangemode`` "tozero")."""
    finite = [v for v in (_num(x) for x in values) if v is not None]
    low, high = min([0.0, *finite]), max([0.0, *finite])
    if not high > low:
        return [0.0, 1.0]
    span = high - low
    return [low - pad * span if low < 0 else 0.0, high + pad * span if high > 0 else 0.0]


def _labels(
    uid: str, at: Sequence[tuple[float, float, str, str]], *, color: str = "#555"
) -> dict[str, Any]:
    """Short labels on the plot as one trace of text (plotly's ``mode`` "text"), each at
    (x, y, text, position): drawn once and not measured, where plotly.js draws an
    annotation twice when it first draws a chart, the first time to measure it for the
    autorange. Not in the legend, no hover; the PDFs leave them out."""
    return {
        "uid": uid,
        "name": "",
        "type": "scatter",
        "mode": "text",
        "x": [x for x, _, _, _ in at],
        "y": [y for _, y, _, _ in at],
        "text": [_sym(text) for _, _, text, _ in at],
        "textposition": [position for _, _, _, position in at],
        "textfont": {"size": 11, "color": color},
        "xaxis": "x",
        "yaxis": "y",
        "cliponaxis": False,
        "showlegend": False,
        "hoverinfo": "skip",
    }


SegmentTorques = Sequence[tuple[Sequence[float], Sequence[float]]]
"""The torque along each segment: per segment the times from the cycle's start [s] and the
torques at them [Nm] (``sizing/motion`` ``Profile.segment_torques``)."""


def cycle_figure(
    selection: StoredSelection,
    candidate: CandidateFigures | None,
    t: DocumentText,
    torques: SegmentTorques | None = None,
) -> dict[str, Any]:
    """Fig. 516.2, generalised to segments: speed n(t) and torque T(t) over one period.

    Speeds from the selection's ``segments`` (output speed at each segment's start and
    end, straight between them, also for an S-curve segment, whose share is in the
    segment table), else from its cycle t_1…t_p and n_2. Torque along each segment from
    ``torques`` where given (straight between its points); else the chapter's steps T_1,
    T_2, T_3 of ``candidate`` for the t_1…t_p form; else a note (no J_A; none without a
    candidate). T_rms as a line.
    Every number drawn is the answer's; the only shapes laid through them are the
    chapter's steps and ramps.
    """
    segments = selection.segments
    trapezoid = selection.cycle.is_trapezoid
    end = selection.cycle_time_s
    bounds: list[tuple[str, float, float]]
    if segments:
        # each segment starts at the speed the one before ends at: one point per boundary
        speed_x = [seg.start_s for seg in segments] + [end]
        speed_y = [seg.start_rpm for seg in segments] + [segments[-1].end_rpm]
        names = ["t_1", "t_2", "t_3", "t_p"] if trapezoid and len(segments) == 4 else None
        bounds = [
            (names[k] if names else str(k + 1), seg.start_s, seg.start_s + seg.duration_s)
            for k, seg in enumerate(segments)
        ]
    else:
        c = selection.cycle
        a = c.accel_s or 0.0
        b = a + (c.constant_s or 0.0)
        d = b + (c.decel_s or 0.0)
        n2 = selection.load.speed_rpm
        speed_x, speed_y = [0.0, a, b, d, end], [0.0, n2, n2, 0.0, 0.0]
        bounds = [("t_1", 0.0, a), ("t_2", a, b), ("t_3", b, d), ("t_p", d, end)]

    layout = _base_layout(t)
    layout["margin"] = {"l": 64, "r": 16, "t": 24, "b": 48}
    layout["xaxis"] = _axis(t("fig.time"), anchor="y2", range=[0, end], rangemode="normal")
    layout["yaxis"] = _axis(t("fig.speed"), domain=[0.58, 1], anchor="x")
    layout["yaxis2"] = _axis(t("fig.torque"), domain=[0, 0.46], anchor="x", rangemode="normal")
    layout["legend"]["y"] = -0.22
    data: list[dict[str, Any]] = [
        {
            "uid": "cycle-speed",
            "name": _sym(t("fig.speed_trace")),
            "type": "scatter",
            "mode": "lines",
            "x": speed_x,
            "y": speed_y,
            "xaxis": "x",
            "yaxis": "y",
            "line": {"color": COLORS["speed"], "width": 2.5},
            "hovertemplate": _hover(t, "s", "rpm"),
        }
    ]

    def torque_trace(key: str, x: list[float], y: list[float]) -> dict[str, Any]:
        return {
            "uid": "cycle-torque",
            "name": _sym(t(key)),
            "type": "scatter",
            "mode": "lines",
            "x": x,
            "y": y,
            "xaxis": "x",
            "yaxis": "y2",
            "line": {"color": COLORS["torque"], "width": 2.5},
            "hovertemplate": _hover(t, "s", "Nm"),
        }

    t1, t2, t3, trms = (
        (None,) * 4
        if candidate is None
        else (
            _num(candidate.accel_torque_nm),
            _num(candidate.constant_torque_nm),
            _num(candidate.decel_torque_nm),
            _num(candidate.rms_torque_nm),
        )
    )
    drawn = "none"
    if torques:
        xs = [float(x) for times, _ in torques for x in times]
        ys = [float(y) for _, values in torques for y in values]
        data.append(torque_trace("fig.torque_segments", xs, ys))
        drawn = "segments"
    elif trapezoid and t1 is not None and t2 is not None and t3 is not None:
        (_, _, a), (_, _, b), (_, _, d) = bounds[:3]
        data.append(
            torque_trace(
                "fig.torque_trace",
                [0.0, 0.0, a, a, b, b, d, d, end],
                [0.0, t1, t1, t2, t2, t3, t3, 0.0, 0.0],
            )
        )

        # short labels centred on their phase, 10 px off the step (annotations: plotly.js's
        # text traces cannot be shifted by pixels); the values are in hover and caption
        def label(x: float, y: float, symbol: str, yshift: int) -> dict[str, Any]:
            return {
                "x": x,
                "y": y,
                "xref": "x",
                "yref": "y2",
                "text": _sym(symbol),
                "showarrow": False,
                "yshift": yshift,
                "font": {"size": 12, "color": COLORS["torque"]},
            }

        layout["annotations"] += [
            label(a / 2, t1, "T_1", 10),
            label((a + b) / 2, t2, "T_2", 10 if t2 >= 0 else -10),
            label((b + d) / 2, t3, "T_3", -10),
        ]
        drawn = "steps"
    if drawn != "none" and trms is not None:
        data.append(
            {
                "uid": "cycle-rms",
                "name": _sym(t("fig.rms_trace")),
                "type": "scatter",
                "mode": "lines",
                "x": [0.0, end],
                "y": [trms, trms],
                "xaxis": "x",
                "yaxis": "y2",
                "line": {"color": COLORS["rms"], "width": 1.5, "dash": "dash"},
                "hovertemplate": _hover(t, "s", "Nm"),
            }
        )
    if drawn == "none" and candidate is not None:
        layout["annotations"].append(
            {
                "xref": "paper",
                "yref": "y2 domain",
                "x": 0.5,
                "y": 0.5,
                "text": _sym(t("fig.torques_nodata")),
                "showarrow": False,
                "font": {"size": 14, "color": COLORS["fail"]},
            }
        )
    # each panel's range given here, so that plotly.js draws the figure without its
    # autorange (which first draws the annotations to measure them); the PDF uses it too
    layout["yaxis"]["range"] = _panel_range(speed_y, LINE_PAD)
    torque_values = [y for trace in data[1:] for y in trace["y"]]
    layout["yaxis2"]["range"] = (
        _panel_range(torque_values, LABEL_PAD if drawn == "steps" else LINE_PAD)
        if drawn != "none"
        else [-1, 1]
    )
    layout["meta"] = {"torques": drawn}

    # the phases (t_1 … t_p) or segments (1 … n) named above the speed panel, split by lines
    top = layout["yaxis"]["range"][1]
    phases = [
        ((start + stop) / 2, top, symbol, "top center")
        for symbol, start, stop in bounds
        if stop > start
    ]
    if phases:
        data.append(_labels("cycle-phases", phases))
    for _, _, stop in bounds[:-1]:
        layout["shapes"].append(
            {
                "type": "line",
                "xref": "x",
                "yref": "paper",
                "x0": stop,
                "x1": stop,
                "y0": 0,
                "y1": 1,
                "line": {"color": "#bbb", "width": 1, "dash": "dot"},
            }
        )
    return {"data": data, "layout": layout}


RATIO_COLORS = ("#1f5f99", "#b3471d", "#2e8b57", "#6b4fa0", "#7a6a00", "#c0262d", "#444")
"""One colour per actuator of the ratio chart, in the study's order, repeated past seven."""


def _rgba(color: str, alpha: float) -> str:
    r, g, b = (int(color[k : k + 2], 16) for k in (1, 3, 5))
    return f"rgba({r}, {g}, {b}, {alpha})"


def ratio_figure(study: RatioStudyOut, t: DocumentText) -> dict[str, Any]:
    """The ratio study's chart: the binding utilisation (max value/limit over the checks)
    against the free value for each actuator with a curve, its feasible intervals shaded
    up to the limit 1, its best value marked; the free value on a log axis."""
    unit = "-" if study.unit == "-" else study.unit
    x_title = t(f"fig.ratio.{study.variable}")
    data: list[dict[str, Any]] = []
    for n, entry in enumerate(a for a in study.actuators if a.curve is not None):
        assert entry.curve is not None
        color = RATIO_COLORS[n % len(RATIO_COLORS)]
        group = f"ratio-{entry.model}"
        band_x: list[float | None] = []
        band_y: list[float | None] = []
        for interval in entry.intervals:
            if band_x:
                band_x.append(None)
                band_y.append(None)
            band_x += [interval.low, interval.low, interval.high, interval.high, interval.low]
            band_y += [0.0, 1.0, 1.0, 0.0, 0.0]
        if band_x:
            data.append(
                {
                    "uid": f"ratio-band-{entry.model}",
                    "name": t("fig.ratio.band", model=entry.model),
                    "type": "scatter",
                    "mode": "lines",
                    "x": band_x,
                    "y": band_y,
                    "fill": "toself",
                    "fillcolor": _rgba(color, 0.14),
                    "line": {"width": 0, "color": color},
                    "legendgroup": group,
                    "showlegend": False,
                    "hoverinfo": "skip",
                }
            )
        data.append(
            {
                "uid": f"ratio-curve-{entry.model}",
                "name": entry.model,
                "type": "scatter",
                "mode": "lines",
                "x": entry.curve.values,
                "y": entry.curve.utilisation,
                "line": {"color": color, "width": 2},
                "legendgroup": group,
                "hovertemplate": _hover(t, unit, "-"),
            }
        )
        if entry.best is not None and entry.best_utilisation is not None:
            data.append(
                {
                    "uid": f"ratio-best-{entry.model}",
                    "name": t("fig.ratio.best", model=entry.model),
                    "type": "scatter",
                    "mode": "markers",
                    "x": [entry.best],
                    "y": [entry.best_utilisation],
                    "marker": {"color": color, "size": 9, "symbol": "diamond"},
                    "legendgroup": group,
                    "showlegend": False,
                    "hovertemplate": _hover(t, unit, "-"),
                }
            )
    data.append(
        {
            "uid": "ratio-limit",
            "name": t("fig.ratio.limit"),
            "type": "scatter",
            "mode": "lines",
            "x": [study.min, study.max],
            "y": [1.0, 1.0],
            "line": {"color": COLORS["limit"], "width": 1.5, "dash": "dash"},
            "hovertemplate": _hover(t, unit, "-"),
        }
    )
    layout = _base_layout(t)
    layout["xaxis"] = _axis(x_title, type="log", rangemode="normal")
    layout["yaxis"] = _axis(t("fig.ratio.utilisation"))
    return {"data": data, "layout": layout}


EN = DocumentText("en")
"""English, for the doctests."""
