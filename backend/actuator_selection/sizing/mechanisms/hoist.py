"""A hoist: a drum winding a rope that lifts a load, from first principles."""

from __future__ import annotations

from dataclasses import dataclass

from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import STANDARD_GRAVITY_M_PER_S2, _check
from actuator_selection.sizing.mechanisms.linear import (
    _check_efficiency,
    _linear_axis,
    _nonnegative,
)


@dataclass(frozen=True, slots=True, kw_only=True)
class Hoist:
    """A lift: a load on a rope wound on a drum, with an optional counterweight.

    Parameters
    ----------
    load_mass_kg
        m [kg], ≥ 0, of the cage or hook and its payload (rope neglected).
    drum_diameter_m
        D [m], > 0, at the rope's centre line; r = D/2.
    efficiency
        η [-], 0 < η ≤ 1, applied by power flow.
    counterweight_kg
        m_c [kg], ≥ 0, moving as far as the load, the other way.
    drum_inertia_kgm2
        J_D [kgm²], ≥ 0.
    friction_force_n
        Friction force [N], ≥ 0, of the load's guides.
    """

    load_mass_kg: float
    drum_diameter_m: float
    efficiency: float
    counterweight_kg: float = 0.0
    drum_inertia_kgm2: float = 0.0
    friction_force_n: float = 0.0

    def __post_init__(self) -> None:
        _nonnegative("load_mass_kg", self.load_mass_kg, N_("a mass"))
        _check("drum_diameter_m", self.drum_diameter_m, positive=True, rule=N_("a drum"))
        _check_efficiency("efficiency", self.efficiency, what=N_("hoist"))
        _nonnegative("counterweight_kg", self.counterweight_kg, N_("a mass"))
        _nonnegative("drum_inertia_kgm2", self.drum_inertia_kgm2, N_("a moment of inertia"))
        _nonnegative("friction_force_n", self.friction_force_n, N_("friction opposes motion"))


def hoist_axis(hoist: Hoist, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A hoist (first principles with r = D/2, module doc); positive motion lifts the load.

    J_L = J_D + (m + m_c)·r²,  T_G = (m − m_c)·g·r,  T_F = F_F·r,   η by power flow.

    100 kg against a 60 kg counterweight on a 200 mm drum of 0.05 kgm²:
    T_G = 40·9.81·0.1 = 39.24 Nm, J_L = 0.05 + 160·0.1² = 1.65 kgm²:

    >>> axis = hoist_axis(Hoist(load_mass_kg=100, drum_diameter_m=0.2, efficiency=0.9,
    ...                         counterweight_kg=60, drum_inertia_kgm2=0.05))
    >>> round(axis.gravity_torque_nm, 4), round(axis.inertia_kgm2, 4)
    (39.24, 1.65)
    """
    return _linear_axis(
        radius_m=hoist.drum_diameter_m / 2,
        radius_field="drum_diameter_m",
        rotating_inertia_kgm2=hoist.drum_inertia_kgm2,
        moving_mass_kg=hoist.load_mass_kg + hoist.counterweight_kg,
        gravity_force_n=(hoist.load_mass_kg - hoist.counterweight_kg) * g,
        friction_force_n=hoist.friction_force_n,
        efficiency=hoist.efficiency,
    )
