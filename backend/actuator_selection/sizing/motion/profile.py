"""What the flowchart reads of one cycle: its Profile, the torques on an actuator, the
winding's heating.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.deferred import Deferred, defer_field
from actuator_selection.sizing.motion.segments import FloatArray, Motion, Piece, pieces_of
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM


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
        operation like the vectorised flowchart's (``sizing/engine/``)."""
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
        sizing.thermal.overload_duration_s`), in torque² units: x → T² with
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
        Written operation for operation like the vectorised flowchart (``sizing/engine/``).

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
            k_T·K_INL [Nm/rpm] (:func:`~actuator_selection.sizing.electrical.
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
        operation like the vectorised flowchart (``sizing/engine/``).

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


def heating_gain_array(durations_s: FloatArray, thermal_time_constants_s: FloatArray) -> FloatArray:
    """:func:`heating_gain` of each element (the arrays broadcast), bit for bit: the
    quotients by numpy (IEEE division, as Python's floats divide), then ``math.expm1``
    itself on each, in one C loop (``map``) rather than a call of Python per gain
    (numpy's ``expm1`` may differ from the C library's in the last bit). Called with
    numpy's errors ignored."""
    ratios = np.negative(durations_s) / thermal_time_constants_s
    flat = np.fromiter(map(math.expm1, ratios.ravel().tolist()), np.float64, ratios.size)
    gains: FloatArray = np.negative(flat).reshape(ratios.shape)
    return gains


def mean_abs_speed_rpm(
    duration_s: Any, start_rpm: Any, end_rpm: Any, accel_start: Any, accel_end: Any
) -> Any:
    """A piece's mean |n| [rpm]: (n_a + n_b)/2, plus (α_a − α_b)·t/12 (in rpm) where the
    acceleration ramps (a jerk ramp's speed is quadratic in time), as :func:`_summed`
    sums the travel; a piece never passes through standstill (:class:`Segment`). Floats
    or arrays, the same IEEE operations on both."""
    ramp = (accel_start - accel_end) * duration_s / 12.0 / RAD_PER_S_PER_RPM
    return abs((start_rpm + end_rpm) / 2 + ramp)


def _require_finite_result(value: float, what: str, *, field: str = "load") -> None:
    """Finite inputs can still overflow a product: a 422 naming the input, never ±∞ or a
    500 (PostgreSQL's JSON refuses ``Infinity``)."""
    if not math.isfinite(value):
        raise InvalidInputError(field, code="result_overflow", params={"what": what})
