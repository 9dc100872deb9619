"""Motion cycles as segments: several moves, reversals, dwells, S-curves (issue "Real axes").

The chapter's cycle (Fig. 516.2) is one trapezoid: accelerate in t_1, run for t_2, brake
in t_3, pause for t_p. Machines move in several steps, both ways, with jerk-limited
ramps, and hold weights at standstill. A :class:`Motion` is a closed list of
:class:`Segment` (each a duration with its start and end speed at the output, a share
of jerk-limited ramp, and a process torque) driving an
:class:`~actuator_selection.core.axis.AxisLoad`. The CHA manual sums the RMS torque
over n segments; so does this module:

    T_rms = √( Σ_k ∫ T_k(t)² dt / t_0 ),   n_av = Σ_k ∫ |n_k(t)| dt / t_0,

with the torque of each piece from :mod:`~actuator_selection.core.axis` (Eq. 514.1 with
the load's friction, gravity, process torque and efficiency). Within a piece the
acceleration is constant or varies linearly (a jerk ramp), so the torque varies linearly
and ∫T² dt = t·(T_a² + T_a·T_b + T_b²)/3 exactly.

The chapter's trapezoid is the shorthand :func:`trapezoid`: its four segments give the
chapter's T_1, T_2, T_3, n_av and ED operation for operation (Eq. 514.1, 514.3, 514.4),
and T_rms of Eq. 514.2 with squares taken as ``x * x``.

What the flowchart reads from a cycle, per actuator (J_A):

- ``accel_torque_nm`` T_1: of the torques at every piece's ends while the speed does not
  fall in magnitude (accelerating, running, standing), the one of largest magnitude,
  signed; in the trapezoid the chapter's T_1;
- ``decel_torque_nm`` T_3: the same over the braking pieces (speed falling in magnitude);
  0 where the cycle never brakes; in the trapezoid the chapter's T_3;
- ``constant_torque_nm`` T_2: the same over pieces at constant nonzero speed; None
  where the cycle has none; in the trapezoid T_L.

Worked example (Table 516.1 with the FHA-25C-50-L's J_A = 0.86 kgm²):

>>> from actuator_selection.core.axis import AxisLoad
>>> m = trapezoid(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0,
...               load=AxisLoad(inertia_kgm2=1.3, friction_torque_nm=5))
>>> profile = profile_of(m)
>>> t = profile.torques(0.86)
>>> round(t.accel_torque_nm, 2), round(t.decel_torque_nm, 2), round(t.rms_torque_nm, 2)
(95.48, -85.48, 35.57)
>>> round(profile.mean_speed_rpm, 2), round(profile.duty_cycle_percent, 2)
(6.15, 23.08)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, fields
from typing import Any

import numpy as np
import numpy.typing as npt

from actuator_selection.core.axis import AxisLoad
from actuator_selection.core.deferred import Deferred, defer_field
from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.messages import N_
from actuator_selection.core.units import RAD_PER_S_PER_RPM, rpm_to_rad_per_s

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
        for name in ("duration_s", "start_rpm", "end_rpm", "jerk_share", "process_torque_nm"):
            value = getattr(self, name)
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
        for k, (a, b) in enumerate(zip(self.segments, self.segments[1:], strict=False)):
            if a.end_rpm != b.start_rpm:
                raise InvalidInputError(f"segments.{k + 1}.start_rpm", code="speed_jump")
        if self.segments[-1].end_rpm != self.segments[0].start_rpm:
            raise InvalidInputError("segments", code="cycle_not_closed")
        if not sum(s.duration_s for s in self.segments) > 0:
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
    where the load drives back; :mod:`~actuator_selection.core.axis`), split where the
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


@dataclass(frozen=True, slots=True, kw_only=True)
class CycleTorques:
    """Torques of one actuator over the cycle [Nm] (module docstring)."""

    accel_torque_nm: float
    constant_torque_nm: float | None
    decel_torque_nm: float
    rms_torque_nm: float


@dataclass(frozen=True, slots=True, kw_only=True)
class SegmentTorque:
    """The torque at the start and end of each piece of one segment, for the cycle chart."""

    segment: int
    times_s: tuple[float, ...]
    """Times from the cycle's start at which the torques hold."""
    torques_nm: tuple[float, ...]


@dataclass(frozen=True, slots=True, kw_only=True)
class Profile:
    """A cycle prepared for the flowchart: its pieces and the figures that do not depend
    on the actuator (arrays built by :func:`profile_arrays`, read back as floats)."""

    motion: Motion
    load: AxisLoad
    """The motion's axis load (``motion.load``), apart so that it is read without building
    the motion (a batch's profiles build it only when read). Replace both together."""
    pieces: tuple[Piece, ...]
    cycle_s: float
    mean_speed_rpm: float
    duty_cycle_percent: float
    peak_speed_rpm: float
    accel_floor_nm: float
    decel_floor_nm: float
    rms_floor_nm: float
    holding_torque_nm: float
    braking_s: float

    def torques(self, actuator_inertia_kgm2: float) -> CycleTorques:
        """T_1, T_2, T_3, T_rms for an actuator of inertia J_A, written operation for
        operation like the vectorised flowchart's (``core/engine/``)."""
        j_a = actuator_inertia_kgm2
        energy = 0.0
        accel, accel_abs = 0.0, -1.0
        decel, decel_abs = 0.0, -1.0
        constant, constant_abs = math.nan, -1.0
        for p in self.pieces:
            inertia = j_a + p.inertia_kgm2
            t0 = p.static_nm + inertia * p.accel_start
            t1 = p.static_nm + inertia * p.accel_end
            if p.accel_start == p.accel_end:
                energy += t0 * t0 * p.duration_s
            else:
                energy += (t0 * t0 + t0 * t1 + t1 * t1) / 3.0 * p.duration_s
            for torque in (t0, t1):
                magnitude = abs(torque)
                if p.braking:
                    if magnitude > decel_abs:
                        decel, decel_abs = torque, magnitude
                elif magnitude > accel_abs:
                    accel, accel_abs = torque, magnitude
                if p.constant_speed and magnitude > constant_abs:
                    constant, constant_abs = torque, magnitude
        rms = math.sqrt(energy / self.cycle_s)
        for value, what in ((accel, "T_1 (Eq. 514.1)"), (decel, "T_3 (Eq. 514.1)")):
            _require_finite_result(value, what)
        _require_finite_result(rms, "T_rms (Eq. 514.2)")
        return CycleTorques(
            accel_torque_nm=accel,
            constant_torque_nm=None if constant_abs < 0 else constant,
            decel_torque_nm=decel,
            rms_torque_nm=rms,
        )

    def heating_gains(self, thermal_time_constant_s: float) -> tuple[tuple[float, ...], float]:
        """g_k = 1 − e^(−t_k/τ_th) for each piece, and 1 − e^(−t_0/τ_th) for the cycle
        (:func:`heating_gain`)."""
        tau = thermal_time_constant_s
        return tuple([heating_gain(p.duration_s, tau) for p in self.pieces]), heating_gain(
            self.cycle_s, tau
        )

    def thermal_torque_nm(
        self,
        actuator_inertia_kgm2: float,
        gains: Sequence[float],
        cycle_gain: float,
        no_load_slope: float | None = None,
    ) -> float:
        """The peak of the winding's heating over the repeating cycle, as a torque [Nm].

        A first-order thermal model of the winding (losses ∝ T², one time constant
        τ_th; the model of Fig. 520.1's overload durations, :func:`~actuator_selection.
        core.thermal.overload_duration_s`), in torque² units: x → T² with
        dx/dt = (T² − x)/τ_th, so that x = T_c² is the continuous limit T_c reached in
        steady state. Over a piece of duration t_k whose T² is taken as its mean m_k,

            x_end = x_start + (m_k − x_start)·g_k,   g_k = 1 − e^(−t_k/τ_th),

        exact for a constant torque, within (T_b² − T_a²)·t_k/τ_th of the truth for a
        ramp (m_k = (T_a² + T_a·T_b + T_b²)/3, the mean of a linear torque's square, as
        in T_rms). Once around the cycle x_N = A·x_0 + B with A = e^(−t_0/τ_th) and B
        the end of a cycle started at 0, so the repeating cycle starts at
        x_0 = B/(1 − A) (the periodic steady state, what a machine reaches after a few
        τ_th). The peak of x is at a piece's end (within a piece x moves monotonically
        towards m_k); its square root is returned. A cycle short against τ_th gives
        √x → T_rms (Eq. 514.2); a segment long against it gives its own torque.
        Written operation for operation like the vectorised flowchart (``core/engine/``).

        With ``no_load_slope`` k_T·K_INL, the heating follows the winding current rather
        than the torque alone (Eq. 522.2, 522.3): a piece counts as its rms torque plus
        the torque k_T·K_INL·|n| that its speed-dependent no-load current takes from the
        continuous stall current, (√m_k + k_T·K_INL·|n̄_k|)², |n̄_k| its mean |n|
        (:func:`mean_abs_speed_rpm`); at constant torque T and speed n that is T +
        k_T·K_INL·n against T_0, the current-based edge T ≤ T_0 − k_T·K_INL·n of the
        continuous check, and at standstill the torque alone.

        Parameters
        ----------
        actuator_inertia_kgm2
            J_A [kgm²].
        gains, cycle_gain
            :meth:`heating_gains` for τ_th.
        no_load_slope
            k_T·K_INL [Nm/rpm] (:func:`~actuator_selection.core.electrical.
            no_load_torque_slope_nm_per_rpm`), or None: the torque alone.
        """
        j_a = actuator_inertia_kgm2
        energy, heat = 0.0, 0.0
        squares = []
        for p, gain in zip(self.pieces, gains, strict=True):
            inertia = j_a + p.inertia_kgm2
            t0 = p.static_nm + inertia * p.accel_start
            t1 = p.static_nm + inertia * p.accel_end
            if p.accel_start == p.accel_end:
                square = t0 * t0
            else:
                square = (t0 * t0 + t0 * t1 + t1 * t1) / 3.0
            if no_load_slope is not None:
                speed = mean_abs_speed_rpm(
                    p.duration_s, p.start_rpm, p.end_rpm, p.accel_start, p.accel_end
                )
                torque = math.sqrt(square) + no_load_slope * speed
                square = torque * torque
            squares.append(square)
            energy += square * p.duration_s
            heat = heat + (square - heat) * gain
        # cycle_gain is 0 only where t_0/τ_th underflows: then x stays at the mean, T_rms².
        start = heat / cycle_gain if cycle_gain > 0 else energy / self.cycle_s
        peak = heat = start
        for square, gain in zip(squares, gains, strict=True):
            heat = heat + (square - heat) * gain
            if heat > peak:
                peak = heat
        return math.sqrt(peak)

    def thermal_speed_rpm(self, gains: Sequence[float], cycle_gain: float) -> float:
        """The speed the winding's speed-dependent heating follows, at its peak over the
        repeating cycle [rpm]; never below n_av.

        The chapter judges speed by the cycle's mean n_av (Eq. 514.3), a linear average of
        |n|: it stands for a cycle short against the winding's thermal time constant, as
        T_rms does for torque. A segment long against τ_th heats the winding with its own
        speed (iron losses and the no-load current I_NLR = I_NLS + K_INL·n of Eq. 522.2
        grow with speed), whatever the mean. The same first-order model as
        :meth:`thermal_torque_nm`, on the quantity the chapter averages: y → |n| with
        dy/dt = (|n| − y)/τ_th, each piece's |n| taken as its mean
        (:func:`mean_abs_speed_rpm`), the periodic steady state y_0 = B/(1 − A), the peak
        at a piece's end. A cycle short against τ_th gives n_av back; a run at k times a
        speed limit n_c from standstill crosses n_c after τ_th·ln(k/(k − 1)) (the linear
        counterpart of Fig. 520.1's model): 1.1·τ_th at k = 1.5. Written operation for
        operation like the vectorised flowchart (``core/engine/``).

        Parameters
        ----------
        gains, cycle_gain
            :meth:`heating_gains` for τ_th.
        """
        heat = 0.0
        speeds = []
        for p, gain in zip(self.pieces, gains, strict=True):
            speed = mean_abs_speed_rpm(
                p.duration_s, p.start_rpm, p.end_rpm, p.accel_start, p.accel_end
            )
            speeds.append(speed)
            heat = heat + (speed - heat) * gain
        # cycle_gain is 0 only where t_0/τ_th underflows: then y stays at the mean, n_av.
        start = heat / cycle_gain if cycle_gain > 0 else self.mean_speed_rpm
        peak = heat = start
        for speed, gain in zip(speeds, gains, strict=True):
            heat = heat + (speed - heat) * gain
            if heat > peak:
                peak = heat
        mean = self.mean_speed_rpm
        return peak if peak > mean else mean

    def segment_torques(self, actuator_inertia_kgm2: float) -> tuple[SegmentTorque, ...]:
        """Per segment, the torque at the ends of its pieces along the cycle's time."""
        out: dict[int, tuple[list[float], list[float]]] = {}
        clock = 0.0
        for p in self.pieces:
            inertia = actuator_inertia_kgm2 + p.inertia_kgm2
            times, torques = out.setdefault(p.segment, ([], []))
            times.extend((clock, clock + p.duration_s))
            torques.extend(
                (p.static_nm + inertia * p.accel_start, p.static_nm + inertia * p.accel_end)
            )
            clock += p.duration_s
        return tuple(
            SegmentTorque(segment=k, times_s=tuple(ts), torques_nm=tuple(qs))
            for k, (ts, qs) in out.items()
        )


class _PiecesOf(Deferred):
    """:func:`pieces_of` a motion (or of what builds it), when a profile's pieces are
    first read: a batch answers thousands of cycles from their arrays and reads few."""

    __slots__ = ("_motion",)

    def __init__(self, motion: Motion | Deferred) -> None:
        self._motion = motion

    def resolve(self) -> tuple[Piece, ...]:
        motion = self._motion
        return pieces_of(motion.resolve() if isinstance(motion, Deferred) else motion)


defer_field(Profile, "pieces")
defer_field(Profile, "motion")


def heating_gain(duration_s: float, thermal_time_constant_s: float) -> float:
    """1 − e^(−t/τ_th), the share of the way to its steady state that a first-order
    system covers in t, by ``math.expm1`` (exact for short t, where 1 − exp(−t/τ) would
    cancel). Both flowcharts call this on Python floats, so they agree bit for bit.

    >>> round(heating_gain(600.0, 600.0), 6)  # 1 − 1/e
    0.632121
    """
    return -math.expm1(-duration_s / thermal_time_constant_s)


def mean_abs_speed_rpm(
    duration_s: Any, start_rpm: Any, end_rpm: Any, accel_start: Any, accel_end: Any
) -> Any:
    """A piece's mean |n| [rpm]: (n_a + n_b)/2, plus (α_a − α_b)·t/12 (in rpm) where the
    acceleration ramps (a jerk ramp's speed is quadratic in time), as :func:`_summed`
    sums the travel; a piece never passes through standstill (:class:`Segment`). Floats
    or arrays, the same IEEE operations on both."""
    ramp = (accel_start - accel_end) * duration_s / 12.0 / RAD_PER_S_PER_RPM
    return abs((start_rpm + end_rpm) / 2 + ramp)


def pieces_of(motion: Motion) -> tuple[Piece, ...]:
    """The cycle's pieces in order (:class:`Piece`)."""
    return tuple(
        p for k, seg in enumerate(motion.segments) for p in _pieces_of(k, seg, motion.load)
    )


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
    zero = np.zeros(rows)
    with np.errstate(all="ignore"):  # as Python floats: an overflow gives inf, no error
        accel = speed_rpm * RAD_PER_S_PER_RPM / accel_s
        decel = -speed_rpm * RAD_PER_S_PER_RPM / decel_s

    def columns(*values: FloatArray) -> FloatArray:
        return np.stack(values, axis=1)

    pattern = np.array([[False, True, False, False]])
    inertia = columns(inertia_kgm2, inertia_kgm2, inertia_kgm2, inertia_kgm2)
    return PieceArrays(
        duration=columns(accel_s, constant_s, decel_s, pause_s),
        start_rpm=columns(zero, speed_rpm, speed_rpm, zero),
        end_rpm=columns(speed_rpm, speed_rpm, zero, zero),
        accel_start=columns(accel, zero, decel, zero),
        accel_end=columns(accel, zero, decel, zero),
        static=columns(torque_nm, torque_nm, torque_nm, zero),
        inertia=inertia,
        braking=np.repeat(np.array([[False, False, True, False]]), rows, axis=0),
        constant_speed=np.repeat(pattern, rows, axis=0),
        moving=np.repeat(np.array([[True, True, True, False]]), rows, axis=0),
        direction=np.repeat(np.array([[1.0, 1.0, 1.0, 0.0]]), rows, axis=0),
        holding=torque_nm.copy(),
    )


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
    cycle (:func:`_summed`, on the pieces' columns)."""
    rows = p.duration.shape[0]
    columns = zip(
        p.duration.T,
        p.start_rpm.T,
        p.end_rpm.T,
        p.accel_start.T,
        p.accel_end.T,
        p.static.T,
        p.inertia.T,
        p.braking.T,
        p.moving.T,
        p.direction.T,
        strict=True,
    )
    with np.errstate(all="ignore"):  # as Python floats: overflow gives inf, no error
        return CycleFigures(*_summed(columns, np.zeros(rows), _ARRAY_MATH))


def _where(condition: bool, if_true: float, if_false: float) -> float:
    return if_true if condition else if_false


def _float_maximum(a: float, b: float) -> float:
    """``np.maximum`` on two floats: NaN if either is, else the larger, ``b`` on a tie
    (``np.maximum(0.0, -0.0)`` is −0.0)."""
    return a if a > b or a != a else b


_ARRAY_MATH = (np.where, np.maximum, np.sqrt)
_FLOAT_MATH = (_where, _float_maximum, math.sqrt)


def _summed(
    columns: Iterable[tuple[Any, ...]], zero: Any, ops: tuple[Any, Any, Any]
) -> tuple[Any, ...]:
    """The figures of :class:`CycleFigures`, in its order, summed piece by piece in the
    order of the pieces (the trapezoid: the chapter's operations). ``columns`` holds each
    piece's duration, start and end speed, start and end acceleration, static torque,
    inertia, braking, moving and direction: arrays of many cycles (:func:`cycle_figures`)
    or floats of one (:func:`profile_of`), with ``ops`` (where, maximum, sqrt) to match.
    The same operations in the same order on IEEE doubles: a single profile and a batch
    agree bit for bit, and one cycle costs no numpy call (~0.3 ms of them).

    n_av sums ∫|n| dt: (n_a + n_b)/2·t for a piece of constant acceleration, plus
    (α_a − α_b)·t²/12 (in rpm) where the acceleration ramps (a jerk ramp's speed is
    quadratic in time).

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
    for t, n0, n1, a0, a1, static, inertia, braking, moving, s in columns:
        cycle = cycle + t
        ramp = (a0 - a1) * (t * t) / 12.0 / RAD_PER_S_PER_RPM
        distance = where(a0 == a1, (n0 + n1) / 2 * t, (n0 + n1) / 2 * t + ramp)
        travel = travel + abs(distance)
        moving_s = moving_s + where(moving, t, 0.0)
        braking_s = braking_s + where(braking, t, 0.0)
        peak = maximum(peak, maximum(abs(n0), abs(n1)))
        for alpha in (a0, a1):
            at_zero = static + (0.0 + inertia) * alpha
            grows = where(s == 0, abs(at_zero), s * at_zero)
            accel_floor = where(braking, accel_floor, maximum(accel_floor, grows))
            decel_floor = where(braking, maximum(decel_floor, -(s * at_zero)), decel_floor)
        # ∫T² dt as a quadratic in J_A: T_a = p_a + a0·J_A, T_b = p_b + a1·J_A.
        pa = static + inertia * a0
        pb = static + inertia * a1
        third = t / 3.0
        a_coef = a_coef + third * (pa * pa + pa * pb + pb * pb)
        b_coef = b_coef + third * (2 * pa * a0 + pa * a1 + pb * a0 + 2 * pb * a1)
        c_coef = c_coef + third * (a0 * a0 + a0 * a1 + a1 * a1)
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
    again."""

    def column(name: str) -> FloatArray:
        return np.array([getattr(p, name) for p in profiles], dtype=np.float64)

    return CycleFigures(
        cycle_s=column("cycle_s"),
        mean_speed_rpm=column("mean_speed_rpm"),
        duty_cycle_percent=column("duty_cycle_percent"),
        peak_speed_rpm=column("peak_speed_rpm"),
        accel_floor_nm=column("accel_floor_nm"),
        decel_floor_nm=column("decel_floor_nm"),
        rms_floor_nm=column("rms_floor_nm"),
        braking_s=column("braking_s"),
    )


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
    return _profile(motion, load, pieces, _summed(columns, 0.0, _FLOAT_MATH), holding)


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


def _require_finite_result(value: float, what: str, *, field: str = "load") -> None:
    """Finite inputs can still overflow a product: a 422 naming the input, never ±∞ or a
    500 (PostgreSQL's JSON refuses ``Infinity``)."""
    if not math.isfinite(value):
        raise InvalidInputError(field, code="result_overflow", params={"what": what})
