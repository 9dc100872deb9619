"""A motion cycle as segments and the pieces the torque is linear on (Segment, Motion, the
chapter's trapezoid).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM, rpm_to_rad_per_s

FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]

MAX_SEGMENTS = 200
"""Segments in one cycle: more than any machine cycle an engineer sizes by hand."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Segment:
    """One step of a cycle at the actuator output.

    Parameters
    ----------
    duration_s
        Duration [s], ≥ 0; > 0 where the speed changes.
    start_rpm, end_rpm
        Output speed at the start and at the end [rpm], signed (negative: the other
        way). The speed changes at constant acceleration, or along an S-curve
        (``jerk_share``). A segment does not pass through standstill: a reversal is two
        segments, one braking to 0 and one accelerating the other way.
    jerk_share
        Share of the duration in which the acceleration ramps up and down [-], 0…1: 0 a
        constant acceleration, 1 a pure S-curve (the acceleration rises linearly to its
        peak and falls back to 0). Its peak is Δω/(t·(1 − share/2)).
    process_torque_nm
        An external torque during the segment at the output [Nm], signed; positive
        opposes positive rotation (a pressing or cutting force, at the output).
    """

    duration_s: float
    start_rpm: float
    end_rpm: float
    jerk_share: float = 0.0
    process_torque_nm: float = 0.0

    def __post_init__(self) -> None:
        values = (
            self.duration_s,
            self.start_rpm,
            self.end_rpm,
            self.jerk_share,
            self.process_torque_nm,
        )
        if not all(map(math.isfinite, values)):  # the first that is not finite
            for name, value in zip(_SEGMENT_NUMBERS, values, strict=True):
                if not math.isfinite(value):
                    raise InvalidInputError(name, code="not_finite", params={"value": value})
        if self.duration_s < 0:
            raise InvalidInputError(
                "duration_s", code="must_be_nonnegative", params={"rule": N_("a duration")}
            )
        if self.start_rpm != self.end_rpm and self.duration_s <= 0:
            raise InvalidInputError("duration_s", code="duration_zero_with_speed_change")
        if self.start_rpm * self.end_rpm < 0:
            raise InvalidInputError("end_rpm", code="speed_sign_change")
        if not 0 <= self.jerk_share <= 1:
            raise InvalidInputError("jerk_share", code="share_range")

    @property
    def direction(self) -> int:
        """+1, −1, or 0 at standstill: the sign of the speed."""
        speed = self.end_rpm if self.end_rpm != 0 else self.start_rpm
        return (speed > 0) - (speed < 0)


_SEGMENT_NUMBERS = ("duration_s", "start_rpm", "end_rpm", "jerk_share", "process_torque_nm")
"""A segment's numbers, in the order :meth:`Segment.__post_init__` checks them."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Motion:
    """A closed cycle: segments in order, the last ending at the speed the first starts at."""

    segments: tuple[Segment, ...]
    load: AxisLoad

    def __post_init__(self) -> None:
        if not self.segments:
            raise InvalidInputError("segments", code="segments_empty")
        if len(self.segments) > MAX_SEGMENTS:
            raise InvalidInputError(
                "segments", code="segments_too_many", params={"max": MAX_SEGMENTS}
            )
        segments = self.segments
        for k in range(1, len(segments)):
            if segments[k - 1].end_rpm != segments[k].start_rpm:
                raise InvalidInputError(f"segments.{k}.start_rpm", code="speed_jump")
        if segments[-1].end_rpm != segments[0].start_rpm:
            raise InvalidInputError("segments", code="cycle_not_closed")
        if not sum([s.duration_s for s in segments]) > 0:
            raise InvalidInputError("segments", code="cycle_zero_duration")


def trapezoid(
    *,
    speed_rpm: float,
    accel_s: float,
    constant_s: float,
    decel_s: float,
    pause_s: float,
    load: AxisLoad,
) -> Motion:
    """The chapter's cycle (Fig. 516.2) as four segments: 0 → n_2 in t_1, n_2 for t_2,
    n_2 → 0 in t_3, standstill for t_p (kept even where t_2 or t_p is 0, so that T_2 is
    reported as the chapter reports it)."""
    return Motion(
        segments=(
            Segment(duration_s=accel_s, start_rpm=0.0, end_rpm=speed_rpm),
            Segment(duration_s=constant_s, start_rpm=speed_rpm, end_rpm=speed_rpm),
            Segment(duration_s=decel_s, start_rpm=speed_rpm, end_rpm=0.0),
            Segment(duration_s=pause_s, start_rpm=0.0, end_rpm=0.0),
        ),
        load=load,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class Piece:
    """A stretch of a segment in which the acceleration is constant or linear and the
    torque's efficiency factor does not change: T = c + (J_A + J)·α at each end."""

    segment: int
    """Index of the segment it belongs to."""
    duration_s: float
    start_rpm: float
    end_rpm: float
    accel_start: float
    """Output acceleration at the start [rad/s²]."""
    accel_end: float
    """… at the end [rad/s²] (equal to the start where constant)."""
    static_nm: float
    """c: the load's torque without inertia, times the efficiency factor [Nm]."""
    inertia_kgm2: float
    """J: the load's inertia times the efficiency factor [kgm²]."""
    braking: bool
    """Whether the speed falls in magnitude."""
    direction: int

    @property
    def constant_speed(self) -> bool:
        """Moving at constant speed."""
        return self.direction != 0 and self.accel_start == 0.0 and self.accel_end == 0.0


def _pieces_of(k: int, seg: Segment, load: AxisLoad) -> list[Piece]:
    s = seg.direction
    # T_G + s·T_F + T_P (the trapezoid: 0 + 1·T_L + 0 = T_L exactly).
    static = load.gravity_torque_nm + s * load.friction_torque_nm + seg.process_torque_nm
    braking = s != 0 and abs(seg.end_rpm) < abs(seg.start_rpm)
    if seg.start_rpm == seg.end_rpm:
        ramps = [(seg.duration_s, seg.start_rpm, seg.end_rpm, 0.0, 0.0)]
    else:
        t = seg.duration_s
        dn = seg.end_rpm - seg.start_rpm
        if seg.jerk_share == 0:
            alpha = rpm_to_rad_per_s(dn) / t  # Eq. 514.1: (n_2·2π/60)/t_1
            ramps = [(t, seg.start_rpm, seg.end_rpm, alpha, alpha)]
        else:
            t_j = seg.jerk_share * t / 2
            t_c = t - 2 * t_j
            peak = rpm_to_rad_per_s(dn) / (t - t_j)
            gained = dn * (t_j / 2) / (t - t_j)  # [rpm] while the acceleration ramps
            n_a, n_b = seg.start_rpm + gained, seg.end_rpm - gained
            ramps = [
                (t_j, seg.start_rpm, n_a, 0.0, peak),
                (t_c, n_a, n_b, peak, peak),
                (t_j, n_b, seg.end_rpm, peak, 0.0),
            ]
    pieces: list[Piece] = []
    eta = load.efficiency
    for t, n0, n1, a0, a1 in ramps:
        for part in _split_by_power_flow(t, n0, n1, a0, a1, static, load.inertia_kgm2, s, eta):
            pt, pn0, pn1, pa0, pa1, factor = part
            pieces.append(
                Piece(
                    segment=k,
                    duration_s=pt,
                    start_rpm=pn0,
                    end_rpm=pn1,
                    accel_start=pa0,
                    accel_end=pa1,
                    static_nm=static * factor,
                    inertia_kgm2=load.inertia_kgm2 * factor,
                    braking=braking,
                    direction=s,
                )
            )
    return pieces


def _split_by_power_flow(
    t: float,
    n0: float,
    n1: float,
    a0: float,
    a1: float,
    static: float,
    inertia: float,
    s: int,
    eta: float,
) -> list[tuple[float, float, float, float, float, float]]:
    """The piece with its efficiency factor (1/η where the actuator drives the load, η
    where the load drives back; :mod:`~actuator_selection.sizing.axis`), split where the
    load side's torque T_load = c + J_L·α changes sign within it."""
    if eta == 1.0 or s == 0:
        return [(t, n0, n1, a0, a1, 1.0)]
    x0, x1 = static + inertia * a0, static + inertia * a1

    def factor(x: float) -> float:
        return 1.0 / eta if x * s > 0 else eta

    if x0 * x1 >= 0 or t == 0:
        return [(t, n0, n1, a0, a1, factor(x0 if x0 != 0 else x1))]
    share = x0 / (x0 - x1)
    tau = share * t
    a_mid = a0 + (a1 - a0) * share
    # speed at τ: n0 + (a0·τ + (a1 − a0)·τ²/(2t)) in rpm
    n_mid = n0 + (a0 * tau + (a1 - a0) * tau * tau / (2 * t)) / RAD_PER_S_PER_RPM
    return [
        (tau, n0, n_mid, a0, a_mid, factor(x0)),
        (t - tau, n_mid, n1, a_mid, a1, factor(x1)),
    ]


def pieces_of(motion: Motion) -> tuple[Piece, ...]:
    """The cycle's pieces in order (:class:`Piece`)."""
    return tuple(
        p for k, seg in enumerate(motion.segments) for p in _pieces_of(k, seg, motion.load)
    )
