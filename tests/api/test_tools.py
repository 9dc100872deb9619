"""The engineering tools over HTTP: chapter numbers, independent values, and bad input."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient


def tool(client: TestClient, name: str, body: dict[str, Any]) -> Any:
    return client.post(f"/api/v1/tools/{name}", json=body)


# ------------------------------------------------------------------ Eq. 521.2


def test_controller_voltage_cha_25a_50_from_catalogue(client: TestClient) -> None:
    """5600 rpm × 37 V/1000 rpm + 4.0 A × 3.7 Ω = 207.2 V + 14.8 V = 222.0 V as printed;
    ω·L·I = 2π·6·5600/60 s⁻¹ × 6.0 mH × 4.0 A = 84.4 V in quadrature: 237.5 V."""
    body = tool(client, "controller-voltage", {"model": "CHA-25A-50", "output_speed_rpm": 112})
    assert body.status_code == 200
    out = body.json()
    inductive = 2 * math.pi * 6 * 5600 / 60 * 6.0e-3 * 4.0
    assert out["voltage_v"] == pytest.approx(math.hypot(222.0, inductive))
    assert out["printed_v"] == pytest.approx(222.0)
    assert out["inductive_v"] == pytest.approx(inductive)
    assert out["back_emf_v"] == pytest.approx(207.2)
    assert out["resistive_v"] == pytest.approx(14.8)
    assert out["motor_speed_rpm"] == pytest.approx(-5600)  # the output turns the other way
    buses = {b["bus_class"]: b for b in out["bus_classes"]}
    # Space-vector modulation: U_LL,rms = U_DC / √2.
    assert buses["320vdc"]["available_voltage_v"] == pytest.approx(320 / math.sqrt(2))
    assert buses["320vdc"]["sufficient"] is False  # 226.3 V < 237.5 V (as printed: 222.0 V)
    assert buses["560vdc"]["sufficient"] is True
    assert buses["24vdc"]["sufficient"] is False


def test_controller_voltage_explicit_constants(client: TestClient) -> None:
    body = {
        "output_speed_rpm": 60,
        "gear_ratio": 100,
        "voltage_constant_v_per_krpm": 50,
        "max_current_a": 2,
        "resistance_ohm": 10,
        "inductance_mh": 5,
        "pole_pairs": 4,
    }
    out = tool(client, "controller-voltage", body).json()
    inductive = 2 * math.pi * 4 * 6000 / 60 * 5e-3 * 2
    assert out["voltage_v"] == pytest.approx(math.hypot(6000 * 50 / 1000 + 2 * 10, inductive))
    body["output_speed_rpm"] = 0  # standstill: only the resistive drop
    assert tool(client, "controller-voltage", body).json()["voltage_v"] == pytest.approx(20)
    body |= {"output_speed_rpm": 60, "inductance_mh": 0}  # L = 0: Eq. 521.2 as printed
    assert tool(client, "controller-voltage", body).json()["voltage_v"] == pytest.approx(320)


def test_controller_voltage_says_no_data_instead_of_guessing(client: TestClient) -> None:
    """The FHA-C catalogue gives k_E per output rpm, not the motor K_E per 1000 rpm."""
    response = tool(client, "controller-voltage", {"model": "FHA-17C-50", "output_speed_rpm": 10})
    assert response.status_code == 422
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", "voltage_constant_v_per_krpm"]
    assert error["msg"].startswith("no data")


@pytest.mark.parametrize(
    ("body", "loc"),
    [
        ({"model": "NOPE", "output_speed_rpm": 10}, ["body", "model"]),
        ({"output_speed_rpm": 10}, ["body", "gear_ratio"]),
        ({"model": "CHA-25A-50", "output_speed_rpm": -1}, ["body", "output_speed_rpm"]),
        (
            {"model": "CHA-25A-50", "output_speed_rpm": 10, "max_current_a": -1},
            ["body", "max_current_a"],
        ),
    ],
)
def test_controller_voltage_bad_input(
    client: TestClient, body: dict[str, Any], loc: list[str]
) -> None:
    response = tool(client, "controller-voltage", body)
    assert 400 <= response.status_code < 500
    assert loc in [e["loc"] for e in response.json()["detail"]]


# ------------------------------------------------------------------ sensors


def test_kty_940_ohm_on_fha_c_is_shutdown(client: TestClient) -> None:
    body = {"sensor": "KTY84-130", "resistance_ohm": 940, "family": "FHA-C"}
    out = tool(client, "sensor-temperature", body).json()
    assert out["temperature_c"] == pytest.approx(90.0)
    assert out["state"] == "shutdown"


@pytest.mark.parametrize(
    ("family", "resistance", "temperature", "state"),
    [
        # Table 519.2, column FHA/CHA: warning 80 °C = 882 Ω, shutdown 90 °C = 940 Ω.
        ("CHA", 881.0, 70 + 10 * (881 - 826) / (882 - 826), "normal"),  # 70 °C = 826 Ω
        ("CHA", 882.0, 80.0, "warning"),
        ("CHA", 911.0, 85.0, "warning"),  # midpoint of 882 and 940 Ω
        ("FHA-C", 1000.0, 100.0, "shutdown"),  # R100 of the datasheet
        # Column FFA/FPA/CHM/LynxDrive/TorkDrive: 120 °C = 1127 Ω, 140 °C = 1262 Ω.
        ("TorkDrive", 1127.0, 120.0, "warning"),
        ("LynxDrive", (1127 + 1194) / 2, 125.0, "warning"),  # midpoint of 120 and 130 °C
        ("TorkDrive", 1262.0, 140.0, "shutdown"),
        ("CHM", 1062.0, 110.0, "normal"),
    ],
)
def test_kty_against_both_limit_columns(
    client: TestClient, family: str, resistance: float, temperature: float, state: str
) -> None:
    body = {"sensor": "KTY 84-130", "resistance_ohm": resistance, "family": family}
    out = tool(client, "sensor-temperature", body).json()
    assert out["temperature_c"] == pytest.approx(temperature, abs=1e-9)
    assert out["state"] == state


def test_kty_without_family_gives_temperature_only(client: TestClient) -> None:
    out = tool(client, "sensor-temperature", {"sensor": "kty84_130", "resistance_ohm": 603}).json()
    # Between 20 °C = 581 Ω and 30 °C = 626 Ω (the datasheet prints 25 °C = 603 Ω).
    assert out["temperature_c"] == pytest.approx(20 + 10 * (603 - 581) / (626 - 581))
    assert out["temperature_c"] == pytest.approx(25, abs=0.2)
    assert out["state"] is None


@pytest.mark.parametrize(
    ("resistance", "zone", "state"),
    [
        (250.0, "below", "normal"),
        (1000.0, "around", "warning"),
        (1330.0, "above", "shutdown"),
        (4000.0, "far_above", "shutdown"),
    ],
)
def test_ptc_on_fha_c_tells_a_zone_never_a_temperature(
    client: TestClient, resistance: float, zone: str, state: str
) -> None:
    """FHA-C-L: PTC 116-K13-145 °C (Table 518.1); DIN 44081: 550 Ω at T_NAT − 5 K, 1330 at +5 K."""
    body = {"sensor": "PTC", "resistance_ohm": resistance, "family": "FHA-C"}
    out = tool(client, "sensor-temperature", body).json()
    assert out["temperature_c"] is None
    assert out["ptc"]["zone"] == zone
    assert out["ptc"]["nominal_response_temperature_c"] == 145
    assert out["state"] == state


def test_ptc_triplet_of_torkdrive_divides_by_three(client: TestClient) -> None:
    """3 × PTC (130 °C) in series: 3 × 1330 Ω is the +5 K point of the string."""
    body = {"sensor": "PTC", "resistance_ohm": 3 * 1330, "family": "TorkDrive"}
    out = tool(client, "sensor-temperature", body).json()
    assert out["ptc"]["resistance_per_sensor_ohm"] == pytest.approx(1330)
    assert out["ptc"]["zone"] == "above"
    body["resistance_ohm"] = 3 * 1000
    assert tool(client, "sensor-temperature", body).json()["ptc"]["zone"] == "around"


@pytest.mark.parametrize(
    ("body", "loc"),
    [
        ({"sensor": "PT100", "resistance_ohm": 100}, ["body", "sensor"]),
        ({"sensor": "KTY84-130", "resistance_ohm": 300}, ["body", "resistance_ohm"]),  # < −40 °C
        ({"sensor": "KTY84-130", "resistance_ohm": 2700}, ["body", "resistance_ohm"]),  # > 300 °C
        ({"sensor": "KTY84-130", "resistance_ohm": -5}, ["body", "resistance_ohm"]),
        ({"sensor": "PTC", "resistance_ohm": 500}, ["body", "nominal_response_temperature_c"]),
        (
            {"sensor": "PTC", "resistance_ohm": 500, "family": "CHA"},
            ["body", "nominal_response_temperature_c"],
        ),  # CHA: 120 °C or 145 °C by size
        ({"sensor": "KTY84-130", "resistance_ohm": 900, "family": "XYZ"}, ["body", "family"]),
    ],
)
def test_sensor_bad_input(client: TestClient, body: dict[str, Any], loc: list[str]) -> None:
    response = tool(client, "sensor-temperature", body)
    assert 400 <= response.status_code < 500
    assert loc in [e["loc"] for e in response.json()["detail"]], response.json()


# ------------------------------------------------------------------ overload


def test_overload_duration_from_cold_and_preloaded(client: TestClient) -> None:
    out = tool(
        client, "overload-duration", {"overload_factor": 2.0, "thermal_time_constant_s": 600}
    ).json()
    assert out["time_to_shutdown_s"] == pytest.approx(172.6, abs=0.05)  # 600 · ln(4/3)
    preloaded = tool(
        client,
        "overload-duration",
        {
            "overload_factor": 2.0,
            "thermal_time_constant_s": 600,
            "preload_factor": 0.5,
        },
    ).json()
    assert preloaded["time_to_shutdown_s"] == pytest.approx(600 * math.log(3.75 / 3))


def test_overload_curve_up_to_catalogue_ratio(client: TestClient) -> None:
    """CHA-25A-50: I_max/I_0 = 4.0 A / 2.3 A; τ_th is not published, so it is given."""
    out = tool(
        client,
        "overload-duration",
        {
            "overload_factor": 1.5,
            "model": "CHA-25A-50",
            "thermal_time_constant_s": 900,
        },
    ).json()
    curve = out["curve"]
    assert curve[-1]["overload_factor"] == pytest.approx(4.0 / 2.3)
    assert all(p["overload_factor"] > 1 for p in curve)
    times = [p["time_to_shutdown_s"] for p in curve]
    assert times == sorted(times, reverse=True)  # more overload, less time
    k = curve[-1]["overload_factor"]
    assert times[-1] == pytest.approx(900 * math.log(k**2 / (k**2 - 1)))


@pytest.mark.parametrize(
    ("body", "loc"),
    [
        ({"overload_factor": 1.0, "thermal_time_constant_s": 600}, ["body", "overload_factor"]),
        ({"overload_factor": 0.5, "thermal_time_constant_s": 600}, ["body", "overload_factor"]),
        ({"overload_factor": 2.0}, ["body", "thermal_time_constant_s"]),
        ({"overload_factor": 2.0, "model": "CHA-25A-50"}, ["body", "thermal_time_constant_s"]),
        (
            {"overload_factor": 2.0, "thermal_time_constant_s": -1},
            ["body", "thermal_time_constant_s"],
        ),
        (
            {"overload_factor": 2.0, "thermal_time_constant_s": 600, "preload_factor": 1.5},
            ["body", "preload_factor"],
        ),
        (
            {"overload_factor": 2.0, "model": "NOPE", "thermal_time_constant_s": 1},
            ["body", "model"],
        ),
    ],
)
def test_overload_bad_input(client: TestClient, body: dict[str, Any], loc: list[str]) -> None:
    response = tool(client, "overload-duration", body)
    assert 400 <= response.status_code < 500
    assert loc in [e["loc"] for e in response.json()["detail"]], response.json()


# ------------------------------------------------------------------ Eq. 522.2/522.3


def test_output_torque_cha_25a_50_at_30_c(client: TestClient) -> None:
    body = {"model": "CHA-25A-50", "current_a": 2.0, "speed_rpm": 50, "temperature_c": 30}
    out = tool(client, "output-torque", body).json()
    assert out["no_load_current_a"] == pytest.approx(0.49)  # 0.19 A + 6e-3 A/rpm · 50 rpm
    assert out["torque_nm"] == pytest.approx(39.26)  # 26.0 Nm/A · 1.51 A
    assert out["motor_speed_rpm"] == pytest.approx(-2500)


@pytest.mark.parametrize(
    ("temperature", "k_inl"),
    [(80.0, 2e-3), (55.0, 4e-3), (42.5, 5e-3)],  # 6 → 2 mA/rpm linearly over 30…80 °C
)
def test_output_torque_interpolates_k_inl(
    client: TestClient, temperature: float, k_inl: float
) -> None:
    body = {"model": "CHA-25A-50", "current_a": 2.0, "speed_rpm": 50, "temperature_c": temperature}
    out = tool(client, "output-torque", body).json()
    assert out["no_load_current_constant_a_per_rpm"] == pytest.approx(k_inl)
    assert out["torque_nm"] == pytest.approx(26.0 * (2.0 - 0.19 - k_inl * 50))


def test_output_torque_refuses_outside_30_to_80_c_unless_asked(client: TestClient) -> None:
    body = {"model": "CHA-25A-50", "current_a": 2.0, "speed_rpm": 50, "temperature_c": 90}
    response = tool(client, "output-torque", body)
    assert response.status_code == 422
    assert ["body", "temperature_c"] in [e["loc"] for e in response.json()["detail"]]
    body["extrapolate"] = True
    out = tool(client, "output-torque", body).json()
    assert out["extrapolated"] is True
    assert out["no_load_current_constant_a_per_rpm"] == pytest.approx(6e-3 - 4e-3 / 50 * 60)


def test_output_torque_below_no_load_current_is_reported(client: TestClient) -> None:
    body = {"model": "CHA-25A-50", "current_a": 0.3, "speed_rpm": 50}
    out = tool(client, "output-torque", body).json()
    assert out["below_no_load_current"] is True
    assert out["torque_nm"] == pytest.approx(26.0 * (0.3 - 0.49))


@pytest.mark.parametrize(
    ("body", "loc"),
    [
        ({"model": "CHA-25A-50", "current_a": -1, "speed_rpm": 50}, ["body", "current_a"]),
        ({"model": "NOPE", "current_a": 1, "speed_rpm": 50}, ["body", "model"]),
        ({"current_a": 1, "speed_rpm": 50}, ["body", "torque_constant_nm_per_a"]),
        (
            {"model": "FHA-17C-50", "current_a": 1, "speed_rpm": 5},
            ["body", "no_load_starting_current_a"],
        ),
    ],
)
def test_output_torque_bad_input(client: TestClient, body: dict[str, Any], loc: list[str]) -> None:
    response = tool(client, "output-torque", body)
    assert 400 <= response.status_code < 500
    assert loc in [e["loc"] for e in response.json()["detail"]], response.json()
