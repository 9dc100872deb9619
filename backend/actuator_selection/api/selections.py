"""The selection flowchart over the catalogue, stored and retrievable."""

from __future__ import annotations

import uuid
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import UTC, datetime
from typing import Any

import pydantic_core
from fastapi import APIRouter, Request, Response

from actuator_selection.api.deps import (
    SessionDep,
    catalogue_snapshot,
    reads_only,
    write_transaction,
)
from actuator_selection.api.drive import CatalogueSnapshot, DriveContext
from actuator_selection.api.errors import RequestFieldError, ResourceNotFoundError, field_error
from actuator_selection.core.actuators import Actuator
from actuator_selection.core.selection import Application, select
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
    sized = size_selection(
        body, body.to_core(), actuators, catalogue, DriveContext(catalogue), datetime.now(UTC)
    )
    store_selections(request, [sized])
    # Encoded once from the dump just stored: returning the model would have FastAPI
    # validate and encode the ≈ 1 MB again.
    return Response(
        pydantic_core.to_json(sized.response), status_code=201, media_type="application/json"
    )


@dataclass(frozen=True, slots=True)
class SizedSelection:
    """A selection computed for storing: its answer, and the request and answer as JSON."""

    out: SelectionOut
    request: dict[str, Any]
    response: dict[str, Any]


def size_selection(
    body: SelectionRequest,
    app: Application,
    actuators: Sequence[Actuator],
    catalogue: CatalogueSnapshot,
    drive: DriveContext,
    created_at: datetime,
) -> SizedSelection:
    """The whole ranking of ``app`` over ``actuators`` as POST /selections answers it."""
    out = SelectionOut.build(
        id=str(uuid.uuid4()),
        created_at=created_at,
        catalogue_version=catalogue.version,
        request=body,
        selection=select(actuators, app),
        drives={a.model: drive.options(a, speed_rpm=body.load.speed_rpm) for a in actuators},
    )
    return SizedSelection(
        out=out, request=body.model_dump(mode="json"), response=out.model_dump(mode="json")
    )


def store_selections(request: Request, sized: Sequence[SizedSelection]) -> None:
    """Store selections computed from a read snapshot, in a short write transaction of
    their own, committed before this returns (so before the 201)."""
    with write_transaction(request) as writer:
        repository = SelectionRepository(writer)
        for s in sized:
            repository.add(
                id=s.out.id,
                created_at=s.out.created_at,
                catalogue_version=s.out.catalogue_version,
                request=s.request,
                response=s.response,
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
