"""The ratio study's load cases at many values of an external ratio i (issue 31 part 1,
:mod:`actuator_selection.sizing.ratio`): :func:`geared`, a load case behind the ratio as
a selection builds it, and :func:`geared_cases`, the same at many ratios at once as the
engine's columns, no application built per value."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

import numpy as np

from actuator_selection.sizing.application import Application
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import FloatArray
from actuator_selection.sizing.engine.cases import Cases, cases_of
from actuator_selection.sizing.loads import _square, squares
from actuator_selection.sizing.mechanisms import Transmission, with_transmission
from actuator_selection.sizing.motion import (
    Motion,
    PieceArrays,
    trapezoid_piece_arrays,
)
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM

MONOTONE_SHARES = {"max_speed": 1, "inertia_ratio": -1, "drive_voltage": 1}
"""How three checks' shares (value/limit) move with the ratio i of :func:`geared` and
:func:`geared_cases` (the study's ``monotone``): the peak speed n_L·i rises with i, the
load inertia J_tr + J_L/i² falls (each a product, quotient or sum of a positive
constant: monotone in floating point too), against the actuator's n_max and 3·J_A; the
voltage U = √((|n|·i_A·K_E/1000 + I·R)² + (|n|·i_A·2π/60·p·L·I)²) at the peak speed n
rises with it (a product by, or a sum with, a constant ≥ 0 and the square and √ of
a value ≥ 0 are monotone as rounded) where the actuator's constants are ≥ 0
(:data:`~actuator_selection.sizing.ratio_floors.NON_NEGATIVE`), against its bus's
U_DC/√2. The reflected speed and inertia of Van de Straete et al. (1999) and Giberti
et al. (2011)."""


def geared(app: Application, transmission: Transmission) -> Application:
    """``app`` behind an external ratio i (between the actuator output and the load, in
    series with any the mechanism has): the cycle's speeds ×i and process torques ÷i, the
    load through :func:`~actuator_selection.sizing.mechanisms.with_transmission` (J_L/i² +
    J_tr, T/i, η_tr·η by the power flow). At i = 1 with J_tr = 0 and η = 1 it is ``app``'s
    own load case."""
    i = transmission.ratio
    if app.pattern is not None and app.load is not None and transmission.efficiency == 1:
        # the chapter's shorthand stays one (T_L as friction, η = 1): the numbers of
        # with_transmission, and the engine's trapezoid columns
        pattern, load = app.pattern, app.load
        return dataclasses.replace(
            app,
            pattern=dataclasses.replace(pattern, speed_rpm=pattern.speed_rpm * i),
            load=Load(
                torque_nm=load.torque_nm / i,
                inertia_kgm2=transmission.inertia_kgm2 + load.inertia_kgm2 / _square(i),
            ),
        )
    motion = app.cycle
    segments = tuple(
        dataclasses.replace(
            s,
            start_rpm=s.start_rpm * transmission.ratio,
            end_rpm=s.end_rpm * transmission.ratio,
            process_torque_nm=s.process_torque_nm / transmission.ratio,
        )
        for s in motion.segments
    )
    axis = with_transmission(motion.load, transmission)
    return dataclasses.replace(
        app, pattern=None, load=None, motion=Motion(segments=segments, load=axis)
    )


def one_case(app: Application) -> Cases:
    """``cases_of([app])``, its cycle's figures those of ``app``'s profile (summed on
    floats, :func:`~actuator_selection.sizing.motion.profile_of`: the numbers the arrays
    give, bit for bit), not summed again on one-row arrays (~0.3 ms of numpy calls): the
    case a study repeats at its values (:func:`geared_cases`, :func:`~actuator_selection.
    sizing.linear_cases.linear_cases`)."""
    assert app.profile is not None  # computed once, then read by cases_of
    return cases_of([app])


def geared_cases(
    app: Application, transmission_inertia_kgm2: float, efficiency: float = 1.0
) -> Callable[[FloatArray], Cases] | None:
    """:func:`geared` at many ratios at once, as the engine's load cases: the trapezoid's
    speed ×i, T_L ÷i, J_L/i² + J_tr as columns (what :func:`geared` computes for each
    ratio, the same operations), η_tr by the power flow as :func:`~actuator_selection.
    core.motion.segments.pieces_of` puts it (:func:`_by_power_flow`), the rest of
    ``app``'s case repeated. None where ``app`` is a cycle of segments."""
    pattern, load = app.pattern, app.load
    if pattern is None or load is None:
        return None
    base = one_case(app)
    # With η_tr < 1, geared() writes the shorthand as a cycle of segments: what the
    # brake's drop reads of the axis (its weight, none here) is that axis's, not T_L.
    chain = Transmission(ratio=1.0, inertia_kgm2=transmission_inertia_kgm2, efficiency=efficiency)
    requests = base.requests if efficiency == 1 else one_case(geared(app, chain)).requests

    def at(ratios: FloatArray) -> Cases:
        def repeated(value: float) -> FloatArray:
            return np.full(ratios.size, value)

        inertia = transmission_inertia_kgm2 + load.inertia_kgm2 / squares(ratios)
        pieces = trapezoid_piece_arrays(
            speed_rpm=pattern.speed_rpm * ratios,
            accel_s=repeated(pattern.accel_s),
            constant_s=repeated(pattern.constant_s),
            decel_s=repeated(pattern.decel_s),
            pause_s=repeated(pattern.pause_s),
            torque_nm=load.torque_nm / ratios,
            inertia_kgm2=inertia,
        )
        if efficiency != 1:
            pieces = _by_power_flow(pieces, efficiency)
        return base.repeated_with(pieces, inertia, requests[np.zeros(ratios.size, dtype=np.intp)])

    return at


def _by_power_flow(pieces: PieceArrays, efficiency: float) -> PieceArrays:
    """The trapezoid's pieces with the chain's η (η_tr·1) by the power flow, as
    :func:`~actuator_selection.sizing.motion.segments.pieces_of` applies it to the
    segments :func:`geared` builds: c and J × 1/η where the load side's torque
    c + J·α acts in the direction of motion (the actuator drives), × η where it does
    not (the load drives back), × 1 at standstill. Each of the trapezoid's pieces
    accelerates uniformly, so none is split."""
    with np.errstate(all="ignore"):
        load_side = pieces.static + pieces.inertia * pieces.accel_start
    factor = np.where(
        pieces.direction == 0,
        1.0,
        np.where(load_side * pieces.direction > 0, 1.0 / efficiency, efficiency),
    )
    return dataclasses.replace(
        pieces, static=pieces.static * factor, inertia=pieces.inertia * factor
    )


def geared_torque_floor(
    app: Application, transmission_inertia_kgm2: float, efficiency: float = 1.0
) -> Callable[[FloatArray, FloatArray], FloatArray] | None:
    """A lower bound of the engine's |T_1| (the ``peak_torque`` check's value) of
    :func:`geared_cases` between neighbouring ratios: given the ratios (ascending, n)
    and the actuators' J_A (m), intervals × actuators ((n − 1) × m); NaN where none is
    proven (J_A not published or negative, a negative operand, an overflow's inf·0).
    None where ``app`` is a cycle of segments.

    The reflection of Giberti et al. (2011) and Van de Straete et al. (1999): the
    trapezoid's accelerating piece carries, at ratio i, T(i) = c(i) + (J_A + J(i))·α(i)
    (:func:`~actuator_selection.sizing.engine.block.evaluate_block`), with c = f·(T_L/i),
    J = f·(J_tr + J_L/i²), α = n_L·i·2π/60/t_1 (:func:`~actuator_selection.sizing.
    motion.trapezoid_piece_arrays`), f the power flow's factor (1/η, η or 1 by the sign
    of the load side's torque, :func:`_by_power_flow`; 1 where η = 1). T_L/i,
    J_tr + J_L/i² and α are each monotone in i, and so is each as computed here and by
    :func:`geared_cases` (the same operations; a correctly rounded +, ×, ÷ by a constant
    is monotone): between ratios a and b each is at least the lesser of its values at
    a and b, and f at least its least value. Where those bounds c_lo, J_lo, α_lo and J_A
    are ≥ 0, rounding is monotone in each operand of J_A + J, (J_A + J)·α and c + …, so
    T(i) ≥ T_lo = c_lo + (J_A + J_lo)·α_lo ≥ 0, computed in that order: |T(i)| ≥ T_lo.
    The accelerating piece does not brake, so the engine's |T_1| (the largest |T| of
    the pieces that do not) is at least its |T(i)|. Elsewhere no bound is claimed."""
    pattern, load = app.pattern, app.load
    if pattern is None or load is None:
        return None
    factors = (1.0,) if efficiency == 1 else (1.0, 1.0 / efficiency, efficiency)

    def floor(ratios: FloatArray, inertia_a: FloatArray) -> FloatArray:
        between = GearedBounds(pattern, load, transmission_inertia_kgm2, factors, ratios)
        return between.accelerating(inertia_a)

    return floor


def geared_rms_floor(
    app: Application, transmission_inertia_kgm2: float, efficiency: float = 1.0
) -> Callable[[FloatArray, FloatArray], FloatArray] | None:
    """A lower bound of the engine's T_rms (the ``continuous_duty`` check's value) of
    :func:`geared_cases` between neighbouring ratios, as :func:`geared_torque_floor`
    bounds |T_1|: intervals × actuators, NaN where none is proven; None where ``app``
    is a cycle of segments.

    The rms torque of Giberti et al. (2011) as a function of the ratio, bounded piece by
    piece: T_rms² = Σ T_k²·t_k / t_0 over the trapezoid's pieces, summed in their order
    from 0 (:func:`~actuator_selection.sizing.engine.block.evaluate_block`). A lower
    bound of each |T_k| gives one of T_k² (a correctly rounded x·x is monotone in |x|),
    of each term (× t_k ≥ 0), of the sum (+ is monotone in each operand), and of
    √(Σ/t_0). Accelerating: T_lo of :func:`geared_torque_floor`. Running: T = c + (J_A
    + J)·0 = c ≥ c_lo ≥ 0. Braking (α < 0): T = c + (J_A + J)·α lies between
    c_lo + (J_A + J_hi)·α_lo and c_hi + (J_A + J_lo)·α_hi (each operand at the end of
    its range that lowers or raises it; α_hi ≤ 0, J_A + J ≥ 0): |T| is at least the
    lower where that is ≥ 0, at least −(the upper) where that is ≤ 0, else 0. At rest:
    T = 0. Where the accelerating piece has no bound, none is claimed."""
    pattern, load = app.pattern, app.load
    if pattern is None or load is None:
        return None
    factors = (1.0,) if efficiency == 1 else (1.0, 1.0 / efficiency, efficiency)
    durations = (pattern.accel_s, pattern.constant_s, pattern.decel_s, pattern.pause_s)
    cycle = 0.0
    for t in durations:  # t_0 as cycle_figures sums it
        cycle = cycle + t

    def floor(ratios: FloatArray, inertia_a: FloatArray) -> FloatArray:
        between = GearedBounds(pattern, load, transmission_inertia_kgm2, factors, ratios)
        col = np.newaxis
        energy = between.accelerating(inertia_a)  # NaN where not proven: NaN after
        with np.errstate(all="ignore"):
            energy *= energy
            energy *= pattern.accel_s
            running = between.c_lo * between.c_lo * pattern.constant_s
            energy += running[:, col]
            braking = between.braking_square(inertia_a)
            braking *= pattern.decel_s
            energy += braking
            # at rest T = 0: + 0·t_4 leaves the sum as it is
            energy /= cycle
            rms: FloatArray = np.sqrt(energy, out=energy)
        return rms

    return floor


class GearedBounds:
    """The operands of :func:`geared_cases`' pieces at neighbouring ratios (ascending),
    bounded between them: each the lesser (``_lo``) or the larger (``_hi``) of its
    values at the two, over every factor of the power flow; the J_L term and the
    accelerations as :func:`geared_cases` and :func:`~actuator_selection.sizing.motion.
    trapezoid_piece_arrays` compute them."""

    def __init__(
        self,
        pattern: SpeedPattern,
        load: Load,
        transmission_inertia_kgm2: float,
        factors: tuple[float, ...],
        ratios: FloatArray,
    ) -> None:
        with np.errstate(all="ignore"):
            static = load.torque_nm / ratios
            inertia = transmission_inertia_kgm2 + load.inertia_kgm2 / squares(ratios)
            speed = pattern.speed_rpm * ratios
            accel = speed * RAD_PER_S_PER_RPM / pattern.accel_s
            decel = -speed * RAD_PER_S_PER_RPM / pattern.decel_s
            self.c_lo = np.min([_least(static) * f for f in factors], axis=0)
            self.c_hi = np.max([_most(static) * f for f in factors], axis=0)
            self.j_lo = np.min([_least(inertia) * f for f in factors], axis=0)
            self.j_hi = np.max([_most(inertia) * f for f in factors], axis=0)
        self.a_lo = _least(accel)
        self.d_lo, self.d_hi = _least(decel), _most(decel)

    def accelerating(self, inertia_a: FloatArray) -> FloatArray:
        """T_lo of the accelerating piece (:func:`geared_torque_floor`), intervals ×
        actuators; NaN where not proven."""
        c_lo, j_lo, a_lo = self.c_lo, self.j_lo, self.a_lo
        with np.errstate(all="ignore"):
            provable = (c_lo >= 0) & (j_lo >= 0) & (a_lo >= 0)
            j_a = np.where(inertia_a >= 0, inertia_a, np.nan)
            bound: FloatArray = j_a + j_lo[:, np.newaxis]  # in place after: one array
            bound *= a_lo[:, np.newaxis]
            bound += c_lo[:, np.newaxis]
        bound[~provable] = np.nan
        return bound

    def braking_square(self, inertia_a: FloatArray) -> FloatArray:
        """A lower bound of the braking piece's T², intervals × actuators: the larger of
        −T_hi, T_lo and 0 (:func:`geared_rms_floor`; T_lo ≤ T ≤ T_hi, so where T_hi ≤ 0
        |T| ≥ −T_hi, where T_lo ≥ 0 |T| ≥ T_lo; fmax: a NaN end gives no bound), 0 where
        the operands' signs the argument needs do not hold."""
        col = np.newaxis
        with np.errstate(all="ignore"):
            bound: FloatArray = inertia_a + self.j_lo[:, col]  # then −T_hi, in place
            bound *= self.d_hi[:, col]
            bound += self.c_hi[:, col]
            np.negative(bound, out=bound)
            lower = inertia_a + self.j_hi[:, col]
            lower *= self.d_lo[:, col]
            lower += self.c_lo[:, col]
            np.fmax(bound, lower, out=bound)
            np.fmax(bound, 0.0, out=bound)
            # where J_A is negative or NaN the accelerating piece's bound is NaN
            bound[~((self.j_lo >= 0) & (self.d_hi <= 0) & (self.c_lo >= 0))] = 0.0
            bound *= bound
        return bound


def _least(values: FloatArray) -> FloatArray:
    """The lesser of each pair of neighbouring ``values``."""
    return np.minimum(values[:-1], values[1:])


def _most(values: FloatArray) -> FloatArray:
    """The larger of each pair of neighbouring ``values``."""
    return np.maximum(values[:-1], values[1:])
