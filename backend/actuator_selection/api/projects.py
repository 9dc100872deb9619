"""Machine projects: several axes on one DC bus, sized, stored, edited, listed (issue 31)."""

from __future__ import annotations

import base64
import gzip
from datetime import UTC, datetime
from functools import partial
from typing import Annotated

from fastapi import APIRouter, Path, Query, Request, Response

from actuator_selection.api.selections import unknown_models
from actuator_selection.http.deps import (
    SessionDep,
    read_transaction,
    reads_only,
    route_path,
    write_transaction,
)
from actuator_selection.http.errors import RequestFieldError, service_error
from actuator_selection.schemas.projects import ProjectOut, ProjectPageOut, ProjectRequest
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.projects import (
    create_project as store_new_project,
)
from actuator_selection.services.projects import (
    project_page,
    resize_project,
    stored_project,
    stored_request,
)

router = APIRouter(tags=["projects"])

MAX_PAGE = 100
"""Projects per page at most (``limit``)."""
_CURSOR_PREFIX = "project:"

ProjectId = Annotated[str, Path(max_length=36)]


def _refuse_unknown_models(body: ProjectRequest, catalogue: CatalogueSnapshot) -> None:
    """422 naming each chosen or listed model of an axis that the catalogue lacks."""
    errors = []
    for k, axis in enumerate(body.axes):
        asked = [axis.model] if axis.model is not None else []
        known = {a.model for a in catalogue.actuators_of([*asked, *(axis.models or [])])}
        if axis.model is not None and axis.model not in known:
            errors.append(
                service_error(
                    ["body", "axes", k, "model"],
                    "unknown_actuator",
                    "unknown_actuator",
                    model=axis.model,
                )
            )
        errors += unknown_models(["body", "axes", k, "models"], axis.models or [], known)
    if errors:
        raise RequestFieldError(errors)


def _catalogue(request: Request, body: ProjectRequest) -> CatalogueSnapshot:
    reader = partial(read_transaction, request)
    held: CatalogueSnapshot = request.app.state.catalogue.latest(reader)
    wanted = [m for a in body.axes for m in ([a.model] if a.model else []) + (a.models or [])]
    if not held.has_all(wanted):
        held = request.app.state.catalogue.refresh(reader)
    _refuse_unknown_models(body, held)
    return held


def _json(body: bytes, status_code: int = 200, location: str | None = None) -> Response:
    headers = {"Location": location} if location is not None else None
    return Response(body, status_code, headers, media_type="application/json")


@router.post(
    "/projects",
    status_code=201,
    response_model=ProjectOut,
    responses={422: {"description": "invalid axis or bus, or a model the catalogue lacks"}},
    description="Sizes every axis as POST /selections would (its chosen model, else the "
    "first candidate that publishes J_A), sums their electrical power on the DC bus over "
    "the machine cycle with their offsets, and stores the project.",
)
@reads_only  # writes in its own short transaction
def create_project(body: ProjectRequest, request: Request) -> Response:
    """Size a machine project and store it."""
    project_id, answer = store_new_project(
        body,
        _catalogue(request, body),
        partial(write_transaction, request),
        datetime.now(UTC),
    )
    location = project_location(request, project_id)
    return _json(answer, 201, location)


def project_location(request: Request, project_id: str) -> str:
    """The path of a stored project: a 201's ``Location``."""
    return route_path(request, "get_project", project_id=project_id)


@router.get(
    "/projects/{project_id}",
    response_model=ProjectOut,
    responses={404: {"description": "unknown project"}},
)
def get_project(project_id: ProjectId, session: SessionDep) -> Response:
    """A stored project, as it was last sized."""
    return _json(gzip.decompress(stored_project(session, project_id)))


@router.put(
    "/projects/{project_id}",
    response_model=ProjectOut,
    responses={
        404: {"description": "unknown project"},
        422: {"description": "invalid axis or bus, or a model the catalogue lacks"},
    },
)
@reads_only
def edit_project(project_id: ProjectId, body: ProjectRequest, request: Request) -> Response:
    """Replace a project's axes and bus, sized again and stored in place."""
    return _json(
        resize_project(
            project_id,
            body,
            _catalogue(request, body),
            partial(read_transaction, request),
            partial(write_transaction, request),
            datetime.now(UTC),
        )
    )


@router.post(
    "/projects/{project_id}/size",
    response_model=ProjectOut,
    responses={
        404: {"description": "unknown project"},
        422: {"description": "the catalogue no longer has a model an axis names"},
    },
)
@reads_only
def size_project_again(project_id: ProjectId, request: Request) -> Response:
    """Size a stored project again against the catalogue as it is now, stored in place."""
    reader = partial(read_transaction, request)
    stored = stored_request(reader, project_id)
    return _json(
        resize_project(
            project_id,
            stored,
            _catalogue(request, stored),
            reader,
            partial(write_transaction, request),
            datetime.now(UTC),
        )
    )


def encode_cursor(created_at: datetime, project_id: str) -> str:
    """The opaque cursor of the page after a project."""
    text = f"{_CURSOR_PREFIX}{created_at.isoformat()}|{project_id}"
    return base64.urlsafe_b64encode(text.encode()).decode().rstrip("=")


def decode_cursor(cursor: str) -> tuple[datetime, str]:
    """The (created_at, id) a cursor of :func:`encode_cursor` holds; 422 for other text."""
    try:
        text = base64.urlsafe_b64decode(cursor + "=" * (-len(cursor) % 4)).decode()
        at, project_id = text.removeprefix(_CURSOR_PREFIX).split("|", 1)
        if not text.startswith(_CURSOR_PREFIX) or not project_id:
            raise ValueError(cursor)
        return datetime.fromisoformat(at), project_id
    except (ValueError, UnicodeDecodeError):
        raise RequestFieldError(
            [service_error(["query", "cursor"], "invalid_cursor", "invalid_cursor")]
        ) from None


@router.get("/projects", response_model=ProjectPageOut)
def list_projects(
    session: SessionDep,
    limit: Annotated[
        int, Query(ge=1, le=MAX_PAGE, description=f"at most this many (≤ {MAX_PAGE})")
    ] = 20,
    cursor: Annotated[
        str | None,
        Query(max_length=200, description="the `next_cursor` of the page before"),
    ] = None,
) -> ProjectPageOut:
    """Stored projects in brief, oldest first, a page at a time."""
    briefs, more = project_page(
        session, limit=limit, after=decode_cursor(cursor) if cursor is not None else None
    )
    last = briefs[-1] if briefs else None
    return ProjectPageOut.model_validate(
        {
            "projects": briefs,
            "next_cursor": encode_cursor(last["created_at"], last["id"]) if more and last else None,
        }
    )
