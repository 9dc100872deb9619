"""The error handlers: a write conflict is a 409 that says to retry, never a 500."""

from __future__ import annotations

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
    assert "send it again" in response.json()["detail"]
    assert client.post("/broken").status_code == 500  # other errors are not dressed as 409
