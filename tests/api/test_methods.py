"""405 and OPTIONS name the methods a path allows; CORS only where configured
(issue 26 item 6)."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from fastapi.testclient import TestClient
from sqlalchemy import Engine

from actuator_selection.app import create_app
from actuator_selection.config import Settings
from actuator_selection.schemas.tools import SensorTemperatureRequest

TOOL = "/api/v1/tools/sensor-temperature"
TOOL_BODY: dict[str, Any] = SensorTemperatureRequest.model_json_schema()["examples"][0]
LISTED_ORIGIN = "https://tools.example.com"


def _entry(response: Any) -> dict[str, Any]:
    (entry,) = response.json()["detail"]
    assert set(entry) >= {"loc", "msg", "type", "code", "params"}
    return dict(entry)


@pytest.mark.parametrize(
    ("method", "path", "allowed"),
    [
        ("DELETE", "/api/v1/health", "GET, HEAD, OPTIONS"),
        ("DELETE", "/api/v1/selections", "OPTIONS, POST"),
        ("PUT", TOOL, "OPTIONS, POST"),
        ("PATCH", "/api/v1/actuators", "GET, HEAD, OPTIONS, POST"),
        ("POST", "/api/v1/actuators/FHA-25C-50-L", "DELETE, GET, HEAD, OPTIONS, PUT"),
    ],
)
def test_a_405_names_the_methods_the_path_allows(
    client: TestClient, method: str, path: str, allowed: str
) -> None:
    """Not the static mount's ``GET, HEAD``: the union of the methods of every route on
    the path (a path may be served by several routes), and OPTIONS."""
    response = client.request(method, path)
    assert response.status_code == 405
    assert response.headers["Allow"] == allowed
    entry = _entry(response)
    assert (entry["loc"], entry["code"]) == (["request"], "method_not_allowed")
    assert entry["params"] == {"method": method, "allowed": allowed}


def test_every_method_the_allow_header_names_is_served(client: TestClient) -> None:
    """What a 405 lists is true: none of those methods is refused with 405 itself."""
    allowed = client.post("/api/v1/actuators/FHA-25C-50-L").headers["Allow"].split(", ")
    for method in allowed:
        response = client.request(method, "/api/v1/actuators/FHA-25C-50-L")
        assert response.status_code != 405, method


def test_head_answers_as_get_without_the_body(client: TestClient) -> None:
    got = client.get("/api/v1/actuators/FHA-25C-50-L")
    head = client.head("/api/v1/actuators/FHA-25C-50-L")
    assert (head.status_code, got.status_code) == (200, 200)
    assert head.content == b""
    assert head.headers["content-type"] == got.headers["content-type"]
    assert head.headers["content-length"] == got.headers["content-length"]
    missing = client.head("/api/v1/actuators/NOPE")
    assert (missing.status_code, missing.content) == (404, b"")


def test_options_answers_the_allowed_methods(client: TestClient) -> None:
    response = client.options("/api/v1/selections")
    assert response.status_code == 204
    assert response.headers["Allow"] == "OPTIONS, POST"
    assert response.content == b""


def test_without_cors_a_preflight_gets_no_permission(client: TestClient) -> None:
    """No CORS_ALLOW_ORIGINS (the default): the preflight is answered with ``Allow`` but
    grants no other origin anything, so a browser refuses the cross-origin call."""
    response = client.options(
        "/api/v1/selections",
        headers={"Origin": LISTED_ORIGIN, "Access-Control-Request-Method": "POST"},
    )
    assert response.status_code == 204
    assert response.headers["Allow"] == "OPTIONS, POST"
    assert "Access-Control-Allow-Origin" not in response.headers


@pytest.fixture
def cors_client(seeded_engine: Engine) -> Iterator[TestClient]:
    """The API with ``CORS_ALLOW_ORIGINS`` naming :data:`LISTED_ORIGIN`."""
    url = seeded_engine.url.render_as_string(hide_password=False)
    app = create_app(Settings(database_url=url, cors_allow_origins=f" {LISTED_ORIGIN} ,"))
    with TestClient(app, raise_server_exceptions=False) as test_client:
        yield test_client


def test_a_preflight_from_a_listed_origin_succeeds(cors_client: TestClient) -> None:
    response = cors_client.options(
        TOOL,
        headers={
            "Origin": LISTED_ORIGIN,
            "Access-Control-Request-Method": "POST",
            "Access-Control-Request-Headers": "authorization, content-type",
        },
    )
    assert response.status_code == 200
    assert response.headers["Access-Control-Allow-Origin"] == LISTED_ORIGIN
    assert "POST" in response.headers["Access-Control-Allow-Methods"]
    allowed_headers = response.headers["Access-Control-Allow-Headers"].lower()
    assert {"authorization", "content-type"} <= set(allowed_headers.replace(" ", "").split(","))
    answer = cors_client.post(TOOL, json=TOOL_BODY, headers={"Origin": LISTED_ORIGIN})
    assert answer.status_code == 200, answer.text
    assert answer.headers["Access-Control-Allow-Origin"] == LISTED_ORIGIN


def test_a_preflight_from_another_origin_gets_no_permission(cors_client: TestClient) -> None:
    response = cors_client.options(
        TOOL,
        headers={"Origin": "https://elsewhere.example", "Access-Control-Request-Method": "POST"},
    )
    assert response.status_code == 204
    assert response.headers["Allow"] == "OPTIONS, POST"
    assert "Access-Control-Allow-Origin" not in response.headers


def test_an_unknown_api_path_is_404_whatever_the_method(client: TestClient) -> None:
    response = client.post("/api/v1/no-such-route", json={})
    assert response.status_code == 404
    entry = _entry(response)
    assert (entry["loc"], entry["code"]) == (["path"], "route_not_found")


def test_the_405_message_in_german(client: TestClient) -> None:
    response = client.delete("/api/v1/health", headers={"Accept-Language": "de"})
    assert response.status_code == 405
    assert _entry(response)["msg"] == (
        "Methode DELETE ist hier nicht zulässig; zulässig: GET, HEAD, OPTIONS"
    )
