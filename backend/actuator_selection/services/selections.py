"""Selections: size a load case against the catalogue, store it, read it back.

The answer lists every candidate lean: its verdict, torques and checks as numbers,
and, for candidates that are not unsuitable, its drive options grouped so that no
controller and no voltage check is written twice. The full detail of one candidate
(every check in words, every criterion of Table 521.1) is computed on request from
the stored load case (:func:`candidate_detail`).

The answer is built as plain JSON data (the response models of
``schemas.selections`` describe it, and the tests validate it against them): building
~1,000 model instances per selection cost more than the engineering.

A stored selection is its request, its catalogue version and its answer, the answer
gzip-compressed as it was sent (the starter catalogue's answer: ~55 kB, ~7 kB stored).
"""

from __future__ import annotations

import gzip
import uuid
from collections.abc import Callable, Iterable, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from datetime import datetime
from typing import Any

import pydantic_core
from sqlalchemy.orm import Session

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.checks import RULES, Check
from actuator_selection.core.compatibility import Controller
from actuator_selection.core.drive import DriveOption, DriveOptions
from actuator_selection.core.errors import ConflictError, NotFoundError
from actuator_selection.core.selection import Application, Candidate, Verdict, evaluate, select
from actuator_selection.db.repositories import CatalogueRepository, SelectionRepository
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.selections import (
    RANKING_RULE,
    CandidateDetailOut,
    DirectLoad,
    SelectionRequest,
)
from actuator_selection.services.catalogue import CatalogueSnapshot, DriveContext

JSON = dict[str, Any]

CHECK_RULES: list[JSON] = [
    {"name": rule.name, "reference": rule.reference, "unit": rule.unit} for rule in RULES
]
"""``check_rules`` of every answer: the flowchart's checks in their order."""

STORE_COMPRESSION = 6
"""gzip level of stored answers: ~8× smaller than the JSON at ~0.4 ms for 50 kB, once
for the row and for the answer to a client that accepts gzip."""

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


def _check(check: Check) -> JSON:
    out: JSON = {
        "name": check.name,
        "status": check.status.value,
        "value": check.value,
        "limit": check.limit,
    }
    if check.approximate:
        out["approximate"] = True
    if check.missing is not None:
        out["missing"] = check.missing
    return out


class _DriveOptionGroups:
    """Groups a candidate's drive options and numbers the controllers they refer to."""

    def __init__(self) -> None:
        self.controllers: dict[Controller, int] = {}

    def groups(self, drive: DriveOptions) -> list[JSON]:
        """Options best first, those alike in level, missing data and voltage check as one."""
        grouped: dict[tuple[Any, ...], JSON] = {}
        for option in drive.options:
            key = (option.match.verdict, option.match.no_data, option.voltage)
            group = grouped.get(key)
            if group is None:
                group = grouped[key] = self._group(option)
            group["controllers"].append(self._index(option.match.controller))
        return list(grouped.values())

    def refs(self) -> list[JSON]:
        """The ``controllers`` of the answer, in index order."""
        return [
            {
                "manufacturer": c.manufacturer,
                "type": c.type,
                "variant": c.variant,
                "source_row": c.source_row,
            }
            for c in self.controllers
        ]

    def _index(self, controller: Controller) -> int:
        index = self.controllers.get(controller)
        if index is None:
            index = self.controllers[controller] = len(self.controllers)
        return index

    @staticmethod
    def _group(option: DriveOption) -> JSON:
        v = option.voltage
        return {
            "level": option.match.verdict.value,
            "missing": [r.criterion.value for r in option.match.no_data],
            "controllers": [],
            "voltage": {
                "status": v.status.value,
                "value": v.value,
                "limit": v.limit,
                "reference": v.reference,
            },
        }


def _candidate(
    candidate: Candidate, drive: DriveContext, speed_rpm: float, groups: _DriveOptionGroups
) -> JSON:
    a = candidate.actuator
    t = candidate.torques
    if candidate.verdict is Verdict.UNSUITABLE:
        excluded, groups_out = drive.excluded(a), None
    else:
        options = drive.options(a, speed_rpm=speed_rpm)
        excluded, groups_out = options.excluded, groups.groups(options)
    return {
        "model": a.model,
        "family": a.family,
        "gear_ratio": a.gear_ratio,
        "verdict": candidate.verdict.value,
        "accel_torque_nm": t.accel_torque_nm if t else None,
        "constant_torque_nm": t.constant_torque_nm if t else None,
        "decel_torque_nm": t.decel_torque_nm if t else None,
        "rms_torque_nm": t.rms_torque_nm if t else None,
        "checks": [_check(c) for c in candidate.checks],
        "controllers_excluded": excluded,
        "drive_options": groups_out,
    }


def size_selection(
    body: SelectionRequest,
    app: Application,
    actuators: Sequence[Actuator],
    catalogue: CatalogueSnapshot,
    drive: DriveContext,
    created_at: datetime,
) -> SizedSelection:
    """The whole ranking of ``app`` over ``actuators`` as POST /selections answers it."""
    selection = select(actuators, app)
    speed = body.load.speed_rpm
    groups = _DriveOptionGroups()
    candidates = [_candidate(c, drive, speed, groups) for c in selection.candidates]
    request = body.model_dump(mode="json")
    load = app.load
    answer = {
        "id": str(uuid.uuid4()),
        "created_at": created_at,
        "catalogue_version": catalogue.version,
        "load": {
            "speed_rpm": speed,
            "torque_nm": load.torque_nm,
            "inertia_kgm2": load.inertia_kgm2,
        },
        "mechanism": None if isinstance(body.load, DirectLoad) else request["load"],
        "cycle": request["cycle"],
        "high_dynamics": body.high_dynamics,
        "models": body.models,
        "cycle_time_s": selection.cycle_time_s,
        "mean_speed_rpm": selection.mean_speed_rpm,
        "duty_cycle_percent": selection.duty_cycle_percent,
        "ranking": RANKING_RULE,
        "check_rules": CHECK_RULES,
        "controllers": groups.refs(),
        "candidates": candidates,
    }
    encoded = pydantic_core.to_json(answer)
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

    The answers are compressed before the transaction begins: on SQLite the write lock
    is held for the inserts alone.
    """
    rows = [(s, gzip.compress(s.answer, compresslevel=STORE_COMPRESSION, mtime=0)) for s in sized]
    with writer() as session:
        repository = SelectionRepository(session)
        for s, answer_gzip in rows:
            repository.add(
                id=s.id,
                created_at=s.created_at,
                catalogue_version=s.catalogue_version,
                request=s.request,
                answer_gzip=answer_gzip,
            )


def stored_answer(session: Session, selection_id: str) -> bytes:
    """The stored answer of a selection, gzip-compressed as stored."""
    stored = SelectionRepository(session).answer_gzip(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    return stored


def stored_answer_json(session: Session, selection_id: str) -> JSON | None:
    """The stored answer of a selection as JSON data, or None."""
    stored = SelectionRepository(session).answer_gzip(selection_id)
    return None if stored is None else pydantic_core.from_json(gzip.decompress(stored))


def candidate_detail(
    session: Session, catalogue: CatalogueSnapshot, selection_id: str, model: str
) -> CandidateDetailOut:
    """One candidate of a stored selection in full, computed again from its load case.

    The flowchart is deterministic, so the detail is the stored answer's candidate in
    full, as long as the catalogue is the one the selection used; after a catalogue
    change it would not be, and the caller is told to run the selection again.
    """
    stored = SelectionRepository(session).request(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    request, version = stored
    if version != catalogue.version:
        raise ConflictError(
            "selection_id",
            f"the catalogue has changed since this selection (version {version}, now "
            f"{catalogue.version}); run the selection again for the detail",
            where="path",
        )
    body = SelectionRequest.model_validate(request)
    actuator = next((a for a in catalogue.actuators_of([model])), None)
    record = CatalogueRepository(session).actuator(model)
    if actuator is None or record is None or (body.models is not None and model not in body.models):
        raise NotFoundError(
            "model", f"{model!r} is no candidate of selection {selection_id!r}", where="path"
        )
    return CandidateDetailOut.build(
        selection_id=selection_id,
        catalogue_version=version,
        candidate=evaluate(actuator, body.to_core()),
        drive=DriveContext(catalogue).options(actuator, speed_rpm=body.load.speed_rpm),
        actuator=ActuatorOut.from_record(record),
    )
