"""The chapter's worked example (Table 516.1 load and cycle, Table 516.3 FHA-25C-50-L), once."""

from __future__ import annotations

from typing import Any

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.selection import Application

PATTERN = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
LOAD = Load(torque_nm=5, inertia_kgm2=1.3)
APPLICATION = Application(pattern=PATTERN, load=LOAD)
FHA_25C_50_L = Actuator(
    model="FHA-25C-50-L",
    family="FHA-C",
    gear_ratio=50,
    max_torque_nm=151,
    max_speed_rpm=90,
    inertia_kgm2=0.86,
)


def request() -> dict[str, Any]:
    """A fresh selection request body of the worked example (no model restriction)."""
    return {
        "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
    }


DRIVEN: dict[str, Any] = {
    "motor_voltage_constant_v_per_krpm": 37.0,
    "max_current_a": 4.0,
    "resistance_line_ohm": 3.7,
    "inductance_line_mh": 6.0,
    "pole_pairs": 6.0,
    "dc_bus_voltage_v": 560.0,
}
"""The winding of the CHA-25A-50 (CHA catalogue 1018854: K_E 37 V/1000 rpm, I_max 4.0 A,
R 3.7 Ω, L 6.0 mH line-to-line, p = 6) on a 560 V bus of a listed controller: with
``dataclasses.replace(actuator, **DRIVEN)`` a synthetic actuator of the tests has a drive
that reaches the worked example's 40 rpm (93.8 V needed, 396 V available), so that the
``drive_voltage`` check passes and its verdict can be suitable."""
