"""A conveyor belt carrying a load, from first principles."""

from __future__ import annotations

from dataclasses import dataclass

from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import STANDARD_GRAVITY_M_PER_S2, _check
from actuator_selection.sizing.mechanisms.belt import _reflected_roller
from actuator_selection.sizing.mechanisms.linear import (
    _check_efficiency,
    _check_incline,
    _linear_axis,
    _nonnegative,
    _sin_cos,
)


@dataclass(frozen=True, slots=True, kw_only=True)
class Conveyor:
    """A belt conveyor: the load rides on a belt between a drive roller and a tail roller,
    the carrying strand sliding on a bed.

    Parameters
    ----------
    load_mass_kg
        m_L [kg], ≥ 0, of everything on the belt.
    belt_mass_kg
        m_B [kg], ≥ 0, of the whole belt (it all moves at v; its weight is balanced). Half
        of it, the carrying strand, lies on the bed with the load.
    roller_diameter_m
        D [m], > 0, of the drive roller.
    friction_coefficient
        μ [-], ≥ 0, between the carrying strand and its bed; normal force
        (m_L + m_B/2)·g·cos θ.
    efficiency
        η [-], 0 < η ≤ 1, applied by power flow.
    incline_deg
        θ [°], −90…90, of the conveyor (the load is lifted for θ > 0).
    drive_roller_inertia_kgm2
        J_D [kgm²], ≥ 0.
    tail_roller_inertia_kgm2
        J_T [kgm²], ≥ 0.
    tail_roller_diameter_m
        D_T [m], > 0; None: the drive roller's. J_T reaches the drive as J_T·(D/D_T)².
    friction_force_n
        Friction force [N], ≥ 0, independent of the weight (scrapers, bearing drag).
    """

    load_mass_kg: float
    belt_mass_kg: float
    roller_diameter_m: float
    friction_coefficient: float
    efficiency: float
    incline_deg: float = 0.0
    drive_roller_inertia_kgm2: float = 0.0
    tail_roller_inertia_kgm2: float = 0.0
    tail_roller_diameter_m: float | None = None
    friction_force_n: float = 0.0

    def __post_init__(self) -> None:
        _nonnegative("load_mass_kg", self.load_mass_kg, N_("a mass"))
        _nonnegative("belt_mass_kg", self.belt_mass_kg, N_("a mass"))
        _check("roller_diameter_m", self.roller_diameter_m, positive=True, rule=N_("a roller"))
        _nonnegative(
            "friction_coefficient", self.friction_coefficient, N_("friction opposes motion")
        )
        _check_efficiency("efficiency", self.efficiency, what=N_("conveyor"))
        _check_incline("incline_deg", self.incline_deg)
        _nonnegative(
            "drive_roller_inertia_kgm2", self.drive_roller_inertia_kgm2, N_("a moment of inertia")
        )
        _nonnegative(
            "tail_roller_inertia_kgm2", self.tail_roller_inertia_kgm2, N_("a moment of inertia")
        )
        if self.tail_roller_diameter_m is not None:
            _check(
                "tail_roller_diameter_m",
                self.tail_roller_diameter_m,
                positive=True,
                rule=N_("a roller"),
            )
        _nonnegative("friction_force_n", self.friction_force_n, N_("friction opposes motion"))


def conveyor_axis(conveyor: Conveyor, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A belt conveyor (first principles with r = D/2, module doc).

    J_L = J_D + J_T·(D/D_T)² + (m_L + m_B)·(D/2)²,
    T_G = m_L·g·sin θ·D/2,
    T_F = (μ·(m_L + m_B/2)·g·cos θ + F_F)·D/2,   η by power flow.

    30 kg on a horizontal 10 kg belt, 100 mm rollers of 0.004 kgm² each, μ = 0.2:
    T_F = 0.2·35·9.81·0.05 = 3.4335 Nm, J_L = 0.008 + 40·0.05² = 0.108 kgm²:

    >>> axis = conveyor_axis(Conveyor(load_mass_kg=30, belt_mass_kg=10, roller_diameter_m=0.1,
    ...     friction_coefficient=0.2, efficiency=0.9, drive_roller_inertia_kgm2=0.004,
    ...     tail_roller_inertia_kgm2=0.004))
    >>> round(axis.friction_torque_nm, 4), round(axis.inertia_kgm2, 4)
    (3.4335, 0.108)
    """
    sin_t, cos_t = _sin_cos(conveyor.incline_deg)
    tail = _reflected_roller(
        conveyor.tail_roller_inertia_kgm2,
        conveyor.roller_diameter_m,
        conveyor.tail_roller_diameter_m,
        "tail_roller_diameter_m",
    )
    on_bed_kg = conveyor.load_mass_kg + conveyor.belt_mass_kg / 2
    return _linear_axis(
        radius_m=conveyor.roller_diameter_m / 2,
        radius_field="roller_diameter_m",
        rotating_inertia_kgm2=conveyor.drive_roller_inertia_kgm2 + tail,
        moving_mass_kg=conveyor.load_mass_kg + conveyor.belt_mass_kg,
        gravity_force_n=conveyor.load_mass_kg * sin_t * g,
        friction_force_n=conveyor.friction_coefficient * on_bed_kg * g * cos_t
        + conveyor.friction_force_n,
        efficiency=conveyor.efficiency,
    )
