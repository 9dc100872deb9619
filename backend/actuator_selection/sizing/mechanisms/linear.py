"""What every linear axis shares: mm/s and N at the output, the checks of its inputs, the
reflected mass, force and weight on an incline (first principles, see the package).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol, overload

import numpy as np
import numpy.typing as npt

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_, Text
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import _check, _check_result, _square, squares
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM

FloatArray = npt.NDArray[np.float64]

MM_PER_M = 1000.0
"""Millimetres in a metre: linear axes take their load speed in mm/s."""

MAX_INCLINE_DEG = 90.0
"""|θ| bound [°]: vertical. Beyond it the axis is the same one with its direction reversed."""


@overload
def mm_to_m(length_mm: float) -> float: ...
@overload
def mm_to_m(length_mm: FloatArray) -> FloatArray: ...
def mm_to_m(length_mm: Any) -> Any:
    """A length given in millimetres [mm] in metres [m] (a float, or an array of many).

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


def half(diameter_m: Any) -> Any:
    """r = d/2 of a diameter [m] (a float, or an array of many)."""
    return diameter_m / 2


class InclinedMass(Protocol):
    """A mass m moved on an incline θ, with a counterweight m_c, friction μ and a further
    friction force F_F: what a screw's, a pinion's and a belt's axis share."""

    @property
    def mass_kg(self) -> float: ...
    @property
    def counterweight_kg(self) -> float: ...
    @property
    def friction_coefficient(self) -> float: ...
    @property
    def friction_force_n(self) -> float: ...
    @property
    def incline_deg(self) -> float: ...


def incline_forces(axis: InclinedMass, *, g: float) -> tuple[float, float]:
    """The weight's force (m·sin θ − m_c)·g and the friction force μ·m·g·cos θ + F_F [N]
    of ``axis``'s mass moved by a screw, a pinion or a belt (first principles, module
    doc)."""
    sin_t, cos_t = _sin_cos(axis.incline_deg)
    return (
        (axis.mass_kg * sin_t - axis.counterweight_kg) * g,
        axis.friction_coefficient * axis.mass_kg * g * cos_t + axis.friction_force_n,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class LinearLaw:
    """A linear axis (:func:`_linear_axis`) as a function of its free length L [m] (a
    screw's lead, a pinion's or a pulley's diameter): r and the rotating parts' J of L,
    as its mechanism computes them, on an array of many L; the rest does not depend on
    L."""

    radius_m: Callable[[FloatArray], FloatArray]
    rotating_inertia_kgm2: Callable[[FloatArray], FloatArray]
    moving_mass_kg: float
    gravity_force_n: float
    friction_force_n: float
    efficiency: float


def linear_axis_columns(
    law: LinearLaw, lengths_m: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """r and :func:`_linear_axis` at many lengths L at once (``law``): n per mm/s =
    1/(1000·r·2π/60), J_L = J_rot + m_moving·r², T_G = F_G·r and T_F = F_F·r as columns,
    the same operations in the same order (r² as Python's ``**``, the C library's pow,
    which numpy's x·x does not match in the last bit for ~0.08 % of values). Not
    checked: the caller sees to the results being finite and r² not vanishing, where
    :func:`_linear_axis` raises."""
    with np.errstate(all="ignore"):
        radius_m = law.radius_m(lengths_m)
        speed = 1.0 / (MM_PER_M * radius_m * RAD_PER_S_PER_RPM)
        inertia = law.rotating_inertia_kgm2(lengths_m) + law.moving_mass_kg * squares(radius_m)
        gravity = law.gravity_force_n * radius_m
        friction = law.friction_force_n * radius_m
    return radius_m, speed, inertia, gravity, friction
