"""A quote line's servo controller, named by its Table 521.1 row and checked against it."""

from __future__ import annotations

from typing import Any

from tests.api._sales_fixtures import SalesApi, api, sales_api_with

__all__ = ["api", "sales_api_with"]

MODEL = "CHA-32A-30"
"""Suitable for the worked example; Table 521.1 excludes SEW MOVIAXIS for it (issue 13)."""


def _listed(selection: dict[str, Any], model: str) -> dict[int, str]:
    """Table 521.1 rows the selection answer lists for ``model``, with their level."""
    refs = selection["controllers"]
    candidate = next(c for c in selection["candidates"] if c["model"] == model)
    return {
        refs[i]["source_row"]: group["level"]
        for group in candidate["drive_options"] or []
        for i in group["controllers"]
    }


def _row_of(api: SalesApi, type_name: str) -> int:
    controllers = api.get("/api/v1/controllers", role=None).json()
    rows = controllers if isinstance(controllers, list) else controllers["controllers"]
    return int(next(c["source_row"] for c in rows if c["type"] == type_name))


def _body(api: SalesApi, selection_id: str, row: int) -> dict[str, Any]:
    return api.quote_body(
        selection_id,
        actuator={"model": MODEL, "quantity": 1},
        controller={
            "type_name": "400 V, 5 A",
            "item_code": "CTRL-SINAMICS-S120",
            "quantity": 1,
            "source_row": row,
        },
    )


def test_a_listed_controller_is_quoted_with_its_row_and_level(api: SalesApi) -> None:
    selection = api.selection(models=[MODEL])
    listed = _listed(selection, MODEL)
    assert listed, "the actuator has controllers Table 521.1 does not exclude"
    row, level = next(iter(listed.items()))
    response = api.post("/api/v1/quotes", json=_body(api, selection["id"], row))
    assert response.status_code == 201, response.text
    quote = response.json()
    line = quote["items"][1]
    assert line["kind"] == "controller"
    assert f"Table 521.1 row {row}: {level}" in line["description"]
    document = api.get(quote["document_url"]).text
    assert f"Table 521.1 row {row}: {level}" in document


def test_an_excluded_controller_is_422_naming_the_field_and_table_521_1(api: SalesApi) -> None:
    selection = api.selection(models=[MODEL])
    moviaxis = _row_of(api, "MOVIAXIS")
    assert moviaxis not in _listed(selection, MODEL), "Table 521.1 excludes it for CHA"
    before = api.get("/api/v1/quotes").json()["total"]
    response = api.post("/api/v1/quotes", json=_body(api, selection["id"], moviaxis))
    assert response.status_code == 422, response.text
    [error] = response.json()["detail"]
    assert error["loc"] == ["body", "controller", "source_row"]
    assert error["type"] == "controller_not_compatible"
    assert "MOVIAXIS" in error["msg"]
    assert "Table 521.1" in error["msg"]
    assert api.get("/api/v1/quotes").json()["total"] == before


def test_an_unknown_row_is_422(api: SalesApi) -> None:
    selection = api.selection(models=[MODEL])
    response = api.post("/api/v1/quotes", json=_body(api, selection["id"], 999_999))
    assert response.status_code == 422, response.text
    [error] = response.json()["detail"]
    assert (error["loc"], error["type"]) == (
        ["body", "controller", "source_row"],
        "unknown_controller",
    )


def test_a_row_is_a_whole_number(api: SalesApi) -> None:
    selection = api.selection(models=[MODEL])
    body = _body(api, selection["id"], 3)
    body["controller"]["source_row"] = "3"
    response = api.post("/api/v1/quotes", json=body)
    assert response.status_code == 422
    assert ["body", "controller", "source_row"] in [e["loc"] for e in response.json()["detail"]]
