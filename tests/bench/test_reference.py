"""The bench's numpy reference computes what the service computes.

``make bench`` prints the batch's time as a ratio to ``bench/reference.py``, a plain numpy
computation of the same checks and ranking; the ratio means something only while both
name the same best actuators. Here they must, case for case, over random load cases on
the starter catalogue, through the API as a client sees it.
"""

from __future__ import annotations

import sys
from pathlib import Path

from fastapi.testclient import TestClient
from sqlalchemy import Engine

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from bench.reference import disagreements, numpy_reference, snapshot_actuators
from bench.selection import http_case, random_cases

CASES = 600


def test_the_reference_names_the_services_best_three(
    client: TestClient, seeded_engine: Engine
) -> None:
    actuators = snapshot_actuators(seeded_engine.url.render_as_string(hide_password=False))
    apps = random_cases(CASES, seed=5)
    answer = client.post(
        "/api/v1/selections/batch",
        json={"cases": [http_case(a) for a in apps], "top": 3, "include_checks": False},
    )
    assert answer.status_code == 200, answer.text
    service = [[c["model"] for c in r["candidates"]] for r in answer.json()["results"]]
    assert len(service) == CASES
    reference = numpy_reference(actuators, apps, 3)
    assert disagreements(actuators, reference, service) == 0
