"""The actuator's output bearing (cross roller bearing) under an external load.

Harmonic Drive's actuator manuals check the output bearing in three steps; the
formulas are the same in the Harmonic Drive AG CHA manual (Engineering Data AC Servo
Actuators CHA, 1018854, §4.3 "output bearing": maximum tilting moment, dynamic
equivalent load with Table 70.4 of 12/2015 / 75.4 of 8/2018, static load safety
factor) and in the Harmonic Drive LLC FHA-C manual, chapter 2 "Guidelines for sizing"
(formulas (1), (5)–(7), (9), (10); public copy
easymanua.ls/harmonic-drive/fha-series/manual?p=25 and p=26):

1. maximum tilting moment M = F_r·(L_r + R) + F_a·L_a (formula (1)), at most the
   allowable moment (FHA-C "permissible moment capacity", CHA M_dyn);
2. static safety factor f_s = C_0/P_0 with P_0 = X_0·(F_r + 2M/d_p) + Y_0·F_a,
   X_0 = 1, Y_0 = 0.44 (formula (9)), at least 1.5 in normal operation, 2 with shock
   or vibration, 3 for precise positioning (formula (10));
3. life L_10 = 10⁶/(60·n_av)·(C/(f_w·P_c))^B [h] (formula (7)), P_c = X·(F_r + 2M/d_p) +
   Y·F_a with X, Y = 1, 0.45 where F_a/(F_r + 2M/d_p) ≤ 1.5, else 0.67, 0.67 (formula (5),
   CHA Table 70.4). The life exponent B is the bearing type's
   (:class:`~actuator_selection.catalogue.parts.BearingType`, ISO 281 and the CHA manual
   1018854 12/2015, p. 69, Table 69.3): 10/3 for a cross roller bearing, 3 for the
   four-point contact ball bearing of the CHA-14A, -17A and -20A (CHA manual 1018854
   8/2018 V03, output bearing Table 55.1, type column "F").

**Oscillating motion** (FHA-C formula (8), CSF manual §2-7 "life under oscillating
movement"): L_oc = 10⁶/(60·n_1)·(90/θ)·(C/(f_w·P_c))^(10/3) with n_1 reciprocating
oscillations per minute and θ half the oscillating angle [°]. One reciprocation of
amplitude 2θ turns the bearing through 4θ degrees = θ/90 revolutions, so n_1·θ/90 is the
bearing's travel in revolutions per minute: the cycle's mean |speed| n_av (Eq. 514.3 sums
|n|). L_10 at n_av is therefore formula (8) for a cycle that moves to and fro, and the
same check covers rotation and oscillation (:func:`oscillating_life_h`; a test computes
both for a reciprocating cycle of segments).

The forces are taken as acting throughout the cycle, so the manual's averages F_rav,
F_aav (formulas (2), (3)) are the forces themselves. The functions take the ``xp``
operations of :mod:`actuator_selection.sizing.checks` so that the flowchart's rules run
them unchanged on floats and on numpy arrays.

A load of 1000 N radial at 50 mm and 500 N axial at 20 mm on an FHA-14C (FHA-C mini
manual Table 1: d_p = 54 mm, R = 14 mm, C = 7400 N, C_0 = 12800 N):

>>> from actuator_selection.sizing.checks import FLOAT_OPS as xp
>>> m = tilting_moment_nm(radial_force_n=1000, axial_force_n=500,
...                       radial_lever_m=0.05, axial_lever_m=0.02, offset_m=0.014)
>>> round(m, 6)
74.0
>>> p0 = static_equivalent_load_n(radial_force_n=1000, axial_force_n=500, moment_nm=m,
...                               pitch_diameter_m=0.054)
>>> round(p0, 1), round(12800 / p0, 3)
(3960.7, 3.232)
>>> round(dynamic_equivalent_load_n(radial_force_n=1000, axial_force_n=500, moment_nm=m,
...                                 pitch_diameter_m=0.054, xp=xp), 1)
3965.7
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from actuator_selection.catalogue.parts import BearingType
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM

STATIC_RADIAL_FACTOR = 1.0
"""X_0 of the static equivalent load (FHA-C manual formula (9); HD AG: x_0 = 1)."""
STATIC_AXIAL_FACTOR = 0.44
"""Y_0 of the static equivalent load (FHA-C manual formula (9); HD AG: y_0 = 0.44)."""
AXIAL_RATIO_LIMIT = 1.5
"""F_a/(F_r + 2M/d_p) up to which X = 1, Y = 0.45 (FHA-C formula (5); CHA Table 70.4)."""
RADIAL_FACTOR_LOW_AXIAL, AXIAL_FACTOR_LOW_AXIAL = 1.0, 0.45
"""X, Y where the axial share is at most :data:`AXIAL_RATIO_LIMIT`."""
RADIAL_FACTOR_HIGH_AXIAL, AXIAL_FACTOR_HIGH_AXIAL = 0.67, 0.67
"""X, Y where the axial share exceeds :data:`AXIAL_RATIO_LIMIT`."""
LIFE_EXPONENT = 10.0 / 3.0
"""Life exponent B of a cross roller bearing, a roller bearing (ISO 281: p = 10/3 for
roller bearings; FHA-C formula (7); CHA manual 1018854 12/2015, Table 69.3: B = 10/3)."""
LIFE_EXPONENT_INVERSE = 0.3
"""1/B, for the dynamic load rating a required life needs (3/10 exactly as a float)."""
BALL_LIFE_EXPONENT = 3.0
"""Life exponent B of a ball bearing, the CHA's four-point contact bearing (ISO 281: p = 3
for ball bearings; CHA manual 1018854 12/2015, Table 69.3: B = 3)."""
BALL_LIFE_EXPONENT_INVERSE = 1.0 / 3.0
"""1/B of a ball bearing."""


def life_exponent(bearing_type: str | None) -> float:
    """B of the life formula for ``bearing_type``; NaN where the type is not published.

    >>> life_exponent("four_point_contact_ball"), round(life_exponent("cross_roller"), 4)
    (3.0, 3.3333)
    """
    if bearing_type == BearingType.FOUR_POINT_CONTACT_BALL:
        return BALL_LIFE_EXPONENT
    if bearing_type == BearingType.CROSS_ROLLER:
        return LIFE_EXPONENT
    return math.nan


FRETTING_SWING_DEG = 5.0
"""The swing below which the CHA manual warns of fretting of the output bearing under
oscillating motion (Harmonic Drive AG, Engineering Data AC Servo Actuators CHA, 1018854
12/2015, p. 69, note on oscillating motion): the rolling elements then move back and forth
over the same short track, the lubricant is not renewed and the races wear (fretting
corrosion, false brinelling)."""
DEG_PER_RPM_S = 6.0
"""One rpm for one second turns 360°/60 = 6°."""


def swing_deg(pieces: Any, where: Any) -> Any:
    """The cycle's swing [°]: the range of the output's angle over one cycle (its largest
    less its least, from the start of the cycle), from its pieces' (duration, start speed,
    end speed, start and end acceleration) in order, as floats of one cycle or arrays of
    many; ``where`` is ``numpy.where`` for arrays. For a cycle that moves to and fro it is
    the stroke, for one that moves on in one direction the move; either way below
    :data:`FRETTING_SWING_DEG` the bearing's rolling elements only rock on a short track.
    A piece's angle is its ∫n dt as Eq. 514.3 sums it (with the jerk ramp's term); the
    extremes are taken at the pieces' ends, where a move reverses or stops.

    >>> swing_deg([(0.1, 0.0, 10.0, 1.0, 1.0), (0.1, 10.0, 0.0, -1.0, -1.0),
    ...            (0.1, 0.0, -10.0, -1.0, -1.0), (0.1, -10.0, 0.0, 1.0, 1.0)],
    ...           lambda c, a, b: a if c else b)
    6.0
    """
    angle = low = high = 0.0
    for t, n0, n1, a0, a1 in pieces:
        ramp = (a0 - a1) * (t * t) / 12.0 / RAD_PER_S_PER_RPM
        distance = where(a0 == a1, (n0 + n1) / 2 * t, (n0 + n1) / 2 * t + ramp)
        angle = angle + distance * DEG_PER_RPM_S
        low = where(angle < low, angle, low)
        high = where(angle > high, angle, high)
    return high - low


REVOLUTIONS_PER_RATING = 1e6
"""The basic dynamic load rating C is for 10⁶ revolutions (L_10)."""
NORMAL_LOAD_FACTOR = 1.5
"""f_w for "normal operation": 1.2 to 1.5 (FHA-C formula (7); CHA "operating factor"),
the upper end, the safe side. Smooth operation 1 to 1.2; shock or vibration 1.5 to 3."""
NORMAL_STATIC_SAFETY = 1.5
"""The least f_s for "normal operation" (FHA-C formula (10); HD AG static load safety
factor table); 2 with shock or vibration, 3 for precise positioning."""


@dataclass(frozen=True, slots=True, kw_only=True)
class OutputLoad:
    """An external load on the output flange (FHA-C manual Fig. 1; CHA §4.3).

    Parameters
    ----------
    radial_force_n, axial_force_n
        F_r, F_a [N], ≥ 0, acting throughout the cycle.
    radial_lever_m
        L_r [m]: from the output flange's face to where F_r acts (the manual adds the
        bearing's offset R to reach its centre plane).
    axial_lever_m
        L_a [m]: the distance of F_a from the axis.
    load_factor
        f_w of the life formula (:data:`NORMAL_LOAD_FACTOR` by default).
    static_safety_min
        The least static safety factor f_s (:data:`NORMAL_STATIC_SAFETY` by default).
    required_life_h
        The L_10 life the application needs [h]; None: the life is not checked.
    """

    radial_force_n: float
    axial_force_n: float
    radial_lever_m: float
    axial_lever_m: float
    load_factor: float = NORMAL_LOAD_FACTOR
    static_safety_min: float = NORMAL_STATIC_SAFETY
    required_life_h: float | None = None


def tilting_moment_nm(
    *,
    radial_force_n: Any,
    axial_force_n: Any,
    radial_lever_m: Any,
    axial_lever_m: Any,
    offset_m: Any,
) -> Any:
    """Maximum tilting moment M = F_r·(L_r + R) + F_a·L_a [Nm] (FHA-C formula (1), CHA §4.3).

    >>> round(tilting_moment_nm(radial_force_n=100.0, axial_force_n=0.0, radial_lever_m=0.1,
    ...                         axial_lever_m=0.0, offset_m=0.02), 9)
    12.0
    """
    return radial_force_n * (radial_lever_m + offset_m) + axial_force_n * axial_lever_m


def static_equivalent_load_n(
    *, radial_force_n: Any, axial_force_n: Any, moment_nm: Any, pitch_diameter_m: Any
) -> Any:
    """P_0 = X_0·(F_r + 2M/d_p) + Y_0·F_a [N] (FHA-C formula (9)), X_0 = 1, Y_0 = 0.44.

    >>> static_equivalent_load_n(radial_force_n=0.0, axial_force_n=100.0, moment_nm=0.0,
    ...                          pitch_diameter_m=0.05)
    44.0
    """
    radial = radial_force_n + 2.0 * moment_nm / pitch_diameter_m
    return STATIC_RADIAL_FACTOR * radial + STATIC_AXIAL_FACTOR * axial_force_n


def dynamic_equivalent_load_n(
    *, radial_force_n: Any, axial_force_n: Any, moment_nm: Any, pitch_diameter_m: Any, xp: Any
) -> Any:
    """P_c = X·(F_r + 2M/d_p) + Y·F_a [N] (FHA-C formula (6), CHA Eq. 70.1), X and Y by
    the axial share (:data:`AXIAL_RATIO_LIMIT`); ``xp`` the rules' operations.

    >>> from actuator_selection.sizing.checks import FLOAT_OPS
    >>> dynamic_equivalent_load_n(radial_force_n=0.0, axial_force_n=100.0, moment_nm=0.0,
    ...                           pitch_diameter_m=0.05, xp=FLOAT_OPS)
    67.0
    """
    radial = radial_force_n + 2.0 * moment_nm / pitch_diameter_m
    low_axial = axial_force_n <= AXIAL_RATIO_LIMIT * radial
    x = xp.where(low_axial, RADIAL_FACTOR_LOW_AXIAL, RADIAL_FACTOR_HIGH_AXIAL)
    y = xp.where(low_axial, AXIAL_FACTOR_LOW_AXIAL, AXIAL_FACTOR_HIGH_AXIAL)
    return x * radial + y * axial_force_n


def life_revolutions_factor(
    *, required_life_h: Any, mean_speed_rpm: Any, xp: Any, exponent_inverse: float = 0.3
) -> Any:
    """(L_h·60·n_av/10⁶)^(1/B): the dynamic load rating a required life L_h needs, per
    newton of f_w·P_c (FHA-C formula (7) solved for C), 1/B = ``exponent_inverse``
    (3/10 for a roller bearing, 1/3 for a ball bearing). Depends on the case alone."""
    revolutions = required_life_h * 60.0 * mean_speed_rpm / REVOLUTIONS_PER_RATING
    return xp.pow(revolutions, exponent_inverse)


def oscillating_life_h(
    *,
    dynamic_load_rating_n: float,
    load_factor: float,
    equivalent_load_n: float,
    oscillations_per_min: float,
    half_angle_deg: float,
) -> float:
    """L_oc = 10⁶/(60·n_1)·(90/θ)·(C/(f_w·P_c))^(10/3) [h] (FHA-C formula (8)): n_1
    reciprocations per minute [cpm], θ half the oscillating angle [°].

    Equal to :func:`l10_life_h` at n_av = n_1·θ/90 (module docstring):

    >>> l10 = l10_life_h(dynamic_load_rating_n=7400, load_factor=1.5,
    ...                  equivalent_load_n=1000, mean_speed_rpm=12 * 45 / 90)
    >>> oc = oscillating_life_h(dynamic_load_rating_n=7400, load_factor=1.5,
    ...                         equivalent_load_n=1000, oscillations_per_min=12,
    ...                         half_angle_deg=45)
    >>> abs(oc - l10) < 1e-9 * l10
    True
    """
    ratio = dynamic_load_rating_n / (load_factor * equivalent_load_n)
    return (
        REVOLUTIONS_PER_RATING
        / (60.0 * oscillations_per_min)
        * (90.0 / half_angle_deg)
        * math.pow(ratio, LIFE_EXPONENT)
    )


def l10_life_h(
    *,
    dynamic_load_rating_n: float,
    load_factor: float,
    equivalent_load_n: float,
    mean_speed_rpm: float,
    exponent: float = LIFE_EXPONENT,
) -> float:
    """L_10 = 10⁶/(60·n_av)·(C/(f_w·P_c))^B [h] (FHA-C formula (7)), B = ``exponent`` (10/3
    for a roller bearing, 3 for a ball bearing); infinite without load or without motion.

    >>> round(l10_life_h(dynamic_load_rating_n=7400, load_factor=1.5,
    ...                  equivalent_load_n=1000, mean_speed_rpm=10), 0)
    340657.0
    >>> round(l10_life_h(dynamic_load_rating_n=7400, load_factor=1.5,
    ...                  equivalent_load_n=1000, mean_speed_rpm=10, exponent=3.0), 0)
    200111.0
    """
    if equivalent_load_n <= 0 or mean_speed_rpm <= 0:
        return float("inf")
    ratio = dynamic_load_rating_n / (load_factor * equivalent_load_n)
    return REVOLUTIONS_PER_RATING / (60.0 * mean_speed_rpm) * math.pow(ratio, exponent)
