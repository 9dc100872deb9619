"""Eq. 521.2 (controller output voltage), Eq. 522.2/522.3 (torque from current) and the
direction of rotation, against the CHA / FHA-C catalogue values and first principles."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from actuator_selection.catalogue.controllers import BusClass
from actuator_selection.errors import InvalidInputError, MissingDataError, OutOfRangeError
from actuator_selection.sizing.electrical import (
    OUTPUT_TURNS_OPPOSITE_TO_MOTOR,
    DcBusClass,
    Modulation,
    OutputTorque,
    check_output_voltage,
    check_output_voltage_all,
    controller_output_voltage,
    controller_output_voltage_from_output_constant,
    line_resistance_from_phase_ohm,
    max_output_voltage_v,
    motor_speed_rpm,
    no_load_current_constant_a_per_rpm,
    output_speed_rpm,
    output_torque_from_current,
    output_voltage_constant_v_per_rpm,
)

SEED = Path(__file__).parents[2] / "seed_data"

# CHA-25A-50 (CHA catalogue): n_max 112 rpm, i 50, k_EM 37 V/1000 rpm, I_max 4.0 A,
# R 3.7 Ω, L 6.0 mH line-to-line, p = 6; k_Tout 26.0 Nm/A, I_NLS 0.19 A, K_INL 6 and
# 2 ·10⁻³ A/rpm at 30/80 °C.
CHA_25A_50 = {
    "gear_ratio": 50.0,
    "motor_voltage_constant_v_per_krpm": 37.0,
    "max_current_a": 4.0,
    "resistance_line_ohm": 3.7,
    "inductance_line_h": 6.0e-3,
    "pole_pairs": 6.0,
}


def _torque(
    *,
    current_a: float,
    output_speed_rpm: float,
    temperature_c: float = 30.0,
    extrapolate: bool = False,
    k_inl_80c: float | None = 2 / 1000,
) -> OutputTorque:
    """The CHA-25A-50 of the catalogue: K_INL 6 and 2 ·10⁻³ A/rpm at 30 and 80 °C."""
    return output_torque_from_current(
        current_a=current_a,
        output_speed_rpm=output_speed_rpm,
        torque_constant_nm_per_a=26.0,
        no_load_starting_current_a=0.19,
        no_load_current_constant_30c_a_per_rpm=6 / 1000,
        no_load_current_constant_80c_a_per_rpm=k_inl_80c,
        temperature_c=temperature_c,
        extrapolate=extrapolate,
    )


def _buses() -> dict[BusClass, DcBusClass]:
    with (SEED / "dc_bus_classes.csv").open(encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    assert all(r["source"].strip() for r in rows)
    return {
        BusClass(r["bus_class"]): DcBusClass(
            bus_class=BusClass(r["bus_class"]), nominal_voltage_v=float(r["nominal_dc_voltage_v"])
        )
        for r in rows
    }


# --------------------------------------------------------------------------- direction


def test_output_turns_opposite_to_motor() -> None:
    assert OUTPUT_TURNS_OPPOSITE_TO_MOTOR is True
    assert motor_speed_rpm(output_speed_rpm=112, gear_ratio=50) == -5600
    assert motor_speed_rpm(output_speed_rpm=-10, gear_ratio=100) == 1000
    assert output_speed_rpm(motor_speed_rpm=3500, gear_ratio=50) == -70


@pytest.mark.parametrize("n_out", [-90.0, -0.5, 0.0, 1e-3, 47.0])
def test_direction_round_trip_and_sign(n_out: float) -> None:
    n_motor = motor_speed_rpm(output_speed_rpm=n_out, gear_ratio=80)
    assert abs(n_motor) == pytest.approx(80 * abs(n_out))
    assert n_motor * n_out <= 0  # never the same direction
    assert output_speed_rpm(motor_speed_rpm=n_motor, gear_ratio=80) == pytest.approx(n_out)
    if n_out == 0:
        assert math.copysign(1.0, n_motor) == 1.0  # standstill is 0.0, not -0.0


def test_gear_ratio_must_be_positive() -> None:
    with pytest.raises(InvalidInputError) as err:
        motor_speed_rpm(output_speed_rpm=10, gear_ratio=0)
    assert err.value.field == "gear_ratio"


# --------------------------------------------------------------------------- Eq. 521.2


def test_cha_25a_50_output_voltage_is_222_v_as_printed_237_5_v_with_the_inductive_drop() -> None:
    u = controller_output_voltage(output_speed_rpm=112, **CHA_25A_50)
    # 112 rpm · 50 = 5600 rpm; 5600 · 37/1000 = 207.2 V; 4.0 A · 3.7 Ω = 14.8 V
    assert u.motor_speed_rpm == -5600
    assert u.back_emf_v == pytest.approx(207.2, abs=1e-9)
    assert u.resistive_v == pytest.approx(14.8, abs=1e-9)
    assert u.printed_v == pytest.approx(222.0, abs=1e-9)
    # ω = 2π·6·5600/60 rad/s; ω·L·I = 3518.6 · 6.0 mH · 4.0 A = 84.45 V, in quadrature
    inductive = 2 * math.pi * 6 * 5600 / 60 * 6.0e-3 * 4.0
    assert u.inductive_v == pytest.approx(inductive, rel=1e-12)
    assert u.total_v == pytest.approx(math.hypot(222.0, inductive), rel=1e-12)
    assert u.total_v == pytest.approx(237.52, abs=5e-3)
    assert u.reference == "Eq. 521.2 with ωL·I in quadrature"


def test_cha_58a_50_at_60_rpm_needs_426_5_v() -> None:
    """Issue 28 item 2: CHA-58A-50 (K_E 105 V/krpm, I_max 14.4 A, R 2.4 Ω, L 9 mH, p = 6)
    at 60 rpm: 315 V + 34.56 V in phase, ω·L·I = 244.3 V in quadrature, 426.5 V, more
    than the 396.0 V a 560 V bus delivers; Eq. 521.2 as printed said 349.6 V, enough."""
    u = controller_output_voltage(
        output_speed_rpm=60,
        gear_ratio=50,
        motor_voltage_constant_v_per_krpm=105,
        max_current_a=14.4,
        resistance_line_ohm=2.4,
        inductance_line_h=9e-3,
        pole_pairs=6,
    )
    omega_el = 2 * math.pi * 3000 / 60 * 6
    assert u.printed_v == pytest.approx(3000 * 0.105 + 14.4 * 2.4, rel=1e-12)
    assert u.inductive_v == pytest.approx(omega_el * 9e-3 * 14.4, rel=1e-12)
    assert u.total_v == pytest.approx(426.5, abs=0.05)
    bus = DcBusClass(bus_class=BusClass.V560, nominal_voltage_v=560)
    assert not check_output_voltage(required_voltage_v=u.total_v, bus=bus).sufficient
    assert check_output_voltage(required_voltage_v=u.printed_v, bus=bus).sufficient


def test_output_voltage_terms_are_linear_in_speed_and_independent_of_direction() -> None:
    at_rest = controller_output_voltage(output_speed_rpm=0, **CHA_25A_50)
    assert at_rest.total_v == pytest.approx(14.8)  # I_MAX·R only
    assert at_rest.inductive_v == 0.0
    half = controller_output_voltage(output_speed_rpm=56, **CHA_25A_50)
    assert half.back_emf_v == pytest.approx(207.2 / 2)
    full = controller_output_voltage(output_speed_rpm=112, **CHA_25A_50)
    assert half.inductive_v == pytest.approx(full.inductive_v / 2)
    reverse = controller_output_voltage(output_speed_rpm=-112, **CHA_25A_50)
    assert reverse.total_v == full.total_v
    assert reverse.motor_speed_rpm == 5600
    printed = controller_output_voltage(
        output_speed_rpm=112, **{**CHA_25A_50, "inductance_line_h": 0}
    )
    assert printed.total_v == pytest.approx(222.0)  # L = 0: Eq. 521.2 as printed


def test_output_side_constant_is_i_times_k_e_per_1000() -> None:
    # i·K_E/1000 = 50 · 37 / 1000 = 1.85 V per output rpm
    k_out = output_voltage_constant_v_per_rpm(motor_voltage_constant_v_per_krpm=37, gear_ratio=50)
    assert k_out == pytest.approx(1.85, abs=1e-12)
    u = controller_output_voltage_from_output_constant(
        output_speed_rpm=112,
        gear_ratio=50,
        output_voltage_constant_v_per_rpm=k_out,
        max_current_a=4.0,
        resistance_line_ohm=3.7,
        inductance_line_h=6.0e-3,
        pole_pairs=6,
    )
    assert u.total_v == pytest.approx(
        controller_output_voltage(output_speed_rpm=112, **CHA_25A_50).total_v, rel=1e-12
    )
    assert u.motor_speed_rpm == -5600


def test_fha_25c_50_with_phase_resistance() -> None:
    """FHA-25C-50: k_E 2.5 V/rpm at the output, I_max 7.3 A, R 2.6 Ω per phase, n_max 90 rpm."""
    r_ll = line_resistance_from_phase_ohm(2.6)
    assert r_ll == pytest.approx(5.2)  # two phases of the star in series
    u = controller_output_voltage_from_output_constant(
        output_speed_rpm=90,
        gear_ratio=50,
        output_voltage_constant_v_per_rpm=2.5,
        max_current_a=7.3,
        resistance_line_ohm=r_ll,
        inductance_line_h=0.0,  # the FHA-C catalogue gives no pole pairs: as printed
        pole_pairs=1,
    )
    # 90 · 2.5 = 225 V; 7.3 · 5.2 = 37.96 V
    assert u.back_emf_v == pytest.approx(225.0)
    assert u.resistive_v == pytest.approx(37.96)
    assert u.total_v == pytest.approx(262.96)


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("gear_ratio", 0.0),
        ("motor_voltage_constant_v_per_krpm", -1.0),
        ("max_current_a", -0.1),
        ("resistance_line_ohm", 0.0),
        ("inductance_line_h", -1e-3),
        ("pole_pairs", 0.0),
        ("output_speed_rpm", math.inf),
    ],
)
def test_output_voltage_inputs_are_checked(field: str, value: float) -> None:
    args = {"output_speed_rpm": 112.0, **CHA_25A_50, field: value}
    with pytest.raises(InvalidInputError) as err:
        controller_output_voltage(**args)
    assert err.value.field == field


def test_phase_resistance_must_be_positive() -> None:
    with pytest.raises(InvalidInputError) as err:
        line_resistance_from_phase_ohm(0.0)
    assert err.value.field == "resistance_phase_ohm"


# --------------------------------------------------------------------------- bus classes


def test_bus_classes_seed() -> None:
    buses = _buses()
    assert {b: v.nominal_voltage_v for b, v in buses.items()} == {
        BusClass.V24: 24,
        BusClass.V320: 320,
        BusClass.V560: 560,
    }


def test_max_output_voltage_from_first_principles() -> None:
    # SVPWM: line-to-line peak = U_DC, rms = U_DC/√2. Sine-triangle: phase peak U_DC/2,
    # line-to-line peak √3·U_DC/2, rms √3·U_DC/(2√2).
    sv = max_output_voltage_v(dc_bus_voltage_v=560, modulation=Modulation.SPACE_VECTOR)
    st = max_output_voltage_v(dc_bus_voltage_v=560, modulation=Modulation.SINE_TRIANGLE)
    assert sv == pytest.approx(395.980, abs=1e-3)
    assert st == pytest.approx(342.929, abs=1e-3)
    assert sv / st == pytest.approx(2 / math.sqrt(3))  # the SVPWM gain of 15.5 %


def test_cha_25a_50_on_the_bus_classes() -> None:
    buses = _buses()
    sv = check_output_voltage(required_voltage_v=222.0, bus=buses[BusClass.V320])
    assert sv.sufficient
    assert sv.modulation is Modulation.SPACE_VECTOR
    assert sv.available_voltage_v == pytest.approx(226.274, abs=1e-3)
    # (226.274 − 222)/226.274 = 1.889 %
    assert sv.margin_percent == pytest.approx(1.889, abs=1e-3)
    st = check_output_voltage(
        required_voltage_v=222.0, bus=buses[BusClass.V320], modulation=Modulation.SINE_TRIANGLE
    )
    assert not st.sufficient  # 195.96 V < 222 V
    assert st.margin_percent < 0
    checks = check_output_voltage_all(required_voltage_v=222.0, buses=buses.values())
    assert [(c.bus_class, c.sufficient) for c in checks] == [
        (BusClass.V24, False),
        (BusClass.V320, True),
        (BusClass.V560, True),
    ]


def test_bus_voltage_must_be_positive() -> None:
    with pytest.raises(InvalidInputError) as err:
        max_output_voltage_v(dc_bus_voltage_v=0, modulation=Modulation.SPACE_VECTOR)
    assert err.value.field == "dc_bus_voltage_v"


# --------------------------------------------------------------------------- Eq. 522.2/3


def test_cha_25a_50_torque_example() -> None:
    t = _torque(current_a=2.0, output_speed_rpm=50)
    # I_NLR = 0.19 + 0.006 · 50 = 0.49 A; T = 26 · (2.0 − 0.49) = 39.26 Nm
    assert t.no_load_running_current_a == pytest.approx(0.49, abs=1e-12)
    assert t.torque_producing_current_a == pytest.approx(1.51, abs=1e-12)
    assert t.output_torque_nm == pytest.approx(39.26, abs=1e-9)
    assert not t.below_no_load_current
    assert not t.extrapolated


def test_torque_formula_algebra() -> None:
    """T = K_T·I − K_T·I_NLS − K_T·K_INL·n: 52 − 4.94 − 7.8 = 39.26 Nm."""
    t = _torque(current_a=2.0, output_speed_rpm=50)
    assert t.output_torque_nm == pytest.approx(26 * 2.0 - 26 * 0.19 - 26 * 0.006 * 50)
    # One more ampere adds exactly K_T; one more rpm removes K_T·K_INL.
    more_i = _torque(current_a=3.0, output_speed_rpm=50)
    assert more_i.output_torque_nm - t.output_torque_nm == pytest.approx(26.0)
    more_n = _torque(current_a=2.0, output_speed_rpm=51)
    assert t.output_torque_nm - more_n.output_torque_nm == pytest.approx(26 * 0.006)


@pytest.mark.parametrize(
    ("temperature_c", "k_inl", "torque_nm"),
    [
        (30, 6e-3, 39.26),
        (55, 4e-3, 41.86),  # midpoint: (6 + 2)/2 = 4 ·10⁻³ A/rpm, I_NLR 0.39 A, 26·1.61
        (80, 2e-3, 44.46),  # I_NLR 0.29 A, 26·1.71
        (40, 5.2e-3, 40.3),  # 6 − 4·10/50 = 5.2 ·10⁻³, I_NLR 0.45 A, 26·1.55
    ],
)
def test_k_inl_interpolated_in_temperature(
    temperature_c: float, k_inl: float, torque_nm: float
) -> None:
    t = _torque(current_a=2.0, output_speed_rpm=50, temperature_c=temperature_c)
    assert t.no_load_current_constant_a_per_rpm == pytest.approx(k_inl, abs=1e-15)
    assert t.output_torque_nm == pytest.approx(torque_nm, abs=1e-9)


@pytest.mark.parametrize("temperature_c", [29.9, 80.1, -10.0])
def test_temperature_outside_30_80_is_refused(temperature_c: float) -> None:
    with pytest.raises(OutOfRangeError) as err:
        _torque(current_a=2.0, output_speed_rpm=50, temperature_c=temperature_c)
    assert err.value.field == "temperature_c"


def test_extrapolation_on_request() -> None:
    # 90 °C: 6 − 4·60/50 = 1.2 ·10⁻³ A/rpm, I_NLR = 0.19 + 0.06 = 0.25 A, T = 26·1.75 = 45.5 Nm
    t = _torque(current_a=2.0, output_speed_rpm=50, temperature_c=90, extrapolate=True)
    assert t.extrapolated
    assert t.output_torque_nm == pytest.approx(45.5, abs=1e-9)
    # 130 °C would give a negative K_INL: it stops at 0.
    k = no_load_current_constant_a_per_rpm(
        temperature_c=130,
        constant_30c_a_per_rpm=6e-3,
        constant_80c_a_per_rpm=2e-3,
        extrapolate=True,
    )
    assert k == 0.0


def test_missing_80c_constant_only_matters_away_from_30c() -> None:
    at_30 = _torque(current_a=2.0, output_speed_rpm=50, k_inl_80c=None)
    assert at_30.output_torque_nm == pytest.approx(39.26)
    with pytest.raises(MissingDataError) as err:
        _torque(current_a=2.0, output_speed_rpm=50, temperature_c=40, k_inl_80c=None)
    assert err.value.field == "no_load_current_constant_80c_a_per_rpm"


def test_negative_current_is_refused() -> None:
    with pytest.raises(InvalidInputError) as err:
        _torque(current_a=-0.1, output_speed_rpm=50)
    assert err.value.field == "current_a"


def test_current_below_no_load_current_is_reported_not_clamped() -> None:
    t = _torque(current_a=0.3, output_speed_rpm=50)
    # 26 · (0.3 − 0.49) = −4.94 Nm
    assert t.output_torque_nm == pytest.approx(-4.94, abs=1e-9)
    assert t.below_no_load_current
    assert "below the no-load running current" in t.message
    exact = _torque(current_a=0.49, output_speed_rpm=50)
    assert exact.output_torque_nm == pytest.approx(0.0, abs=1e-9)


def test_torque_uses_speed_magnitude() -> None:
    fwd = _torque(current_a=2.0, output_speed_rpm=50)
    rev = _torque(current_a=2.0, output_speed_rpm=-50)
    assert rev.output_torque_nm == pytest.approx(fwd.output_torque_nm)
