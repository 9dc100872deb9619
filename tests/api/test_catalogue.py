"""Catalogue reads over HTTP."""

from __future__ import annotations

import pytest
from fastapi.testclient import TestClient


def test_health_reaches_the_database(client: TestClient) -> None:
    response = client.get("/api/v1/health")
    assert response.status_code == 200
    assert response.json() == {"status": "ok"}


def test_list_and_filter_actuators(client: TestClient) -> None:
    everything = client.get("/api/v1/actuators").json()
    models = [a["model"] for a in everything]
    assert models == sorted(models)
    assert {"FHA-25C-50-L", "CHA-25A-50", "FHA-8C-30"} <= set(models)
    cha = client.get("/api/v1/actuators", params={"family": "CHA"}).json()
    assert cha
    assert all(a["family"] == "CHA" for a in cha)
    strong = client.get("/api/v1/actuators", params={"min_max_torque_nm": 1000}).json()
    assert strong
    assert all(a["max_torque_nm"] >= 1000 for a in strong)
    light = client.get("/api/v1/actuators", params={"max_inertia_kgm2": 0.01}).json()
    assert light
    assert all(a["inertia_kgm2"] <= 0.01 for a in light)
    expected = {
        a["model"] for a in everything if a["family"] == "CHA" and a["max_torque_nm"] >= 100
    }
    both = client.get("/api/v1/actuators", params={"family": "CHA", "min_max_torque_nm": 100})
    assert {a["model"] for a in both.json()} == expected


def test_get_actuator_with_source_and_empty_unpublished_values(client: TestClient) -> None:
    body = client.get("/api/v1/actuators/FHA-25C-50-L").json()
    assert (body["max_torque_nm"], body["max_speed_rpm"], body["inertia_kgm2"]) == (151, 90, 0.86)
    assert body["stall_torque_nm"] is None
    assert body["continuous_duty_zone"] is None
    assert "Table 516.3" in body["source"]
    assert body["output_turns_opposite_to_motor"] is True


def test_unknown_model_is_404(client: TestClient) -> None:
    response = client.get("/api/v1/actuators/NOPE-1")
    assert response.status_code == 404
    (entry,) = response.json()["detail"]
    assert (entry["loc"], entry["type"]) == (["path", "model"], "not_found")
    assert "NOPE-1" in entry["msg"]


@pytest.mark.parametrize("value", ["nan", "inf", "-1", "lots"])
def test_bad_filter_is_422_naming_it(client: TestClient, value: str) -> None:
    response = client.get("/api/v1/actuators", params={"min_max_torque_nm": value})
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["query", "min_max_torque_nm"]


def test_families_carry_sensor_limits(client: TestClient) -> None:
    families = {f["name"]: f for f in client.get("/api/v1/families").json()}
    cha = families["CHA"]
    assert (cha["warning_temperature_c"], cha["shutdown_temperature_c"]) == (80, 90)
    assert (cha["warning_resistance_ohm"], cha["shutdown_resistance_ohm"]) == (882, 940)
    assert families["FHA-C mini"]["shutdown_temperature_c"] is None


def test_selection_records_the_catalogue_version(client: TestClient) -> None:
    version = client.get("/api/v1/catalogue/version").json()["version"]
    assert version >= 1  # the seed wrote the catalogue
    body = {
        "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
        "models": ["FHA-25C-50-L"],
    }
    created = client.post("/api/v1/selections", json=body).json()
    assert created["catalogue_version"] == version
