"""Measured motion profiles: sampled speeds as the segments the flowchart sizes.

A PLC trace, a CAM table or a simulation export gives the motion as samples: times
t_0 < t_1 < … < t_N and, at each, the speed v_i (or the position, whose derivative
:func:`speeds_from_positions` takes) and perhaps a process load L_i. Between two samples
the speed is taken as linear (constant acceleration), as the motion file of IDTA 02021
§2.2.2 reads its rows; the cycle lasts t_N − t_0 and repeats, so it ends at the speed it
starts at.

:func:`fit_segments` turns the samples into the :class:`~actuator_selection.sizing.motion.
Segment` list of the flowchart: the fewest breakpoints, chosen among the samples, such
that the straight line between two breakpoints stays within ``tolerance`` of every
sample's speed and the segment's mean process load within ``tolerance`` of every sample's
load (best-first Ramer–Douglas–Peucker on the speed curve, with the largest deviation
split first). A profile made of ramps and runs (the chapter's Fig. 516.2, a CAM table of
constant accelerations) comes back as its few segments, exactly; a noisy trace as at most
``max_segments`` segments, and :attr:`SampledCycle.deviation` says how far they lie from
the samples. Where the speed changes sign between two samples the zero crossing is a
breakpoint (a segment does not pass through standstill); speeds within the tolerance of 0
count as standstill.

The figures of the samples themselves (:func:`sample_figures`: t_0, n_av of Eq. 514.3,
ED of Eq. 514.4, the peak speed and acceleration, the process load's RMS and peak) stand
beside the same figures of the segments, so that the approximation is visible.

Worked example (Fig. 516.2, Table 516.1: n_2 = 40 rpm, t_1 = t_2 = t_3 = 0.1 s, t_p = 1 s)
sampled every 1 ms:

>>> t = np.linspace(0.0, 1.3, 1301)
>>> v = np.interp(t, [0.0, 0.1, 0.2, 0.3, 1.3], [0.0, 40.0, 40.0, 0.0, 0.0])
>>> cycle = fit_segments(t, v, None, tolerance=1e-6)
>>> [(round(d, 3), round(e, 3)) for d, e, _ in cycle.segments]
[(0.1, 40.0), (0.1, 40.0), (0.1, 0.0), (1.0, 0.0)]
>>> round(cycle.samples.mean_speed, 4), round(cycle.samples.duty_cycle_percent, 2)
(6.1538, 23.08)
"""

from __future__ import annotations

import heapq
import itertools
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.motion import MAX_SEGMENTS

FloatArray = npt.NDArray[np.float64]

DEFAULT_TOLERANCE = 0.002
"""Default deviation allowed between the samples and the segments, as a share of the peak
speed (and of the peak process load): 0.2 %, the resolution of a 10-bit speed reading."""


@dataclass(frozen=True, slots=True, kw_only=True)
class SampledFigures:
    """The figures of a cycle that do not depend on the actuator, in the profile's units
    (speeds in rpm or mm/s, loads in Nm or N)."""

    cycle_s: float
    """t_0, the cycle time [s]."""
    mean_speed: float
    """n_av = ∫|v| dt / t_0 (Eq. 514.3)."""
    duty_cycle_percent: float
    """ED = time in motion / t_0 · 100 (Eq. 514.4) [%]."""
    peak_speed: float
    """max |v|."""
    peak_accel: float
    """max |dv/dt| [speed unit per s]."""
    rms_load: float | None
    """√(∫L² dt / t_0) of the process load, None without one."""
    peak_load: float | None
    """max |L|, None without one."""


@dataclass(frozen=True, slots=True, kw_only=True)
class SampledCycle:
    """The samples as segments (module docstring)."""

    start_speed: float
    segments: tuple[tuple[float, float, float], ...]
    """Each segment's duration [s], end speed and process load, in order."""
    samples: SampledFigures
    """The figures of the samples."""
    fitted: SampledFigures
    """The same figures of the segments."""
    deviation: float
    """The largest |v_i − v(t_i)| between a sample and the segments, in the speed unit."""
    load_deviation: float
    """The largest |L_i − L_k| between a sample's load and its segment's, in the load unit."""
    exact: bool
    """Whether the segments lie within the tolerance of every sample."""


def speeds_from_positions(time_s: FloatArray, position: FloatArray) -> FloatArray:
    """dx/dt at each sample, by second-order central differences (one-sided at the ends;
    ``numpy.gradient`` on uneven steps): exact where the position is quadratic in time
    over the three samples, as along a ramp of constant acceleration."""
    if time_s.size < 3:
        return np.zeros_like(position) if time_s.size < 2 else np.gradient(position, time_s)
    return np.asarray(np.gradient(position, time_s, edge_order=2), dtype=np.float64)


def _mean_abs(t0: FloatArray, v0: FloatArray, v1: FloatArray) -> FloatArray:
    """∫|v| dt over each interval of a linear speed (a sign change counted as two
    triangles)."""
    same = v0 * v1 >= 0
    magnitude = np.abs(v0) + np.abs(v1)
    crossing = (v0 * v0 + v1 * v1) / (2 * np.where(magnitude > 0, magnitude, 1.0))
    return np.where(same, np.abs(v0 + v1) / 2, crossing) * t0


def sample_figures(
    time_s: FloatArray, speed: FloatArray, load: FloatArray | None
) -> SampledFigures:
    """:class:`SampledFigures` of a speed linear between the samples and a load linear
    between them (∫L² dt of a linear L: dt·(L_a² + L_a·L_b + L_b²)/3, as ``sizing.motion``
    sums T²)."""
    dt = np.diff(time_s)
    cycle = float(time_s[-1] - time_s[0])
    v0, v1 = speed[:-1], speed[1:]
    travel = float(np.sum(_mean_abs(dt, v0, v1)))
    moving = float(np.sum(np.where((v0 != 0) | (v1 != 0), dt, 0.0)))
    accel = np.abs(np.diff(speed)) / dt
    rms_load = peak_load = None
    if load is not None:
        la, lb = load[:-1], load[1:]
        energy = float(np.sum(dt * (la * la + la * lb + lb * lb) / 3.0))
        rms_load = math.sqrt(energy / cycle)
        peak_load = float(np.max(np.abs(load)))
    return SampledFigures(
        cycle_s=cycle,
        mean_speed=travel / cycle,
        duty_cycle_percent=moving / cycle * 100.0,
        peak_speed=float(np.max(np.abs(speed))),
        peak_accel=float(np.max(accel)) if accel.size else 0.0,
        rms_load=rms_load,
        peak_load=peak_load,
    )


def _with_crossings(
    time_s: FloatArray, speed: FloatArray, load: FloatArray | None
) -> tuple[FloatArray, FloatArray, FloatArray | None, npt.NDArray[np.intp]]:
    """The samples with a sample at each zero crossing of the speed between two samples
    (load interpolated), and the indices of the crossings."""
    crosses = np.flatnonzero(speed[:-1] * speed[1:] < 0)
    if not crosses.size:
        return time_s, speed, load, crosses
    v0, v1 = speed[crosses], speed[crosses + 1]
    share = v0 / (v0 - v1)
    t_c = time_s[crosses] + share * (time_s[crosses + 1] - time_s[crosses])
    at = crosses + 1
    new_load = None
    if load is not None:
        l_c = load[crosses] + share * (load[crosses + 1] - load[crosses])
        new_load = np.insert(load, at, l_c)
    # np.insert places value j before old index at[j]: the inserted sample's new index.
    return (
        np.insert(time_s, at, t_c),
        np.insert(speed, at, 0.0),
        new_load,
        at + np.arange(at.size),
    )


def _segment_load(time_s: FloatArray, load: FloatArray, i: int, j: int) -> float:
    """The time-weighted mean of a linear load between samples i and j."""
    t, x = time_s[i : j + 1], load[i : j + 1]
    return float(np.sum(np.diff(t) * (x[:-1] + x[1:]) / 2) / (t[-1] - t[0]))


def _worst(
    time_s: FloatArray,
    speed: FloatArray,
    load: FloatArray | None,
    i: int,
    j: int,
    speed_tol: float,
    load_tol: float,
) -> tuple[float, int, float, float]:
    """The worst sample between breakpoints i and j: its deviation in tolerances, its
    index, and the speed and load deviations of the range."""
    t, v = time_s[i : j + 1], speed[i : j + 1]
    chord = v[0] + (v[-1] - v[0]) * (t - t[0]) / (t[-1] - t[0])
    dev_v = np.abs(v - chord)
    score = dev_v / speed_tol
    dev_l = 0.0
    if load is not None:
        deviation = np.abs(load[i : j + 1] - _segment_load(time_s, load, i, j))
        dev_l = float(np.max(deviation))
        score = np.maximum(score, deviation / load_tol)
    if score.size < 3:  # one interval: nothing to split
        return 0.0, i, float(np.max(dev_v)), dev_l
    # the worst sample, or the one beside it where the worst is an end (a load's step)
    k = min(max(int(np.argmax(score)), 1), score.size - 2)
    return float(np.max(score)), i + k, float(np.max(dev_v)), dev_l


def fit_segments(
    time_s: FloatArray,
    speed: FloatArray,
    load: FloatArray | None,
    *,
    tolerance: float = DEFAULT_TOLERANCE,
    max_segments: int = MAX_SEGMENTS,
) -> SampledCycle:
    """The samples as at most ``max_segments`` segments (module docstring).

    Parameters
    ----------
    time_s
        Sample times [s], strictly increasing, at least two.
    speed
        Speed at each sample (rpm or mm/s), finite; the last equal to the first within
        the tolerance (a cycle).
    load
        Process load at each sample (Nm or N), or None.
    tolerance
        Deviation allowed, as a share of the peak speed and of the peak load, > 0.
    max_segments
        At most this many segments.
    """
    peak = float(np.max(np.abs(speed)))
    speed_tol = tolerance * peak if peak > 0 else tolerance
    speed = np.where(np.abs(speed) <= speed_tol, 0.0, speed)
    if abs(speed[-1] - speed[0]) > speed_tol:
        raise InvalidInputError(
            "speed",
            code="profile_not_closed",
            params={"first": float(speed[0]), "last": float(speed[-1])},
        )
    speed = speed.copy()
    speed[-1] = speed[0]
    load_peak = float(np.max(np.abs(load))) if load is not None else 0.0
    load_tol = tolerance * load_peak if load_peak > 0 else tolerance
    samples = sample_figures(time_s, speed, load)
    t, v, x, crossings = _with_crossings(time_s, speed, load)
    fixed = sorted({0, t.size - 1, *crossings.tolist()})
    if len(fixed) - 1 > max_segments:
        raise InvalidInputError(
            "speed",
            code="profile_too_many_reversals",
            params={"count": crossings.size, "max": max_segments},
        )
    heap: list[tuple[float, int, int, int]] = []
    ranges: dict[int, tuple[int, float, float]] = {}

    def consider(i: int, j: int) -> None:
        score, k, dev_v, dev_l = _worst(t, v, x, i, j, speed_tol, load_tol)
        ranges[i] = (j, dev_v, dev_l)
        if score > 1.0:
            heapq.heappush(heap, (-score, i, j, k))

    for i, j in itertools.pairwise(fixed):
        consider(i, j)
    count = len(fixed) - 1
    while heap and count < max_segments:
        _, i, j, k = heapq.heappop(heap)
        consider(i, k)
        consider(k, j)
        count += 1
    starts = sorted(ranges)
    segments = []
    for i in starts:
        j = ranges[i][0]
        process = _segment_load(t, x, i, j) if x is not None else 0.0
        segments.append((float(t[j] - t[i]), float(v[j]), process))
    deviation = max(r[1] for r in ranges.values())
    load_deviation = max(r[2] for r in ranges.values())
    breaks = np.array([*starts, t.size - 1])
    fitted_load = None
    if x is not None:
        fitted_load = np.array([s[2] for s in segments])
    fitted = _fitted_figures(t[breaks], v[breaks], fitted_load)
    return SampledCycle(
        start_speed=float(v[0]),
        segments=tuple(segments),
        samples=samples,
        fitted=fitted,
        deviation=deviation,
        load_deviation=load_deviation,
        exact=not heap and deviation <= speed_tol and load_deviation <= load_tol,
    )


def _fitted_figures(
    time_s: FloatArray, speed: FloatArray, loads: FloatArray | None
) -> SampledFigures:
    """:func:`sample_figures` of the segments (their loads constant along each)."""
    figures = sample_figures(time_s, speed, None)
    if loads is None:
        return figures
    dt = np.diff(time_s)
    rms = math.sqrt(float(np.sum(dt * loads * loads)) / figures.cycle_s)
    return SampledFigures(
        cycle_s=figures.cycle_s,
        mean_speed=figures.mean_speed,
        duty_cycle_percent=figures.duty_cycle_percent,
        peak_speed=figures.peak_speed,
        peak_accel=figures.peak_accel,
        rms_load=rms,
        peak_load=float(np.max(np.abs(loads))),
    )
