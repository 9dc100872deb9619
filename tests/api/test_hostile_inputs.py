"""Hostile and absurd inputs: each a clear 4xx naming the field and the rule, never a 500
and never a half-written record. Run on SQLite and PostgreSQL (``client``/``api`` fixtures).
"""

from __future__ import annotations

import io
import struct
import time
import zipfile
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example
from tests.api._sales_fixtures import SalesApi, api, sales_api_with
from tests.api.test_admin import NEW, admin, export_zip, import_, unchanged, version, zipped

from actuator_selection.schemas.batch import MAX_BATCH_CASES

__all__ = ["api", "sales_api_with"]

CYCLE = {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0}
DAY = {"accel_s": 86_400, "constant_s": 86_400, "decel_s": 86_400, "pause_s": 0}
SCREW: dict[str, Any] = {
    "type": "ball_screw",
    "speed_rpm": 40,
    "mass_kg": 100,
    "lead_m": 0.01,
    "friction_coefficient": 0.1,
    "efficiency": 0.9,
}


def only_error(response: Any, status: int = 422) -> dict[str, Any]:
    """The single entry of an error body in the house shape."""
    assert response.status_code == status, response.text
    (error,) = response.json()["detail"]
    assert set(error) >= {"loc", "msg", "type"}
    return dict(error)


def selection(client: TestClient, load: dict[str, Any], cycle: dict[str, Any]) -> Any:
    body = {"load": load, "cycle": cycle, "models": ["FHA-25C-50-L"]}
    return client.post("/api/v1/selections", json=body)


# 1. Physical lower bounds: no overflow, no Infinity, no load that underflows to zero.


@pytest.mark.parametrize(
    ("changes", "cycle", "field", "rule"),
    [
        ({"efficiency": 1e-300}, CYCLE, "efficiency", "greater than or equal to 0.01"),
        ({"efficiency": 1e-152}, DAY, "efficiency", "greater than or equal to 0.01"),
        ({"efficiency": 0.0099}, CYCLE, "efficiency", "greater than or equal to 0.01"),
        ({"lead_m": 5e-324}, CYCLE, "lead_m", "greater than or equal to 0.000001"),
    ],
)
def test_absurd_ball_screw_is_refused(
    client: TestClient, changes: dict[str, Any], cycle: dict[str, Any], field: str, rule: str
) -> None:
    error = only_error(selection(client, {**SCREW, **changes}, cycle))
    assert error["loc"] == ["body", "load", "ball_screw", field]
    assert rule in error["msg"]


def test_rotary_table_diameter_has_a_lower_bound(client: TestClient) -> None:
    table = {
        "type": "rotary_table",
        "speed_rpm": 10,
        "mass_kg": 50,
        "diameter_m": 5e-324,
        "friction_coefficient": 0.02,
        "friction_radius_m": 0.15,
    }
    error = only_error(selection(client, table, CYCLE))
    assert error["loc"] == ["body", "load", "rotary_table", "diameter_m"]


def test_worst_case_inside_the_bounds_is_finite_and_stored(client: TestClient) -> None:
    """Every bound at its extreme at once: the README's promise of finite results holds, and
    the selection stores (PostgreSQL refuses Infinity in JSON) and reads back."""
    load = {
        "type": "ball_screw",
        "speed_rpm": 100_000,
        "mass_kg": 1_000_000,
        "lead_m": 100,
        "friction_coefficient": 10,
        "efficiency": 0.01,
        "screw_inertia_kgm2": 1_000_000,
    }
    cycle = {"accel_s": 1e-4, "constant_s": 86_400, "decel_s": 1e-4, "pause_s": 86_400}
    response = selection(client, load, cycle)
    assert response.status_code == 201, response.text
    body = response.json()
    (candidate,) = body["candidates"]
    for name in ("accel_torque_nm", "decel_torque_nm", "rms_torque_nm"):
        assert isinstance(candidate[name], float), name
    assert client.get(f"/api/v1/selections/{body['id']}").json() == body
    # The smallest lead and efficiency allowed give a load that is small, not zero.
    small = {**SCREW, "lead_m": 1e-6, "efficiency": 0.01}
    resolved = selection(client, small, CYCLE).json()["load"]
    assert resolved["torque_nm"] > 0
    assert resolved["inertia_kgm2"] > 0


# 2. Location headers of non-Latin-1 names.


def test_location_of_a_non_latin1_model_is_percent_encoded(api: SalesApi) -> None:
    response = admin(api, "post", "/api/v1/actuators", json={**NEW, "model": "FHA-Ω"})
    assert response.status_code == 201, response.text
    location = response.headers["location"]
    assert location == "/api/v1/actuators/FHA-%CE%A9"
    assert api.get(location, role=None).json()["model"] == "FHA-Ω"


# 9. The batch's size is checked before its cases are validated.


def test_too_many_batch_cases_are_refused_at_once(client: TestClient) -> None:
    case = {**worked_example.request(), "high_dynamics": True}
    body = {"cases": [case] * (MAX_BATCH_CASES + 1), "top": 1}
    started = time.perf_counter()
    response = client.post("/api/v1/selections/batch", json=body)
    elapsed = time.perf_counter() - started
    error = only_error(response)
    assert error["loc"] == ["body", "cases"]
    assert f"at most {MAX_BATCH_CASES} cases" in error["msg"]
    assert f"got {MAX_BATCH_CASES + 1}" in error["msg"]
    # Validating every case took ~3.4 s; refusing by count alone is JSON decoding only.
    assert elapsed < 1.5, elapsed
