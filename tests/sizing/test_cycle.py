"""Eq. 514.1–514.4 against the chapter's worked example and first principles."""

from __future__ import annotations

import math

import pytest

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.cycle import (
    Load,
    SpeedPattern,
    acceleration_torque_nm,
    cycle_torques,
    duty_cycle_percent,
    mean_speed_rpm,
)

# Table 516.1 and Table 516.3 (FHA-25C-50-L).
EXAMPLE = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
EXAMPLE_LOAD = Load(torque_nm=5, inertia_kgm2=1.3)
J_A = 0.86


def test_worked_example_matches_chapter() -> None:
    """The chapter prints T_1 ≈ 95 Nm, T_3 ≈ −85 Nm, T_rms ≈ 35 Nm, n_av ≈ 6 rpm, ED ≈ 23 %."""
    t = cycle_torques(pattern=EXAMPLE, load=EXAMPLE_LOAD, actuator_inertia_kgm2=J_A)
    assert t.accel_torque_nm == pytest.approx(95.5, abs=0.05)
    assert t.constant_torque_nm == 5
    assert t.decel_torque_nm == pytest.approx(-85.5, abs=0.05)
    assert t.rms_torque_nm == pytest.approx(35.6, abs=0.05)
    assert mean_speed_rpm(EXAMPLE) == pytest.approx(6.15, abs=0.005)
    assert duty_cycle_percent(EXAMPLE) == pytest.approx(23.1, abs=0.05)


def test_worked_example_by_hand() -> None:
    """Each term computed by hand: 2π/60 · 2.16 kgm² · 40 rpm / 0.1 s = 90.4779 Nm."""
    inertia_torque = 2 * math.pi / 60 * (0.86 + 1.3) * 40 / 0.1
    assert inertia_torque == pytest.approx(90.4779, abs=1e-4)
    t = cycle_torques(pattern=EXAMPLE, load=EXAMPLE_LOAD, actuator_inertia_kgm2=J_A)
    assert t.accel_torque_nm == pytest.approx(5 + inertia_torque, rel=1e-12)
    # Corrected third line of Eq. 514.1: T_3 = T_L − (T_1 − T_L).
    assert t.decel_torque_nm == pytest.approx(5 - (t.accel_torque_nm - 5), rel=1e-12)
    assert mean_speed_rpm(EXAMPLE) == pytest.approx(8 / 1.3, rel=1e-12)
    assert duty_cycle_percent(EXAMPLE) == pytest.approx(30 / 1.3, rel=1e-12)


def _numeric_rms(pattern: SpeedPattern, t1: float, t2: float, t3: float, steps: int) -> float:
    """RMS of the piecewise-constant torque of Fig. 516.2 by midpoint quadrature."""
    total = pattern.cycle_s
    dt = total / steps
    acc = 0.0
    for k in range(steps):
        t = (k + 0.5) * dt
        if t < pattern.accel_s:
            torque = t1
        elif t < pattern.accel_s + pattern.constant_s:
            torque = t2
        elif t < pattern.moving_s:
            torque = t3
        else:
            torque = 0.0
        acc += torque**2 * dt
    return math.sqrt(acc / total)


def _numeric_mean_speed(pattern: SpeedPattern, steps: int) -> float:
    """Mean of the trapezoidal speed profile by midpoint quadrature."""
    dt = pattern.cycle_s / steps
    acc = 0.0
    for k in range(steps):
        t = (k + 0.5) * dt
        if t < pattern.accel_s:
            n = pattern.speed_rpm * t / pattern.accel_s
        elif t < pattern.accel_s + pattern.constant_s:
            n = pattern.speed_rpm
        elif t < pattern.moving_s:
            n = pattern.speed_rpm * (pattern.moving_s - t) / pattern.decel_s
        else:
            n = 0.0
        acc += n * dt
    return acc / pattern.cycle_s


@pytest.mark.parametrize(
    "pattern",
    [
        EXAMPLE,
        SpeedPattern(speed_rpm=60, accel_s=0.2, constant_s=0.0, decel_s=0.2, pause_s=0.6),
        SpeedPattern(speed_rpm=25, accel_s=0.05, constant_s=1.5, decel_s=0.3, pause_s=0.0),
    ],
)
def test_rms_and_mean_speed_match_quadrature(pattern: SpeedPattern) -> None:
    """Eq. 514.2 and 514.3 equal the time averages of the profiles of Fig. 516.2."""
    t = cycle_torques(pattern=pattern, load=EXAMPLE_LOAD, actuator_inertia_kgm2=J_A)
    assert t.constant_torque_nm is not None  # the trapezoid always has its run at n_2
    numeric = _numeric_rms(
        pattern, t.accel_torque_nm, t.constant_torque_nm, t.decel_torque_nm, steps=130_000
    )
    assert t.rms_torque_nm == pytest.approx(numeric, rel=1e-3)
    assert mean_speed_rpm(pattern) == pytest.approx(_numeric_mean_speed(pattern, 130_000), rel=1e-4)


def test_triangular_profile_without_load_torque() -> None:
    """t_2 = 0, T_L = 0: ±J·ω/t for half the motion each, so T_rms = J·ω/t·√(ED)."""
    pattern = SpeedPattern(speed_rpm=30, accel_s=0.5, constant_s=0, decel_s=0.5, pause_s=1.0)
    j_total = 0.5 + 1.5
    alpha = 30 * 2 * math.pi / 60 / 0.5  # rad/s²
    t = cycle_torques(
        pattern=pattern, load=Load(torque_nm=0, inertia_kgm2=1.5), actuator_inertia_kgm2=0.5
    )
    assert t.accel_torque_nm == pytest.approx(j_total * alpha, rel=1e-12)
    assert t.decel_torque_nm == pytest.approx(-j_total * alpha, rel=1e-12)
    assert t.rms_torque_nm == pytest.approx(j_total * alpha * math.sqrt(0.5), rel=1e-12)
    # Half the peak speed on average while moving, moving half the time.
    assert mean_speed_rpm(pattern) == pytest.approx(30 / 2 * 0.5, rel=1e-12)
    assert duty_cycle_percent(pattern) == pytest.approx(50.0, rel=1e-12)


def test_constant_speed_only_load_torque() -> None:
    """No inertia: every torque is T_L, and T_rms = T_L·√(ED)."""
    pattern = SpeedPattern(speed_rpm=10, accel_s=0.1, constant_s=0.8, decel_s=0.1, pause_s=1.0)
    t = cycle_torques(
        pattern=pattern, load=Load(torque_nm=12, inertia_kgm2=0), actuator_inertia_kgm2=0
    )
    assert (t.accel_torque_nm, t.constant_torque_nm, t.decel_torque_nm) == (12, 12, 12)
    assert t.rms_torque_nm == pytest.approx(12 * math.sqrt(0.5), rel=1e-12)


def test_asymmetric_braking_uses_deceleration_time() -> None:
    """With t_3 = 2·t_1 the braking inertia torque halves; the chapter's form assumes t_3 = t_1."""
    pattern = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.2, pause_s=1.0)
    t = cycle_torques(pattern=pattern, load=EXAMPLE_LOAD, actuator_inertia_kgm2=J_A)
    inertia_torque = 2 * math.pi / 60 * 2.16 * 40
    assert t.accel_torque_nm == pytest.approx(5 + inertia_torque / 0.1)
    assert t.decel_torque_nm == pytest.approx(5 - inertia_torque / 0.2)
    # Energy check: the braking impulse (T_L − T_3)·t_3 equals the angular momentum J·ω.
    omega = 40 * 2 * math.pi / 60
    assert (5 - t.decel_torque_nm) * 0.2 == pytest.approx(2.16 * omega)


def test_acceleration_torque_scales_with_speed_and_time() -> None:
    base = acceleration_torque_nm(
        load_torque_nm=0, actuator_inertia_kgm2=1, load_inertia_kgm2=1, speed_rpm=60, time_s=1
    )
    assert base == pytest.approx(2 * 2 * math.pi)  # J = 2 kgm², α = 2π rad/s²
    doubled = acceleration_torque_nm(
        load_torque_nm=0, actuator_inertia_kgm2=1, load_inertia_kgm2=1, speed_rpm=120, time_s=1
    )
    assert doubled == pytest.approx(2 * base)


@pytest.mark.parametrize(
    ("field", "kwargs"),
    [
        ("speed_rpm", {"speed_rpm": 0}),
        ("speed_rpm", {"speed_rpm": -1}),
        ("accel_s", {"accel_s": 0}),
        ("decel_s", {"decel_s": -0.1}),
        ("constant_s", {"constant_s": -1}),
        ("pause_s", {"pause_s": -1}),
        ("accel_s", {"accel_s": math.nan}),
        ("pause_s", {"pause_s": math.inf}),
    ],
)
def test_speed_pattern_rejects_bad_values(field: str, kwargs: dict[str, float]) -> None:
    values = {"speed_rpm": 40.0, "accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0}
    values.update(kwargs)
    with pytest.raises(InvalidInputError) as caught:
        SpeedPattern(**values)
    assert caught.value.field == field


@pytest.mark.parametrize(
    ("field", "torque", "inertia"),
    [("torque_nm", -1.0, 1.0), ("inertia_kgm2", 1.0, -0.5), ("torque_nm", math.nan, 1.0)],
)
def test_load_rejects_bad_values(field: str, torque: float, inertia: float) -> None:
    with pytest.raises(InvalidInputError) as caught:
        Load(torque_nm=torque, inertia_kgm2=inertia)
    assert caught.value.field == field


def test_rms_overflow_is_a_domain_error_not_overflow_or_infinity() -> None:
    """T_L ≈ 1.6e152 (η = 1e-152), day-long phases: T_1²·t overflows; never ∞ or a 500."""
    pattern = SpeedPattern(
        speed_rpm=40, accel_s=86_400, constant_s=86_400, decel_s=86_400, pause_s=0
    )
    load = Load(torque_nm=1.56e152, inertia_kgm2=0.0)
    with pytest.raises(InvalidInputError) as caught:
        cycle_torques(pattern=pattern, load=load, actuator_inertia_kgm2=0.86)
    assert caught.value.field == "load"
    assert "T_rms" in caught.value.message
    # 1e200 squared raises OverflowError inside float ** : the same domain error.
    with pytest.raises(InvalidInputError, match="T_rms"):
        cycle_torques(
            pattern=pattern,
            load=Load(torque_nm=1e200, inertia_kgm2=0.0),
            actuator_inertia_kgm2=0.86,
        )


def test_torque_overflow_is_a_domain_error() -> None:
    pattern = SpeedPattern(speed_rpm=1e300, accel_s=1e-10, constant_s=0, decel_s=1e-10, pause_s=0)
    with pytest.raises(InvalidInputError, match="T_1"):
        cycle_torques(
            pattern=pattern, load=Load(torque_nm=0, inertia_kgm2=1e10), actuator_inertia_kgm2=1.0
        )


def test_mean_speed_overflow_is_a_domain_error() -> None:
    pattern = SpeedPattern(speed_rpm=1e308, accel_s=10, constant_s=10, decel_s=10, pause_s=0)
    with pytest.raises(InvalidInputError, match="n_av"):
        mean_speed_rpm(pattern)
