"""Catalogue reads over HTTP."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pytest
from fastapi.testclient import TestClient


def test_health_reaches_the_database(client: TestClient) -> None:
    response = client.get("/api/v1/health")
    assert response.status_code == 200
    assert response.json() == {"status": "ok"}


def _listed(client: TestClient, **params: Any) -> list[dict[str, Any]]:
    response = client.get("/api/v1/actuators", params=params)
    assert response.status_code == 200, response.text
    page = response.json()
    assert page["next_cursor"] is None  # without a limit: all of them
    actuators: list[dict[str, Any]] = page["actuators"]
    return actuators


def test_list_and_filter_actuators(client: TestClient) -> None:
    everything = _listed(client)
    models = [a["model"] for a in everything]
    assert models == sorted(models)
    assert {"FHA-25C-50-L", "CHA-25A-50", "FHA-8C-30"} <= set(models)
    cha = _listed(client, family="CHA")
    assert cha
    assert all(a["family"] == "CHA" for a in cha)
    strong = _listed(client, min_max_torque_nm=1000)
    assert strong
    assert all(a["max_torque_nm"] >= 1000 for a in strong)
    light = _listed(client, max_inertia_kgm2=0.01)
    assert light
    assert all(a["inertia_kgm2"] <= 0.01 for a in light)
    expected = {
        a["model"] for a in everything if a["family"] == "CHA" and a["max_torque_nm"] >= 100
    }
    both = _listed(client, family="CHA", min_max_torque_nm=100)
    assert {a["model"] for a in both} == expected


def test_more_filters(client: TestClient) -> None:
    everything = _listed(client)
    rules: list[tuple[dict[str, float], Callable[[dict[str, Any]], bool]]] = [
        ({"max_max_torque_nm": 100}, lambda a: a["max_torque_nm"] <= 100),
        ({"gear_ratio": 50}, lambda a: a["gear_ratio"] == 50),
        (
            {"min_continuous_torque_nm": 50},
            lambda a: a["continuous_torque_nm"] is not None and a["continuous_torque_nm"] >= 50,
        ),
    ]
    for params, rule in rules:
        found = [a["model"] for a in _listed(client, **params)]
        expected = [a["model"] for a in everything if a["max_torque_nm"] is not None and rule(a)]
        assert found == expected, params
        assert 0 < len(found) < len(everything), params


@pytest.mark.parametrize("limit", [1, 7, 500])
def test_pages_follow_their_cursors(client: TestClient, limit: int) -> None:
    """Page by page, with a filter: every actuator once, in the order of the whole list."""
    whole = [a["model"] for a in _listed(client, min_max_speed_rpm=50)]
    seen: list[str] = []
    cursor: str | None = None
    while True:
        params: dict[str, Any] = {"limit": limit, "min_max_speed_rpm": 50}
        if cursor is not None:
            params["cursor"] = cursor
        page = client.get("/api/v1/actuators", params=params).json()
        assert 0 < len(page["actuators"]) <= limit
        seen += [a["model"] for a in page["actuators"]]
        cursor = page["next_cursor"]
        if cursor is None:
            break
        assert len(page["actuators"]) == limit
    assert seen == whole
    assert len(whole) > 7


@pytest.mark.parametrize(
    ("params", "loc"),
    [
        ({"limit": 0}, ["query", "limit"]),
        ({"limit": 501}, ["query", "limit"]),
        ({"cursor": "not-a-cursor"}, ["query", "cursor"]),
        ({"cursor": "x" * 201}, ["query", "cursor"]),
        ({"gear_ratio": 0}, ["query", "gear_ratio"]),
    ],
)
def test_bad_paging_is_422_naming_it(
    client: TestClient, params: dict[str, Any], loc: list[str]
) -> None:
    response = client.get("/api/v1/actuators", params=params, headers={"Accept-Language": "de"})
    assert response.status_code == 422, response.text
    (entry,) = response.json()["detail"]
    assert entry["loc"] == loc
    if params.get("cursor") == "not-a-cursor":
        assert (entry["type"], entry["code"]) == ("invalid_cursor", "invalid_cursor")
        assert "erste Seite" in entry["msg"]


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
