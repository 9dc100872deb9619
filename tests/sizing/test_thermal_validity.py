"""Thermal validity (issue "The checks a sizing engineer signs", item 3): T_rms stands only
for a cycle short against the winding's thermal time constant (check ``thermal_peak``).

Reference values come from the first-order model in closed form, not from the code
under test: a cycle of constant-torque pieces has an exact periodic solution, and a step
from a settled state crosses the limit after Fig. 520.1's overload duration
τ_th·ln((k² − p²)/(k² − 1)) (sizing/thermal, public-catalogue-data.md "Overload
duration").
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable

import numpy as np
import pytest
from tests.oracle.flowchart import operands

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.checks import Check, Operands, Status
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import evaluate_batch
from actuator_selection.sizing.motion import Motion, Segment
from actuator_selection.sizing.selection import Application, Verdict, evaluate
from actuator_selection.sizing.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S, overload_duration_s

# CHA-25A-50 (CHA Engineering Data 1018854 12/2015, CHA-25A table, ratio 50): T_max 98 Nm,
# n_max 112 rpm, J_out 0.97 kgm², T_0 55 Nm; rated motor speed 3500 rpm / 50 = 70 rpm.
CHA_25A_50 = Actuator(
    model="CHA-25A-50",
    family="CHA",
    gear_ratio=50,
    max_torque_nm=98,
    max_speed_rpm=112,
    inertia_kgm2=0.97,
    stall_torque_nm=55,
    rated_speed_rpm=70,
)
T_0 = 55.0
TAU = DEFAULT_THERMAL_TIME_CONSTANT_S


def thermal(actuator: Actuator, app: Application) -> Check:
    return next(c for c in evaluate(actuator, app).checks if c.name == "thermal_peak")


def continuous(actuator: Actuator, app: Application) -> Check:
    return next(c for c in evaluate(actuator, app).checks if c.name == "continuous_duty")


def value(check: Check) -> float:
    """The check's value, which these cases always have."""
    assert check.value is not None
    return check.value


def hold(*steps: tuple[float, float], tau: float | None = None) -> Application:
    """A cycle at standstill: each step holds a torque [Nm] for a time [s] (a process
    torque, so that no inertia enters and every piece's torque is constant)."""
    return Application(
        motion=Motion(
            segments=tuple(
                Segment(duration_s=t, start_rpm=0.0, end_rpm=0.0, process_torque_nm=torque)
                for torque, t in steps
            ),
            load=AxisLoad(inertia_kgm2=0.0, friction_torque_nm=0.0),
        ),
        thermal_time_constant_s=tau,
    )


def periodic_peak(steps: list[tuple[float, float]], tau: float) -> float:
    """Closed form of the first-order model's periodic steady state for constant-torque
    steps: x_0 = Σ_k T_k²·(1 − e^(−t_k/τ))·e^(−(t_{k+1}+…+t_N)/τ) / (1 − e^(−t_0/τ)),
    then x along the steps; the largest x, as a torque."""
    t_0 = sum(t for _, t in steps)
    after = [sum(t for _, t in steps[k + 1 :]) for k in range(len(steps))]
    x = sum(
        torque**2 * (1 - math.exp(-t / tau)) * math.exp(-rest / tau)
        for (torque, t), rest in zip(steps, after, strict=True)
    ) / (1 - math.exp(-t_0 / tau))
    peak = x
    for torque, t in steps:
        x = torque**2 + (x - torque**2) * math.exp(-t / tau)
        peak = max(peak, x)
    return math.sqrt(peak)


def long_trapezoid(pause_s: float, tau: float | None = None) -> Application:
    """The issue's case with the chapter's cycle: 80 Nm (T_L) for an hour at 10 rpm,
    1 s ramps, J_L = 0.5 kgm², then a pause."""
    return Application(
        pattern=SpeedPattern(
            speed_rpm=10, accel_s=1.0, constant_s=3600.0, decel_s=1.0, pause_s=pause_s
        ),
        load=Load(torque_nm=80, inertia_kgm2=0.5),
        thermal_time_constant_s=tau,
    )


# --- the issue's case ---------------------------------------------------------------------


def test_an_hour_at_1_45_t0_then_ten_hours_pause_fails_though_t_rms_passes() -> None:
    """CHA-25A-50 carrying 80 Nm (1.45·T_0) for an hour, then paused for ten hours: T_rms =
    80·√(1/11) ≈ 24 Nm passes continuous_duty; the winding, after an hour at 1.45·T_0
    (6·τ_th), is at 80·√(1 − e^(−6)) ≈ 79.9 Nm of heating: unsuitable."""
    app = long_trapezoid(pause_s=36000.0)
    rms = continuous(CHA_25A_50, app)
    assert rms.status is Status.PASS
    assert rms.value == pytest.approx(80 * math.sqrt(3602 / 39602), rel=2e-3)
    check = thermal(CHA_25A_50, app)
    assert check.status is Status.FAIL
    assert check.limit == T_0
    # The 1 s ramps at 80 ± 1.5 Nm move this by < 0.1 %.
    assert check.value == pytest.approx(80 * math.sqrt(1 - math.exp(-3600 / TAU)), rel=1e-3)
    assert check.approximate  # τ_th assumed, and no zone: the T_0 rectangle
    assert "τ_th = 600 s assumed" in check.message
    assert "not short against τ_th" in check.message
    assert evaluate(CHA_25A_50, app).verdict is Verdict.UNSUITABLE


@pytest.mark.parametrize("minutes", [15, 30, 62])
def test_the_issue_case_fails_for_every_time_constant_the_issue_implies(minutes: int) -> None:
    """Shutdown after 10–40 min at k = 1.45 means τ_th = t/ln(k²/(k² − 1)) ≈ 15–62 min;
    with any of them the hour at 80 Nm heats the winding past T_0."""
    tau = minutes * 60.0
    check = thermal(CHA_25A_50, long_trapezoid(pause_s=36000.0, tau=tau))
    assert check.status is Status.FAIL
    assert check.value == pytest.approx(80 * math.sqrt(1 - math.exp(-3600 / tau)), rel=2e-3)
    assert not check.message.count("assumed")  # the request's τ_th is no assumption


def test_the_issue_case_with_a_ten_minute_pause_fails_on_t_rms_already() -> None:
    """Read as a ten-minute pause, T_rms = 80·√(60/70) ≈ 74 Nm exceeds T_0 by itself; the
    heating check fails too, with the hour's torque."""
    app = long_trapezoid(pause_s=600.0)
    assert continuous(CHA_25A_50, app).status is Status.FAIL
    assert continuous(CHA_25A_50, app).value == pytest.approx(80 * math.sqrt(3602 / 4202), rel=2e-3)
    check = thermal(CHA_25A_50, app)
    assert check.status is Status.FAIL
    assert value(check) > value(continuous(CHA_25A_50, app))


def test_a_time_constant_long_against_the_hour_gives_t_rms_back() -> None:
    """The check's verdict turns on τ_th: with τ_th ≫ 11 h the cycle is short again and the
    peak tends to T_rms."""
    app = long_trapezoid(pause_s=36000.0, tau=1e9)
    check = thermal(CHA_25A_50, app)
    assert check.status is Status.PASS
    rms = continuous(CHA_25A_50, app).value
    assert rms is not None
    assert check.value == pytest.approx(rms, rel=1e-4)


def test_the_same_torque_for_one_second_in_eleven_is_judged_by_t_rms() -> None:
    """80 Nm for 1 s, pause 10 s: T_rms = 80/√11 = 24.12 Nm; t_0 = 11 s is short against
    τ_th, so the check agrees with continuous_duty and its value lies within 0.5 % above
    T_rms (by the closed form: 24.23 Nm)."""
    app = hold((80.0, 1.0), (0.0, 10.0))
    rms = continuous(CHA_25A_50, app)
    check = thermal(CHA_25A_50, app)
    assert rms.value == pytest.approx(80 / math.sqrt(11), rel=1e-12)
    assert (rms.status, check.status) == (Status.PASS, Status.PASS)
    assert value(rms) <= value(check) <= value(rms) * 1.005
    assert check.value == pytest.approx(periodic_peak([(80.0, 1.0), (0.0, 10.0)], TAU), rel=1e-9)
    assert "short against τ_th: T_rms = 24.12 Nm governs" in check.message


# --- the model against closed forms -----------------------------------------------------


@pytest.mark.parametrize(
    "steps",
    [
        [(80.0, 3600.0), (0.0, 36000.0)],
        [(70.0, 1200.0), (20.0, 300.0), (0.0, 2400.0)],
        [(30.0, 0.5), (60.0, 45.0), (-40.0, 900.0), (0.0, 5.0)],
    ],
)
@pytest.mark.parametrize("tau", [60.0, 600.0, 3600.0])
def test_constant_torque_steps_match_the_closed_form(
    steps: list[tuple[float, float]], tau: float
) -> None:
    check = thermal(CHA_25A_50, hold(*steps, tau=tau))
    assert check.value == pytest.approx(periodic_peak(steps, tau), rel=1e-10)


@pytest.mark.parametrize("k", [1.2, 1.45, 2.0, 3.0])
@pytest.mark.parametrize("preload", [0.0, 0.5, 0.9])
def test_a_step_reaches_the_limit_after_the_overload_duration_of_fig_520_1(
    k: float, preload: float
) -> None:
    """From a state settled at p·T_0 (100·τ_th), a step to k·T_0 held for
    τ_th·ln((k² − p²)/(k² − 1)) (thermal.overload_duration_s, Fig. 520.1's model) brings
    the heating to T_0 exactly; 1 % shorter passes, 1 % longer fails."""
    tau = 900.0
    t = overload_duration_s(overload_factor=k, thermal_time_constant_s=tau, preload_factor=preload)
    assert t is not None

    def check(duration: float) -> Check:
        return thermal(CHA_25A_50, hold((preload * T_0, 100 * tau), (k * T_0, duration), tau=tau))

    assert check(t).value == pytest.approx(T_0, rel=1e-9)
    assert check(0.99 * t).status is Status.PASS
    assert check(1.01 * t).status is Status.FAIL


def test_a_single_step_response_in_closed_form() -> None:
    """One step from cold: after t at k·T_0 the heating is k·T_0·√(1 − e^(−t/τ_th))
    (x = T²·(1 − e^(−t/τ)), the first-order step response), here with the pause so long
    that each cycle starts cold."""
    tau, k = 600.0, 1.45
    for t in (60.0, 300.0, 600.0, 1800.0):
        check = thermal(CHA_25A_50, hold((k * T_0, t), (0.0, 200 * tau), tau=tau))
        assert check.value == pytest.approx(k * T_0 * math.sqrt(1 - math.exp(-t / tau)), rel=1e-12)


def test_the_short_cycle_limit_is_t_rms() -> None:
    """The worked example's cycle (t_0 = 1.3 s): the heating peak exceeds T_rms by an amount
    proportional to t_0/τ_th (first order), and equals it within 1e-6 at τ_th = 10⁶·t_0."""
    cha_like = dataclasses.replace(CHA_25A_50, inertia_kgm2=0.86, stall_torque_nm=40)
    pattern = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
    load = Load(torque_nm=5, inertia_kgm2=1.3)

    def excess(tau: float) -> float:
        app = Application(pattern=pattern, load=load, thermal_time_constant_s=tau)
        peak, rms = thermal(cha_like, app).value, continuous(cha_like, app).value
        assert peak is not None
        assert rms is not None
        assert peak >= rms
        return (peak - rms) / rms

    assert excess(1.3e6) < 1e-6
    assert excess(600.0) / excess(6000.0) == pytest.approx(10.0, rel=0.01)
    assert excess(600.0) < 1e-3


def test_a_smaller_time_constant_is_the_safe_side() -> None:
    """The heating peak never falls as τ_th shrinks (so an assumed τ_th on the short side
    errs towards failing), over cycles short and long against it."""
    apps: list[Callable[[float], Application]] = [
        lambda tau: long_trapezoid(pause_s=36000.0, tau=tau),
        lambda tau: hold((80.0, 1.0), (0.0, 10.0), tau=tau),
        lambda tau: hold((30.0, 0.5), (60.0, 45.0), (-40.0, 900.0), (0.0, 5.0), tau=tau),
    ]
    taus = [30.0, 60.0, 120.0, 300.0, 600.0, 1200.0, 3600.0, 36000.0]
    for make in apps:
        peaks = [value(thermal(CHA_25A_50, make(tau))) for tau in taus]
        assert all(a >= b for a, b in itertools.pairwise(peaks))


def test_the_default_leaves_a_one_minute_cycle_to_t_rms_within_three_percent() -> None:
    """The default τ_th = 600 s is ten times the chapter's one-minute duty cycle
    ("ED = 1 min.", Fig. 517.1): any on/off share of a 60 s cycle peaks at most
    √(0.1/(1 − e^(−0.1))) − 1 = 2.5 % above T_rms."""
    for share in (0.01, 0.1, 0.3, 0.5, 0.9):
        app = hold((50.0, 60.0 * share), (0.0, 60.0 * (1 - share)))
        peak, rms = thermal(CHA_25A_50, app).value, continuous(CHA_25A_50, app).value
        assert peak is not None
        assert rms is not None
        assert rms <= peak <= rms * 1.026


# --- a segment cycle with a long dwell ----------------------------------------------------


def pressing(dwell_s: float, idle_s: float) -> Application:
    """Move out at 20 rpm, press with 75 Nm for ``dwell_s`` at standstill, move back, idle."""
    return Application(
        motion=Motion(
            segments=(
                Segment(duration_s=0.5, start_rpm=0, end_rpm=20),
                Segment(duration_s=10.0, start_rpm=20, end_rpm=20),
                Segment(duration_s=0.5, start_rpm=20, end_rpm=0),
                Segment(duration_s=dwell_s, start_rpm=0, end_rpm=0, process_torque_nm=75),
                Segment(duration_s=0.5, start_rpm=0, end_rpm=-20, jerk_share=0.5),
                Segment(duration_s=10.0, start_rpm=-20, end_rpm=-20),
                Segment(duration_s=0.5, start_rpm=-20, end_rpm=0, jerk_share=0.5),
                Segment(duration_s=idle_s, start_rpm=0, end_rpm=0),
            ),
            load=AxisLoad(inertia_kgm2=2.0, friction_torque_nm=8.0),
        )
    )


def test_a_long_pressing_dwell_fails_where_t_rms_passes() -> None:
    """Pressing with 75 Nm (1.36·T_0) for 20 min in a 100-min cycle: T_rms ≈ 75·√0.2 =
    33.5 Nm passes; the dwell is two τ_th long, so the winding heats to about
    75·√((1 − e^(−2))/(1 − e^(−10))) ≈ 69.7 Nm: fails. A 20-s press in a 100-s cycle
    (same shares) passes."""
    long = pressing(dwell_s=1200.0, idle_s=4778.0)
    assert continuous(CHA_25A_50, long).status is Status.PASS
    check = thermal(CHA_25A_50, long)
    assert check.status is Status.FAIL
    # The moves (22 s at ≤ 40 Nm) change the closed form of the two-step cycle by < 1 %.
    assert check.value == pytest.approx(
        periodic_peak([(75.0, 1200.0), (0.0, 4800.0)], TAU), rel=1e-2
    )
    short = pressing(dwell_s=20.0, idle_s=58.0)
    assert continuous(CHA_25A_50, short).status is Status.PASS
    assert thermal(CHA_25A_50, short).status is Status.PASS


# --- τ_th: catalogue, request, default ----------------------------------------------------


def test_the_catalogues_time_constant_comes_first() -> None:
    """A published τ_th (a hypothetical 1200 s here: no public source gives one) is used
    whatever the request says, and is no assumption; with a zone as well the check is
    exact, without one it keeps the rectangle's approximation."""
    published = dataclasses.replace(CHA_25A_50, thermal_time_constant_s=1200.0)
    steps = [(80.0, 3600.0), (0.0, 36000.0)]
    for tau in (None, 60.0, 1e6):
        check = thermal(published, hold(*steps, tau=tau))
        assert check.value == pytest.approx(periodic_peak(steps, 1200.0), rel=1e-10)
        assert "assumed" not in check.message
        assert check.approximate  # no zone: T_0 stands in for its edge
    zoned = dataclasses.replace(
        published,
        zone=ContinuousDutyZone(
            points=(ZonePoint(speed_rpm=0, torque_nm=55), ZonePoint(speed_rpm=70, torque_nm=50))
        ),
    )
    assert not thermal(zoned, hold(*steps)).approximate
    assert thermal(
        dataclasses.replace(zoned, thermal_time_constant_s=None), hold(*steps)
    ).approximate


def test_the_thermal_operands_land_in_their_fields() -> None:
    """operands() appends t_0, τ_th, whether it is assumed, the heating peak as a torque
    and as a speed, and k_T·K_INL (tests/sizing/test_continuous.py)."""
    app = hold((80.0, 1.0), (0.0, 10.0), tau=123.0)
    q = operands(CHA_25A_50, app, app.profile.torques(0.97), app.profile)
    start = Operands._fields.index("cycle_s")
    assert Operands._fields[start : start + 6] == (
        "cycle_s",
        "thermal_time_constant_s",
        "thermal_time_constant_assumed",
        "thermal_torque_nm",
        "thermal_speed_rpm",
        "no_load_torque_slope_nm_per_rpm",
    )
    assert (q.cycle_s, q.thermal_time_constant_s, q.thermal_time_constant_assumed) == (
        11.0,
        123.0,
        False,
    )
    assert q.thermal_torque_nm == pytest.approx(periodic_peak([(80.0, 1.0), (0.0, 10.0)], 123.0))
    bare = operands(
        dataclasses.replace(CHA_25A_50, inertia_kgm2=None), hold((8.0, 1.0)), None, app.profile
    )
    assert math.isnan(bare.thermal_torque_nm)
    assert (bare.thermal_time_constant_s, bare.thermal_time_constant_assumed) == (TAU, True)


@pytest.mark.parametrize("tau", [0.0, -1.0, math.inf, math.nan])
def test_a_time_constant_must_be_positive_and_finite(tau: float) -> None:
    with pytest.raises(InvalidInputError, match="thermal_time_constant_s"):
        hold((10.0, 1.0), tau=tau)


def test_without_j_a_the_check_fails_when_t_rms_fails_for_every_j_a() -> None:
    """The heating peak is at least its mean T_rms², so T_rms's least over J_A ≥ 0 bounds it:
    a cycle whose least T_rms exceeds T_0 fails without J_A; a light one lacks data."""
    no_j = dataclasses.replace(CHA_25A_50, inertia_kgm2=None)
    heavy = thermal(no_j, long_trapezoid(pause_s=600.0))
    assert (heavy.status, heavy.missing) == (
        Status.FAIL,
        "moment of inertia J_A (the cycle's torques need it)",
    )
    light = thermal(no_j, long_trapezoid(pause_s=36000.0))
    assert light.status is Status.NO_DATA


# --- the vectorised flowchart -------------------------------------------------------------


def test_batch_equals_single_bit_for_bit() -> None:
    """Cases with and without a τ_th of their own, against actuators with and without a
    (hypothetical) published one, as the chapter's trapezoids (column path) and as
    segments (piece path): every value, limit, status and approximation with ==."""
    actuators = [
        CHA_25A_50,
        dataclasses.replace(CHA_25A_50, model="T1200", thermal_time_constant_s=1200.0),
        dataclasses.replace(CHA_25A_50, model="T90", thermal_time_constant_s=90.0),
        dataclasses.replace(CHA_25A_50, model="LIGHT", inertia_kgm2=0.3, stall_torque_nm=30),
        dataclasses.replace(CHA_25A_50, model="NOJ", inertia_kgm2=None),
    ]
    trapezoids = [
        long_trapezoid(pause_s=36000.0),
        long_trapezoid(pause_s=600.0, tau=1800.0),
        Application(
            pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1),
            load=Load(torque_nm=5, inertia_kgm2=1.3),
            thermal_time_constant_s=45.0,
        ),
        Application(
            pattern=SpeedPattern(speed_rpm=30, accel_s=0.2, constant_s=0.0, decel_s=0.3, pause_s=0),
            load=Load(torque_nm=20, inertia_kgm2=0.4),
        ),
    ]
    segments = [
        pressing(dwell_s=1200.0, idle_s=4778.0),
        dataclasses.replace(pressing(dwell_s=20.0, idle_s=58.0), thermal_time_constant_s=300.0),
        hold((80.0, 1.0), (0.0, 10.0)),
        hold((30.0, 0.5), (60.0, 45.0), (-40.0, 900.0), (0.0, 5.0), tau=77.7),
        # More pieces than the batch keeps between its passes: recomputed there.
        hold(*((10.0 * (k % 7), 30.0 + k) for k in range(40))),
    ]
    for apps in (trapezoids, segments, trapezoids + segments):
        ev = evaluate_batch(actuators, apps)
        k = ev.check_names.index("thermal_peak")
        for i, app in enumerate(apps):
            for j, actuator in enumerate(actuators):
                check = thermal(actuator, app)
                value = ev.values[i, j, k]
                assert (np.isnan(value) and check.value is None) or value == check.value
                limit = ev.limits[i, j, k]
                assert (np.isnan(limit) and check.limit is None) or limit == check.limit
                assert ev.status(i, j, "thermal_peak") is check.status
                assert bool(ev.approximate[i, j, k]) is check.approximate
                assert ev.verdict(i, j) is evaluate(actuator, app).verdict
