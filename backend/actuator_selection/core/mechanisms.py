"""Mechanisms resolved to the actuator output (issue "Real axes").

Each mechanism here gives one :class:`~actuator_selection.core.axis.AxisLoad`: the load
inertia J_L, the friction torque T_F, the signed gravity torque T_G and the efficiency η
at the shaft that drives it, with the factors that turn its load speed (mm/s for a linear
axis, rpm for a rotary one) into output rpm and its process force (N or Nm) into output
torque. :func:`with_transmission` puts a ratio (a gearbox or a belt reduction) between the
actuator and any of them.

The chapter's two mechanisms keep their equations (:mod:`~actuator_selection.core.loads`,
Eq. 515.4 and 515.6). The others follow from first principles, written once for every
linear axis: a mass moving at v [m/s] while the driving shaft turns at ω [rad/s] with
v = r·ω (r [m/rad]: P/2π for a screw, D/2 for a pulley, pinion, roller or drum) has

    kinetic energy  ½·m·v² = ½·(m·r²)·ω²         →  J = m·r²     (reflected inertia)
    power           F·v = (F·r)·ω                →  T = F·r      (reflected force)

so a weight m·g on an incline θ gives T_G = m·g·sin θ·r, guide friction μ·m·g·cos θ gives
T_F = μ·m·g·cos θ·r, and a process force of 1 N gives r Nm. The efficiency η is not
folded into these torques: :class:`~actuator_selection.core.axis.AxisLoad` applies it by
the direction of power flow, T = T_load/η when the actuator drives and T = T_load·η when
the load drives back, to friction, gravity, process and inertia torque alike (the
convention of the sizing tools engineers know, see :mod:`~actuator_selection.core.axis`).
Only the chapter's ball screw keeps Eq. 515.4, which divides T_F by η and so carries
η = 1 on.

Linear axes speak mm/s and N: ``speed_rpm_per_unit`` = 1/(1000·r·2π/60) output rpm per
mm/s, ``torque_nm_per_force_unit`` = r Nm per N. A counterweight hangs on a rope over a
pulley of its own (pulley and rope neglected) and moves as far as the load: it adds its
mass to the inertia and takes m_c·g·r from the gravity torque whatever the incline.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from actuator_selection.core.axis import AxisLoad
from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.loads import (
    STANDARD_GRAVITY_M_PER_S2,
    BallScrew,
    RotaryTable,
    _check,
    _check_result,
    _square,
    ball_screw_load,
    rotary_table_load,
)
from actuator_selection.core.messages import N_, Text
from actuator_selection.core.units import RAD_PER_S_PER_RPM

MM_PER_M = 1000.0
"""Millimetres in a metre: linear axes take their load speed in mm/s."""

MAX_INCLINE_DEG = 90.0
"""|θ| bound [°]: vertical. Beyond it the axis is the same one with its direction reversed."""


def mm_to_m(length_mm: float) -> float:
    """A length given in millimetres [mm] in metres [m].

    >>> mm_to_m(10.0)
    0.01
    """
    return length_mm / MM_PER_M


def rpm_per_mm_per_s(radius_m: float) -> float:
    """Shaft speed [rpm] per mm/s of a load moving at v = r·ω.

    n = v/r · 60/2π with v in m/s: 1/(1000·r·2π/60) rpm per mm/s.

    A 50 mm pulley (r = 25 mm) turns 60/(2π·25) rpm per mm/s:

    >>> round(rpm_per_mm_per_s(0.025), 6), round(60 / (2 * math.pi * 25), 6)
    (0.381972, 0.381972)
    """
    return 1.0 / (MM_PER_M * radius_m * RAD_PER_S_PER_RPM)


def _speed_factor(radius_m: float, field: str) -> float:
    """:func:`rpm_per_mm_per_s`, or an error naming ``field`` where r is too small for it."""
    denominator = MM_PER_M * radius_m * RAD_PER_S_PER_RPM
    if denominator == 0 or radius_m * radius_m == 0:
        raise InvalidInputError(field, code="radius_vanishes")
    speed = 1.0 / denominator
    _check_result(field, speed, what=N_("n per mm/s = 1/(1000·r·2π/60)"))
    return speed


def _check_efficiency(field: str, value: float, *, what: Text) -> None:
    if not math.isfinite(value):
        raise InvalidInputError(field, code="not_finite", params={"value": value})
    if value <= 0:
        raise InvalidInputError(field, code="efficiency_positive", params={"what": what})
    if value > 1:
        raise InvalidInputError(field, code="efficiency_above_one", params={"what": what})


def _check_incline(field: str, value: float) -> None:
    if not math.isfinite(value):
        raise InvalidInputError(field, code="not_finite", params={"value": value})
    if abs(value) > MAX_INCLINE_DEG:
        raise InvalidInputError(field, code="incline_range")


def _sin_cos(incline_deg: float) -> tuple[float, float]:
    """sin θ and cos θ, exact at 0° and ±90° (a vertical axis has no guide friction at all,
    not μ·m·g·6·10⁻¹⁷)."""
    if incline_deg == 0:
        return 0.0, 1.0
    if abs(incline_deg) == MAX_INCLINE_DEG:
        return math.copysign(1.0, incline_deg), 0.0
    theta = math.radians(incline_deg)
    return math.sin(theta), math.cos(theta)


def _nonnegative(field: str, value: float, rule: Text) -> None:
    _check(field, value, positive=False, rule=rule)


def _linear_axis(
    *,
    radius_m: float,
    radius_field: str,
    rotating_inertia_kgm2: float,
    moving_mass_kg: float,
    gravity_force_n: float,
    friction_force_n: float,
    efficiency: float,
) -> AxisLoad:
    """The :class:`AxisLoad` of a linear axis with v = r·ω (first principles, module doc).

    J_L = J_rot + m_moving·r²,  T_G = F_G·r,  T_F = F_F·r.
    """
    speed = _speed_factor(radius_m, radius_field)
    inertia = rotating_inertia_kgm2 + moving_mass_kg * _square(radius_m)
    gravity = gravity_force_n * radius_m
    friction = friction_force_n * radius_m
    _check_result(radius_field, inertia, what=N_("J_L = J + m·r²"))
    _check_result(radius_field, gravity, what=N_("T_G = F_G·r"))
    _check_result(radius_field, friction, what=N_("T_F = F_F·r"))
    return AxisLoad(
        inertia_kgm2=inertia,
        friction_torque_nm=friction,
        gravity_torque_nm=gravity,
        efficiency=efficiency,
        speed_rpm_per_unit=speed,
        torque_nm_per_force_unit=radius_m,
        speed_unit="mm/s",
        force_unit="N",
    )


# --- the chapter's mechanisms ------------------------------------------------------------


def chapter_ball_screw_axis(screw: BallScrew, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> AxisLoad:
    """A horizontal ball-screw axis exactly as the chapter sizes it (Eq. 515.4).

    J_L = J_S + m·(P/2π)²,  T_F = μ·m·P·g/(2π·η),  η = 1 on (Eq. 515.4 holds the losses),
    T_G = 0; load speed in mm/s (1 mm/s is 60/(1000·P) rpm), process force in N (P/2π Nm).
    T_F and J_L are those of :func:`~actuator_selection.core.loads.ball_screw_load`.

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
    sin_t, cos_t = _sin_cos(screw.incline_deg)
    return _linear_axis(
        radius_m=screw.lead_m / (2 * math.pi),
        radius_field="lead_m",
        rotating_inertia_kgm2=screw.screw_inertia_kgm2,
        moving_mass_kg=screw.mass_kg + screw.counterweight_kg,
        gravity_force_n=(screw.mass_kg * sin_t - screw.counterweight_kg) * g,
        friction_force_n=screw.friction_coefficient * screw.mass_kg * g * cos_t
        + screw.friction_force_n,
        efficiency=screw.efficiency,
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
    sin_t, cos_t = _sin_cos(belt.incline_deg)
    idler = _reflected_roller(
        belt.idler_inertia_kgm2, belt.pulley_diameter_m, belt.idler_diameter_m, "idler_diameter_m"
    )
    return _linear_axis(
        radius_m=belt.pulley_diameter_m / 2,
        radius_field="pulley_diameter_m",
        rotating_inertia_kgm2=belt.pulley_inertia_kgm2 + idler,
        moving_mass_kg=belt.mass_kg + belt.belt_mass_kg + belt.counterweight_kg,
        gravity_force_n=(belt.mass_kg * sin_t - belt.counterweight_kg) * g,
        friction_force_n=belt.friction_coefficient * belt.mass_kg * g * cos_t
        + belt.friction_force_n,
        efficiency=belt.efficiency,
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
    sin_t, cos_t = _sin_cos(rack.incline_deg)
    return _linear_axis(
        radius_m=rack.pinion_diameter_m / 2,
        radius_field="pinion_diameter_m",
        rotating_inertia_kgm2=rack.pinion_inertia_kgm2,
        moving_mass_kg=rack.mass_kg + rack.counterweight_kg,
        gravity_force_n=(rack.mass_kg * sin_t - rack.counterweight_kg) * g,
        friction_force_n=rack.friction_coefficient * rack.mass_kg * g * cos_t
        + rack.friction_force_n,
        efficiency=rack.efficiency,
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


# --- a ratio between the actuator and the mechanism ---------------------------------------


@dataclass(frozen=True, slots=True, kw_only=True)
class Transmission:
    """A gearbox or belt reduction between the actuator output and a mechanism.

    Parameters
    ----------
    ratio
        i [-], > 0: actuator output speed over mechanism shaft speed (i > 1 reduces).
    inertia_kgm2
        J_tr [kgm²], ≥ 0, of the transmission referred to the actuator side.
    efficiency
        η_tr [-], 0 < η ≤ 1.
    """

    ratio: float
    inertia_kgm2: float = 0.0
    efficiency: float = 1.0

    def __post_init__(self) -> None:
        _check("ratio", self.ratio, positive=True, rule=N_("output speed over mechanism speed"))
        _nonnegative("inertia_kgm2", self.inertia_kgm2, N_("a moment of inertia"))
        _check_efficiency("efficiency", self.efficiency, what=N_("transmission"))


def with_transmission(load: AxisLoad, transmission: Transmission) -> AxisLoad:
    """``load`` seen through a ratio i (first principles: ω_out = i·ω_mech, P = T·ω).

    J_L = J_tr + J_mech/i²,  T_F = T_F,mech/i,  T_G = T_G,mech/i,
    speed factor × i, force factor / i,  η = η_tr·η_mech.

    One η by power flow for the whole chain is the vendor convention of
    :mod:`~actuator_selection.core.axis`; it applies η_tr to J_tr·α as well (on the safe
    side by J_tr·α·(1/η_tr − 1) while driving).

    The vertical belt axis of :func:`belt_axis` behind a 5:1 belt reduction (0.0001 kgm²,
    η 0.95): J_L = 0.0001 + 0.003125/25 = 0.000225 kgm², T_G = 1.22625/5 = 0.24525 Nm:

    >>> belt = belt_axis(BeltDrive(mass_kg=5, pulley_diameter_m=0.05,
    ...                            friction_coefficient=0.1, efficiency=0.9, incline_deg=90))
    >>> axis = with_transmission(belt, Transmission(ratio=5, inertia_kgm2=0.0001,
    ...                                             efficiency=0.95))
    >>> round(axis.inertia_kgm2, 7), round(axis.gravity_torque_nm, 5), round(axis.efficiency, 3)
    (0.000225, 0.24525, 0.855)
    >>> round(axis.speed_rpm_per_unit, 6)  # 5·60/(2π·25)
    1.909859
    """
    i = transmission.ratio
    i_squared = _square(i)
    if i_squared == 0:
        raise InvalidInputError("ratio", code="ratio_too_small")
    reflected = load.inertia_kgm2 / i_squared
    inertia = transmission.inertia_kgm2 + reflected
    friction = load.friction_torque_nm / i
    gravity = load.gravity_torque_nm / i
    speed = load.speed_rpm_per_unit * i
    force = load.torque_nm_per_force_unit / i
    efficiency = transmission.efficiency * load.efficiency
    for value, what in (
        (inertia, "J_L = J_tr + J/i²"),
        (friction, "T_F/i"),
        (gravity, "T_G/i"),
        (speed, N_("the speed factor × i")),
        (force, N_("the force factor / i")),
    ):
        _check_result("ratio", value, what=what)
    for before, after in (
        (load.inertia_kgm2, reflected),
        (load.friction_torque_nm, friction),
        (load.gravity_torque_nm, gravity),
        (load.torque_nm_per_force_unit, force),
    ):
        if before != 0 and after == 0:
            raise InvalidInputError("ratio", code="ratio_too_large")
    if efficiency == 0:
        raise InvalidInputError("efficiency", code="efficiency_product_zero")
    return AxisLoad(
        inertia_kgm2=inertia,
        friction_torque_nm=friction,
        gravity_torque_nm=gravity,
        efficiency=efficiency,
        speed_rpm_per_unit=speed,
        torque_nm_per_force_unit=force,
        speed_unit=load.speed_unit,
        force_unit=load.force_unit,
    )
