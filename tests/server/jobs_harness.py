"""Batch jobs against real processes: servers, ``worker`` processes, a job's life."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx
import pytest
from sqlalchemy import Engine, text
from tests import worked_example

from actuator_selection.config import REPO_ROOT

DEADLINE_S = 300.0
"""A deadline for a job to finish, not an expectation (two shared cores, eight users)."""
STALLED_AFTER_S = 3.0
"""``JOB_STALLED_AFTER_S`` of the workers the tests start: a killed worker's chunk runs
again after about this long."""
NDJSON = {"Content-Type": "application/x-ndjson"}


def cases(n: int) -> bytes:
    """``n`` load cases as JSON lines: the worked example at ``n`` speeds, each its own
    ``case_id`` (``c<index>``)."""
    base = worked_example.request()
    lines = []
    for i in range(n):
        case = json.loads(json.dumps(base))
        case["load"]["speed_rpm"] = 10 + (i % 50)
        case["case_id"] = f"c{i}"
        lines.append(json.dumps(case, separators=(",", ":")))
    return ("\n".join(lines) + "\n").encode()


@dataclass
class Worker:
    """``python -m actuator_selection worker`` in a subprocess."""

    database_url: str
    log_path: Path
    process: subprocess.Popen[bytes] | None = None

    def start(self) -> None:
        env = {
            **os.environ,
            "DATABASE_URL": self.database_url,
            "JOB_STALLED_AFTER_S": str(STALLED_AFTER_S),
        }
        with self.log_path.open("ab") as log:
            self.process = subprocess.Popen(
                [sys.executable, "-m", "actuator_selection", "worker"],
                cwd=REPO_ROOT,
                env=env,
                stdout=log,
                stderr=subprocess.STDOUT,
            )

    @property
    def pid(self) -> int:
        assert self.process is not None
        return self.process.pid

    def kill(self) -> None:
        assert self.process is not None
        self.process.send_signal(signal.SIGKILL)
        self.process.wait(10)

    def stop(self) -> None:
        if self.process is None or self.process.poll() is not None:
            return
        self.process.terminate()
        try:
            self.process.wait(20)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait(10)

    def log(self) -> str:
        return self.log_path.read_text(errors="replace")[-5000:]


def wait_for(predicate: Any, what: str, deadline_s: float = DEADLINE_S) -> Any:
    """Poll ``predicate`` until it returns something true; fail after ``deadline_s``."""
    deadline = time.monotonic() + deadline_s
    while time.monotonic() < deadline:
        found = predicate()
        if found:
            return found
        time.sleep(0.05)
    pytest.fail(f"gave up waiting for {what} after {deadline_s:g} s")


def registered_workers(engine: Engine) -> list[int]:
    """procrastinate's ids of the workers registered now."""
    with engine.connect() as conn:
        return list(conn.scalars(text("SELECT id FROM procrastinate_workers ORDER BY id")))


def submit(client: httpx.Client, body: bytes, **params: Any) -> str:
    """POST the job; its path (``Location``)."""
    response = client.post("/api/v1/batch-jobs", content=body, headers=NDJSON, params=params)
    assert response.status_code == 202, response.text
    location: str = response.headers["Location"]
    assert response.json()["state"] == "queued"
    return location


def finished(client: httpx.Client, location: str) -> dict[str, Any]:
    """Wait until the job has ended; its resource."""

    def ended() -> dict[str, Any] | None:
        job: dict[str, Any] = client.get(location).json()
        return job if job["state"] not in ("queued", "running") else None

    job: dict[str, Any] = wait_for(ended, f"job {location} to end")
    return job


def result_cases(client: httpx.Client, location: str) -> list[dict[str, Any]]:
    """The job's results, one dict per line."""
    response = client.get(f"{location}/results")
    assert response.status_code == 200, response.text
    assert response.headers["content-type"].startswith("application/x-ndjson")
    return [json.loads(line) for line in response.text.splitlines()]


def assert_each_case_once(results: list[dict[str, Any]], n: int) -> None:
    """Every case 0…n-1 answered exactly once, in order, with its own ``case_id``."""
    assert [r["case"] for r in results] == list(range(n))
    assert [r["case_id"] for r in results] == [f"c{i}" for i in range(n)]
    assert all(r["candidates"] for r in results)
