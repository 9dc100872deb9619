"""Catalogue administration: actuators, zones, interfaces, controllers, import and export.

Writes are validated by the seed files' rules (``catalogue/files.py``), so
an actuator or controller this accepts is one the seed loader accepts and vice
versa. Every change raises the catalogue version (the repositories do). Retiring is
a soft delete: a retired actuator leaves listings and selections and stays for the
quotes that name it; a retired controller leaves the compatibility matrix (Table
521.1) and every candidate's controller list.

An import is the whole catalogue in the seed format: actuators and controllers it
lacks are retired, other rows it lacks removed; it runs in the request's one
transaction, and ``dry_run`` reports the changes and writes nothing.
"""

from __future__ import annotations

import io
import json
import zipfile
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from datetime import datetime
from typing import Any, Literal

from sqlalchemy.orm import Session

from actuator_selection.catalogue.csvio import CatalogueFileError, to_json_values, write
from actuator_selection.catalogue.files import CATALOGUE_SPECS, JSON_KEYS
from actuator_selection.db.admin import CatalogueAdminRepository
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.db.seed import CatalogueFiles
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.admin import CatalogueImportOut, ZoneIn
from actuator_selection.schemas.controllers import ControllerOut, InterfaceOut
from actuator_selection.services.errors import (
    Loc,
    UseCaseError,
    conflict,
    file_problems,
    invalid,
    not_found,
    worded,
)


def _field_errors(exc: CatalogueFileError, *prefix: str | int, rows: bool = False) -> UseCaseError:
    """422 entries at ``body.<prefix>.<column>`` (or ``<prefix>.<index>.<column>`` for rows)."""
    entries = []
    for p in exc.problems:
        loc: Loc = ["body", *prefix]
        if rows:
            loc.append(p.line)
        if p.column:
            loc.append(p.column)
        entries.append(worded(loc, f"{p.column or 'value'} {p.message}", "invalid_value"))
    return UseCaseError(entries)


def _validated(
    validate: Callable[[Mapping[str, object]], dict[str, Any]], values: Mapping[str, object]
) -> dict[str, Any]:
    """``validate(values)``, its problems as 422 entries at ``body.<column>``."""
    try:
        return validate(values)
    except CatalogueFileError as exc:
        raise _field_errors(exc) from None


def _keyed_by_path(body: Mapping[str, Any], column: str, value: str | int) -> dict[str, Any]:
    """``body`` with ``column`` set to the path's ``value``; a body that names another
    value is refused (null or absent: the path's)."""
    if body.get(column) not in (None, value, str(value)):
        raise invalid(["body", column], "path_mismatch", "mismatch", value=value)
    return {**body, column: value}


def _unknown_model(model: str) -> UseCaseError:
    return not_found(["path", "model"], "unknown_actuator", model=model)


def _actuator_out(session: Session, model: str) -> ActuatorOut:
    record = CatalogueRepository(session).actuator(model)
    if record is None:
        raise _unknown_model(model)
    return ActuatorOut.from_record(record)


def _known(session: Session, model: str, *, active: bool = False) -> None:
    state = CatalogueAdminRepository(session).state(model)
    if state is None:
        raise _unknown_model(model)
    if active and state.retired_at is not None:
        raise conflict(["path", "model"], "actuator_retired", "retired", model=model)


def create_actuator(session: Session, body: Mapping[str, Any]) -> ActuatorOut:
    """Add an actuator (the columns of actuators.csv); 409 when the model exists."""
    repository = CatalogueAdminRepository(session)
    values = _validated(repository.validate_actuator, body)
    if repository.state(values["model"]) is not None:
        raise conflict(["body", "model"], "actuator_exists", "exists", model=values["model"])
    repository.save_actuator(values)
    return _actuator_out(session, values["model"])


def replace_actuator(session: Session, model: str, body: Mapping[str, Any]) -> ActuatorOut:
    """Replace an actuator's values (a missing column becomes empty); brings back a retired one."""
    _known(session, model)
    repository = CatalogueAdminRepository(session)
    values = _validated(repository.validate_actuator, _keyed_by_path(body, "model", model))
    repository.save_actuator(values)
    return _actuator_out(session, model)


def retire_actuator(session: Session, model: str, *, now: datetime) -> None:
    """Retire an actuator (idempotent)."""
    _known(session, model)
    CatalogueAdminRepository(session).retire(model, now=now)


def set_zone(session: Session, model: str, body: ZoneIn) -> ActuatorOut:
    """Replace the continuous-duty zone's edge (Fig. 517.1) of an active actuator."""
    _known(session, model, active=True)
    repository = CatalogueAdminRepository(session)
    points = [p.model_dump() for p in body.points]
    try:
        checked = repository.validate_zone(model, points, body.source)
    except CatalogueFileError as exc:
        source = [p for p in exc.problems if p.column == "source"]
        if source:
            raise _field_errors(CatalogueFileError(source[:1])) from None
        raise _field_errors(exc, "points", rows=True) from None
    repository.set_zone(model, checked, source=str(body.source).strip())
    return _actuator_out(session, model)


def delete_zone(session: Session, model: str) -> None:
    """Remove an active actuator's zone."""
    _known(session, model, active=True)
    CatalogueAdminRepository(session).set_zone(model, [], source=None)


def set_interface(session: Session, model: str, body: Mapping[str, Any]) -> InterfaceOut:
    """Replace what the controller matching knows of an active actuator.

    Options are space-separated text as in actuator_interfaces.csv, or JSON arrays of
    names.
    """
    _known(session, model, active=True)
    given = {
        k: " ".join(v) if isinstance(v, list) and all(isinstance(o, str) for o in v) else v
        for k, v in body.items()
    }
    repository = CatalogueAdminRepository(session)
    values = _validated(
        repository.validate_interface, _keyed_by_path(given, "actuator_model", model)
    )
    repository.set_interface(model, values)
    return InterfaceOut.from_record(ProtectionRepository(session).interfaces([model])[model])


def delete_interface(session: Session, model: str) -> None:
    """Forget an active actuator's interface."""
    _known(session, model, active=True)
    CatalogueAdminRepository(session).set_interface(model, None)


def _controller_out(session: Session, row: int) -> ControllerOut:
    record = ProtectionRepository(session).controller(row)
    assert record is not None, "written in this request"
    return ControllerOut.from_record(record)


def _known_controller(session: Session, row: int) -> None:
    if CatalogueAdminRepository(session).controller_state(row) is None:
        raise not_found(["path", "row"], "unknown_controller_row", row=row)


def create_controller(session: Session, body: Mapping[str, Any]) -> ControllerOut:
    """Add a row to the compatibility matrix; the next free row without ``source_row``."""
    repository = CatalogueAdminRepository(session)
    if body.get("source_row") is None:
        body = {**body, "source_row": repository.next_controller_row()}
    values = _validated(repository.validate_controller, body)
    row = values["source_row"]
    if repository.controller_state(row) is not None:
        raise conflict(["body", "source_row"], "controller_exists", "exists", row=row)
    repository.save_controller(values)
    return _controller_out(session, row)


def replace_controller(session: Session, row: int, body: Mapping[str, Any]) -> ControllerOut:
    """Replace a controller's values; brings back a retired one."""
    _known_controller(session, row)
    repository = CatalogueAdminRepository(session)
    values = _validated(repository.validate_controller, _keyed_by_path(body, "source_row", row))
    repository.save_controller(values)
    return _controller_out(session, row)


def retire_controller(session: Session, row: int, *, now: datetime) -> None:
    """Retire a controller (idempotent)."""
    _known_controller(session, row)
    CatalogueAdminRepository(session).retire_controller(row, now=now)


@dataclass(frozen=True, slots=True)
class CatalogueExport:
    """The active catalogue in the seed format, and the version it is."""

    media_type: str
    body: bytes
    version: int
    filename: str | None


def export_catalogue(session: Session, format: Literal["zip", "json"]) -> CatalogueExport:
    """The active catalogue (retired actuators and controllers left out) as ZIP or JSON."""
    stored = CatalogueAdminRepository(session).export()
    version = CatalogueVersionRepository(session).current()
    if format == "json":
        document = {
            JSON_KEYS[spec.file]: [to_json_values(spec, row) for row in stored[spec.file]]
            for spec in CATALOGUE_SPECS
        }
        text = json.dumps(document, ensure_ascii=False, allow_nan=False)
        return CatalogueExport("application/json", text.encode("utf-8"), version, None)
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for spec in CATALOGUE_SPECS:
            archive.writestr(spec.file, write(spec, stored[spec.file]))
    return CatalogueExport(
        "application/zip", buffer.getvalue(), version, f"catalogue-v{version}.zip"
    )


def import_catalogue(
    session: Session, files: CatalogueFiles, *, dry_run: bool
) -> CatalogueImportOut:
    """Replace the whole catalogue by ``files``, atomically; every problem named (422)."""
    try:
        changes = CatalogueAdminRepository(session).import_catalogue(files, dry_run=dry_run)
    except CatalogueFileError as exc:
        raise file_problems(exc) from None
    return CatalogueImportOut.build(
        changes, dry_run=dry_run, version=CatalogueVersionRepository(session).current()
    )
