"""The selection flowchart over the catalogue, stored and retrievable."""

from __future__ import annotations

import uuid
from datetime import UTC, datetime

import pydantic_core
from fastapi import APIRouter, Request, Response

from actuator_selection.api.deps import (
    SessionDep,
    catalogue_snapshot,
    reads_only,
    write_transaction,
)
from actuator_selection.api.drive import DriveContext
from actuator_selection.api.errors import RequestFieldError, ResourceNotFoundError, field_error
from actuator_selection.core.selection import select
from actuator_selection.db.repositories import (
    SelectionRepository,
)
from actuator_selection.schemas.selections import RANKING_RULE, SelectionOut, SelectionRequest

router = APIRouter(tags=["selections"])


@router.post(
    "/selections",
    status_code=201,
    response_model=SelectionOut,
    responses={422: {"description": "invalid load case, or a model the catalogue lacks"}},
    description="Runs the flowchart for every catalogue actuator (or the `models` listed) and "
    f"stores the result. Ranking: {RANKING_RULE}.",
)
@reads_only
def create_selection(body: SelectionRequest, request: Request, session: SessionDep) -> Response:
    """Size the load case against the catalogue and store the selection."""
    catalogue = catalogue_snapshot(request, session)
    actuators = catalogue.actuators_of(body.models)
    if body.models is not None:
        known = {a.model for a in actuators}
        unknown = [
            field_error(["body", "models", i], f"unknown actuator model {m!r}", "unknown_model")
            for i, m in enumerate(body.models)
            if m not in known
        ]
        if unknown:
            raise RequestFieldError(unknown)
    selection = select(actuators, body.to_core())
    drive = DriveContext(catalogue)
    speed = body.load.speed_rpm
    out = SelectionOut.build(
        id=str(uuid.uuid4()),
        created_at=datetime.now(UTC),
        catalogue_version=catalogue.version,
        request=body,
        selection=selection,
        drives={a.model: drive.options(a, speed_rpm=speed) for a in actuators},
    )
    stored_request, stored_response = body.model_dump(mode="json"), out.model_dump(mode="json")
    # Computed from the read snapshot above; stored in a short write transaction of its own.
    with write_transaction(request) as writer:
        SelectionRepository(writer).add(
            id=out.id,
            created_at=out.created_at,
            catalogue_version=out.catalogue_version,
            request=stored_request,
            response=stored_response,
        )
    # Encoded once from the dump just stored: returning the model would have FastAPI
    # validate and encode the ≈ 1 MB again.
    return Response(
        pydantic_core.to_json(stored_response), status_code=201, media_type="application/json"
    )


@router.get(
    "/selections/{selection_id}",
    response_model=SelectionOut,
    responses={404: {"description": "unknown selection"}},
)
def get_selection(selection_id: str, session: SessionDep) -> Response:
    """A stored selection, exactly as it was answered."""
    stored = SelectionRepository(session).response(selection_id)
    if stored is None:
        raise ResourceNotFoundError.at(
            ["path", "selection_id"], f"no selection {selection_id!r}", "not_found"
        )
    # Written as stored: it was a validated SelectionOut when it was stored, and
    # validating the ≈ 1 MB again took 45 % of this request.
    return Response(pydantic_core.to_json(stored), media_type="application/json")
