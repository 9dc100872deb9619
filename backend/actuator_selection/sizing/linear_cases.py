"""The ratio study's load cases at many leads of a screw or diameters of a pinion or a
belt's pulley (issue 31 part 1, :mod:`actuator_selection.sizing.ratio`):
:func:`linear_cases`, the cases a selection builds at each value (an axis, a trapezoid
of segments, their pieces by the power flow) as the engine's columns, no application
built per value, as :func:`~actuator_selection.sizing.ratio_cases.geared_cases` does for
an external ratio."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from actuator_selection.sizing.application import Application
from actuator_selection.sizing.engine import FloatArray
from actuator_selection.sizing.engine.cases import REQUEST_FIELDS, Cases, cases_of
from actuator_selection.sizing.mechanisms.linear import LinearLaw, linear_axis_columns, mm_to_m
from actuator_selection.sizing.motion import PieceArrays
from actuator_selection.sizing.ratio_cases import one_case
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM

_DROP = REQUEST_FIELDS.index("drop_torque_nm")
_TRAVEL = REQUEST_FIELDS.index("travel_mm_per_rad")


def linear_cases(
    base: Application,
    law: LinearLaw,
    speed_mm_per_s: float,
    vary: Callable[[float], Application],
) -> Callable[[FloatArray], Cases] | None:
    """The cases of ``vary`` (``base``, the request's own load case, with the mechanism's
    free length L in mm, a screw's lead or a pinion's or pulley's diameter, set to each
    value) at many values at once: the axis of ``law`` at each L
    (:func:`~actuator_selection.sizing.mechanisms.linear.linear_axis_columns`), the
    trapezoid's speed v·n-per-mm/s, its four pieces as
    :func:`~actuator_selection.sizing.motion.segments.pieces_of` makes them (constant
    accelerations: none is split; η by the power flow), T_G's |·| as the brake's drop
    and the travel per radian among the further inputs; the rest of ``base``'s case
    repeated. The same operations in the same order, so the same numbers, bit for bit (a
    test compares them). Where a value would make a selection refuse the case (r² or a
    result not finite, a speed of 0) the cases are built by ``vary`` value by value, which
    raises as a selection does. None where ``base``'s cycle is not the chapter's
    trapezoid (no process loads, no jerk)."""
    motion = base.motion
    if motion is None or not _trapezoid(base):
        return None
    segments = motion.segments
    durations = [s.duration_s for s in segments]
    eta = law.efficiency
    first = one_case(base)

    def by_value(values: FloatArray) -> Cases:
        return cases_of([vary(float(x)) for x in values])

    def at(values: FloatArray) -> Cases:
        radius, speed_factor, inertia, gravity, friction = linear_axis_columns(law, mm_to_m(values))
        with np.errstate(all="ignore"):
            speed = speed_mm_per_s * speed_factor
            travel = 60.0 / (2.0 * math.pi * speed_factor)
        checked = (radius * radius, speed_factor, inertia, gravity, friction, speed, travel)
        if not (
            np.all(checked[0] != 0)
            and all(np.isfinite(c).all() for c in checked)
            and np.all(speed > 0)
        ):
            return by_value(values)
        pieces = _pieces(durations, speed, inertia, gravity, friction, eta)
        requests = first.requests[np.zeros(values.size, dtype=np.intp)]
        requests[:, _DROP] = np.abs(gravity)
        requests[:, _TRAVEL] = travel
        return first.repeated_with(pieces, inertia, requests)

    return at


def _trapezoid(app: Application) -> bool:
    """Whether ``app``'s motion is the chapter's trapezoid at a speed > 0 (0 → n, n, n → 0,
    0; no jerk, no process torque) as :func:`~actuator_selection.sizing.motion.trapezoid`
    builds it."""
    motion = app.motion
    if motion is None or len(motion.segments) != 4:
        return False
    n = motion.segments[1].start_rpm
    ends = [(s.start_rpm, s.end_rpm) for s in motion.segments]
    return (
        n > 0
        and ends == [(0.0, n), (n, n), (n, 0.0), (0.0, 0.0)]
        and all(s.jerk_share == 0 and s.process_torque_nm == 0 for s in motion.segments)
    )


_DIRECTION = np.array([[1.0, 1.0, 1.0, 0.0]])
_BRAKING = np.array([[False, False, True, False]])


def _pieces(
    durations: list[float],
    speed: FloatArray,
    inertia: FloatArray,
    gravity: FloatArray,
    friction: FloatArray,
    eta: float,
) -> PieceArrays:
    """:func:`~actuator_selection.sizing.motion.piece_arrays` of the trapezoids at peak
    speeds ``speed`` (> 0) on the axes ``inertia``, ``gravity``, ``friction`` (η
    ``eta``): one piece per segment, as ``_pieces_of`` computes each (the load side's
    torque c + J·α does not change sign within a segment of constant α)."""
    rows = speed.size
    zero = np.zeros(rows)
    columns = []
    for k, (start, end) in enumerate(((zero, speed), (speed, speed), (speed, zero), (zero, zero))):
        s = 0 if k == 3 else 1  # the direction: the sign of a speed > 0, at rest 0
        static = gravity + s * friction + 0.0  # T_G + s·T_F + T_P, T_P = 0
        t = durations[k]
        if k in (1, 3):
            alpha = zero
        else:
            with np.errstate(all="ignore"):
                alpha = (end - start) * RAD_PER_S_PER_RPM / t
        if eta == 1.0 or s == 0:
            factor: FloatArray | float = 1.0
        else:
            load_side = static + inertia * alpha
            factor = np.where(load_side * s > 0, 1.0 / eta, eta)
        duration = np.full(rows, t)
        columns.append((duration, start, end, alpha, alpha, static * factor, inertia * factor))
    # every table in one array (quantity × piece × case) seen transposed, as
    # trapezoid_piece_arrays builds them: one numpy call, not a stack per table
    tables: FloatArray = np.array(
        [[c[q] for c in columns] for q in range(7)], dtype=np.float64
    ).transpose(0, 2, 1)
    duration, start_rpm, end_rpm, accel_start, accel_end, static_t, inertia_t = tables
    direction = _DIRECTION.repeat(rows, axis=0)
    return PieceArrays(
        duration=duration,
        start_rpm=start_rpm,
        end_rpm=end_rpm,
        accel_start=accel_start,
        accel_end=accel_end,
        static=static_t,
        inertia=inertia_t,
        braking=_BRAKING.repeat(rows, axis=0),
        constant_speed=(direction != 0) & (accel_start == 0.0) & (accel_end == 0.0),
        moving=direction != 0,
        direction=direction,
        holding=np.abs(gravity) + friction,
    )
