"""POST /selections/limits: the inverse solve against first principles and against the
flowchart itself (just inside the limit no check fails, just beyond the limiting one does)."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example

API = "/api/v1/selections"
OMEGA_2 = 2 * math.pi / 60 * 40  # the worked example's n_2 = 40 rpm [rad/s]


def limits(client: TestClient, body: dict[str, Any]) -> dict[str, dict[str, Any]]:
    response = client.post(f"{API}/limits", json=body)
    assert response.status_code == 200, response.text
    return {x["quantity"]: x for x in response.json()["limits"]}


def checks_at(client: TestClient, body: dict[str, Any], model: str) -> dict[str, str]:
    response = client.post(API, json=body | {"models": [model]})
    assert response.status_code == 201, response.text
    return {c["name"]: c["status"] for c in response.json()["candidates"][0]["checks"]}


def actuator(client: TestClient, model: str) -> dict[str, Any]:
    data: dict[str, Any] = client.get(f"/api/v1/actuators/{model}").json()
    return data


def test_the_shortest_pause_of_the_worked_example_on_fha_25c_50(client: TestClient) -> None:
    """The issue's case: T_rms² = (T_1²·t_1 + T_L²·t_2 + T_3²·t_3)/(t_1 + t_2 + t_3 + t_p)
    reaches the allowable continuous torque T_c at t_p = E/T_c² − 0.3 s; the winding's
    heating peak (thermal_peak, τ_th assumed 600 s) lies a little above T_rms, so the limit
    lies a little beyond, and tends to that value as τ_th grows."""
    body = worked_example.request()
    a = actuator(client, "FHA-25C-50")
    j = a["inertia_kgm2"] + 1.3
    t_1 = 5 + j * OMEGA_2 / 0.1
    t_3 = 5 - j * OMEGA_2 / 0.1
    energy = (t_1 * t_1 + 5 * 5 + t_3 * t_3) * 0.1
    by_rms = energy / a["continuous_torque_nm"] ** 2 - 0.3
    pause = limits(client, body | {"model": "FHA-25C-50"})["pause_s"]
    assert by_rms < pause["value"] < by_rms * 1.005
    assert [c["name"] for c in pause["limiting_checks"]] == ["thermal_peak"]
    assert pause["limiting_checks"][0]["reference"]
    assert pause["verdict"] == "suitable"
    # the flowchart itself: just inside every check passes, just beyond the limiting one fails
    inside = body | {"cycle": body["cycle"] | {"pause_s": pause["value"] * (1 + 1e-6)}}
    beyond = body | {"cycle": body["cycle"] | {"pause_s": pause["value"] * (1 - 1e-6)}}
    assert set(checks_at(client, inside, "FHA-25C-50").values()) == {"pass"}
    assert checks_at(client, beyond, "FHA-25C-50")["thermal_peak"] == "fail"
    # a winding slow against the cycle (τ_th = 1 day): T_rms decides, to first principles
    slow = limits(client, body | {"model": "FHA-25C-50", "thermal_time_constant_s": 86_400})[
        "pause_s"
    ]
    assert slow["value"] == pytest.approx(by_rms, rel=1e-4)


def test_acceleration_and_inertia_limits_from_first_principles(client: TestClient) -> None:
    """On the chapter's FHA-25C-50-L (no continuous data): t_1 is bound by T_1 = T_max,
    t_1 = (J_A + J_L)·ω_2/(T_max − T_L); J_L by the inertia ratio, 3·J_A."""
    found = limits(client, worked_example.request() | {"model": "FHA-25C-50-L"})
    a = actuator(client, "FHA-25C-50-L")
    accel = found["accel_s"]
    expected = (a["inertia_kgm2"] + 1.3) * OMEGA_2 / (a["max_torque_nm"] - 5)
    assert accel["value"] == pytest.approx(expected, rel=1e-8)
    assert [c["name"] for c in accel["limiting_checks"]] == ["peak_torque"]
    assert accel["verdict"] == "unconfirmed"  # continuous duty lacks data on this entry
    inertia = found["load_inertia_kgm2"]
    assert inertia["value"] == pytest.approx(3 * a["inertia_kgm2"], rel=1e-8)
    assert [c["name"] for c in inertia["limiting_checks"]] == ["inertia_ratio"]
    assert found["pause_s"]["value"] == 0.0  # nothing that a pause relieves can fail here
    assert found["pause_s"]["limiting_checks"] == []


def test_limits_of_a_cycle_of_segments_vary_its_last_dwell(client: TestClient) -> None:
    body = {
        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {
            "segments": [
                {"speed": 40, "duration_s": 0.1},
                {"duration_s": 0.1},
                {"speed": 0, "duration_s": 0.1},
                {"duration_s": 1.0},
            ]
        },
        "model": "FHA-25C-50",
    }
    found = limits(client, body)
    assert "accel_s" not in found  # t_1 is solved for the chapter's cycle
    shorthand = limits(client, worked_example.request() | {"model": "FHA-25C-50"})
    assert found["pause_s"] == shorthand["pause_s"]
    assert found["load_inertia_kgm2"] == shorthand["load_inertia_kgm2"]


@pytest.mark.parametrize(
    ("change", "loc"),
    [
        ({"model": "NO-SUCH-ACTUATOR"}, ["body", "model"]),
        ({"model": ""}, ["body", "model"]),
        (
            {
                "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
                "cycle": {
                    "segments": [{"speed": 40, "duration_s": 1}, {"speed": 0, "duration_s": 1}]
                },
            },
            ["body", "cycle", "segments"],
        ),
    ],
)
def test_a_bad_limits_request_is_a_422_naming_the_field(
    client: TestClient, change: dict[str, Any], loc: list[str]
) -> None:
    body = worked_example.request() | {"model": "FHA-25C-50"} | change
    response = client.post(f"{API}/limits", json=body)
    assert response.status_code == 422, response.text
    assert [str(x) for x in response.json()["detail"][0]["loc"]] == loc
