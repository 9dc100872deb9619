"""The selection report as PDF (fpdf2, A4, built-in Helvetica, page numbers): the content
of :mod:`actuator_selection.services.reports`, laid out for print. Imported only when a
PDF is asked for (:func:`~actuator_selection.services.reports.report_pdf`)."""

from __future__ import annotations

from fpdf import FPDF
from fpdf.enums import XPos, YPos

from actuator_selection.core.checks import margin_percent
from actuator_selection.schemas.quotes import StoredCandidate, StoredCheck, cycle_facts
from actuator_selection.services.reports import (
    STATUS_WORDS,
    SelectionReport,
    pdf_number,
    pdf_text,
)


class _Pdf(FPDF):
    def __init__(self, title: str) -> None:
        super().__init__(orientation="portrait", unit="mm", format="A4")
        self._title = title
        self.set_auto_page_break(auto=True, margin=15)
        self.set_margins(15, 15, 15)
        self.set_title(title)
        self.set_creator("actuator selection service")

    def footer(self) -> None:
        self.set_y(-12)
        self.set_font("Helvetica", size=8)
        self.cell(0, 5, pdf_text(self._title), align="L")
        self.set_x(self.l_margin)
        self.cell(0, 5, f"page {self.page_no()} of {{nb}}", align="R")


def _facts(pdf: FPDF, rows: list[tuple[str, str]]) -> None:
    pdf.set_font("Helvetica", size=9)
    with pdf.table(col_widths=(60, 60), width=120, align="LEFT", first_row_as_headings=False) as t:
        for label, value in rows:
            row = t.row()
            row.cell(pdf_text(label))
            row.cell(value)


def _check_rows(checks: list[StoredCheck]) -> list[tuple[str, ...]]:
    return [
        (
            pdf_text(c.name),
            STATUS_WORDS.get(c.status, c.status) + (" (approx.)" if c.approximate else ""),
            pdf_text(c.reference),
            pdf_number(c.value, c.unit),
            pdf_number(c.limit, c.unit),
            pdf_number(margin_percent(c.value, c.limit), "%"),
        )
        for c in checks
    ]


def _candidate(pdf: FPDF, rank: int, c: StoredCandidate) -> None:
    pdf.set_font("Helvetica", style="B", size=10)
    pdf.cell(
        0,
        6,
        pdf_text(f"{rank}. {c.model} ({c.family}, i = {c.gear_ratio:g}): {c.verdict}"),
        new_x=XPos.LMARGIN,
        new_y=YPos.NEXT,
    )
    pdf.set_font("Helvetica", size=8.5)
    torques = (
        f"T1 = {pdf_number(c.accel_torque_nm, 'Nm')}, T2 = {pdf_number(c.constant_torque_nm, 'Nm')}"
        f", T3 = {pdf_number(c.decel_torque_nm, 'Nm')}, T_rms = {pdf_number(c.rms_torque_nm, 'Nm')}"
    )
    pdf.cell(0, 5, torques, new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    with pdf.table(col_widths=(34, 22, 26, 30, 30, 24), line_height=4.6) as t:
        t.row(("check", "status", "reference", "value", "limit", "margin"))
        for cells in _check_rows(c.checks):
            t.row(cells)
    pdf.ln(3)


def render_pdf(report: SelectionReport) -> bytes:
    """The report as a PDF document (A4)."""
    s = report.selection
    pdf = _Pdf(f"Selection report {s.id}")
    pdf.add_page()
    pdf.set_font("Helvetica", style="B", size=16)
    pdf.cell(0, 9, "Selection report", new_x=XPos.LMARGIN, new_y=YPos.NEXT)
    pdf.set_font("Helvetica", size=9)
    pdf.multi_cell(
        0,
        4.5,
        pdf_text(
            f"Selection {s.id} of {s.created_at:%Y-%m-%d %H:%M} UTC, catalogue version "
            f"{s.catalogue_version}. Sized by Engineering Data for Harmonic Drive Servo "
            "Actuators (Eq. 514.1-522.3); every figure is the one stored with the selection."
        ),
        new_x=XPos.LMARGIN,
        new_y=YPos.NEXT,
    )
    pdf.ln(2)
    for title, rows in (
        (
            "Load case (at the actuator output)",
            [
                ("load speed n2", pdf_number(s.load.speed_rpm, "rpm")),
                ("load torque T_L", pdf_number(s.load.torque_nm, "Nm")),
                ("load inertia J_L", pdf_number(s.load.inertia_kgm2, "kgm²")),
                ("J_L <= 3 J_A binding", "yes" if s.high_dynamics else "no"),
            ],
        ),
        (
            "Cycle (Fig. 516.2, Eq. 514.3, 514.4)",
            [
                *(
                    (label, pdf_number(value, unit))
                    for _, label, value, unit in cycle_facts(s.cycle, s.segments)
                ),
                ("cycle time", pdf_number(s.cycle_time_s, "s")),
                ("mean speed n_av", pdf_number(s.mean_speed_rpm, "rpm")),
                ("duty cycle ED", pdf_number(s.duty_cycle_percent, "%")),
            ],
        ),
    ):
        pdf.set_font("Helvetica", style="B", size=11)
        pdf.cell(0, 7, title, new_x=XPos.LMARGIN, new_y=YPos.NEXT)
        _facts(pdf, rows)
        pdf.ln(2)
    pdf.set_font("Helvetica", style="B", size=11)
    pdf.cell(
        0,
        7,
        f"Candidates ({len(s.candidates)}, ranked as answered)",
        new_x=XPos.LMARGIN,
        new_y=YPos.NEXT,
    )
    for rank, candidate in enumerate(s.candidates, start=1):
        _candidate(pdf, rank, candidate)
    return bytes(pdf.output())
