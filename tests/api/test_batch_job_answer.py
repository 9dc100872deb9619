"""A batch job's 202 is the job as accepted, whatever its workers do meanwhile (issue 32
item 4): a CI run read back a job the in-process worker had started already."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient
from tests.server.jobs_harness import NDJSON, cases

from actuator_selection.i18n.localize import localizer
from actuator_selection.services import jobs


class EagerQueue:
    """The quickest worker there can be: computes every chunk, for real, as it is queued."""

    def __init__(self, app: Any) -> None:
        self.app = app
        self.ran: list[tuple[str, int]] = []

    def enqueue(self, job_id: str, chunks: int) -> None:
        state = self.app.state
        for chunk in range(chunks):
            jobs.run_chunk(state.session_factory, state.catalogue, localizer, job_id, chunk)
            self.ran.append((job_id, chunk))

    def close(self) -> None:
        pass


def test_the_202_is_the_job_as_accepted_though_a_worker_has_done_it(client: TestClient) -> None:
    queue = EagerQueue(client.app)
    client.app.state.job_queue, before = queue, client.app.state.job_queue  # type: ignore[attr-defined]
    try:
        response = client.post("/api/v1/batch-jobs", content=cases(250), headers=NDJSON)
    finally:
        client.app.state.job_queue = before  # type: ignore[attr-defined]
    assert response.status_code == 202, response.text
    accepted = response.json()
    per_chunk = client.app.state.settings.job_chunk_cases  # type: ignore[attr-defined]
    chunks = -(-250 // per_chunk)
    assert (accepted["state"], accepted["cases_done"], accepted["chunks"]) == ("queued", 0, chunks)
    assert accepted["started_at"] is None
    assert queue.ran == [(accepted["id"], k) for k in range(chunks)]
    now = client.get(response.headers["Location"]).json()
    assert (now["state"], now["cases_done"]) == ("done", 250)
