"""A million-case batch job over the starter catalogue, computed by two workers.

Not part of the tests. On a throw-away PostgreSQL database ($TEST_POSTGRES_URL), seeded
with the starter catalogue, it starts one server (``serve``) and two ``worker``
processes, sends ``--cases`` random load cases (``bench.selection.random_cases``, the
chapter's cycle) as one job, follows its progress, then downloads the results and checks
that every case is answered exactly once. It prints the time to accept the job, to
compute it and to read it back. ``--kill-at 0.5`` SIGKILLs one worker when half the
cases are done (the job must still complete, every case once).

    python -m bench.jobs                       # 1,000,000 cases, top 3, no checks
    python -m bench.jobs --cases 100000 --kill-at 0.5
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import time
from typing import Any

import httpx
import pydantic_core

from actuator_selection.config import REPO_ROOT
from bench.http import _postgres_database, _serve
from bench.selection import http_case, random_cases, starter_catalogue

WORKERS = 2


BLOCK = 10_000
"""Cases drawn at a time (each block its own seed), so that memory holds their JSON only."""


def _body(n: int) -> bytes:
    """``n`` random cases as JSON lines, each ``case_id`` its index."""
    body = bytearray()
    for first in range(0, n, BLOCK):
        apps = random_cases(min(BLOCK, n - first), seed=first)
        for i, app in enumerate(apps, start=first):
            case = {**_rounded(http_case(app)), "case_id": str(i)}
            body += pydantic_core.to_json(case) + b"\n"
    return bytes(body)


def _rounded(value: Any) -> Any:
    """``value`` with every float to 4 decimals, as an ERP would send its figures."""
    if isinstance(value, dict):
        return {k: _rounded(v) for k, v in value.items()}
    return round(value, 4) if isinstance(value, float) else value


def _worker(url: str) -> subprocess.Popen[bytes]:
    return subprocess.Popen(
        [sys.executable, "-m", "actuator_selection", "worker"],
        cwd=REPO_ROOT,
        env={**os.environ, "DATABASE_URL": url},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )


def main() -> None:
    parser = argparse.ArgumentParser(prog="python -m bench.jobs")
    parser.add_argument("--cases", type=int, default=1_000_000)
    parser.add_argument("--top", type=int, default=3)
    parser.add_argument("--kill-at", type=float, default=None, help="progress to kill at")
    args = parser.parse_args()
    found = _postgres_database()
    if found is None:
        sys.exit("bench.jobs needs PostgreSQL at $TEST_POSTGRES_URL")
    url, drop = found
    processes: list[subprocess.Popen[bytes]] = []
    try:
        starter_catalogue(url)
        # the body is received whole before the request is admitted: give it time and room
        server, base = _serve(url, {"MAX_JOB_BODY_BYTES": str(1 << 30), "BODY_TIMEOUT_S": "600"})
        processes.append(server)
        workers = [_worker(url) for _ in range(WORKERS)]
        processes += workers
        body = _body(args.cases)
        print(
            f"batch job: {args.cases} cases ({len(body) / 1e6:.0f} MB of JSON lines), top "
            f"{args.top}, no checks; {WORKERS} workers on PostgreSQL"
        )
        with httpx.Client(base_url=base, timeout=600) as client:
            start = time.perf_counter()
            accepted = client.post(
                "/api/v1/batch-jobs",
                content=body,
                params={"top": args.top},
                headers={"Content-Type": "application/x-ndjson"},
            )
            accepted.raise_for_status()
            del body
            location = accepted.headers["Location"]
            job = accepted.json()
            took = time.perf_counter() - start
            print(f"  accepted in {took:7.1f} s ({job['chunks']} chunks)")
            computing = time.perf_counter()
            shown = -1.0
            killed = False
            while job["state"] in ("queued", "running"):
                time.sleep(1)
                job = client.get(location).json()
                if job["progress"] - shown >= 0.1:
                    shown = job["progress"]
                    print(
                        f"  {job['progress']:6.1%} after {time.perf_counter() - computing:6.1f} s"
                        f", ETA {job['eta_s']} s"
                    )
                if args.kill_at is not None and not killed and job["progress"] >= args.kill_at:
                    workers[0].send_signal(signal.SIGKILL)
                    killed = True
                    print(f"  SIGKILLed worker 1 at {job['progress']:.1%}")
            computed = time.perf_counter() - computing
            if job["state"] != "done":
                sys.exit(f"the job ended {job['state']}: {job['error']}")
            print(f"  computed in {computed:7.1f} s = {args.cases / computed:8.0f} cases/s")
            reading = time.perf_counter()
            seen = bytearray(args.cases)
            size = 0
            with client.stream("GET", f"{location}/results") as response:
                for line in response.iter_lines():
                    size += len(line) + 1
                    seen[json.loads(line)["case"]] += 1
            read = time.perf_counter() - reading
            once = seen.count(1)
            print(
                f"  results read in {read:7.1f} s ({size / 1e6:.0f} MB); cases answered "
                f"exactly once: {once} of {args.cases}"
                + ("" if once == args.cases else "  ← MISMATCH")
            )
            print(f"  total {time.perf_counter() - start:7.1f} s")
    finally:
        for process in processes:
            if process.poll() is None:
                process.terminate()
                process.wait(30)
        drop()


if __name__ == "__main__":
    main()
