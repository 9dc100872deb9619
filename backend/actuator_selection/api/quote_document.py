"""The printable quote: HTML laid out for A4, with the engineering that justifies the offer.

In English or German (``api/quote_document_text.py``: every label from one table,
numbers, money and dates formatted by Babel for the locale); the seller block, net,
VAT and gross totals, payment, delivery and validity terms, and page numbers in print.

Built by hand with :func:`html.escape` on every value (Jinja2 is not installed
and not needed): customer text can hold anything and must never become markup.
The speed/torque diagram is a plotly figure built here with
``plotly.graph_objects`` and drawn in the browser by the app's own plotly.js
(``PLOTLY_URL``) through a small script of this module; no CDN, no inline code.

Every number comes from the stored quote and the stored selection (immutable),
plus the actuator's catalogue entry as copied into the quote when it was made.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from decimal import Decimal
from html import escape
from string import Template
from typing import Any

import plotly.graph_objects as go

from actuator_selection.api.quote_document_text import TEXT, DocumentText, Language
from actuator_selection.api.static import PLOTLY_URL
from actuator_selection.core.quote_terms import SellerParty
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

GRID = "#e4e6ea"
ENGLISH = DocumentText("en")


def e(value: object) -> str:
    """``value`` as HTML text, every markup character escaped; '—' for None."""
    return "—" if value is None else escape(str(value), quote=True)


def num(value: float | None, unit: str = "", t: DocumentText = ENGLISH) -> str:
    """A measured value for print: 2 decimals from 1 up, 4 significant digits below."""
    if value is None:
        return "—"
    size = abs(value)
    if size >= 1000:
        text = t.number(value, "#,##0")
    elif size >= 1 or value == 0:
        text = t.number(value, "#,##0.00")
    else:
        text = t.number(value, "@###")
    return e(f"{text} {t.unit(unit)}".strip())


def num_plain(value: object, t: DocumentText = ENGLISH) -> str:
    """A catalogue number as printed there (50, 0.86); '—' when absent."""
    if isinstance(value, int | float) and not isinstance(value, bool):
        return e(t.number(value, "#,##0.######"))
    return e(value)


def money(amount: Decimal, currency: str, t: DocumentText = ENGLISH) -> str:
    """``1,234.50 EUR`` (``1.234,50 EUR`` in German)."""
    return e(t.money(amount, currency))


def script_safe_json(text: str) -> str:
    """JSON text that cannot end the ``<script>`` element holding it.

    ``<`` can only occur inside JSON strings, where ``\\u003c`` means the same.

    >>> script_safe_json('{"name": "</script><b>"}')
    '{"name": "\\\\u003c/script>\\\\u003cb>"}'
    """
    return text.replace("<", "\\u003c")


def _rows(rows: Iterable[tuple[str, str]]) -> str:
    return "".join(f"<tr><th scope='row'>{k}</th><td>{v}</td></tr>" for k, v in rows)


def _label(t: DocumentText, key: str, fallback: str) -> str:
    """The label ``key`` if the table has it, else ``fallback`` (a name added later)."""
    return t(key) if key in TEXT else fallback


_SEGMENT_FACT = re.compile(r"segment_(\d+)_(duration_s|start_rpm|end_rpm)")
_CYCLE_FACTS = {
    "accel_s": "accel_time",
    "constant_s": "constant_time",
    "decel_s": "decel_time",
    "pause_s": "pause_time",
}


def _cycle_label(t: DocumentText, key: str, label: str) -> str:
    """The label of a cycle fact (``schemas.quotes.cycle_facts``) in the document's language."""
    if key in _CYCLE_FACTS:
        return t(_CYCLE_FACTS[key])
    if (match := _SEGMENT_FACT.fullmatch(key)) is not None:
        return t(f"segment_{match.group(2)}", k=match.group(1))
    return label[:1].upper() + label[1:]


def _check_row(c: StoredCheck, t: DocumentText) -> str:
    """One row of the checks table; the message only where the check did not pass."""
    message = f"<div class='small muted'>{e(c.summary)}</div>" if c.status != "pass" else ""
    approximate = t("approximate") if c.approximate else ""
    return (
        f"<tr data-check='{e(c.name)}'><td>{e(_label(t, 'check_' + c.name, c.name))}{message}"
        f"</td><td class='status-{e(c.status)}'>{e(_label(t, 'result_' + c.status, c.status))}"
        f"{e(approximate)}</td><td class='num'>{num(c.value, c.unit, t)}</td>"
        f"<td class='num'>{num(c.limit, c.unit, t)}</td>"
        f"<td class='num'>{num(c.margin_percent, '%', t)}</td>"
        f"<td>{e(t.reference(c.reference))}</td></tr>"
    )


def _check(checks: Iterable[StoredCheck], name: str) -> StoredCheck | None:
    return next((c for c in checks if c.name == name), None)


def speed_torque_figure(
    candidate: StoredCandidate,
    selection: StoredSelection,
    actuator: Mapping[str, Any],
    t: DocumentText = ENGLISH,
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
                name=t("zone"),
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
                name=t("zone_approximate"),
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
                name=f"T_max = {t.number(t_max, '#,##0.###')} Nm",
                line={"color": "#444", "width": 2},
            )
        )
    if n_max is not None:
        fig.add_trace(
            go.Scatter(
                x=[n_max, n_max],
                y=[0, t_max or 0],
                mode="lines",
                name=f"n_max = {t.number(n_max, '#,##0.###')} {t.unit('rpm')}",
                line={"color": "#444", "width": 2, "dash": "dot"},
            )
        )
    t3 = candidate.decel_torque_nm
    points = [
        (t("point_accel"), n2, candidate.accel_torque_nm, "#b3471d", "triangle-up", "top right"),
        (
            t("point_decel"),
            n2,
            abs(t3) if t3 is not None else None,
            "#c0262d",
            "triangle-down",
            "bottom right",
        ),
        (t("point_rms"), n_av, candidate.rms_torque_nm, "#6b4fa0", "circle", "top right"),
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
                text=[f"{t.number(y, '#,##0.0')} Nm"],
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
            "title": {"text": t("axis_speed", rpm=t.unit("rpm"))},
            "range": [0, 1.1 * max(n_max or 0, n2)],
            "gridcolor": GRID,
        },
        yaxis={
            "title": {"text": t("axis_torque")},
            "range": [0, 1.15 * max([t for t in (t_max, *tops) if t is not None] or [1])],
            "gridcolor": GRID,
        },
        legend={"orientation": "v", "x": 1.02, "xanchor": "left", "y": 1, "yanchor": "top"},
        showlegend=True,
        # Plotly's own number formatting (axis ticks) in the document's locale.
        separators=t.number(1000.5, "#,##0.0")[-2] + t.number(1000.5, "#,##0.0")[1],
    )
    return fig


_PAGE = Template(
    """<!doctype html>
<html lang="$lang">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>$title</title>
<link rel="icon" href="data:,">
<style>
@page { size: A4; margin: 14mm 15mm 16mm 15mm;
  @bottom-right { content: "$page_label " counter(page) " $of_label " counter(pages);
                  font: 8pt system-ui, sans-serif; color: #555; } }
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
.customer, .address, .terms { white-space: pre-line; }
.parties { display: grid; grid-template-columns: 1fr 1fr; gap: 8mm; }
table.totals td { padding: 1mm 2mm; }
table.terms-table th { text-align: left; font-weight: 600; padding: .6mm 4mm .6mm 0;
      vertical-align: top; white-space: nowrap; width: 30%; }
table.terms-table td { padding: .6mm 0; vertical-align: top; }
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
<p class="screen-only small muted">$print_hint</p>
$example_banner$placeholder_banner
<div class="head">
  <div>
    <h1>$heading</h1>
    <div class="muted">$subtitle</div>
  </div>
  <table class="meta" aria-label="$quote_details">
    <tr><th scope="row">$l_number</th><td data-field="number">$number</td></tr>
    <tr><th scope="row">$l_date</th><td data-field="date">$date</td></tr>
    <tr><th scope="row">$l_valid_until</th><td data-field="valid-until">$valid_until</td></tr>
    <tr><th scope="row">$l_status</th><td data-field="status">$status</td></tr>
  </table>
</div>
<div class="parties">
  <section aria-labelledby="seller-heading">
    <h2 id="seller-heading">$l_seller</h2>
    <div data-field="seller"><strong>$seller_name</strong>
    <div class="address">$seller_address</div>
    <table class="meta">$seller_rows</table></div>
  </section>
  <section aria-labelledby="customer-heading">
    <h2 id="customer-heading">$l_customer</h2>
    <div class="customer" data-field="customer">$customer</div>
    <table class="meta">$customer_reference</table>
  </section>
</div>
$unconfirmed_banner
<h2>$l_items</h2>
<table class="lines">
<thead><tr><th>$col_position</th><th>$col_item</th><th>$col_description</th>
<th class="num">$col_quantity</th><th class="num">$col_unit_price</th>
<th class="num">$col_amount</th></tr></thead>
<tbody>$lines</tbody>
<tfoot>
<tr><td colspan="5" class="num">$l_subtotal</td>
<td class="num" data-field="subtotal">$subtotal</td></tr>
<tr><td colspan="5" class="num">$l_discount</td>
<td class="num" data-field="discount">− $discount_amount</td></tr>
$total_rows
</tfoot>
</table>
<p class="small muted">$prices_from
$rounding</p>
<h2>$l_terms</h2>
<table class="terms-table">
<tr><th scope="row">$l_payment_terms</th>
<td class="terms" data-field="payment-terms">$payment_terms</td></tr>
<tr><th scope="row">$l_delivery_terms</th>
<td class="terms" data-field="delivery-terms">$delivery_terms</td></tr>
<tr><th scope="row">$l_validity</th><td data-field="validity">$validity</td></tr>
</table>
$notes
<section class="justification" aria-labelledby="why">
<h2 id="why">$l_justification</h2>
<p>$justification_intro</p>
<div class="cols keep">
  <div><h3>$l_load</h3><table class="facts">$load</table>
  <h3>$l_torques</h3><table class="facts">$torques</table></div>
  <div><h3>$l_cycle</h3><table class="facts">$cycle</table>
  <h3>$l_catalogue</h3><table class="facts">$catalogue</table></div>
</div>
<div class="keep">
<h3>$l_checks</h3>
<table class="checks">
<thead><tr><th>$col_check</th><th>$col_result</th><th class="num">$col_value</th>
<th class="num">$col_limit</th><th class="num">$col_margin</th><th>$col_reference</th></tr></thead>
<tbody>$checks</tbody>
</table>
</div>
<div class="keep">
<h3>$l_diagram</h3>
<div id="speed-torque" role="img" aria-label="$diagram_label"></div>
<script type="application/json" id="figure-data">$figure</script>
</div>
<footer class="small muted">
$catalogue_source<br>
$selection_footer$version_note
$figures_fixed
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
    quote: QuoteOut,
    *,
    selection: StoredSelection | None,
    record: QuoteRecord,
    language: Language = "en",
    current_seller: SellerParty,
    placeholder_seller_name: str | None = None,
) -> str:
    """The HTML document of ``quote`` in ``language``; every text from outside is escaped.

    ``current_seller`` (the settings' seller) stands in for the seller of a quote made
    before quotes stored theirs. A seller named ``placeholder_seller_name`` (the
    settings' default) is flagged with a banner.
    """
    t = DocumentText(language)
    candidate = (
        next((c for c in selection.candidates if c.model == quote.actuator_model), None)
        if selection is not None
        else None
    )
    actuator = record.actuator_snapshot
    seller = record.seller or current_seller
    example_banner = (
        f"<div class='banner' data-field='example-prices'>"
        f"{e(t('example_banner', name=quote.price_list.name))}</div>"
        if quote.price_list.is_example
        else ""
    )
    placeholder_banner = (
        f"<div class='banner' data-field='placeholder-seller'>{e(t('placeholder_seller'))}</div>"
        if placeholder_seller_name is not None and seller.name == placeholder_seller_name
        else ""
    )
    unconfirmed_banner = (
        f"<div class='banner warn' data-field='unconfirmed'>{e(t('unconfirmed_banner'))}<ul>"
        + "".join(f"<li>{e(reason)}</li>" for reason in quote.verdict_reasons)
        + "</ul></div>"
        if quote.unconfirmed
        else ""
    )
    lines = "".join(
        f"<tr><td>{item.position}</td><td>{e(item.item_code)}</td><td>{e(item.description)}</td>"
        f"<td class='num'>{e(t.number(item.quantity, '#,##0'))}</td>"
        f"<td class='num'>{money(item.unit_price, quote.currency, t)}</td>"
        f"<td class='num'>{money(item.line_total, quote.currency, t)}</td></tr>"
        for item in quote.items
    )
    currency = quote.currency
    if record.tax is not None:
        tax = record.tax
        total_rows = (
            f"<tr class='net'><td colspan='5' class='num'>{e(t('net_total'))}</td>"
            f"<td class='num' data-field='total'>{money(tax.net, currency, t)}</td></tr>"
            f"<tr><td colspan='5' class='num'>"
            f"{e(t('vat', percent=t.percent(tax.vat_percent)))}</td>"
            f"<td class='num' data-field='vat'>{money(tax.vat_amount, currency, t)}</td></tr>"
            f"<tr class='total'><td colspan='5' class='num'>"
            f"{e(t('gross_total', currency=currency))}</td>"
            f"<td class='num' data-field='gross'>{money(tax.gross, currency, t)}</td></tr>"
        )
        rounding = f"{t('rounding')} {t('vat_rounding')}"
    else:
        # A quote made before VAT was stated: net only, as it was sent.
        total_rows = (
            f"<tr class='total'><td colspan='5' class='num'>"
            f"{e(t('total_no_tax', currency=currency))}</td>"
            f"<td class='num' data-field='total'>{money(quote.total, currency, t)}</td></tr>"
        )
        rounding = t("rounding")
    seller_rows = [(e(t("vat_id")), f"<span data-field='seller-vat-id'>{e(seller.vat_id)}</span>")]
    seller_rows.append((e(t("email")), e(seller.email)))
    if seller.phone:
        seller_rows.append((e(t("phone")), e(seller.phone)))
    payment_terms = record.payment_terms or seller.standard_terms("payment", language)
    delivery_terms = record.delivery_terms or seller.standard_terms("delivery", language)
    customer = e(quote.customer.name) + (
        "\n" + e(quote.customer.address) if quote.customer.address else ""
    )
    reference = (
        _rows([(e(t("your_reference")), e(quote.customer.reference))])
        if quote.customer.reference
        else ""
    )
    notes = (
        f"<h2>{e(t('notes'))}</h2><p class='customer'>{e(quote.notes)}</p>" if quote.notes else ""
    )
    load_rows: list[tuple[str, str]] = []
    cycle_rows: list[tuple[str, str]] = []
    torque_rows: list[tuple[str, str]] = []
    check_rows = ""
    figure_json = "null"
    selection_date = "—"
    if selection is not None:
        load = selection.load
        load_rows = [
            (e(t("load_speed")), num(load.speed_rpm, "rpm", t)),
            (e(t("load_torque")), num(load.torque_nm, "Nm", t)),
            (e(t("load_inertia")), num(load.inertia_kgm2, "kgm²", t)),
            (e(t("high_dynamics")), e(t("yes" if selection.high_dynamics else "no"))),
        ]
        if selection.mechanism:
            load_rows.append(
                (
                    e(t("mechanism")),
                    e(", ".join(f"{k} = {v}" for k, v in selection.mechanism.items())),
                )
            )
        cycle_rows = [
            (e(_cycle_label(t, key, label)), num(value, unit, t))
            for key, label, value, unit in cycle_facts(selection.cycle, selection.segments)
        ] + [
            (e(t("cycle_time")), num(selection.cycle_time_s, "s", t)),
            (e(t("mean_speed")), num(selection.mean_speed_rpm, "rpm", t)),
            (e(t("duty_cycle")), num(selection.duty_cycle_percent, "%", t)),
        ]
        created = selection.created_at
        selection_date = f"{t.date(created.date())} {created.strftime('%H:%M')} UTC"
    if candidate is not None and selection is not None:
        torque_rows = [
            (e(t("accel_torque")), num(candidate.accel_torque_nm, "Nm", t)),
            (e(t("constant_torque")), num(candidate.constant_torque_nm, "Nm", t)),
            (e(t("decel_torque")), num(candidate.decel_torque_nm, "Nm", t)),
            (e(t("rms_torque")), num(candidate.rms_torque_nm, "Nm", t)),
        ]
        check_rows = "".join(_check_row(c, t) for c in candidate.checks)
        figure_json = script_safe_json(
            speed_torque_figure(candidate, selection, actuator, t).to_json()
        )
    catalogue_rows = [
        (
            e(t("family_ratio")),
            f"{e(actuator.get('family'))}, i = {num_plain(actuator.get('gear_ratio'), t)}",
        ),
        (e(t("max_torque")), num(actuator.get("max_torque_nm"), "Nm", t)),
        (e(t("max_speed")), num(actuator.get("max_speed_rpm"), "rpm", t)),
        (e(t("inertia")), num(actuator.get("inertia_kgm2"), "kgm²", t)),
        (e(t("stall_torque")), num(actuator.get("stall_torque_nm"), "Nm", t)),
    ]
    version_note = (
        t("version_note", old=quote.selection_catalogue_version, new=quote.catalogue_version)
        if quote.selection_catalogue_version != quote.catalogue_version
        else ""
    )
    verdict = t("verdict_suitable" if quote.verdict == "suitable" else "verdict_unconfirmed")
    labels = {
        f"l_{key}": e(t(key))
        for key in (
            "number",
            "date",
            "valid_until",
            "status",
            "seller",
            "customer",
            "items",
            "subtotal",
            "terms",
            "payment_terms",
            "delivery_terms",
            "validity",
            "justification",
        )
    }
    columns = {
        key: e(t(key))
        for key in (
            "col_position",
            "col_item",
            "col_description",
            "col_quantity",
            "col_unit_price",
            "col_amount",
            "col_check",
            "col_result",
            "col_value",
            "col_limit",
            "col_margin",
            "col_reference",
        )
    }
    return _PAGE.substitute(
        labels,
        **columns,
        lang=language,
        title=e(t("title", number=quote.number)),
        print_hint=e(t("print_hint")),
        page_label=e(t("page")),
        of_label=e(t("of")),
        heading=e(t("heading")),
        subtitle=e(t("subtitle")),
        quote_details=e(t("quote_details")),
        number=e(quote.number),
        date=e(t.date(quote.created_at.date())),
        valid_until=e(t.date(quote.valid_until)),
        status=e(t(f"status_{quote.status.value}")),
        seller_name=e(seller.name),
        seller_address=e(seller.address),
        seller_rows=_rows(seller_rows),
        customer=customer,
        customer_reference=reference,
        example_banner=example_banner,
        placeholder_banner=placeholder_banner,
        unconfirmed_banner=unconfirmed_banner,
        lines=lines,
        subtotal=money(quote.subtotal, currency, t),
        l_discount=e(t("discount", percent=t.percent(quote.discount_percent))),
        discount_amount=money(quote.discount_amount, currency, t),
        total_rows=total_rows,
        prices_from=e(
            t("prices_from", name=quote.price_list.name, date=t.date(quote.price_list.priced_on))
        ),
        rounding=e(rounding),
        payment_terms=e(payment_terms),
        delivery_terms=e(delivery_terms),
        validity=e(t("validity_text", date=t.date(quote.valid_until))),
        notes=notes,
        justification_intro=t(
            "justification_intro", model=e(quote.actuator_model), verdict=e(verdict)
        ),
        l_load=e(t("load_heading")),
        l_torques=e(t("torques_heading")),
        l_cycle=e(t("cycle_heading")),
        l_catalogue=e(t("catalogue_heading")),
        l_checks=e(t("checks_heading")),
        l_diagram=e(t("diagram_heading")),
        diagram_label=e(t("diagram_label", model=quote.actuator_model)),
        load=_rows(load_rows),
        cycle=_rows(cycle_rows),
        torques=_rows(torque_rows),
        catalogue=_rows(catalogue_rows),
        checks=check_rows,
        figure=figure_json,
        catalogue_source=e(t("catalogue_source", source=actuator.get("source"))),
        selection_footer=e(
            t(
                "selection_footer",
                id=quote.selection_id,
                date=selection_date,
                version=quote.selection_catalogue_version,
                quote_version=quote.catalogue_version,
            )
        ),
        version_note=e(version_note),
        figures_fixed=e(t("figures_fixed")),
        plotly_url=e(PLOTLY_URL),
        document_script=e("/api/v1" + DOCUMENT_SCRIPT_PATH),
    )
