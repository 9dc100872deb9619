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
    # the FHA-C catalogue gives no winding constants for the drive's voltage (K_E in V_rms)
    assert pause["verdict"] == "unconfirmed"
    # the flowchart itself: just inside every check passes, just beyond the limiting one fails
    inside = body | {"cycle": body["cycle"] | {"pause_s": pause["value"] * (1 + 1e-6)}}
    beyond = body | {"cycle": body["cycle"] | {"pause_s": pause["value"] * (1 - 1e-6)}}
    inside_checks = checks_at(client, inside, "FHA-25C-50")
    assert inside_checks.pop("drive_voltage") == "no_data"
    assert set(inside_checks.values()) == {"pass"}
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
    shorthand = limits(client, worked_example.request() | {"model": "FHA-25C-50"})
    # t_1 is the first segment's duration, a ramp from standstill as in the chapter's cycle
    assert found["accel_s"]["value"] == pytest.approx(shorthand["accel_s"]["value"], rel=1e-8)
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


def test_a_stored_candidates_limits_equal_the_posted_ones(client: TestClient) -> None:
    body = worked_example.request()
    created = client.post(API, json=body)
    assert created.status_code == 201
    selection_id = created.json()["id"]
    stored = client.get(f"{API}/{selection_id}/candidates/FHA-25C-50/limits")
    assert stored.status_code == 200, stored.text
    posted = client.post(f"{API}/limits", json=body | {"model": "FHA-25C-50"})
    assert stored.json() == posted.json()
    missing = client.get(f"{API}/{selection_id}/candidates/NO-SUCH/limits")
    assert missing.status_code == 404
    assert missing.json()["detail"][0]["loc"] == ["path", "model"]
    unknown = client.get(f"{API}/00000000-0000-0000-0000-000000000000/candidates/FHA-25C-50/limits")
    assert unknown.status_code == 404


# Issue 29 item 6: a belt axis (a mechanism with the t_1…t_p cycle, which the core sizes as a
# cycle of segments) lost its shortest-t_1 row without a word.
BELT_AXIS: dict[str, Any] = {
    "load": {
        "type": "belt",
        "mass_kg": 15.0,
        "pulley_diameter_mm": 60,
        "friction_coefficient": 0.1,
        "efficiency": 0.9,
        "speed": 500,
    },
    "cycle": {"accel_s": 0.2, "constant_s": 0.5, "decel_s": 0.2, "pause_s": 0.5},
}


def test_a_belt_axis_has_its_shortest_t1_from_the_flowchart(client: TestClient) -> None:
    """The row is there, and the flowchart agrees: just above it no check fails, just below
    it the limiting check does."""
    selection = client.post(API, json=BELT_AXIS)
    assert selection.status_code == 201, selection.text
    model = next(c["model"] for c in selection.json()["candidates"] if c["verdict"] != "unsuitable")
    found = limits(client, BELT_AXIS | {"model": model})
    assert set(found) == {"pause_s", "accel_s", "load_inertia_kgm2"}
    accel = found["accel_s"]
    assert accel["value"] is not None
    assert accel["reason"] is None
    limiting = [c["name"] for c in accel["limiting_checks"]]
    assert limiting
    at = BELT_AXIS["cycle"]
    inside = BELT_AXIS | {"cycle": at | {"accel_s": accel["value"] * (1 + 1e-6)}}
    beyond = BELT_AXIS | {"cycle": at | {"accel_s": accel["value"] * (1 - 1e-6)}}
    assert "fail" not in checks_at(client, inside, model).values()
    assert checks_at(client, beyond, model)[limiting[0]] == "fail"


def test_a_limit_that_cannot_be_solved_says_why_in_both_languages(client: TestClient) -> None:
    """No value, and the reason as a code, its params and words: a cycle that does not
    start with a ramp from standstill has no t_1; a speed above n_max fails at any t_1."""
    body = {
        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {
            "segments": [
                {"duration_s": 0.2},
                {"speed": 40, "duration_s": 0.1},
                {"speed": 0, "duration_s": 0.1},
                {"duration_s": 1.0},
            ]
        },
        "model": "FHA-25C-50",
    }
    accel = limits(client, body)["accel_s"]
    assert accel["value"] is None
    assert accel["reason_code"] == "limit.accel_no_ramp"
    assert "standstill" in accel["reason"]
    german = client.post(f"{API}/limits", json=body, headers={"Accept-Language": "de"})
    reason_de = {x["quantity"]: x for x in german.json()["limits"]}["accel_s"]["reason"]
    assert reason_de
    assert "Stillstand" in reason_de
    too_fast = worked_example.request() | {"model": "FHA-25C-50"}
    too_fast["load"] = too_fast["load"] | {"speed_rpm": 1000}
    found = limits(client, too_fast)
    for quantity in ("accel_s", "pause_s"):
        row = found[quantity]
        assert row["value"] is None
        assert row["reason_code"] == "limit.none.min"
        assert row["reason_params"]["value"] == 86_400
        assert row["reason_params"]["check"]["code"] == "max_speed.fail"
        assert "max_speed" in [c["name"] for c in row["limiting_checks"]]
        assert "86400" in row["reason"].replace(" ", "").replace("\u202f", "")
