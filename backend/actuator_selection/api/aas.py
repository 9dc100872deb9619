"""A stored selection as an IDTA 02021 sizing record (Asset Administration Shell)."""

from __future__ import annotations

from typing import Annotated, Any
from urllib.parse import quote

from fastapi import APIRouter, Path, Query, Request, Response
from fastapi.exceptions import RequestValidationError
from pydantic import ValidationError
from starlette.concurrency import run_in_threadpool

from actuator_selection.api.selections import create_selection
from actuator_selection.http.deps import SessionDep, catalogue_snapshot, reads_only
from actuator_selection.i18n.localize import localizer
from actuator_selection.schemas.aas import AasRecordQuery
from actuator_selection.schemas.selections import SelectionOut, SelectionRequest
from actuator_selection.services.aas import (
    SUBMODEL_SEMANTIC_ID,
    SizingRecord,
    record_aasx,
    record_json,
    sizing_record,
)
from actuator_selection.services.aas_import import request_from_record
from actuator_selection.services.aas_project import project_record

router = APIRouter(tags=["selections"])

AASX_MEDIA_TYPE = "application/asset-administration-shell-package"

_ERRORS: dict[int | str, dict[str, Any]] = {
    404: {"description": "unknown selection"},
    409: {"description": "the catalogue has changed since the selection"},
}

SelectionId = Annotated[str, Path(max_length=36)]
RecordQuery = Annotated[AasRecordQuery, Query()]


def _record(
    request: Request, session: SessionDep, selection_id: str, query: AasRecordQuery
) -> SizingRecord:
    return sizing_record(
        session,
        catalogue_snapshot(request, session),
        selection_id,
        localizers={"en": localizer("en"), "de": localizer("de")},
        link=str(request.url_for("get_selection", selection_id=selection_id)),
        project_name=query.project_name,
        client_name=query.client_name,
        model_name=query.model,
    )


@router.get(
    "/selections/{selection_id}/aas",
    response_class=Response,
    responses={
        200: {
            "content": {"application/json": {"schema": {"type": "object"}}},
            "description": "AAS JSON: a shell and its IDTA 02021 PowerDriveTrainSizing "
            "submodel (docs/aas.md)",
        },
        **_ERRORS,
    },
)
def get_selection_aas(
    selection_id: SelectionId,
    request: Request,
    session: SessionDep,
    query: RecordQuery,
) -> Response:
    """The selection as an IDTA 02021 "Sizing of Power Drive Trains" record, AAS JSON."""
    record = _record(request, session, selection_id, query)
    return Response(record_json(record), media_type="application/json")


@router.get(
    "/selections/{selection_id}/aas.aasx",
    response_class=Response,
    responses={
        200: {
            "content": {AASX_MEDIA_TYPE: {"schema": {"type": "string", "format": "binary"}}},
            "description": "AASX package: the AAS JSON and the motion file "
            "(aasx/files/MotionSection1.csv)",
        },
        **_ERRORS,
    },
)
def get_selection_aasx(
    selection_id: SelectionId,
    request: Request,
    session: SessionDep,
    query: RecordQuery,
) -> Response:
    """The selection as an IDTA 02021 record in an AASX package with its motion file."""
    record = _record(request, session, selection_id, query)
    name = quote(f"selection-{selection_id}.aasx", safe="")
    return Response(
        record_aasx(record),
        media_type=AASX_MEDIA_TYPE,
        headers={"Content-Disposition": f'attachment; filename="{name}"'},
    )


ProjectId = Annotated[str, Path(max_length=36)]
_PROJECT_ERRORS: dict[int | str, dict[str, Any]] = {
    404: {"description": "unknown project"},
    409: {"description": "the catalogue has changed since the project was sized"},
}


def _project_record(
    request: Request, session: SessionDep, project_id: str, client_name: str
) -> SizingRecord:
    return project_record(
        session,
        catalogue_snapshot(request, session),
        project_id,
        localizers={"en": localizer("en"), "de": localizer("de")},
        link=str(request.url_for("get_project", project_id=project_id)),
        client_name=client_name,
    )


ClientName = Annotated[str, Query(max_length=200, description="the client, as written")]


@router.get(
    "/projects/{project_id}/aas",
    response_class=Response,
    tags=["projects"],
    responses={
        200: {
            "content": {"application/json": {"schema": {"type": "object"}}},
            "description": "AAS JSON: a shell and one IDTA 02021 PowerDriveTrainSizing "
            "submodel per axis (docs/aas.md)",
        },
        **_PROJECT_ERRORS,
    },
)
def get_project_aas(
    project_id: ProjectId, request: Request, session: SessionDep, client_name: ClientName = ""
) -> Response:
    """The machine project as IDTA 02021 records, one drive train per axis, AAS JSON."""
    record = _project_record(request, session, project_id, client_name)
    return Response(record_json(record), media_type="application/json")


@router.get(
    "/projects/{project_id}/aas.aasx",
    response_class=Response,
    tags=["projects"],
    responses={
        200: {
            "content": {AASX_MEDIA_TYPE: {"schema": {"type": "string", "format": "binary"}}},
            "description": "AASX package: the AAS, a motion file per axis and the project",
        },
        **_PROJECT_ERRORS,
    },
)
def get_project_aasx(
    project_id: ProjectId, request: Request, session: SessionDep, client_name: ClientName = ""
) -> Response:
    """The machine project as IDTA 02021 records in an AASX package with its motion files."""
    record = _project_record(request, session, project_id, client_name)
    name = quote(f"project-{project_id}.aasx", safe="")
    return Response(
        record_aasx(record),
        media_type=AASX_MEDIA_TYPE,
        headers={"Content-Disposition": f'attachment; filename="{name}"'},
    )


_JSON_EXAMPLE = {
    "assetAdministrationShells": [],
    "submodels": [
        {
            "modelType": "Submodel",
            "id": "urn:example:sizing",
            "idShort": "PowerDriveTrainSizing",
            "semanticId": {
                "type": "ExternalReference",
                "keys": [{"type": "GlobalReference", "value": SUBMODEL_SEMANTIC_ID}],
            },
            "submodelElements": [],
        }
    ],
}
"""The shape of an AAS JSON record (an AASX carries the motion file it needs)."""


@router.post(
    "/selections/from-aas",
    status_code=201,
    response_model=SelectionOut,
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {
                AASX_MEDIA_TYPE: {
                    "schema": {"type": "string", "format": "binary"},
                    "example": "(the AASX package, as GET /selections/{id}/aas.aasx writes it)",
                },
                "application/json": {"schema": {"type": "object"}, "example": _JSON_EXAMPLE},
            },
        }
    },
    responses={422: {"description": "a record that cannot be read or lacks the axis"}},
)
@reads_only  # no request transaction: it writes in its own (services.selections)
async def create_selection_from_aas(request: Request) -> Response:
    """Size the axis an IDTA 02021 record (AASX or AAS JSON) describes, and store it."""
    content = await request.body()
    return await run_in_threadpool(_size_record, content, request)


def _size_record(content: bytes, request: Request) -> Response:
    wanted = request_from_record(content)
    try:
        body = SelectionRequest.model_validate(wanted)
    except ValidationError as exc:
        errors = [{**e, "loc": ("body", *e["loc"])} for e in exc.errors()]
        raise RequestValidationError(errors) from None
    return create_selection(body, request)
