"""Mechanisms over the API, as a machine designer sizes them: a vertical pick-and-place axis
on a belt with a two-move cycle, a ball-screw axis in mm/s behind a reduction, units at the
edge, and bad values answered 422 with the field named."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

API = "/api/v1/selections"
G = 9.81

PICK_AND_PLACE: dict[str, Any] = {
    "load": {
        "type": "belt",
        "mass_kg": 4.0,
        "pulley_diameter_mm": 50,
        "friction_coefficient": 0.0,
        "efficiency": 0.9,
        "incline_deg": 90,
        "transmission": {"ratio": 1.5, "efficiency": 1.0},
    },
    "cycle": {
        "segments": [  # down 180 mm to pick, up 180 mm to place (two moves), in mm/s
            {"speed": -300, "duration_s": 0.2},
            {"duration_s": 0.4},
            {"speed": 0, "duration_s": 0.2},
            {"duration_s": 0.3},
            {"speed": 300, "duration_s": 0.2, "jerk_share": 0.5},
            {"duration_s": 0.4},
            {"speed": 0, "duration_s": 0.2, "jerk_share": 0.5},
            {"duration_s": 0.5},
        ]
    },
    "brake": True,
}


def created(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    return answer


def test_a_vertical_pick_and_place_belt_axis_is_sized_end_to_end(client: TestClient) -> None:
    answer = created(client, PICK_AND_PLACE)
    r, i, m = 0.025, 1.5, 4.0
    # first principles: the weight at the pulley through the ratio, v = ω·r
    assert answer["load"]["gravity_torque_nm"] == pytest.approx(m * G * r / i)
    assert answer["load"]["inertia_kgm2"] == pytest.approx(m * r * r / (i * i))
    assert answer["load"]["efficiency"] == pytest.approx(0.9)
    speed_rpm = 300 / 1000 / r * 60 / (2 * math.pi) * i
    assert answer["load"]["speed_rpm"] == pytest.approx(speed_rpm)
    assert answer["segments"][0]["end_rpm"] == pytest.approx(-speed_rpm)
    assert answer["cycle_time_s"] == pytest.approx(2.4)
    verdicts = {c["verdict"] for c in answer["candidates"]}
    assert "suitable" in verdicts
    best = answer["candidates"][0]
    assert best["verdict"] == "suitable"
    brake = next(c for c in best["checks"] if c["name"] == "brake_holding")
    assert brake["value"] == pytest.approx(m * G * r / i)  # the weight held at rest
    detail = client.get(f"{API}/{answer['id']}/candidates/{best['model']}").json()
    assert len(detail["segment_torques"]) == len(PICK_AND_PLACE["cycle"]["segments"])
    # lowering at constant speed the weight drives back: T_G·η; lifting: T_G/η
    runs = {s["segment"]: s["torques_nm"][0] for s in detail["segment_torques"]}
    weight = m * G * r / i
    assert runs[1] == pytest.approx(weight * 0.9)
    assert runs[5] == pytest.approx(weight / 0.9)


def test_a_ball_screw_at_300_mm_per_s_fits_behind_a_reduction(client: TestClient) -> None:
    """The new user's axis from the issue: 300 mm/s on a 10 mm lead is 1,800 rpm at the
    screw, beyond every actuator; a 1:10 belt up-ratio brings the output to 180 rpm."""
    axis = {
        "type": "ball_screw_incline",
        "mass_kg": 50,
        "lead_mm": "10 mm",
        "friction_coefficient": 0.05,
        "efficiency": 0.9,
        "speed": "300 mm/s",
    }
    cycle = {"accel_s": 0.1, "constant_s": 0.5, "decel_s": 0.1, "pause_s": 0.5}
    direct = created(client, {"load": axis, "cycle": cycle})
    assert direct["load"]["speed_rpm"] == pytest.approx(1800)
    assert {c["verdict"] for c in direct["candidates"]} == {"unsuitable"}
    geared = created(client, {"load": axis | {"transmission": {"ratio": 0.1}}, "cycle": cycle})
    assert geared["load"]["speed_rpm"] == pytest.approx(180)
    assert any(c["verdict"] != "unsuitable" for c in geared["candidates"])
    # the same axis in inches answers the same numbers
    imperial = created(
        client,
        {
            "load": axis
            | {"lead_mm": "0.3937007874015748 in", "speed": "11.811023622047244 in/s"}
            | {"transmission": {"ratio": 0.1}},
            "cycle": cycle,
        },
    )
    assert imperial["load"] == pytest.approx(geared["load"])
    assert [c["model"] for c in imperial["candidates"]] == [
        c["model"] for c in geared["candidates"]
    ]


@pytest.mark.parametrize(
    ("change", "loc"),
    [
        ({"pulley_diameter_mm": -5}, ["body", "load", "belt", "pulley_diameter_mm"]),
        ({"pulley_diameter_mm": "5 kg"}, ["body", "load", "belt", "pulley_diameter_mm"]),
        ({"efficiency": 1.5}, ["body", "load", "belt", "efficiency"]),
        ({"transmission": {"ratio": 0}}, ["body", "load", "belt", "transmission", "ratio"]),
        ({"type": "crane"}, ["body", "load"]),
    ],
)
def test_a_bad_mechanism_value_is_a_422_naming_it(
    client: TestClient, change: dict[str, Any], loc: list[str]
) -> None:
    body = PICK_AND_PLACE | {"load": PICK_AND_PLACE["load"] | change}
    response = client.post(API, json=body)
    assert response.status_code == 422, response.text
    got = response.json()["detail"][0]["loc"]
    assert [str(x) for x in got][: len(loc)] == loc or [str(x) for x in got] == [
        x for x in loc if x != "belt"
    ], got


def test_a_batch_takes_machine_axes_and_answers_as_single(client: TestClient) -> None:
    geared_screw = {
        "load": {
            "type": "ball_screw_incline",
            "mass_kg": 50,
            "lead_mm": 10,
            "friction_coefficient": 0.05,
            "efficiency": 0.9,
            "speed": 300,
            "transmission": {"ratio": 0.1},
        },
        "cycle": {"accel_s": 0.1, "constant_s": 0.5, "decel_s": 0.1, "pause_s": 0.5},
    }
    cases = [PICK_AND_PLACE, geared_screw]
    response = client.post(f"{API}/batch", json={"cases": cases, "top": 2})
    assert response.status_code == 200, response.text
    for case, result in zip(cases, response.json()["results"], strict=True):
        single = created(client, case)
        assert result["load"] == single["load"]
        assert result["mean_speed_rpm"] == single["mean_speed_rpm"]
        assert [c["model"] for c in result["candidates"]] == [
            c["model"] for c in single["candidates"][:2]
        ]
        for got, want in zip(result["candidates"], single["candidates"], strict=False):
            assert got["rms_torque_nm"] == want["rms_torque_nm"]


def test_the_brake_drop_of_the_vertical_belt_axis_is_a_distance(client: TestClient) -> None:
    """Issue 28, item 9: how far the pick-and-place load falls while CHA-25A-50's brake
    closes (70 ms, CHA 1018854 12/2015 Table 36.3), in mm through the belt and the
    ratio: the weight T_G = m·g·r/i accelerates J_L + J_A, θ = ½·T_G/(J_L + J_A)·t_c², the
    load travels θ·r/i — at most free fall ½·g·t_c² = 24.0 mm. Single and batch agree."""
    body = PICK_AND_PLACE | {"models": ["CHA-25A-50"], "emergency_stops": 20}
    answer = created(client, body)
    row = client.get("/api/v1/actuators/CHA-25A-50").json()
    j_a, t_c = row["inertia_kgm2"], row["brake_closing_time_s"]
    r, i, m = 0.025, 1.5, 4.0
    theta = 0.5 * (m * G * r / i) / (m * r * r / (i * i) + j_a) * t_c**2
    drop_mm = theta * r / i * 1000
    assert drop_mm < 0.5 * G * t_c**2 * 1000
    detail = client.get(f"{API}/{answer['id']}/candidates/CHA-25A-50").json()
    said = {c["name"]: c for c in detail["checks"]}["brake_emergency_stops"]["message"]
    assert f"the load falls by up to {drop_mm:.3g} mm" in said, said
    assert f"the output turns {math.degrees(theta):.3g}°" in said
    assert f"free fall would be {0.5 * G * t_c**2 * 1000:.3g} mm" in said
    holding = {c["name"]: c for c in detail["checks"]}["brake_holding"]["message"]
    assert "safety factor S = 1" in holding  # the default, said to be the user's choice
    german = client.get(
        f"{API}/{answer['id']}/candidates/CHA-25A-50", headers={"Accept-Language": "de"}
    ).json()
    worte = {c["name"]: c for c in german["checks"]}["brake_emergency_stops"]["message"]
    assert "fällt die Last um bis zu" in worte, worte
    batch = client.post(f"{API}/batch", json={"cases": [body], "top": 1, "include_messages": True})
    assert batch.status_code == 200, batch.text
    (result,) = batch.json()["results"]
    (candidate,) = result["candidates"]
    assert candidate["checks"] == detail["checks"]
