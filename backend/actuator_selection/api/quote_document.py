"""The printable quote: HTML laid out for A4, with the engineering that justifies the offer.

Built by hand with :func:`html.escape` on every value (Jinja2 is not installed
and not needed): customer text can hold anything and must never become markup.
The speed/torque diagram is a plotly figure built here with
``plotly.graph_objects`` and drawn in the browser by the app's own plotly.js
(``PLOTLY_URL``) through a small script of this module; no CDN, no inline code.

Every number comes from the stored quote and the stored selection (immutable),
plus the actuator's catalogue entry as copied into the quote when it was made.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from decimal import Decimal
from html import escape
from string import Template
from typing import Any

import plotly.graph_objects as go

from actuator_selection.api.static import PLOTLY_URL
from actuator_selection.core.money import ROUNDING_RULE
from actuator_selection.core.sales import QuoteRecord
from actuator_selection.schemas.quotes import (
    QuoteOut,
    StoredCandidate,
    StoredCheck,
    StoredSelection,
    cycle_facts,
)

DOCUMENT_SCRIPT_PATH = "/quote-document.js"
"""Route (under /api/v1) of the script that draws the figure from the page's JSON."""

DOCUMENT_SCRIPT = """\
// Draws the quote document's speed/torque diagram from its embedded JSON.
(function () {
  var data = document.getElementById("figure-data");
  var target = document.getElementById("speed-torque");
  if (!data || !target || !window.Plotly) return;
  var figure = JSON.parse(data.textContent);
  window.Plotly.newPlot(target, figure.data, figure.layout, {
    staticPlot: true, displayModeBar: false, responsive: false
  }).then(function () { document.documentElement.dataset.figure = "ready"; });
})();
"""

CHECK_TITLES = {
    "max_speed": "Maximum speed n₂ ≤ n_max",
    "inertia_ratio": "Inertia ratio J_L ≤ 3·J_A",
    "peak_torque": "Acceleration torque T₁ ≤ T_max",
    "decel_torque": "Deceleration torque |T₃| ≤ T_max",
    "continuous_duty": "Continuous duty (n_av, T_rms) in zone",
    "thermal_peak": "Winding heating over the cycle ≤ continuous limit",
    "brake_holding": "Holding brake: T_L at standstill ≤ holding torque",
    "drive_current": "Peak motor current ≤ I_max",
    "drive_voltage": "Output voltage with ωL·I ≤ DC bus output",
    "bearing_moment": "Output bearing: tilting moment ≤ allowable",
    "bearing_static_safety": "Output bearing: static safety f_s ≥ required",
    "bearing_life": "Output bearing: L₁₀ life ≥ required",
}
GRID = "#e4e6ea"
STATUS_TEXT = {"pass": "pass", "fail": "FAIL", "warn": "warning", "no_data": "no data"}


def e(value: object) -> str:
    """``value`` as HTML text, every markup character escaped; '—' for None."""
    return "—" if value is None else escape(str(value), quote=True)


def num(value: float | None, unit: str = "") -> str:
    """A measured value for print: 2 decimals from 1 up, 4 significant digits below."""
    if value is None:
        return "—"
    size = abs(value)
    if size >= 1000:
        text = f"{value:,.0f}"
    elif size >= 1 or value == 0:
        text = f"{value:.2f}"
    else:
        text = f"{value:.4g}"
    return e(f"{text} {unit}".strip())


def num_plain(value: object) -> str:
    """A catalogue number as printed there (50, 0.86); '—' when absent."""
    if isinstance(value, int | float) and not isinstance(value, bool):
        return e(f"{value:g}")
    return e(value)


def money(amount: Decimal, currency: str) -> str:
    """``1,234.50 EUR``."""
    return e(f"{amount:,.2f} {currency}")


def script_safe_json(text: str) -> str:
    """JSON text that cannot end the ``<script>`` element holding it.

    ``<`` can only occur inside JSON strings, where ``\\u003c`` means the same.

    >>> script_safe_json('{"name": "</script><b>"}')
    '{"name": "\\\\u003c/script>\\\\u003cb>"}'
    """
    return text.replace("<", "\\u003c")


def _rows(rows: Iterable[tuple[str, str]]) -> str:
    return "".join(f"<tr><th scope='row'>{k}</th><td>{v}</td></tr>" for k, v in rows)


def _check_row(c: StoredCheck) -> str:
    """One row of the checks table; the message only where the check did not pass."""
    message = f"<div class='small muted'>{e(c.summary)}</div>" if c.status != "pass" else ""
    approximate = " (approx.)" if c.approximate else ""
    return (
        f"<tr data-check='{e(c.name)}'><td>{e(CHECK_TITLES.get(c.name, c.name))}{message}</td>"
        f"<td class='status-{e(c.status)}'>{e(STATUS_TEXT.get(c.status, c.status))}"
        f"{approximate}</td><td class='num'>{num(c.value, c.unit)}</td>"
        f"<td class='num'>{num(c.limit, c.unit)}</td>"
        f"<td class='num'>{num(c.margin_percent, '%')}</td><td>{e(c.reference)}</td></tr>"
    )


def _check(checks: Iterable[StoredCheck], name: str) -> StoredCheck | None:
    return next((c for c in checks if c.name == name), None)


def speed_torque_figure(
    candidate: StoredCandidate, selection: StoredSelection, actuator: Mapping[str, Any]
) -> go.Figure:
    """The speed/torque diagram (Fig. 517.1 style) of the quoted actuator and load case.

    Limits come from the candidate's checks (n_max, T_max, the continuous limit),
    the zone edge from the actuator's catalogue entry as quoted, the operating
    points from the candidate's torques and the selection's speeds.
    """
    checks = candidate.checks
    n_max_check = _check(checks, "max_speed")
    n_max = n_max_check.limit if n_max_check else None
    t_max_check = _check(checks, "peak_torque")
    t_max = t_max_check.limit if t_max_check else None
    continuous = _check(checks, "continuous_duty")
    n2 = selection.load.speed_rpm
    n_av = selection.mean_speed_rpm
    fig = go.Figure()
    zone = actuator.get("continuous_duty_zone")
    if zone:
        xs = [p["speed_rpm"] for p in zone]
        ys = [p["torque_nm"] for p in zone]
        fig.add_trace(
            go.Scatter(
                x=[0, *xs, xs[-1]],
                y=[0, *ys, 0],
                fill="toself",
                mode="lines",
                name="continuous-duty zone",
                line={"color": "#2e8b57"},
                fillcolor="rgba(46,139,87,0.22)",
            )
        )
    elif continuous is not None and continuous.limit is not None and continuous.approximate:
        edge_speed = n_max or n_av
        fig.add_trace(
            go.Scatter(
                x=[0, 0, edge_speed, edge_speed, 0],
                y=[0, continuous.limit, continuous.limit, 0, 0],
                fill="toself",
                mode="lines",
                name="continuous limit (approximate)",
                line={"color": "#2e8b57", "dash": "dash"},
                fillcolor="rgba(46,139,87,0.15)",
            )
        )
    if t_max is not None:
        fig.add_trace(
            go.Scatter(
                x=[0, n_max or n2],
                y=[t_max, t_max],
                mode="lines",
                name=f"T_max = {t_max:g} Nm",
                line={"color": "#444", "width": 2},
            )
        )
    if n_max is not None:
        fig.add_trace(
            go.Scatter(
                x=[n_max, n_max],
                y=[0, t_max or 0],
                mode="lines",
                name=f"n_max = {n_max:g} rpm",
                line={"color": "#444", "width": 2, "dash": "dot"},
            )
        )
    t3 = candidate.decel_torque_nm
    points = [
        ("T₁ (acceleration)", n2, candidate.accel_torque_nm, "#b3471d", "triangle-up", "top right"),
        (
            "|T₃| (deceleration)",
            n2,
            abs(t3) if t3 is not None else None,
            "#c0262d",
            "triangle-down",
            "bottom right",
        ),
        ("T_rms at n_av", n_av, candidate.rms_torque_nm, "#6b4fa0", "circle", "top right"),
    ]
    tops = [y for _, _, y, _, _, _ in points]
    for label, x, y, color, symbol, position in points:
        if y is None:
            continue
        fig.add_trace(
            go.Scatter(
                x=[x],
                y=[y],
                mode="markers+text",
                name=label,
                text=[f"{y:.1f} Nm"],
                textposition=position,
                marker={"color": color, "size": 11, "symbol": symbol},
            )
        )
    fig.update_layout(
        template="none",
        width=640,
        height=280,
        margin={"l": 56, "r": 8, "t": 12, "b": 44},
        font={"family": "system-ui, 'Segoe UI', Roboto, sans-serif", "size": 11},
        xaxis={
            "title": {"text": "output speed n [rpm]"},
            "range": [0, 1.1 * max(n_max or 0, n2)],
            "gridcolor": GRID,
        },
        yaxis={
            "title": {"text": "output torque T [Nm]"},
            "range": [0, 1.15 * max([t for t in (t_max, *tops) if t is not None] or [1])],
            "gridcolor": GRID,
        },
        legend={"orientation": "v", "x": 1.02, "xanchor": "left", "y": 1, "yanchor": "top"},
        showlegend=True,
    )
    return fig


_PAGE = Template(
    """<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>Quote $number</title>
<link rel="icon" href="data:,">
<style>
@page { size: A4; margin: 14mm 15mm 14mm 15mm; }
* { box-sizing: border-box; }
html { color: #1b1f24; background: #eef0f3; }
body { font: 10.5pt/1.4 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; margin: 0; }
.sheet { background: #fff; width: 210mm; min-height: 297mm; margin: 12px auto; padding: 16mm 15mm;
         box-shadow: 0 1px 6px rgba(0,0,0,.15); }
h1 { font-size: 20pt; margin: 0 0 2mm; letter-spacing: .02em; }
h2 { font-size: 13pt; margin: 7mm 0 2mm; border-bottom: 1.5px solid #1b1f24; padding-bottom: 1mm; }
h3 { font-size: 11pt; margin: 4mm 0 1.5mm; }
.head { display: flex; justify-content: space-between; gap: 10mm; align-items: flex-start; }
.meta th { text-align: left; font-weight: 600; padding-right: 4mm; white-space: nowrap; }
.meta td { white-space: nowrap; }
.meta td, .meta th { padding: .4mm 0; vertical-align: top; }
.customer { white-space: pre-line; }
.muted { color: #555; }
.small { font-size: 8.5pt; }
.banner { border: 2px solid #c0262d; background: #fdecea; color: #7d1419; padding: 3mm 4mm;
          margin: 4mm 0; font-weight: 600; }
.banner.warn { border-color: #a67c00; background: #fff6d6; color: #5c4500; }
.banner ul { margin: 1mm 0 0 5mm; padding: 0; font-weight: 400; }
table.lines, table.checks, table.facts { width: 100%; border-collapse: collapse; }
table.lines th, table.lines td, table.checks th, table.checks td { padding: 1.3mm 2mm;
      border-bottom: .5px solid #c8ccd2; vertical-align: top; text-align: left; }
table.lines thead th, table.checks thead th { border-bottom: 1.5px solid #1b1f24;
      font-weight: 600; }
table.checks td:nth-child(2), table.checks td:nth-child(6) { white-space: nowrap; }
.num { text-align: right !important; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.lines tfoot td { border-bottom: none; }
table.lines tfoot tr.total td { border-top: 1.5px solid #1b1f24; font-weight: 700;
      font-size: 11.5pt; }
table.facts th { text-align: left; font-weight: 500; color: #333; padding: .5mm 4mm .5mm 0;
      width: 45%; }
table.facts td { padding: .5mm 0; font-variant-numeric: tabular-nums; }
.cols { display: grid; grid-template-columns: 1fr 1fr; gap: 8mm; }
.status-pass { color: #1e7b3c; font-weight: 600; }
.status-fail { color: #c0262d; font-weight: 700; }
.status-warn, .status-no_data { color: #7a6a00; font-weight: 600; }
#speed-torque { width: 640px; height: 280px; margin: 1mm auto 0; }
.justification { font-size: 9pt; line-height: 1.3; }
.justification h3 { font-size: 10pt; margin: 3mm 0 1mm; }
.justification .small { font-size: 7.5pt; }
.justification table.checks td, .justification table.checks th { padding: .8mm 1.5mm; }
.justification { break-before: page; page-break-before: always; }
.keep { break-inside: avoid; page-break-inside: avoid; }
footer { margin-top: 3mm; border-top: .5px solid #c8ccd2; padding-top: 1.5mm; }
.justification h2 { margin-top: 0; }
.justification p { margin: 1mm 0; }
@media print {
  html, body { background: #fff; }
  .sheet { width: auto; min-height: 0; margin: 0; padding: 0; box-shadow: none; }
  .screen-only { display: none; }
  a { color: inherit; text-decoration: none; }
}
@media screen {
  .justification { border-top: 1px dashed #c8ccd2; padding-top: 6mm; margin-top: 10mm; }
}
</style>
</head>
<body>
<main class="sheet">
<p class="screen-only small muted">Print this page (Ctrl+P) to A4 or to PDF;
the layout is made for it.</p>
$example_banner
<div class="head">
  <div>
    <h1>Quotation</h1>
    <div class="muted">Harmonic Drive servo actuator, sized by the actuator selection service</div>
  </div>
  <table class="meta" aria-label="quote details">
    <tr><th scope="row">Quote no.</th><td data-field="number">$number</td></tr>
    <tr><th scope="row">Date</th><td>$date</td></tr>
    <tr><th scope="row">Valid until</th><td>$valid_until</td></tr>
    <tr><th scope="row">Status</th><td data-field="status">$status</td></tr>
  </table>
</div>
<h2>Customer</h2>
<div class="cols">
  <div class="customer" data-field="customer">$customer</div>
  <table class="meta">$customer_reference</table>
</div>
$unconfirmed_banner
<h2>Items</h2>
<table class="lines">
<thead><tr><th>Pos.</th><th>Item</th><th>Description</th><th class="num">Qty</th>
<th class="num">Unit price</th><th class="num">Amount</th></tr></thead>
<tbody>$lines</tbody>
<tfoot>
<tr><td colspan="5" class="num">Subtotal</td>
<td class="num" data-field="subtotal">$subtotal</td></tr>
<tr><td colspan="5" class="num">Discount $discount_percent %</td>
<td class="num" data-field="discount">− $discount_amount</td></tr>
<tr class="total"><td colspan="5" class="num">Total ($currency, excluding taxes)</td>
<td class="num" data-field="total">$total</td></tr>
</tfoot>
</table>
<p class="small muted">Prices from the price list “$price_list”, valid on $price_date.
Rounding: $rounding.</p>
$notes
<section class="justification" aria-labelledby="why">
<h2 id="why">Engineering justification</h2>
<p>$model for the load case below, by <em>Engineering Data for Harmonic Drive Servo
Actuators</em>. Verdict: <strong data-field="verdict">$verdict</strong>.</p>
<div class="cols keep">
  <div><h3>Load (at the actuator output)</h3><table class="facts">$load</table>
  <h3>Torques (Eq. 514.1, 514.2)</h3><table class="facts">$torques</table></div>
  <div><h3>Cycle (Fig. 516.2)</h3><table class="facts">$cycle</table>
  <h3>Catalogue data used</h3><table class="facts">$catalogue</table></div>
</div>
<div class="keep">
<h3>Checks of the selection flowchart</h3>
<table class="checks">
<thead><tr><th>Check</th><th>Result</th><th class="num">Value</th><th class="num">Limit</th>
<th class="num">Margin</th><th>Reference</th></tr></thead>
<tbody>$checks</tbody>
</table>
</div>
<div class="keep">
<h3>Speed/torque diagram</h3>
<div id="speed-torque" role="img"
 aria-label="speed/torque diagram of $model with the operating points"></div>
<script type="application/json" id="figure-data">$figure</script>
</div>
<footer class="small muted">
Catalogue data: $catalogue_source.<br>
Selection $selection_id of $selection_date, made with catalogue version $selection_version;
catalogue version $quote_version when this quote was made.$version_note
Figures are those computed by the service and stored with the selection;
they do not change afterwards.
</footer>
</section>
</main>
<script src="$plotly_url"></script>
<script src="$document_script"></script>
</body>
</html>
"""
)


def render_quote_document(
    quote: QuoteOut, *, selection: StoredSelection | None, record: QuoteRecord
) -> str:
    """The HTML document of ``quote``; every text from outside is escaped."""
    candidate = (
        next((c for c in selection.candidates if c.model == quote.actuator_model), None)
        if selection is not None
        else None
    )
    actuator = record.actuator_snapshot
    example_banner = (
        "<div class='banner' data-field='example-prices'>EXAMPLE PRICES — not real prices. "
        f"The price list “{e(quote.price_list.name)}” holds invented figures for trying the "
        "service out; do not send this document to a customer.</div>"
        if quote.price_list.is_example
        else ""
    )
    unconfirmed_banner = (
        "<div class='banner warn' data-field='unconfirmed'>Suitability unconfirmed: "
        "no check failed, but these could not be made for lack of published data:<ul>"
        + "".join(f"<li>{e(reason)}</li>" for reason in quote.verdict_reasons)
        + "</ul></div>"
        if quote.unconfirmed
        else ""
    )
    lines = "".join(
        f"<tr><td>{item.position}</td><td>{e(item.item_code)}</td><td>{e(item.description)}</td>"
        f"<td class='num'>{item.quantity}</td>"
        f"<td class='num'>{money(item.unit_price, quote.currency)}</td>"
        f"<td class='num'>{money(item.line_total, quote.currency)}</td></tr>"
        for item in quote.items
    )
    customer = e(quote.customer.name) + (
        "\n" + e(quote.customer.address) if quote.customer.address else ""
    )
    reference = (
        _rows([("Your reference", e(quote.customer.reference))]) if quote.customer.reference else ""
    )
    notes = f"<h2>Notes</h2><p class='customer'>{e(quote.notes)}</p>" if quote.notes else ""
    load_rows: list[tuple[str, str]] = []
    cycle_rows: list[tuple[str, str]] = []
    torque_rows: list[tuple[str, str]] = []
    check_rows = ""
    figure_json = "null"
    selection_date = "—"
    if selection is not None:
        load = selection.load
        load_rows = [
            ("Load speed n₂", num(load.speed_rpm, "rpm")),
            ("Load torque T_L", num(load.torque_nm, "Nm")),
            ("Load inertia J_L", num(load.inertia_kgm2, "kgm²")),
            ("J_L ≤ 3·J_A binding (high dynamics)", "yes" if selection.high_dynamics else "no"),
        ]
        if selection.mechanism:
            load_rows.append(
                (
                    "Mechanism (as entered)",
                    e(", ".join(f"{k} = {v}" for k, v in selection.mechanism.items())),
                )
            )
        cycle_rows = [
            (e(label[0].upper() + label[1:]), num(value, unit))
            for _, label, value, unit in cycle_facts(selection.cycle, selection.segments)
        ] + [
            ("Cycle time t₀", num(selection.cycle_time_s, "s")),
            ("Mean speed n_av (Eq. 514.3)", num(selection.mean_speed_rpm, "rpm")),
            ("Duty cycle ED (Eq. 514.4)", num(selection.duty_cycle_percent, "%")),
        ]
        selection_date = e(selection.created_at.strftime("%Y-%m-%d %H:%M UTC"))
    if candidate is not None and selection is not None:
        torque_rows = [
            ("Acceleration T₁", num(candidate.accel_torque_nm, "Nm")),
            ("Constant speed T₂", num(candidate.constant_torque_nm, "Nm")),
            ("Deceleration T₃", num(candidate.decel_torque_nm, "Nm")),
            ("RMS T_rms", num(candidate.rms_torque_nm, "Nm")),
        ]
        check_rows = "".join(_check_row(c) for c in candidate.checks)
        figure_json = script_safe_json(
            speed_torque_figure(candidate, selection, actuator).to_json()
        )
    catalogue_rows = [
        (
            "Family, gear ratio",
            f"{e(actuator.get('family'))}, i = {num_plain(actuator.get('gear_ratio'))}",
        ),
        ("Peak torque T_max", num(actuator.get("max_torque_nm"), "Nm")),
        ("Max. speed n_max", num(actuator.get("max_speed_rpm"), "rpm")),
        ("Inertia J_A", num(actuator.get("inertia_kgm2"), "kgm²")),
        ("Stall torque T₀", num(actuator.get("stall_torque_nm"), "Nm")),
    ]
    version_note = (
        f" The catalogue changed between selection and quote "
        f"(v{quote.selection_catalogue_version} → v{quote.catalogue_version}); the "
        "justification shows the selection's figures."
        if quote.selection_catalogue_version != quote.catalogue_version
        else ""
    )
    return _PAGE.substitute(
        number=e(quote.number),
        date=e(quote.created_at.strftime("%Y-%m-%d")),
        valid_until=e(quote.valid_until.isoformat()),
        status=e(quote.status.value),
        customer=customer,
        customer_reference=reference,
        example_banner=example_banner,
        unconfirmed_banner=unconfirmed_banner,
        lines=lines,
        subtotal=money(quote.subtotal, quote.currency),
        discount_percent=e(f"{quote.discount_percent.normalize():f}"),
        discount_amount=money(quote.discount_amount, quote.currency),
        currency=e(quote.currency),
        total=money(quote.total, quote.currency),
        price_list=e(quote.price_list.name),
        price_date=e(quote.price_list.priced_on.isoformat()),
        rounding=e(ROUNDING_RULE),
        notes=notes,
        model=e(quote.actuator_model),
        verdict=e(quote.verdict),
        load=_rows(load_rows),
        cycle=_rows(cycle_rows),
        torques=_rows(torque_rows),
        catalogue=_rows(catalogue_rows),
        checks=check_rows,
        figure=figure_json,
        selection_id=e(quote.selection_id),
        selection_date=selection_date,
        selection_version=e(quote.selection_catalogue_version),
        quote_version=e(quote.catalogue_version),
        version_note=version_note,
        catalogue_source=e(actuator.get("source")),
        plotly_url=e(PLOTLY_URL),
        document_script=e("/api/v1" + DOCUMENT_SCRIPT_PATH),
    )
