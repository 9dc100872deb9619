"""Concurrent clients against the real server: no 5xx but a deliberate 503, no reset, no mix-up."""

from __future__ import annotations

import http.client
import json
import re
import subprocess
import threading
import time
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import httpx
from sqlalchemy import text
from tests.server.conftest import (
    WORKED_EXAMPLE,
    LiveServer,
    StartServer,
    quote_body,
    stored_selection,
)

CLIENTS = 32
DURATION_S = 10.0
QUOTE_CLIENTS = 64
QUOTE_NUMBER = re.compile(r"Q-\d{4}-(\d{5})")


def _hammer(
    server: LiveServer, body: dict[str, Any], *, clients: int, seconds: float
) -> Counter[str]:
    """``clients`` keep-alive clients POST ``body`` to /selections for ``seconds``.

    Counts the answers by status and transport failures (resets) by exception type.
    """
    outcomes: Counter[str] = Counter()
    lock = threading.Lock()
    deadline = time.monotonic() + seconds

    def client_loop() -> None:
        with server.client() as client:
            while time.monotonic() < deadline:
                try:
                    status = str(client.post("/api/v1/selections", json=body).status_code)
                except httpx.TransportError as exc:
                    status = type(exc).__name__
                with lock:
                    outcomes[status] += 1

    with ThreadPoolExecutor(clients) as pool:
        for future in [pool.submit(client_loop) for _ in range(clients)]:
            future.result()
    return outcomes


def test_32_clients_posting_whole_catalogue_selections_all_get_201(
    start_server: StartServer,
) -> None:
    server, _ = start_server()
    outcomes = _hammer(server, WORKED_EXAMPLE, clients=CLIENTS, seconds=DURATION_S)
    assert set(outcomes) == {"201"}, outcomes
    assert outcomes["201"] >= CLIENTS


def test_64_concurrent_quotes_are_committed_or_refused_with_503_and_numbered_without_gaps(
    start_server: StartServer,
) -> None:
    server, engine = start_server()
    with server.client("sales") as client:
        selection_id = stored_selection(client)
    barrier = threading.Barrier(QUOTE_CLIENTS)

    def create(i: int) -> httpx.Response:
        with server.client("sales") as client:
            body = quote_body(selection_id, notes=f"client {i}")
            barrier.wait()
            return client.post("/api/v1/quotes", json=body)

    with ThreadPoolExecutor(QUOTE_CLIENTS) as pool:
        answers = list(pool.map(create, range(QUOTE_CLIENTS)))
    statuses = Counter(a.status_code for a in answers)
    assert set(statuses) <= {201, 503}, statuses
    assert all("Retry-After" in a.headers for a in answers if a.status_code == 503)
    answered = sorted(a.json()["number"] for a in answers if a.status_code == 201)
    with engine.connect() as conn:
        stored = sorted(conn.execute(text("SELECT number FROM quotes")).scalars())
    assert stored == answered
    sequence = [int(QUOTE_NUMBER.fullmatch(n).group(1)) for n in stored]  # type: ignore[union-attr]
    assert sequence == list(range(1, len(stored) + 1))


def test_overload_is_answered_503_with_retry_after_at_once(start_server: StartServer) -> None:
    server, _ = start_server(
        MAX_CONCURRENT_REQUESTS="1", MAX_QUEUED_REQUESTS="1", QUEUE_TIMEOUT_S="30"
    )
    barrier = threading.Barrier(12)

    def post(_: int) -> tuple[httpx.Response, float]:
        with server.client() as client:
            barrier.wait()
            started = time.monotonic()
            response = client.post("/api/v1/selections", json=WORKED_EXAMPLE)
            return response, time.monotonic() - started

    with ThreadPoolExecutor(12) as pool:
        answers = list(pool.map(post, range(12)))
    refused = [(r, s) for r, s in answers if r.status_code == 503]
    assert {r.status_code for r, _ in answers} == {201, 503}
    assert all(int(r.headers["Retry-After"]) >= 1 for r, _ in refused)
    # A full queue is answered at once, not after the queue timeout.
    assert min(s for _, s in refused) < 5
    with server.client() as client:
        assert client.get("/api/v1/health").status_code == 200


def test_an_unexpected_error_is_a_500_that_keeps_the_connection(
    start_server: StartServer, tmp_path: Path
) -> None:
    """Starlette's handler for ``Exception`` re-raises after answering; uvicorn then
    closed the keep-alive connection, and the client's next request on it failed."""
    server, _ = start_server()
    server.stop()
    fault = LiveServer(
        database_url=server.database_url,
        log_path=tmp_path / "fault.log",
        keys=server.keys,
        app="tests.server.faulty_app:app",
    )
    fault.start()
    try:
        conn = http.client.HTTPConnection("127.0.0.1", fault.port, timeout=10)
        for path, status in [("/api/v1/deliberate-fault", 500), ("/api/v1/health", 200)] * 2:
            conn.request("GET", path)
            response = conn.getresponse()
            response.read()
            assert response.status == status, path
        conn.close()
    finally:
        fault.stop()


def test_selections_record_the_catalogue_version_they_were_computed_with(
    start_server: StartServer,
) -> None:
    """Catalogue imports alternate T_max of one actuator while clients size against it."""
    server, _ = start_server()
    model = "FHA-25C-50-L"
    with server.client("admin") as admin_client:
        exported = admin_client.get("/api/v1/catalogue/export", params={"format": "json"})
        assert exported.status_code == 200, exported.text
        first = int(admin_client.get("/api/v1/catalogue/version").json()["version"])
    catalogue = exported.json()
    (row,) = [r for r in catalogue["actuators"] if r["model"] == model]
    torques = [float(row["max_torque_nm"]), 97.0]
    expected = {first: torques[0]}
    done = threading.Event()
    changed = threading.Event()  # a few imports have committed
    body = {**WORKED_EXAMPLE, "models": [model]}

    def admin() -> None:
        with server.client("admin") as client:
            for k in range(1, 1000):
                if done.is_set():
                    return
                row["max_torque_nm"] = torques[k % 2]
                imported = client.post(
                    "/api/v1/catalogue/import",
                    content=json.dumps(catalogue),
                    headers={"content-type": "application/json"},
                )
                assert imported.status_code == 200, imported.text
                expected[first + k] = torques[k % 2]
                if k == 3:
                    changed.set()

    def size() -> list[dict[str, Any]]:
        # Size until the catalogue has changed under the clients, however fast
        # a selection is against an import (bounded).
        out: list[dict[str, Any]] = []
        with server.client() as client:
            while len(out) < 30 or (not changed.is_set() and len(out) < 5000):
                response = client.post("/api/v1/selections", json=body)
                assert response.status_code == 201, response.text
                out.append(response.json())
        return out

    with ThreadPoolExecutor(5) as pool:
        writer = pool.submit(admin)
        sizers = [pool.submit(size) for _ in range(4)]
        selections = [s for f in sizers for s in f.result()]
        done.set()
        writer.result()
    seen: Counter[int] = Counter()
    for selection in selections:
        (candidate,) = selection["candidates"]
        version = selection["catalogue_version"]
        (peak,) = [c for c in candidate["checks"] if c["name"] == "peak_torque"]
        assert peak["limit"] == expected[version], (version, peak["limit"])
        seen[version] += 1
    assert len(seen) > 1  # the catalogue did change under the clients


def test_two_worker_processes_serve_one_coherent_catalogue(start_server: StartServer) -> None:
    """``serve --workers 2``: an admin change made through one process is seen by both."""
    server, _ = start_server(WORKERS="2")
    assert server.process is not None
    children = subprocess.run(
        ["pgrep", "-P", str(server.process.pid)], capture_output=True, text=True, check=False
    ).stdout.split()
    assert len(children) >= 2, children  # the supervisor's workers (and its resource tracker)
    model = "FHA-25C-50-L"
    with server.client("admin") as admin_client:
        exported = admin_client.get("/api/v1/catalogue/export", params={"format": "json"})
        (row,) = [r for r in exported.json()["actuators"] if r["model"] == model]
        put = admin_client.put(f"/api/v1/actuators/{model}", json={**row, "max_torque_nm": 97})
        assert put.status_code == 200, put.text
    body = {**WORKED_EXAMPLE, "models": [model]}
    limits = set()
    for _ in range(20):
        with server.client() as client:  # a new connection each time: either worker
            (candidate,) = client.post("/api/v1/selections", json=body).json()["candidates"]
        limits |= {c["limit"] for c in candidate["checks"] if c["name"] == "peak_torque"}
    assert limits == {97}
