"""Several axes on one DC bus (sizing/bus.py): analytic cases, opposition, conservation."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.bus import (
    COPPER_LOSS_FACTOR,
    AxisPower,
    Motor,
    axis_power,
    braking_resistor,
    capacitor,
    machine_bus,
)
from actuator_selection.sizing.motion import Motion, Segment, profile_of, trapezoid

TWO_PI = 2.0 * math.pi


def _hand_axis() -> tuple[Motor, Motion]:
    """J = J_A + J_L = 1 kgm², T_F = 2 Nm, 60 rpm (ω = 2π rad/s), t_1 = t_3 = 0.5 s,
    t_2 = 1 s, t_p = 1 s; α = 4π rad/s²; k_T = 10 Nm/A, R_LL = 2 Ω, no no-load current."""
    motor = Motor(
        inertia_kgm2=0.1,
        torque_constant_nm_per_a=10.0,
        resistance_line_ohm=2.0,
        no_load_starting_current_a=0.0,
        no_load_current_constant_a_per_rpm=0.0,
    )
    motion = trapezoid(
        speed_rpm=60,
        accel_s=0.5,
        constant_s=1.0,
        decel_s=0.5,
        pause_s=1.0,
        load=AxisLoad(inertia_kgm2=0.9, friction_torque_nm=2.0),
    )
    return motor, motion


def test_an_analytic_case_by_hand() -> None:
    motor, motion = _hand_axis()
    power = axis_power(profile_of(motion), motor)
    energies = power.energies_j()
    alpha, omega = 4 * math.pi, TWO_PI
    t_acc, t_dec = 2 + alpha, 2 - alpha  # Eq. 514.1 with J = 1 kgm²
    # ∫T·ω over a ramp of 0.5 s from 0 to ω: T·ω·0.5/2
    mech = t_acc * omega * 0.25 + 2 * omega * 1.0 + t_dec * omega * 0.25
    assert energies["mechanical"] == pytest.approx(mech, rel=1e-12)
    assert mech == pytest.approx(2.0 * 3 * math.pi)  # friction × angle: inertia returns
    copper = (
        COPPER_LOSS_FACTOR
        * 2.0
        * ((t_acc / 10) ** 2 * 0.5 + (2 / 10) ** 2 + (t_dec / 10) ** 2 * 0.5)
    )
    assert energies["copper"] == pytest.approx(copper, rel=1e-12)
    assert energies["no_load"] == 0.0
    f = power.figures()
    # peak at the end of the ramp up: T·ω + 1.5·R·(T/k_T)²
    assert f.peak_w == pytest.approx(t_acc * omega + 3.0 * (t_acc / 10) ** 2, rel=1e-12)
    # braking: P(τ) = T_3·ω(τ) + 3·(T_3/10)², most negative at the start of the ramp down
    assert f.regen_peak_w == pytest.approx(-(t_dec * omega + 3.0 * (t_dec / 10) ** 2), rel=1e-12)
    p_cu = 3.0 * (t_dec / 10) ** 2
    # ω falls linearly from 2π over 0.5 s; P < 0 while ω(τ) > −p_cu/T_3
    omega_zero = -p_cu / t_dec
    tau_zero = 0.5 * (1 - omega_zero / omega)
    regen = -(t_dec * (omega + omega_zero) / 2 * tau_zero + p_cu * tau_zero)
    assert f.regen_energy_j == pytest.approx(regen, rel=1e-12)
    assert f.regen_pulses == 1
    assert f.regen_pulse_energy_j == pytest.approx(regen, rel=1e-12)
    assert f.cycle_s == 3.0
    assert f.mean_w == pytest.approx((mech + copper) / 3.0, rel=1e-12)


def _busy_axis(gravity: float, efficiency: float) -> tuple[Motor, Motion]:
    motor = Motor(
        inertia_kgm2=0.05,
        torque_constant_nm_per_a=26.0,
        resistance_line_ohm=3.7,
        no_load_starting_current_a=0.19,
        no_load_current_constant_a_per_rpm=2e-3,
    )
    load = AxisLoad(
        inertia_kgm2=0.4, friction_torque_nm=3.0, gravity_torque_nm=gravity, efficiency=efficiency
    )
    motion = Motion(
        segments=(
            Segment(duration_s=0.3, start_rpm=0, end_rpm=50, jerk_share=0.6),
            Segment(duration_s=0.4, start_rpm=50, end_rpm=50, process_torque_nm=4.0),
            Segment(duration_s=0.2, start_rpm=50, end_rpm=0, jerk_share=1.0),
            Segment(duration_s=0.25, start_rpm=0, end_rpm=0),
            Segment(duration_s=0.35, start_rpm=0, end_rpm=-40),
            Segment(duration_s=0.35, start_rpm=-40, end_rpm=0, jerk_share=0.3),
            Segment(duration_s=0.15, start_rpm=0, end_rpm=0),
        ),
        load=load,
    )
    return motor, motion


def _fine_integral(power: AxisPower, what: str, n: int = 400_001) -> float:
    """∫ of one power on a fine grid (trapezoid rule): independent of the exact integration."""
    total = 0.0
    for p in power.pieces:
        if p.duration_s <= 0:
            continue
        x = np.linspace(0.0, p.duration_s, n // len(power.pieces))
        total += float(np.trapezoid(getattr(p, what)(x), x))
    return total


def test_energy_is_conserved_over_a_cycle() -> None:
    """Electrical in = mechanical out + losses, to 0.1 %, for a cycle with S-curves,
    reversals, a process torque, gravity and a mechanism efficiency; each term checked
    against a fine-grid integral of its own, and the bus's net energy against the axis's."""
    for gravity, eta in ((0.0, 1.0), (6.0, 0.85)):
        motor, motion = _busy_axis(gravity, eta)
        power = axis_power(profile_of(motion), motor)
        e = power.energies_j()
        for what in ("mechanical", "no_load", "copper", "electrical"):
            assert e[what] == pytest.approx(_fine_integral(power, what), rel=1e-6, abs=1e-9)
        assert e["no_load"] > 0
        assert e["copper"] > 0
        bus = machine_bus([power], [0.0])
        net = bus.figures.mean_w * bus.cycle_s
        assert net == pytest.approx(e["mechanical"] + e["no_load"] + e["copper"], rel=1e-3)
        assert bus.figures.energy_in_j - bus.figures.regen_energy_j == pytest.approx(net, rel=1e-9)


def test_with_eta_one_and_no_gravity_mechanical_energy_is_the_friction_and_process_work() -> None:
    motor, motion = _busy_axis(0.0, 1.0)
    power = axis_power(profile_of(motion), motor)
    angle_1 = TWO_PI * 50 / 60 * (0.3 / 2 + 0.4 + 0.2 / 2)  # ramps at their mean speed
    angle_2 = TWO_PI * 40 / 60 * (0.35 / 2 + 0.35 / 2)
    work = 3.0 * (angle_1 + angle_2) + 4.0 * TWO_PI * 50 / 60 * 0.4
    assert power.energies_j()["mechanical"] == pytest.approx(work, rel=1e-9)


def _opposed() -> tuple[Motor, Motion, Motion]:
    """Two axes with the same speeds, B's process torque set so that its torque is A's
    negated in every segment: A accelerates while B, pushed by its process, regenerates the
    same power, and A brakes while B motors."""
    motor = Motor(
        inertia_kgm2=0.1,
        torque_constant_nm_per_a=10.0,
        resistance_line_ohm=2.0,
        no_load_starting_current_a=0.1,
        no_load_current_constant_a_per_rpm=1e-3,
    )
    j = 0.1 + 0.9
    alpha = TWO_PI * 60 / 60 / 0.5
    speeds = ((0, 60, 0.5), (60, 60, 1.0), (60, 0, 0.5), (0, 0, 1.0))
    a_tp = (0.0, 5.0, 0.0, 0.0)
    accel = (alpha, 0.0, -alpha, 0.0)
    load = AxisLoad(inertia_kgm2=0.9, friction_torque_nm=0.0)
    a = Motion(
        segments=tuple(
            Segment(duration_s=t, start_rpm=n0, end_rpm=n1, process_torque_nm=tp)
            for (n0, n1, t), tp in zip(speeds, a_tp, strict=True)
        ),
        load=load,
    )
    b = Motion(
        segments=tuple(
            Segment(duration_s=t, start_rpm=n0, end_rpm=n1, process_torque_nm=-2 * j * al - tp)
            for (n0, n1, t), tp, al in zip(speeds, a_tp, accel, strict=True)
        ),
        load=load,
    )
    return motor, a, b


def test_two_axes_in_exact_opposition_put_no_regenerative_energy_on_the_bus() -> None:
    motor, a, b = _opposed()
    pa, pb = axis_power(profile_of(a), motor), axis_power(profile_of(b), motor)
    # each alone regenerates: the test can fail
    assert pa.figures().regen_energy_j > 1.0
    assert pb.figures().regen_energy_j > 1.0
    bus = machine_bus([pa, pb], [0.0, 0.0])
    for s in bus.stretches:  # the mechanical powers cancel: only the losses remain
        x = np.linspace(0, s.duration_s, 7)
        assert np.all(s.total(x) >= 0)
    assert bus.figures.regen_energy_j == 0.0
    assert bus.figures.regen_peak_w == 0.0
    assert bus.figures.regen_pulses == 0
    losses = sum(p.energies_j()["copper"] + p.energies_j()["no_load"] for p in (pa, pb))
    assert bus.figures.mean_w * bus.cycle_s == pytest.approx(losses, rel=1e-9)
    # the same with B's cycle started one segment later and offset back by its length
    b_rotated = Motion(segments=(*b.segments[1:], b.segments[0]), load=b.load)
    rotated = machine_bus([pa, axis_power(profile_of(b_rotated), motor)], [0.0, 0.5])
    assert rotated.figures.regen_energy_j == 0.0
    assert rotated.figures.mean_w == pytest.approx(bus.figures.mean_w, rel=1e-12)
    # out of phase, they do regenerate
    assert machine_bus([pa, pb], [0.0, 1.5]).figures.regen_energy_j > 0


def test_one_axis_alone_is_its_own_bus() -> None:
    motor, motion = _busy_axis(6.0, 0.85)
    power = axis_power(profile_of(motion), motor)
    own = power.figures()
    bus = machine_bus([power], [0.4])  # an offset moves the cycle, not its figures
    for name in ("peak_w", "regen_peak_w", "least_w"):
        assert getattr(bus.figures, name) == pytest.approx(getattr(own, name), rel=1e-9)
    for name in ("mean_w", "regen_energy_j", "energy_in_j", "regen_pulse_energy_j"):
        assert getattr(bus.figures, name) == pytest.approx(getattr(own, name), rel=1e-9)
    assert bus.figures.regen_pulses == own.regen_pulses


def test_random_phasing_worst_case_bounds_every_alignment_and_is_reached() -> None:
    motor, a, b = _opposed()
    pa, pb = axis_power(profile_of(a), motor), axis_power(profile_of(b), motor)
    worst = machine_bus([pa, pb], [0.0, 0.0]).phasing
    assert worst.worst_peak_w == pytest.approx(pa.figures().peak_w + pb.figures().peak_w)
    peaks = [machine_bus([pa, pb], [0.0, o]).figures.peak_w for o in np.linspace(0, 3, 61)]
    assert max(peaks) <= worst.worst_peak_w * (1 + 1e-12)
    # two copies of A in phase reach it (A's peak is a left limit, B's a right one: their
    # sum never reaches Σ max, which is an upper bound)
    twice = machine_bus([pa, pa], [0.0, 0.0])
    assert twice.figures.peak_w == pytest.approx(twice.phasing.worst_peak_w, rel=1e-12)
    assert worst.std_w > 0
    assert worst.statistical_peak_w == pytest.approx(worst.mean_w + 3 * worst.std_w)
    assert worst.statistical_peak_w < worst.worst_peak_w


def test_motor_of_a_catalogue_actuator() -> None:
    """R per phase becomes 2·R_ph line-to-line (star); K_INL at 80 °C where published."""
    from actuator_selection.catalogue.actuators import Actuator
    from actuator_selection.errors import MissingDataError
    from actuator_selection.sizing.bus import motor_of

    a = Actuator(
        model="X-1",
        family="X",
        gear_ratio=50.0,
        max_torque_nm=10.0,
        inertia_kgm2=0.2,
        torque_constant_nm_per_a=26.0,
        resistance_phase_ohm=2.6,
        no_load_starting_current_a=0.19,
        no_load_current_constant_30c_a_per_rpm=6e-3,
        no_load_current_constant_80c_a_per_rpm=2e-3,
    )
    m = motor_of(a)
    assert m.resistance_line_ohm == 5.2
    assert m.no_load_current_constant_a_per_rpm == 2e-3
    with pytest.raises(MissingDataError):
        motor_of(dataclasses.replace(a, inertia_kgm2=None))


def test_capacitor_and_braking_resistor() -> None:
    motor, motion = _hand_axis()
    bus = machine_bus([axis_power(profile_of(motion), motor)], [0.0])
    f = bus.figures
    no_data = capacitor(
        capacitance_f=None, nominal_voltage_v=320, max_voltage_v=None, pulse_energy_j=1.0
    )
    assert no_data.energy_j is None
    assert no_data.absorbs_every_pulse is None
    cap = capacitor(
        capacitance_f=1e-3,
        nominal_voltage_v=320,
        max_voltage_v=390,
        pulse_energy_j=f.regen_pulse_energy_j,
    )
    assert cap.energy_j == pytest.approx(0.5 * 1e-3 * (390**2 - 320**2))
    r = braking_resistor(f, no_data, chopper_voltage_v=390)
    assert r.needed
    assert r.peak_power_w == f.regen_peak_w
    assert r.continuous_power_w == pytest.approx(f.regen_energy_j / 3.0)
    assert r.max_resistance_ohm == pytest.approx(390**2 / f.regen_peak_w)
    big = capacitor(
        capacitance_f=1.0,
        nominal_voltage_v=320,
        max_voltage_v=390,
        pulse_energy_j=f.regen_pulse_energy_j,
    )
    assert big.absorbs_every_pulse
    # a capacitance that takes part of the pulse leaves the rest to the resistor
    part = capacitor(
        capacitance_f=1e-4,
        nominal_voltage_v=320,
        max_voltage_v=390,
        pulse_energy_j=f.regen_pulse_energy_j,
    )
    assert part.energy_j is not None
    assert 0 < part.energy_j < f.regen_pulse_energy_j
    rest = braking_resistor(f, part, chopper_voltage_v=390)
    assert rest.pulse_energy_j == pytest.approx(f.regen_pulse_energy_j - part.energy_j)
    assert rest.continuous_power_w == pytest.approx((f.regen_energy_j - part.energy_j) / 3.0)
    assert not braking_resistor(f, big, chopper_voltage_v=None).needed
    assert braking_resistor(f, no_data, chopper_voltage_v=None).max_resistance_ohm is None
