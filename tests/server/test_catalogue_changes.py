"""Catalogue changes made through the API are seen by the next request of every process."""

from __future__ import annotations

from typing import Any

from tests.server.conftest import WORKED_EXAMPLE, LiveServer, StartServer

TRIES = 20
COPIED = "FHA-25C-50-L"
NEW_MODEL = "FHA-25C-50-L-TEST"
"""A model created by the test: the published row of :data:`COPIED` under a new name."""


def _select(server: LiveServer, models: list[str]) -> Any:
    with server.client() as client:  # a new connection each time: any worker
        return client.post("/api/v1/selections", json={**WORKED_EXAMPLE, "models": models})


def test_a_model_created_by_an_admin_is_selectable_at_once_in_every_worker(
    start_server: StartServer,
) -> None:
    """Each worker holds the catalogue before the model is created (a selection naming an
    existing model); a selection naming only the new model then finds it, whichever
    worker answers, with no whole-catalogue selection in between."""
    server, _ = start_server(WORKERS="2")
    for _ in range(2 * TRIES):
        assert _select(server, [COPIED]).status_code == 201
    with server.client("admin") as admin:
        exported = admin.get("/api/v1/catalogue/export", params={"format": "json"}).json()
        (row,) = [r for r in exported["actuators"] if r["model"] == COPIED]
        created = admin.post("/api/v1/actuators", json={**row, "model": NEW_MODEL})
        assert created.status_code == 201, created.text
    answers = [_select(server, [NEW_MODEL]) for _ in range(TRIES)]
    assert [a.status_code for a in answers] == [201] * TRIES, answers[0].text
    for answer in answers:
        (candidate,) = answer.json()["candidates"]
        assert candidate["model"] == NEW_MODEL
