"""A batch job's 202 is the job as accepted, whatever its workers do meanwhile (issue 32
item 4): a CI run read back a job the in-process worker had started already. A job's
answer is the batch's: each line the result ``POST /selections/batch`` gives the case in
words, in the job's language, with ``case`` first."""

from __future__ import annotations

import json
from typing import Any

import pytest
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


@pytest.mark.parametrize(("language", "checks", "top"), [("en", False, 3), ("de", True, 2)])
def test_a_jobs_lines_are_the_batchs_results_in_words(
    client: TestClient, language: str, checks: bool, top: int
) -> None:
    per_chunk = client.app.state.settings.job_chunk_cases  # type: ignore[attr-defined]
    body = cases(max(per_chunk, 200) + 30)  # two chunks, two slices of the batch engine's
    queue = EagerQueue(client.app)
    client.app.state.job_queue, before = queue, client.app.state.job_queue  # type: ignore[attr-defined]
    params: dict[str, str | int] = {"top": top, "include_checks": str(checks).lower()}
    words = {"Accept-Language": language}
    try:
        response = client.post(
            "/api/v1/batch-jobs", content=body, headers=NDJSON | words, params=params
        )
    finally:
        client.app.state.job_queue = before  # type: ignore[attr-defined]
    assert response.status_code == 202, response.text
    assert len({chunk for _, chunk in queue.ran}) > 1
    lines = client.get(f"{response.headers['Location']}/results").content.splitlines()
    batch = client.post(
        "/api/v1/selections/batch",
        json={
            "cases": [json.loads(line) for line in body.splitlines()],
            "top": top,
            "include_checks": checks,
            "include_messages": True,
        },
        headers=words,
    )
    assert batch.status_code == 200, batch.text
    expected = [{"case": k, **r} for k, r in enumerate(batch.json()["results"])]
    found = [json.loads(line) for line in lines]
    assert found == expected
    assert [list(r) for r in found] == [list(r) for r in expected]  # members in order
    assert all(c["reasons"] is not None for r in found for c in r["candidates"])
