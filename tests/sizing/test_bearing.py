"""Output bearing checks: tilting moment, static safety factor and L_10 life (CHA manual
§4.3; Harmonic Drive LLC FHA-C manual ch. 2, formulas (1), (5)–(7), (9), (10)).

Reference values are worked by hand from the manuals' formulas with the bearing data of
the FHA-C mini manual (§2-3 Table 1: FHA-14C d_p = 54 mm, R = 14 mm, C = 7400 N,
C_0 = 12800 N, moment capacity 75 Nm) and the CHA tables (CHA-25A: d_p = 0.088 m,
R = 0.018 m, C = 30000 N, C_0 = 45000 N, M_dyn = 254 Nm). No numeric worked example of
the bearing check was found in the public copies searched, so none is reproduced."""

from __future__ import annotations

import dataclasses
import math

import pytest

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.bearing import OutputLoad, l10_life_h, oscillating_life_h
from actuator_selection.sizing.checks import (
    BEARING_AXIAL_FORCE,
    BEARING_FRETTING,
    BEARING_LIFE,
    BEARING_MOMENT,
    BEARING_RADIAL_FORCE,
    BEARING_STATIC,
    RULES,
    Status,
    rules_for,
)
from actuator_selection.sizing.cycle import Load, SpeedPattern, mean_speed_rpm
from actuator_selection.sizing.engine import evaluate_batch
from actuator_selection.sizing.motion import Motion, Segment
from actuator_selection.sizing.selection import Application, evaluate

BEARING_RULES = (
    BEARING_MOMENT,
    BEARING_STATIC,
    BEARING_RADIAL_FORCE,
    BEARING_AXIAL_FORCE,
    BEARING_FRETTING,
)
"""The output bearing's checks where an output load is given, in the answers' order."""

FHA_14C_50 = Actuator(
    model="FHA-14C-50",
    family="FHA-C mini",
    gear_ratio=50,
    max_torque_nm=18,
    max_speed_rpm=116,
    inertia_kgm2=0.05,
    output_bearing_pitch_diameter_m=0.054,
    output_bearing_offset_m=0.014,
    output_bearing_dynamic_load_rating_n=7400,
    output_bearing_static_load_rating_n=12800,
    output_bearing_moment_load_nm=75,
    output_bearing_type="cross_roller",  # as formula (7) of the FHA-C manual takes it
)
CHA_25A_50 = Actuator(
    model="CHA-25A-50",
    family="CHA",
    gear_ratio=50,
    max_torque_nm=98,
    max_speed_rpm=112,
    inertia_kgm2=0.97,
    output_bearing_pitch_diameter_m=0.088,
    output_bearing_offset_m=0.018,
    output_bearing_dynamic_load_rating_n=30000,
    output_bearing_static_load_rating_n=45000,
    output_bearing_dynamic_tilting_moment_nm=254,
    output_bearing_static_tilting_moment_nm=1050,
    output_bearing_type="cross_roller",
)
# CHA-20A-50 (CHA manual 1018854 8/2018 V03, Table 55.1): d_p 70 mm, R 16 mm, C 24200 N,
# C_0 31000 N, M_dyn 172 Nm; a four-point contact ball bearing (type "F").
CHA_20A_50 = Actuator(
    model="CHA-20A-50",
    family="CHA",
    gear_ratio=50,
    max_torque_nm=56,
    max_speed_rpm=120,
    inertia_kgm2=0.58,
    output_bearing_pitch_diameter_m=0.070,
    output_bearing_offset_m=0.016,
    output_bearing_dynamic_load_rating_n=24200,
    output_bearing_static_load_rating_n=31000,
    output_bearing_dynamic_tilting_moment_nm=172,
    output_bearing_static_tilting_moment_nm=603,
    output_bearing_type="four_point_contact_ball",
)
FHA_25C_50 = Actuator(  # FHA-C manual §1-4-2 gives no R, d_p, C, C_0
    model="FHA-25C-50",
    family="FHA-C",
    gear_ratio=50,
    max_torque_nm=150,
    max_speed_rpm=90,
    inertia_kgm2=0.8,
    output_bearing_radial_load_n=4900,
    output_bearing_axial_load_n=14700,
    output_bearing_moment_load_nm=370,
)
PATTERN = SpeedPattern(speed_rpm=30, accel_s=0.2, constant_s=1.0, decel_s=0.2, pause_s=1.0)


def app(load: OutputLoad | None) -> Application:
    return Application(pattern=PATTERN, load=Load(torque_nm=2, inertia_kgm2=0.1), output_load=load)


def check(a: Actuator, load: OutputLoad, name: str):  # type: ignore[no-untyped-def]
    return next(c for c in evaluate(a, app(load)).checks if c.name == name)


LIGHT = OutputLoad(
    radial_force_n=300,
    axial_force_n=200,
    radial_lever_m=0.05,
    axial_lever_m=0.01,
    required_life_h=20000,
)
HEAVY = OutputLoad(
    radial_force_n=1000,
    axial_force_n=500,
    radial_lever_m=0.05,
    axial_lever_m=0.02,
    required_life_h=20000,
)


def test_no_output_load_adds_no_bearing_check() -> None:
    assert rules_for(app(None)) == RULES
    assert rules_for(app(LIGHT)) == (*RULES, *BEARING_RULES, BEARING_LIFE)
    no_life = OutputLoad(radial_force_n=1, axial_force_n=0, radial_lever_m=0, axial_lever_m=0)
    assert rules_for(app(no_life)) == (*RULES, *BEARING_RULES)


def test_tilting_moment_by_hand_pass_and_fail() -> None:
    light = check(FHA_14C_50, LIGHT, "bearing_moment")
    assert light.value == pytest.approx(300 * (0.05 + 0.014) + 200 * 0.01)  # 21.2 Nm
    assert (light.limit, light.status) == (75, Status.PASS)
    heavy = check(FHA_14C_50, HEAVY, "bearing_moment")
    assert heavy.value == pytest.approx(1000 * 0.064 + 500 * 0.02)  # 74 Nm ≤ 75 Nm
    assert heavy.status is Status.PASS
    heavier = OutputLoad(
        radial_force_n=1100, axial_force_n=500, radial_lever_m=0.05, axial_lever_m=0.02
    )
    over = check(FHA_14C_50, heavier, "bearing_moment")
    assert over.value == pytest.approx(1100 * 0.064 + 10)
    assert over.status is Status.FAIL
    assert "allowable moment load = 75 Nm" in over.message


def test_cha_moment_is_held_against_m_dyn() -> None:
    c = check(CHA_25A_50, HEAVY, "bearing_moment")
    assert c.value == pytest.approx(1000 * (0.05 + 0.018) + 500 * 0.02)
    assert c.limit == 254
    assert "M_dyn" in c.message


def test_static_safety_by_hand() -> None:
    m = 1000 * 0.064 + 500 * 0.02
    p_0 = 1000 + 2 * m / 0.054 + 0.44 * 500  # formula (9): 3960.7 N
    c = check(FHA_14C_50, HEAVY, "bearing_static_safety")
    assert c.value == pytest.approx(1.5 * p_0)
    assert c.limit == 12800
    assert c.status is Status.PASS  # f_s = 3.23 ≥ 1.5
    assert f"= {12800 / p_0:.3g} ≥ the required 1.5" in c.message
    precise = OutputLoad(
        radial_force_n=1000,
        axial_force_n=500,
        radial_lever_m=0.05,
        axial_lever_m=0.02,
        static_safety_min=3.5,
    )
    assert check(FHA_14C_50, precise, "bearing_static_safety").status is Status.FAIL


def test_life_by_hand_and_against_the_required_life() -> None:
    n_av = mean_speed_rpm(PATTERN)
    m = 300 * 0.064 + 200 * 0.01
    radial = 300 + 2 * m / 0.054
    assert 1.5 * radial >= 200  # formula (5): X = 1, Y = 0.45
    p_c = radial + 0.45 * 200
    life = 1e6 / (60 * n_av) * (7400 / (1.5 * p_c)) ** (10 / 3)
    c = check(FHA_14C_50, LIGHT, "bearing_life")
    assert c.status is Status.PASS
    assert c.value == pytest.approx(1.5 * p_c * (20000 * 60 * n_av / 1e6) ** 0.3, rel=1e-12)
    assert c.limit == 7400
    assert life == pytest.approx(
        l10_life_h(
            dynamic_load_rating_n=7400, load_factor=1.5, equivalent_load_n=p_c, mean_speed_rpm=n_av
        ),
        rel=1e-12,
    )
    assert f"L_10 = 10⁶/(60·n_av)·(C/(f_w·P_c))^B = {life:.4g} h" in c.message
    assert "cross roller bearing: B = 10/3" in c.message
    # The check passes exactly when L_10 ≥ the required life.
    heavy = check(FHA_14C_50, HEAVY, "bearing_life")
    m = 74.0
    p_c = 1000 + 2 * m / 0.054 + 0.45 * 500
    heavy_life = 1e6 / (60 * n_av) * (7400 / (1.5 * p_c)) ** (10 / 3)
    assert (heavy_life >= 20000) is (heavy.status is Status.PASS)


def test_high_axial_share_uses_x_y_of_0_67() -> None:
    axial = OutputLoad(
        radial_force_n=0,
        axial_force_n=1000,
        radial_lever_m=0,
        axial_lever_m=0,
        required_life_h=1000,
    )
    c = check(FHA_14C_50, axial, "bearing_life")
    n_av = mean_speed_rpm(PATTERN)
    assert c.value == pytest.approx(1.5 * 0.67 * 1000 * (1000 * 60 * n_av / 1e6) ** 0.3, rel=1e-12)


def test_fha_c_without_r_or_c_says_no_data() -> None:
    statuses = {c.name: (c.status, c.missing) for c in evaluate(FHA_25C_50, app(LIGHT)).checks}
    assert statuses["bearing_moment"] == (Status.NO_DATA, "output bearing offset R")
    assert statuses["bearing_static_safety"][0] is Status.NO_DATA
    assert statuses["bearing_life"][0] is Status.NO_DATA


def test_batch_equals_single_for_the_bearing_checks() -> None:
    # a cross roller, a ball (CHA-20A) and an unpublished bearing type
    ball = dataclasses.replace(CHA_20A_50, output_bearing_type="four_point_contact_ball")
    untyped = dataclasses.replace(FHA_14C_50, model="UNTYPED", output_bearing_type=None)
    actuators = [FHA_14C_50, CHA_25A_50, FHA_25C_50, ball, untyped]
    loads = [
        OutputLoad(
            radial_force_n=fr,
            axial_force_n=fa,
            radial_lever_m=lr,
            axial_lever_m=la,
            static_safety_min=fs,
            required_life_h=life,
        )
        for fr, fa in ((0, 0), (300, 200), (1000, 500), (0, 1000), (5000, 100))
        for lr, la in ((0.0, 0.0), (0.05, 0.02))
        for fs, life in ((1.5, 20000), (3.0, 500))
    ]
    apps = [app(load) for load in loads]
    rules = rules_for(apps[0])
    ev = evaluate_batch(actuators, apps, rules=rules)
    for i, application in enumerate(apps):
        for j, actuator in enumerate(actuators):
            c = evaluate(actuator, application)
            assert ev.verdict(i, j) is c.verdict
            for k, one in enumerate(c.checks):
                assert ev.status(i, j, one.name) is one.status, (i, j, one.name)
                value, limit = ev.values[i, j, k], ev.limits[i, j, k]
                assert (None if math.isnan(value) else value) == one.value, (i, j, one.name)
                assert (None if math.isnan(limit) else limit) == one.limit, (i, j, one.name)
                assert ev.missing(i, j, one.name) == one.missing


def test_a_to_and_fro_cycle_is_checked_as_formula_8_reads_it() -> None:
    """An indexing axis swinging ±60° (a 120° stroke each way, θ = 60°) 10 times a minute:
    formula (8) with n_1 = 10 cpm gives the life the check reads at the cycle's n_av,
    since n_1·θ/90 revolutions per minute is the travel that n_av sums."""
    stroke_deg, t_ramp, t_run, t_dwell = 120.0, 0.5, 1.0, 1.0
    # trapezoidal move of the stroke: travel = n·(t_ramp + t_run)/60 rev
    speed = stroke_deg / 360 / ((t_ramp + t_run) / 60)
    go = [
        Segment(duration_s=t_ramp, start_rpm=0, end_rpm=speed),
        Segment(duration_s=t_run, start_rpm=speed, end_rpm=speed),
        Segment(duration_s=t_ramp, start_rpm=speed, end_rpm=0),
        Segment(duration_s=t_dwell, start_rpm=0, end_rpm=0),
    ]
    back = [
        Segment(duration_s=s.duration_s, start_rpm=-s.start_rpm, end_rpm=-s.end_rpm) for s in go
    ]
    motion = Motion(segments=(*go, *back), load=AxisLoad(inertia_kgm2=0.1, friction_torque_nm=2))
    swing = Application(motion=motion, output_load=LIGHT)
    cycles_per_min = 60 / swing.profile.cycle_s
    assert cycles_per_min == pytest.approx(10)
    m = 300 * 0.064 + 200 * 0.01
    p_c = 300 + 2 * m / 0.054 + 0.45 * 200
    formula_8 = oscillating_life_h(
        dynamic_load_rating_n=7400,
        load_factor=1.5,
        equivalent_load_n=p_c,
        oscillations_per_min=cycles_per_min,
        half_angle_deg=stroke_deg / 2,
    )
    c = next(k for k in evaluate(FHA_14C_50, swing).checks if k.name == "bearing_life")
    assert f"= {formula_8:.4g} h" in c.message
    assert LIGHT.required_life_h is not None
    assert (formula_8 >= LIGHT.required_life_h) is (c.status is Status.PASS)


# --- issue 28, item 4: the life exponent by bearing type --------------------------------------

BALL_CASE = OutputLoad(
    radial_force_n=2000,
    axial_force_n=0,
    radial_lever_m=0.02,
    axial_lever_m=0,
    required_life_h=90000,
)
"""2 kN at 20 mm on the CHA-20A: M = 2000·(0.020 + 0.016) = 72 Nm, P_c = 2000 + 2·72/0.070
= 4057 N, C/(f_w·P_c) = 24200/(1.5·4057) = 3.98; at n_av = 15 rpm L_10 = 69,800 h with
B = 3 (ball) against 110,700 h with B = 10/3, 1.58 times as long; 90,000 h required."""


def test_a_ball_bearing_takes_exponent_3_and_fails_where_10_3_would_pass() -> None:
    n_av = mean_speed_rpm(PATTERN)
    assert n_av == pytest.approx(15.0)
    p_c = 2000 + 2 * 2000 * (0.020 + 0.016) / 0.070
    ratio = 24200 / (1.5 * p_c)
    life_ball = 1e6 / (60 * n_av) * ratio**3
    life_roller = 1e6 / (60 * n_av) * ratio ** (10 / 3)
    assert life_ball < 90000 < life_roller
    assert life_roller / life_ball == pytest.approx(ratio ** (1 / 3))
    c = check(CHA_20A_50, BALL_CASE, "bearing_life")
    # C needed for 90,000 h: f_w·P_c·(L_h·60·n_av/10⁶)^(1/3)
    assert c.value == pytest.approx(1.5 * p_c * (90000 * 60 * n_av / 1e6) ** (1 / 3), rel=1e-12)
    assert (c.status, c.limit, c.approximate) == (Status.FAIL, 24200, False)
    assert f"^B = {life_ball:.4g} h" in c.message
    assert "four-point contact ball bearing: B = 3" in c.message
    # the same bearing taken as a roller bearing (the old exponent) passes: the 1.58x
    roller = dataclasses.replace(CHA_20A_50, output_bearing_type="cross_roller")
    passed = check(roller, BALL_CASE, "bearing_life")
    assert passed.status is Status.PASS
    assert f"^B = {life_roller:.4g} h" in passed.message
    # the pass side with B = 3: a lighter load
    light = dataclasses.replace(BALL_CASE, radial_force_n=1500)
    assert check(CHA_20A_50, light, "bearing_life").status is Status.PASS


def test_an_unpublished_bearing_type_takes_the_stricter_exponent_as_approximate() -> None:
    untyped = dataclasses.replace(CHA_20A_50, output_bearing_type=None)
    c = check(untyped, BALL_CASE, "bearing_life")
    ball = check(CHA_20A_50, BALL_CASE, "bearing_life")
    assert (c.value, c.status, c.approximate) == (ball.value, Status.FAIL, True)
    assert "the bearing's type is not published" in c.message
    # a short life (below 10⁶ revolutions) where 10/3 is the stricter exponent
    short = dataclasses.replace(BALL_CASE, required_life_h=100)
    revolutions = 100 * 60 * 15 / 1e6
    assert revolutions < 1
    needed = check(untyped, short, "bearing_life").value
    assert needed == pytest.approx(
        check(
            dataclasses.replace(CHA_20A_50, output_bearing_type="cross_roller"),
            short,
            "bearing_life",
        ).value
    )


def reciprocating(stroke_deg: float, jerk_share: float = 0.0) -> Application:
    """To and fro through ``stroke_deg``: a trapezoidal move of 0.5 s ramps and 1 s at
    speed each way, 1 s dwells (travel = n·1.5 s/60 rev), on the CHA-20A's output load."""
    speed = stroke_deg / 360 / (1.5 / 60)
    go = [
        Segment(duration_s=0.5, start_rpm=0, end_rpm=speed, jerk_share=jerk_share),
        Segment(duration_s=1.0, start_rpm=speed, end_rpm=speed),
        Segment(duration_s=0.5, start_rpm=speed, end_rpm=0, jerk_share=jerk_share),
        Segment(duration_s=1.0, start_rpm=0, end_rpm=0),
    ]
    back = [
        Segment(
            duration_s=s.duration_s,
            start_rpm=-s.start_rpm,
            end_rpm=-s.end_rpm,
            jerk_share=s.jerk_share,
        )
        for s in go
    ]
    motion = Motion(segments=(*go, *back), load=AxisLoad(inertia_kgm2=0.01, friction_torque_nm=1))
    return Application(motion=motion, output_load=LIGHT)


@pytest.mark.parametrize(("stroke", "status"), [(4.0, Status.WARN), (6.0, Status.PASS)])
def test_a_swing_below_5_degrees_warns_of_fretting(stroke: float, status: Status) -> None:
    """The CHA manual warns of fretting for oscillating motion below 5°: a ±2° swing warns,
    a ±3° one does not; the warning leaves the verdict as the other checks make it."""
    case = reciprocating(stroke)
    c = evaluate(CHA_20A_50, case)
    fretting = next(k for k in c.checks if k.name == "bearing_fretting")
    assert fretting.limit == pytest.approx(stroke, rel=1e-12)  # the stroke, first principles
    assert (fretting.value, fretting.status) == (5.0, status)
    without = tuple(r for r in rules_for(case) if r.name != "bearing_fretting")
    assert c.verdict is evaluate(CHA_20A_50, case, rules=without).verdict
    if status is Status.WARN:
        assert f"swings only {stroke:.3g}° per cycle, below 5°" in fretting.message
        assert fretting.message in c.reasons


def test_the_swing_counts_a_jerk_limited_move_and_one_way_moves() -> None:
    # S-curve ramps: the same stroke (the ramp's term integrates to the same angle)
    smooth = evaluate(CHA_20A_50, reciprocating(4.0, jerk_share=1.0))
    fretting = next(k for k in smooth.checks if k.name == "bearing_fretting")
    assert fretting.limit == pytest.approx(4.0, rel=1e-9)
    # the chapter's trapezoid: one move of n·(t_1/2 + t_2 + t_3/2) = 30 rpm·1.2 s = 216°
    one_way = check(CHA_20A_50, LIGHT, "bearing_fretting")
    assert one_way.limit == pytest.approx(30 * 1.2 * 6)
    assert one_way.status is Status.PASS


def test_batch_equals_single_for_the_fretting_check() -> None:
    apps = [reciprocating(s, j) for s in (1.0, 4.0, 5.0, 30.0) for j in (0.0, 0.5)]
    apps.append(app(LIGHT))
    actuators = [CHA_20A_50, FHA_14C_50]
    for application in apps:
        ev = evaluate_batch(actuators, [application], rules=rules_for(application))
        for j, actuator in enumerate(actuators):
            c = evaluate(actuator, application)
            k = [x.name for x in c.checks].index("bearing_fretting")
            one = c.checks[k]
            assert ev.status(0, j, "bearing_fretting") is one.status
            assert ev.limits[0, j, k] == one.limit
            assert ev.values[0, j, k] == one.value
            assert ev.verdict(0, j) is c.verdict
