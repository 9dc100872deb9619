"""U+0000 in any input: a 422 naming where it is, never a 500 (PostgreSQL cannot store it)."""

from __future__ import annotations

from typing import Any

import pytest
from tests.api._sales_fixtures import WORKED_EXAMPLE, SalesApi, api, sales_api_with
from tests.api.test_admin import NEW, admin

__all__ = ["api", "sales_api_with"]


@pytest.mark.parametrize(
    ("path", "loc"),
    [
        ("/api/v1/actuators/FHA%00", ["path"]),
        ("/api/v1/actuators/FHA%00/controllers", ["path"]),
        ("/api/v1/selections/a%00b", ["path"]),
        ("/api/v1/quotes/Q-2026-0000%00", ["path"]),
        ("/api/v1/actuators?family=CHA%00", ["query", "family"]),
        ("/api/v1/quotes?q=%00", ["query", "q"]),
    ],
)
def test_nul_in_the_url(api: SalesApi, path: str, loc: list[str]) -> None:
    response = api.get(path)
    assert response.status_code == 422
    (error,) = response.json()["detail"]
    assert error["loc"] == loc
    assert "U+0000" in error["msg"]


@pytest.mark.parametrize(
    ("method", "path", "body", "loc"),
    [
        ("post", "/api/v1/selections", {**WORKED_EXAMPLE, "models": ["FHA\x00"]}, ["models"]),
        (
            "post",
            "/api/v1/selections/batch",
            {"cases": [WORKED_EXAMPLE, {**WORKED_EXAMPLE, "models": ["FHA\x00"]}]},
            ["cases", 1, "models"],
        ),
        ("post", "/api/v1/actuators", {**NEW, "notes": "a\x00b"}, ["notes"]),
        (
            "post",
            "/api/v1/controllers",
            {"manufacturer": "X\x00", "type": "Y", "source": "z"},
            ["manufacturer"],
        ),
        (
            "put",
            "/api/v1/actuators/CHA-25A-50/interface",
            {"source": "\x00"},
            ["source"],
        ),
    ],
)
def test_nul_in_a_body(
    api: SalesApi, method: str, path: str, body: dict[str, Any], loc: list[str]
) -> None:
    response = admin(api, method, path, json=body)
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", *loc]
    assert "U+0000" in error["msg"]


def test_nul_in_a_quote_writes_no_quote(api: SalesApi) -> None:
    selection = api.selection(["FHA-25C-50-L"])
    body = api.quote_body(selection["id"], customer={"name": "Muster\x00 GmbH"})
    response = api.post("/api/v1/quotes", json=body)
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", "customer", "name"]
    assert api.get("/api/v1/quotes").json()["total"] == 0
