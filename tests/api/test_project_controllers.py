"""A servo controller per axis of a machine project (issue 31): chosen from those Table
521.1 does not exclude for the axis's actuator on the project's DC bus class, checked,
stored with the project, and read by the bus summary."""

from __future__ import annotations

import copy
from typing import Any

from fastapi.testclient import TestClient
from tests.api.test_projects import API, PICK_AND_PLACE_CELL, created

from actuator_selection.schemas.projects import ProjectOut


def _with_controllers(client: TestClient) -> tuple[dict[str, Any], dict[str, Any]]:
    """The cell sized once, then sized again with each axis's best controller chosen."""
    first = created(client, PICK_AND_PLACE_CELL)
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    for axis, sized in zip(body["axes"], first["axes"], strict=True):
        assert sized["controller"] is None
        axis["model"] = sized["model"]
        if sized["controllers"]:  # the wrist's 24 V winding has none on a 560 V bus
            axis["controller"] = sized["controllers"][0]["source_row"]
    assert sum("controller" in a for a in body["axes"]) >= 2
    return first, body


def test_each_axis_takes_a_listed_controller_stored_with_the_project(
    client: TestClient,
) -> None:
    first, body = _with_controllers(client)
    assert first["bus"]["controllers_bus_mark"] is None
    assert first["bus"]["voltage_status"] is None
    response = client.put(f"{API}/{first['id']}", json=body)
    assert response.status_code == 200, response.text
    answer = response.json()
    for axis, asked in zip(answer["axes"], body["axes"], strict=True):
        controller = axis["controller"]
        if "controller" not in asked:
            assert controller is None
            continue
        assert controller["source_row"] == asked["controller"]
        assert controller["bus_mark"] in ("tested", "possible")
        assert controller["voltage"]["reference"]
        assert {k: controller[k] for k in ("source_row", "name", "level", "bus_mark")} in axis[
            "controllers"
        ]
    taken = [a["controller"] for a in answer["axes"] if a["controller"] is not None]
    marks = {c["bus_mark"] for c in taken}
    assert answer["bus"]["controllers_bus_mark"] == (
        "possible" if "possible" in marks else "tested"
    )
    statuses = {c["voltage"]["status"] for c in taken}
    assert answer["bus"]["voltage_status"] in statuses
    assert ProjectOut.model_validate(answer).model_dump(mode="json") == answer
    # durable: the request keeps the choice, and sizing again keeps it
    stored = client.get(f"{API}/{first['id']}").json()
    asked = [a.get("controller") for a in body["axes"]]
    assert [a["controller"] for a in stored["request"]["axes"]] == asked
    again = client.post(f"{API}/{first['id']}/size").json()
    assert [(a["controller"] or {}).get("source_row") for a in again["axes"]] == asked


def _all_rows(client: TestClient) -> dict[int, str]:
    controllers = client.get("/api/v1/controllers").json()
    rows = controllers if isinstance(controllers, list) else controllers["controllers"]
    return {int(c["source_row"]): c["type"] for c in rows}


def test_a_controller_not_listed_for_the_axis_is_422_naming_the_axis(
    client: TestClient,
) -> None:
    first, body = _with_controllers(client)
    listed = {c["source_row"] for c in first["axes"][1]["controllers"]}
    others = sorted(set(_all_rows(client)) - listed)
    assert others, "Table 521.1 has a controller the rack's actuator may not take"
    body["axes"][1]["controller"] = others[0]
    response = client.post(API, json=body)
    assert response.status_code == 422, response.text
    error = response.json()["detail"][0]
    assert error["loc"] == ["body", "axes", 1, "controller"]
    assert error["code"] in ("controller_not_compatible", "controller_not_listed")
    assert error["params"]["rows"] == sorted(listed)[:12]
    assert "Table 521.1" in error["msg"]


def test_an_unknown_row_is_422(client: TestClient) -> None:
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    body["axes"][2]["controller"] = 999_999
    response = client.post(API, json=body)
    assert response.status_code == 422, response.text
    error = response.json()["detail"][0]
    assert error["loc"] == ["body", "axes", 2, "controller"]
    assert error["code"] == "unknown_controller"


def test_an_actuator_that_does_not_run_on_the_bus_lists_no_controller(
    client: TestClient,
) -> None:
    """The wrist's CHA-14A-E has a 24 V winding: on a ≥ 560 VDC bus nothing drives it,
    on the 24 VDC bus only controllers Table 521.1 marks for that class."""
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    body["axes"] = [body["axes"][2] | {"model": "CHA-14A-E-30"}]
    assert created(client, body)["axes"][0]["controllers"] == []
    body["bus"] = {"bus_class": "24vdc"}
    listed = created(client, body)["axes"][0]["controllers"]
    assert listed
    assert {c["bus_mark"] for c in listed} <= {"tested", "possible"}
