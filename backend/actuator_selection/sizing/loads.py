"""Load torque T_L and load inertia J_L of common mechanisms (Eq. 515.4, 515.6).

Both mechanisms are driven directly by the actuator output, so T_L and J_L are
already referred to the output shaft.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_, Text
from actuator_selection.sizing.cycle import Load

STANDARD_GRAVITY_M_PER_S2 = 9.81
"""g as the chapter writes it under Eq. 515.6 (g = 9,81 m/s²)."""


def _check(field: str, value: float, *, positive: bool, rule: Text) -> None:
    if not math.isfinite(value):
        raise InvalidInputError(field, code="not_finite", params={"value": value})
    if (value <= 0) if positive else (value < 0):
        code = "must_be_positive" if positive else "must_be_nonnegative"
        raise InvalidInputError(field, code=code, params={"rule": rule})


def _square(x: float) -> float:
    """``x**2`` as before (the same rounding), +∞ where Python's float power overflows."""
    try:
        return x**2
    except OverflowError:
        return math.inf


def squares(values: npt.NDArray[np.float64]) -> npt.NDArray[np.float64]:
    """x² of each value as :func:`_square` computes it (Python's ``**``, +∞ where it
    overflows), for the load cases built as columns (the ratio study): numpy's x·x
    differs from it in the last bit for about 0.08 % of values."""
    return np.array([_square(x) for x in values.tolist()], dtype=np.float64)


def _check_result(field: str, value: float, *, what: str) -> None:
    """A result that overflowed names the input that drove it there (422, never ∞ or a 500)."""
    if not math.isfinite(value):
        raise InvalidInputError(field, code="mechanism_overflow", params={"what": what})


@dataclass(frozen=True, slots=True, kw_only=True)
class BallScrew:
    """Linear horizontal motion by a ball screw (Fig. 515.2).

    Parameters
    ----------
    mass_kg
        Moved mass m [kg], ≥ 0.
    lead_m
        Screw lead P [m per revolution], > 0.
    friction_coefficient
        Coefficient of friction μ of the guide [-], ≥ 0.
    efficiency
        Screw efficiency η [-], 0 < η ≤ 1.
    screw_inertia_kgm2
        Moment of inertia of the screw J_S [kgm²], ≥ 0.
    """

    mass_kg: float
    lead_m: float
    friction_coefficient: float
    efficiency: float
    screw_inertia_kgm2: float = 0.0

    def __post_init__(self) -> None:
        _check("mass_kg", self.mass_kg, positive=False, rule=N_("a mass"))
        _check("lead_m", self.lead_m, positive=True, rule=N_("the screw advances per revolution"))
        _check(
            "friction_coefficient",
            self.friction_coefficient,
            positive=False,
            rule=N_("friction opposes motion"),
        )
        _check("efficiency", self.efficiency, positive=True, rule=N_("η divides Eq. 515.4"))
        if self.efficiency > 1:
            raise InvalidInputError(
                "efficiency", code="efficiency_above_one", params={"what": N_("screw")}
            )
        _check(
            "screw_inertia_kgm2",
            self.screw_inertia_kgm2,
            positive=False,
            rule=N_("a moment of inertia"),
        )


@dataclass(frozen=True, slots=True, kw_only=True)
class RotaryTable:
    """A rotating disc, e.g. an indexing table (Fig. 515.3 and 515.5).

    Parameters
    ----------
    mass_kg
        Mass of the table and its load m [kg], ≥ 0.
    diameter_m
        Diameter D of the (solid, uniform) disc [m], > 0.
    friction_coefficient
        Coefficient of friction μ of the bearing [-], ≥ 0.
    friction_radius_m
        Radius r at which the friction force acts [m], ≥ 0.
    """

    mass_kg: float
    diameter_m: float
    friction_coefficient: float
    friction_radius_m: float

    def __post_init__(self) -> None:
        _check("mass_kg", self.mass_kg, positive=False, rule=N_("a mass"))
        _check("diameter_m", self.diameter_m, positive=True, rule=N_("a disc has a size"))
        _check(
            "friction_coefficient",
            self.friction_coefficient,
            positive=False,
            rule=N_("friction opposes motion"),
        )
        _check("friction_radius_m", self.friction_radius_m, positive=False, rule=N_("a radius"))


def ball_screw_load(screw: BallScrew, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> Load:
    """T_L and J_L of a horizontal ball-screw axis (Eq. 515.4).

    J_L = J_S + m·(P/2π)²,   T_L = μ·m·P·g / (2π·η)

    A 100 kg slide on a 10 mm lead screw (μ = 0.1, η = 0.9, J_S = 0.001 kgm²):

    >>> load = ball_screw_load(BallScrew(mass_kg=100, lead_m=0.01, friction_coefficient=0.1,
    ...                                  efficiency=0.9, screw_inertia_kgm2=0.001))
    >>> round(load.inertia_kgm2, 7), round(load.torque_nm, 5)
    (0.0012533, 0.17348)
    """
    radius_per_rad = screw.lead_m / (2 * math.pi)
    torque = screw.friction_coefficient * screw.mass_kg * g * radius_per_rad / screw.efficiency
    inertia = screw.screw_inertia_kgm2 + screw.mass_kg * _square(radius_per_rad)
    # Each input is finite, but a tiny η divides the friction torque past the largest float.
    _check_result("efficiency", torque, what=N_("T_L = μ·m·P·g/(2π·η) (Eq. 515.4)"))
    _check_result("lead_m", inertia, what=N_("J_L = J_S + m·(P/2π)² (Eq. 515.4)"))
    return Load(torque_nm=torque, inertia_kgm2=inertia)


def rotary_table_load(table: RotaryTable, *, g: float = STANDARD_GRAVITY_M_PER_S2) -> Load:
    """T_L and J_L of a rotary table, a uniform disc about its axis (Eq. 515.6).

    J_L = m·D²/8,   T_L = μ·m·g·r

    >>> load = rotary_table_load(RotaryTable(mass_kg=50, diameter_m=0.4,
    ...                                      friction_coefficient=0.02, friction_radius_m=0.15))
    >>> round(load.inertia_kgm2, 6), round(load.torque_nm, 5)
    (1.0, 1.4715)
    """
    torque = table.friction_coefficient * table.mass_kg * g * table.friction_radius_m
    inertia = table.mass_kg * _square(table.diameter_m) / 8
    _check_result("friction_radius_m", torque, what=N_("T_L = μ·m·g·r (Eq. 515.6)"))
    _check_result("diameter_m", inertia, what=N_("J_L = m·D²/8 (Eq. 515.6)"))
    return Load(torque_nm=torque, inertia_kgm2=inertia)
