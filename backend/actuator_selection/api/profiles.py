"""Measured motion profiles: upload a CSV, answer the cycle it sizes, name it in selections."""

from __future__ import annotations

from datetime import UTC, datetime
from typing import Annotated, Any

from fastapi import APIRouter, Path, Query, Request
from fastapi.responses import JSONResponse
from starlette.concurrency import run_in_threadpool

from actuator_selection.http.deps import (
    catalogue_snapshot,
    read_transaction,
    reads_only,
    route_path,
    write_transaction,
)
from actuator_selection.http.errors import language_of
from actuator_selection.http.media_types import unsupported_media_type
from actuator_selection.i18n.localize import localized
from actuator_selection.schemas.profiles import ProfileOut, ProfileQuery
from actuator_selection.services.errors import not_found
from actuator_selection.services.profile_csv import MAX_PROFILE_BYTES, ColumnUnits
from actuator_selection.services.profiles import read_and_fit, store_profile, stored_profile

router = APIRouter(tags=["profiles"])

MEDIA_TYPES = ("text/csv", "text/plain", "text/tab-separated-values", "application/octet-stream")
"""What a profile file may be sent as (the page sends a file as it is)."""

_CSV_EXAMPLE = "Time [s];AngularVelocity [rad/s]\n0;0\n0.1;4.18879\n0.2;4.18879\n0.3;0\n1.3;0\n"


async def _chunks(request: Request) -> list[bytes]:
    """The body's chunks as they arrive, at most :data:`MAX_PROFILE_BYTES` and one more
    chunk (the reader names the limit, with the line it reached)."""
    chunks: list[bytes] = []
    size = 0
    async for chunk in request.stream():
        chunks.append(chunk)
        size += len(chunk)
        if size > MAX_PROFILE_BYTES:
            break
    return chunks


@router.post(
    "/profiles",
    status_code=201,
    response_model=ProfileOut,
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {"text/csv": {"schema": {"type": "string"}, "example": _CSV_EXAMPLE}},
        }
    },
    responses={
        413: {"description": "a file larger than the bulk body limit"},
        415: {"description": "a body that is not a CSV file"},
        422: {"description": "a file that breaks a rule: the entry names its line and column"},
    },
)
@reads_only  # no request transaction: it writes in its own
async def create_profile(request: Request, query: Annotated[ProfileQuery, Query()]) -> JSONResponse:
    """Read a measured motion profile (CSV) into the cycle the flowchart sizes, and store it."""
    media_type = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if media_type not in MEDIA_TYPES:
        raise unsupported_media_type(media_type, MEDIA_TYPES)
    chunks = await _chunks(request)
    stored = await run_in_threadpool(_read_and_store, request, chunks, query)
    location = route_path(request, "get_profile", profile_id=stored["id"])
    return JSONResponse(stored, status_code=201, headers={"Location": location})


def _read_and_store(request: Request, chunks: list[bytes], query: ProfileQuery) -> dict[str, Any]:
    with read_transaction(request) as session:
        catalogue = catalogue_snapshot(request, session)
    speeds = [a.max_speed_rpm for a in catalogue.actuators if a.max_speed_rpm is not None]
    units = ColumnUnits(
        time=query.time_unit,
        position=query.position_unit,
        velocity=query.velocity_unit,
        acceleration=query.acceleration_unit,
        load=query.load_unit,
    )
    answer = read_and_fit(
        iter(chunks), units, tolerance=query.tolerance_percent / 100.0, max_speeds_rpm=speeds
    )
    answer["notes"] = _worded(answer["notes"], language_of(request.scope))
    with write_transaction(request) as session:
        return store_profile(session, answer, datetime.now(UTC))


def _worded(notes: list[dict[str, Any]], language: str) -> list[dict[str, Any]]:
    return [localized(note, language) for note in notes]


@router.get(
    "/profiles/{profile_id}",
    response_model=ProfileOut,
    responses={404: {"description": "unknown profile"}},
)
def get_profile(profile_id: Annotated[str, Path(max_length=36)], request: Request) -> JSONResponse:
    """A stored profile, as its upload answered it."""
    with read_transaction(request) as session:
        answer = stored_profile(session, profile_id)
    if answer is None:
        raise not_found(["path", "profile_id"], "unknown_profile", id=profile_id)
    return JSONResponse(answer)
