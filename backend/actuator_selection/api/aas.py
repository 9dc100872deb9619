"""A stored selection as an IDTA 02021 sizing record (Asset Administration Shell)."""

from __future__ import annotations

from typing import Annotated, Any
from urllib.parse import quote

from fastapi import APIRouter, Path, Query, Request, Response

from actuator_selection.api.deps import SessionDep, catalogue_snapshot
from actuator_selection.api.messages import localizer
from actuator_selection.schemas.aas import AasRecordQuery
from actuator_selection.services.aas import (
    SizingRecord,
    record_aasx,
    record_json,
    sizing_record,
)

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
