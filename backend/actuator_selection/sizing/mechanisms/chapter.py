"""The chapter's two mechanisms as axis loads: the ball screw (Eq. 515.4) and the rotary
table (Eq. 515.6).
"""

from __future__ import annotations

import math

from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import (
    STANDARD_GRAVITY_M_PER_S2,
    BallScrew,
    RotaryTable,
    ball_screw_load,
    rotary_table_load,
)
from actuator_selection.sizing.mechanisms.linear import _speed_factor

# --- the chapter's mechanisms ------------------------------------------------------------


def chapter_ball_screw_axis(screw: BallScrew, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A horizontal ball-screw axis exactly as the chapter sizes it (Eq. 515.4).

    J_L = J_S + m·(P/2π)²,  T_F = μ·m·P·g/(2π·η),  η = 1 on (Eq. 515.4 holds the losses),
    T_G = 0; load speed in mm/s (1 mm/s is 60/(1000·P) rpm), process force in N (P/2π Nm).
    T_F and J_L are those of :func:`~actuator_selection.sizing.loads.ball_screw_load`.

    >>> screw = BallScrew(mass_kg=100, lead_m=0.01, friction_coefficient=0.1,
    ...                   efficiency=0.9, screw_inertia_kgm2=0.001)
    >>> axis = chapter_ball_screw_axis(screw)
    >>> round(axis.inertia_kgm2, 7), round(axis.friction_torque_nm, 5), axis.efficiency
    (0.0012533, 0.17348, 1.0)
    >>> round(axis.speed_rpm_per_unit, 6)  # 60/(1000·0.01) = 6 rpm per mm/s
    6.0
    """
    load = ball_screw_load(screw, g=g)
    radius_m = screw.lead_m / (2 * math.pi)
    speed = _speed_factor(radius_m, "lead_m")
    return AxisLoad(
        inertia_kgm2=load.inertia_kgm2,
        friction_torque_nm=load.torque_nm,
        speed_rpm_per_unit=speed,
        torque_nm_per_force_unit=radius_m,
        speed_unit="mm/s",
        force_unit="N",
    )


def rotary_table_axis(table: RotaryTable, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A rotary table on the output (Eq. 515.6): J_L = m·D²/8, T_F = μ·m·g·r, η = 1.

    Speed in rpm and process load in Nm, one for one.

    >>> axis = rotary_table_axis(RotaryTable(mass_kg=50, diameter_m=0.4,
    ...                                      friction_coefficient=0.02, friction_radius_m=0.15))
    >>> round(axis.inertia_kgm2, 6), round(axis.friction_torque_nm, 5), axis.speed_unit
    (1.0, 1.4715, 'rpm')
    """
    load = rotary_table_load(table, g=g)
    return AxisLoad(inertia_kgm2=load.inertia_kgm2, friction_torque_nm=load.torque_nm)
