"""Catalogue resources: actuators and their families."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Self

from pydantic import Field, create_model

from actuator_selection.catalogue.fields import ACTUATOR_FIELDS, CatalogueField, Kind
from actuator_selection.catalogue.records import ActuatorRecord, FamilyRecord
from actuator_selection.schemas.common import ResponseModel
from actuator_selection.sizing.electrical import OUTPUT_TURNS_OPPOSITE_TO_MOTOR


class ZonePointOut(ResponseModel):
    """A corner of the continuous-duty zone's upper edge."""

    speed_rpm: float
    torque_nm: float


class ActuatorBody(ResponseModel):
    """What every actuator body does; :data:`ActuatorOut` adds its properties."""

    @classmethod
    def from_record(cls, record: ActuatorRecord) -> Self:
        """The response body of one catalogue record."""
        zone = record.actuator.zone
        return cls(
            **record.values,
            continuous_duty_zone=(
                [ZonePointOut(speed_rpm=p.speed_rpm, torque_nm=p.torque_nm) for p in zone.points]
                if zone
                else None
            ),
            continuous_duty_zone_source=record.zone_source,
        )


def _property(field: CatalogueField) -> tuple[Any, Any]:
    """The property of a catalogue value: a number or a text, ``null`` where the catalogue
    has none, described by its symbol, words and unit."""
    kind: Any = float if field.kind is Kind.NUMBER else str
    return (kind if field.required else kind | None, Field(description=field.description))


_ZONE_AND_DIRECTION: dict[str, tuple[Any, Any]] = {
    "continuous_duty_zone": (
        list[ZonePointOut] | None,
        Field(description="upper edge of the continuous-duty zone, where published"),
    ),
    "continuous_duty_zone_source": (str | None, ...),
    "output_turns_opposite_to_motor": (
        bool,
        Field(
            default=OUTPUT_TURNS_OPPOSITE_TO_MOTOR,
            description="the integrated Harmonic Drive gear reverses the direction: the output "
            "turns counter-clockwise when the motor shaft turns clockwise (chapter, Direction "
            "of Rotation)",
        ),
    ),
}
"""The properties besides the catalogue values; they follow the interface's values
(``feedback``), where the body has always shown them."""


def _properties() -> dict[str, tuple[Any, Any]]:
    properties: dict[str, tuple[Any, Any]] = {}
    for field in ACTUATOR_FIELDS:
        properties[field.name] = _property(field)
        if field.name == "feedback":
            properties |= _ZONE_AND_DIRECTION
    return properties


if TYPE_CHECKING:

    class ActuatorOut(ActuatorBody):
        def __getattr__(self, name: str) -> Any:
            """A catalogue value: its property is generated from its declaration."""

else:
    ActuatorOut = create_model(
        "ActuatorOut",
        __base__=ActuatorBody,
        __module__=__name__,
        __doc__="""A catalogue actuator; ``null`` where no public source gives the value.""",
        **_properties(),
    )
    """A catalogue actuator: a property per catalogue value (:data:`ACTUATOR_FIELDS`), in
    their order, and its continuous-duty zone."""


class ActuatorPageOut(ResponseModel):
    """A page of catalogue actuators, ordered by model."""

    actuators: list[ActuatorOut]
    next_cursor: str | None = Field(
        description="give as `cursor` for the next page; null: this is the last page"
    )


class FamilyOut(ResponseModel):
    """A product family with its temperature sensor (Table 518.1) and limits (Table 519.2)."""

    name: str
    description: str | None
    temperature_sensors: str | None
    warning_temperature_c: float | None
    shutdown_temperature_c: float | None
    temperature_tolerance_percent: float | None
    warning_resistance_ohm: float | None
    shutdown_resistance_ohm: float | None
    resistance_tolerance_percent: float | None
    source: str

    @classmethod
    def from_record(cls, record: FamilyRecord) -> FamilyOut:
        """The response body of one family."""
        return cls.model_validate(record, from_attributes=True)
