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

import base64
import gzip
import uuid
from collections.abc import Callable, Iterable, Iterator, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from datetime import datetime
from typing import Any

import numpy as np
import numpy.typing as npt
import orjson
from sqlalchemy.orm import Session

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.db.repositories import (
    CatalogueRepository,
    NewSelection,
    SelectionRepository,
)
from actuator_selection.errors import ConflictError, NotFoundError
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.checks import Localize, english
from actuator_selection.schemas.selections import CandidateDetailOut, SelectionRequest
from actuator_selection.services.catalogue import (
    ActuatorColumns,
    CatalogueCache,
    CatalogueSnapshot,
    DriveContext,
)
from actuator_selection.services.errors import invalid, not_found
from actuator_selection.services.presenters import selection as presenter
from actuator_selection.services.presenters.detail import (
    candidate_detail as candidate_detail_answer,
)
from actuator_selection.services.presenters.selection import (
    JSON,
    dump_json,
    or_none,
)
from actuator_selection.services.ratio import guidance
from actuator_selection.sizing.checks import Rule, rules_for
from actuator_selection.sizing.engine import VERDICT_BY_CODE, FloatArray, evaluate_batch
from actuator_selection.sizing.motion import SegmentTorque
from actuator_selection.sizing.selection import Application, Verdict, evaluate, select

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
    ranking: bytes | None = None
    """The ranking beyond the answer's candidates (:func:`presenter.ranking_rest`), or
    None when the answer lists every candidate."""

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
            ranking_zstd=self.ranking,
        )


@dataclass(frozen=True, slots=True)
class _Ranked:
    """The candidates of one case, best first, as the engine ranked them."""

    actuators: list[Actuator]
    verdicts: list[Verdict]
    verdict_codes: npt.NDArray[np.int8]
    """The verdicts as the engine's codes (:data:`VERDICT_BY_CODE`), in the ranking's order."""
    columns: ActuatorColumns
    """The actuators' columns as asked (:meth:`CatalogueSnapshot.columns`)."""
    order: npt.NDArray[np.intp]
    """Where each place of the ranking stands in :attr:`columns`."""
    torques: tuple[FloatArray, FloatArray, FloatArray, FloatArray]
    """T_1, T_2, T_3, T_rms in the ranking's order; NaN without J_A (T_2 also where the
    cycle never runs steadily)."""
    checks: presenter.RankedChecks

    def torques_of(self, start: int, stop: int) -> list[presenter.Torques]:
        """The torques of the candidates ranked ``start`` to ``stop``, None for NaN."""
        return list(zip(*(or_none(t[start:stop]) for t in self.torques), strict=True))

    def rest(self, start: int) -> bytes:
        """:func:`presenter.ranking_rest` from place ``start`` on, its names read from
        :attr:`columns` in the ranking's order at once."""
        at, c = self.order[start:], self.columns
        return presenter.ranking_rest(
            start=start,
            model=c.model[at].tolist(),
            family=c.family[at].tolist(),
            gear_ratio=c.gear_ratio[at].tolist(),
            verdict=_VERDICT_VALUES[self.verdict_codes[start:]].tolist(),
            excluded=c.excluded[at].tolist(),
            torques=self.torques,
            checks=self.checks,
        )


_VERDICTS = np.array(VERDICT_BY_CODE, dtype=object)
"""The verdicts by the engine's code, to index with an array of codes."""
_VERDICT_VALUES = np.array([v.value for v in VERDICT_BY_CODE], dtype=object)
"""Their values as answers write them, likewise."""


def _ranked(
    actuators: Sequence[Actuator],
    app: Application,
    catalogue: CatalogueSnapshot,
    rules: tuple[Rule, ...],
) -> _Ranked:
    """The candidates of ``app`` over ``actuators`` by ``rules`` (``rules_for(app)``),
    ranked: the engine's 1 × N view of one case, whatever the number of actuators."""
    asked = tuple(actuators)
    ev = evaluate_batch(actuators, [app], rules=rules, arrays=catalogue.arrays(asked))
    torques = (ev.accel_torque_nm[0], ev.decel_torque_nm[0], ev.rms_torque_nm[0])
    if np.isinf(torques).any():
        # Finite inputs that overflow a torque: the ranked candidates' torques name the
        # input (422).
        select(actuators, app)
    columns = catalogue.columns(asked)
    if len(asked) == 1:  # one actuator (a one-model selection): ranked as it stands
        order, in_order = _FIRST, _as_they_stand
    else:
        order = np.array(ev.ranking(0), dtype=np.intp)

        def in_order(values: npt.NDArray[Any]) -> npt.NDArray[Any]:
            return values[order]

    codes = in_order(ev.verdicts[0])
    return _Ranked(
        actuators=in_order(columns.actuator).tolist(),
        verdicts=_VERDICTS[codes].tolist(),
        verdict_codes=codes,
        columns=columns,
        order=order,
        torques=(
            in_order(ev.accel_torque_nm[0]),
            in_order(ev.constant_torque_nm[0]),
            in_order(ev.decel_torque_nm[0]),
            in_order(ev.rms_torque_nm[0]),
        ),
        checks=presenter.RankedChecks.of(ev, order, in_order),
    )


_FIRST = np.zeros(1, dtype=np.intp)
"""The ranking of one actuator."""


def _as_they_stand(values: npt.NDArray[Any]) -> npt.NDArray[Any]:
    """Values of one actuator in the ranking's order: as they stand."""
    return values


@dataclass(frozen=True, slots=True)
class _Answered:
    """The candidates an answer lists, the rest of the ranking stored, and the binding."""

    candidates: list[JSON]
    total: int
    counts: dict[str, int]
    rest: bytes | None
    """:func:`presenter.ranking_rest` from the first candidate not listed; None when every
    candidate is listed."""
    binding: JSON | None


def _candidates(
    actuators: Sequence[Actuator],
    app: Application,
    catalogue: CatalogueSnapshot,
    groups: presenter.DriveOptionGroups,
    top: int,
    rules: tuple[Rule, ...],
) -> _Answered:
    """Every actuator's candidate for ``app``, ranked (``sizing.candidates.ranking_key``)
    by the engine: the first ``top`` as the answer lists them, the rest as stored; a
    candidate's detail is the engine's 1 × 1 view, with the checks in words."""
    speed = app.profile.peak_speed_rpm  # computed first: the engine takes its figures
    ranked = _ranked(actuators, app, catalogue, rules)
    total = len(ranked.actuators)
    shown = min(top, total)
    candidates = presenter.candidates(
        ranked.actuators[:shown],
        ranked.verdicts[:shown],
        ranked.torques_of(0, shown),
        ranked.checks.dicts(0, shown),
        catalogue=catalogue,
        groups=groups,
        speed_rpm=speed,
    )
    return _Answered(
        candidates=candidates,
        total=total,
        counts=presenter.verdict_counts(ranked.verdict_codes),
        rest=ranked.rest(shown) if shown < total else None,
        binding=presenter.binding(ranked.actuators, ranked.verdicts, ranked.checks, app),
    )


def size_selection(
    body: SelectionRequest,
    app: Application,
    actuators: Sequence[Actuator],
    catalogue: CatalogueSnapshot,
    created_at: datetime,
    *,
    guide: bool = False,
    top: int = presenter.DEFAULT_TOP,
) -> SizedSelection:
    """The ranking of ``app`` over ``actuators`` as POST /selections answers it: its first
    ``top`` candidates, the rest stored to be paged (:func:`candidate_page`); ``guide``:
    where nothing fits, with the ratio study's leads or diameters that make an actuator
    fit (``binding.transmissions``; a batch's cases go without)."""
    groups = presenter.DriveOptionGroups(catalogue)
    rules = rules_for(app)
    answered = _candidates(actuators, app, catalogue, groups, top, rules)
    binding = answered.binding
    if binding is not None and guide:  # nothing fits: where the load's own lead or
        binding["transmissions"] = guidance(body, actuators, catalogue)  # diameter would
    # The selection request's fields alone (a batch case's ``case_id`` is the batch's).
    request = body.model_dump(mode="json", include=set(SelectionRequest.model_fields))
    id_ = str(uuid.uuid4())
    listed = len(answered.candidates)
    answer = presenter.selection_answer(
        id=id_,
        created_at=created_at,
        catalogue_version=catalogue.version,
        body=body,
        request=request,
        profile=app.profile,
        rules=rules,
        controllers=groups.refs(),
        candidates=answered.candidates,
        total=answered.total,
        counts=answered.counts,
        next_cursor=cursor(id_, listed) if listed < answered.total else None,
        binding=binding,
    )
    encoded = dump_json(answer)
    return SizedSelection(
        id=id_,
        created_at=created_at,
        catalogue_version=catalogue.version,
        request=request,
        answer=encoded,
        answer_gzip=gzip.compress(encoded, compresslevel=STORE_COMPRESSION, mtime=0),
        ranking=answered.rest,
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
    top: int = presenter.DEFAULT_TOP,
) -> SizedSelection:
    """Size ``body`` against the catalogue and store it, its answer listing the first
    ``top`` candidates; returns what was committed.

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
    sized = _sized(body, held, now, check, top)
    with writer() as session:
        repository = SelectionRepository(session)
        if not repository.add_at_version(sized.row):
            sized = _sized(body, catalogue.pinned(session), now, check, top)
            stored = repository.add_at_version(sized.row)
            assert stored, "the version is pinned by this transaction"
    return sized


def _sized(
    body: SelectionRequest,
    catalogue: CatalogueSnapshot,
    now: datetime,
    check: Callable[[CatalogueSnapshot], None],
    top: int,
) -> SizedSelection:
    check(catalogue)
    return size_selection(
        body,
        body.to_core(),
        catalogue.actuators_of(body.models),
        catalogue,
        now,
        guide=True,
        top=top,
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
    """The stored answer of a selection as JSON data with the whole ranking in
    ``candidates`` (those the answer listed, then the rest as stored, without drive
    options), or None; an answer of an older shape than
    :data:`~.presenters.selection.ANSWER_VERSION` (its upgrade, a migration, not run) is
    an error."""
    stored = _stored_ranking(session, selection_id)
    if stored is None:
        return None
    answer, rest = stored
    listed: list[JSON] = answer["candidates"]
    if rest is not None:
        listed.extend(presenter.ranked_candidates(rest, len(listed), answer["total_candidates"]))
    return answer


def _stored_ranking(session: Session, selection_id: str) -> tuple[JSON, bytes | None] | None:
    """The stored answer of a selection as JSON data and the rest of its ranking as stored
    (:func:`presenter.ranking_rest`; None: the answer lists it whole), or None."""
    stored = SelectionRepository(session).ranking(selection_id)
    if stored is None:
        return None
    answer, version, rest = stored
    if version != presenter.ANSWER_VERSION:
        raise RuntimeError(
            f"selection {selection_id!r} holds an answer of version {version}, not "
            f"{presenter.ANSWER_VERSION}: upgrade the database "
            "(python -m actuator_selection migrate)"
        )
    data: JSON = orjson.loads(gzip.decompress(answer))
    return data, rest


def cursor(selection_id: str, place: int) -> str:
    """The cursor that reads a stored selection's ranking from ``place`` on (0: the best
    candidate): opaque to clients, tied to the selection."""
    return base64.urlsafe_b64encode(f"{place}:{selection_id}".encode()).rstrip(b"=").decode()


def _place(token: str, selection_id: str, total: int) -> int:
    """The place a :func:`cursor` of ``selection_id`` reads from; 422 for anything else."""
    try:
        text = base64.urlsafe_b64decode(token + "=" * (-len(token) % 4)).decode("ascii")
    except ValueError:
        text = ""
    place, _, of = text.partition(":")
    if not (place.isascii() and place.isdigit()) or of != selection_id or int(place) >= total:
        raise invalid(["query", "cursor"], "invalid_cursor")
    return int(place)


@dataclass(frozen=True, slots=True)
class RankingRead:
    """A stored selection's ranking read from a cursor on: :meth:`page`, :meth:`lines`."""

    selection_id: str
    answer: JSON
    rest: bytes | None
    start: int

    @property
    def total(self) -> int:
        """How many candidates the ranking holds."""
        total: int = self.answer["total_candidates"]
        return total

    def candidates(self, start: int, stop: int) -> list[JSON]:
        """The candidates ranked ``start`` to ``stop`` (exclusive)."""
        listed: list[JSON] = self.answer["candidates"]
        out = listed[start:stop]
        if stop > len(listed) and self.rest is not None:
            out += presenter.ranked_candidates(self.rest, max(start, len(listed)), stop)
        return out

    def page(self, limit: int) -> JSON:
        """``CandidatePageOut``: up to ``limit`` candidates from the cursor on."""
        stop = min(self.start + limit, self.total)
        return {
            "selection_id": self.selection_id,
            "start": self.start,
            "total_candidates": self.total,
            "candidates": self.candidates(self.start, stop),
            "next_cursor": cursor(self.selection_id, stop) if stop < self.total else None,
        }

    def lines(self, block: int = 500) -> Iterator[bytes]:
        """Every candidate from the cursor on as a line of JSON (``CandidateOut``), in
        blocks of ``block`` candidates."""
        for start in range(self.start, self.total, block):
            rows = self.candidates(start, min(start + block, self.total))
            yield b"".join(dump_json(row) + b"\n" for row in rows)


def read_ranking(session: Session, selection_id: str, token: str | None) -> RankingRead:
    """A stored selection's ranking from the cursor ``token`` on (None: from the best
    candidate); 404 for an unknown selection, 422 for a cursor that is not one of its.

    A stored selection keeps its whole ranking as it was sized (the answer's candidates
    and the rest beside it), so a cursor reads the same candidates after any catalogue
    change: the ranking of the catalogue version the selection names."""
    stored = _stored_ranking(session, selection_id)
    if stored is None:
        raise not_found(["path", "selection_id"], "unknown_selection", selection_id=selection_id)
    answer, rest = stored
    start = 0 if token is None else _place(token, selection_id, answer["total_candidates"])
    return RankingRead(selection_id, answer, rest, start)


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
