"""Drive sizing: peak current against I_max (Eq. 522.2, 522.3 reversed), the controller's
output voltage with the inductive drop (Eq. 521.2 with ωL·I), the energy braking returns.

Reference values are derived here from first principles (the chapter's equations written
out by hand), from the CHA catalogue values (1018854 12/2015, Tables 36.1, 44.1) and from
the chapter's worked example; the vectorised flowchart must agree with the scalar one
bit for bit."""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence

import pytest
from tests.oracle.flowchart import ORDER, operands

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.checks import (
    DRIVE_CURRENT,
    DRIVE_VOLTAGE,
    RULES,
    Operands,
    Rule,
    Status,
    regenerative_energy_j,
    rules_for,
)
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.electrical import controller_output_voltage
from actuator_selection.sizing.engine import evaluate_batch
from actuator_selection.sizing.selection import Application, evaluate

TWO_PI_OVER_60 = 2 * math.pi / 60

# CHA-25A-50 (1018854 12/2015 V01, Table 36.1): k_Tout 26.0 Nm/A, I_max 4.0 A, I_NLS
# 0.19 A, K_INL(30 °C) 6e-3 A/rpm, K_E 37 V/krpm, R 3.7 Ω, L 6.0 mH, p = 6.
CHA_25A_50 = Actuator(
    model="CHA-25A-50",
    family="CHA",
    gear_ratio=50,
    max_torque_nm=98,
    max_speed_rpm=112,
    inertia_kgm2=0.97,
    stall_torque_nm=55,
    rated_speed_rpm=70,
    max_current_a=4.0,
    torque_constant_nm_per_a=26.0,
    motor_voltage_constant_v_per_krpm=37,
    resistance_line_ohm=3.7,
    no_load_starting_current_a=0.19,
    no_load_current_constant_30c_a_per_rpm=6e-3,
    inductance_line_mh=6.0,
    pole_pairs=6,
    dc_bus_voltage_v=560,
)
# CHA-58A-50 (Table 44.1): I_max 14.4 A, K_E 105 V/krpm, R 2.4 Ω, L 9 mH, p = 6.
CHA_58A_50 = Actuator(
    model="CHA-58A-50",
    family="CHA",
    gear_ratio=50,
    max_torque_nm=1020,
    max_speed_rpm=60,
    inertia_kgm2=11.9,
    stall_torque_nm=280,
    max_current_a=14.4,
    torque_constant_nm_per_a=75,
    motor_voltage_constant_v_per_krpm=105,
    resistance_line_ohm=2.4,
    no_load_starting_current_a=0.40,
    no_load_current_constant_30c_a_per_rpm=19e-3,
    inductance_line_mh=9,
    pole_pairs=6,
    dc_bus_voltage_v=560,
)
# FHA-25C-50 (Harmonic Drive LLC FHA-C manual §1-4-2): k_T 22 Nm/A, I_max 7.3 A, no
# no-load current, k_E per output rpm only, no pole pairs.
FHA_25C_50 = Actuator(
    model="FHA-25C-50",
    family="FHA-C",
    gear_ratio=50,
    max_torque_nm=150,
    max_speed_rpm=90,
    inertia_kgm2=0.8,
    max_current_a=7.3,
    torque_constant_nm_per_a=22,
    output_voltage_constant_v_per_rpm=2.5,
    resistance_phase_ohm=2.6,
)


def app(
    speed: float, torque: float, inertia: float, t1: float = 0.2, t3: float = 0.2
) -> Application:
    return Application(
        pattern=SpeedPattern(speed_rpm=speed, accel_s=t1, constant_s=0.5, decel_s=t3, pause_s=1),
        load=Load(torque_nm=torque, inertia_kgm2=inertia),
        drive=True,
    )


def hand_peak_current(
    a: Actuator, speed: float, torque: float, inertia: float, t1: float, t3: float
) -> float:
    """Eq. 514.1 for T_1, T_3; Eq. 522.3 solved for I with I_NLR of Eq. 522.2 at n_2."""
    omega = speed * 2 * math.pi / 60
    j = a.inertia_kgm2 + inertia  # type: ignore[operator]
    t_1 = torque + j * omega / t1
    t_3 = torque - j * omega / t3
    i_nlr = a.no_load_starting_current_a + a.no_load_current_constant_30c_a_per_rpm * speed  # type: ignore[operator]
    return max(t_1, abs(t_3)) / a.torque_constant_nm_per_a + i_nlr  # type: ignore[operator]


def check(a: Actuator, application: Application, name: str):  # type: ignore[no-untyped-def]
    return next(c for c in evaluate(a, application).checks if c.name == name)


def test_drive_checks_join_only_when_asked() -> None:
    plain = Application(
        pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1),
        load=Load(torque_nm=5, inertia_kgm2=1.3),
    )
    assert rules_for(plain) == RULES
    assert rules_for(app(40, 5, 1.3)) == (*RULES, DRIVE_CURRENT)


@pytest.mark.parametrize(
    ("torque", "inertia", "status"), [(5.0, 0.2, Status.PASS), (10.0, 1.0, Status.FAIL)]
)
def test_peak_current_against_a_hand_derived_value(
    torque: float, inertia: float, status: Status
) -> None:
    c = check(CHA_25A_50, app(100, torque, inertia), "drive_current")
    expected = hand_peak_current(CHA_25A_50, 100, torque, inertia, 0.2, 0.2)
    assert c.value == pytest.approx(expected, rel=1e-12)
    assert c.limit == 4.0
    assert c.status is status
    assert (expected <= 4.0) is (status is Status.PASS)
    assert c.reference == "Eq. 522.2, Eq. 522.3"
    assert not c.approximate


def test_peak_current_inverts_the_torque_from_current_of_eq_522() -> None:
    """Eq. 522.3 forward (electrical.output_torque_from_current) at the current the check
    reports gives back the peak torque: the check is that equation solved for I."""
    from actuator_selection.sizing.electrical import output_torque_from_current

    application = app(100, 5.0, 0.2)
    c = check(CHA_25A_50, application, "drive_current")
    torques = evaluate(CHA_25A_50, application).torques
    assert torques is not None
    assert c.value is not None
    back = output_torque_from_current(
        current_a=c.value,
        output_speed_rpm=100,
        torque_constant_nm_per_a=26.0,
        no_load_starting_current_a=0.19,
        no_load_current_constant_30c_a_per_rpm=6e-3,
    )
    assert back.output_torque_nm == pytest.approx(
        max(torques.accel_torque_nm, -torques.decel_torque_nm), rel=1e-12
    )


def test_peak_current_without_no_load_data_is_approximate() -> None:
    c = check(FHA_25C_50, app(60, 20, 1.0), "drive_current")
    omega = 60 * TWO_PI_OVER_60
    t_1 = 20 + 1.8 * omega / 0.2
    assert c.value == pytest.approx(t_1 / 22, rel=1e-12)
    assert c.approximate
    assert "approximate" in c.message


def test_peak_current_fails_on_its_lower_bound_without_j_a() -> None:
    no_j = Actuator(
        model="X", family="CHA", gear_ratio=50, max_current_a=1.0, torque_constant_nm_per_a=26
    )
    c = check(no_j, app(100, 50, 1.0), "drive_current")
    omega = 100 * TWO_PI_OVER_60
    floor = (50 + 1.0 * omega / 0.2) / 26  # T_1 at J_A = 0, no no-load data
    assert c.status is Status.FAIL
    assert c.value == pytest.approx(floor, rel=1e-12)
    assert c.missing == "moment of inertia J_A (T_1 and T_3 need it)"


def test_regenerative_energy_is_the_braking_torque_times_the_angle() -> None:
    # T_3 constant while the speed falls linearly: angle = ω_2·t_3/2.
    assert regenerative_energy_j(decel_torque_nm=-100.0, speed_rpm=60, decel_s=0.5) == (
        pytest.approx(100.0 * 2 * math.pi * 0.5 / 2)
    )
    assert regenerative_energy_j(decel_torque_nm=3.0, speed_rpm=60, decel_s=0.5) == 0.0
    c = check(CHA_25A_50, app(100, 5.0, 0.2), "drive_current")
    torques = evaluate(CHA_25A_50, app(100, 5.0, 0.2)).torques
    assert torques is not None
    energy = -torques.decel_torque_nm * (100 * TWO_PI_OVER_60) * 0.2 / 2
    assert f"braking returns up to {energy:.4g} J per cycle" in c.message


def test_voltage_with_the_inductive_drop_fails_where_eq_521_2_passes() -> None:
    """CHA-58A-50 at 60 rpm on a 560 V bus (issue 11): Eq. 521.2 as printed gives 349.6 V,
    below 560/√2 = 396.0 V; with ω·L·I in quadrature it needs 426.5 V."""
    c = check(CHA_58A_50, app(60, 100, 5), "drive_voltage")
    motor_rpm = 60 * 50
    printed = motor_rpm * 105 / 1000 + 14.4 * 2.4
    omega_el = 2 * math.pi * motor_rpm / 60 * 6
    full = math.hypot(printed, omega_el * 9e-3 * 14.4)
    tool = controller_output_voltage(
        output_speed_rpm=60,
        gear_ratio=50,
        motor_voltage_constant_v_per_krpm=105,
        max_current_a=14.4,
        resistance_line_ohm=2.4,
        inductance_line_h=9e-3,
        pole_pairs=6,
    )
    assert printed == pytest.approx(tool.printed_v, rel=1e-12)
    assert tool.total_v == c.value  # one formula: the tool's answer is the check's
    assert c.value == pytest.approx(full, rel=1e-12)
    assert c.value == pytest.approx(426.5, abs=0.05)
    assert c.limit == pytest.approx(560 / math.sqrt(2))
    assert printed < c.limit < c.value
    assert c.status is Status.FAIL
    assert f"Eq. 521.2 as printed (no inductive drop) gives {printed:.4g} V_rms" in c.message


def test_voltage_passes_at_a_lower_speed() -> None:
    c = check(CHA_58A_50, app(40, 100, 5), "drive_voltage")
    motor_rpm = 40 * 50
    full = math.hypot(
        motor_rpm * 0.105 + 14.4 * 2.4, 2 * math.pi * motor_rpm / 60 * 6 * 9e-3 * 14.4
    )
    assert c.value == pytest.approx(full, rel=1e-12)
    assert c.status is Status.PASS


def test_voltage_says_no_data_without_pole_pairs_or_rms_k_e() -> None:
    c = check(FHA_25C_50, app(60, 20, 1.0), "drive_voltage")
    assert c.status is Status.NO_DATA
    assert c.missing == "motor voltage constant K_E (V_rms)"
    no_poles = dataclasses.replace(CHA_25A_50, pole_pairs=None)
    assert check(no_poles, app(60, 20, 1.0), "drive_voltage").missing == "number of pole pairs p"


def test_new_operands_land_in_their_fields() -> None:
    application = app(40, 5, 1.3)
    q = operands(CHA_25A_50, application, None, application.profile)
    assert q.decel_s == 0.2
    assert q.gear_ratio == 50
    assert q.torque_constant_nm_per_a == 26.0
    assert q.max_current_a == 4.0
    assert q.no_load_starting_current_a == 0.19
    assert q.no_load_current_constant_a_per_rpm == 6e-3
    assert q.motor_voltage_constant_v_per_krpm == 37
    assert q.resistance_line_ohm == 3.7
    assert q.inductance_line_h == 6.0 / 1000
    assert q.pole_pairs == 6
    assert q.dc_bus_voltage_v == 560
    assert math.isnan(q.radial_force_n)
    assert math.isnan(q.required_life_h)
    # The output bearing's operands end here; the thermal ones follow
    # (tests/sizing/test_thermal_validity.py).
    assert ORDER[ORDER.index("cycle_s") - 1] == "bearing_dynamic_tilting_moment_nm"
    assert set(ORDER) <= set(Operands._fields)


def assert_batch_equals_scalar(
    actuators: Sequence[Actuator], apps: Sequence[Application], rules: Sequence[Rule]
) -> None:
    ev = evaluate_batch(actuators, apps, rules=rules)
    for i, application in enumerate(apps):
        for j, actuator in enumerate(actuators):
            c = evaluate(actuator, application, rules=rules)
            assert ev.verdict(i, j) is c.verdict
            for k, one in enumerate(c.checks):
                assert ev.status(i, j, one.name) is one.status, (i, j, one.name)
                value, limit = ev.values[i, j, k], ev.limits[i, j, k]
                assert (None if math.isnan(value) else value) == one.value, (i, j, one.name)
                assert (None if math.isnan(limit) else limit) == one.limit, (i, j, one.name)
                assert ev.approximate[i, j, k] == one.approximate
                assert ev.missing(i, j, one.name) == one.missing


def test_batch_equals_single_for_the_drive_checks() -> None:
    no_j = Actuator(
        model="X", family="CHA", gear_ratio=50, max_current_a=1.0, torque_constant_nm_per_a=26
    )
    actuators = [CHA_25A_50, CHA_58A_50, FHA_25C_50, no_j]
    apps = [
        app(speed, torque, inertia, t1, t3)
        for speed in (20, 40, 60, 100)
        for torque, inertia in ((5, 0.2), (10, 1.0), (100, 5))
        for t1, t3 in ((0.2, 0.2), (0.1, 0.4))
    ]
    rules = (*RULES, DRIVE_CURRENT)
    assert DRIVE_VOLTAGE in RULES
    assert all(rules_for(a) == rules for a in apps)
    assert_batch_equals_scalar(actuators, apps, rules)
