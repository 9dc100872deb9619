"""A plain numpy computation of a batch's numbers: the reference a batch request is held to.

For every case × actuator: T_1, T_3, T_rms, n_av (Eq. 514.1–514.3), the eight checks'
pass/fail/no-data decisions of every selection (speed, inertia, peak and braking torque,
continuous torque with the current-based edge, the winding's heating peak and its
speed, the drive's voltage), the verdicts, and the best ``top`` actuators of each case
by the service's ranking (verdict, the nearest miss among the unsuitable, then T_max,
J_A, model). It leaves out the lower bounds without J_A (every starter actuator has
J_A). Written the way one would write it by hand with numpy, with none of the service's
rule table, exact-rounding care, JSON or HTTP: what the numbers alone cost here.

:func:`disagreements` counts the cases whose top actuators differ from the service's,
so that the reference is known to compute the same thing. The actuators are the
service's catalogue snapshot (:func:`snapshot_actuators`), whose ``dc_bus_voltage_v`` is
the best DC bus a controller listed for the actuator (Table 521.1) runs on.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.sizing.selection import Application
from actuator_selection.sizing.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S

FloatArray = npt.NDArray[np.float64]


def _slope(actuator: Actuator) -> float | None:
    """k_T·K_INL [Nm/rpm], K_INL at 80 °C where published, else at 30 °C."""
    k_inl = actuator.no_load_current_constant_80c_a_per_rpm
    if k_inl is None:
        k_inl = actuator.no_load_current_constant_30c_a_per_rpm
    if actuator.torque_constant_nm_per_a is None or k_inl is None:
        return None
    return actuator.torque_constant_nm_per_a * k_inl


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
    # The continuous torque at n_av: the zone's edge; without a zone, where k_T and K_INL
    # are published, the current-based edge T_0 − k_T·K_INL·n_av (≥ 0), else T_0 or the
    # allowable continuous torque.
    slope = _row([_slope(a) for a in actuators])
    stall = _row([a.stall_torque_nm for a in actuators])
    on_current = ~zoned & ~np.isnan(slope) & ~np.isnan(stall)
    falling = np.maximum(stall - slope * n_av, 0.0)
    limit = np.where(zoned, edge, np.where(on_current, falling, t_0))
    zone_end = _row([a.zone.max_speed_rpm if a.zone is not None else None for a in actuators])
    speed_limit = np.where(zoned, zone_end, speed_bound)
    # The winding's heating over the repeating cycle (first-order model, τ_th as published,
    # else the service's assumed default): x → the mean square of each phase's torque, the
    # torque k_T·K_INL·|n̄| of the no-load current added where the heating follows the
    # current; y → each phase's mean |n|. Both start where the cycle repeats.
    tau = _row([a.thermal_time_constant_s for a in actuators])
    tau = np.where(np.isnan(tau), DEFAULT_THERMAL_TIME_CONSTANT_S, tau)
    extra = np.where(on_current, slope, 0.0)
    phases = [
        (t1, np.abs(accel), n2 / 2),
        (t2, np.abs(tl) + 0 * ja, n2),
        (t3, np.abs(decel), n2 / 2),
        (tp, 0 * j, 0 * n2),
    ]
    gains = [-np.expm1(-t / tau) for t, _, _ in phases]
    cycle_gain = -np.expm1(-t0 / tau)
    x = np.zeros(rms.shape)
    y = np.zeros(rms.shape)
    heats = [(torque + extra * speed) ** 2 for _, torque, speed in phases]
    for heat, (_, _, speed), gain in zip(heats, phases, gains, strict=True):
        x = x + (heat - x) * gain
        y = y + (speed - y) * gain
    x, y = x / cycle_gain, y / cycle_gain
    peak, speed_peak = x, y
    for heat, (_, _, speed), gain in zip(heats, phases, gains, strict=True):
        x = x + (heat - x) * gain
        y = y + (speed - y) * gain
        peak, speed_peak = np.maximum(peak, x), np.maximum(speed_peak, y)
    thermal = np.sqrt(peak)
    thermal_speed = np.maximum(speed_peak, n_av)
    heating_limit = np.where(on_current, stall, limit)
    # The voltage the axis needs at n_2 and I_max (Eq. 521.2, ωL·I in quadrature) against
    # U_DC/√2 of the best bus a listed controller shares (the snapshot's dc_bus_voltage_v).
    ratio = _row([a.gear_ratio for a in actuators])
    k_e = _row([a.motor_voltage_constant_v_per_krpm for a in actuators])
    i_max = _row([a.max_current_a for a in actuators])
    r_line = _row([a.resistance_line_ohm for a in actuators])
    l_line = _row([None if a.inductance_line_mh is None else a.inductance_line_mh / 1000
                   for a in actuators])  # fmt: skip
    poles = _row([a.pole_pairs for a in actuators])
    bus = _row([a.dc_bus_voltage_v for a in actuators])
    in_phase = n2 * ratio * (k_e / 1000) + i_max * r_line
    inductive = n2 * ratio * (2 * math.pi / 60) * poles * l_line * i_max
    voltage = np.sqrt(in_phase * in_phase + inductive * inductive)
    no_voltage_data = np.isnan(k_e + i_max + r_line + l_line + poles + bus)

    no_ja, no_t_max, no_n_max = np.isnan(ja), np.isnan(t_max), np.isnan(n_max)
    no_limit = ~zoned & np.isnan(t_0)
    no_data = [
        no_n_max,
        no_ja,
        no_ja | no_t_max,
        no_ja | no_t_max,
        no_ja | no_limit,
        no_ja | no_limit,
        np.broadcast_to(~zoned & np.isnan(speed_bound), rms.shape),
        np.broadcast_to(no_voltage_data, rms.shape),
    ]
    values = [n2 + 0 * n_max, jl + 0 * ja, accel, -decel, rms, thermal, thermal_speed, voltage]
    limits = [n_max, 3 * ja, t_max, t_max, limit, heating_limit, speed_limit, bus / math.sqrt(2)]
    exceeded = [
        n2 > n_max,
        (jl > 3 * ja) & dyn,
        accel > t_max,
        -decel > t_max,
        ~(rms <= limit),
        ~(thermal <= heating_limit),
        ~(thermal_speed <= speed_limit),
        voltage > bus / math.sqrt(2),
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


def disagreements(
    actuators: Sequence[Actuator], reference: npt.NDArray[np.intp], service: Sequence[Sequence[str]]
) -> int:
    """How many cases the reference and the service name different best actuators for."""
    names = np.asarray([a.model for a in actuators])
    return sum(
        list(names[row]) != list(models) for row, models in zip(reference, service, strict=True)
    )


def snapshot_actuators(url: str) -> list[Actuator]:
    """The actuators of the catalogue at ``url`` as the service sizes with them."""
    engine = make_engine(url)
    try:
        with make_session_factory(engine)() as session:
            return list(CatalogueSnapshot.read(session, 0).actuators)
    finally:
        engine.dispose()
