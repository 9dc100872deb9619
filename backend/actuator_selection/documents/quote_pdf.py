"""The quote document as PDF (fpdf2, A4, page numbers): the same words, numbers and order as
the HTML document, from the same context (``documents/quote_document.py``,
:func:`~actuator_selection.documents.quote_document.quote_document_context`), so a German PDF
says what the German HTML says. The speed/torque diagram is the HTML's figure definition
(the plotly JSON that plotly.js draws there) drawn with the PDF's own lines
(:meth:`~actuator_selection.documents.pdf.FigurePdf.figure`). Tables are kept on one page
where they fit, and an item code is never broken inside.

Laid out by :class:`~actuator_selection.documents.pdf.DocumentPdf` (fonts, footer, tables).
"""

from __future__ import annotations

import json
from typing import Any

from fpdf.enums import XPos, YPos
from markupsafe import Markup

from actuator_selection.documents.pdf import FigurePdf


def _item_widths(pdf: FigurePdf, codes: list[str]) -> tuple[float, ...]:
    """The items table's column widths: the item code's column as wide as the longest code
    (an item code is never broken), taken from the description's."""
    pdf.font(8)
    code = max([32.0, *(pdf.get_string_width(pdf.words(c)) + 4.0 for c in codes)])
    code = min(code, 70.0)
    return (10, code, 94 - code, 16, 29, 29)


def render_quote_pdf(context: dict[str, Any]) -> bytes:
    """The quote document of ``context`` (``quote_document_context``) as a PDF (A4)."""
    c = context
    pdf = FigurePdf(
        title=c["title"], lang=c["lang"], page_label=c["page_label"], of_label=c["of_label"]
    )
    pdf.add_page()
    for banner in (c["example_banner"], c["placeholder_banner"]):
        if banner:
            pdf.font(8.5, bold=True)
            pdf.multi_cell(0, 4.4, pdf.words(banner), border=1, new_x=XPos.LMARGIN, new_y=YPos.NEXT)
            pdf.ln(1)
    pdf.heading(c["heading"], 16)
    pdf.paragraph(c["subtitle"])
    pdf.ln(1)
    pdf.facts(
        [
            (c["l_number"], c["number"]),
            (c["l_date"], c["date"]),
            (c["l_valid_until"], c["valid_until"]),
            (c["l_status"], c["status"]),
        ],
        width=90,
    )
    seller = c["seller"]
    pdf.heading(c["l_seller"])
    pdf.paragraph(f"{seller['name']}\n{seller['address']}")
    pdf.facts([(row["label"], row["value"]) for row in seller["rows"]], width=90)
    pdf.heading(c["l_customer"])
    pdf.paragraph(c["customer"])
    pdf.facts(list(c["customer_reference"]), width=90)
    if c["unconfirmed"]:
        pdf.ln(1)
        pdf.paragraph(c["unconfirmed"]["text"])
        for reason in c["unconfirmed"]["reasons"]:
            pdf.paragraph(Markup("– ") + reason, size=8)
    pdf.heading(c["l_items"])
    money_rows: list[list[object]] = [
        [i["position"], i["code"], i["description"], i["quantity"], i["unit_price"], i["total"]]
        for i in c["items"]
    ]
    money_rows.append(["", "", c["l_subtotal"], "", "", c["subtotal"]])
    money_rows.append(["", "", c["discount_label"], "", "", f"− {c['discount_amount']}"])
    money_rows += [["", "", row["label"], "", "", row["value"]] for row in c["totals"]]
    pdf.grid(
        (
            c["col_position"],
            c["col_item"],
            c["col_description"],
            c["col_quantity"],
            c["col_unit_price"],
            c["col_amount"],
        ),
        money_rows,
        _item_widths(pdf, [str(i["code"]) for i in c["items"]]),
        right=(3, 4, 5),
    )
    pdf.ln(1)
    pdf.paragraph(c["prices_from"], size=7.5)
    pdf.paragraph(c["rounding"], size=7.5)
    pdf.heading(c["l_terms"])
    pdf.facts(
        [
            (c["l_payment_terms"], c["payment_terms"]),
            (c["l_delivery_terms"], c["delivery_terms"]),
            (c["l_validity"], c["validity"]),
        ],
        width=178,
    )
    if c["notes"]:
        pdf.heading(c["notes_heading"])
        pdf.paragraph(c["notes"])
    pdf.heading(c["l_justification"], 13)
    pdf.paragraph(c["justification_intro"])
    if c["axes"]:
        pdf.heading(c["l_axes"], 10)
        pdf.grid(
            (c["col_axis"], c["col_actuator"], c["col_verdict"], c["col_controller"]),
            [(a["name"], a["model"], a["verdict"], a["controller"]) for a in c["axes"]],
            (20, 40, 28, 90),
        )
    for title, rows in (
        (c["l_load"], c["load_rows"]),
        (c["l_torques"], c["torque_rows"]),
        (c["l_cycle"], c["cycle_rows"]),
        (c["l_catalogue"], c["catalogue_rows"]),
    ):
        if rows:
            pdf.heading(title, 10)
            pdf.facts(rows)
    if c["checks"]:
        pdf.heading(c["l_checks"], 10)
        pdf.grid(
            (
                c["col_check"],
                c["col_result"],
                c["col_value"],
                c["col_limit"],
                c["col_margin"],
                c["col_reference"],
            ),
            [
                (
                    ch["label"] + (Markup("\n") + ch["message"] if ch["message"] else ""),
                    f"{ch['status_label']}{ch['approximate']}",
                    ch["value"],
                    ch["limit"],
                    ch["margin"],
                    ch["reference"],
                )
                for ch in c["checks"]
            ],
            (62, 24, 22, 22, 18, 30),
            right=(2, 3, 4),
        )
    figure = json.loads(str(c["figure"]))
    if figure:
        if pdf.will_page_break(72):  # the heading stays with its diagram
            pdf.add_page()
        pdf.heading(c["l_diagram"], 10)
        pdf.figure(figure, width=pdf.epw, height=62, number=c["tick_number"])
    pdf.ln(1)
    pdf.paragraph(c["catalogue_source"], size=7.5)
    pdf.paragraph(f"{c['selection_footer']}{c['version_note']}", size=7.5)
    pdf.paragraph(c["figures_fixed"], size=7.5)
    return bytes(pdf.output())
