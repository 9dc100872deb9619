"""Catalogue reads: actuators and families."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Query

from actuator_selection.api.deps import SessionDep
from actuator_selection.api.errors import ResourceNotFoundError, service_error
from actuator_selection.db.repositories import (
    ActuatorFilter,
    CatalogueRepository,
    CatalogueVersionRepository,
)
from actuator_selection.schemas.actuators import ActuatorOut, FamilyOut

router = APIRouter(tags=["catalogue"])


@router.get("/actuators")
def list_actuators(
    session: SessionDep,
    family: Annotated[str | None, Query(max_length=40, description="e.g. CHA")] = None,
    min_max_torque_nm: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="T_max at least [Nm]")
    ] = None,
    max_inertia_kgm2: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="J_A at most [kgm²]")
    ] = None,
    min_max_speed_rpm: Annotated[
        float | None, Query(ge=0, allow_inf_nan=False, description="n_max at least [rpm]")
    ] = None,
) -> list[ActuatorOut]:
    """Catalogue actuators, filtered, ordered by model."""
    records = CatalogueRepository(session).actuators(
        ActuatorFilter(
            family=family,
            min_max_torque_nm=min_max_torque_nm,
            max_inertia_kgm2=max_inertia_kgm2,
            min_max_speed_rpm=min_max_speed_rpm,
        )
    )
    return [ActuatorOut.from_record(r) for r in records]


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
