"""Machine projects (issue 31): size each axis as a selection, sum their power on the bus,
store, read back, edit, list.

Each axis is sized by the selection service (:func:`services.selections.size_selection`,
the same ranking and figures as ``POST /selections`` for its load case); its actuator is
the one the engineer chose or the first candidate that publishes J_A (a suitable one
where there is one, as the ranking puts them first). Its power over the cycle and the
bus's come from :mod:`actuator_selection.sizing.bus`.
"""

from __future__ import annotations

import gzip
import uuid
from collections.abc import Callable
from contextlib import AbstractContextManager
from datetime import datetime
from typing import Any

import orjson
from sqlalchemy.orm import Session

from actuator_selection.db.projects import ProjectRepository, StoredProject
from actuator_selection.errors import DomainError, MissingDataError, NotFoundError
from actuator_selection.schemas.projects import ProjectRequest
from actuator_selection.services import axis_controllers
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.presenters.project import axis_body, project_answer
from actuator_selection.services.presenters.selection import dump_json
from actuator_selection.services.selections import STORE_COMPRESSION, size_selection
from actuator_selection.sizing.bus import (
    axis_power,
    braking_resistor,
    capacitor,
    machine_bus,
    motor_of,
)

JSON = dict[str, Any]
Writer = Callable[[], AbstractContextManager[Session]]


def _pick(candidates: list[JSON], catalogue: CatalogueSnapshot) -> JSON:
    """The first candidate whose actuator publishes J_A (its power needs it)."""
    by_model = {a.model: a for a in catalogue.actuators_of([c["model"] for c in candidates])}
    for c in candidates:
        if by_model[c["model"]].inertia_kgm2 is not None:
            return c
    return candidates[0]  # motor_of says no data


def size_project(
    body: ProjectRequest,
    catalogue: CatalogueSnapshot,
    *,
    id: str,
    created_at: datetime,
    updated_at: datetime,
) -> JSON:
    """The project's answer (``schemas.projects.ProjectOut``) as JSON data."""
    dc_bus = next((b for b in catalogue.buses if b.bus_class == body.bus.bus_class), None)
    if dc_bus is None:
        raise MissingDataError(
            "bus.bus_class", f"no data: the catalogue has no voltage for {body.bus.bus_class}"
        )
    axes_out, powers, offsets, controllers = [], [], [], []
    for k, axis in enumerate(body.axes):
        try:
            app = axis.to_core()
            models = [axis.model] if axis.model is not None else axis.models
            sized = size_selection(axis, app, catalogue.actuators_of(models), catalogue, updated_at)
            selection = orjson.loads(sized.answer)
            candidate = _pick(selection["candidates"], catalogue)
            actuator = catalogue.actuators_of([candidate["model"]])[0]
            power = axis_power(app.profile, motor_of(actuator))
        except DomainError as exc:
            raise exc.moved(f"axes.{k}.{exc.field}") from None
        listed = axis_controllers.choices(catalogue, actuator, dc_bus)
        controller = axis_controllers.chosen(
            row=axis.controller,
            loc=["body", "axes", k, "controller"],
            catalogue=catalogue,
            actuator=actuator,
            bus=dc_bus,
            listed=listed,
            speed_rpm=app.profile.peak_speed_rpm,
        )
        powers.append(power)
        offsets.append(axis.offset_s)
        controllers.append(controller)
        axes_out.append(
            axis_body(axis, actuator, candidate, selection["check_rules"], power)
            | {"controller": controller, "controllers": listed}
        )
    bus = machine_bus(powers, offsets)
    cap = capacitor(
        capacitance_f=None if body.bus.capacitance_uf is None else body.bus.capacitance_uf * 1e-6,
        nominal_voltage_v=dc_bus.nominal_voltage_v,
        max_voltage_v=body.bus.max_voltage_v,
        pulse_energy_j=bus.figures.regen_pulse_energy_j,
    )
    return project_answer(
        id=id,
        created_at=created_at,
        updated_at=updated_at,
        catalogue_version=catalogue.version,
        body=body,
        axes=axes_out,
        bus=bus,
        cap=cap,
        resistor=braking_resistor(bus.figures, cap, body.bus.chopper_voltage_v),
        controllers=axis_controllers.bus_summary(controllers),
    )


def _stored(answer: JSON, request: ProjectRequest) -> StoredProject:
    encoded = dump_json(answer)
    return StoredProject(
        id=answer["id"],
        created_at=answer["created_at"],
        updated_at=answer["updated_at"],
        catalogue_version=answer["catalogue_version"],
        request=request.model_dump(mode="json"),
        answer_gzip=gzip.compress(encoded, compresslevel=STORE_COMPRESSION, mtime=0),
    )


def create_project(
    body: ProjectRequest, catalogue: CatalogueSnapshot, writer: Writer, now: datetime
) -> tuple[str, bytes]:
    """Size a new project and store it; its id and its answer as JSON bytes."""
    project_id = str(uuid.uuid4())
    answer = size_project(body, catalogue, id=project_id, created_at=now, updated_at=now)
    with writer() as session:
        ProjectRepository(session).add(_stored(answer, body))
    return project_id, dump_json(answer)


def _existing(session: Session, project_id: str) -> StoredProject:
    found = ProjectRepository(session).get(project_id)
    if found is None:
        raise NotFoundError("project_id", f"no project {project_id!r}", where="path")
    return found


def stored_request(reader: Writer, project_id: str) -> ProjectRequest:
    """The request a stored project was last sized with."""
    with reader() as session:
        return ProjectRequest.model_validate(_existing(session, project_id).request)


def resize_project(
    project_id: str,
    body: ProjectRequest | None,
    catalogue: CatalogueSnapshot,
    reader: Writer,
    writer: Writer,
    now: datetime,
) -> bytes:
    """Size a stored project again, with a new request (an edit) or its own (against the
    catalogue as it is now), and store it in place."""
    with reader() as session:
        old = _existing(session, project_id)
    request = body if body is not None else ProjectRequest.model_validate(old.request)
    answer = size_project(
        request, catalogue, id=project_id, created_at=old.created_at, updated_at=now
    )
    with writer() as session:
        if not ProjectRepository(session).replace(_stored(answer, request)):
            raise NotFoundError("project_id", f"no project {project_id!r}", where="path")
    return dump_json(answer)


def stored_project(session: Session, project_id: str) -> bytes:
    """A stored project's answer, gzip-compressed as stored."""
    return _existing(session, project_id).answer_gzip


def project_page(
    session: Session, *, limit: int, after: tuple[datetime, str] | None
) -> tuple[list[JSON], bool]:
    """Up to ``limit`` projects in brief after ``after``, and whether more follow."""
    rows = ProjectRepository(session).page(limit=limit + 1, after=after)
    briefs = [
        {
            "id": p.id,
            "name": p.request.get("name", ""),
            "created_at": p.created_at,
            "updated_at": p.updated_at,
            "catalogue_version": p.catalogue_version,
            "axes": len(p.request.get("axes", [])),
        }
        for p in rows[:limit]
    ]
    return briefs, len(rows) > limit
