"""Issue 28, item 4 over HTTP: the CHA-20A's four-point contact ball bearing takes the
life exponent 3 (ISO 281; CHA manual 1018854 12/2015, Table 69.3), its cross roller
neighbours 10/3; the single answer and the batch agree (==). First principles: formula
(7) of the FHA-C manual / CHA §4.3 written out by hand."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

API = "/api/v1/selections"
BODY: dict[str, Any] = {
    "load": {"speed_rpm": 30, "torque_nm": 2, "inertia_kgm2": 0.1},
    "cycle": {"accel_s": 0.2, "constant_s": 1.0, "decel_s": 0.2, "pause_s": 1.0},
    "output_load": {
        "radial_force_n": 2000,
        "axial_force_n": 0,
        "radial_lever_m": 0.02,
        "axial_lever_m": 0,
        "required_life_h": 90000,
    },
    "models": ["CHA-20A-50", "CHA-25A-50"],
}
N_AV = (30 * 0.2 / 2 * 2 + 30 * 1.0) / 2.4  # Eq. 514.3: 15 rpm


def life_h(c: float, p_c: float, exponent: float) -> float:
    return 1e6 / (60 * N_AV) * math.pow(c / (1.5 * p_c), exponent)


def test_the_cha_20a_bearing_is_a_ball_bearing_in_the_catalogue(client: TestClient) -> None:
    ball = client.get("/api/v1/actuators/CHA-20A-50").json()
    roller = client.get("/api/v1/actuators/CHA-25A-50").json()
    assert ball["output_bearing_type"] == "four_point_contact_ball"
    assert roller["output_bearing_type"] == "cross_roller"
    assert "Table 55.1" in ball["source"]


def test_the_cha_20a_life_fails_with_exponent_3_and_the_batch_agrees(client: TestClient) -> None:
    response = client.post(API, json=BODY)
    assert response.status_code == 201, response.text
    answer = response.json()
    detail = client.get(f"{API}/{answer['id']}/candidates/CHA-20A-50").json()
    checks = {c["name"]: c for c in detail["checks"]}
    life = checks["bearing_life"]
    # d_p = 70 mm, R = 16 mm, C = 24200 N (CHA manual 8/2018, Table 55.1)
    p_c = 2000 + 2 * 2000 * (0.020 + 0.016) / 0.070
    assert life["value"] == pytest.approx(1.5 * p_c * (90000 * 60 * N_AV / 1e6) ** (1 / 3))
    assert (life["status"], life["limit"]) == ("fail", 24200)
    assert life_h(24200, p_c, 3) < 90000 < life_h(24200, p_c, 10 / 3)  # 10/3 would pass
    assert f"{life_h(24200, p_c, 3):.4g} h" in life["message"]
    assert "four-point contact ball bearing: B = 3" in life["message"]
    assert detail["verdict"] == "unsuitable"
    # CHA-25A-50: a cross roller bearing, exponent 10/3 (d_p 88 mm... from its catalogue row)
    roller = client.get(f"{API}/{answer['id']}/candidates/CHA-25A-50").json()
    roller_life = {c["name"]: c for c in roller["checks"]}["bearing_life"]
    assert "cross roller bearing: B = 10/3" in roller_life["message"]
    # the batch (the vectorised flowchart) gives the same checks, number for number
    batch = client.post(f"{API}/batch", json={"cases": [BODY], "top": 2, "include_messages": True})
    assert batch.status_code == 200, batch.text
    (result,) = batch.json()["results"]
    got = {c["model"]: c for c in result["candidates"]}
    assert got["CHA-20A-50"]["checks"] == detail["checks"]
    assert got["CHA-25A-50"]["checks"] == roller["checks"]
    lean = {c["model"]: c for c in answer["candidates"]}["CHA-20A-50"]
    lean_life = {c["name"]: c for c in lean["checks"]}["bearing_life"]
    assert (lean_life["value"], lean_life["status"]) == (life["value"], "fail")
    assert math.isfinite(lean_life["value"])


def swinging(stroke_deg: float) -> dict[str, Any]:
    """To and fro through ``stroke_deg``: 0.5 s ramps and 1 s at speed each way, so the
    stroke is n·1.5 s·6 °/(rpm·s); on the CHA-20A with a light output load."""
    speed = stroke_deg / 1.5 / 6
    return {
        "load": {"torque_nm": 1, "inertia_kgm2": 0.01},
        "cycle": {
            "segments": [
                {"speed": speed, "duration_s": 0.5},
                {"duration_s": 1.0},
                {"speed": 0, "duration_s": 0.5},
                {"duration_s": 1.0},
                {"speed": -speed, "duration_s": 0.5},
                {"duration_s": 1.0},
                {"speed": 0, "duration_s": 0.5},
                {"duration_s": 1.0},
            ]
        },
        "output_load": {
            "radial_force_n": 300,
            "axial_force_n": 0,
            "radial_lever_m": 0.02,
            "axial_lever_m": 0,
        },
        "models": ["CHA-20A-50"],
    }


@pytest.mark.parametrize(("stroke", "status"), [(3.0, "warn"), (8.0, "pass")])
def test_a_swing_below_5_degrees_warns_of_fretting_over_http(
    client: TestClient, stroke: float, status: str
) -> None:
    response = client.post(API, json=swinging(stroke))
    assert response.status_code == 201, response.text
    (candidate,) = response.json()["candidates"]
    checks = {c["name"]: c for c in candidate["checks"]}
    fretting = checks["bearing_fretting"]
    assert fretting["limit"] == pytest.approx(stroke, rel=1e-12)
    assert (fretting["value"], fretting["status"]) == (5, status)
    assert candidate["verdict"] == "suitable"  # a warning: the verdict stands
    detail = client.get(f"{API}/{response.json()['id']}/candidates/CHA-20A-50").json()
    words = {c["name"]: c for c in detail["checks"]}["bearing_fretting"]["message"]
    if status == "warn":
        assert words in detail["reasons"]
        assert "fretting" in words
    german = client.get(
        f"{API}/{response.json()['id']}/candidates/CHA-20A-50",
        headers={"Accept-Language": "de"},
    ).json()
    assert (
        "Abtrieb schwenkt"
        in {c["name"]: c for c in german["checks"]}["bearing_fretting"]["message"]
    )


def test_the_technical_report_lists_the_fretting_check(client: TestClient) -> None:
    """The report PDF names every check of the answer, the new one too, in both languages."""
    created = client.post(API, json=swinging(3.0))
    assert created.status_code == 201, created.text
    for language in ("en", "de"):
        pdf = client.get(
            f"{API}/{created.json()['id']}/report.pdf", headers={"Accept-Language": language}
        )
        assert pdf.status_code == 200, pdf.text
        assert pdf.content.startswith(b"%PDF")
