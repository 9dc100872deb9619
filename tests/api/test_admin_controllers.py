"""Controller management: Table 521.1 rows written by the seed rules, retired, imported."""

from __future__ import annotations

import json
from typing import Any

import pytest
from tests.api._sales_fixtures import WORKED_EXAMPLE, SalesApi, api, sales_api_with
from tests.api.test_admin import admin, export_json, import_, version

__all__ = ["api", "sales_api_with"]

NEW: dict[str, Any] = {
    "manufacturer": "Example Drives",
    "type": "XD 7",
    "cha_chm": "tested",
    "fha_c": "○",  # the chapter's printed mark is accepted and stored as "possible"
    "bus_560vdc": "tested",
    "sensor_ptc": "tested",
    "sensor_kty84_130": "possible",
    "feedback_endat": "tested",
    "source": "test data, not a real controller",
}


def controllers(api: SalesApi) -> dict[int, dict[str, Any]]:
    rows = api.get("/api/v1/controllers", role=None).json()
    return {r["source_row"]: r for r in rows}


def candidate_controllers(api: SalesApi, model: str) -> set[int]:
    """The rows among the controllers of ``model``'s candidate in a selection."""
    body = {**WORKED_EXAMPLE, "models": [model]}
    response = api.post("/api/v1/selections", role=None, json=body)
    assert response.status_code in (200, 201), response.text
    selection = response.json()
    (candidate,) = selection["candidates"]
    detail = api.get(f"/api/v1/selections/{selection['id']}/candidates/{model}", role=None)
    listed = {c["source_row"] for c in detail.json()["controllers"]}
    if candidate["drive_options"] is not None:  # the answer lists them too, grouped
        rows = selection["controllers"]
        groups = candidate["drive_options"]
        assert listed == {rows[i]["source_row"] for g in groups for i in g["controllers"]}
    return listed


def test_create_a_controller_with_the_next_row(api: SalesApi) -> None:
    before, rows = version(api), controllers(api)
    response = admin(api, "post", "/api/v1/controllers", json=NEW)
    assert response.status_code == 201, response.text
    body = response.json()
    row = max(rows) + 1
    assert body["source_row"] == row
    assert response.headers["location"] == f"/api/v1/controllers/{row}"
    assert body["marks"] == {
        "cha_chm": "tested",
        "fha_c": "possible",
        "bus_560vdc": "tested",
        "sensor_ptc": "tested",
        "sensor_kty84_130": "possible",
        "feedback_endat": "tested",
    }
    assert body["source"] == NEW["source"]
    assert api.get(f"/api/v1/controllers/{row}", role=None).json() == body
    assert controllers(api)[row] == body
    assert version(api) == before + 1
    # A CHA runs on ≥ 560 VDC with PTC or KTY: the new row is now among its controllers.
    assert row in candidate_controllers(api, "CHA-25A-50")
    again = admin(api, "post", "/api/v1/controllers", json={**NEW, "source_row": row})
    assert again.status_code == 409
    (entry,) = again.json()["detail"]
    assert entry["loc"] == ["body", "source_row"]
    assert f"PUT /controllers/{row}" in entry["msg"]


@pytest.mark.parametrize(
    ("column", "value", "rule"),
    [
        ("cha_chm", "yes", "tested (●), possible (○) or empty"),
        ("source_row", 0, "whole number"),
        ("source_row", "2.5", "whole number"),
        ("source_row", 10**12, "whole number"),
        ("manufacturer", "x" * 81, "at most 80 characters"),
        ("manufacturer", None, "required"),
        ("source", "  ", "required"),
        ("bus_48vdc", "tested", "unknown column"),
        ("feedback_ttl", ["tested"], "text, a number or null"),
        ("type", "SINAMICS S120", "row 3 already"),
    ],
)
def test_controller_writes_obey_the_seed_rules(
    api: SalesApi, column: str, value: object, rule: str
) -> None:
    before, rows = version(api), controllers(api)
    body = {**NEW, column: value}
    if column == "type":
        body["manufacturer"] = "SIEMENS"
    response = admin(api, "post", "/api/v1/controllers", json=body)
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", column]
    assert rule in error["msg"]
    assert (version(api), controllers(api)) == (before, rows)


def test_replace_a_controller(api: SalesApi) -> None:
    row3 = controllers(api)[3]
    assert row3["type"] == "SINAMICS S120"
    written = {
        "manufacturer": "SIEMENS",
        "type": "SINAMICS S120",
        **row3["marks"],
        "feedback_hiperface": "possible",
        "correction": row3["correction"],
        "source": row3["source"],
    }
    before = version(api)
    response = admin(api, "put", "/api/v1/controllers/3", json=written)
    assert response.status_code == 200, response.text
    assert response.json()["marks"] == {**row3["marks"], "feedback_hiperface": "possible"}
    assert version(api) == before + 1
    same = admin(api, "put", "/api/v1/controllers/3", json={**written, "source_row": 3})
    assert same.status_code == 200
    as_null = admin(api, "put", "/api/v1/controllers/3", json={**written, "source_row": None})
    assert as_null.status_code == 200  # null, as missing: the path names the row
    assert version(api) == before + 1  # nothing changed, no new version
    mismatch = admin(api, "put", "/api/v1/controllers/3", json={**written, "source_row": 4})
    assert mismatch.status_code == 422
    assert mismatch.json()["detail"][0]["loc"] == ["body", "source_row"]
    assert admin(api, "put", "/api/v1/controllers/999", json=written).status_code == 404
    assert admin(api, "put", "/api/v1/controllers/0", json=written).status_code == 422
    assert admin(api, "put", "/api/v1/controllers/x", json=written).status_code == 422


def test_retire_and_bring_back_a_controller(api: SalesApi) -> None:
    assert 1 in candidate_controllers(api, "CHA-25A-50")  # SIEMENS SIMODRIVE 611D
    before = version(api)
    assert admin(api, "delete", "/api/v1/controllers/1").status_code == 204
    assert admin(api, "delete", "/api/v1/controllers/1").status_code == 204  # idempotent
    assert version(api) == before + 1
    assert api.get("/api/v1/controllers/1", role=None).status_code == 404
    assert 1 not in controllers(api)
    assert 1 not in candidate_controllers(api, "CHA-25A-50")
    matched = api.get("/api/v1/actuators/CHA-25A-50/controllers", role=None).json()
    assert 1 not in {c["source_row"] for c in matched["controllers"]}
    assert 1 not in {c["source_row"] for c in export_json(api)["controllers"]}
    # Its row number stays taken: a new controller gets another one.
    taken = admin(api, "post", "/api/v1/controllers", json={**NEW, "source_row": 1})
    assert taken.status_code == 409
    # The retired row's name is free while it is retired, and PUT brings the row back.
    row1 = {"manufacturer": "SIEMENS", "type": "SIMODRIVE 611D", "source": "Table 521.1"}
    back = admin(api, "put", "/api/v1/controllers/1", json=row1)
    assert back.status_code == 200, back.text
    assert api.get("/api/v1/controllers/1", role=None).status_code == 200
    assert admin(api, "delete", "/api/v1/controllers/999").status_code == 404


def test_import_retires_and_brings_back_controllers(api: SalesApi) -> None:
    document = export_json(api)
    assert len(document["controllers"]) == 28
    without_row_5 = {
        **document,
        "controllers": [c for c in document["controllers"] if c["source_row"] != 5],
        "kty84_130": document["kty84_130"][1:],
    }
    before = version(api)
    dry = import_(api, json.dumps(without_row_5).encode(), "application/json", dry_run=True)
    assert dry.status_code == 200, dry.text
    files = dry.json()["files"]
    assert files["controllers.csv"] == {"inserted": 0, "updated": 0, "unchanged": 27, "retired": 1}
    assert files["kty84_130.csv"]["retired"] == 1
    assert 5 in controllers(api)
    assert version(api) == before

    done = import_(api, json.dumps(without_row_5).encode(), "application/json")
    assert done.json()["files"] == files
    assert 5 not in controllers(api)
    assert version(api) == before + 1
    # The runtime reads the table as imported: its lowest point is gone.
    coldest = min(document["kty84_130"], key=lambda p: p["temperature_c"])
    reading = api.post(
        "/api/v1/tools/sensor-temperature",
        role=None,
        json={"sensor": "kty84_130", "resistance_ohm": coldest["resistance_ohm"]},
    )
    assert reading.status_code == 422
    assert "outside the KTY 84-130 table" in reading.json()["detail"][0]["msg"]

    back = import_(api, json.dumps(document).encode(), "application/json")
    assert back.json()["files"]["controllers.csv"]["updated"] == 1
    assert controllers(api)[5]["type"] == "MDLU"
    assert export_json(api) == document


def test_a_bad_controller_row_imports_nothing(api: SalesApi) -> None:
    document = export_json(api)
    document["controllers"][2]["sensor_ptc"] = "maybe"
    document["actuators"][0]["notes"] = "changed"
    before = version(api)
    response = import_(api, json.dumps(document).encode(), "application/json")
    assert response.status_code == 422
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", "controllers", 2, "sensor_ptc"]
    assert version(api) == before
    assert export_json(api)["actuators"][0]["notes"] != "changed"


def test_set_and_remove_an_actuators_interface(api: SalesApi) -> None:
    path = "/api/v1/actuators/FHA-25C-50-L/interface"
    before = version(api)
    given = {
        "dc_bus_classes": ["560vdc", "320vdc"],
        "temperature_sensors": "ptc",
        "feedback_systems": ["endat"],
        "source": "test interface",
    }
    response = admin(api, "put", path, json=given)
    assert response.status_code == 200, response.text
    assert {k: response.json()[k] for k in ("dc_bus_classes", "feedback_systems", "source")} == {
        "dc_bus_classes": ["320vdc", "560vdc"],
        "feedback_systems": ["endat"],
        "source": "test interface",
    }
    assert version(api) == before + 1
    assert admin(api, "put", path, json=given).status_code == 200
    assert version(api) == before + 1  # the same values: no new version
    matched = api.get("/api/v1/actuators/FHA-25C-50-L/controllers", role=None).json()
    assert matched["interface"] == response.json()
    # Every criterion now has data: no controller is left unconfirmed.
    assert {c["level"] for c in matched["controllers"]} <= {"tested", "possible", "excluded"}
    assert all(not c["missing"] for c in matched["controllers"])

    assert admin(api, "delete", path).status_code == 204
    gone = api.get("/api/v1/actuators/FHA-25C-50-L/controllers", role=None).json()["interface"]
    assert (gone["dc_bus_classes"], gone["temperature_sensors"], gone["source"]) == (
        None,
        None,
        None,
    )
    assert version(api) == before + 2


@pytest.mark.parametrize(
    ("body", "column", "rule"),
    [
        ({"dc_bus_classes": "48vdc", "source": "x"}, "dc_bus_classes", "unknown: 48vdc"),
        ({"feedback_systems": ["endat", "endat"], "source": "x"}, "feedback_systems", "once"),
        ({"temperature_sensors": "ptc"}, "source", "required"),
        ({"actuator_model": "CHA-20A-30", "source": "x"}, "actuator_model", "path"),
    ],
)
def test_bad_interface_is_named_and_changes_nothing(
    api: SalesApi, body: dict[str, Any], column: str, rule: str
) -> None:
    before = version(api)
    response = admin(api, "put", "/api/v1/actuators/CHA-25A-50/interface", json=body)
    assert response.status_code == 422
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", column]
    assert rule in error["msg"]
    assert version(api) == before
    assert admin(api, "put", "/api/v1/actuators/NOPE-1/interface", json=body).status_code == 404


@pytest.mark.parametrize(
    ("change", "file", "column", "rule"),
    [
        (lambda d: d["kty84_130"][:1], "kty84_130", "temperature_c", "at least two"),
        (
            lambda d: [{**p, "resistance_ohm": 1000} for p in d["kty84_130"]],
            "kty84_130",
            "resistance_ohm",
            "rise strictly",
        ),
        (lambda d: d["dc_bus_classes"][1:], "dc_bus_classes", "bus_class", "missing: 24vdc"),
    ],
)
def test_import_refuses_tables_the_runtime_cannot_use(
    api: SalesApi, change: Any, file: str, column: str, rule: str
) -> None:
    document = export_json(api)
    document[file] = change(document)
    before = version(api)
    response = import_(api, json.dumps(document).encode(), "application/json")
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert (error["file"], error["column"]) == (file, column)
    assert rule in error["msg"]
    assert version(api) == before


@pytest.mark.parametrize(
    ("method", "path", "body", "column"),
    [
        ("post", "/api/v1/controllers", {**NEW, "manufacturer": "X\ud800"}, "manufacturer"),
        ("put", "/api/v1/actuators/CHA-25A-50/interface", {"source": "a\ud800"}, "source"),
    ],
)
def test_lone_surrogates_are_refused(
    api: SalesApi, method: str, path: str, body: dict[str, Any], column: str
) -> None:
    raw = json.dumps(body)  # json.dumps writes the lone surrogate as the escape \ud800
    response = admin(api, method, path, content=raw, headers={"Content-Type": "application/json"})
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", column]
    assert "valid Unicode" in error["msg"]
