"""The selection report as PDF (A4, page numbers): the content of
:mod:`actuator_selection.services.reports`, laid out for print by
:class:`~actuator_selection.services.pdf.DocumentPdf`, in the language of its
:class:`~actuator_selection.services.reports.ReportWords`. Imported only when a PDF is
asked for (the report's route imports it then)."""

from __future__ import annotations

from actuator_selection.core.checks import margin_percent
from actuator_selection.schemas.quotes import StoredCandidate, StoredCheck, cycle_facts
from actuator_selection.services.pdf import DocumentPdf
from actuator_selection.services.reports import ReportWords, SelectionReport

SIGNIFICANT = "@#####"
"""Numbers to six significant digits (a CLDR pattern), in the language's format."""


def number(value: float | None, unit: str, t: ReportWords) -> str:
    """A number to six significant digits with its unit; '–' when unknown."""
    if value is None:
        return "–"
    return f"{t.number(value, SIGNIFICANT)} {t.unit(unit)}".strip()


def _check_rows(checks: list[StoredCheck], t: ReportWords) -> list[tuple[str, ...]]:
    return [
        (
            t(f"check_{c.name}"),
            t(f"result_{c.status}") + (t("approximate") if c.approximate else ""),
            t.reference(c.reference),
            number(c.value, c.unit, t),
            number(c.limit, c.unit, t),
            number(margin_percent(c.value, c.limit), "%", t),
        )
        for c in checks
    ]


def _candidate(pdf: DocumentPdf, rank: int, c: StoredCandidate, t: ReportWords) -> None:
    ratio = t.number(c.gear_ratio, "#,##0.######")
    pdf.heading(f"{rank}. {c.model} ({c.family}, i = {ratio}): {t(f'verdict_{c.verdict}')}", 10)
    pdf.paragraph(
        f"T₁ = {number(c.accel_torque_nm, 'Nm', t)}, T₂ = {number(c.constant_torque_nm, 'Nm', t)}"
        f", T₃ = {number(c.decel_torque_nm, 'Nm', t)}, T_rms = {number(c.rms_torque_nm, 'Nm', t)}"
    )
    pdf.grid(
        (
            t("col_check"),
            t("col_result"),
            t("col_reference"),
            t("col_value"),
            t("col_limit"),
            t("col_margin"),
        ),
        _check_rows(c.checks, t),
        (50, 32, 30, 24, 24, 18),
        right=(3, 4, 5),
    )
    pdf.ln(2)


def render_pdf(report: SelectionReport, t: ReportWords) -> bytes:
    """The report as a PDF document (A4) in the language of ``t``."""
    s = report.selection
    pdf = DocumentPdf(
        title=t("report_document_title", id=s.id),
        lang=t.language,
        page_label=t("page"),
        of_label=t("of"),
    )
    pdf.add_page()
    pdf.heading(t("report_title"), 16)
    pdf.paragraph(
        t(
            "report_intro",
            id=s.id,
            date=t.date(s.created_at.date()),
            time=f"{s.created_at:%H:%M}",
            version=s.catalogue_version,
        )
    )
    pdf.heading(t("load_heading"))
    pdf.facts(
        [
            (t("load_speed"), number(s.load.speed_rpm, "rpm", t)),
            (t("load_torque"), number(s.load.torque_nm, "Nm", t)),
            (t("load_inertia"), number(s.load.inertia_kgm2, "kgm²", t)),
            (t("high_dynamics"), t("yes" if s.high_dynamics else "no")),
        ]
    )
    pdf.heading(t("cycle_heading"))
    pdf.facts(
        [
            *(
                (t.cycle_label(key, label), number(value, unit, t))
                for key, label, value, unit in cycle_facts(s.cycle, s.segments)
            ),
            (t("cycle_time"), number(s.cycle_time_s, "s", t)),
            (t("mean_speed"), number(s.mean_speed_rpm, "rpm", t)),
            (t("duty_cycle"), number(s.duty_cycle_percent, "%", t)),
        ]
    )
    pdf.heading(t("report_candidates", count=len(s.candidates)), 11)
    for rank, candidate in enumerate(s.candidates, start=1):
        _candidate(pdf, rank, candidate, t)
    return bytes(pdf.output())
