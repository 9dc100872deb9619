"""The continuous checks over the API (issue "A verdict an application engineer signs",
items 3, 5 and 6): the seeded CHA-25A-50 (CHA manual 1018854: T_0 55 Nm, rated output
speed 3500/50 = 70 rpm, k_T 26 Nm/A, I_0 2.3 A, I_NLS 0.19 A, K_INL(80 °C) 2·10⁻³ A/rpm).
"""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests.api.test_selections_batch import single_candidates, without

API = "/api/v1/selections"

RUN_105: dict[str, Any] = {
    "load": {"torque_nm": 52, "inertia_kgm2": 0.5},
    "cycle": {
        "segments": [
            {"speed": 105, "duration_s": 0.5},
            {"duration_s": 1800},
            {"speed": 0, "duration_s": 0.5},
            {"duration_s": 3600},
        ]
    },
    "models": ["CHA-25A-50"],
}
"""52 Nm at 105 rpm (1.5 × the rated 70 rpm) for 30 minutes, then an hour's pause."""


def created(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    return answer


def test_half_an_hour_at_105_rpm_is_unsuitable_on_the_speed(client: TestClient) -> None:
    """n_av is 35 rpm, so the chapter's mean passes; the winding follows 105 rpm for five
    of its time constants (600 s assumed) and reaches ≈ 105·(1 − e⁻³) ≈ 100 rpm > 70 rpm."""
    answer = created(client, RUN_105)
    assert answer["mean_speed_rpm"] == pytest.approx(35.0, abs=0.01)
    (candidate,) = answer["candidates"]
    assert candidate["verdict"] == "unsuitable"  # was "suitable"
    assert {"name": "continuous_speed", "reference": "Eq. 514.3; Fig. 520.1 (model)",
            "unit": "rpm"} in answer["check_rules"]  # fmt: skip
    checks = {c["name"]: c for c in candidate["checks"]}
    # the speed, and the winding current: 52/26 + 0.19 + 0.002·105 = 2.40 A > I_0 = 2.3 A
    failed = [n for n, c in checks.items() if c["status"] == "fail"]
    assert failed == ["thermal_peak", "continuous_speed"]
    speed = checks["continuous_speed"]
    assert speed["limit"] == 70
    assert speed["value"] == pytest.approx(105 * (1 - math.exp(-3)), abs=0.3)

    detail = client.get(f"{API}/{answer['id']}/candidates/CHA-25A-50").json()
    full = next(c for c in detail["checks"] if c["name"] == "continuous_speed")
    assert (full["unit"], full["approximate"]) == ("rpm", True)  # τ_th assumed
    assert full["margin_percent"] == pytest.approx((70 - full["value"]) / 70 * 100)
    assert full["message_code"] == "continuous_speed.fail"
    assert "exceeds the rated speed 70 rpm" in full["message"]
    german = client.get(
        f"{API}/{answer['id']}/candidates/CHA-25A-50", headers={"Accept-Language": "de"}
    ).json()
    de = next(c for c in german["checks"] if c["name"] == "continuous_speed")
    assert "überschreitet Nenndrehzahl 70 min⁻¹" in de["message"]
    heating = next(c for c in detail["checks"] if c["name"] == "thermal_peak")
    assert heating["message_code"] == "thermal_peak.current_fail"
    assert detail["reasons"] == [heating["message"], full["message"]]


def test_a_minute_at_105_rpm_is_suitable(client: TestClient) -> None:
    body = {**RUN_105, "cycle": {"segments": [*RUN_105["cycle"]["segments"]]}}
    body["cycle"]["segments"][1] = {"duration_s": 60}
    (candidate,) = created(client, body)["candidates"]
    assert candidate["verdict"] == "suitable"


def test_53_nm_at_68_rpm_fails_on_the_winding_current(client: TestClient) -> None:
    """Inside the 55 Nm rectangle, but 53/26 + 0.19 + 0.002·68 = 2.36 A > I_0 = 2.3 A."""
    body = {
        "load": {"speed_rpm": 68, "torque_nm": 53, "inertia_kgm2": 0.01},
        "cycle": {"accel_s": 0.5, "constant_s": 3600, "decel_s": 0.5, "pause_s": 0},
        "models": ["CHA-25A-50"],
    }
    answer = created(client, body)
    (candidate,) = answer["candidates"]
    duty = next(c for c in candidate["checks"] if c["name"] == "continuous_duty")
    assert duty["status"] == "fail"
    assert duty["value"] / 26 + 0.19 + 0.002 * answer["mean_speed_rpm"] > 2.3
    assert duty["limit"] == pytest.approx(55 - 26 * 0.002 * answer["mean_speed_rpm"])
    assert candidate["verdict"] == "unsuitable"


def test_the_batch_answers_as_the_single_selection(client: TestClient) -> None:
    cases = [RUN_105, {**RUN_105, "models": None}]
    response = client.post(
        f"{API}/batch", json={"cases": cases, "top": 3, "include_messages": True}
    )
    assert response.status_code == 200, response.text
    for case, result in zip(cases, response.json()["results"], strict=True):
        single, details = single_candidates(client, case, 3)
        assert result["mean_speed_rpm"] == single["mean_speed_rpm"]
        assert [without(c, "controllers", "reason_checks") for c in result["candidates"]] == [
            without(c, "controllers") for c in details
        ]
