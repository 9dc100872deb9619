"""The catalogue in memory: read once per catalogue version, read again after any change."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from sqlalchemy import Connection, event
from tests import worked_example
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

__all__ = ["api", "sales_api_with"]

MODEL = "FHA-25C-50-L"


@pytest.fixture
def statements(connection: Connection) -> Iterator[list[str]]:
    """The SQL the app sends on the test's connection, as it sends it."""
    sent: list[str] = []

    def record(*args: Any) -> None:
        sent.append(args[2])

    event.listen(connection, "before_cursor_execute", record)
    yield sent
    event.remove(connection, "before_cursor_execute", record)


def _peak_limit(api: SalesApi) -> float:
    body = {**worked_example.request(), "models": [MODEL]}
    response = api.client.post("/api/v1/selections", json=body)
    assert response.status_code == 201, response.text
    (candidate,) = response.json()["candidates"]
    (peak,) = [c for c in candidate["checks"] if c["name"] == "peak_torque"]
    limit: float = peak["limit"]
    return limit


def _set_peak_torque(api: SalesApi, torque: float) -> None:
    """T_max of MODEL changed by an admin, the rest of its row as exported."""
    exported = api.get("/api/v1/catalogue/export", role="admin", params={"format": "json"})
    (row,) = [r for r in exported.json()["actuators"] if r["model"] == MODEL]
    put = api.client.put(
        f"/api/v1/actuators/{MODEL}",
        json={**row, "max_torque_nm": torque},
        headers=api.headers("admin"),
    )
    assert put.status_code == 200, put.text


def _reads_actuators(sql: list[str]) -> bool:
    return any("FROM actuators" in s for s in sql)


def test_a_warm_selection_reads_only_the_version(api: SalesApi, statements: list[str]) -> None:
    _peak_limit(api)  # warms the cache
    assert _reads_actuators(statements)
    statements.clear()
    _peak_limit(api)
    assert not _reads_actuators(statements)
    assert any("catalogue_state" in s for s in statements)  # the version is checked each time


def test_a_catalogue_change_is_seen_by_the_next_selection(
    api: SalesApi, statements: list[str]
) -> None:
    assert _peak_limit(api) == 151
    _set_peak_torque(api, 97)
    statements.clear()
    assert _peak_limit(api) == 97
    assert _reads_actuators(statements)


def test_two_apps_on_one_database_stay_coherent(api: SalesApi, sales_api_with: Any) -> None:
    """Two processes of a deployment, each with its own cache, one database."""
    other = sales_api_with()
    assert _peak_limit(api) == _peak_limit(other) == 151
    _set_peak_torque(other, 97)
    assert _peak_limit(api) == 97


def test_a_candidates_detail_after_a_catalogue_change_is_a_conflict(api: SalesApi) -> None:
    """The detail is computed again from the stored load case: only with the catalogue the
    selection used, else it would not be the stored answer's candidate."""
    body = {**worked_example.request(), "models": [MODEL]}
    selection = api.client.post("/api/v1/selections", json=body).json()
    url = f"/api/v1/selections/{selection['id']}/candidates/{MODEL}"
    before = api.client.get(url)
    assert before.status_code == 200, before.text
    assert before.json()["catalogue_version"] == selection["catalogue_version"]
    _set_peak_torque(api, 97)
    after = api.client.get(url)
    assert after.status_code == 409, after.text
    (error,) = after.json()["detail"]
    assert error["loc"] == ["path", "selection_id"]
    assert "run the selection again" in error["msg"]
    # the stored answer itself stays as it was answered
    assert api.client.get(f"/api/v1/selections/{selection['id']}").json() == selection


def test_the_cycle_after_a_catalogue_change_keeps_the_stored_torques(api: SalesApi) -> None:
    """The cycle's torque along each segment is computed again as the detail is: after a
    catalogue change it is a conflict, and ``torques=false`` still draws the stored T_1,
    T_2, T_3 (what the page falls back to); the report draws those too."""
    body = {**worked_example.request(), "models": [MODEL]}
    selection = api.client.post("/api/v1/selections", json=body).json()
    url = f"/api/v1/selections/{selection['id']}/candidates/{MODEL}/cycle"
    assert api.client.get(url).json()["layout"]["meta"] == {"torques": "segments"}
    _set_peak_torque(api, 97)
    after = api.client.get(url)
    assert after.status_code == 409, after.text
    assert after.json()["detail"][0]["loc"] == ["path", "selection_id"]
    lean = api.client.get(url, params={"torques": "false"})
    assert lean.status_code == 200, lean.text
    assert lean.json()["layout"]["meta"] == {"torques": "steps"}
    report = api.client.get(f"/api/v1/selections/{selection['id']}/report.pdf")
    assert report.status_code == 200
