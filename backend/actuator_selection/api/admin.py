"""Catalogue management for admin keys: actuators, zones, controllers, import/export.

The use cases live in ``services/catalogue_admin.py``; each endpoint calls one.

Writes are validated by the seed files' rules (``catalogue/files.py``), so
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

import json
from datetime import UTC, datetime
from typing import Annotated, Any, Literal
from urllib.parse import quote

from fastapi import APIRouter, Body, Depends, Path, Query, Response

from actuator_selection.api.uploads import (
    SpooledUpload,
    file_errors,
    spooled_upload,
    text_of,
    too_many_rows,
    unsupported,
    unzip_csv,
)
from actuator_selection.catalogue.csvio import (
    WHOLE_NUMBER_MAX,
    CatalogueFileError,
    Problem,
    TooManyRowsError,
)
from actuator_selection.catalogue.files import ACTUATORS, CATALOGUE_SPECS, CONTROLLERS, INTERFACES
from actuator_selection.db.seed import CatalogueFiles, catalogue_from_json, parse_catalogue
from actuator_selection.http.auth import AdminDep
from actuator_selection.http.deps import SessionDep
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.admin import CatalogueImportOut, ZoneIn, write_json_schema
from actuator_selection.schemas.controllers import ControllerOut, InterfaceOut
from actuator_selection.services import catalogue_admin

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


@router.post(
    "/actuators", status_code=201, openapi_extra=_ACTUATOR_BODY, responses={**_ERRORS, 409: {}}
)
def create_actuator(
    _: AdminDep, session: SessionDep, response: Response, body: Annotated[dict[str, Any], Body()]
) -> ActuatorOut:
    """Add an actuator (the columns of actuators.csv, units in the names)."""
    out = catalogue_admin.create_actuator(session, body)
    # A header is Latin-1: a model such as "FHA-Ω" is sent percent-encoded (RFC 3986).
    response.headers["Location"] = f"/api/v1/actuators/{quote(out.model, safe='')}"
    return out


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
    return catalogue_admin.replace_actuator(session, model, body)


@router.delete(
    "/actuators/{model}",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown model"}},
)
def retire_actuator(model: str, _: AdminDep, session: SessionDep) -> Response:
    """Retire an actuator: gone from listings and selections, kept for quotes (idempotent)."""
    catalogue_admin.retire_actuator(session, model, now=datetime.now(UTC))
    return Response(status_code=204)


@router.put(
    "/actuators/{model}/zone",
    responses={**_ERRORS, 404: {"description": "unknown model"}, 409: {"description": "retired"}},
)
def set_zone(model: str, body: ZoneIn, _: AdminDep, session: SessionDep) -> ActuatorOut:
    """Replace the continuous-duty zone's edge (Fig. 517.1) of an actuator."""
    return catalogue_admin.set_zone(session, model, body)


@router.delete(
    "/actuators/{model}/zone",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown model"}},
)
def delete_zone(model: str, _: AdminDep, session: SessionDep) -> Response:
    """Remove an actuator's zone (its continuous-duty check then uses T₀ or says no data)."""
    catalogue_admin.delete_zone(session, model)
    return Response(status_code=204)


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
    return catalogue_admin.set_interface(session, model, body)


@router.delete(
    "/actuators/{model}/interface",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown model"}, 409: {"description": "retired"}},
)
def delete_interface(model: str, _: AdminDep, session: SessionDep) -> Response:
    """Forget an actuator's interface: its bus, sensor and feedback criteria say no data."""
    catalogue_admin.delete_interface(session, model)
    return Response(status_code=204)


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
    out = catalogue_admin.create_controller(session, body)
    response.headers["Location"] = f"/api/v1/controllers/{out.source_row}"
    return out


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
    return catalogue_admin.replace_controller(session, row, body)


@router.delete(
    "/controllers/{row}",
    status_code=204,
    responses={**_ERRORS, 404: {"description": "unknown row"}},
)
def retire_controller(row: Row, _: AdminDep, session: SessionDep) -> Response:
    """Retire a controller: gone from the matrix and from selections (idempotent)."""
    catalogue_admin.retire_controller(session, row, now=datetime.now(UTC))
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
    export = catalogue_admin.export_catalogue(session, format)
    headers = {"X-Catalogue-Version": str(export.version)}
    if export.filename is not None:
        headers["Content-Disposition"] = f'attachment; filename="{export.filename}"'
    return Response(export.body, media_type=export.media_type, headers=headers)


def catalogue_upload(
    upload: Annotated[SpooledUpload, Depends(spooled_upload)],
) -> CatalogueFiles:
    """The request body as the seed files: a ZIP of CSV files, each parsed row by row as it
    unpacks, or their JSON form (415 otherwise, 422 naming file, line and column of every
    problem, 413 naming the file and line past the rows a file may hold)."""
    try:
        if upload.media_type == "application/zip":
            with unzip_csv(upload.file, wanted=tuple(s.file for s in CATALOGUE_SPECS)) as files:
                return parse_catalogue(files)
        if upload.media_type == "application/json":
            body = upload.file.read()
            try:
                document = json.loads(text_of(body, file="(body)"))
            # RecursionError: arrays or objects nested thousands deep (the catalogue's
            # own depth is three); ValueError: not JSON, or an integer of over 4300 digits.
            except (ValueError, RecursionError) as exc:
                reason = "nested too deeply" if isinstance(exc, RecursionError) else str(exc)
                message = f"must be a JSON object, and is not valid JSON ({reason})"
                problem = Problem(file="(body)", line=0, column=None, message=message)
                raise CatalogueFileError([problem]) from None
            if not isinstance(document, dict):
                problem = Problem(
                    file="(body)", line=0, column=None, message="must be a JSON object"
                )
                raise CatalogueFileError([problem])
            return catalogue_from_json(document)
    except TooManyRowsError as exc:
        raise too_many_rows(exc) from None
    except CatalogueFileError as exc:
        raise file_errors(exc) from None
    raise unsupported(upload.media_type, ("application/zip", "application/json"))


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
    files: Annotated[CatalogueFiles, Depends(catalogue_upload)],
    session: SessionDep,
    dry_run: Annotated[bool, Query(description="report what would change, change nothing")] = False,
) -> CatalogueImportOut:
    """Replace the whole catalogue from the seed files, atomically."""
    return catalogue_admin.import_catalogue(session, files, dry_run=dry_run)
