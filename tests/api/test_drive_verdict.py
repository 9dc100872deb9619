"""Issue 28, "A verdict an application engineer signs": an actuator is suitable only if a
controller that Table 521.1 lists for it delivers the voltage the axis needs (item 1),
and that voltage is one answer, Eq. 521.2 with the inductive drop, wherever it is asked:
the selection's check, each controller's check and the voltage tool (item 2).

Reference values from first principles: the belt's speed n_2 = v/r, Eq. 521.2 written out
with the CHA tables' constants (CHA-14A-E-30: K_E 3 V/1000 rpm, I_max 7.4 A, R 0.42 Ω,
L 0.35 mH, p = 5; CHA-58A-50: K_E 105 V/1000 rpm, I_max 14.4 A, R 2.4 Ω, L 9 mH, p = 6)
and the space-vector limit U_DC/√2."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

API = "/api/v1/selections"

BELT_AXIS: dict[str, Any] = {
    "load": {
        "type": "belt",
        "mass_kg": 15.0,
        "pulley_diameter_mm": 60,
        "friction_coefficient": 0.05,
        "efficiency": 0.9,
    },
    "cycle": {
        "segments": [  # out and back at 0.5 m/s
            {"speed": 500, "duration_s": 0.2},
            {"duration_s": 0.4},
            {"speed": 0, "duration_s": 0.2},
            {"duration_s": 0.5},
            {"speed": -500, "duration_s": 0.2},
            {"duration_s": 0.4},
            {"speed": 0, "duration_s": 0.2},
            {"duration_s": 0.5},
        ]
    },
}
"""The issue's belt axis: 15 kg on a 60 mm pulley at 0.5 m/s, horizontal."""

SPEED_RPM = 0.5 / 0.030 * 60 / (2 * math.pi)
"""n_2 = v/r = 0.5 m/s / 30 mm = 16.67 rad/s = 159.2 rpm."""


def needed_v(
    speed_rpm: float, ratio: float, k_e: float, i_max: float, r: float, l_h: float, p: float
) -> float:
    """√((n·i·K_E/1000 + I·R)² + (2π·p·n·i/60·L·I)²), written out."""
    motor = speed_rpm * ratio
    return math.hypot(motor * k_e / 1000 + i_max * r, 2 * math.pi * p * motor / 60 * l_h * i_max)


def created(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    return answer


def by_name(checks: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    return {c["name"]: c for c in checks}


def candidate(answer: dict[str, Any], model: str) -> dict[str, Any]:
    found: dict[str, Any] = next(c for c in answer["candidates"] if c["model"] == model)
    return found


# --- item 1: "suitable" only with a listed controller that can run the axis -----------------


def test_the_belt_axis_is_not_suitable_on_an_actuator_no_listed_controller_can_drive(
    client: TestClient,
) -> None:
    """CHA-14A-E-30 runs on the 24 V bus only: at n_2 = 159.2 rpm it needs 18.60 V (Eq.
    521.2 as printed: 17.43 V), every listed controller delivers 24/√2 = 16.97 V. Without
    ``drive`` it was ranked first, "suitable, all checks passed"."""
    answer = created(client, BELT_AXIS)
    assert answer["load"]["speed_rpm"] == pytest.approx(SPEED_RPM)
    small = candidate(answer, "CHA-14A-E-30")
    assert small["verdict"] == "unsuitable"
    failed = [c for c in small["checks"] if c["status"] != "pass"]
    assert [c["name"] for c in failed] == ["drive_voltage"]  # the quantity that binds
    (voltage,) = failed
    assert voltage["status"] == "fail"
    expected = needed_v(SPEED_RPM, 30, 3, 7.4, 0.42, 0.35e-3, 5)
    assert voltage["value"] == pytest.approx(expected, rel=1e-12)
    assert voltage["value"] == pytest.approx(18.60, abs=0.005)
    assert voltage["limit"] == pytest.approx(24 / math.sqrt(2), rel=1e-12)
    # The top candidate is suitable, and a listed controller drives it.
    best = answer["candidates"][0]
    assert best["verdict"] == "suitable"
    assert by_name(best["checks"])["drive_voltage"]["status"] == "pass"
    assert any(g["voltage"]["status"] == "pass" for g in best["drive_options"])
    # The candidate's detail words the failure, naming the voltages, and the controllers
    # listed under it say the same, with the same number.
    detail = client.get(f"{API}/{answer['id']}/candidates/CHA-14A-E-30").json()
    assert detail["verdict"] == "unsuitable"
    words = by_name(detail["checks"])["drive_voltage"]["message"]
    assert f"{voltage['value']:.4g} V_rms" in words
    assert "exceeds 16.97 V_rms from a 24 V DC bus" in words
    assert detail["controllers"], "Table 521.1 lists controllers for it"
    for controller in detail["controllers"]:
        assert controller["voltage"]["status"] == "fail"
        assert controller["voltage"]["value"] == voltage["value"]
        assert controller["voltage"]["limit"] == voltage["limit"]


def test_a_slower_belt_axis_is_suitable_on_the_same_actuator(client: TestClient) -> None:
    """The pass side: at 0.4 m/s (n_2 = 127.3 rpm) CHA-14A-E-30 needs 14.87 V ≤ 16.97 V."""
    slow = {
        **BELT_AXIS,
        "cycle": {
            "segments": [
                {**s, "speed": s["speed"] * 0.8} if "speed" in s else s
                for s in BELT_AXIS["cycle"]["segments"]
            ]
        },
        "models": ["CHA-14A-E-30"],
    }
    (small,) = created(client, slow)["candidates"]
    voltage = by_name(small["checks"])["drive_voltage"]
    expected = needed_v(SPEED_RPM * 0.8, 30, 3, 7.4, 0.42, 0.35e-3, 5)
    assert voltage["value"] == pytest.approx(expected, rel=1e-12)
    assert voltage["value"] < voltage["limit"]
    assert voltage["status"] == "pass"
    assert small["verdict"] == "suitable"


def test_the_batch_and_the_limits_agree_with_the_single_answer(client: TestClient) -> None:
    """The batch's top 3 leaves CHA-14A-E-30 out, and its candidates equal the single
    selection's (the scalar flowchart's) with ==; the limits see the same failure."""
    single = created(client, BELT_AXIS)
    response = client.post(
        f"{API}/batch", json={"cases": [BELT_AXIS], "top": 3, "include_messages": True}
    )
    assert response.status_code == 200, response.text
    (result,) = response.json()["results"]
    top = [c["model"] for c in result["candidates"]]
    assert "CHA-14A-E-30" not in top
    assert top == [c["model"] for c in single["candidates"][:3]]
    both = {**BELT_AXIS, "models": ["CHA-14A-E-30", "CHA-20A-30"]}
    response = client.post(
        f"{API}/batch", json={"cases": [both], "top": 2, "include_messages": True}
    )
    (result,) = response.json()["results"]
    alone = created(client, both)
    for got in result["candidates"]:
        detail = client.get(f"{API}/{alone['id']}/candidates/{got['model']}").json()
        assert got["verdict"] == detail["verdict"]
        assert got["checks"] == detail["checks"]
    assert [c["verdict"] for c in result["candidates"]] == ["suitable", "unsuitable"]
    limits = client.post(f"{API}/limits", json={**BELT_AXIS, "model": "CHA-14A-E-30"})
    assert limits.status_code == 200, limits.text
    for limit in limits.json()["limits"]:
        assert limit["verdict"] != "suitable", limit


def test_with_drive_sizing_the_verdict_is_the_same(client: TestClient) -> None:
    """``drive`` adds the current check; the voltage check is the same either way."""
    plain = candidate(created(client, BELT_AXIS), "CHA-14A-E-30")
    sized = candidate(created(client, {**BELT_AXIS, "drive": True}), "CHA-14A-E-30")
    assert sized["verdict"] == plain["verdict"] == "unsuitable"
    assert by_name(sized["checks"])["drive_voltage"] == by_name(plain["checks"])["drive_voltage"]
    assert "drive_current" in by_name(sized["checks"])
    assert "drive_current" not in by_name(plain["checks"])


# --- item 2: one formula for the voltage --------------------------------------------------------


def test_the_voltage_tool_includes_the_inductive_drop_and_agrees_with_the_selection(
    client: TestClient,
) -> None:
    """CHA-58A-50 at 60 rpm: 426.5 V with ω·L·I in quadrature, more than the 396.0 V of the
    560 V bus; the tool said 349.6 V, sufficient. The selection's check, its controllers'
    checks and the tool give the same number (==)."""
    response = client.post(
        "/api/v1/tools/controller-voltage", json={"model": "CHA-58A-50", "output_speed_rpm": 60}
    )
    assert response.status_code == 200, response.text
    tool = response.json()
    expected = needed_v(60, 50, 105, 14.4, 2.4, 9e-3, 6)
    assert tool["voltage_v"] == pytest.approx(expected, rel=1e-12)
    assert tool["voltage_v"] == pytest.approx(426.5, abs=0.05)
    assert tool["printed_v"] == pytest.approx(3000 * 0.105 + 14.4 * 2.4, rel=1e-12)
    assert tool["inductive_v"] == pytest.approx(2 * math.pi * 6 * 3000 / 60 * 9e-3 * 14.4)
    assert (tool["inductance_mh"], tool["pole_pairs"]) == (9, 6)
    buses = {b["bus_class"]: b for b in tool["bus_classes"]}
    assert buses["560vdc"]["sufficient"] is False
    assert buses["560vdc"]["available_voltage_v"] == pytest.approx(560 / math.sqrt(2))
    body = {
        "load": {"speed_rpm": 60, "torque_nm": 50, "inertia_kgm2": 5},
        "cycle": {"accel_s": 0.2, "constant_s": 0.5, "decel_s": 0.2, "pause_s": 1.0},
        "models": ["CHA-58A-50"],
    }
    (c,) = created(client, body)["candidates"]
    voltage = by_name(c["checks"])["drive_voltage"]
    assert voltage["value"] == tool["voltage_v"]
    assert voltage["limit"] == buses["560vdc"]["available_voltage_v"]
    assert voltage["status"] == "fail"
    assert c["verdict"] == "unsuitable"
    slower = client.post(
        "/api/v1/tools/controller-voltage", json={"model": "CHA-58A-50", "output_speed_rpm": 40}
    ).json()
    assert {b["bus_class"]: b["sufficient"] for b in slower["bus_classes"]}["560vdc"] is True


def test_the_voltage_tool_names_the_inductance_it_lacks(client: TestClient) -> None:
    body = {
        "output_speed_rpm": 60,
        "gear_ratio": 100,
        "voltage_constant_v_per_krpm": 50,
        "max_current_a": 2,
        "resistance_ohm": 10,
    }
    response = client.post("/api/v1/tools/controller-voltage", json=body)
    assert response.status_code == 422
    assert ["body", "inductance_mh"] in [e["loc"] for e in response.json()["detail"]]
    bad = client.post("/api/v1/tools/controller-voltage", json={**body, "pole_pairs": 0})
    assert bad.status_code == 422
    assert ["body", "pole_pairs"] in [e["loc"] for e in bad.json()["detail"]]
