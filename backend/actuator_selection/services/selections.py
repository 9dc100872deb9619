"""Selections: size a load case against the catalogue, store it, read it back.

The engine ranks the candidates; the answer is built from its results by the
selection presenter (``services/presenters/selection.py``, its contract
``SelectionOut``). The full detail of one candidate (every check in words, every
criterion of Table 521.1) is computed on request from the stored load case
(:func:`candidate_detail`, presented by ``services/presenters/detail.py``).

A stored selection is its request, its catalogue version and its answer, the answer
gzip-compressed as it was sent (the starter catalogue's answer: 49 kB, 6.8 kB stored),
with the version of the answer's shape (:data:`~.presenters.selection.ANSWER_VERSION`).
"""

from __future__ import annotations

import gzip
import uuid
from collections.abc import Callable, Iterable, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from datetime import datetime
from typing import Any

import numpy as np
import orjson
from sqlalchemy.orm import Session

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.engine import (
    VERDICT_BY_CODE,
    evaluate_batch,
)
from actuator_selection.core.errors import ConflictError, NotFoundError
from actuator_selection.core.motion import SegmentTorque
from actuator_selection.core.selection import Application, Verdict, evaluate, select
from actuator_selection.db.repositories import (
    CatalogueRepository,
    NewSelection,
    SelectionRepository,
)
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.checks import Localize, english
from actuator_selection.schemas.selections import CandidateDetailOut, SelectionRequest
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot, DriveContext
from actuator_selection.services.presenters import selection as presenter
from actuator_selection.services.presenters.detail import (
    candidate_detail as candidate_detail_answer,
)
from actuator_selection.services.presenters.selection import (
    CHECKS_AS_DICTS_UP_TO,
    JSON,
    checks_as_dicts,
    checks_of,
    dump_json,
    or_none,
)
from actuator_selection.services.ratio import guidance

STORE_COMPRESSION = 1
"""gzip level of stored answers, compressed once for the row and for the answer to a
client that accepts gzip. The starter catalogue's whole answer: 49 kB of JSON, 6.8 kB
at level 1 in 0.08 ms (level 6: 5.6 kB in 0.35 ms)."""

Writer = Callable[[], AbstractContextManager[Session]]
"""Opens a short write transaction that commits when its block ends."""


@dataclass(frozen=True, slots=True)
class SizedSelection:
    """A selection computed for storing: the request and the answer, as JSON."""

    id: str
    created_at: datetime
    catalogue_version: int
    request: JSON
    answer: bytes
    """The answer's JSON."""
    answer_gzip: bytes
    """The same, gzip-compressed: stored, and sent to clients that accept gzip."""

    @property
    def row(self) -> NewSelection:
        """What is stored of it."""
        return NewSelection(
            id=self.id,
            created_at=self.created_at,
            catalogue_version=self.catalogue_version,
            request=self.request,
            answer_gzip=self.answer_gzip,
            answer_version=presenter.ANSWER_VERSION,
        )


@dataclass(frozen=True, slots=True)
class _Ranked:
    """The candidates of one case, best first, as the answer lists them."""

    actuators: list[Actuator]
    verdicts: list[Verdict]
    torques: list[tuple[float | None, float | None, float | None, float | None]]
    """T_1, T_2, T_3, T_rms; None without J_A (T_2 also where the cycle never runs
    steadily)."""
    checks: list[Any]
    """Per candidate, its checks: a list of dicts, or their JSON (``orjson.Fragment``)."""
    check_dicts: Callable[[], list[list[JSON]]]
    """Per candidate, its checks as dicts (made when asked: :func:`presenter.binding`)."""


def _ranked(
    actuators: Sequence[Actuator], app: Application, catalogue: CatalogueSnapshot
) -> _Ranked:
    """The candidates of ``app`` over ``actuators``, ranked: the engine's 1 × N view of one
    case, whatever the number of actuators."""
    ev = evaluate_batch(actuators, [app], arrays=catalogue.arrays(tuple(actuators)))
    torques = (ev.accel_torque_nm[0], ev.decel_torque_nm[0], ev.rms_torque_nm[0])
    if any(np.isinf(t).any() for t in torques):
        # Finite inputs that overflow a torque: the ranked candidates' torques name the
        # input (422).
        select(actuators, app)
    order = np.array(ev.ranking(0), dtype=np.intp)
    checks = checks_of(ev)
    places = order.tolist()

    def check_dicts() -> list[list[JSON]]:
        rows = checks if len(checks) <= CHECKS_AS_DICTS_UP_TO else checks_as_dicts(ev)
        return [rows[j] for j in places]

    return _Ranked(
        actuators=[actuators[j] for j in places],
        verdicts=[VERDICT_BY_CODE[v] for v in ev.verdicts[0][order].tolist()],
        torques=list(
            zip(
                or_none(ev.accel_torque_nm[0][order]),
                or_none(ev.constant_torque_nm[0][order]),
                or_none(ev.decel_torque_nm[0][order]),
                or_none(ev.rms_torque_nm[0][order]),
                strict=True,
            )
        ),
        checks=[checks[j] for j in places],
        check_dicts=check_dicts,
    )


def _candidates(
    actuators: Sequence[Actuator],
    app: Application,
    catalogue: CatalogueSnapshot,
    groups: presenter.DriveOptionGroups,
) -> tuple[list[JSON], JSON | None]:
    """Every actuator's candidate for ``app``, ranked (``core.candidates.ranking_key``)
    by the engine; a candidate's detail is the engine's 1 × 1 view, with the checks in
    words."""
    speed = app.profile.peak_speed_rpm  # computed first: the engine takes its figures
    ranked = _ranked(actuators, app, catalogue)
    candidates = presenter.candidates(
        ranked.actuators,
        ranked.verdicts,
        ranked.torques,
        ranked.checks,
        catalogue=catalogue,
        groups=groups,
        speed_rpm=speed,
    )
    return candidates, presenter.binding(ranked.actuators, ranked.verdicts, ranked.check_dicts, app)


def size_selection(
    body: SelectionRequest,
    app: Application,
    actuators: Sequence[Actuator],
    catalogue: CatalogueSnapshot,
    created_at: datetime,
    *,
    guide: bool = False,
) -> SizedSelection:
    """The whole ranking of ``app`` over ``actuators`` as POST /selections answers it;
    ``guide``: where nothing fits, with the ratio study's leads or diameters that make an
    actuator fit (``binding.transmissions``; a batch's cases go without)."""
    groups = presenter.DriveOptionGroups(catalogue)
    candidates, binding = _candidates(actuators, app, catalogue, groups)
    if binding is not None and guide:  # nothing fits: where the load's own lead or
        binding["transmissions"] = guidance(body, actuators)  # diameter would
    # The selection request's fields alone (a batch case's ``case_id`` is the batch's).
    request = body.model_dump(mode="json", include=set(SelectionRequest.model_fields))
    answer = presenter.selection_answer(
        id=str(uuid.uuid4()),
        created_at=created_at,
        catalogue_version=catalogue.version,
        body=body,
        request=request,
        profile=app.profile,
        rules=app.rules,
        controllers=groups.refs(),
        candidates=candidates,
        binding=binding,
    )
    encoded = dump_json(answer)
    return SizedSelection(
        id=answer["id"],
        created_at=created_at,
        catalogue_version=catalogue.version,
        request=request,
        answer=encoded,
        answer_gzip=gzip.compress(encoded, compresslevel=STORE_COMPRESSION, mtime=0),
    )


def store_selections(writer: Writer, sized: Iterable[SizedSelection]) -> None:
    """Store selections in one short write transaction, committed before this returns.

    The answers were compressed when they were sized (:attr:`SizedSelection.answer_gzip`),
    before the transaction begins: on SQLite the write lock is held for the inserts alone.
    """
    with writer() as session:
        repository = SelectionRepository(session)
        for s in sized:
            repository.add(s.row)


def create_selection(
    body: SelectionRequest,
    *,
    catalogue: CatalogueCache,
    reader: Writer,
    writer: Writer,
    now: datetime,
    check: Callable[[CatalogueSnapshot], None],
) -> SizedSelection:
    """Size ``body`` against the catalogue and store it; returns what was committed.

    The catalogue is the one this process holds in memory: no read precedes the sizing.
    Its version is checked where it matters, in the statement that stores the selection
    (:meth:`~actuator_selection.db.repositories.SelectionRepository.add_at_version`), so
    a request costs one short write transaction. When a catalogue change (from any
    process) has raised the version meanwhile, nothing was stored: the selection is
    sized again in that same transaction, against the catalogue at the version it pins,
    which no change can raise before it commits. So every stored selection is its
    catalogue version's answer, and a stream of catalogue changes cannot starve it.
    ``check`` refuses a request the catalogue cannot answer (unknown models), but never
    on the strength of the snapshot held alone: a model it lacks may have been created
    since (by any process), so the version is read first, and the catalogue with it
    when it has changed (:meth:`~CatalogueCache.refresh`). Only models the current
    catalogue lacks are refused.
    """
    held = catalogue.latest(reader)
    if not held.has_all(body.models):
        held = catalogue.refresh(reader)
    sized = _sized(body, held, now, check)
    with writer() as session:
        repository = SelectionRepository(session)
        if not repository.add_at_version(sized.row):
            sized = _sized(body, catalogue.pinned(session), now, check)
            stored = repository.add_at_version(sized.row)
            assert stored, "the version is pinned by this transaction"
    return sized


def _sized(
    body: SelectionRequest,
    catalogue: CatalogueSnapshot,
    now: datetime,
    check: Callable[[CatalogueSnapshot], None],
) -> SizedSelection:
    check(catalogue)
    return size_selection(
        body, body.to_core(), catalogue.actuators_of(body.models), catalogue, now, guide=True
    )


def stored_answer(session: Session, selection_id: str) -> bytes:
    """The stored answer of a selection, gzip-compressed as stored."""
    stored = SelectionRepository(session).answer_gzip(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    return stored


def stored_request(session: Session, selection_id: str) -> JSON:
    """The stored request of a selection: its fields as it was asked, defaults stated."""
    stored = SelectionRepository(session).request(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    return stored[0]


def stored_answer_json(session: Session, selection_id: str) -> JSON | None:
    """The stored answer of a selection as JSON data, or None; an answer of an older
    shape than :data:`~.presenters.selection.ANSWER_VERSION` (its upgrade, a migration,
    not run) is an error."""
    stored = SelectionRepository(session).answer(selection_id)
    if stored is None:
        return None
    answer, version = stored
    if version != presenter.ANSWER_VERSION:
        raise RuntimeError(
            f"selection {selection_id!r} holds an answer of version {version}, not "
            f"{presenter.ANSWER_VERSION}: upgrade the database "
            "(python -m actuator_selection migrate)"
        )
    data: JSON = orjson.loads(gzip.decompress(answer))
    return data


def stored_candidate(
    session: Session, catalogue: CatalogueSnapshot, selection_id: str, model: str, *, what: str
) -> tuple[SelectionRequest, Actuator]:
    """The stored load case of a selection and one of its candidates' actuator, for what
    is computed again from them (``what``: the detail, the limits).

    The flowchart is deterministic, so a candidate computed again is the stored answer's,
    as long as the catalogue is the one the selection used; after a catalogue change it
    would not be, and the caller is told to run the selection again (409).
    """
    stored = SelectionRepository(session).request(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    request, version = stored
    if version != catalogue.version:
        raise ConflictError(
            "selection_id",
            f"the catalogue has changed since this selection (version {version}, now "
            f"{catalogue.version}); run the selection again for {what}",
            where="path",
        )
    body = SelectionRequest.model_validate(request)
    actuator = next((a for a in catalogue.actuators_of([model])), None)
    if actuator is None or (body.models is not None and model not in body.models):
        raise NotFoundError(
            "model", f"{model!r} is no candidate of selection {selection_id!r}", where="path"
        )
    return body, actuator


def segment_torques(
    session: Session, catalogue: CatalogueSnapshot, selection_id: str, model: str
) -> tuple[SegmentTorque, ...] | None:
    """The torque along each segment of a stored selection's cycle for one of its
    candidates, computed again from its load case (:func:`stored_candidate`), as the detail
    gives it; None where the catalogue has no J_A for the actuator."""
    body, actuator = stored_candidate(
        session, catalogue, selection_id, model, what="the torque along the cycle"
    )
    j_a = actuator.inertia_kgm2
    return None if j_a is None else body.to_core().profile.segment_torques(j_a)


def candidate_detail(
    session: Session,
    catalogue: CatalogueSnapshot,
    selection_id: str,
    model: str,
    localize: Localize = english,
) -> CandidateDetailOut:
    """One candidate of a stored selection in full, computed again from its load case
    (:func:`stored_candidate`), its check messages in words by ``localize``."""
    body, actuator = stored_candidate(session, catalogue, selection_id, model, what="the detail")
    return detail_of(session, catalogue, body, actuator, selection_id, localize)


def detail_of(
    session: Session,
    catalogue: CatalogueSnapshot,
    body: SelectionRequest,
    actuator: Actuator,
    selection_id: str,
    localize: Localize = english,
) -> CandidateDetailOut:
    """``actuator`` in full for the load case ``body`` (a stored selection's, or a machine
    project's axis, named ``selection_id`` in the answer)."""
    model = actuator.model
    record = CatalogueRepository(session).actuator(model)
    if record is None:  # pragma: no cover - the snapshot and the table agree
        raise NotFoundError("model", f"no actuator {model!r}", where="path")
    version = catalogue.version
    app = body.to_core()
    return candidate_detail_answer(
        selection_id=selection_id,
        catalogue_version=version,
        candidate=evaluate(actuator, app, arrays=catalogue.arrays((actuator,))),
        profile=app.profile,
        drive=DriveContext(catalogue).options(actuator, speed_rpm=app.profile.peak_speed_rpm),
        actuator=ActuatorOut.from_record(record),
        localize=localize,
    )
