"""Catalogue reads: actuators and families."""

from __future__ import annotations

import base64
from typing import Annotated

from fastapi import APIRouter, Query

from actuator_selection.db.repositories import (
    ActuatorFilter,
    CatalogueRepository,
    CatalogueVersionRepository,
)
from actuator_selection.http.deps import SessionDep
from actuator_selection.http.errors import RequestFieldError, ResourceNotFoundError, service_error
from actuator_selection.schemas.actuators import ActuatorOut, ActuatorPageOut, FamilyOut

router = APIRouter(tags=["catalogue"])


MAX_PAGE = 500
"""Actuators per page at most (``limit``)."""
_CURSOR_PREFIX = "after:"


def encode_cursor(model: str) -> str:
    """The opaque cursor of the page after ``model``."""
    return base64.urlsafe_b64encode(f"{_CURSOR_PREFIX}{model}".encode()).decode().rstrip("=")


def decode_cursor(cursor: str) -> str:
    """The model name a cursor of :func:`encode_cursor` holds; 422 for any other text."""
    try:
        text = base64.urlsafe_b64decode(cursor + "=" * (-len(cursor) % 4)).decode()
    except (ValueError, UnicodeDecodeError):
        text = ""
    if not text.startswith(_CURSOR_PREFIX) or len(text) == len(_CURSOR_PREFIX):
        raise RequestFieldError(
            [service_error(["query", "cursor"], "invalid_cursor", "invalid_cursor")]
        )
    return text.removeprefix(_CURSOR_PREFIX)


Limit = Annotated[
    int | None,
    Query(ge=1, le=MAX_PAGE, description=f"at most this many (≤ {MAX_PAGE}); omitted: all"),
]
Cursor = Annotated[
    str | None,
    Query(
        max_length=200,
        description="the `next_cursor` of the page before; omitted: the first page",
    ),
]


@router.get("/actuators")
def list_actuators(
    session: SessionDep,
    family: Annotated[str | None, Query(max_length=40, description="e.g. CHA")] = None,
    min_max_torque_nm: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="T_max at least [Nm]")
    ] = None,
    max_max_torque_nm: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="T_max at most [Nm]")
    ] = None,
    min_continuous_torque_nm: Annotated[
        float | None,
        Query(
            ge=0,
            allow_inf_nan=False,
            description="continuous torque T_N at least [Nm] (leaves out those without one)",
        ),
    ] = None,
    gear_ratio: Annotated[
        float | None, Query(gt=0, allow_inf_nan=False, description="gear ratio i, e.g. 50")
    ] = None,
    max_inertia_kgm2: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="J_A at most [kgm²]")
    ] = None,
    min_max_speed_rpm: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="n_max at least [rpm]")
    ] = None,
    limit: Limit = None,
    cursor: Cursor = None,
) -> ActuatorPageOut:
    """Catalogue actuators, filtered, ordered by model; a page of ``limit`` of them, the next
    one from ``next_cursor``."""
    records = CatalogueRepository(session).actuators(
        ActuatorFilter(
            family=family,
            min_max_torque_nm=min_max_torque_nm,
            max_max_torque_nm=max_max_torque_nm,
            min_continuous_torque_nm=min_continuous_torque_nm,
            gear_ratio=gear_ratio,
            max_inertia_kgm2=max_inertia_kgm2,
            min_max_speed_rpm=min_max_speed_rpm,
            after_model=decode_cursor(cursor) if cursor is not None else None,
            limit=limit + 1 if limit is not None else None,  # one more: is there a next page?
        )
    )
    more = limit is not None and len(records) > limit
    page = records[:limit] if limit is not None else records
    return ActuatorPageOut(
        actuators=[ActuatorOut.from_record(r) for r in page],
        next_cursor=encode_cursor(page[-1].actuator.model) if more else None,
    )


@router.get("/actuators/{model}", responses={404: {"description": "unknown model"}})
def get_actuator(model: str, session: SessionDep) -> ActuatorOut:
    """One catalogue actuator."""
    record = CatalogueRepository(session).actuator(model)
    if record is None:
        raise ResourceNotFoundError(
            [service_error(["path", "model"], "not_found", "unknown_actuator", model=model)]
        )
    return ActuatorOut.from_record(record)


@router.get("/families")
def list_families(session: SessionDep) -> list[FamilyOut]:
    """Product families with their temperature sensors and limits (Tables 518.1, 519.2)."""
    return [FamilyOut.from_record(f) for f in CatalogueRepository(session).families()]


@router.get("/catalogue/version")
def catalogue_version(session: SessionDep) -> dict[str, int]:
    """The catalogue's version: raised by every change; each selection records the one it used."""
    return {"version": CatalogueVersionRepository(session).current()}
