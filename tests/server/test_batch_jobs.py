"""Batch jobs on real processes (issue 32 item 4): workers on PostgreSQL sharing a job, one
killed mid-chunk, every case answered exactly once; cancel; SQLite in the server; 4xx."""

from __future__ import annotations

import csv
import io
import os
import platform
import signal
import socket
import subprocess
import sys
from pathlib import Path
from typing import Any

from sqlalchemy import Engine, text
from tests.server.conftest import CHUNK_CASES, Deploy
from tests.server.jobs_harness import (
    NDJSON,
    assert_each_case_once,
    cases,
    finished,
    registered_workers,
    result_cases,
    submit,
    wait_for,
)

from actuator_selection.app import GC_THRESHOLDS
from actuator_selection.config import REPO_ROOT

CASES = 3000


def _doing(engine: Engine, worker_id: int) -> list[int]:
    """The chunks procrastinate has handed to ``worker_id`` whose answers are not written
    yet (a chunk whose answer is written may still be ``doing`` for a moment, until the
    worker reports it done)."""
    with engine.connect() as conn:
        return list(
            conn.scalars(
                text(
                    "SELECT (j.args->>'chunk')::int FROM procrastinate_jobs j "
                    "WHERE j.worker_id = :w AND j.status = 'doing' AND NOT EXISTS ("
                    "SELECT 1 FROM batch_job_results r WHERE r.chunk = (j.args->>'chunk')::int)"
                ),
                {"w": worker_id},
            )
        )


def _wrote(engine: Engine, worker: str) -> int:
    with engine.connect() as conn:
        return int(
            conn.scalar(
                text("SELECT count(*) FROM batch_job_results WHERE worker = :w"), {"w": worker}
            )
        )


def _writers(engine: Engine, chunks: list[int]) -> set[str]:
    with engine.connect() as conn:
        return set(
            conn.scalars(
                text("SELECT worker FROM batch_job_results WHERE chunk = ANY(:c)"), {"c": chunks}
            )
        )


def test_two_workers_share_a_job_and_one_killed_mid_chunk_loses_nothing(
    deploy: Deploy,
) -> None:
    """Worker A is SIGKILLed while it computes a chunk; that chunk runs again on B, and
    every case is answered exactly once."""
    d = deploy("postgresql")
    server = d.server()
    first = d.worker()
    (first_id,) = registered_workers(d.engine)
    second = d.worker()
    with server.client() as client:
        location = submit(client, cases(CASES), top=5, include_checks="true")
        # A has written a chunk of its share and is inside the next one: A is stopped
        # (SIGSTOP) while this is read, so that it is killed in the state read (a chunk
        # takes a few milliseconds), and let go on where it is between two chunks
        a_wrote = f"{socket.gethostname()}:{first.pid}"

        def stopped_in_a_chunk() -> list[int]:
            os.kill(first.pid, signal.SIGSTOP)
            doing = _doing(d.engine, first_id) if _wrote(d.engine, a_wrote) else []
            if not doing:
                os.kill(first.pid, signal.SIGCONT)
            return doing

        lost = wait_for(stopped_in_a_chunk, "worker A to be in a chunk after one written")
        first.kill()  # A will never write the chunks it holds
        assert lost == _doing(d.engine, first_id)
        assert first.process is not None
        assert first.process.returncode == -9
        job = finished(client, location)
        assert job["state"] == "done", (job, second.log())
        assert job["cases_done"] == CASES
        assert job["chunks_done"] == CASES // CHUNK_CASES
        assert job["progress"] == 1.0
        assert job["eta_s"] == 0
        assert_each_case_once(result_cases(client, location), CASES)
    host = socket.gethostname()
    assert _writers(d.engine, lost) == {f"{host}:{second.pid}"}
    with d.engine.connect() as conn:
        writers = set(conn.scalars(text("SELECT DISTINCT worker FROM batch_job_results")))
    assert writers == {f"{host}:{first.pid}", f"{host}:{second.pid}"}


def test_a_worker_process_is_tuned_as_a_served_one(deploy: Deploy) -> None:
    """A job worker sizes the same batches as ``serve`` does: its process starts with the
    served process's collector thresholds and allocator settings (``app.tune_process``),
    and says so in its log."""
    d = deploy("postgresql")
    said = d.worker().log()  # registered with the queue: its start is logged before that
    allocator = "tuned" if platform.libc_ver()[0] == "glibc" else "as the C library has it"
    assert f"collector thresholds {GC_THRESHOLDS}, allocator {allocator}" in said


def test_a_cancelled_job_stops_and_keeps_nothing(deploy: Deploy) -> None:
    d = deploy("postgresql")
    server = d.server()
    d.worker()
    with server.client() as client:
        location = submit(client, cases(CASES), top=5, include_checks="true")
        wait_for(lambda: client.get(location).json()["chunks_done"], "a chunk to be done")
        cancelled = client.post(f"{location}/cancel")
        assert cancelled.status_code == 200, cancelled.text
        assert cancelled.json()["state"] == "cancelled"
        # the queue drains: the chunks left find the job cancelled and write nothing
        with d.engine.connect() as conn:
            wait_for(
                lambda: (
                    not conn.scalar(
                        text(
                            "SELECT count(*) FROM procrastinate_jobs "
                            "WHERE status IN ('todo', 'doing')"
                        )
                    )
                ),
                "the queue to drain",
            )
            conn.rollback()
            assert conn.scalar(text("SELECT count(*) FROM batch_job_results")) == 0
            assert conn.scalar(text("SELECT count(*) FROM batch_job_chunks")) == 0
        job = client.get(location).json()
        assert (job["state"], job["cases_done"]) == ("cancelled", 0)
        assert client.post(f"{location}/cancel").json()["detail"][0]["type"] == "job_finished"
        assert client.get(f"{location}/results").status_code == 409
        assert client.delete(location).status_code == 204
        assert client.get(location).status_code == 404


def test_without_workers_a_job_waits_queued(deploy: Deploy) -> None:
    d = deploy("postgresql")
    server = d.server()
    with server.client() as client:
        location = submit(client, cases(250))
        job = client.get(location).json()
        assert (job["state"], job["chunks"], job["eta_s"]) == ("queued", 3, None)
        early = client.get(f"{location}/results")
        assert early.status_code == 409
        assert early.json()["detail"][0]["code"] == "job_not_done"
    with d.engine.connect() as conn:
        assert conn.scalar(text("SELECT count(*) FROM procrastinate_jobs")) == 3


def test_on_sqlite_the_server_computes_the_job(deploy: Deploy) -> None:
    d = deploy("sqlite")
    server = d.server()
    with server.client() as client:
        location = submit(client, cases(500), top=2)
        job = finished(client, location)
        assert job["state"] == "done", (job, server.log())
        assert (job["chunks"], job["top"], job["include_checks"]) == (5, 2, False)
        results = result_cases(client, location)
        assert_each_case_once(results, 500)
        assert all(len(r["candidates"]) == 2 for r in results)
        assert all("checks" not in c for r in results for c in r["candidates"])
        table = client.get(f"{location}/results", params={"format": "csv"})
        assert table.status_code == 200, table.text
        assert table.headers["content-type"].startswith("text/csv")
        rows = list(csv.DictReader(io.StringIO(table.text)))
        assert len(rows) == 500 * 2
        expected = [
            (str(r["case"]), r["case_id"], str(rank), c["model"], c["verdict"])
            for r in results
            for rank, c in enumerate(r["candidates"], start=1)
        ]
        columns = ("case", "case_id", "rank", "model", "verdict")
        assert [tuple(row[k] for k in columns) for row in rows] == expected


def test_bad_job_requests_are_4xx_naming_the_field(deploy: Deploy) -> None:
    d = deploy("sqlite")
    server = d.server(MAX_JOB_BODY_BYTES="4096")
    good = cases(3).splitlines()
    with server.client() as client:

        def post(body: bytes, **params: int) -> tuple[int, list[dict[str, Any]]]:
            r = client.post("/api/v1/batch-jobs", content=body, headers=NDJSON, params=params)
            return r.status_code, r.json()["detail"]

        status, detail = post(cases(40))  # 5.5 kB
        assert (status, detail[0]["type"]) == (413, "body_too_large"), detail
        status, detail = post(b"")
        assert (status, detail[0]["code"]) == (422, "job_without_cases")
        status, detail = post(good[0] + b'\n{"load": {"speed_rpm": -1}}\n' + good[1])
        assert status == 422
        assert all(e["loc"][:2] == ["body", 1] for e in detail), detail
        status, detail = post(b"[1, 2]\n")
        assert (status, detail[0]["loc"][:2]) == (422, ["body", 0])
        unknown = good[2].replace(b'"case_id"', b'"models":["NO-SUCH-MODEL"],"case_id"')
        status, detail = post(good[0] + b"\n" + unknown)
        assert (status, detail[0]["loc"], detail[0]["code"]) == (
            422,
            ["body", 1, "models", 0],
            "unknown_actuator",
        )
        status, detail = post(good[0], top=0)
        assert (status, detail[0]["loc"]) == (422, ["query", "top"])
        wrong_type = client.post("/api/v1/batch-jobs", json={"cases": []})
        assert wrong_type.status_code == 415
        assert wrong_type.json()["detail"][0]["loc"] == ["header", "Content-Type"]
        missing = client.get("/api/v1/batch-jobs/no-such-job")
        assert (missing.status_code, missing.json()["detail"][0]["code"]) == (404, "unknown_job")
        assert client.delete("/api/v1/batch-jobs/no-such-job").status_code == 404
        assert client.get("/api/v1/batch-jobs", params={}).status_code in (404, 405)


def test_the_worker_command_refuses_sqlite_saying_the_server_computes_jobs(
    tmp_path: Path,
) -> None:
    url = f"sqlite:///{tmp_path / 'db.sqlite3'}"
    done = subprocess.run(
        [sys.executable, "-m", "actuator_selection", "--database-url", url, "worker"],
        cwd=REPO_ROOT,
        capture_output=True,
        text=True,
        timeout=120,
        check=False,
    )
    assert done.returncode == 2
    assert "the server computes them" in done.stderr
