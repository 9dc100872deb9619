"""A rack and pinion, from first principles."""

from __future__ import annotations

from dataclasses import dataclass

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
    half,
    incline_forces,
)


@dataclass(frozen=True, slots=True, kw_only=True)
class RackPinion:
    """A linear axis driven by a pinion on a rack.

    Parameters
    ----------
    mass_kg
        Moved mass m [kg], ≥ 0 (on a moving gantry with a fixed rack: the actuator too).
    pinion_diameter_m
        Pitch diameter d of the pinion [m], > 0; r = d/2.
    friction_coefficient
        μ [-] of the guide, ≥ 0; its normal force is m·g·cos θ.
    efficiency
        η [-] of the rack and pinion, 0 < η ≤ 1, applied by power flow.
    incline_deg
        θ [°], −90…90.
    pinion_inertia_kgm2
        J_P [kgm²], ≥ 0.
    counterweight_kg
        m_c [kg], ≥ 0 (module doc).
    friction_force_n
        Friction force [N], ≥ 0, independent of the weight.
    """

    mass_kg: float
    pinion_diameter_m: float
    friction_coefficient: float
    efficiency: float
    incline_deg: float = 0.0
    pinion_inertia_kgm2: float = 0.0
    counterweight_kg: float = 0.0
    friction_force_n: float = 0.0

    def __post_init__(self) -> None:
        _nonnegative("mass_kg", self.mass_kg, N_("a mass"))
        _check("pinion_diameter_m", self.pinion_diameter_m, positive=True, rule=N_("a pinion"))
        _nonnegative(
            "friction_coefficient", self.friction_coefficient, N_("friction opposes motion")
        )
        _check_efficiency("efficiency", self.efficiency, what=N_("rack and pinion"))
        _check_incline("incline_deg", self.incline_deg)
        _nonnegative("pinion_inertia_kgm2", self.pinion_inertia_kgm2, N_("a moment of inertia"))
        _nonnegative("counterweight_kg", self.counterweight_kg, N_("a mass"))
        _nonnegative("friction_force_n", self.friction_force_n, N_("friction opposes motion"))


def rack_pinion_axis(rack: RackPinion, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A rack-and-pinion axis (first principles with r = d/2, module doc).

    J_L = J_P + (m + m_c)·(d/2)²,  T_G = (m·sin θ − m_c)·g·d/2,
    T_F = (μ·m·g·cos θ + F_F)·d/2,   η by power flow.

    200 kg on a horizontal rack, 80 mm pinion, μ = 0.05: T_F = 0.05·200·9.81·0.04 = 3.924 Nm,
    J_L = 0.002 + 200·0.04² = 0.322 kgm²:

    >>> axis = rack_pinion_axis(RackPinion(mass_kg=200, pinion_diameter_m=0.08,
    ...     friction_coefficient=0.05, efficiency=0.95, pinion_inertia_kgm2=0.002))
    >>> round(axis.friction_torque_nm, 4), round(axis.inertia_kgm2, 4), axis.gravity_torque_nm
    (3.924, 0.322, 0.0)
    """
    law = rack_pinion_law(rack, g=g)
    return _linear_axis(
        radius_m=half(rack.pinion_diameter_m),
        radius_field="pinion_diameter_m",
        rotating_inertia_kgm2=rack.pinion_inertia_kgm2,
        moving_mass_kg=law.moving_mass_kg,
        gravity_force_n=law.gravity_force_n,
        friction_force_n=law.friction_force_n,
        efficiency=rack.efficiency,
    )


def rack_pinion_law(rack: RackPinion, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> LinearLaw:
    """:func:`rack_pinion_axis` as a function of the pinion's diameter d: r = d/2, J_P,
    and the moved mass m + m_c and the forces, which do not depend on d."""
    gravity, friction = incline_forces(rack, g=g)
    inertia = rack.pinion_inertia_kgm2
    return LinearLaw(
        radius_m=half,
        rotating_inertia_kgm2=lambda diameters: np.full(diameters.shape, inertia),
        moving_mass_kg=rack.mass_kg + rack.counterweight_kg,
        gravity_force_n=gravity,
        friction_force_n=friction,
        efficiency=rack.efficiency,
    )
