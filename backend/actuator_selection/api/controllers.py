"""Servo controllers (Table 521.1) and their matching against catalogue actuators."""

from __future__ import annotations

from typing import Annotated, Literal

from fastapi import APIRouter, Path, Query

from actuator_selection.catalogue.controllers import (
    BusClass,
    FeedbackSystem,
    Option,
    SupportLevel,
    product_family,
)
from actuator_selection.catalogue.csvio import WHOLE_NUMBER_MAX
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.repositories import CatalogueRepository
from actuator_selection.errors import NotFoundError
from actuator_selection.http.deps import SessionDep
from actuator_selection.http.errors import (
    RequestFieldError,
    ResourceNotFoundError,
    field_error,
    service_error,
)
from actuator_selection.schemas.controllers import (
    ActuatorControllersOut,
    ControllerMatchOut,
    ControllerOut,
    InterfaceOut,
)
from actuator_selection.sizing.compatibility import match_controllers

router = APIRouter(tags=["controllers"])


@router.get(
    "/controllers", responses={422: {"description": "an unknown family or a bad filter value"}}
)
def list_controllers(
    session: SessionDep,
    manufacturer: Annotated[str | None, Query(max_length=80, description="substring")] = None,
    family: Annotated[
        str | None, Query(max_length=40, description="actuator family, e.g. CHA or FHA-C mini")
    ] = None,
    bus_class: BusClass | None = None,
    sensor: TemperatureSensor | None = None,
    feedback: FeedbackSystem | None = None,
    level: Annotated[
        Literal["tested", "possible"],
        Query(description="least level the given criteria need: 'possible' admits ● and ○"),
    ] = "possible",
) -> list[ControllerOut]:
    """Rows of Table 521.1 that support every given criterion at the given level."""
    options: list[Option] = [o for o in (bus_class, sensor, feedback) if o is not None]
    if family is not None:
        try:
            options.append(product_family(family))
        except NotFoundError as exc:  # a filter value, named where it was sent
            raise RequestFieldError(
                [field_error(["query", "family"], exc.message, "unknown_family")]
            ) from None
    wanted = {SupportLevel.TESTED} if level == "tested" else set(SupportLevel)
    records = ProtectionRepository(session).controllers()
    return [
        ControllerOut.from_record(r)
        for r in records
        if (manufacturer is None or manufacturer.lower() in r.controller.manufacturer.lower())
        and all(r.controller.level(o) in wanted for o in options)
    ]


@router.get("/controllers/{row}", responses={404: {"description": "unknown or retired row"}})
def get_controller(
    row: Annotated[int, Path(ge=1, le=WHOLE_NUMBER_MAX, description="`source_row`")],
    session: SessionDep,
) -> ControllerOut:
    """One row of the compatibility matrix (Table 521.1's rows keep their printed number)."""
    record = ProtectionRepository(session).controller(row)
    if record is None:
        raise ResourceNotFoundError(
            [service_error(["path", "row"], "not_found", "unknown_controller_row", row=row)]
        )
    return ControllerOut.from_record(record)


@router.get("/actuators/{model}/controllers", responses={404: {"description": "unknown model"}})
def actuator_controllers(model: str, session: SessionDep) -> ActuatorControllersOut:
    """Every controller matched against the actuator, supported ones first."""
    if CatalogueRepository(session).actuator(model) is None:
        raise ResourceNotFoundError(
            [service_error(["path", "model"], "not_found", "unknown_actuator", model=model)]
        )
    repo = ProtectionRepository(session)
    interface = repo.interfaces([model])[model]
    result = match_controllers(
        actuator=interface.interface, controllers=[r.controller for r in repo.controllers()]
    )
    return ActuatorControllersOut(
        model=model,
        interface=InterfaceOut.from_record(interface),
        controllers=[ControllerMatchOut.from_core(m) for m in result.matches],
    )
