"""Hostile input against the real server: one request must not stop the process (issue 26).

Unit text used to be matched by a pattern with nested quantifiers: ``"1 aaaa…a!"`` in one
field held the event loop for seconds, doubling with each letter, and nothing else was
answered, ``/health`` included. Here the longest such text goes to the server, again and
again from one thread, while another asks ``/health``: both answer, each in no more time
than a few normal selections take (SQLite and PostgreSQL). Likewise a batch body that
takes seconds to validate leaves ``/health`` answering while it is validated.
"""

from __future__ import annotations

import json
import select
import socket
import statistics
import threading
import time
from typing import Any

import httpx
from bench.batch import slow_to_validate
from tests.server.conftest import StartServer

from actuator_selection.schemas.quantities import MAX_QUANTITY_TEXT

RATIO = 50
"""A refused request or a health check meanwhile may take this many times a normal
selection (each takes less); headroom for a machine shared with other work."""
ATTACKS = 5
TIMEOUT_S = 60.0
"""The clients' timeout (``LiveServer.client``): the old pattern took years on this text."""


def body(mass: str) -> dict[str, Any]:
    """The issue's reproducer: a belt axis whose mass is ``mass``."""
    return {
        "load": {
            "type": "belt",
            "speed": 300,
            "mass_kg": mass,
            "pulley_diameter_mm": 50,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
        },
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
    }


def test_adversarial_unit_text_leaves_health_answering(start_server: StartServer) -> None:
    server, _ = start_server()
    hostile = body("1 " + "a" * (MAX_QUANTITY_TEXT - 3) + "!")
    assert len(hostile["load"]["mass_kg"]) == MAX_QUANTITY_TEXT
    with server.client() as client:
        normal = []
        for _ in range(3):
            start = time.perf_counter()
            response = client.post("/api/v1/selections", json=body("1 kg"))
            normal.append(time.perf_counter() - start)
            assert response.status_code == 201, response.text
    budget = RATIO * statistics.median(normal)

    answers: list[tuple[int, float]] = []
    failures: list[BaseException] = []

    def attack() -> None:
        try:
            with server.client() as attacker:
                for _ in range(ATTACKS):
                    start = time.perf_counter()
                    response = attacker.post("/api/v1/selections", json=hostile)
                    answers.append((response.status_code, time.perf_counter() - start))
        except httpx.HTTPError as exc:
            failures.append(exc)

    thread = threading.Thread(target=attack)
    health: list[float] = []
    with server.client() as checker:
        thread.start()
        while thread.is_alive() or len(health) < ATTACKS:
            start = time.perf_counter()
            response = checker.get("/api/v1/health")
            health.append(time.perf_counter() - start)
            assert response.status_code == 200, response.text
    thread.join(TIMEOUT_S)
    assert not failures, failures
    assert [status for status, _ in answers] == [422] * ATTACKS
    assert max(elapsed for _, elapsed in answers) <= budget, (answers, budget)
    assert max(health) <= budget, (health, budget)


def test_a_batch_being_validated_leaves_health_answering(start_server: StartServer) -> None:
    """The per-case batch's cases are validated off the event loop: ``/health``, asked
    once the batch's body is sent, is answered while the batch is still being validated
    (its 422 not yet come). Validated on the event loop (as FastAPI does by itself), the
    process answered the 422 first and ``/health`` only after it."""
    server, _ = start_server()
    n, body = slow_to_validate()  # seconds of validation, the last case refused
    url = httpx.URL(server.url)
    head = (
        f"POST /api/v1/selections/batch HTTP/1.1\r\nHost: {url.host}:{url.port}\r\n"
        f"Content-Type: application/json\r\nContent-Length: {len(body)}\r\n"
        "Connection: close\r\n\r\n"
    ).encode()
    with socket.create_connection((url.host, url.port), timeout=TIMEOUT_S) as batch:
        batch.sendall(head + body)
        with server.client() as checker:
            health = checker.get("/api/v1/health")
        answered_first = select.select([batch], [], [], 0)[0] == []
        answer = _read_all(batch)
    assert health.status_code == 200, health.text
    status_line, _, rest = answer.partition(b"\r\n")
    assert status_line.split()[1] == b"422", answer[:2000]
    assert ["body", "cases", n - 1, "load", "torque_nm"] in [
        error["loc"] for error in json.loads(_body_of(rest))["detail"]
    ]
    assert answered_first, "/health was answered only after the batch's validation"


def _read_all(sock: socket.socket) -> bytes:
    """Everything the server sends until it closes the connection."""
    pieces = []
    while piece := sock.recv(1 << 16):
        pieces.append(piece)
    return b"".join(pieces)


def _body_of(after_status: bytes) -> bytes:
    """The body of an HTTP/1.1 answer (after its status line), chunked or not."""
    headers, _, body = after_status.partition(b"\r\n\r\n")
    if b"transfer-encoding: chunked" not in headers.lower():
        return body
    out: list[bytes] = []
    while True:
        size, _, body = body.partition(b"\r\n")
        n = int(size, 16)
        if not n:
            return b"".join(out)
        out.append(body[:n])
        body = body[n + 2 :]
