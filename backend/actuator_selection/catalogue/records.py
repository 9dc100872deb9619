"""Catalogue records: the engineering types with what the catalogue says besides them.

Repositories hand these out; the API's schemas build their bodies from them. Each
keeps its source, so every value shown can be traced to the publication it came from.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.controllers import ActuatorInterface, Controller
from actuator_selection.catalogue.fields import CatalogueValue


@dataclass(frozen=True, slots=True, kw_only=True)
class ActuatorRecord:
    """A catalogue actuator: the engine's record and every value the catalogue holds for it."""

    actuator: Actuator
    values: Mapping[str, CatalogueValue]
    """Every value of :data:`~.catalogue_fields.ACTUATOR_FIELDS` by name, as stored (the
    engine's among them): what the API shows, with the row's ``notes``, ``derivation``
    (how derived values were obtained) and ``source``."""
    zone_source: str | None
    """The sources of the continuous-duty zone's points, where it has any."""


@dataclass(frozen=True, slots=True, kw_only=True)
class FamilyRecord:
    """A product family with its temperature sensor and limits (Tables 518.1, 519.2)."""

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


@dataclass(frozen=True, slots=True, kw_only=True)
class ControllerRecord:
    """A controller with its catalogue provenance."""

    controller: Controller
    source: str


@dataclass(frozen=True, slots=True, kw_only=True)
class InterfaceRecord:
    """An actuator's matching data and how it was obtained."""

    interface: ActuatorInterface
    derivation: str | None
    source: str | None
