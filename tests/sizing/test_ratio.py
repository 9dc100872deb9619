"""The ratio study (issue 31 part 1) against the analytic answers of a pure inertia load
(Giberti et al.'s i* = √(J_L/J_A), the peak-torque roots of Van de Straete et al.) and a
friction-only load."""

from __future__ import annotations

import math

import pytest

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import evaluate
from actuator_selection.sizing.mechanisms import Transmission
from actuator_selection.sizing.ratio import inertia_matched_ratio, ratio_study
from actuator_selection.sizing.ratio_cases import geared
from actuator_selection.sizing.selection import Verdict

RPM = 2 * math.pi / 60

J_A, J_L = 0.02, 0.5
N_L, T_1 = 60.0, 0.1  # load speed [rpm], ramp [s]
EPS = N_L * RPM / T_1  # load acceleration ε_L [rad/s²]
T_STAR = 2 * math.sqrt(J_A * J_L) * EPS  # the least peak torque, at i*
T_MAX = 1.1 * T_STAR


def _app(torque_nm: float, inertia_kgm2: float, speed_rpm: float, accel_s: float) -> Application:
    pattern = SpeedPattern(
        speed_rpm=speed_rpm, accel_s=accel_s, constant_s=0.2, decel_s=accel_s, pause_s=1.0
    )
    return Application(pattern=pattern, load=Load(torque_nm=torque_nm, inertia_kgm2=inertia_kgm2))


def _vary(app: Application):  # type: ignore[no-untyped-def]
    return lambda i: geared(app, Transmission(ratio=i))


def _roots(a: float, b: float, c: float) -> tuple[float, float]:
    root = math.sqrt(b * b - 4 * a * c)
    return (b - root) / (2 * a), (b + root) / (2 * a)


def test_pure_inertia_best_ratio_is_the_inertia_match_and_the_ends_the_torque_roots() -> None:
    actuator = Actuator(
        model="A",
        family="F",
        gear_ratio=50,
        max_torque_nm=T_MAX,
        max_speed_rpm=5000,
        inertia_kgm2=J_A,
    )
    (result,) = ratio_study([actuator], _vary(_app(0.0, J_L, N_L, T_1)), 1, 20)
    i_star = inertia_matched_ratio(J_L, J_A)
    assert i_star == pytest.approx(5.0)
    assert result.best == pytest.approx(i_star, rel=2e-3)
    assert result.best_utilisation == pytest.approx(T_STAR / T_MAX, rel=2e-5)
    # T(i) = (J_A·i + J_L/i)·ε ≤ T_max: J_A·ε·i² − T_max·i + J_L·ε ≤ 0
    low, high = _roots(J_A * EPS, T_MAX, J_L * EPS)
    (interval,) = result.intervals
    assert interval.low == pytest.approx(low, rel=2e-5)
    assert interval.high == pytest.approx(high, rel=2e-5)
    assert interval.low_binding == interval.high_binding == ("peak_torque", "decel_torque")
    assert result.best_binding == "peak_torque"


def test_friction_only_load_between_the_torque_root_and_the_speed_limit() -> None:
    j_a, friction, n_max, t_max = 1e-4, 40.0, 3000.0, 10.0
    actuator = Actuator(
        model="B",
        family="F",
        gear_ratio=50,
        max_torque_nm=t_max,
        max_speed_rpm=n_max,
        inertia_kgm2=j_a,
    )
    (result,) = ratio_study([actuator], _vary(_app(friction, 0.0, 300.0, 1.0)), 1, 20)
    eps = 300.0 * RPM / 1.0
    # T_1 = J_A·i·ε + T_F/i ≤ T_max and n = i·300 ≤ 3000
    low, _ = _roots(j_a * eps, t_max, friction)
    (interval,) = result.intervals
    assert interval.low == pytest.approx(low, rel=2e-5)
    assert interval.high == pytest.approx(n_max / 300.0, rel=2e-5)
    assert interval.high_binding == ("max_speed",)


def test_the_ends_re_checked_one_by_one() -> None:
    """Just inside each end no check fails, just outside one does (the engine's 1 × 1)."""
    actuator = Actuator(
        model="A",
        family="F",
        gear_ratio=50,
        max_torque_nm=T_MAX,
        max_speed_rpm=5000,
        inertia_kgm2=J_A,
    )
    vary = _vary(_app(0.0, J_L, N_L, T_1))
    (result,) = ratio_study([actuator], vary, 1, 20)
    (interval,) = result.intervals
    for end, outside in ((interval.low, 1 - 1e-4), (interval.high, 1 + 1e-4)):
        assert evaluate(actuator, vary(end)).verdict is not Verdict.UNSUITABLE
        assert evaluate(actuator, vary(end * outside)).verdict is Verdict.UNSUITABLE


def test_several_actuators_side_by_side() -> None:
    """The one with no fitting ratio gets none; a ratio of 1 is the load case itself."""
    fits = Actuator(
        model="A",
        family="F",
        gear_ratio=50,
        max_torque_nm=T_MAX,
        max_speed_rpm=5000,
        inertia_kgm2=J_A,
    )
    weak = Actuator(
        model="W",
        family="F",
        gear_ratio=50,
        max_torque_nm=0.5 * T_STAR,
        max_speed_rpm=5000,
        inertia_kgm2=J_A,
    )
    app = _app(0.0, J_L, N_L, T_1)
    a, w = ratio_study([fits, weak], _vary(app), 1, 20)
    assert a.intervals
    assert not w.intervals
    assert w.best is None
    assert w.verdict is None
    assert evaluate(fits, _vary(app)(1.0)).torques == evaluate(fits, app).torques


def test_several_intervals_where_a_check_is_not_monotonic() -> None:
    """A free value on which the speed swings, n = 50 + 40·sin x ≤ 70 rpm: feasible where
    sin x ≤ ½, three intervals in 1…20, each end where sin x = ½."""
    actuator = Actuator(
        model="S",
        family="F",
        gear_ratio=50,
        max_torque_nm=100,
        max_speed_rpm=70,
        inertia_kgm2=J_A,
    )
    (result,) = ratio_study([actuator], lambda x: _app(0.0, 0.0, 50 + 40 * math.sin(x), 0.1), 1, 20)
    expected = [(5, 13), (17, 25), (29, 37)]  # × π/6
    assert len(result.intervals) == 3
    for interval, (low, high) in zip(result.intervals, expected, strict=True):
        assert interval.low == pytest.approx(low * math.pi / 6, rel=2e-5)
        assert interval.high == pytest.approx(high * math.pi / 6, rel=2e-5)
        assert interval.low_binding == interval.high_binding == ("max_speed",)
