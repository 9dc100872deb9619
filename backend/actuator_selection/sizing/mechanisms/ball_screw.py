"""A ball screw on an incline, from first principles."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import STANDARD_GRAVITY_M_PER_S2, _check
from actuator_selection.sizing.mechanisms.linear import (
    LinearLaw,
    _check_efficiency,
    _check_incline,
    _linear_axis,
    _nonnegative,
    incline_forces,
)

# --- linear axes from first principles ----------------------------------------------------


@dataclass(frozen=True, slots=True, kw_only=True)
class InclinedBallScrew:
    """A ball-screw axis at any incline, vertical included (Fig. 515.2 tilted by θ).

    Parameters
    ----------
    mass_kg
        Moved mass m [kg], ≥ 0 (slide and payload).
    lead_m
        Screw lead P [m per revolution], > 0.
    friction_coefficient
        μ [-] of the guide, ≥ 0; its normal force is m·g·cos θ.
    efficiency
        η [-] of the screw, 0 < η ≤ 1, applied by power flow (module doc).
    incline_deg
        θ [°], −90…90: 0 horizontal, 90 vertical with positive motion lifting.
    screw_inertia_kgm2
        J_S [kgm²], ≥ 0.
    counterweight_kg
        m_c [kg], ≥ 0, hanging on a rope over a pulley (module doc).
    friction_force_n
        A friction force [N], ≥ 0, that does not depend on the weight (seals, wipers,
        preload).
    """

    mass_kg: float
    lead_m: float
    friction_coefficient: float
    efficiency: float
    incline_deg: float = 0.0
    screw_inertia_kgm2: float = 0.0
    counterweight_kg: float = 0.0
    friction_force_n: float = 0.0

    def __post_init__(self) -> None:
        _nonnegative("mass_kg", self.mass_kg, N_("a mass"))
        _check("lead_m", self.lead_m, positive=True, rule=N_("the screw advances per revolution"))
        _nonnegative(
            "friction_coefficient", self.friction_coefficient, N_("friction opposes motion")
        )
        _check_efficiency("efficiency", self.efficiency, what=N_("screw"))
        _check_incline("incline_deg", self.incline_deg)
        _nonnegative("screw_inertia_kgm2", self.screw_inertia_kgm2, N_("a moment of inertia"))
        _nonnegative("counterweight_kg", self.counterweight_kg, N_("a mass"))
        _nonnegative("friction_force_n", self.friction_force_n, N_("friction opposes motion"))


def inclined_ball_screw_axis(
    screw: InclinedBallScrew, *, g: float = STANDARD_GRAVITY_M_PER_S2
) -> AxisLoad:
    """A ball screw at incline θ (first principles with r = P/2π, module doc).

    J_L = J_S + (m + m_c)·(P/2π)²,
    T_G = (m·sin θ − m_c)·g·P/2π,
    T_F = (μ·m·g·cos θ + F_F)·P/2π,   η of the screw by power flow.

    A vertical 20 kg slide on a 10 mm lead: T_G = 20·9.81·0.01/2π = 0.31226 Nm, no guide
    friction; J_L = 20·(0.01/2π)² = 5.066·10⁻⁵ kgm²:

    >>> axis = inclined_ball_screw_axis(InclinedBallScrew(
    ...     mass_kg=20, lead_m=0.01, friction_coefficient=0.1, efficiency=0.9, incline_deg=90))
    >>> round(axis.gravity_torque_nm, 5), axis.friction_torque_nm, round(axis.inertia_kgm2, 8)
    (0.31226, 0.0, 5.066e-05)
    >>> axis.efficiency
    0.9
    """
    law = inclined_ball_screw_law(screw, g=g)
    return _linear_axis(
        radius_m=screw_radius_m(screw.lead_m),
        radius_field="lead_m",
        rotating_inertia_kgm2=screw.screw_inertia_kgm2,
        moving_mass_kg=law.moving_mass_kg,
        gravity_force_n=law.gravity_force_n,
        friction_force_n=law.friction_force_n,
        efficiency=screw.efficiency,
    )


def screw_radius_m(lead_m: Any) -> Any:
    """r = P/2π of a lead P [m] (a float, or an array of many leads)."""
    return lead_m / (2 * math.pi)


def inclined_ball_screw_law(
    screw: InclinedBallScrew, *, g: float = STANDARD_GRAVITY_M_PER_S2
) -> LinearLaw:
    """:func:`inclined_ball_screw_axis` as a function of the lead P: r = P/2π, J_S, and
    the moved mass m + m_c and the forces, which do not depend on P."""
    gravity, friction = incline_forces(screw, g=g)
    inertia = screw.screw_inertia_kgm2
    return LinearLaw(
        radius_m=screw_radius_m,
        rotating_inertia_kgm2=lambda leads: np.full(leads.shape, inertia),
        moving_mass_kg=screw.mass_kg + screw.counterweight_kg,
        gravity_force_n=gravity,
        friction_force_n=friction,
        efficiency=screw.efficiency,
    )
