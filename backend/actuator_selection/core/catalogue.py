"""Catalogue records: the engineering types with what the catalogue says besides them.

Repositories hand these out; the API's schemas build their bodies from them. Each
keeps its source, so every value shown can be traced to the publication it came from.
"""

from __future__ import annotations

from dataclasses import dataclass

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.compatibility import ActuatorInterface, Controller


@dataclass(frozen=True, slots=True, kw_only=True)
class ActuatorRecord:
    """A catalogue actuator with what the catalogue says besides the engineering values."""

    actuator: Actuator
    continuous_current_a: float | None
    inductance_line_mh: float | None
    inductance_phase_mh: float | None
    motor_torque_constant_nm_per_a: float | None
    mass_kg: float | None
    max_dc_bus_voltage_v: float | None
    supply_voltage: str | None
    feedback: str | None
    notes: str | None
    source: str
    zone_source: str | None
    derivation: str | None = None
    """How derived values of the row were obtained (e.g. rated output speed = n_N / i)."""
    read_at: str | None = None
    """Where values were read or checked (public copies of the documents ``source`` cites)."""


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
