"""Catalogue management for admin keys: actuators, zones, controllers, import/export.

Writes are validated by the seed files' rules (``core/catalogue_files.py``), so
an actuator or controller the API accepts is one the seed loader accepts and
vice versa. Every change raises the catalogue version. Retiring is a soft
delete: a retired actuator leaves listings and selections and stays for the
quotes that name it; a retired controller leaves the compatibility matrix
(Table 521.1) and every candidate's controller list.

Import and export use the seed format: a ZIP of the eight files of
``seed_data/`` (families, actuators, zone points, controllers, temperature
sensors, KTY 84-130 points, DC bus classes, actuator interfaces;
``Content-Type: application/zip``), or JSON with one array per file, keyed by
the file's stem (``{"families": [...], "actuators": [...], ...}``), of objects
keyed by the CSV column names (``application/json``). An import is the whole
catalogue: actuators and controllers it lacks are retired, other rows it lacks
removed; it runs in one transaction, and ``?dry_run=true`` reports the changes
and writes nothing.
"""

from __future__ import annotations

import io
import json
import zipfile
from collections.abc import Callable, Mapping
from datetime import UTC, datetime
from typing import Annotated, Any, Literal
from urllib.parse import quote

from fastapi import APIRouter, Body, Depends, Path, Query, Response

from actuator_selection.api.auth import AdminDep
from actuator_selection.api.deps import SessionDep
from actuator_selection.api.errors import (
    ConflictError,
    RequestFieldError,
    ResourceNotFoundError,
    field_error,
)
from actuator_selection.api.uploads import (
    Upload,
    file_errors,
    raw_upload,
    text_of,
    unsupported,
    unzip_csv,
)
from actuator_selection.core.catalogue_files import (
    ACTUATORS,
    CATALOGUE_SPECS,
    CONTROLLERS,
    INTERFACES,
    JSON_KEYS,
)
from actuator_selection.core.csvio import (
    WHOLE_NUMBER_MAX,
    CatalogueFileError,
    Problem,
    to_json_values,
    write,
)
from actuator_selection.db.admin import CatalogueAdminRepository
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.db.seed import catalogue_from_json, parse_catalogue
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.admin import CatalogueImportOut, ZoneIn, write_json_schema
from actuator_selection.schemas.controllers import ControllerOut, InterfaceOut

router = APIRouter(tags=["catalogue management"])


def _body(schema: dict[str, Any]) -> dict[str, Any]:
    return {"requestBody": {"required": True, "content": {"application/json": {"schema": schema}}}}


_ACTUATOR_BODY = _body(write_json_schema(ACTUATORS))
_CONTROLLER_BODY = _body(write_json_schema(CONTROLLERS, optional=("source_row",)))
_INTERFACE_BODY = _body(write_json_schema(INTERFACES, without=("actuator_model",)))
_ERRORS: dict[int | str, dict[str, Any]] = {
    401: {"description": "no or a bad API key"},
    403: {"description": "the key lacks the admin role"},
    422: {"description": "a value breaks a rule of the seed file; the entry names the column"},
}
Row = Annotated[
    int,
    Path(ge=1, le=WHOLE_NUMBER_MAX, description="the controller's row (`source_row`)"),
]


def _field_errors(exc: CatalogueFileError, *prefix: str | int, rows: bool = False) -> Exception:
    """422 entries at ``body.<prefix>.<column>`` (or ``<prefix>.<index>.<column>`` for rows)."""
    entries = []
    for p in exc.problems:
        loc: list[str | int] = ["body", *prefix]
        if rows:
            loc.append(p.line)
        if p.column:
            loc.append(p.column)
        entries.append(field_error(loc, f"{p.column or 'value'} {p.message}", "invalid_value"))
    return RequestFieldError(entries)


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
        raise RequestFieldError(
            [field_error(["body", column], f"must be {value!r}, as in the path", "mismatch")]
        )
    return {**body, column: value}


def _unknown_model(model: str) -> ResourceNotFoundError:
    return ResourceNotFoundError.at(
        ["path", "model"], f"unknown actuator model {model!r}", "not_found"
    )


def _actuator_out(session: SessionDep, model: str) -> ActuatorOut:
    record = CatalogueRepository(session).actuator(model)
    if record is None:
        raise _unknown_model(model)
    return ActuatorOut.from_record(record)


def _known(session: SessionDep, model: str, *, active: bool = False) -> None:
    state = CatalogueAdminRepository(session).state(model)
    if state is None:
        raise _unknown_model(model)
    if active and state.retired_at is not None:
        raise ConflictError.at(
            ["path", "model"],
            f"actuator {model!r} is retired; PUT /actuators/{model} brings it back first",
            "retired",
        )


@router.post(
    "/actuators", status_code=201, openapi_extra=_ACTUATOR_BODY, responses={**_ERRORS, 409: {}}
)
def create_actuator(
    _: AdminDep, session: SessionDep, response: Response, body: Annotated[dict[str, Any], Body()]
) -> ActuatorOut:
    """Add an actuator (the columns of actuators.csv, units in the names)."""
    repository = CatalogueAdminRepository(session)
    values = _validated(repository.validate_actuator, body)
    if repository.state(values["model"]) is not None:
        raise ConflictError.at(
            ["body", "model"],
            f"actuator {values['model']!r} exists (retired ones too); "
            "PUT /actuators/{model} replaces it",
            "exists",
        )
    repository.save_actuator(values)
    # A header is Latin-1: a model such as "FHA-Ω" is sent percent-encoded (RFC 3986).
    response.headers["Location"] = f"/api/v1/actuators/{quote(values['model'], safe='')}"
    return _actuator_out(session, values["model"])


@router.put(
    "/actuators/{model}",
    openapi_extra=_ACTUATOR_BODY,
    responses={**_ERRORS, 404: {"description": "unknown model"}},
)
def replace_actuator(
    model: str, _: AdminDep, session: SessionDep, body: Annotated[dict[str, Any], Body()]
) -> ActuatorOut:
    """Replace an actuator's values (every column; a missing one becomes empty).

    A retired actuator is brought back.
    """
    _known(session, model)
    repository = CatalogueAdminRepository(session)
    values = _validated(repository.validate_actuator, _keyed_by_path(body, "model", model))
    repository.save_actuator(values)
    return _actuator_out(session, model)


@router.delete(
    "/actuators/{model}",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown model"}},
)
def retire_actuator(model: str, _: AdminDep, session: SessionDep) -> Response:
    """Retire an actuator: gone from listings and selections, kept for quotes (idempotent)."""
    _known(session, model)
    CatalogueAdminRepository(session).retire(model, now=datetime.now(UTC))
    return Response(status_code=204)


@router.put(
    "/actuators/{model}/zone",
    responses={**_ERRORS, 404: {"description": "unknown model"}, 409: {"description": "retired"}},
)
def set_zone(model: str, body: ZoneIn, _: AdminDep, session: SessionDep) -> ActuatorOut:
    """Replace the continuous-duty zone's edge (Fig. 517.1) of an actuator."""
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


@router.delete(
    "/actuators/{model}/zone",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown model"}},
)
def delete_zone(model: str, _: AdminDep, session: SessionDep) -> Response:
    """Remove an actuator's zone (its continuous-duty check then uses T₀ or says no data)."""
    _known(session, model, active=True)
    CatalogueAdminRepository(session).set_zone(model, [], source=None)
    return Response(status_code=204)


def _interface_out(session: SessionDep, model: str) -> InterfaceOut:
    return InterfaceOut.from_record(ProtectionRepository(session).interfaces([model])[model])


@router.put(
    "/actuators/{model}/interface",
    openapi_extra=_INTERFACE_BODY,
    responses={**_ERRORS, 404: {"description": "unknown model"}, 409: {"description": "retired"}},
)
def set_interface(
    model: str, _: AdminDep, session: SessionDep, body: Annotated[dict[str, Any], Body()]
) -> InterfaceOut:
    """Replace what the controller matching knows of an actuator (actuator_interfaces.csv).

    Options are space-separated text as in the file, or JSON arrays of names; an
    empty or missing one is "no data" (the criterion is then neither confirmed nor
    excluded).
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
    return _interface_out(session, model)


@router.delete(
    "/actuators/{model}/interface",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown model"}, 409: {"description": "retired"}},
)
def delete_interface(model: str, _: AdminDep, session: SessionDep) -> Response:
    """Forget an actuator's interface: its bus, sensor and feedback criteria say no data."""
    _known(session, model, active=True)
    CatalogueAdminRepository(session).set_interface(model, None)
    return Response(status_code=204)


def _controller_out(session: SessionDep, row: int) -> ControllerOut:
    record = ProtectionRepository(session).controller(row)
    assert record is not None, "written in this request"
    return ControllerOut.from_record(record)


def _known_controller(session: SessionDep, row: int) -> None:
    if CatalogueAdminRepository(session).controller_state(row) is None:
        raise ResourceNotFoundError.at(["path", "row"], f"no controller in row {row}", "not_found")


@router.post(
    "/controllers",
    status_code=201,
    openapi_extra=_CONTROLLER_BODY,
    responses={**_ERRORS, 409: {"description": "the row exists"}},
)
def create_controller(
    _: AdminDep, session: SessionDep, response: Response, body: Annotated[dict[str, Any], Body()]
) -> ControllerOut:
    """Add a row to the compatibility matrix (the columns of controllers.csv).

    Marks are ``tested`` (●), ``possible`` (○) or empty. Without ``source_row``
    the row takes the next free number; Table 521.1's rows keep 1–28.
    """
    repository = CatalogueAdminRepository(session)
    if body.get("source_row") is None:
        body = {**body, "source_row": repository.next_controller_row()}
    values = _validated(repository.validate_controller, body)
    row = values["source_row"]
    if repository.controller_state(row) is not None:
        raise ConflictError.at(
            ["body", "source_row"],
            f"controller row {row} exists (retired ones too); PUT /controllers/{row} replaces it",
            "exists",
        )
    repository.save_controller(values)
    response.headers["Location"] = f"/api/v1/controllers/{row}"
    return _controller_out(session, row)


@router.put(
    "/controllers/{row}",
    openapi_extra=_CONTROLLER_BODY,
    responses={**_ERRORS, 404: {"description": "unknown row"}},
)
def replace_controller(
    row: Row, _: AdminDep, session: SessionDep, body: Annotated[dict[str, Any], Body()]
) -> ControllerOut:
    """Replace a controller's values (every column; a missing one becomes empty).

    A retired controller is brought back.
    """
    _known_controller(session, row)
    repository = CatalogueAdminRepository(session)
    values = _validated(repository.validate_controller, _keyed_by_path(body, "source_row", row))
    repository.save_controller(values)
    return _controller_out(session, row)


@router.delete(
    "/controllers/{row}",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown row"}},
)
def retire_controller(row: Row, _: AdminDep, session: SessionDep) -> Response:
    """Retire a controller: gone from the matrix and from selections (idempotent)."""
    _known_controller(session, row)
    CatalogueAdminRepository(session).retire_controller(row, now=datetime.now(UTC))
    return Response(status_code=204)


@router.get(
    "/catalogue/export",
    responses={
        200: {
            "content": {"application/zip": {}, "application/json": {}},
            "description": "the seed files as a ZIP, or their JSON form",
        }
    },
)
def export_catalogue(
    _: AdminDep,
    session: SessionDep,
    format: Annotated[
        Literal["zip", "json"], Query(description="zip of CSV files or JSON")
    ] = "zip",
) -> Response:
    """The active catalogue in the seed format (retired actuators and controllers left out)."""
    stored = CatalogueAdminRepository(session).export()
    version = CatalogueVersionRepository(session).current()
    headers = {"X-Catalogue-Version": str(version)}
    if format == "json":
        body = {
            JSON_KEYS[spec.file]: [to_json_values(spec, row) for row in stored[spec.file]]
            for spec in CATALOGUE_SPECS
        }
        return Response(
            json.dumps(body, ensure_ascii=False, allow_nan=False),
            media_type="application/json",
            headers=headers,
        )
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for spec in CATALOGUE_SPECS:
            archive.writestr(spec.file, write(spec, stored[spec.file]))
    headers["Content-Disposition"] = f'attachment; filename="catalogue-v{version}.zip"'
    return Response(buffer.getvalue(), media_type="application/zip", headers=headers)


@router.post(
    "/catalogue/import",
    responses={
        **_ERRORS,
        415: {"description": "neither application/zip nor application/json"},
        422: {"description": "every problem with file, line, column and rule; nothing changed"},
    },
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {
                "application/zip": {"schema": {"type": "string", "format": "binary"}},
                "application/json": {"schema": {"type": "object"}},
            },
        }
    },
)
def import_catalogue(
    _: AdminDep,
    upload: Annotated[Upload, Depends(raw_upload)],
    session: SessionDep,
    dry_run: Annotated[bool, Query(description="report what would change, change nothing")] = False,
) -> CatalogueImportOut:
    """Replace the whole catalogue from the seed files, atomically."""
    try:
        if upload.media_type == "application/zip":
            files = parse_catalogue(
                unzip_csv(upload.body, wanted=tuple(s.file for s in CATALOGUE_SPECS))
            )
        elif upload.media_type == "application/json":
            try:
                document = json.loads(text_of(upload.body, file="(body)"))
            except ValueError:
                document = None
            if not isinstance(document, dict):
                problem = Problem(
                    file="(body)", line=0, column=None, message="must be a JSON object"
                )
                raise CatalogueFileError([problem])
            files = catalogue_from_json(document)
        else:
            raise unsupported(upload.media_type, ("application/zip", "application/json"))
        changes = CatalogueAdminRepository(session).import_catalogue(files, dry_run=dry_run)
    except CatalogueFileError as exc:
        raise file_errors(exc) from None
    return CatalogueImportOut.build(
        changes, dry_run=dry_run, version=CatalogueVersionRepository(session).current()
    )
