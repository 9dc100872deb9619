"""Hostile input against the real server: one request must not stop the process (issue 26).

Unit text used to be matched by a pattern with nested quantifiers: ``"1 aaaa…a!"`` in one
field held the event loop for seconds, doubling with each letter, and nothing else was
answered, ``/health`` included. Here the longest such text goes to the server, again and
again from one thread, while another asks ``/health``: both answer, each in no more time
than a few normal selections take (SQLite and PostgreSQL).
"""

from __future__ import annotations

import statistics
import threading
import time
from typing import Any

import httpx
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
