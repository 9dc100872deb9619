"""A cycle's figures (n_av, the torque floors, ...) summed for many cycles at once on
arrays, and on floats for one.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.deferred import Deferred
from actuator_selection.sizing.motion.profile import Profile, _PiecesOf, _require_finite_result
from actuator_selection.sizing.motion.segments import (
    BoolArray,
    FloatArray,
    Motion,
    Piece,
    pieces_of,
)
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM


@dataclass(frozen=True, slots=True, eq=False)
class PieceArrays:
    """The pieces of many cycles as arrays, cycles × pieces, padded with empty standstill
    pieces (no time, no torque: they change no sum and no maximum)."""

    duration: FloatArray
    start_rpm: FloatArray
    end_rpm: FloatArray
    accel_start: FloatArray
    accel_end: FloatArray
    static: FloatArray
    inertia: FloatArray
    braking: BoolArray
    constant_speed: BoolArray
    moving: BoolArray
    direction: FloatArray
    holding: FloatArray
    """Per cycle: the torque the actuator or its brake holds at standstill, |T_G| + T_F
    (friction counted as the chapter's conservative reading: a T_L that may act at rest)."""


def piece_arrays(motions: Sequence[Motion]) -> PieceArrays:
    """:class:`PieceArrays` of ``motions``."""
    lists = [pieces_of(m) for m in motions]
    width = max((len(ps) for ps in lists), default=1)
    shape = (len(lists), width)

    def fill(attr: str) -> FloatArray:
        out = np.zeros(shape)
        for i, ps in enumerate(lists):
            out[i, : len(ps)] = [getattr(p, attr) for p in ps]
        return out

    def flags(attr: str) -> BoolArray:
        out = np.zeros(shape, dtype=np.bool_)
        for i, ps in enumerate(lists):
            out[i, : len(ps)] = [getattr(p, attr) for p in ps]
        return out

    direction = fill("direction")
    return PieceArrays(
        duration=fill("duration_s"),
        start_rpm=fill("start_rpm"),
        end_rpm=fill("end_rpm"),
        accel_start=fill("accel_start"),
        accel_end=fill("accel_end"),
        static=fill("static_nm"),
        inertia=fill("inertia_kgm2"),
        braking=flags("braking"),
        constant_speed=flags("constant_speed"),
        moving=direction != 0,
        direction=direction,
        holding=np.array(
            [abs(m.load.gravity_torque_nm) + m.load.friction_torque_nm for m in motions],
            dtype=np.float64,
        ),
    )


def trapezoid_piece_arrays(
    *,
    speed_rpm: FloatArray,
    accel_s: FloatArray,
    constant_s: FloatArray,
    decel_s: FloatArray,
    pause_s: FloatArray,
    torque_nm: FloatArray,
    inertia_kgm2: FloatArray,
) -> PieceArrays:
    """:func:`piece_arrays` of the chapter's trapezoids (:func:`trapezoid` with a friction
    load T_L, J_L), built as columns: the same arrays, bit for bit (a test compares them),
    without a Python object per piece, for batches of thousands of cases."""
    rows = speed_rpm.size
    tables: FloatArray
    one = None
    if rows == 1:
        # One case: its pieces on Python floats, in one numpy call where the arrays took
        # a dozen.
        one = trapezoid_piece_floats(
            speed_rpm.item(),
            accel_s.item(),
            constant_s.item(),
            decel_s.item(),
            pause_s.item(),
            torque_nm.item(),
            inertia_kgm2.item(),
        )
    if one is not None:
        tables = np.array(one, dtype=np.float64).reshape(len(one), 1, 4)
    else:
        with np.errstate(all="ignore"):  # as Python floats: an overflow gives inf, no error
            columns = _trapezoid_columns(
                speed_rpm,
                accel_s,
                constant_s,
                decel_s,
                pause_s,
                torque_nm,
                inertia_kgm2,
                np.zeros(rows),
            )
        # The pieces as columns, every table in one array (quantity × piece × case) seen
        # transposed: the same values as an array per table (np.stack, then np.array per
        # table, cost a one-case selection ~7 %, then ~4 % of its time).
        tables = np.array(columns, dtype=np.float64).transpose(0, 2, 1)
    duration, start_rpm, end_rpm, accel_start, accel_end, static, inertia = tables
    return PieceArrays(
        duration=duration,
        start_rpm=start_rpm,
        end_rpm=end_rpm,
        accel_start=accel_start,
        accel_end=accel_end,
        static=static,
        inertia=inertia,
        braking=_repeated(_TRAPEZOID_BRAKING, rows),
        constant_speed=_repeated(_TRAPEZOID_CONSTANT, rows),
        moving=_repeated(_TRAPEZOID_MOVING, rows),
        direction=_repeated(_TRAPEZOID_DIRECTION, rows),
        holding=torque_nm.copy(),
    )


# The trapezoid's pieces (accelerate, run, brake, pause), one row to repeat per case.
TRAPEZOID_BRAKING = (False, False, True, False)
TRAPEZOID_CONSTANT = (False, True, False, False)
"""The trapezoid's pieces that brake and that run at constant speed, as truths."""
_TRAPEZOID_BRAKING = np.array([TRAPEZOID_BRAKING])
_TRAPEZOID_CONSTANT = np.array([TRAPEZOID_CONSTANT])
_TRAPEZOID_MOVING = np.array([[True, True, True, False]])
_TRAPEZOID_DIRECTION = np.array([[1.0, 1.0, 1.0, 0.0]])
for _row in (_TRAPEZOID_BRAKING, _TRAPEZOID_CONSTANT, _TRAPEZOID_MOVING, _TRAPEZOID_DIRECTION):
    _row.setflags(write=False)  # one case's own (not copied: four numpy calls a selection)


def trapezoid_piece_floats(
    speed_rpm: float,
    accel_s: float,
    constant_s: float,
    decel_s: float,
    pause_s: float,
    torque_nm: float,
    inertia_kgm2: float,
) -> tuple[tuple[float, float, float, float], ...] | None:
    """One trapezoid's row of :func:`trapezoid_piece_arrays` as Python floats, a tuple per
    quantity (duration, start and end speed, start and end acceleration, static torque,
    inertia) of its four pieces: the same IEEE operations (an overflow gives inf). None
    where a ramp takes no time (its acceleration divides by 0: ±∞ or NaN on arrays,
    where Python's floats raise)."""
    if accel_s == 0 or decel_s == 0:
        return None
    return _trapezoid_columns(
        speed_rpm, accel_s, constant_s, decel_s, pause_s, torque_nm, inertia_kgm2, 0.0
    )


def _repeated(row: Any, rows: int) -> Any:
    """The trapezoid's ``row`` for ``rows`` cases: itself (read-only) for one."""
    return row if rows == 1 else row.repeat(rows, axis=0)


def _trapezoid_columns(
    speed: Any,
    accel_s: Any,
    constant_s: Any,
    decel_s: Any,
    pause_s: Any,
    static: Any,
    inertia: Any,
    zero: Any,
) -> tuple[tuple[Any, Any, Any, Any], ...]:
    """The trapezoid's pieces (accelerate, run, brake, pause) as :func:`_pieces_of` gives
    them, a tuple per quantity of :class:`PieceArrays` (duration, start and end speed,
    start and end acceleration, static torque, inertia): the arrays of many cases
    (:func:`trapezoid_piece_arrays`) or the floats of one (:func:`trapezoid_profile`)."""
    accel = speed * RAD_PER_S_PER_RPM / accel_s  # Eq. 514.1: (n_2·2π/60)/t_1
    decel = -speed * RAD_PER_S_PER_RPM / decel_s
    return (
        (accel_s, constant_s, decel_s, pause_s),
        (zero, speed, speed, zero),
        (speed, speed, zero, zero),
        (accel, zero, decel, zero),
        (accel, zero, decel, zero),
        (static, static, static, zero),
        (inertia, inertia, inertia, inertia),
    )


_TRAPEZOID_FLAGS = tuple(
    zip(
        _TRAPEZOID_BRAKING[0].tolist(),
        _TRAPEZOID_MOVING[0].tolist(),
        _TRAPEZOID_DIRECTION[0].tolist(),
        strict=True,
    )
)
"""Each trapezoid piece's braking, moving and direction, as floats and truths."""


@dataclass(frozen=True, slots=True, eq=False)
class CycleFigures:
    """What the flowchart needs of each cycle that does not depend on the actuator."""

    cycle_s: FloatArray
    mean_speed_rpm: FloatArray
    duty_cycle_percent: FloatArray
    peak_speed_rpm: FloatArray
    accel_floor_nm: FloatArray
    """The least |T_1| over every J_A ≥ 0."""
    decel_floor_nm: FloatArray
    """The least |T_3| over every J_A ≥ 0."""
    rms_floor_nm: FloatArray
    """The least T_rms over every J_A ≥ 0."""
    braking_s: FloatArray
    """Time spent braking (speed falling in magnitude) [s]: t_3 in the trapezoid."""


def cycle_figures(p: PieceArrays) -> CycleFigures:
    """t_0, n_av (Eq. 514.3), ED (Eq. 514.4), the peak speed and the torque floors of each
    cycle (:func:`_summed`, on the pieces' columns): each piece's terms computed on the
    whole tables at once (:func:`_piece_terms`, elementwise: the numbers of a column at a
    time), then summed piece by piece."""
    rows = p.duration.shape[0]
    with np.errstate(all="ignore"):  # as Python floats: overflow gives inf, no error
        terms = _piece_terms(
            p.duration,
            p.start_rpm,
            p.end_rpm,
            p.accel_start,
            p.accel_end,
            p.static,
            p.inertia,
            p.braking,
            p.moving,
            p.direction,
            _ARRAY_MATH,
        )
        columns = zip(*(term.T for term in terms), strict=True)
        return CycleFigures(*_summed(columns, np.zeros(rows), _ARRAY_MATH))


def _where(condition: bool, if_true: float, if_false: float) -> float:
    return if_true if condition else if_false


def _float_maximum(a: float, b: float) -> float:
    """``np.maximum`` on two floats: NaN if either is, else the larger, ``b`` on a tie
    (``np.maximum(0.0, -0.0)`` is −0.0)."""
    return a if a > b or a != a else b


_ARRAY_MATH = (np.where, np.maximum, np.sqrt)
_FLOAT_MATH = (_where, _float_maximum, math.sqrt)


def _piece_terms(
    t: Any,
    n0: Any,
    n1: Any,
    a0: Any,
    a1: Any,
    static: Any,
    inertia: Any,
    braking: Any,
    moving: Any,
    s: Any,
    ops: tuple[Any, Any, Any],
) -> tuple[Any, ...]:
    """What :func:`_summed` sums or takes the largest of, per piece: its duration, |∫n dt|,
    its time moving and braking, its peak |n|, braking, for each end's acceleration the
    torque at J_A = 0 in the direction of motion and against it, and its ∫T² dt
    coefficients. Elementwise: a piece's floats (:func:`profile_of`), or the tables of
    many cycles' pieces at once (:func:`cycle_figures`), the same operations.

    n_av sums ∫|n| dt: (n_a + n_b)/2·t for a piece of constant acceleration, plus
    (α_a − α_b)·t²/12 (in rpm) where the acceleration ramps (a jerk ramp's speed is
    quadratic in time). ∫T² dt is a quadratic in J_A: T_a = p_a + a0·J_A,
    T_b = p_b + a1·J_A."""
    where, maximum, _sqrt = ops
    ramp = (a0 - a1) * (t * t) / 12.0 / RAD_PER_S_PER_RPM
    distance = where(a0 == a1, (n0 + n1) / 2 * t, (n0 + n1) / 2 * t + ramp)
    ends = []
    for alpha in (a0, a1):
        at_zero = static + (0.0 + inertia) * alpha
        ends += [where(s == 0, abs(at_zero), s * at_zero), -(s * at_zero)]
    pa = static + inertia * a0
    pb = static + inertia * a1
    third = t / 3.0
    return (
        t,
        abs(distance),
        where(moving, t, 0.0),
        where(braking, t, 0.0),
        maximum(abs(n0), abs(n1)),
        braking,
        *ends,
        third * (pa * pa + pa * pb + pb * pb),
        third * (2 * pa * a0 + pa * a1 + pb * a0 + 2 * pb * a1),
        third * (a0 * a0 + a0 * a1 + a1 * a1),
    )


def _summed(
    terms: Iterable[tuple[Any, ...]], zero: Any, ops: tuple[Any, Any, Any]
) -> tuple[Any, ...]:
    """The figures of :class:`CycleFigures`, in its order, summed piece by piece in the
    order of the pieces (the trapezoid: the chapter's operations) from each piece's
    :func:`_piece_terms`: arrays of many cycles (:func:`cycle_figures`) or floats of one
    (:func:`profile_of`), with ``ops`` (where, maximum, sqrt) to match. The same
    operations in the same order on IEEE doubles: a single profile and a batch agree bit
    for bit, and one cycle costs no numpy call (~0.3 ms of them).

    The floors bound the checks from below where J_A is unknown (issue "The checks a
    sizing engineer signs", item 7): the torque T = c + (J_A + J)·α of a piece that does
    not brake grows in the direction of motion with J_A, so |T| ≥ s·T(J_A = 0); that of a
    braking piece falls, so |T| ≥ max(−s·T(0), 0); at standstill it does not depend on
    J_A. T_rms² is a convex quadratic in J_A, least at −B/(2C) or at J_A = 0.
    """
    where, maximum, sqrt = ops
    cycle = travel = moving_s = braking_s = peak = zero
    accel_floor = decel_floor = zero
    a_coef = b_coef = c_coef = zero
    for t, distance, moving_t, braking_t, top, braking, *ends, a_add, b_add, c_add in terms:
        cycle = cycle + t
        travel = travel + distance
        moving_s = moving_s + moving_t
        braking_s = braking_s + braking_t
        peak = maximum(peak, top)
        for grows, falls in (ends[0:2], ends[2:4]):
            accel_floor = where(braking, accel_floor, maximum(accel_floor, grows))
            decel_floor = where(braking, maximum(decel_floor, falls), decel_floor)
        a_coef = a_coef + a_add
        b_coef = b_coef + b_add
        c_coef = c_coef + c_add
    positive = c_coef > 0
    best = where(positive, -b_coef / (2 * where(positive, c_coef, 1.0)), 0.0)
    best = where(best > 0, best, 0.0)
    energy = a_coef + best * (b_coef + best * c_coef)
    rms_floor = sqrt(maximum(energy, 0.0) / cycle)
    return (
        cycle,
        travel / cycle,
        moving_s / cycle * 100.0,
        peak,
        accel_floor,
        decel_floor,
        rms_floor,
        braking_s,
    )


def figures_of(profiles: Sequence[Profile]) -> CycleFigures:
    """The :class:`CycleFigures` of cycles whose profiles are known: the same numbers
    :func:`cycle_figures` gives (a profile's figures are its row of them), not computed
    again. One table, its columns contiguous: an array per figure cost eight numpy calls,
    a tenth of a one-model selection's cases."""
    table = np.array(
        [[getattr(p, name) for name in _FIGURE_NAMES] for p in profiles], dtype=np.float64
    ).reshape(len(profiles), len(_FIGURE_NAMES))
    return CycleFigures(*np.ascontiguousarray(table.T))


def profile_of(motion: Motion) -> Profile:
    """The :class:`Profile` of one cycle: its figures summed on floats as
    :func:`cycle_figures` sums them on arrays for many (:func:`_summed`), so that a single
    selection and a batch agree bit for bit."""
    pieces = pieces_of(motion)
    columns = (
        (
            p.duration_s,
            p.start_rpm,
            p.end_rpm,
            p.accel_start,
            p.accel_end,
            p.static_nm,
            p.inertia_kgm2,
            p.braking,
            p.direction != 0,
            float(p.direction),
        )
        for p in pieces
    )
    load = motion.load
    holding = abs(load.gravity_torque_nm) + load.friction_torque_nm  # as piece_arrays
    terms = (_piece_terms(*piece, _FLOAT_MATH) for piece in columns)
    return _profile(motion, load, pieces, _summed(terms, 0.0, _FLOAT_MATH), holding)


def trapezoid_profile(
    motion: Motion,
    *,
    speed_rpm: float,
    accel_s: float,
    constant_s: float,
    decel_s: float,
    pause_s: float,
) -> Profile:
    """:func:`profile_of` the chapter's trapezoid ``motion`` (:func:`trapezoid` of these
    with a load of friction T_L and inertia J_L alone), the same floats, from its pieces'
    columns (:func:`_trapezoid_columns`) without a :class:`Piece` for each: its pieces
    are built when first read. A one-model selection's cycle."""
    load = motion.load
    # T_G + s·T_F + T_P as _pieces_of sums it (s = 1: 0 + T_L + 0, a T_L of −0.0 as 0.0).
    static = load.gravity_torque_nm + load.friction_torque_nm + 0.0
    columns = _trapezoid_columns(
        speed_rpm, accel_s, constant_s, decel_s, pause_s, static, load.inertia_kgm2, 0.0
    )
    terms = (
        _piece_terms(t, n0, n1, a0, a1, c, j, braking, moving, s, _FLOAT_MATH)
        for (t, n0, n1, a0, a1, c, j), (braking, moving, s) in zip(
            zip(*columns, strict=True), _TRAPEZOID_FLAGS, strict=True
        )
    )
    holding = abs(load.gravity_torque_nm) + load.friction_torque_nm  # as piece_arrays
    figures = _summed(terms, 0.0, _FLOAT_MATH)
    return _profile(motion, load, _PiecesOf(motion), figures, holding)


def profile_from(
    motion: Motion | Deferred, load: AxisLoad, figures: tuple[float, ...], holding: float
) -> Profile:
    """The :class:`Profile` of ``motion`` (or of a :class:`Deferred` that builds it when it
    is first read: the same object for the motion and the pieces, so it should keep what
    it built) with its axis load and its figures, a row of :func:`figure_rows` of arrays
    computed for many cycles at once."""
    return _profile(motion, load, _PiecesOf(motion), figures, holding)


def figure_rows(figures: CycleFigures) -> list[tuple[float, ...]]:
    """Each cycle's figures of ``figures`` as floats, for :func:`profile_from`."""
    return list(zip(*(getattr(figures, name).tolist() for name in _FIGURE_NAMES), strict=True))


_FIGURE_NAMES = tuple(f.name for f in fields(CycleFigures))


def _profile(
    motion: Motion | Deferred,
    load: AxisLoad,
    pieces: tuple[Piece, ...] | Deferred,
    figures: tuple[float, ...],
    holding: float,
) -> Profile:
    cycle_s, mean_speed, duty, peak_speed, accel_floor, decel_floor, rms_floor, braking_s = figures
    profile = Profile(
        motion=motion,  # type: ignore[arg-type]  # a deferrable field
        load=load,
        pieces=pieces,  # type: ignore[arg-type]  # a deferrable field
        cycle_s=cycle_s,
        mean_speed_rpm=mean_speed,
        duty_cycle_percent=duty,
        peak_speed_rpm=peak_speed,
        accel_floor_nm=accel_floor,
        decel_floor_nm=decel_floor,
        rms_floor_nm=rms_floor,
        holding_torque_nm=holding,
        braking_s=braking_s,
    )
    if not math.isfinite(profile.mean_speed_rpm):
        _require_finite_result(profile.mean_speed_rpm, "n_av (Eq. 514.3)", field="speed_rpm")
    _require_finite_result(profile.accel_floor_nm, "T_1 (Eq. 514.1)")
    _require_finite_result(profile.decel_floor_nm, "T_3 (Eq. 514.1)")
    _require_finite_result(profile.rms_floor_nm, "T_rms (Eq. 514.2)")
    return profile
