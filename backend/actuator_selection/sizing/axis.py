"""A load as the actuator output sees it, whatever mechanism lies between (issue "Real axes").

Every mechanism (``sizing/mechanisms``: ball screw, rotary table, belt, rack, conveyor,
lift, with or without a transmission ratio) resolves to one :class:`AxisLoad`; the cycle
(``sizing/motion``) turns it and a list of segments into the torque of each segment.

The torque the actuator gives in a segment (speed direction ``s`` = ±1, output
acceleration α [rad/s²], process torque T_P of the segment) is

    load side:   T_load = T_G + s·T_F + T_P + J_L·α
    at the output: T = T_load/η + J_A·α   where the actuator drives the load (T_load·s > 0),
                   T = T_load·η + J_A·α   where the load drives the actuator back,

the convention of the sizing tools engineers know (losses add to the torque the motor
gives, and relieve it when the load pushes back). With η = 1 it is the chapter's
Eq. 514.1: T = T_L + (J_A + J_L)·α. At standstill friction is zero and the gravity and
process torques are held without losses (on the safe side: friction in a real screw or
gear helps to hold).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_


@dataclass(frozen=True, slots=True, kw_only=True)
class AxisLoad:
    """A load resolved to the actuator output.

    Parameters
    ----------
    inertia_kgm2
        J_L [kgm²], ≥ 0: every moving part after the actuator (transmission, mechanism,
        moved mass), referred to the output.
    friction_torque_nm
        T_F [Nm], ≥ 0: friction at the output, opposing the motion; zero at standstill.
    gravity_torque_nm
        T_G [Nm], signed: a torque that acts whether the axis moves or not (a weight, less
        its counterweight); positive opposes positive rotation (lifting is positive).
    efficiency
        η [-], 0 < η ≤ 1, of what lies between the actuator output and the load, applied
        by the direction of power flow (module docstring). 1 where the mechanism's own
        equation holds its losses already (the chapter's Eq. 515.4 divides T_F by η).
    speed_rpm_per_unit
        Output speed [rpm] per unit of load speed (1 for a rotary load in rpm; for a linear
        axis, rpm per mm/s).
    torque_nm_per_force_unit
        Output torque [Nm] per unit of process load (per N for a linear axis, per Nm for a
        rotary one).
    speed_unit
        The unit of load speed: ``"rpm"`` or ``"mm/s"``.
    force_unit
        The unit of process load: ``"Nm"`` or ``"N"``.
    """

    inertia_kgm2: float
    friction_torque_nm: float
    gravity_torque_nm: float = 0.0
    efficiency: float = 1.0
    speed_rpm_per_unit: float = 1.0
    torque_nm_per_force_unit: float = 1.0
    speed_unit: str = "rpm"
    force_unit: str = "Nm"

    def __post_init__(self) -> None:
        if (
            0.0 <= self.inertia_kgm2 < math.inf
            and 0.0 <= self.friction_torque_nm < math.inf
            and -math.inf < self.gravity_torque_nm < math.inf
            and 0.0 < self.efficiency <= 1.0
            and 0.0 < self.speed_rpm_per_unit < math.inf
            and 0.0 < self.torque_nm_per_force_unit < math.inf
        ):
            return  # every rule below holds (NaN fails each comparison)
        for name in (
            "inertia_kgm2",
            "friction_torque_nm",
            "gravity_torque_nm",
            "efficiency",
            "speed_rpm_per_unit",
            "torque_nm_per_force_unit",
        ):
            value = getattr(self, name)
            if not math.isfinite(value):
                raise InvalidInputError(name, code="not_finite", params={"value": value})
        if self.inertia_kgm2 < 0:
            raise InvalidInputError(
                "inertia_kgm2",
                code="must_be_nonnegative",
                params={"rule": N_("a moment of inertia")},
            )
        if self.friction_torque_nm < 0:
            raise InvalidInputError(
                "friction_torque_nm",
                code="must_be_nonnegative",
                params={"rule": N_("friction opposes motion")},
            )
        if not 0 < self.efficiency <= 1:
            raise InvalidInputError("efficiency", code="efficiency_range")
        if self.speed_rpm_per_unit <= 0:
            raise InvalidInputError("speed_rpm_per_unit", code="positive")
        if self.torque_nm_per_force_unit <= 0:
            raise InvalidInputError("torque_nm_per_force_unit", code="positive")

    @property
    def travel_mm_per_rad(self) -> float | None:
        """How far a linear axis's load moves per radian the actuator output turns [mm/rad],
        from the mechanism's one kinematic ratio (``speed_rpm_per_unit`` output rpm per
        mm/s: n = k·v, so θ = k·v·t·2π/60 and the travel v·t = θ·60/(2π·k)); None for a
        rotary load (speed in rpm), whose output angle is the answer.

        A 10 mm lead advances 10 mm per turn, 10/2π = 1.5915 mm per radian:

        >>> from actuator_selection.sizing.mechanisms import (
        ...     InclinedBallScrew, inclined_ball_screw_axis)
        >>> screw = InclinedBallScrew(mass_kg=20, lead_m=0.01, friction_coefficient=0,
        ...     efficiency=1, incline_deg=90)
        >>> round(inclined_ball_screw_axis(screw).travel_mm_per_rad, 4)
        1.5915
        """
        if self.speed_unit != "mm/s":
            return None
        return 60.0 / (2.0 * math.pi * self.speed_rpm_per_unit)
