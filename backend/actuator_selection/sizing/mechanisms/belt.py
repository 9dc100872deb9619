"""A toothed belt drive (linear), from first principles."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import (
    STANDARD_GRAVITY_M_PER_S2,
    _check,
    _check_result,
    _square,
    squares,
)
from actuator_selection.sizing.mechanisms.linear import (
    FloatArray,
    LinearLaw,
    _check_efficiency,
    _check_incline,
    _linear_axis,
    _nonnegative,
    half,
    incline_forces,
)


@dataclass(frozen=True, slots=True, kw_only=True)
class BeltDrive:
    """A linear axis on a timing belt: the carriage clamped to the belt, a drive pulley on
    the actuator side and an idler at the far end (a pick-and-place axis when vertical).

    Parameters
    ----------
    mass_kg
        Moved mass m [kg], ≥ 0 (carriage and payload).
    pulley_diameter_m
        Pitch diameter D of the drive pulley [m], > 0; r = D/2.
    friction_coefficient
        μ [-] of the carriage guide, ≥ 0; its normal force is m·g·cos θ.
    efficiency
        η [-] of the belt drive, 0 < η ≤ 1, applied by power flow.
    incline_deg
        θ [°], −90…90; 90 is a vertical axis with positive motion lifting.
    belt_mass_kg
        m_B [kg], ≥ 0, the whole belt: all of it moves at v. Its weight is balanced (one
        strand goes up as the other goes down), so it adds inertia only.
    pulley_inertia_kgm2
        J_D [kgm²], ≥ 0, of the drive pulley.
    idler_inertia_kgm2
        J_I [kgm²], ≥ 0, of the idler (idlers of one diameter: their sum).
    idler_diameter_m
        D_I [m], > 0, of the idler; None: the drive pulley's. The idler turns at
        v/(D_I/2), so J_I reaches the drive shaft as J_I·(D/D_I)².
    counterweight_kg
        m_c [kg], ≥ 0 (module doc).
    friction_force_n
        Friction force [N], ≥ 0, independent of the weight.
    """

    mass_kg: float
    pulley_diameter_m: float
    friction_coefficient: float
    efficiency: float
    incline_deg: float = 0.0
    belt_mass_kg: float = 0.0
    pulley_inertia_kgm2: float = 0.0
    idler_inertia_kgm2: float = 0.0
    idler_diameter_m: float | None = None
    counterweight_kg: float = 0.0
    friction_force_n: float = 0.0

    def __post_init__(self) -> None:
        _nonnegative("mass_kg", self.mass_kg, N_("a mass"))
        _check("pulley_diameter_m", self.pulley_diameter_m, positive=True, rule=N_("a pulley"))
        _nonnegative(
            "friction_coefficient", self.friction_coefficient, N_("friction opposes motion")
        )
        _check_efficiency("efficiency", self.efficiency, what=N_("belt drive"))
        _check_incline("incline_deg", self.incline_deg)
        _nonnegative("belt_mass_kg", self.belt_mass_kg, N_("a mass"))
        _nonnegative("pulley_inertia_kgm2", self.pulley_inertia_kgm2, N_("a moment of inertia"))
        _nonnegative("idler_inertia_kgm2", self.idler_inertia_kgm2, N_("a moment of inertia"))
        if self.idler_diameter_m is not None:
            _check("idler_diameter_m", self.idler_diameter_m, positive=True, rule=N_("a pulley"))
        _nonnegative("counterweight_kg", self.counterweight_kg, N_("a mass"))
        _nonnegative("friction_force_n", self.friction_force_n, N_("friction opposes motion"))


def _reflected_roller(
    inertia_kgm2: float, diameter_m: float, roller_diameter_m: float | None, field: str
) -> float:
    """J of a roller of diameter D_R turning with the belt, at the drive shaft (D):
    J·(D/D_R)², from ½·J·(v/r_R)² = ½·J'·(v/r)²."""
    if roller_diameter_m is None:
        return inertia_kgm2
    reflected = inertia_kgm2 * _square(diameter_m / roller_diameter_m)
    _check_result(field, reflected, what=N_("J·(D/D_R)²"))
    return reflected


def belt_axis(belt: BeltDrive, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A timing-belt linear axis (first principles with r = D/2, module doc).

    J_L = J_D + J_I·(D/D_I)² + (m + m_B + m_c)·(D/2)²,
    T_G = (m·sin θ − m_c)·g·D/2,
    T_F = (μ·m·g·cos θ + F_F)·D/2,   η of the belt by power flow.

    A vertical pick-and-place axis, 5 kg on a 50 mm pulley: T_G = 5·9.81·0.025 = 1.22625
    Nm, J_L = 5·0.025² = 0.003125 kgm²; 60/(2π·25) = 0.381972 rpm per mm/s:

    >>> axis = belt_axis(BeltDrive(mass_kg=5, pulley_diameter_m=0.05,
    ...                            friction_coefficient=0.1, efficiency=0.9, incline_deg=90))
    >>> round(axis.gravity_torque_nm, 5), round(axis.inertia_kgm2, 6), axis.friction_torque_nm
    (1.22625, 0.003125, 0.0)
    >>> round(axis.speed_rpm_per_unit, 6), axis.torque_nm_per_force_unit, axis.speed_unit
    (0.381972, 0.025, 'mm/s')
    """
    idler = _reflected_roller(
        belt.idler_inertia_kgm2, belt.pulley_diameter_m, belt.idler_diameter_m, "idler_diameter_m"
    )
    law = belt_law(belt, g=g)
    return _linear_axis(
        radius_m=half(belt.pulley_diameter_m),
        radius_field="pulley_diameter_m",
        rotating_inertia_kgm2=belt.pulley_inertia_kgm2 + idler,
        moving_mass_kg=law.moving_mass_kg,
        gravity_force_n=law.gravity_force_n,
        friction_force_n=law.friction_force_n,
        efficiency=belt.efficiency,
    )


def belt_law(belt: BeltDrive, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> LinearLaw:
    """:func:`belt_axis` as a function of the drive pulley's diameter D: r = D/2,
    J_D + J_I·(D/D_I)² (J_D + J_I without D_I), and the moved mass m + m_B + m_c and the
    forces, which do not depend on D."""
    gravity, friction = incline_forces(belt, g=g)
    pulley, idler, idler_d = (
        belt.pulley_inertia_kgm2,
        belt.idler_inertia_kgm2,
        belt.idler_diameter_m,
    )

    def rotating(diameters: FloatArray) -> FloatArray:
        if idler_d is None:
            return np.full(diameters.shape, pulley + idler)
        return pulley + idler * squares(diameters / idler_d)  # as _reflected_roller

    return LinearLaw(
        radius_m=half,
        rotating_inertia_kgm2=rotating,
        moving_mass_kg=belt.mass_kg + belt.belt_mass_kg + belt.counterweight_kg,
        gravity_force_n=gravity,
        friction_force_n=friction,
        efficiency=belt.efficiency,
    )
