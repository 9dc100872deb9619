"""Issue 28, items 7–9: the gear's own limits, the torsional stiffness and the brake's
emergency stops, each against a hand calculation from first principles, pass and fail,
the engine equal (==) to the scalar oracle (tests/oracle/flowchart.py).

GEAR RATINGS IN THIS FILE ARE TEST VALUES, MADE UP: no public document gives them for
any catalogue actuator (docs/catalogue-data/gear-ratings.csv). They only exercise the
arithmetic.
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import pytest
from tests.oracle.flowchart import evaluate as oracle_evaluate

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.bearing import OutputLoad
from actuator_selection.sizing.checks import RULES, Check, Status
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.mechanisms import (
    Hoist,
    InclinedBallScrew,
    hoist_axis,
    inclined_ball_screw_axis,
)
from actuator_selection.sizing.motion import Motion, Segment
from actuator_selection.sizing.selection import Application, Verdict, evaluate

# The chapter's worked example (Table 516.1) on FHA-25C-50-L (Table 516.3).
N, T1, T2, T3, TP, T_L, J_L, J_A, RATIO = 40.0, 0.1, 0.1, 0.1, 1.0, 5.0, 1.3, 0.86, 50.0
EXAMPLE: dict[str, Any] = {
    "pattern": SpeedPattern(speed_rpm=N, accel_s=T1, constant_s=T2, decel_s=T3, pause_s=TP),
    "load": Load(torque_nm=T_L, inertia_kgm2=J_L),
}
FHA = Actuator(
    model="FHA-25C-50-L", family="FHA-C", gear_ratio=RATIO, max_torque_nm=151, max_speed_rpm=90,
    inertia_kgm2=J_A,
)  # fmt: skip
TEST_RATINGS: dict[str, Any] = {  # TEST VALUES, MADE UP (not catalogue data)
    "gear_average_torque_limit_nm": 80.0,
    "gear_repeated_peak_torque_nm": 120.0,
    "gear_momentary_peak_torque_nm": 200.0,
    "gear_momentary_peak_count": 1000.0,
    "gear_average_input_speed_limit_rpm": 3000.0,
    "gear_rated_torque_nm": 50.0,
    "gear_rated_life_h": 10000.0,
    "gear_life_basis": "L50",
}

# First principles (Eq. 514.1, 514.3; CSD-2A 1019659 11/2014 p. 18):
ALPHA = N * 2 * math.pi / 60 / T1  # rad/s²
T_ACC = T_L + (J_A + J_L) * ALPHA
T_DEC = T_L - (J_A + J_L) * ALPHA
W_ACC, W_RUN, W_DEC = N / 2 * T1, N * T2, N / 2 * T3  # |n|·t, a ramp at n/2, pause 0
T_AV = (
    (W_ACC * abs(T_ACC) ** 3 + W_RUN * T_L**3 + W_DEC * abs(T_DEC) ** 3) / (W_ACC + W_RUN + W_DEC)
) ** (1 / 3)
N_AV = (W_ACC + W_RUN + W_DEC) / (T1 + T2 + T3 + TP)  # the pause included
N_IN = RATIO * N_AV


def life_h(l_n: float, t_n: float) -> float:
    return float(l_n * (t_n / T_AV) ** 3 * (2000.0 / N_IN))


def checks(actuator: Actuator, app: Application) -> dict[str, Check]:
    candidate = evaluate(actuator, app)
    assert candidate == oracle_evaluate(actuator, app)  # engine == scalar oracle
    return {c.name: c for c in candidate.checks}


def test_hand_figures() -> None:
    assert pytest.approx(72.03, abs=0.01) == T_AV
    assert pytest.approx(307.69, abs=0.01) == N_IN
    assert life_h(10000, 50) == pytest.approx(21737, rel=1e-4)


def test_gear_checks_run_only_when_asked() -> None:
    rated = dataclasses.replace(FHA, **TEST_RATINGS)
    names = {c.name for c in evaluate(rated, Application(**EXAMPLE)).checks}
    assert names == {r.name for r in RULES}  # the verdict as before: no gear check


def test_gear_average_torque_and_life_pass_against_the_hand_calculation() -> None:
    rated = dataclasses.replace(FHA, **TEST_RATINGS)
    app = Application(
        **EXAMPLE, gear=True, gear_required_life_h=20000, momentary_torque_nm=150,
        momentary_count=10,
    )  # fmt: skip
    c = checks(rated, app)
    assert c["gear_average_torque"].value == pytest.approx(T_AV, rel=1e-12)
    assert (c["gear_average_torque"].status, c["gear_average_torque"].limit) == (
        Status.PASS,
        80.0,
    )
    assert c["gear_repeated_peak"].value == pytest.approx(abs(T_ACC), rel=1e-12)
    assert c["gear_repeated_peak"].status is Status.PASS
    assert c["gear_input_speed"].value == pytest.approx(N_IN, rel=1e-12)
    assert c["gear_input_speed"].status is Status.PASS
    assert c["gear_momentary_peak"].status is Status.PASS
    life = c["gear_life"]
    assert life.status is Status.PASS
    # the L_n the required 20,000 h need: L_req·(T_av/T_N)³·(n_in,av/n_N)
    assert life.value == pytest.approx(20000 * (T_AV / 50) ** 3 * (N_IN / 2000), rel=1e-12)
    assert f"L_50 = {life_h(10000, 50):.4g} h" in life.message


def test_gear_checks_fail_beyond_their_limits() -> None:
    rated = dataclasses.replace(
        FHA,
        **TEST_RATINGS
        | {
            "gear_average_torque_limit_nm": 70.0,  # TEST VALUES, MADE UP
            "gear_repeated_peak_torque_nm": 90.0,
            "gear_average_input_speed_limit_rpm": 300.0,
            "gear_life_basis": "L10",
        },
    )
    app = Application(
        **EXAMPLE, gear=True, gear_required_life_h=25000, momentary_torque_nm=150,
        momentary_count=2000,
    )  # fmt: skip
    c = checks(rated, app)
    for name in (
        "gear_average_torque",
        "gear_repeated_peak",
        "gear_input_speed",
        "gear_momentary_peak",
        "gear_life",
    ):
        assert c[name].status is Status.FAIL, name
    assert life_h(10000, 50) < 25000
    assert f"L_10 = {life_h(10000, 50):.4g} h" in c["gear_life"].message


def test_without_ratings_the_gear_checks_say_no_data() -> None:
    app = Application(**EXAMPLE, gear=True, gear_required_life_h=20000)
    candidate = evaluate(FHA, app)
    assert candidate == oracle_evaluate(FHA, app)
    gear = [c for c in candidate.checks if c.name.startswith("gear_")]
    assert [c.status for c in gear] == [Status.NO_DATA] * 4
    assert candidate.verdict is Verdict.UNCONFIRMED


# --- stiffness: CHA-25A-50 (CHA manual 1018854 12/2015 §3.3.5 p. 50) -----------------------

CHA = Actuator(
    model="CHA-25A-50", family="CHA", gear_ratio=50, max_torque_nm=127, max_speed_rpm=110,
    inertia_kgm2=1.2, limit_torque_t1_nm=14, limit_torque_t2_nm=48,
    torsional_stiffness_k1_nm_per_rad=25000, torsional_stiffness_k2_nm_per_rad=34000,
    torsional_stiffness_k3_nm_per_rad=44000,
)  # fmt: skip
ARCMIN = 60 * 180 / math.pi


@pytest.mark.parametrize(("required", "status"), [(20.0, Status.PASS), (25.0, Status.FAIL)])
def test_natural_frequency_against_the_hand_calculation(required: float, status: Status) -> None:
    app = Application(
        pattern=SpeedPattern(speed_rpm=20, accel_s=0.2, constant_s=0.5, decel_s=0.2, pause_s=1),
        load=Load(torque_nm=30, inertia_kgm2=1.5),
        min_natural_frequency_hz=required,
    )
    f_n = math.sqrt(25000 / 1.5) / (2 * math.pi)  # 20.55 Hz
    c = checks(CHA, app)["natural_frequency"]
    assert (c.status, c.value) == (status, required)
    assert c.limit == pytest.approx(f_n, rel=1e-12)
    # Eq. 68.2: 30 Nm between T_1 and T_2: φ = T_1/K_1 + (T − T_1)/K_2
    phi = (14 / 25000 + (30 - 14) / 34000) * ARCMIN
    assert f"{phi:.3g} arcmin under T_L = 30 Nm" in c.message
    assert f"{14 / 25000 * ARCMIN:.3g} arcmin under T_1" in c.message


# --- brake: CHA-25A (Table 36.3: 200 emergency stops, closing time 70 ms) ------------------

BRAKED = dataclasses.replace(
    CHA, brake_holding_torque_nm=90, brake_emergency_stop_count=200, brake_closing_time_s=0.07
)


@pytest.mark.parametrize(("stops", "status"), [(200.0, Status.PASS), (201.0, Status.FAIL)])
def test_emergency_stops_and_the_drop(stops: float, status: Status) -> None:
    app = Application(
        pattern=SpeedPattern(speed_rpm=20, accel_s=0.2, constant_s=0.5, decel_s=0.2, pause_s=1),
        load=Load(torque_nm=30, inertia_kgm2=1.5),
        brake=True,
        emergency_stops=stops,
    )
    c = checks(BRAKED, app)["brake_emergency_stops"]
    assert (c.status, c.value, c.limit) == (status, stops, 200)
    # θ = ½·T_L/(J_L + J_A)·t_c²: 30 Nm on 2.7 kgm² for 70 ms
    theta = 0.5 * 30 / (1.5 + 1.2) * 0.07**2
    assert f"{math.degrees(theta):.3g}°" in c.message


def _lift(axis: AxisLoad) -> Application:
    """A short lift and lower of ``axis`` with the brake and 10 emergency stops."""
    up = (
        Segment(duration_s=0.2, start_rpm=0.0, end_rpm=10.0),
        Segment(duration_s=0.2, start_rpm=10.0, end_rpm=0.0),
        Segment(duration_s=1.0, start_rpm=0.0, end_rpm=0.0),
    )
    return Application(motion=Motion(segments=up, load=axis), brake=True, emergency_stops=10)


def _drop_mm(message: str) -> float:
    return float(message.split("falls by up to ")[1].split(" mm")[0])


@pytest.mark.parametrize("j_a", [0.0, 1.2])
def test_the_drop_of_a_hoist_is_free_fall_at_most(j_a: float) -> None:
    """A 200 kg hook on a 0.2 m drum (r = 0.1 m, no drum inertia, η = 1): while the brake
    closes (70 ms) the weight m·g·r accelerates m·r² + J_A; the hook falls
    s = r·θ = ½·g·t²·m·r²/(m·r² + J_A) — free fall ½·g·t² = 24.0 mm where J_A = 0, less
    with the actuator's inertia (first principles, s = ½·a·t²)."""
    m, r, t_c, g = 200.0, 0.1, 0.07, 9.81
    axis = hoist_axis(Hoist(load_mass_kg=m, drum_diameter_m=2 * r, efficiency=1.0))
    actuator = dataclasses.replace(BRAKED, inertia_kgm2=j_a)
    c = checks(actuator, _lift(axis))["brake_emergency_stops"]
    free_fall_mm = 0.5 * g * t_c**2 * 1000
    expected = free_fall_mm * m * r**2 / (m * r**2 + j_a)
    assert _drop_mm(c.message) == pytest.approx(expected, rel=5e-3)  # printed to 3 digits
    assert f"free fall would be {free_fall_mm:.3g} mm" in c.message
    if j_a == 0.0:
        assert f"falls by up to {free_fall_mm:.3g} mm" in c.message
    else:
        assert _drop_mm(c.message) < free_fall_mm


def test_the_drop_of_a_counterweighted_hoist_is_atwoods() -> None:
    """100 kg against a 60 kg counterweight: a = g·(m − m_c)/(m + m_c), s = ½·a·t²."""
    axis = hoist_axis(
        Hoist(load_mass_kg=100, drum_diameter_m=0.2, efficiency=0.9, counterweight_kg=60)
    )
    actuator = dataclasses.replace(BRAKED, inertia_kgm2=0.0)
    c = checks(actuator, _lift(axis))["brake_emergency_stops"]
    expected = 0.5 * 9.81 * 40 / 160 * 0.07**2 * 1000  # 6.01 mm
    assert _drop_mm(c.message) == pytest.approx(expected, rel=5e-3)


def test_the_drop_of_a_vertical_ball_screw_in_mm() -> None:
    """20 kg on a vertical 10 mm lead screw (r = P/2π) with the CHA-25A's J_A = 1.2 kgm²:
    the screw's reflected inertia m·r² is tiny beside J_A, so the slide falls by
    s = ½·g·t²·m·r²/(m·r² + J_A) — microns, not the 24 mm of free fall."""
    screw = InclinedBallScrew(
        mass_kg=20, lead_m=0.01, friction_coefficient=0.0, efficiency=1.0, incline_deg=90
    )
    c = checks(BRAKED, _lift(inclined_ball_screw_axis(screw)))["brake_emergency_stops"]
    r = 0.01 / (2 * math.pi)
    theta = 0.5 * (20 * 9.81 * r) / (20 * r**2 + 1.2) * 0.07**2
    assert _drop_mm(c.message) == pytest.approx(theta * r * 1000, rel=5e-3)
    assert f"the output turns {math.degrees(theta):.3g}°" in c.message


def test_a_horizontal_axis_does_not_fall() -> None:
    belt = inclined_ball_screw_axis(
        InclinedBallScrew(mass_kg=20, lead_m=0.01, friction_coefficient=0.1, efficiency=0.9)
    )
    c = checks(BRAKED, _lift(belt))["brake_emergency_stops"]
    assert "does not fall" in c.message


@pytest.mark.parametrize(("torque", "status"), [(90.0, Status.PASS), (90.5, Status.FAIL)])
def test_the_default_safety_factor_is_said_to_be_the_users_choice(
    torque: float, status: Status
) -> None:
    """S defaults to 1 (the holding torque as published, T_L ≤ T_Br = 90 Nm): no public
    document read names a default, so the answer says S is the user's to set."""
    app = Application(
        pattern=SpeedPattern(speed_rpm=20, accel_s=0.2, constant_s=0.5, decel_s=0.2, pause_s=1),
        load=Load(torque_nm=torque, inertia_kgm2=1.5),
        brake=True,
    )
    c = checks(BRAKED, app)["brake_holding"]
    assert (c.status, c.value, c.limit) == (status, torque, 90)
    assert "safety factor S = 1" in c.message
    assert "set brake_safety_factor from your own risk assessment" in c.message


@pytest.mark.parametrize(("factor", "status"), [(3.0, Status.PASS), (3.01, Status.FAIL)])
def test_brake_holding_with_a_safety_factor(factor: float, status: Status) -> None:
    app = Application(
        pattern=SpeedPattern(speed_rpm=20, accel_s=0.2, constant_s=0.5, decel_s=0.2, pause_s=1),
        load=Load(torque_nm=30, inertia_kgm2=1.5),
        brake=True,
        brake_safety_factor=factor,
    )
    c = checks(BRAKED, app)["brake_holding"]
    assert (c.status, c.value, c.limit) == (status, factor * 30, 90)
    assert "S·T_L" in c.message


@pytest.mark.parametrize(
    ("field", "value"),
    [("brake_safety_factor", 0.9), ("emergency_stops", 0.0), ("gear_required_life_h", -1.0)],
)
def test_bad_request_inputs_name_their_field(field: str, value: float) -> None:
    with pytest.raises(InvalidInputError, match=field):
        Application(**(EXAMPLE | {field: value}))


# --- output bearing forces: FHA-17C-50 (FHA-C manual §1-4-2: 2940 N radial, 9800 N axial) --

FHA_17C = Actuator(
    model="FHA-17C-50", family="FHA-C", gear_ratio=50, max_torque_nm=39, max_speed_rpm=96,
    inertia_kgm2=0.17, output_bearing_radial_load_n=2940, output_bearing_axial_load_n=9800,
    output_bearing_static_load_rating_n=18700,
)  # fmt: skip


@pytest.mark.parametrize(
    ("radial", "axial", "statuses"),
    [
        (2940.0, -9800.0, (Status.PASS, Status.PASS)),
        (2941.0, 9801.0, (Status.FAIL, Status.FAIL)),
    ],
)
def test_fha_c_allowable_forces(radial: float, axial: float, statuses: tuple[Status, ...]) -> None:
    app = Application(
        **EXAMPLE,
        output_load=OutputLoad(
            radial_force_n=radial, axial_force_n=axial, radial_lever_m=0.01, axial_lever_m=0.0
        ),
    )
    c = checks(FHA_17C, app)
    got = (c["bearing_radial_force"], c["bearing_axial_force"])
    assert tuple(x.status for x in got) == statuses
    assert [(x.value, x.limit) for x in got] == [(radial, 2940), (abs(axial), 9800)]


def test_a_bearing_rated_by_c_0_is_not_judged_by_allowable_forces() -> None:
    """The CHA manual rates its output bearing by C, C_0, M_dyn and M_0 (1018854 12/2015,
    Table 51.1) and defines no allowable force: the force checks' premise does not hold.
    They are not applicable (they passed at 0 ≤ 0 before), and the verdict is what the
    other checks make it."""
    cha = dataclasses.replace(CHA, output_bearing_static_load_rating_n=34000)
    app = Application(
        **EXAMPLE,
        output_load=OutputLoad(
            radial_force_n=5000, axial_force_n=0, radial_lever_m=0.01, axial_lever_m=0.0
        ),
    )
    candidate = evaluate(cha, app)
    c = checks(cha, app)
    for name in ("bearing_radial_force", "bearing_axial_force"):
        assert (c[name].status, c[name].value, c[name].limit) == (
            Status.NOT_APPLICABLE,
            None,
            None,
        )
        assert "load ratings C and C_0" in c[name].message
        assert c[name].message not in candidate.reasons  # neither a reason nor a pass
    others = [x.status for x in candidate.checks if x.status is not Status.NOT_APPLICABLE]
    expected = (
        Verdict.UNSUITABLE
        if Status.FAIL in others
        else Verdict.UNCONFIRMED
        if Status.NO_DATA in others
        else Verdict.SUITABLE
    )
    assert candidate.verdict is expected


def test_a_bearing_rated_by_neither_lacks_data() -> None:
    """Neither an allowable force nor C_0 published: the check applies and the force is
    what is missing (no data), not a premise that fails."""
    app = Application(
        **EXAMPLE,
        output_load=OutputLoad(
            radial_force_n=100, axial_force_n=0, radial_lever_m=0.01, axial_lever_m=0.0
        ),
    )
    c = checks(CHA, app)["bearing_radial_force"]
    assert c.status is Status.NO_DATA
    assert c.missing == "allowable radial load on the output bearing"


def test_fretting_is_not_applicable_where_the_output_does_not_move() -> None:
    """A held weight, never moved: no oscillating motion, so the fretting warning's premise
    does not hold (it passed with value 0 before)."""
    held = Motion(
        segments=(Segment(duration_s=1.0, start_rpm=0.0, end_rpm=0.0),),
        load=AxisLoad(inertia_kgm2=J_L, friction_torque_nm=0.0, gravity_torque_nm=T_L),
    )
    still = Application(
        motion=held,
        output_load=OutputLoad(
            radial_force_n=100, axial_force_n=0, radial_lever_m=0.01, axial_lever_m=0.0
        ),
    )
    c = checks(FHA_17C, still)["bearing_fretting"]
    assert (c.status, c.value, c.limit) == (Status.NOT_APPLICABLE, None, None)
    assert c.message == "the output does not move: no oscillating motion"
