"""The engineering report of a stored selection, as CSV and as PDF.

Every number is the stored answer's (``GET /selections/{id}``), read through
``services.selections.stored_answer_json``; the margin is the core's
``(limit − value)/limit`` (``sizing.checks.margin_percent``), the utilisation value/limit.

**CSV** (UTF-8 with a byte order mark so that a spreadsheet reads ``kgm²`` right, RFC 4180
quoting, CRLF line ends, written by the stdlib ``csv`` module): one tidy table with one
header row (``COLUMNS``, with a segment cycle's segments), one row per check of each
candidate in the answer's order; the selection's figures (load, cycle, n_av, ED) and the
candidate's are repeated on each row, so that every row stands alone in a filter or a
pivot table. Numbers are written as
Python's shortest repr of the stored double, so they read back as exactly the answer's
value; an unknown value (and a cycle time of a segment cycle) is an empty cell. Text
cells that a spreadsheet would run as a formula get a leading single quote
(``catalogue.csvio.neutralised``, as the catalogue export does). Column names, check names,
statuses and verdicts are the API's identifiers, numbers have a decimal point, the same
in every language: the CSV is data for programs and spreadsheets.

**PDF** (A4, page numbers, ``documents/report_pdf.py``): a first page a reader can sign
(the inputs in words, the cycle and speed/torque diagrams, the first-ranked candidate's
checks, the top five with their utilisation), then the checks of the candidates asked
for (``?candidates=``), in the request's language.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import date
from typing import Any, Protocol

from markupsafe import Markup
from sqlalchemy.orm import Session

from actuator_selection.catalogue.csvio import neutralised
from actuator_selection.db.repositories import CatalogueRepository
from actuator_selection.errors import NotFoundError
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.quotes import StoredCandidate, StoredSelection, cycle_facts
from actuator_selection.services.errors import invalid, not_found
from actuator_selection.services.selections import stored_answer_json
from actuator_selection.sizing.checks import margin_percent

SELECTION_COLUMNS = (
    "selection_id",
    "catalogue_version",
    "load_speed_rpm",
    "load_torque_nm",
    "load_inertia_kgm2",
    "high_dynamics",
    "accel_s",
    "constant_s",
    "decel_s",
    "pause_s",
    "cycle_time_s",
    "mean_speed_rpm",
    "duty_cycle_percent",
)
"""The selection's figures, the same on every row."""
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
    "utilisation_percent",
    "approximate",
    "missing",
)
"""A candidate's and one of its checks' columns."""
COLUMNS = SELECTION_COLUMNS + CHECK_COLUMNS
"""The CSV's one header row; a segment cycle's segments stand between the two
(``segment_1_duration_s``, ``segment_1_start_rpm``, ``segment_1_end_rpm``, …)."""

TOP = 5
"""How many candidates the report's first page ranks."""

UTILISATION_CHECKS = ("peak_torque", "continuous_duty", "max_speed")
"""The checks whose utilisation the first page's ranking shows: T₁/T_max (Eq. 514.1),
(n_av, T_rms) against the continuous limit (Fig. 517.1), n₂/n_max."""


def utilisation_percent(value: float | None, limit: float | None) -> float | None:
    """value/limit [%]: how much of its limit a check uses; None without a value or a
    positive limit.

    >>> round(utilisation_percent(95.48, 151.0), 2)
    63.23
    """
    if value is None or limit is None or limit <= 0:
        return None
    return value / limit * 100.0


@dataclass(frozen=True, slots=True)
class SelectionReport:
    """A stored selection as the report shows it."""

    selection: StoredSelection
    actuator: dict[str, Any] | None = None
    """The first-ranked candidate's catalogue entry (its continuous-duty zone for the
    diagram), None where the catalogue no longer has it."""
    detailed: tuple[str, ...] = ()
    """The models whose checks the PDF details after its first page."""

    @property
    def top(self) -> list[StoredCandidate]:
        """The first :data:`TOP` candidates in the answer's order."""
        return self.selection.candidates[:TOP]

    def detailed_candidates(self) -> list[tuple[int, StoredCandidate]]:
        """(rank, candidate) of each model asked for, in the answer's order."""
        return [
            (rank, c)
            for rank, c in enumerate(self.selection.candidates, start=1)
            if c.model in self.detailed
        ]

    @staticmethod
    def utilisation(candidate: StoredCandidate, check: str) -> float | None:
        """The utilisation [%] of ``candidate``'s check ``check`` (value/limit)."""
        found = next((c for c in candidate.checks if c.name == check), None)
        return None if found is None else utilisation_percent(found.value, found.limit)


def selection_report(
    session: Session, selection_id: str, candidates: Sequence[str] = ()
) -> SelectionReport:
    """The report of a stored selection, detailing ``candidates``; 404 when there is no
    such selection, 422 naming a model that is not among its candidates."""
    stored = stored_answer_json(session, selection_id)
    if stored is None:
        raise not_found(["path", "selection_id"], "unknown_selection", selection_id=selection_id)
    selection = StoredSelection.model_validate(stored)
    models = {c.model for c in selection.candidates}
    for k, model in enumerate(candidates):
        if model not in models:
            raise invalid(["query", "candidates", k], "unknown_actuator", "unknown", model=model)
    actuator = None
    if selection.candidates:
        record = CatalogueRepository(session).actuator(selection.candidates[0].model)
        if record is not None:
            actuator = ActuatorOut.from_record(record).model_dump(mode="json")
    return SelectionReport(selection, actuator, tuple(dict.fromkeys(candidates)))


@dataclass(frozen=True, slots=True)
class CandidateDiagram:
    """What the speed/torque diagram of one candidate is drawn from: the stored selection,
    the candidate in it, and the actuator's catalogue entry (None: left out or unknown)."""

    selection: StoredSelection
    candidate: StoredCandidate
    actuator: dict[str, Any] | None


def candidate_diagram(
    session: Session, selection_id: str, model: str, *, catalogue: bool = True
) -> CandidateDiagram:
    """The diagram's inputs for ``model`` in a stored selection, with its catalogue entry
    unless ``catalogue`` is false; 404 for an unknown selection or a model that is not one
    of its candidates."""
    stored = stored_answer_json(session, selection_id)
    if stored is None:
        raise not_found(["path", "selection_id"], "unknown_selection", selection_id=selection_id)
    selection = StoredSelection.model_validate(stored)
    candidate = next((c for c in selection.candidates if c.model == model), None)
    if candidate is None:
        raise NotFoundError(
            "model", f"{model!r} is no candidate of selection {selection_id!r}", where="path"
        )
    actuator = None
    if catalogue and (record := CatalogueRepository(session).actuator(model)) is not None:
        actuator = ActuatorOut.from_record(record).model_dump(mode="json")
    return CandidateDiagram(selection, candidate, actuator)


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
    s = report.selection
    cycle = s.cycle
    selection = [
        s.id,
        s.catalogue_version,
        s.load.speed_rpm,
        s.load.torque_nm,
        s.load.inertia_kgm2,
        s.high_dynamics,
        cycle.accel_s,
        cycle.constant_s,
        cycle.decel_s,
        cycle.pause_s,
        s.cycle_time_s,
        s.mean_speed_rpm,
        s.duty_cycle_percent,
    ]
    # A segment cycle's segments: their columns after the selection's (times are empty).
    segments = [] if cycle.is_trapezoid else cycle_facts(cycle, s.segments)
    selection += [value for _, _, value, _ in segments]
    buffer = io.StringIO()
    buffer.write("\ufeff")
    writer = csv.writer(buffer, lineterminator="\r\n")
    writer.writerow((*SELECTION_COLUMNS, *(key for key, *_ in segments), *CHECK_COLUMNS))
    for rank, c in enumerate(s.candidates, start=1):
        head = [
            *selection,
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
                utilisation_percent(check.value, check.limit),
                check.approximate,
                check.missing,
            ]
            writer.writerow([_cell(v) for v in row])
    return buffer.getvalue()


class ReportWords(Protocol):
    """The words and number formats of one language, as the quote document has them
    (``documents.quote_document_text.DocumentText``)."""

    @property
    def language(self) -> str:
        """``en`` or ``de``."""
        ...

    def __call__(self, key: str, **params: object) -> str:
        """The label ``key`` with ``params`` filled in."""
        ...

    def number(self, value: float, pattern: str) -> str:
        """``value`` by a CLDR number pattern, the minus sign before a negative one."""
        ...

    def load_rows(self, load: Mapping[str, Any]) -> list[tuple[Markup, str]]:
        """The load as entered (a stored request's ``load``), field by field, worded."""
        ...

    def words(self, key: str, **params: object) -> Markup:
        """The label ``key`` with its symbols subscripted (``documents.symbols``)."""
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
