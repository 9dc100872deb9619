"""The chapter's worked example (Table 516.1 load and cycle, Table 516.3 FHA-25C-50-L), once."""

from __future__ import annotations

from typing import Any

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.cycle import Load, SpeedPattern
from actuator_selection.core.selection import Application

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
