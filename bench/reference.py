"""A plain numpy computation of a batch's numbers: the reference a batch request is held to.

For every case × actuator: T_1, T_3, T_rms, n_av (Eq. 514.1–514.3), the five checks'
pass/fail/no-data decisions, the verdicts, and the best ``top`` actuators of each case
by the service's ranking (verdict, the nearest miss among the unsuitable, then T_max,
J_A, model). It leaves out the lower bounds without J_A (every starter actuator has
J_A). Written the way one would write it by hand with numpy, with none of the service's
rule table, exact-rounding care, JSON or HTTP: what the numbers alone cost here.

:func:`agreement` says how often its top actuators are the service's, so that the
reference is known to compute the same thing.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.selection import Application
from actuator_selection.core.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S

FloatArray = npt.NDArray[np.float64]


def _column(values: Sequence[float]) -> FloatArray:
    return np.asarray(values, dtype=np.float64)[:, None]


def _row(values: Sequence[float | None]) -> FloatArray:
    return np.asarray([math.nan if v is None else v for v in values], dtype=np.float64)[None, :]


def numpy_reference(
    actuators: Sequence[Actuator], apps: Sequence[Application], top: int
) -> npt.NDArray[np.intp]:
    """Indexes into ``actuators`` of each case's best ``top`` (cases × top)."""
    patterns = [a.pattern for a in apps if a.pattern is not None]
    loads = [a.load for a in apps if a.load is not None]
    assert len(patterns) == len(loads) == len(apps), "the reference sizes the chapter's cycle"
    n2 = _column([p.speed_rpm for p in patterns])
    t1 = _column([p.accel_s for p in patterns])
    t2 = _column([p.constant_s for p in patterns])
    t3 = _column([p.decel_s for p in patterns])
    tp = _column([p.pause_s for p in patterns])
    tl = _column([x.torque_nm for x in loads])
    jl = _column([x.inertia_kgm2 for x in loads])
    dyn = np.asarray([a.high_dynamics for a in apps])[:, None]

    ja = _row([a.inertia_kgm2 for a in actuators])
    t_max = _row([a.max_torque_nm for a in actuators])
    n_max = _row([a.max_speed_rpm for a in actuators])
    t_0 = _row(
        [a.stall_torque_nm if a.stall_torque_nm is not None else a.continuous_torque_nm
         for a in actuators]
    )  # fmt: skip
    zoned = np.asarray([a.zone is not None for a in actuators])[None, :]
    speed_bound = _row(
        [a.continuous_speed_rpm if a.continuous_speed_rpm is not None else a.rated_speed_rpm
         for a in actuators]
    )  # fmt: skip

    omega = n2 * (2 * math.pi / 60)
    j = ja + jl
    accel = tl + j * (omega / t1)
    decel = tl - j * (omega / t3)
    t0 = t1 + t2 + t3 + tp
    rms = np.sqrt((accel * accel * t1 + tl * tl * t2 + decel * decel * t3) / t0)
    n_av = (n2 / 2 * t1 + n2 * t2 + n2 / 2 * t3) / t0
    # the zone's edge at n_av, interpolated per actuator
    edge = np.full(rms.shape, np.nan)
    for k, a in enumerate(actuators):
        if a.zone is not None:
            speeds = [p.speed_rpm for p in a.zone.points]
            torques = [p.torque_nm for p in a.zone.points]
            edge[:, k] = np.interp(n_av[:, 0], speeds, torques, right=np.nan)
    limit = np.where(zoned, edge, t_0)
    # the winding's heating over the repeating cycle (first-order model, τ_th as published,
    # else the service's assumed default): x → mean T² of each phase by 1 − e^(−t/τ)
    tau = _row([a.thermal_time_constant_s for a in actuators])
    tau = np.where(np.isnan(tau), DEFAULT_THERMAL_TIME_CONSTANT_S, tau)
    phases = [(t1, accel * accel), (t2, tl * tl + 0 * ja), (t3, decel * decel), (tp, 0 * j)]
    gains = [-np.expm1(-t / tau) for t, _ in phases]
    x = np.zeros(rms.shape)
    kept = np.ones(rms.shape)
    for (_, heat), gain in zip(phases, gains, strict=True):
        x = x + (heat - x) * gain
        kept = kept * (1 - gain)
    x = x / (1 - kept)  # the start that the cycle repeats
    peak = x
    for (_, heat), gain in zip(phases, gains, strict=True):
        x = x + (heat - x) * gain
        peak = np.maximum(peak, x)
    thermal = np.sqrt(peak)

    no_ja, no_t_max, no_n_max = np.isnan(ja), np.isnan(t_max), np.isnan(n_max)
    no_data = [
        no_n_max,
        no_ja,
        no_ja | no_t_max,
        no_ja | no_t_max,
        no_ja | (~zoned & (np.isnan(t_0) | np.isnan(speed_bound))),
        no_ja | (~zoned & (np.isnan(t_0) | np.isnan(speed_bound))),
    ]
    values = [n2 + 0 * n_max, jl + 0 * ja, accel, -decel, rms, thermal]
    limits = [n_max, 3 * ja, t_max, t_max, limit, limit]
    exceeded = [
        n2 > n_max,
        (jl > 3 * ja) & dyn,
        accel > t_max,
        -decel > t_max,
        ~((rms <= limit) & (zoned | (n_av <= speed_bound))),
        ~((thermal <= limit) & (zoned | (n_av <= speed_bound))),
    ]
    fails = np.zeros(rms.shape, dtype=bool)
    missing = np.zeros(rms.shape, dtype=bool)
    overload = np.zeros(rms.shape)
    for lacking, over, value, bound in zip(no_data, exceeded, values, limits, strict=True):
        failed = ~lacking & over
        fails |= failed
        missing |= lacking
        ratio = np.where(np.isnan(bound), np.inf, np.maximum(value / bound, 1.0))
        overload = np.maximum(overload, np.where(failed, ratio, 0.0))
    verdict = np.where(fails, 2, np.where(missing, 1, 0))

    size = np.lexsort(
        (np.nan_to_num(_row([a.inertia_kgm2 for a in actuators])[0], nan=np.inf),
         np.nan_to_num(t_max[0], nan=np.inf))
    )  # fmt: skip
    position = np.empty(len(actuators), dtype=np.intp)
    position[size] = np.arange(len(actuators))
    # verdict, then the nearest miss among the unsuitable, then the smallest actuator
    ranked = np.lexsort((np.broadcast_to(position, verdict.shape), overload, verdict), axis=-1)
    best: npt.NDArray[np.intp] = ranked[:, :top]
    return best


def agreement(
    actuators: Sequence[Actuator], reference: npt.NDArray[np.intp], service: Sequence[Sequence[str]]
) -> float:
    """Share of cases whose best actuators the reference and the service name alike."""
    names = np.asarray([a.model for a in actuators])
    same = sum(
        list(names[row]) == list(models) for row, models in zip(reference, service, strict=True)
    )
    return same / len(service)
