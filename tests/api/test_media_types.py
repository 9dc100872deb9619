"""JSON endpoints take UTF-8 JSON alone: 415 in the error shape for another media type,
none, or another encoding; file imports keep their own types (issue 26 item 6)."""

from __future__ import annotations

import json
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.config import SEED_DIR
from actuator_selection.http.openapi import ERROR_SCHEMA
from actuator_selection.schemas.tools import SensorTemperatureRequest

__all__ = ["api", "sales_api_with"]

TOOL = "/api/v1/tools/sensor-temperature"
TOOL_BODY: dict[str, Any] = SensorTemperatureRequest.model_json_schema()["examples"][0]


def _entry(response: Any) -> dict[str, Any]:
    (entry,) = response.json()["detail"]
    assert set(entry) >= {"loc", "msg", "type", "code", "params"}
    return dict(entry)


@pytest.mark.parametrize(
    ("content_type", "body", "code", "params"),
    [
        (
            "text/plain",
            json.dumps(TOOL_BODY).encode(),
            "unsupported_media_type",
            {"given": "text/plain", "accepted": "application/json"},
        ),
        (
            "application/x-www-form-urlencoded",
            b"sensor=kty84_130&resistance_ohm=1000",
            "unsupported_media_type",
            {"given": "application/x-www-form-urlencoded", "accepted": "application/json"},
        ),
        (
            "multipart/form-data; boundary=x",
            b'--x\r\nContent-Disposition: form-data; name="sensor"\r\n\r\nkty84_130\r\n--x--\r\n',
            "unsupported_media_type",
            {"given": "multipart/form-data", "accepted": "application/json"},
        ),
        (
            None,
            json.dumps(TOOL_BODY).encode(),
            "media_type_missing",
            {"accepted": "application/json"},
        ),
        (
            "application/json",
            json.dumps(TOOL_BODY).encode("utf-16"),
            "unsupported_charset",
            {"charset": "utf-16"},
        ),
        (
            "application/json",
            json.dumps(TOOL_BODY).encode("utf-32-le"),
            "unsupported_charset",
            {"charset": "utf-32-le"},
        ),
        (
            "application/json; charset=iso-8859-1",
            json.dumps(TOOL_BODY).encode(),
            "unsupported_charset",
            {"charset": "iso-8859-1"},
        ),
    ],
)
def test_a_json_endpoint_answers_415_for_anything_but_utf8_json(
    client: TestClient, content_type: str | None, body: bytes, code: str, params: dict[str, Any]
) -> None:
    headers = {"Content-Type": content_type} if content_type else {}
    response = client.post(TOOL, content=body, headers=headers)
    assert response.status_code == 415, response.text
    entry = _entry(response)
    assert entry["loc"] == ["header", "Content-Type"]
    assert entry["type"] == "unsupported_media_type"
    assert (entry["code"], entry["params"]) == (code, params)


@pytest.mark.parametrize(
    "content_type",
    ["application/json", "application/json; charset=utf-8", "application/json; charset=UTF-8"],
)
def test_utf8_json_is_taken(client: TestClient, content_type: str) -> None:
    response = client.post(
        TOOL, content=json.dumps(TOOL_BODY).encode(), headers={"Content-Type": content_type}
    )
    assert response.status_code == 200, response.text


def test_the_415_message_in_german(client: TestClient) -> None:
    response = client.post(
        TOOL,
        content=json.dumps(TOOL_BODY).encode(),
        headers={"Content-Type": "text/plain", "Accept-Language": "de"},
    )
    assert response.status_code == 415
    assert _entry(response)["msg"] == (
        "Content-Type text/plain wird hier nicht angenommen; senden Sie application/json"
    )


def test_file_imports_keep_their_own_media_types(api: SalesApi) -> None:
    """The price import takes CSV and the catalogue import JSON in its own reading (the
    JSON rule does not reach them); their 415 is worded like the JSON endpoints'."""
    admin = api.headers("admin")
    csv = (SEED_DIR / "example_prices.csv").read_bytes()
    taken = api.client.post(
        "/api/v1/price-lists/import?dry_run=true",
        content=csv,
        headers={**admin, "Content-Type": "text/csv; charset=utf-8"},
    )
    assert taken.status_code == 200, taken.text
    refused = api.client.post(
        "/api/v1/price-lists/import?dry_run=true",
        content=csv,
        headers={**admin, "Content-Type": "application/zip", "Accept-Language": "de"},
    )
    assert refused.status_code == 415
    entry = _entry(refused)
    assert (entry["code"], entry["params"]) == (
        "unsupported_media_type",
        {"given": "application/zip", "accepted": "text/csv"},
    )
    assert entry["msg"].startswith("Content-Type application/zip wird hier nicht angenommen")


def test_the_openapi_document_lists_415_for_every_json_body(client: TestClient) -> None:
    document = client.get("/openapi.json").json()
    bodies = 0
    for item in document["paths"].values():
        for op in item.values():
            content = op.get("requestBody", {}).get("content", {})
            if list(content) == ["application/json"]:
                bodies += 1
                schema = op["responses"]["415"]["content"]["application/json"]["schema"]
                assert schema == {"$ref": f"#/components/schemas/{ERROR_SCHEMA}"}
    assert bodies > 10
