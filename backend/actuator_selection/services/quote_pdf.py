"""The quote document as PDF (fpdf2, A4, page numbers): the same words, numbers and order as
the HTML document, from the same context (``api/quote_document.py``,
:func:`~actuator_selection.api.quote_document.quote_document_context`), so a German PDF
says what the German HTML says. The speed/torque diagram, drawn by plotly.js in the HTML,
is left out here with a sentence saying so.

Text is set in DejaVu Sans where the system has it (Debian's ``fonts-dejavu-core``: every
character of the chapter, ``min⁻¹``, ``≤``, ``€``); without it in fpdf2's built-in
Helvetica, whose Latin-1 holds the German letters but not the chapter's symbols, which are
then written as ``services/reports.py`` writes them (``≤`` → ``<=``, ``min⁻¹`` → ``1/min``).
Imported only when a PDF is asked for: fpdf2 and what it pulls in load on first use.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any, Final

from fpdf import FPDF
from fpdf.enums import XPos, YPos
from markupsafe import Markup

from actuator_selection.services.reports import pdf_text

UNICODE_FONTS: Final = (
    Path("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"),
    Path("/usr/share/fonts/dejavu/DejaVuSans.ttf"),
)
"""Where a Unicode TTF font is looked for (its bold face beside it, ``…-Bold.ttf``)."""

FONT: Final = "doc"


def unicode_font() -> Path | None:
    """The first of :data:`UNICODE_FONTS` that exists with its bold face, else None."""
    for path in UNICODE_FONTS:
        if path.is_file() and path.with_name(path.stem + "-Bold.ttf").is_file():
            return path
    return None


def plain(value: object) -> str:
    """A context value as text: markup (the intro's emphasis, data spans) without its tags."""
    if isinstance(value, Markup):
        return value.striptags()
    return str(value)


class _Pdf(FPDF):
    def __init__(self, context: dict[str, Any]) -> None:
        super().__init__(orientation="portrait", unit="mm", format="A4")
        self._context = context
        font = unicode_font()
        self._unicode = font is not None
        if font is not None:
            self.add_font(FONT, "", str(font))
            self.add_font(FONT, "B", str(font.with_name(font.stem + "-Bold.ttf")))
            self._family = FONT
        else:
            self._family = "Helvetica"
        self.set_auto_page_break(auto=True, margin=16)
        self.set_margins(16, 15, 16)
        self.set_title(self.words(context["title"]))
        self.set_lang(context["lang"])
        self.set_creator("actuator selection service")
        self.alias_nb_pages()

    def words(self, value: object) -> str:
        """``value`` as the font can write it."""
        text = plain(value)
        if self._unicode:
            return text
        return pdf_text(text.replace("min⁻¹", "1/min").replace("„", '"').replace("€", "EUR"))

    def font(self, size: float, *, bold: bool = False) -> None:
        self.set_font(self._family, style="B" if bold else "", size=size)

    def footer(self) -> None:
        c = self._context
        self.set_y(-11)
        self.font(7.5)
        self.cell(0, 5, self.words(c["title"]), align="L")
        self.set_x(self.l_margin)
        page = f"{c['page_label']} {self.page_no()} {c['of_label']} {{nb}}"
        self.cell(0, 5, self.words(page), align="R")

    def heading(self, text: object, size: float = 11) -> None:
        self.ln(1.5)
        self.font(size, bold=True)
        self.multi_cell(0, size * 0.5, self.words(text), new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        self.ln(0.5)

    def paragraph(self, text: object, size: float = 8.5) -> None:
        if not plain(text).strip():
            return
        self.font(size)
        self.multi_cell(0, 4.2, self.words(text), new_x=XPos.LMARGIN, new_y=YPos.NEXT)

    def facts(self, rows: Sequence[tuple[object, object]], width: float = 120) -> None:
        if not rows:
            return
        self.font(8.5)
        with self.table(
            col_widths=(width * 0.55, width * 0.45),
            width=width,
            align="LEFT",
            first_row_as_headings=False,
            line_height=4.4,
        ) as table:
            for label, value in rows:
                table.row((self.words(label), self.words(value)))

    def grid(
        self,
        head: Sequence[object],
        rows: Sequence[Sequence[object]],
        widths: Sequence[float],
        *,
        right: Sequence[int] = (),
    ) -> None:
        self.font(8)
        align = tuple("RIGHT" if i in right else "LEFT" for i in range(len(widths)))
        with self.table(
            col_widths=tuple(widths), text_align=align, line_height=4.4, width=sum(widths)
        ) as table:
            table.row(tuple(self.words(h) for h in head))
            for row in rows:
                table.row(tuple(self.words(v) for v in row))


def render_quote_pdf(context: dict[str, Any]) -> bytes:
    """The quote document of ``context`` (``quote_document_context``) as a PDF (A4)."""
    c = context
    pdf = _Pdf(c)
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
            pdf.paragraph(f"– {reason}", size=8)
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
        (10, 32, 62, 16, 29, 29),
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
                    ch["label"] + (f"\n{ch['message']}" if ch["message"] else ""),
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
    pdf.ln(1)
    pdf.paragraph(c["diagram_note"], size=7.5)
    pdf.paragraph(c["catalogue_source"], size=7.5)
    pdf.paragraph(f"{c['selection_footer']}{c['version_note']}", size=7.5)
    pdf.paragraph(c["figures_fixed"], size=7.5)
    return bytes(pdf.output())
