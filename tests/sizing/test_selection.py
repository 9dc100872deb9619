"""The flowchart's checks, verdicts and ranking (chapter p. 514–517)."""

from __future__ import annotations

import dataclasses
import math

import pytest
from tests import worked_example

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.sizing.checks import Check, overload
from actuator_selection.sizing.cycle import Load
from actuator_selection.sizing.selection import Application, Status, Verdict, evaluate, select

EXAMPLE = worked_example.APPLICATION
FHA = worked_example.FHA_25C_50_L


def status(actuator: Actuator, app: Application, name: str) -> Status:
    return next(c for c in evaluate(actuator, app).checks if c.name == name).status


def test_worked_example_passes_every_check_with_data() -> None:
    c = evaluate(FHA, EXAMPLE)
    by_name = {k.name: k for k in c.checks}
    assert [k.name for k in c.checks] == [
        "max_speed",
        "inertia_ratio",
        "peak_torque",
        "decel_torque",
        "continuous_duty",
        "thermal_peak",
        "continuous_speed",
        "drive_voltage",
    ]
    assert by_name["max_speed"].value == 40
    assert by_name["max_speed"].limit == 90
    assert by_name["inertia_ratio"].limit == pytest.approx(3 * 0.86)
    assert by_name["peak_torque"].value == pytest.approx(95.478, abs=1e-3)
    assert by_name["decel_torque"].value == pytest.approx(85.478, abs=1e-3)
    assert by_name["continuous_duty"].status is Status.NO_DATA
    assert by_name["thermal_peak"].status is Status.NO_DATA
    assert by_name["continuous_speed"].status is Status.NO_DATA
    assert c.verdict is Verdict.UNCONFIRMED
    assert by_name["peak_torque"].reference == "Eq. 514.1"
    assert by_name["max_speed"].reference == "Table 515.1"


def test_max_speed_fails_above_n_max() -> None:
    fast = dataclasses.replace(
        EXAMPLE, pattern=dataclasses.replace(worked_example.PATTERN, speed_rpm=91)
    )
    assert status(FHA, fast, "max_speed") is Status.FAIL
    exact = dataclasses.replace(
        EXAMPLE, pattern=dataclasses.replace(worked_example.PATTERN, speed_rpm=90)
    )
    assert status(FHA, exact, "max_speed") is Status.PASS


def test_inertia_ratio_fails_when_dynamic_and_warns_otherwise() -> None:
    heavy = dataclasses.replace(EXAMPLE, load=Load(torque_nm=5, inertia_kgm2=2.6))  # > 2.58
    assert status(FHA, heavy, "inertia_ratio") is Status.FAIL
    relaxed = dataclasses.replace(heavy, high_dynamics=False)
    assert status(FHA, relaxed, "inertia_ratio") is Status.WARN


def test_peak_torque_fails_when_t1_exceeds_t_max() -> None:
    small = dataclasses.replace(FHA, max_torque_nm=95)
    assert status(small, EXAMPLE, "peak_torque") is Status.FAIL
    assert status(small, EXAMPLE, "decel_torque") is Status.PASS  # |T_3| = 85.48 ≤ 95
    assert evaluate(small, EXAMPLE).verdict is Verdict.UNSUITABLE


def test_decel_torque_fails_on_fast_braking_alone() -> None:
    pattern = dataclasses.replace(
        worked_example.PATTERN, decel_s=0.05
    )  # |T_3| = 180.96 − 5 = 175.96
    app = dataclasses.replace(EXAMPLE, pattern=pattern)
    assert status(FHA, app, "peak_torque") is Status.PASS
    assert status(FHA, app, "decel_torque") is Status.FAIL


def test_continuous_duty_with_zone_pass_and_fail() -> None:
    # n_av = 6.1538 rpm; edge from 40 Nm at 0 rpm to 30 Nm at 90 rpm gives 39.316 Nm there.
    z = ContinuousDutyZone(
        points=(ZonePoint(speed_rpm=0, torque_nm=40), ZonePoint(speed_rpm=90, torque_nm=30))
    )
    check = next(
        c
        for c in evaluate(dataclasses.replace(FHA, zone=z), EXAMPLE).checks
        if c.name == "continuous_duty"
    )
    assert check.status is Status.PASS
    assert not check.approximate
    assert check.limit == pytest.approx(40 - 10 * (8 / 1.3) / 90)
    low = ContinuousDutyZone(
        points=(ZonePoint(speed_rpm=0, torque_nm=35), ZonePoint(speed_rpm=90, torque_nm=30))
    )
    assert status(dataclasses.replace(FHA, zone=low), EXAMPLE, "continuous_duty") is Status.FAIL
    short = ContinuousDutyZone(
        points=(ZonePoint(speed_rpm=0, torque_nm=80), ZonePoint(speed_rpm=5, torque_nm=80))
    )
    assert status(dataclasses.replace(FHA, zone=short), EXAMPLE, "continuous_duty") is Status.FAIL


def test_continuous_duty_approximate_with_stall_torque() -> None:
    cha_like = dataclasses.replace(
        FHA, stall_torque_nm=36, rated_speed_rpm=70, **worked_example.DRIVEN
    )
    ok = evaluate(cha_like, EXAMPLE)
    check = next(c for c in ok.checks if c.name == "continuous_duty")
    assert check.status is Status.PASS
    assert check.approximate
    assert check.limit == 36
    assert ok.verdict is Verdict.SUITABLE
    assert status(
        dataclasses.replace(cha_like, stall_torque_nm=35), EXAMPLE, "continuous_duty"
    ) is (Status.FAIL)
    mini = dataclasses.replace(FHA, continuous_torque_nm=40, continuous_speed_rpm=35)
    assert evaluate(mini, EXAMPLE).checks[4].limit == 40


def test_missing_data_never_passes() -> None:
    bare = Actuator(model="X", family="F", gear_ratio=50)
    c = evaluate(bare, EXAMPLE)
    assert {k.status for k in c.checks} == {Status.NO_DATA}
    assert c.torques is None
    assert c.verdict is Verdict.UNCONFIRMED
    assert all(m.startswith("no data") for m in c.reasons)


def test_margin_percent() -> None:
    check = evaluate(FHA, EXAMPLE).checks[0]
    assert check.margin_percent == pytest.approx((90 - 40) / 90 * 100)


def test_ranking_suitable_smallest_first() -> None:
    rated = dataclasses.replace(FHA, rated_speed_rpm=70, **worked_example.DRIVEN)
    big = dataclasses.replace(rated, model="BIG", max_torque_nm=300, stall_torque_nm=100)
    small = dataclasses.replace(rated, model="SMALL", max_torque_nm=151, stall_torque_nm=40)
    unknown = dataclasses.replace(FHA, model="UNKNOWN")  # no continuous data
    weak = dataclasses.replace(rated, model="WEAK", max_torque_nm=50, stall_torque_nm=40)
    result = select([weak, unknown, big, small], EXAMPLE)
    assert [c.actuator.model for c in result.candidates] == ["SMALL", "BIG", "UNKNOWN", "WEAK"]
    assert [c.verdict for c in result.candidates] == [
        Verdict.SUITABLE,
        Verdict.SUITABLE,
        Verdict.UNCONFIRMED,
        Verdict.UNSUITABLE,
    ]
    assert result.mean_speed_rpm == pytest.approx(8 / 1.3)
    assert result.cycle_time_s == pytest.approx(1.3)


def test_when_nothing_fits_the_nearest_miss_comes_first() -> None:
    """Three actuators too weak for the worked example (T_1 = 95.48 Nm with FHA's J_A):
    ranked by their worst overload, value/limit of the worst failed check, not by size."""
    t_1 = 5 + 2 * math.pi / 60 * (0.86 + 1.3) * 40 / 0.1  # Eq. 514.1 with J_A = 0.86 kgm²
    weakest = dataclasses.replace(FHA, model="W-10", max_torque_nm=10.0)
    near = dataclasses.replace(FHA, model="W-90", max_torque_nm=90.0)
    middle = dataclasses.replace(FHA, model="W-50", max_torque_nm=50.0)
    ranked = select([weakest, near, middle], EXAMPLE).candidates
    assert [c.actuator.model for c in ranked] == ["W-90", "W-50", "W-10"]
    assert all(c.verdict is Verdict.UNSUITABLE for c in ranked)
    assert [c.worst_overload for c in ranked] == [t_1 / 90.0, t_1 / 50.0, t_1 / 10.0]
    peak = next(c for c in ranked[0].checks if c.name == "peak_torque")
    assert peak.utilisation == t_1 / 90.0
    assert peak.overload == t_1 / 90.0


def test_overload_of_a_check() -> None:
    assert overload(Status.PASS, 95.0, 100.0) == 0.0
    assert overload(Status.WARN, 150.0, 100.0) == 0.0  # a warning is no miss
    assert overload(Status.FAIL, 150.0, 100.0) == 1.5
    assert overload(Status.FAIL, 20.0, 40.0) == 1.0  # failed on a further condition
    assert overload(Status.FAIL, 20.0, None) == math.inf  # beyond the zone's last speed
    # suitable and unconfirmed candidates keep their order by size
    big = dataclasses.replace(FHA, model="BIG", max_torque_nm=300.0)
    ranked = select([big, FHA], EXAMPLE).candidates
    assert [c.actuator.model for c in ranked] == ["FHA-25C-50-L", "BIG"]
    assert [c.worst_overload for c in ranked] == [0.0, 0.0]


# --- lower bounds: a check fails without J_A when it fails for every J_A ≥ 0 -------------

NO_J_A = dataclasses.replace(
    FHA, model="NO-JA", inertia_kgm2=None, stall_torque_nm=30.0, rated_speed_rpm=70.0
)
"""The worked example's actuator without a published J_A (and with T_0, so that the
continuous check has a limit)."""


def _check(actuator: Actuator, name: str, app: Application = EXAMPLE) -> Check:
    return next(c for c in evaluate(actuator, app).checks if c.name == name)


def test_peak_torque_fails_without_j_a_when_the_load_alone_exceeds_t_max() -> None:
    floor = 5 + 1.3 * (2 * math.pi / 60 * 40) / 0.1  # T_L + J_L·ω/t_1 = 59.45 Nm
    weak = dataclasses.replace(NO_J_A, max_torque_nm=50.0)
    check = _check(weak, "peak_torque")
    assert check.status is Status.FAIL
    assert check.value == pytest.approx(floor)
    assert check.limit == 50.0
    assert "any J_A ≥ 0" in check.message
    assert "no J_A" in check.message
    assert check.missing == "moment of inertia J_A"
    assert evaluate(weak, EXAMPLE).verdict is Verdict.UNSUITABLE
    strong = dataclasses.replace(NO_J_A, max_torque_nm=60.0)  # above the floor: unknown
    assert _check(strong, "peak_torque").status is Status.NO_DATA


def test_decel_torque_floor_is_the_least_magnitude_of_t_3() -> None:
    floor = 1.3 * (2 * math.pi / 60 * 40) / 0.1 - 5  # −T_3 at J_A = 0 = 49.45 Nm
    assert _check(dataclasses.replace(NO_J_A, max_torque_nm=49.0), "decel_torque").value == (
        pytest.approx(floor)
    )
    assert _check(dataclasses.replace(NO_J_A, max_torque_nm=49.5), "decel_torque").status is (
        Status.NO_DATA
    )
    # T_3 > 0 at J_A = 0 (a large T_L braking itself): some J_A makes T_3 = 0, floor 0
    heavy = Application(pattern=worked_example.PATTERN, load=Load(torque_nm=200, inertia_kgm2=0.1))
    assert heavy.profile.decel_floor_nm == 0.0


def test_rms_floor_is_the_least_t_rms_over_j_a() -> None:
    """Against T_rms (Eq. 514.2) sampled over J_A: no sample lies below the floor, and the
    best sample comes within 1e-6 of it."""
    for load in (Load(torque_nm=5, inertia_kgm2=1.3), Load(torque_nm=150, inertia_kgm2=0.2)):
        profile = Application(pattern=worked_example.PATTERN, load=load).profile
        floor = profile.rms_floor_nm
        samples = [profile.torques(k / 10_000).rms_torque_nm for k in range(0, 100_000, 7)]
        assert min(samples) >= floor * (1 - 1e-12)
        assert min(samples) == pytest.approx(floor, rel=1e-6)
    # the continuous check fails on the floor, with the same limit as with J_A
    small = dataclasses.replace(NO_J_A, stall_torque_nm=10.0)
    check = _check(small, "continuous_duty")
    assert check.status is Status.FAIL
    assert check.limit == 10.0
    assert check.approximate


def test_floors_need_every_other_value() -> None:
    """Without T_max as well, nothing is known: no data, whatever the floor."""
    bare = dataclasses.replace(NO_J_A, max_torque_nm=None)
    assert _check(bare, "peak_torque").status is Status.NO_DATA
    assert _check(bare, "peak_torque").missing == "moment of inertia J_A"


def test_brake_holds_the_load_torque_at_standstill() -> None:
    """CHA-25A-50's brake holds 90 Nm (CHA tables): T_L = 5 Nm passes, 95 Nm fails; the
    check is made only for an actuator fitted with the brake."""
    braked = dataclasses.replace(FHA, brake_holding_torque_nm=90.0)
    with_brake = dataclasses.replace(EXAMPLE, brake=True)
    check = evaluate(braked, with_brake).checks[-1]
    assert check.name == "brake_holding"
    assert (check.status, check.value, check.limit) == (Status.PASS, 5.0, 90.0)
    assert check.utilisation == 5.0 / 90.0
    heavy = dataclasses.replace(with_brake, load=Load(torque_nm=95, inertia_kgm2=1.3))
    failed = evaluate(braked, heavy).checks[-1]
    assert (failed.status, failed.value) == (Status.FAIL, 95.0)
    assert "exceeds the brake's holding torque = 90 Nm" in failed.message
    assert [c.name for c in evaluate(braked, EXAMPLE).checks][-1] == "drive_voltage"
    unpublished = evaluate(FHA, with_brake).checks[-1]
    assert (unpublished.status, unpublished.missing) == (Status.NO_DATA, "brake holding torque")
