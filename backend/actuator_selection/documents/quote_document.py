"""The printable quote: HTML laid out for A4, with the engineering that justifies the offer.

In English or German (``documents/quote_document_text.py``: every label from the gettext catalogue,
numbers, money and dates formatted by Babel for the locale); the seller block, net,
VAT and gross totals, payment, delivery and validity terms, and page numbers in print.

Rendered from ``documents/templates/quote_document.html`` by Jinja2 with autoescaping:
customer text can hold anything and must never become markup, so every value is
escaped by the template engine, not by hand.
The speed/torque diagram is a plotly figure built here with
``plotly.graph_objects`` and drawn in the browser by the app's own plotly.js (its URL
given by the router, where ``http/static.py`` serves it) through a small script of this
module; no CDN, no inline code.

Every number comes from the stored quote and the stored selection (immutable),
plus the actuator's catalogue entry as copied into the quote when it was made.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterable, Mapping
from decimal import Decimal
from typing import Any

from jinja2 import Environment, PackageLoader, StrictUndefined, select_autoescape
from markupsafe import Markup

from actuator_selection.catalogue.citations import citation
from actuator_selection.documents.figures import DiagramPoints, diagram_figure
from actuator_selection.documents.quote_document_text import DocumentText, Language, load_rows
from actuator_selection.documents.symbols import symbols
from actuator_selection.i18n.localize import render_check
from actuator_selection.sales.money import ROUNDING_RULE
from actuator_selection.sales.quote_terms import VAT_ROUNDING_RULE, SellerParty
from actuator_selection.sales.records import QuoteRecord
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

ENGLISH = DocumentText("en")


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
    return f"{text} {t.unit(unit)}".strip()


def num_plain(value: object, t: DocumentText = ENGLISH) -> str:
    """A catalogue number as printed there (50, 0.86); '—' when absent."""
    if isinstance(value, int | float) and not isinstance(value, bool):
        return t.number(value, "#,##0.######")
    return "—" if value is None else str(value)


def money(amount: Decimal, currency: str, t: DocumentText = ENGLISH) -> str:
    """``1,234.50 EUR`` (``1.234,50 EUR`` in German)."""
    return t.money(amount, currency)


def script_safe_json(text: str) -> str:
    """JSON text that cannot end the ``<script>`` element holding it.

    ``<`` can only occur inside JSON strings, where ``\\u003c`` means the same.

    >>> script_safe_json('{"name": "</script><b>"}')
    '{"name": "\\\\u003c/script>\\\\u003cb>"}'
    """
    return text.replace("<", "\\u003c")


def _label(t: DocumentText, key: str, fallback: str) -> Markup:
    """The label ``key`` if the table has it, else ``fallback`` (a name added later, its
    underscores as spaces), symbols subscripted."""
    return t.words(key) if t.has(key) else symbols(fallback.replace("_", " "))


def margin_text(value: float | None, limit: float | None, t: DocumentText) -> str:
    """A check's margin (limit − value)/limit for print, to 3 significant digits; where the
    value is more than twice its limit, how many times the limit it is (``× 33.3``) instead
    of a margin beyond −100 %.

    >>> margin_text(4.0, 4.2, ENGLISH), margin_text(100.0, 3.0, ENGLISH)
    ('4.76 %', '33.3 × limit')
    """
    if value is None or limit is None or limit <= 0:
        return "—"
    margin = (limit - value) / limit * 100.0
    if margin < -100.0:
        return t("times_limit", factor=t.number(value / limit, "@##"))
    return f"{t.number(margin, '@##')} %"


def _check_row(c: StoredCheck, t: DocumentText, language: Language) -> dict[str, str | None]:
    """One row of the checks table; the message (in ``language``) only where the check did
    not pass."""
    return {
        "name": c.name,
        "label": _label(t, "check." + c.name, c.name),
        "message": t.message(render_check(c.phrase, language)) if c.status != "pass" else None,
        # (a check that does not apply says so in its row; it is no reason: _reasons)
        "status": c.status,
        "status_label": _label(t, "result_" + c.status, c.status),
        "approximate": t("approximate") if c.approximate else "",
        "value": num(c.value, c.unit, t),
        "limit": num(c.limit, c.unit, t),
        "margin": margin_text(c.value, c.limit, t),
        "reference": t.reference(c.reference),
    }


_DATA_PARAMS = frozenset({"name", "source"})
"""Parameters that are data as entered or catalogued (a price list's name, a catalogue
source), marked ``translate="no"``: they stay as written in every language."""


def _with_data(t: DocumentText, key: str, **params: str) -> Markup:
    """The label ``key`` with ``params`` filled in, escaped; the data among them
    (:data:`_DATA_PARAMS`) each in a ``<span translate="no">``."""
    slots = {k: f"\x00{k}\x00" if k in _DATA_PARAMS else v for k, v in params.items()}
    text = Markup.escape(t(key, **slots))
    for k in _DATA_PARAMS & params.keys():
        span = Markup('<span translate="no">{}</span>').format(params[k])
        text = Markup(text.replace(f"\x00{k}\x00", span))
    return text


def _open_checks(checks: Iterable[StoredCheck], t: DocumentText) -> list[Markup]:
    """The checks that did not pass, each its name and its message in ``t``'s language."""
    return [
        _label(t, "check." + c.name, c.name) + ": " + t.message(render_check(c.phrase, t.language))
        for c in checks
        if c.open
    ]


def _on_axis_markup(axis: str, text: Markup, t: DocumentText) -> Markup:
    """``text`` after the project axis it is for (``Axis Z: …``), the axis's name escaped."""
    slot = "\x00"
    return Markup(Markup.escape(t("item_axis", axis=axis, description=slot)).replace(slot, text))


def _reasons(
    quote: QuoteOut, candidate: StoredCandidate | None, record: QuoteRecord, language: Language
) -> list[Markup]:
    """Why the quote is unconfirmed, in ``language``: the quoted candidate's checks that did
    not pass, as the stored selection holds them; a project quote's, each axis's as the
    quote stored them, after the axis (the quote's stored English reasons where the
    selection is gone, or the project was stored before it kept its axes' checks)."""
    t = DocumentText(language)
    if candidate is not None:
        return _open_checks(candidate.checks, t)
    axes = record.axes or ()
    if axes and all("checks" in a for a in axes):
        return [
            _on_axis_markup(a["name"], reason, t)
            for a in axes
            for reason in _open_checks((StoredCheck.model_validate(c) for c in a["checks"]), t)
        ]
    return [t.message(reason) for reason in quote.verdict_reasons]


def _check(checks: Iterable[StoredCheck], name: str) -> StoredCheck | None:
    return next((c for c in checks if c.name == name), None)


def diagram_points(candidate: StoredCandidate, selection: StoredSelection) -> DiagramPoints:
    """What the speed/torque diagram draws of a stored candidate and its selection."""
    return DiagramPoints(
        n2=selection.load.speed_rpm,
        n_av=selection.mean_speed_rpm,
        t1=candidate.accel_torque_nm,
        t3=candidate.decel_torque_nm,
        trms=candidate.rms_torque_nm,
        statuses={c.name: c.status for c in candidate.checks},
    )


def speed_torque_figure(
    candidate: StoredCandidate,
    selection: StoredSelection,
    actuator: Mapping[str, Any] | None,
    t: DocumentText = ENGLISH,
) -> dict[str, Any]:
    """The speed/torque diagram (Fig. 517.1) of a stored candidate as plotly JSON, sized
    for print: the page's figure (``documents/figures.py``), the same definition."""
    figure = diagram_figure(diagram_points(candidate, selection), actuator, t)
    layout = figure["layout"]
    layout.update(width=640, height=280, margin={"l": 56, "r": 8, "t": 12, "b": 44})
    layout["legend"] = {"orientation": "v", "x": 1.02, "xanchor": "left", "y": 1, "yanchor": "top"}
    return figure


_TEMPLATES = Environment(
    loader=PackageLoader("actuator_selection.documents", "templates"),
    autoescape=select_autoescape(["html"], default=True),
    undefined=StrictUndefined,
    trim_blocks=False,
)
"""Jinja2 with autoescaping: every value is HTML-escaped unless it is :class:`Markup`
(the one translation that carries markup, and the figure's script-safe JSON)."""


def render_quote_document(context: dict[str, Any], *, plotly_url: str) -> str:
    """The HTML document of a quote from its content (:func:`quote_document_context`),
    its diagram drawn by the plotly.js at ``plotly_url``; every text from outside is
    escaped (Jinja2 autoescaping)."""
    template = _TEMPLATES.get_template("quote_document.html")
    return template.render(**context, plotly_url=plotly_url)


_ACTUATOR_ITEM = re.compile(
    r"Servo actuator (?P<model>\S+) \((?P<family>.+), gear ratio (?P<ratio>\S+)\)"
)
_CONTROLLER_ITEM = re.compile(
    r"Servo controller (?P<type_name>.+?)"
    r"(?: \((?P<controller>.+), Table 521\.1 row (?P<row>\d+): "
    r"(?P<level>tested|possible|unconfirmed)\))?"
)


def item_description(kind: str, description: str, t: DocumentText) -> tuple[str, bool]:
    """An item's description in the document's language, and whether it is the service's
    own words: the descriptions the service writes (``services/quotes.py``: "Servo actuator
    … (…, gear ratio …)", "Servo controller …") are worded again; a price list's
    description is the seller's data and stays as written.

    >>> item_description("actuator", "Servo actuator CHA-25A-50 (CHA, gear ratio 50)",
    ...     DocumentText("de"))
    ('Servoantrieb CHA-25A-50 (CHA, Untersetzung 50)', True)
    >>> item_description("actuator", "Servo actuator CHA-25A-50 (list price)", DocumentText("de"))
    ('Servo actuator CHA-25A-50 (list price)', False)
    """
    if kind == "actuator" and (m := _ACTUATOR_ITEM.fullmatch(description)):
        return t("item_actuator", **m.groupdict()), True
    if kind == "controller" and (m := _CONTROLLER_ITEM.fullmatch(description)):
        if m["row"] is None:
            return t("item_controller", type_name=m["type_name"]), True
        level = t("level_" + m["level"])
        return t("item_controller_row", **{**m.groupdict(), "level": level}), True
    return description, False


def _on_axis(axis: str | None, description: str, t: DocumentText) -> str:
    """A line's description, after the project axis it is for (a selection's: as it is)."""
    return description if axis is None else t("item_axis", axis=axis, description=description)


def _axes_rows(quote: QuoteOut, t: DocumentText) -> list[dict[str, str]]:
    """A project quote's axes for the document: each axis's actuator, its verdict in the
    project's sizing and its controller (Table 521.1 row and match); none for a selection's."""
    rows = []
    for axis in quote.axes or []:
        c = axis.controller
        rows.append(
            {
                "name": axis.name,
                "model": axis.actuator_model,
                "verdict": t(f"verdict.{axis.verdict}"),
                "controller": "—"
                if c is None
                else t(
                    "axis_controller", name=c.name, row=c.source_row, level=t("level_" + c.level)
                ),
            }
        )
    return rows


def quote_document_context(
    quote: QuoteOut,
    *,
    selection: StoredSelection | None,
    record: QuoteRecord,
    language: Language = "en",
    current_seller: SellerParty,
    placeholder_seller_name: str | None = None,
) -> dict[str, Any]:
    """Everything the quote document shows, worded and formatted in ``language``: the
    template's variables, which the HTML (:func:`render_quote_document`) and the PDF
    (``documents/quote_pdf.py``) both lay out."""
    t = DocumentText(language)
    candidate = (
        next((c for c in selection.candidates if c.model == quote.actuator_model), None)
        if selection is not None
        else None
    )
    actuator = record.actuator_snapshot
    seller = record.seller or current_seller
    currency = quote.currency
    rounding_rule = t("rounding", rule=t.translate(ROUNDING_RULE))
    if record.tax is not None:
        tax = record.tax
        totals = [
            {"cls": "net", "label": t("net_total"), "field": "total",
             "value": money(tax.net, currency, t)},
            {"cls": "", "label": t("vat", percent=t.percent(tax.vat_percent)), "field": "vat",
             "value": money(tax.vat_amount, currency, t)},
            {"cls": "total", "label": t("gross_total", currency=currency), "field": "gross",
             "value": money(tax.gross, currency, t)},
        ]  # fmt: skip
        rounding = f"{rounding_rule} {t.translate(VAT_ROUNDING_RULE)}."
    else:
        # A quote made before VAT was stated: net only, as it was sent.
        totals = [
            {"cls": "total", "label": t("total_no_tax", currency=currency), "field": "total",
             "value": money(quote.total, currency, t)},
        ]  # fmt: skip
        rounding = rounding_rule
    seller_rows = [{"label": t("vat_id"), "value": seller.vat_id, "field": "seller-vat-id"}]
    seller_rows.append({"label": t("email"), "value": seller.email, "field": ""})
    if seller.phone:
        seller_rows.append({"label": t("phone"), "value": seller.phone, "field": ""})
    load_facts: list[tuple[Markup, str]] = []
    cycle_rows: list[tuple[Markup, str]] = []
    torque_rows: list[tuple[Markup, str]] = []
    checks: list[dict[str, str | None]] = []
    figure_json = "null"
    selection_date = "—"
    if selection is not None:
        load = selection.load
        load_facts = [
            (t.words("load_speed"), num(load.speed_rpm, "rpm", t)),
            (t.words("load_torque"), num(load.torque_nm, "Nm", t)),
            (t.words("load_inertia"), num(load.inertia_kgm2, "kgm²", t)),
            (t.words("high_dynamics"), t("yes" if selection.high_dynamics else "no")),
        ]
        if selection.mechanism:
            load_facts += load_rows(t, selection.mechanism)
        cycle_rows = [
            (symbols(t.cycle_label(key, label)), num(value, unit, t))
            for key, label, value, unit in cycle_facts(selection.cycle, selection.segments)
        ] + [
            (t.words("cycle_time"), num(selection.cycle_time_s, "s", t)),
            (t.words("mean_speed"), num(selection.mean_speed_rpm, "rpm", t)),
            (t.words("duty_cycle"), num(selection.duty_cycle_percent, "%", t)),
        ]
        created = selection.created_at
        selection_date = f"{t.date(created.date())} {created.strftime('%H:%M')} UTC"
    if candidate is not None and selection is not None:
        torque_rows = [
            (t.words("accel_torque"), num(candidate.accel_torque_nm, "Nm", t)),
            (t.words("constant_torque"), num(candidate.constant_torque_nm, "Nm", t)),
            (t.words("decel_torque"), num(candidate.decel_torque_nm, "Nm", t)),
            (t.words("rms_torque"), num(candidate.rms_torque_nm, "Nm", t)),
        ]
        checks = [_check_row(c, t, language) for c in candidate.checks]
        figure_json = script_safe_json(
            json.dumps(speed_torque_figure(candidate, selection, actuator, t))
        )
    family_ratio = (
        f"{num_plain(actuator.get('family'), t)}, i = {num_plain(actuator.get('gear_ratio'), t)}"
    )
    catalogue_rows = [
        (t.words("family_ratio"), family_ratio),
        (t.words("max_torque"), num(actuator.get("max_torque_nm"), "Nm", t)),
        (t.words("max_speed"), num(actuator.get("max_speed_rpm"), "rpm", t)),
        (t.words("inertia"), num(actuator.get("inertia_kgm2"), "kgm²", t)),
        (t.words("stall_torque"), num(actuator.get("stall_torque_nm"), "Nm", t)),
    ]
    if quote.project_id is not None:  # each axis's actuator: in the axes table
        catalogue_rows = []
    version_note = (
        t("version_note", old=quote.selection_catalogue_version, new=quote.catalogue_version)
        if quote.selection_catalogue_version != quote.catalogue_version
        else ""
    )
    verdict = t("verdict.suitable" if quote.verdict == "suitable" else "verdict.unconfirmed")
    axes = _axes_rows(quote, t)
    labels = {
        f"l_{key}": t(key)
        for key in (
            "number", "date", "valid_until", "status", "seller", "customer", "items",
            "subtotal", "terms", "payment_terms", "delivery_terms", "validity",
            "justification",
        )
    }  # fmt: skip
    columns = {
        key: t(key)
        for key in (
            "col_position", "col_item", "col_description", "col_quantity", "col_unit_price",
            "col_amount", "col_check", "col_result", "col_value", "col_limit", "col_margin",
            "col_reference",
        )
    }  # fmt: skip
    customer = quote.customer.name + (
        "\n" + quote.customer.address if quote.customer.address else ""
    )
    return dict(
        **labels,
        **columns,
        lang=language,
        title=t("title", number=quote.number),
        print_hint=t("print_hint"),
        page_label=t("page"),
        of_label=t("of"),
        heading=t("heading"),
        subtitle=t("subtitle"),
        quote_details=t("quote_details"),
        number=quote.number,
        date=t.date(quote.created_at.date()),
        valid_until=t.date(quote.valid_until),
        status=t(f"quote.status.{quote.status.value}"),
        seller={"name": seller.name, "address": seller.address, "rows": seller_rows},
        customer=customer,
        customer_reference=(
            [(t("your_reference"), quote.customer.reference)] if quote.customer.reference else []
        ),
        example_banner=(
            _with_data(t, "example_banner", name=quote.price_list.name)
            if quote.price_list.is_example
            else ""
        ),
        placeholder_banner=(
            t("placeholder_seller")
            if placeholder_seller_name is not None and seller.name == placeholder_seller_name
            else ""
        ),
        unconfirmed=(
            {
                "text": t("unconfirmed_banner"),
                "reasons": _reasons(quote, candidate, record, language),
            }
            if quote.unconfirmed
            else None
        ),
        l_axes=t("axes_heading"),
        col_axis=t("col_axis"),
        col_actuator=t("col_actuator"),
        col_verdict=t("col_verdict"),
        col_controller=t("col_controller"),
        axes=axes,
        items=[
            {
                "position": item.position,
                "code": item.item_code,
                "description": _on_axis(
                    item.axis, item_description(item.kind, item.description, t)[0], t
                ),
                # a price list's words are the seller's data: not translated
                "data": not item_description(item.kind, item.description, t)[1],
                "quantity": t.number(item.quantity, "#,##0"),
                "unit_price": money(item.unit_price, currency, t),
                "total": money(item.line_total, currency, t),
            }
            for item in quote.items
        ],
        subtotal=money(quote.subtotal, currency, t),
        discount_label=t("discount", percent=t.percent(quote.discount_percent)),
        discount_amount=money(quote.discount_amount, currency, t),
        totals=totals,
        prices_from=_with_data(
            t, "prices_from", name=quote.price_list.name, date=t.date(quote.price_list.priced_on)
        ),
        rounding=rounding,
        payment_terms=record.payment_terms or seller.standard_terms("payment", language),
        delivery_terms=record.delivery_terms or seller.standard_terms("delivery", language),
        validity=t("validity_text", date=t.date(quote.valid_until)),
        notes_heading=t("notes"),
        notes=quote.notes or "",
        # the one label with markup (<em> around the chapter's title): its arguments escaped
        justification_intro=(
            Markup(t("justification_intro", model="{model}", verdict="{verdict}")).format(
                model=quote.actuator_model, verdict=verdict
            )
            if quote.project_id is None
            else Markup(t("project_intro", verdict="{verdict}")).format(verdict=verdict)
        ),
        l_load=t("load_heading"),
        l_torques=t("torques_heading"),
        l_cycle=t("cycle_heading"),
        l_catalogue=t("catalogue_heading"),
        l_checks=t("checks_heading"),
        l_diagram=t("diagram_heading"),
        diagram_label=(
            t("diagram_label", model=quote.actuator_model)
            if quote.actuator_model is not None
            else ""
        ),
        load_rows=load_facts,
        cycle_rows=cycle_rows,
        torque_rows=torque_rows,
        catalogue_rows=catalogue_rows,
        checks=checks,
        figure=Markup(figure_json),  # script-safe JSON (no "<"), not HTML
        # the manufacturer's document as cited (a mirror address a quote stored before the
        # read_at split may hold is left out), the chapter's words ("Table") translated
        catalogue_source=_with_data(
            t, "catalogue_source", source=t.reference(citation(str(actuator.get("source"))))
        ),
        selection_footer=(
            t(
                "selection_footer",
                id=quote.selection_id,
                date=selection_date,
                version=quote.selection_catalogue_version,
                quote_version=quote.catalogue_version,
            )
            if quote.project_id is None
            else t(
                "project_footer",
                id=quote.project_id,
                version=quote.selection_catalogue_version,
                quote_version=quote.catalogue_version,
            )
        ),
        version_note=version_note,
        figures_fixed=t("figures_fixed"),
        tick_number=lambda value: t.number(value, "#,##0.###"),  # the PDF's diagram axes
        document_script="/api/v1" + DOCUMENT_SCRIPT_PATH,
    )
