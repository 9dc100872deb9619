"""The error handlers: a write conflict is a 409 that says to retry, never a 500."""

from __future__ import annotations

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from sqlalchemy.exc import IntegrityError

from actuator_selection.api import errors


def test_a_write_conflict_is_409_and_says_to_retry() -> None:
    app = FastAPI()
    errors.install(app)

    @app.post("/conflict")
    def conflict() -> None:
        # What a unique index raises when a concurrent transaction committed the key first.
        raise IntegrityError("INSERT INTO controllers ...", {}, Exception("duplicate key"))

    @app.post("/broken")
    def broken() -> None:
        raise RuntimeError("a bug")

    client = TestClient(app, raise_server_exceptions=False)
    response = client.post("/conflict")
    assert response.status_code == 409
    (entry,) = response.json()["detail"]
    assert entry["type"] == "write_conflict"
    assert "send it again" in entry["msg"]
    assert client.post("/broken").status_code == 500  # other errors are not dressed as 409


@pytest.mark.parametrize(
    ("method", "path", "status", "loc", "type_"),
    [
        ("get", "/api/v1/actuators/NOPE", 404, ["path", "model"], "not_found"),
        ("get", "/api/v1/selections/nope", 404, ["path", "selection_id"], "not_found"),
        ("get", "/api/v1/controllers/999", 404, ["path", "row"], "not_found"),
        ("get", "/api/v1/no-such-route", 404, ["path"], "not_found"),
        ("delete", "/api/v1/health", 405, ["request"], "method_not_allowed"),
        ("get", "/api/v1/quotes", 401, ["header", "Authorization"], "unauthorized"),
        ("post", "/api/v1/selections", 422, ["body"], "missing"),
    ],
)
def test_every_error_has_the_one_shape(
    client: TestClient, method: str, path: str, status: int, loc: list[str], type_: str
) -> None:
    """Every 4xx answers ``{"detail": [{"loc", "msg", "type"}]}`` naming where and which rule."""
    response = getattr(client, method)(path)
    assert response.status_code == status
    entries = response.json()["detail"]
    assert isinstance(entries, list)
    assert all(set(e) >= {"loc", "msg", "type"} and e["msg"] for e in entries)
    assert (entries[0]["loc"], entries[0]["type"]) == (loc, type_)
