"""Batch selection: the flowchart for thousands of load cases in one request (ERP).

The cases are ranked by the engine (``sizing.engine``), which details the
best ``top`` of each from the same arrays; the answer is written as JSON slice by slice
(:data:`STREAM_CASES` cases at a time) while it is sent, so memory stays flat in the
number of cases. Cases asked to be stored are sized as POST /selections sizes them and
committed before the first slice is returned.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterator, Sequence
from datetime import UTC, datetime
from typing import Any, NamedTuple

import numpy as np
import pydantic_core

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.phrases.check_messages import Wording
from actuator_selection.schemas.batch import (
    MAX_BATCH_CANDIDATES,
    MAX_CANDIDATES_WITH_CONTROLLERS,
    MAX_STORED_CASES,
    BatchSelectionRequest,
)
from actuator_selection.schemas.checks import Localize
from actuator_selection.schemas.controllers import DriveOptionBodies, controllers_note
from actuator_selection.schemas.selections import RANKING_RULE
from actuator_selection.services.catalogue import CatalogueSnapshot, DriveContext
from actuator_selection.services.errors import UseCaseError, entry
from actuator_selection.services.presenters.batch import (
    CodedChecks,
    actuator_body,
    batch_candidate_body,
    coded_checks_json,
    coded_summary,
    controllers_summary,
    members_json,
    result_body,
    worded_reasons,
)
from actuator_selection.services.presenters.batch_rows import (
    Column,
    candidate_columns,
    case_loads,
    case_rows,
    json_texts,
    pieces,
    rows,
)
from actuator_selection.services.presenters.selection import dump_json, json_items
from actuator_selection.services.selections import (
    Writer,
    size_selection,
    store_selections,
)
from actuator_selection.sizing.checks import Rule, rules_for
from actuator_selection.sizing.engine import (
    VERDICT_BY_CODE,
    CatalogueArrays,
    RankedCells,
    ranked_cells,
    select_batch,
)
from actuator_selection.sizing.engine.detail import DecidedCells
from actuator_selection.sizing.selection import VALUE_OF, Application, Selection


def too_many_candidates(cases: int, top: int) -> list[dict[str, Any]]:
    """The error entry, if ``cases`` × ``top`` is beyond what one answer holds."""
    if cases * top <= MAX_BATCH_CANDIDATES:
        return []
    return [
        entry(
            ["body", "top"],
            "too_many_candidates",
            "too_many_candidates",
            max=MAX_BATCH_CANDIDATES,
            cases=cases,
            top=top,
        )
    ]


def check_limits(body: BatchSelectionRequest) -> None:
    """Refuse a request beyond the limits that depend on more than one of its fields (422)."""
    errors: list[dict[str, Any]] = []
    n = len(body.cases)
    if body.store and n > MAX_STORED_CASES:
        errors.append(
            entry(
                ["body", "store"],
                "too_many_to_store",
                "too_many_to_store",
                max=MAX_STORED_CASES,
                cases=n,
            )
        )
    errors += too_many_candidates(n, body.top)
    if body.include_controllers and n * body.top > MAX_CANDIDATES_WITH_CONTROLLERS:
        errors.append(
            entry(
                ["body", "include_controllers"],
                "too_many_candidates",
                "too_many_with_controllers",
                max=MAX_CANDIDATES_WITH_CONTROLLERS,
                cases=n,
                top=body.top,
            )
        )
    if errors:
        raise UseCaseError(errors)


class BatchAnswer(NamedTuple):
    """A batch's answer: its JSON, slice by slice, and the ids of the cases it stored."""

    chunks: Iterator[bytes]
    stored: list[str]


def size_batch(
    body: BatchSelectionRequest,
    apps: list[Application],
    *,
    catalogue: CatalogueSnapshot,
    writer: Writer,
    localize: Localize,
) -> BatchAnswer:
    """The answer to ``body`` (within :func:`check_limits`, which the caller checks
    before it turns the cases into ``apps``) as JSON, slice by slice. It takes the cases
    out of ``body`` (``body.cases`` is empty afterwards): only ``apps`` stay in memory.

    Cases to be stored are stored (in a write transaction of ``writer``) and the first
    slice is computed before this returns, so that a fault there is still an error
    answer and a 2xx means the cases are committed; the rest is computed while the
    answer is sent.
    """
    ids: list[str | None] = [None] * len(apps)
    if body.store:
        ids = _store(body, apps, catalogue, writer)
    chunks = _result_chunks(_Cases.taken(body, apps, ids, catalogue, localize))
    head = (
        b'{"catalogue_version":'
        + pydantic_core.to_json(catalogue.version)
        + b',"ranking":'
        + pydantic_core.to_json(RANKING_RULE)
        + b',"results":['
    )
    first = next(chunks, b"")
    body_chunks = itertools.chain((head + first,), chunks, (b"]}",))
    return BatchAnswer(body_chunks, [i for i in ids if i is not None])


class Drives:
    """Drive options of the candidates answered, each computed once per request."""

    def __init__(self, context: DriveContext, localize: Localize) -> None:
        self._context = context
        self._summaries: dict[str, dict[str, Any]] = {}
        self._coded: dict[str, dict[str, Any]] = {}
        self._localize = localize
        self._lists: dict[tuple[str, float], list[dict[str, Any]]] = {}
        self._bodies = DriveOptionBodies(localize)  # criteria and voltage checks in words

    def summary(self, actuator: Actuator, speed_rpm: float) -> dict[str, Any]:
        """``controllers_excluded`` and ``controllers_note`` (:func:`controllers_summary`).

        Both rest on the Table 521.1 matching alone, which depends on the actuator and
        not on the load speed, so one computation per model serves every case.
        """
        found = self._summaries.get(actuator.model)
        if found is None:
            drive = self._context.options(actuator, speed_rpm=speed_rpm)
            found = self._summaries[actuator.model] = controllers_summary(
                drive.excluded, controllers_note(drive), self._localize
            )
        return found

    def coded_summary(self, actuator: Actuator, speed_rpm: float) -> dict[str, Any]:
        """:meth:`summary` less its words (:func:`coded_summary`)."""
        found = self._coded.get(actuator.model)
        if found is None:
            found = self._coded[actuator.model] = coded_summary(self.summary(actuator, speed_rpm))
        return found

    def controllers(self, actuator: Actuator, speed_rpm: float) -> list[dict[str, Any]]:
        """The ``controllers`` list of a single selection at load speed n_2."""
        key = (actuator.model, speed_rpm)
        found = self._lists.get(key)
        if found is None:
            drive = self._context.options(actuator, speed_rpm=speed_rpm)
            found = self._lists[key] = [
                o.model_dump(mode="json") for o in self._bodies.controllers(drive)
            ]
        return found


def _store(
    body: BatchSelectionRequest,
    apps: list[Application],
    catalogue: CatalogueSnapshot,
    writer: Writer,
) -> list[str | None]:
    """Store each case as POST /selections does (the whole ranking); their ids.

    The selections are computed first and then written in a transaction of ``writer``,
    so on SQLite the write lock is held for the inserts alone.
    """
    created_at = datetime.now(UTC)
    sized = [
        size_selection(case, app, catalogue.actuators_of(case.models), catalogue, created_at)
        for case, app in zip(body.cases, apps, strict=True)
    ]
    store_selections(writer, sized)
    return [s.id for s in sized]


def _candidates(
    selection: Selection,
    speed_rpm: float,
    body: BatchSelectionRequest,
    drives: Drives,
    localize: Localize,
    coded: CodedChecks,
) -> list[dict[str, Any]]:
    out = []
    summary = drives.summary if body.include_messages else drives.coded_summary
    for c in selection.candidates:
        out.append(
            batch_candidate_body(
                c,
                include_checks=body.include_checks,
                include_messages=body.include_messages,
                controllers=(
                    drives.controllers(c.actuator, speed_rpm) if body.include_controllers else None
                ),
                controllers_summary=summary(c.actuator, speed_rpm),
                localize=localize,
                coded=coded,
            )
        )
    return out


STREAM_CASES = 200
"""Cases computed and written per slice of a batch answer: memory stays flat in the
number of cases (20,000 cases peaked at 622 MB when the answer was built whole). Each
slice has a fixed cost (the engine's and the writer's numpy calls per block, rule and
shape of a message): without words, 10,000 cases with checks took about a tenth less
CPU in slices of 500, but held 37 MB of Python objects at their peak against 15 MB
(tracemalloc), and a server's peak RSS for 20,000 cases rose from 212 to 233 MB; with
words a slice of 500 held 67 MB, one of 200 27 MB (2026-11-27). Kept at 200."""


def _by_rules(apps: list[Application]) -> dict[tuple[Rule, ...], list[int]]:
    """The indexes of the cases by the checks they need (a brake adds one), in order."""
    groups: dict[tuple[Rule, ...], list[int]] = {}
    for i, app in enumerate(apps):
        groups.setdefault(rules_for(app), []).append(i)
    return groups


def _select(
    actuators: Sequence[Actuator],
    arrays: CatalogueArrays,
    apps: list[Application],
    models: Sequence[list[str] | None],
    top: int,
) -> list[Selection]:
    """``select_batch`` for cases whose checks may differ (a brake adds one): each set of
    checks run on its own cases, the selections back in the order of the cases;
    ``arrays`` the catalogue's (the snapshot's, built once per version)."""
    out: list[Selection | None] = [None] * len(apps)
    for rules, indexes in _by_rules(apps).items():
        chosen = select_batch(
            actuators,
            [apps[i] for i in indexes],
            top=top,
            models=[models[i] for i in indexes],
            rules=rules,
            arrays=arrays,
        )
        for i, selection in zip(indexes, chosen, strict=True):
            out[i] = selection
    return [s for s in out if s is not None]


class _Cases(NamedTuple):
    """A batch's cases and what answering them needs, their request models let go."""

    body: BatchSelectionRequest
    actuators: tuple[Actuator, ...]
    arrays: CatalogueArrays
    apps: list[Application]
    models: list[list[str] | None]
    ids: list[tuple[str | None, str | None]]
    """Each case's stored selection's id (None: not stored) and ``case_id``."""
    drives: Drives
    localize: Localize

    @classmethod
    def taken(
        cls,
        body: BatchSelectionRequest,
        apps: list[Application],
        ids: list[str | None],
        catalogue: CatalogueSnapshot,
        localize: Localize,
    ) -> _Cases:
        """The cases of ``body`` (as the core sees them: ``apps``) with their stored
        ``ids``, taken out of ``body``: their request models (36 MB for 20,000 cases)
        are let go before the answer streams, which keeps the peak memory of a large
        batch down."""
        actuators = tuple(catalogue.actuators)
        models = [case.models for case in body.cases]
        case_ids = [case.case_id for case in body.cases]
        body.cases.clear()
        return cls(
            body,
            actuators,
            catalogue.arrays(actuators),
            apps,
            models,
            list(zip(ids, case_ids, strict=True)),
            Drives(DriveContext(catalogue), localize),
            localize,
        )


def _result_chunks(cases: _Cases) -> Iterator[bytes]:
    """The ``results`` array's JSON, :data:`STREAM_CASES` cases at a time, comma-joined.

    These dicts are BatchSelectionOut's JSON (the tests validate them); validating
    them again as models would take longer than the whole flowchart.
    """
    apps = cases.apps
    for start in range(0, len(apps), STREAM_CASES):
        part = slice(start, start + STREAM_CASES)
        written = _from_arrays(cases, part, each=False)
        if written is not None:
            if not start:  # the answer's first case: no comma before it
                written[0] = written[0][1:]
            yield b"".join(written)
            continue
        yield (b"," if start else b"") + b",".join(_worded(cases, part))


def worded_results(
    body: BatchSelectionRequest,
    apps: list[Application],
    *,
    catalogue: CatalogueSnapshot,
    localize: Localize,
) -> Iterator[bytes]:
    """Each case's entry of ``results`` in words (as with ``include_messages``), one JSON
    text a case in the cases' order, nothing stored: what :func:`size_batch` writes
    between the commas of ``results``, for a batch job's chunk, which writes a line a
    case (``services.jobs.chunk_answer``) and so need not read an answer back. ``body``
    asks for the words (``include_messages``)."""
    if not body.include_messages:
        raise ValueError("worded_results writes the words: include_messages must be set")
    cases = _Cases.taken(body, apps, [None] * len(apps), catalogue, localize)
    for start in range(0, len(apps), STREAM_CASES):
        part = slice(start, start + STREAM_CASES)
        written = _from_arrays(cases, part, each=True)
        yield from _worded(cases, part) if written is None else written


def _from_arrays(cases: _Cases, part: slice, *, each: bool) -> list[bytes] | None:
    """:func:`_ranked_results` of the cases ``part``, where they can be written from the
    ranking's arrays: without words, or in the words of a :class:`Wording` (a
    language's, not any function of a message); else None."""
    body, words = cases.body, None
    if body.include_messages:
        if not isinstance(cases.localize, Wording):
            return None
        words = cases.localize
    return _ranked_results(
        body,
        cases.actuators,
        cases.arrays,
        cases.apps[part],
        cases.models[part],
        cases.ids[part],
        cases.drives,
        words,
        each=each,
    )


def _worded(cases: _Cases, part: slice) -> list[bytes]:
    """The entries of ``results`` of the cases ``part``, in words, one JSON text each."""
    body = cases.body
    selections = _select(
        cases.actuators, cases.arrays, cases.apps[part], cases.models[part], body.top
    )
    coded = CodedChecks()  # the slice's checks, written from the engine's arrays
    return [
        dump_json(
            result_body(
                id=id_,
                case_id=case_id,
                selection=selection,
                candidates=_candidates(
                    selection,
                    selection.profile.peak_speed_rpm,
                    body,
                    cases.drives,
                    cases.localize,
                    coded,
                ),
            )
        )
        for (id_, case_id), selection in zip(cases.ids[part], selections, strict=True)
    ]


def _ranked_results(
    body: BatchSelectionRequest,
    actuators: Sequence[Actuator],
    arrays: CatalogueArrays,
    apps: list[Application],
    models: Sequence[list[str] | None],
    ids: list[tuple[str | None, str | None]],
    drives: Drives,
    words: Wording | None,
    *,
    each: bool,
) -> list[bytes] | None:
    """The cases' entries of ``results`` as JSON, written from the ranking's arrays
    (``sizing.engine.ranked_cells``) with no profile per case and no candidate per cell:
    the bytes :func:`result_body` of :func:`_select`'s selections gives, without words
    (``words`` None) or in ``words``' language. With ``each``, one JSON text a case;
    else pieces that, joined, are the cases each after a comma: where every case needs
    the same checks, the pieces of every case in turn (``batch_rows.pieces``), else each
    case's text. None where a cycle's figures or a candidate's torques are not finite:
    the selections then raise the error that names the input."""
    groups = _by_rules(apps)
    whole = len(groups) == 1 and not each
    out: list[bytes] = [] if whole else [b""] * len(apps)
    for rules, indexes in groups.items():
        cases = [apps[i] for i in indexes]
        for ranked in ranked_cells(
            actuators,
            cases,
            top=body.top,
            models=[models[i] for i in indexes],
            rules=rules,
            arrays=arrays,
        ):
            n = len(ranked.counts)
            columns = _ranked_json(
                ranked,
                actuators,
                cases[ranked.start : ranked.start + n],
                [ids[i] for i in indexes[ranked.start : ranked.start + n]],
                body,
                drives,
                words,
            )
            if columns is None:
                return None
            if whole:  # the blocks in the cases' order
                out += pieces(columns, n)
                continue
            for k, row in enumerate(rows(columns, n)):
                out[indexes[ranked.start + k]] = b"".join(row)
    if each:  # each case's text, not after a comma
        return [case[1:] for case in out]
    return out


def _ranked_json(
    ranked: RankedCells,
    actuators: Sequence[Actuator],
    apps: list[Application],
    ids: list[tuple[str | None, str | None]],
    body: BatchSelectionRequest,
    drives: Drives,
    words: Wording | None,
) -> list[Column] | None:
    """:func:`_ranked_results` of one block of cases ranked, as columns over its cases
    (``batch_rows.case_rows``): each member written as JSON over the cells or cases at
    once."""
    f = ranked.figures
    if not all(
        np.isfinite(a).all()
        for a in (f.mean_speed_rpm, f.accel_floor_nm, f.decel_floor_nm, f.rms_floor_nm)
    ):
        return None  # profile_from raises the error that names the input
    columns = ranked.columns
    # T_1…T_rms where the actuator has J_A (T_2 NaN without a constant piece), else None
    known = np.array([a.inertia_kgm2 is not None for a in actuators], dtype=np.bool_)[columns]
    accel, _, decel, rms = ranked.torques
    if not all(np.isfinite(t[known]).all() for t in (accel, decel, rms)):
        return None  # Profile.torques raises the error that names the input
    torques = [json_items(np.where(known, t, math.nan)) for t in ranked.torques]
    peaks = f.peak_speed_rpm.tolist()
    named, first = np.unique(columns, return_index=True)
    heads = np.empty(len(actuators), dtype=object)
    tails = np.empty(len(actuators), dtype=object)
    summary = drives.coded_summary if words is None else drives.summary
    for j, row in zip(named.tolist(), ranked.rows[first].tolist(), strict=True):
        a = actuators[j]
        heads[j] = members_json(actuator_body(a))
        tails[j] = members_json(summary(a, peaks[row]), comma=True)
    controllers = None
    if body.include_controllers:
        controllers = [
            dump_json(drives.controllers(actuators[column], peaks[row]))
            for row, column in zip(ranked.rows.tolist(), columns.tolist(), strict=True)
        ]
    decided = ranked.decided
    checks: list[bytes] | None = None
    if words is None:
        reasons = None
        if body.include_checks:
            checks = coded_checks_json(decided).checks
    elif body.include_checks:
        written = coded_checks_json(decided, words)
        checks, reasons = written.checks, written.reasons(decided.not_passing)
    else:
        reasons = worded_reasons(decided, words)
    candidates = candidate_columns(
        heads[columns].tolist(),
        _VERDICT_JSON[ranked.verdicts].tolist(),
        torques,
        _reason_checks(decided),
        checks,
        controllers,
        tails[columns].tolist(),
        reasons,
    )
    return case_rows(
        json_texts([id_ for id_, _ in ids]),
        json_texts([case_id for _, case_id in ids]),
        case_loads(apps, f.peak_speed_rpm),
        [json_items(f.cycle_s), json_items(f.mean_speed_rpm), json_items(f.duty_cycle_percent)],
        candidates,
        ranked.counts,
    )


def _reason_checks(decided: DecidedCells) -> list[bytes]:
    """Each cell's ``reason_checks`` as JSON: the names of the checks that do not pass."""
    names = [rule.name for rule in decided.rules]
    written: dict[tuple[int, ...], bytes] = {}
    out = []
    for open_rules in decided.not_passing:
        key = tuple(open_rules)
        found = written.get(key)
        if found is None:
            found = written[key] = dump_json([names[k] for k in key])
        out.append(found)
    return out


_VERDICT_JSON = np.array([dump_json(VALUE_OF[v]) for v in VERDICT_BY_CODE], dtype=object)
"""The API's verdict names as JSON strings, by verdict code."""
