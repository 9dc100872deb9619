"""The batch answer is streamed slice by slice by the real server, and reads as one document."""

from __future__ import annotations

import json
import random
from typing import Any

from tests.server.conftest import StartServer

from actuator_selection.services.batch import STREAM_CASES


def _cases(n: int) -> list[dict[str, Any]]:
    rng = random.Random(11)
    return [
        {
            "load": {
                "speed_rpm": rng.uniform(5, 150),
                "torque_nm": rng.uniform(0, 50),
                "inertia_kgm2": rng.uniform(0, 5),
            },
            "cycle": {
                "accel_s": rng.uniform(0.05, 0.5),
                "constant_s": rng.uniform(0, 1),
                "decel_s": rng.uniform(0.05, 0.5),
                "pause_s": rng.uniform(0, 2),
            },
        }
        for _ in range(n)
    ]


def test_a_batch_of_several_slices_is_one_document_equal_to_its_parts(
    start_server: StartServer,
) -> None:
    server, _ = start_server()
    cases = _cases(2 * STREAM_CASES + 7)
    with server.client() as client:
        whole = client.post("/api/v1/selections/batch", json={"cases": cases, "top": 2})
        assert whole.status_code == 200, whole.text[:300]
        assert whole.headers.get("transfer-encoding") == "chunked"  # streamed, not buffered
        document = json.loads(whole.content)
        parts = []
        for start in range(0, len(cases), 300):  # other slice bounds than the server's
            part = client.post(
                "/api/v1/selections/batch",
                json={"cases": cases[start : start + 300], "top": 2},
            )
            assert part.status_code == 200
            parts += part.json()["results"]
    assert len(document["results"]) == len(cases)
    assert document["results"] == parts
    assert set(document) == {"catalogue_version", "ranking", "results"}
