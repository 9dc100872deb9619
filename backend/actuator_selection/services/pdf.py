"""A4 documents in fpdf2 for the quote document and the selection report: text in DejaVu
Sans where the system has it (Debian's ``fonts-dejavu-core``: every character of the
chapter, ``min⁻¹``, ``≤``, ``€``); without it in fpdf2's built-in Helvetica, whose Latin-1
holds the German letters but not the chapter's symbols, which are then written out by
:func:`pdf_text` (``≤`` → ``<=``, ``min⁻¹`` → ``1/min``). Imported only
when a PDF is asked for: fpdf2 and what it pulls in load on first use.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Final

from fpdf import FPDF
from fpdf.enums import XPos, YPos
from markupsafe import Markup

_ASCII = str.maketrans(
    {
        "≤": "<=",
        "≥": ">=",
        "−": "-",
        "–": "-",
        "—": "-",
        "₀": "0",
        "₁": "1",
        "₂": "2",
        "₃": "3",
        "⁻": "^-",
        "…": "...",
        "“": '"',
        "”": '"',
        "‘": "'",
        "’": "'",
        "√": "sqrt",
        "Ω": "Ohm",
    }
)


def pdf_text(text: str) -> str:
    """``text`` in the built-in fonts' Latin-1; what has no Latin-1 form becomes '?'.

    >>> pdf_text("T₁ ≤ T_max, −85.48 Nm, 2 kgm²")
    'T1 <= T_max, -85.48 Nm, 2 kgm²'
    """
    return text.translate(_ASCII).encode("latin-1", "replace").decode("latin-1")


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


class DocumentPdf(FPDF):
    """An A4 document: its title and "page n of N" in the footer, text in DejaVu Sans
    where the system has it (:func:`unicode_font`), else Latin-1 Helvetica."""

    def __init__(self, *, title: str, lang: str, page_label: str, of_label: str) -> None:
        super().__init__(orientation="portrait", unit="mm", format="A4")
        self._title = title
        self._page_label = page_label
        self._of_label = of_label
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
        self.set_title(self.words(title))
        self.set_lang(lang)
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
        self.set_y(-11)
        self.font(7.5)
        self.cell(0, 5, self.words(self._title), align="L")
        self.set_x(self.l_margin)
        page = f"{self._page_label} {self.page_no()} {self._of_label} {{nb}}"
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
