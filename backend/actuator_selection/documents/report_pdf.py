"""The selection report as PDF (A4, page numbers): the content of
:mod:`actuator_selection.documents.reports`, laid out for print by
:class:`~actuator_selection.documents.pdf.FigurePdf`, in the language of its
:class:`~actuator_selection.documents.reports.ReportWords`. Imported only when a PDF is
asked for (the report's route imports it then).

The first page is one a reader can sign: the inputs in words (the load at the output, the
mechanism as entered, the cycle), the cycle and speed/torque diagrams (the figure
definitions of ``documents/quote_document.py``, drawn by the PDF's own lines), the first-ranked
candidate's checks and the top five with their utilisation. The checks of other
candidates follow only for the models asked for (``?candidates=``). Numbers to four
significant digits (the page's rule, ``frontend/lib/format.js``), percentages to three.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from markupsafe import Markup

from actuator_selection.documents.pdf import FigurePdf
from actuator_selection.documents.reports import (
    TOP,
    UTILISATION_CHECKS,
    ReportWords,
    SelectionReport,
    utilisation_percent,
)
from actuator_selection.documents.symbols import symbols
from actuator_selection.schemas.output_load import OutputLoadIn
from actuator_selection.schemas.quotes import StoredCandidate, StoredCheck, cycle_facts

SIGNIFICANT = "@###"
"""Numbers to four significant digits (a CLDR pattern), as the page shows them."""
PERCENT = "@##"
"""Percentages to three significant digits."""


def number(value: float | None, unit: str, t: ReportWords) -> str:
    """A number to four significant digits with its unit; '–' when unknown."""
    if value is None:
        return "–"
    return f"{t.number(value, SIGNIFICANT)} {t.unit(unit)}".strip()


def percent(value: float | None, t: ReportWords) -> str:
    """A percentage to three significant digits; '–' when unknown."""
    return "–" if value is None else f"{t.number(value, PERCENT)} %"


OUTPUT_LOAD_ROWS = (
    ("radial_force_n", "output_load_radial_force", "N"),
    ("axial_force_n", "output_load_axial_force", "N"),
    ("radial_lever_m", "output_load_radial_lever", "m"),
    ("axial_lever_m", "output_load_axial_lever", "m"),
    ("load_factor", "output_load_load_factor", ""),
    ("static_safety_min", "output_load_static_safety", ""),
    ("required_life_h", "output_load_required_life", "h"),
)
"""The output load's inputs as the report lists them: field, label, unit."""


def output_load_rows(load: OutputLoadIn | None, t: ReportWords) -> list[tuple[object, object]]:
    """The external load on the output flange as it was sent (none where none was), one
    row a given value, in ``t``'s words."""
    if load is None:
        return []
    return [
        (t.words(label), number(value, unit, t))
        for name, label, unit in OUTPUT_LOAD_ROWS
        if (value := getattr(load, name)) is not None
    ]


def _check_rows(checks: list[StoredCheck], t: ReportWords) -> list[tuple[object, ...]]:
    return [
        (
            t.words(f"check.{c.name}"),
            t(f"result_{c.status}") + (t("approximate") if c.approximate else ""),
            t.reference(c.reference),
            number(c.value, c.unit, t),
            number(c.limit, c.unit, t),
            percent(utilisation_percent(c.value, c.limit), t),
        )
        for c in checks
    ]


def _checks(pdf: FigurePdf, c: StoredCandidate, t: ReportWords) -> None:
    pdf.grid(
        (
            t("col_check"),
            t("col_result"),
            t("col_reference"),
            t("col_value"),
            t("col_limit"),
            t("col_utilisation"),
        ),
        _check_rows(c.checks, t),
        (56, 31, 28, 20, 20, 23),
        right=(3, 4, 5),
    )


def _candidate_heading(pdf: FigurePdf, rank: int, c: StoredCandidate, t: ReportWords) -> None:
    ratio = t.number(c.gear_ratio, "#,##0.######")
    pdf.heading(f"{rank}. {c.model} ({c.family}, i = {ratio}): {t(f'verdict.{c.verdict}')}", 10)
    torques = (
        ("T_1", c.accel_torque_nm),
        ("T_2", c.constant_torque_nm),
        ("T_3", c.decel_torque_nm),
        ("T_rms", c.rms_torque_nm),
    )
    pdf.paragraph(Markup(", ").join(symbols(f"{s} = {number(v, 'Nm', t)}") for s, v in torques))


def _top(pdf: FigurePdf, report: SelectionReport, t: ReportWords) -> None:
    rows: list[Sequence[object]] = []
    for rank, c in enumerate(report.top, start=1):
        used = [report.utilisation(c, name) for name in UTILISATION_CHECKS]
        rows.append(
            (
                str(rank),
                c.model,
                t(f"verdict.{c.verdict}"),
                *(percent(u, t) for u in used),
            )
        )
    pdf.grid(
        (
            "#",
            t("col_model"),
            t("col_verdict"),
            *(t.words(f"utilisation_{name}") for name in UTILISATION_CHECKS),
        ),
        rows,
        (8, 44, 34, 32, 32, 28),
        right=(3, 4, 5),
    )


def _columns(
    pdf: FigurePdf, left: list[tuple[object, object]], right: list[tuple[object, object]]
) -> None:
    """Two fact tables side by side; the position moves below the taller."""
    top = pdf.get_y()
    half = pdf.epw / 2 - 2
    pdf.facts(left, width=half)
    bottom = pdf.get_y()
    margin = pdf.l_margin
    pdf.set_left_margin(margin + half + 4)
    pdf.set_xy(margin + half + 4, top)
    pdf.facts(right, width=half)
    bottom = max(bottom, pdf.get_y())
    pdf.set_left_margin(margin)
    pdf.set_xy(margin, bottom)


def render_pdf(
    report: SelectionReport,
    t: ReportWords,
    figures: Sequence[Mapping[str, Any]] = (),
) -> bytes:
    """The report as a PDF document (A4) in the language of ``t``; ``figures`` are the
    cycle and the speed/torque diagram (plotly figure definitions), drawn side by side."""
    s = report.selection
    pdf = FigurePdf(
        title=t("report_document_title", id=s.id),
        lang=t.language,
        page_label=t("page"),
        of_label=t("of"),
    )
    pdf.add_page()
    pdf.heading(t("report_title"), 15)
    pdf.paragraph(
        t(
            "report_intro",
            id=s.id,
            date=t.date(s.created_at.date()),
            time=f"{s.created_at:%H:%M}",
            version=s.catalogue_version,
            count=len(s.candidates),
        ),
        size=8,
    )
    load: list[tuple[object, object]] = [
        (t.words("load_speed"), number(s.load.speed_rpm, "rpm", t)),
        (t.words("load_torque"), number(s.load.torque_nm, "Nm", t)),
        (t.words("load_inertia"), number(s.load.inertia_kgm2, "kgm²", t)),
        (t.words("high_dynamics"), t("yes" if s.high_dynamics else "no")),
        *(t.load_rows(s.mechanism) if s.mechanism else []),
        *output_load_rows(s.output_load, t),
    ]
    cycle: list[tuple[object, object]] = [
        *(
            (symbols(t.cycle_label(key, label)), number(value, unit, t))
            for key, label, value, unit in cycle_facts(s.cycle, s.segments)
        ),
        (t.words("cycle_time"), number(s.cycle_time_s, "s", t)),
        (t.words("mean_speed"), number(s.mean_speed_rpm, "rpm", t)),
        (t.words("duty_cycle"), percent(s.duty_cycle_percent, t)),
    ]
    pdf.heading(t("inputs_heading"), 10)
    _columns(pdf, load, cycle)
    if figures:
        if pdf.will_page_break(70):  # the heading stays with its diagrams
            pdf.add_page()
        pdf.heading(t("diagrams_heading"), 10)
        top = pdf.get_y()
        widths = (pdf.epw * 0.42, pdf.epw * 0.58) if len(figures) == 2 else (pdf.epw,)
        margin = pdf.l_margin
        x = margin
        for figure, width in zip(figures, widths, strict=False):
            pdf.set_left_margin(x)
            pdf.set_xy(x, top)
            pdf.figure(
                figure,
                width=width - 2,
                height=58,
                number=lambda v: t.number(v, "#,##0.###"),
                legend=0 if width < pdf.epw * 0.5 else 38,
            )
            x += width
        pdf.set_left_margin(margin)
        pdf.set_xy(margin, top + 60)
    if s.candidates:
        pdf.heading(t("report_chosen"), 11)
        _candidate_heading(pdf, 1, s.candidates[0], t)
        _checks(pdf, s.candidates[0], t)
        pdf.heading(t("report_top", top=min(TOP, len(s.candidates)), count=len(s.candidates)), 10)
        _top(pdf, report, t)
        pdf.paragraph(t("report_details_hint"), size=7)
    for rank, candidate in report.detailed_candidates():
        if rank == 1:
            continue
        _candidate_heading(pdf, rank, candidate, t)
        _checks(pdf, candidate, t)
        pdf.ln(1)
    return bytes(pdf.output())
