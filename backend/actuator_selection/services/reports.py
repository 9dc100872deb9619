"""The engineering report of a stored selection, as CSV and as PDF.

Both list the load case, the cycle figures and every candidate in the answer's order
with its verdict, torques and checks (reference, value, limit, margin). Every number
is the stored answer's (``GET /selections/{id}``), read through
``services.selections.stored_answer_json``; the margin is the core's
``(limit − value)/limit`` (``core.checks.margin_percent``).

**CSV** (UTF-8, RFC 4180 quoting, CRLF line ends, written by the stdlib ``csv``
module): two tables separated by one empty line. The first has the columns
``quantity,value,unit`` and one row per figure of the selection (load, cycle, n_av,
ED, …); the second has one row per check of each candidate, the candidate's columns
repeated on each of its rows (``CHECK_COLUMNS``). Numbers are written as Python's
shortest repr of the stored double, so they read back as exactly the answer's value;
an unknown value is an empty cell. Text cells that a spreadsheet would run as a
formula get a leading single quote (``core.csvio.neutralised``, as the catalogue
export does).

The CSV is data for programs and spreadsheets: its column names, check names, statuses
and verdicts are the API's identifiers and its numbers are written with a decimal point,
the same in every language.

**PDF** (A4, page numbers in the footer, ``services/pdf.py``): the same content for
print, in the request's language (labels, verdicts and statuses worded, references as
the chapter's German edition writes them, numbers to six significant digits in the
language's format, min⁻¹ in German), by the words of :class:`ReportWords`. Text is set
in DejaVu Sans where the system has it; else in Latin-1 Helvetica, with the chapter's
symbols written in ASCII (``≤`` → ``<=``, ``T₁`` → ``T1``, ``−`` → ``-``).
"""

from __future__ import annotations

import csv
import io
from dataclasses import dataclass
from datetime import date
from typing import Any, Protocol

from sqlalchemy.orm import Session

from actuator_selection.core.checks import margin_percent
from actuator_selection.core.csvio import neutralised
from actuator_selection.schemas.quotes import (
    StoredSelection,
    cycle_facts,
)
from actuator_selection.services.errors import not_found
from actuator_selection.services.selections import stored_answer_json

SUMMARY_COLUMNS = ("quantity", "value", "unit")
CHECK_COLUMNS = (
    "rank",
    "model",
    "family",
    "gear_ratio",
    "verdict",
    "accel_torque_nm",
    "constant_torque_nm",
    "decel_torque_nm",
    "rms_torque_nm",
    "check",
    "status",
    "reference",
    "unit",
    "value",
    "limit",
    "margin_percent",
    "approximate",
    "missing",
)
"""The columns of the CSV's second table, one row per check of each candidate."""


@dataclass(frozen=True, slots=True)
class SelectionReport:
    """A stored selection as the report shows it."""

    selection: StoredSelection

    @property
    def summary(self) -> list[tuple[str, float | int | str | None, str]]:
        """(quantity, value, unit) of the load case and the cycle figures."""
        s = self.selection
        return [
            ("selection_id", s.id, ""),
            ("created_at", s.created_at.isoformat(), "UTC"),
            ("catalogue_version", s.catalogue_version, ""),
            ("speed_rpm", s.load.speed_rpm, "rpm"),
            ("torque_nm", s.load.torque_nm, "Nm"),
            ("inertia_kgm2", s.load.inertia_kgm2, "kgm²"),
            ("high_dynamics", "true" if s.high_dynamics else "false", ""),
            *((key, value, unit) for key, _, value, unit in cycle_facts(s.cycle, s.segments)),
            ("cycle_time_s", s.cycle_time_s, "s"),
            ("mean_speed_rpm", s.mean_speed_rpm, "rpm"),
            ("duty_cycle_percent", s.duty_cycle_percent, "%"),
            ("candidates", len(s.candidates), ""),
        ]


def selection_report(session: Session, selection_id: str) -> SelectionReport:
    """The report of a stored selection; 404 when there is none."""
    stored = stored_answer_json(session, selection_id)
    if stored is None:
        raise not_found(["path", "selection_id"], "unknown_selection", selection_id=selection_id)
    return SelectionReport(StoredSelection.model_validate(stored))


def _cell(value: Any) -> str:
    """A CSV cell: numbers as their shortest repr (exact round trip), text neutralised."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(value)
    return neutralised(str(value))


def report_csv(report: SelectionReport) -> str:
    """The report as CSV (see the module's docstring for the layout)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\r\n")
    writer.writerow(SUMMARY_COLUMNS)
    writer.writerows([_cell(q), _cell(v), _cell(u)] for q, v, u in report.summary)
    writer.writerow([])
    writer.writerow(CHECK_COLUMNS)
    for rank, c in enumerate(report.selection.candidates, start=1):
        head = [
            rank,
            c.model,
            c.family,
            c.gear_ratio,
            c.verdict,
            c.accel_torque_nm,
            c.constant_torque_nm,
            c.decel_torque_nm,
            c.rms_torque_nm,
        ]
        for check in c.checks:
            row = [
                *head,
                check.name,
                check.status,
                check.reference,
                check.unit,
                check.value,
                check.limit,
                margin_percent(check.value, check.limit),
                check.approximate,
                check.missing,
            ]
            writer.writerow([_cell(v) for v in row])
    return buffer.getvalue()


class ReportWords(Protocol):
    """The words and number formats of one language, as the quote document has them
    (``api.quote_document_text.DocumentText``)."""

    @property
    def language(self) -> str:
        """``en`` or ``de``."""
        ...

    def __call__(self, key: str, **params: object) -> str:
        """The label ``key`` with ``params`` filled in."""
        ...

    def number(self, value: float, pattern: str) -> str:
        """``value`` by a CLDR number pattern."""
        ...

    def date(self, value: date) -> str:
        """A date as the language writes it."""
        ...

    def unit(self, unit: str) -> str:
        """A unit as the chapter prints it in the language."""
        ...

    def reference(self, reference: str) -> str:
        """A reference to the chapter in the language's words."""
        ...

    def cycle_label(self, key: str, label: str) -> str:
        """The label of a cycle fact (``schemas.quotes.cycle_facts``)."""
        ...
