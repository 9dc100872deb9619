"""A4 documents in fpdf2 for the quote document and the selection report: text in DejaVu
Sans where the system has it (Debian's ``fonts-dejavu-core``: every character of the
chapter, ``min⁻¹``, ``≤``, ``€``); without it in fpdf2's built-in Helvetica, whose Latin-1
holds the German letters but not the chapter's symbols, which are then written out by
:func:`pdf_text` (``≤`` → ``<=``, ``min⁻¹`` → ``1/min``). Imported only
when a PDF is asked for: fpdf2 and what it pulls in load on first use.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any, Final

from fpdf import FPDF
from fpdf.enums import CharVPos, XPos, YPos
from fpdf.line_break import Fragment
from markupsafe import Markup

from actuator_selection.documents.symbols import subscript

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
        **dict(zip("ₐₑₕᵢₖₗₘₙₒₚᵣₛₜᵤᵥₓ", "aehiklmnoprstuvx", strict=True)),
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


_SUB = re.compile(r"<sub>(.*?)</sub>")

SUB_START: Final = "\x0e"
SUB_END: Final = "\x0f"
"""The marks around a subscript that Unicode has no letters for (capitals: ``T_L``, ``J_A``,
``m_B``): :class:`DocumentPdf` sets what is between them lowered and smaller (fpdf2's
``char_vpos`` SUB), as the HTML's ``<sub>`` does. Latin-1 control characters, so that
the built-in fonts' encoding keeps them until they are read."""

_MARKED = re.compile(f"{SUB_START}([^{SUB_END}]*){SUB_END}")


def _marked(sub: str) -> str:
    """A subscript the font cannot write in Unicode's subscript letters, marked."""
    return f"{SUB_START}{sub}{SUB_END}"


def plain(value: object, *, unicode_subscripts: bool = True) -> str:
    r"""A context value as text: markup (the intro's emphasis, data spans) without its tags,
    a subscript (``<sub>av</sub>``, ``documents.symbols.symbols``) in Unicode's subscript
    letters where it has them all (``subscript``), else between :data:`SUB_START` and
    :data:`SUB_END` (set as a subscript by :class:`DocumentPdf`).

    >>> plain(Markup("n<sub>av</sub> &amp; T<sub>L</sub>"))
    'nₐᵥ & T\x0eL\x0f'
    >>> plain(Markup("n<sub>av</sub>"), unicode_subscripts=False)
    'n\x0eav\x0f'
    """
    if isinstance(value, Markup):

        def one(match: re.Match[str]) -> str:
            sub = match.group(1)
            letters = subscript(sub)
            return letters if unicode_subscripts and letters != sub else _marked(sub)

        return Markup(_SUB.sub(one, str(value))).striptags()
    return str(value)


def unmarked(text: str) -> str:
    r"""``text`` without the subscript marks (``T\x0eL\x0f`` → ``TL``)."""
    return text.replace(SUB_START, "").replace(SUB_END, "")


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
        self.set_title(unmarked(self.words(title)))
        self.set_lang(lang)
        self.set_creator("actuator selection service")
        self.alias_nb_pages()

    def words(self, value: object) -> str:
        """``value`` as the font can write it: subscripts in Unicode's letters where the
        font has them, else marked to be set lowered and smaller (:func:`plain`)."""
        text = plain(value, unicode_subscripts=self._unicode)
        if self._unicode:
            return text
        return pdf_text(text.replace("min⁻¹", "1/min").replace("„", '"').replace("€", "EUR"))

    def _parse_chars(self, text: str, markdown: bool, **kwargs: Any) -> Iterator[Fragment]:
        """fpdf2's fragments of ``text`` (every cell, table and paragraph), what lies
        between :data:`SUB_START` and :data:`SUB_END` as subscript fragments."""
        if SUB_START not in text:
            yield from super()._parse_chars(text, markdown, **kwargs)
            return
        for index, piece in enumerate(_MARKED.split(text)):
            if not piece:
                continue
            if index % 2 == 0:
                yield from super()._parse_chars(piece, markdown, **kwargs)
                continue
            before = self.char_vpos
            self.char_vpos = CharVPos.SUB
            try:
                yield from super()._parse_chars(piece, markdown, **kwargs)
            finally:
                self.char_vpos = before

    def text(self, x: float, y: float, text: str = "") -> None:
        """fpdf2's ``text`` (a figure's labels), subscripts marked by :func:`plain` set
        smaller and lowered as fpdf2 sets them in cells (``sub_scale``, ``sub_lift``)."""
        if SUB_START not in text:
            super().text(x, y, text)
            return
        size = self.font_size_pt
        for index, piece in enumerate(_MARKED.split(text)):
            if not piece:
                continue
            if index % 2 == 0:
                super().text(x, y, piece)
                x += self.get_string_width(piece)
                continue
            self.set_font_size(size * self.sub_scale)
            super().text(x, y - self.sub_lift * size / self.k, piece)
            x += self.get_string_width(piece)
            self.set_font_size(size)

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
        self.multi_cell(0, 4.2, self.words(text), align="L", new_x=XPos.LMARGIN, new_y=YPos.NEXT)

    def whole(self, draw: Callable[[Any], None]) -> None:
        """``draw`` (a table) on one page: first on a copy, and where that breaks the page,
        on the next page; a table longer than a page breaks where it must."""
        with self.offset_rendering() as dummy:
            draw(dummy)
        if dummy.page_break_triggered and self.get_y() > self.t_margin + 10:
            self.add_page()
        draw(self)

    def facts(self, rows: Sequence[tuple[object, object]], width: float = 120) -> None:
        """Label and value rows, left-aligned (never justified), kept on one page."""
        if rows:
            self.whole(lambda pdf: pdf._facts(rows, width))

    def _facts(self, rows: Sequence[tuple[object, object]], width: float) -> None:
        self.font(8.5)
        with self.table(
            col_widths=(width * 0.55, width * 0.45),
            width=width,
            align="LEFT",
            text_align="LEFT",
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
        """A table with a heading row; numbers (columns ``right``) right-aligned, the rest
        left-aligned; kept on one page."""
        self.whole(lambda pdf: pdf._grid(head, rows, widths, right))

    def _grid(
        self,
        head: Sequence[object],
        rows: Sequence[Sequence[object]],
        widths: Sequence[float],
        right: Sequence[int],
    ) -> None:
        self.font(8)
        align = tuple("RIGHT" if i in right else "LEFT" for i in range(len(widths)))
        with self.table(
            col_widths=tuple(widths), text_align=align, line_height=4.4, width=sum(widths)
        ) as table:
            table.row(tuple(self.words(h) for h in head))
            for row in rows:
                table.row(tuple(self.words(v) for v in row))


NumberText = Callable[[float], str]
"""How a figure's tick labels write a number (the document's language)."""


def _color(text: str | None, default: tuple[int, ...] = (68, 68, 68)) -> tuple[int, ...]:
    """A plotly colour (``#rrggbb`` or ``rgba(r,g,b,a)``) as RGB, a transparent one blended
    onto white paper.

    >>> _color("#2e8b57"), _color("rgba(46,139,87,0.5)")
    ((46, 139, 87), (150, 197, 171))
    """
    if not text:
        return default
    if text.startswith("#") and len(text) == 7:
        return tuple(int(text[i : i + 2], 16) for i in (1, 3, 5))
    if (match := re.fullmatch(r"rgba?\(([^)]*)\)", text.replace(" ", ""))) is not None:
        parts = [float(p) for p in match.group(1).split(",")]
        alpha = parts[3] if len(parts) > 3 else 1.0
        return tuple(round(255 - alpha * (255 - c)) for c in parts[:3])
    return default


def nice_ticks(top: float, count: int = 5) -> list[float]:
    """Ticks 0, step, 2·step … up to ``top``, the step 1, 2 or 5 × 10ⁿ.

    >>> nice_ticks(165.0)
    [0.0, 50.0, 100.0, 150.0]
    """
    if top <= 0:
        return [0.0]
    raw = top / count
    power = 10.0 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 5, 10) if m * power >= raw)
    return [k * step for k in range(int(top / step + 1e-9) + 1)]


def _axis(
    layout: Mapping[str, Any], name: str, data: Sequence[Mapping[str, Any]]
) -> tuple[float, float, str]:
    axis = layout.get(name, {})
    title = axis.get("title", {})
    text = title.get("text", "") if isinstance(title, Mapping) else str(title or "")
    if "range" in axis:
        low, high = axis["range"]
        return float(low), float(high), text
    key = name[0]
    values = [float(v) for trace in data for v in trace.get(key, []) if v is not None]
    high = max(values or [1.0])
    low = min([0.0, *values])
    return low, high * 1.1 if high > 0 else 1.0, text


def _y_axis(trace: Mapping[str, Any]) -> str:
    """The layout's name of a trace's y axis ("y2" → "yaxis2")."""
    return "yaxis" + str(trace.get("yaxis", "y"))[1:]


def _scale(low: float, high: float, bottom: float, height: float) -> Callable[[float], float]:
    """Page position of a value on an axis from ``low`` at ``bottom`` up to ``high``."""
    span = high - low if high != low else 1.0
    return lambda v: bottom - (v - low) / span * height


class FigurePdf(DocumentPdf):
    """A :class:`DocumentPdf` that draws a plotly figure (its JSON: the same definition an
    HTML document hands to plotly.js) with the PDF's own lines, areas and text: filled
    ``toself`` areas, lines (solid, dash, dot), markers (circle, triangles) with their text,
    axes with ticks and titles, panels stacked by their y axes' ``domain`` on one x axis,
    vertical line shapes, and a legend of the traces' names."""

    def figure(
        self,
        figure: Mapping[str, Any],
        *,
        width: float,
        height: float,
        number: NumberText,
        legend: float = 48.0,
    ) -> None:
        """Draw ``figure`` in a box of ``width`` × ``height`` mm at the current position
        (a new page first where it would not fit); the position moves below it."""
        if self.will_page_break(height):
            self.add_page()
        data: Sequence[Mapping[str, Any]] = figure.get("data", [])
        layout: Mapping[str, Any] = figure.get("layout", {})
        x_low, x_high, x_title = _axis(layout, "xaxis", data)
        left, top = self.l_margin + 13.0, self.get_y() + 2.0
        plot_w = width - 13.0 - (legend if legend else 0.0)
        plot_h = height - 12.0

        def px(x: float) -> float:
            return left + (x - x_low) / (x_high - x_low) * plot_w

        # one panel per y axis, stacked by its domain (the cycle's speed above its torque)
        names = sorted((k for k in layout if re.fullmatch(r"yaxis\d*", k)), key=len) or ["yaxis"]
        panels: dict[str, tuple[float, float, Callable[[float], float]]] = {}
        for name in names:
            low_d, high_d = layout.get(name, {}).get("domain", (0.0, 1.0))
            p_top, p_h = top + (1.0 - float(high_d)) * plot_h, (float(high_d) - low_d) * plot_h
            mine = [trace for trace in data if _y_axis(trace) == name]
            y_low, y_high, y_title = _axis(layout, name, mine)
            panels[name] = (p_top, p_h, _scale(y_low, y_high, p_top + p_h, p_h))
            self._y_axis(y_low, y_high, y_title, left, plot_w, p_top, p_h, panels[name][2], number)
            self.set_draw_color(68, 68, 68)
            self.set_line_width(0.25)
            self.line(left, p_top + p_h, left + plot_w, p_top + p_h)
        self.set_line_width(0.1)
        self.set_draw_color(228, 230, 234)
        self.font(6.5)
        for tick in nice_ticks(x_high):
            if tick < x_low:
                continue
            for p_top, p_h, _ in panels.values():
                self.line(px(tick), p_top, px(tick), p_top + p_h)
            label = number(tick)
            self.text(px(tick) - self.get_string_width(label) / 2, top + plot_h + 3.2, label)
        self._shapes(layout, px, top, plot_h)
        self.set_draw_color(68, 68, 68)
        x_label = self.figure_words(x_title)
        self.text(left + (plot_w - self.get_string_width(x_label)) / 2, top + plot_h + 7.5, x_label)
        entries: list[tuple[str, tuple[int, ...], str]] = []
        for p_top, p_h, py in panels.values():
            with self.rect_clip(left, p_top - 1, plot_w + 1, p_h + 1):
                for trace in data:
                    if panels.get(_y_axis(trace)) == (p_top, p_h, py):
                        entries.append(self._trace(trace, px, py))
        if legend:
            self._legend(entries, left + plot_w + 3.0, top)
        self.set_draw_color(0, 0, 0)
        self.set_fill_color(255, 255, 255)
        self.set_text_color(0, 0, 0)
        self.set_dash_pattern()
        self.set_line_width(0.2)
        self.set_xy(self.l_margin, top + height)

    def _y_axis(
        self,
        low: float,
        high: float,
        title: str,
        left: float,
        plot_w: float,
        top: float,
        height: float,
        py: Callable[[float], float],
        number: NumberText,
    ) -> None:
        """A panel's grid, tick labels, axis line and rotated title."""
        self.set_line_width(0.1)
        self.set_draw_color(228, 230, 234)
        self.font(6.5)
        step_ticks = nice_ticks(max(high, -low))
        for tick in sorted({*step_ticks, *(-v for v in step_ticks)}):
            if not low <= tick <= high:
                continue
            self.line(left, py(tick), left + plot_w, py(tick))
            label = number(tick)
            self.text(left - 1.2 - self.get_string_width(label), py(tick) + 1.0, label)
        self.set_draw_color(68, 68, 68)
        self.set_line_width(0.25)
        self.line(left, top, left, top + height)
        label = self.figure_words(title)
        y = top + (height + self.get_string_width(label)) / 2
        with self.rotation(90, self.l_margin + 2.5, y):
            self.text(self.l_margin + 2.5, y, label)

    def _shapes(
        self, layout: Mapping[str, Any], px: Callable[[float], float], top: float, height: float
    ) -> None:
        """The figure's vertical lines across the plot (plotly's ``shapes`` of type line at
        an x, ``yref`` paper: the cycle's phase boundaries), dotted as plotly.js draws them."""
        for shape in layout.get("shapes", []):
            if shape.get("type") != "line" or shape.get("yref") != "paper":
                continue
            if shape.get("x0") != shape.get("x1"):
                continue
            self.set_draw_color(*_color(shape.get("line", {}).get("color"), (187, 187, 187)))
            self.set_line_width(0.15)
            self.set_dash_pattern(dash=0.4, gap=0.8)
            x = px(float(shape["x0"]))
            self.line(x, top, x, top + height)
            self.set_dash_pattern()

    def figure_words(self, text: str) -> str:
        """A figure's text (plotly's, HTML where it holds a tag: ``T<sub>L</sub>``) as the
        font can write it."""
        return self.words(Markup(text) if "<" in text else text)

    def _trace(
        self, trace: Mapping[str, Any], px: Callable[[float], float], py: Callable[[float], float]
    ) -> tuple[str, tuple[int, ...], str]:
        xs, ys = trace.get("x", []), trace.get("y", [])
        points = [
            (px(x), py(y)) for x, y in zip(xs, ys, strict=False) if x is not None and y is not None
        ]
        mode = str(trace.get("mode", "lines"))
        line = trace.get("line", {})
        marker = trace.get("marker", {})
        color = _color(line.get("color") or marker.get("color"))
        if trace.get("fill") == "toself" and len(points) > 2:
            self.set_fill_color(*_color(trace.get("fillcolor"), (220, 235, 225)))
            self.polygon(points, style="F")
        if "lines" in mode and len(points) > 1:
            self.set_draw_color(*color)
            self.set_line_width(0.12 * float(line.get("width", 2)))
            dash = line.get("dash")
            self.set_dash_pattern(dash=1.2 if dash == "dash" else 0.4, gap=0.8) if dash else (
                self.set_dash_pattern()
            )
            self.polyline(points)
            self.set_dash_pattern()
        if "markers" in mode:
            self.set_fill_color(*color)
            texts = trace.get("text", [])
            for k, (x, y) in enumerate(points):
                self._marker(str(marker.get("symbol", "circle")), x, y)
                if "text" in mode and k < len(texts):
                    self.font(6.5)
                    self.set_text_color(*color)
                    above = "top" in str(trace.get("textposition", "top"))
                    self.text(
                        x + 1.6, y - 1.4 if above else y + 3.2, self.figure_words(str(texts[k]))
                    )
                    self.set_text_color(0, 0, 0)
        kind = "marker" if "markers" in mode else "area" if trace.get("fill") else "line"
        return self.figure_words(str(trace.get("name", ""))), color, kind

    def _marker(self, symbol: str, x: float, y: float, r: float = 1.1) -> None:
        if symbol == "triangle-up":
            self.polygon([(x - r, y + r), (x + r, y + r), (x, y - r)], style="F")
        elif symbol == "triangle-down":
            self.polygon([(x - r, y - r), (x + r, y - r), (x, y + r)], style="F")
        else:
            self.circle(x, y, r, style="F")

    def _legend(
        self, entries: Sequence[tuple[str, tuple[int, ...], str]], x: float, y: float
    ) -> None:
        self.font(6.5)
        for name, color, kind in entries:
            if not name:
                continue
            if kind == "marker":
                self.set_fill_color(*color)
                self._marker("circle", x + 2.0, y + 1.2, 0.9)
            elif kind == "area":
                self.set_fill_color(*_color(None, color))
                self.rect(x, y, 4.0, 2.4, style="F")
            else:
                self.set_draw_color(*color)
                self.set_line_width(0.4)
                self.line(x, y + 1.2, x + 4.0, y + 1.2)
            self.set_xy(x + 5.0, y - 0.6)
            self.multi_cell(self.epw - (x - self.l_margin) - 5.0, 3.0, self.words(name))
            y = self.get_y() + 0.6
