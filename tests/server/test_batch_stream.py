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


def test_a_table_of_cases_is_streamed_and_equals_its_halves(start_server: StartServer) -> None:
    """POST /selections/batch/columns: sent in pieces (chunked), one document whose
    candidates are those of its cases sent in two halves."""
    server, _ = start_server()
    cases = _cases(600)
    columns = {
        name: [case[part][name] for case in cases]
        for part, names in (("load", ("speed_rpm", "torque_nm", "inertia_kgm2")),
                            ("cycle", ("accel_s", "constant_s", "decel_s", "pause_s")))
        for name in names
    }  # fmt: skip
    url = "/api/v1/selections/batch/columns"
    with server.client() as client:
        whole = client.post(url, json={**columns, "top": 2})
        assert whole.status_code == 200, whole.text[:300]
        assert whole.headers.get("transfer-encoding") == "chunked"  # streamed, not buffered
        halves = [
            client.post(url, json={**{k: v[part] for k, v in columns.items()}, "top": 2}).json()
            for part in (slice(0, 250), slice(250, None))
        ]
    document = json.loads(whole.content)
    table = document["candidates"]
    first, second = (half["candidates"] for half in halves)
    assert table["case"] == first["case"] + [250 + i for i in second["case"]]
    for key in table.keys() - {"case"}:
        assert table[key] == first[key] + second[key], key
    for column, a, b in zip(document["checks"], halves[0]["checks"], halves[1]["checks"],
                            strict=True):  # fmt: skip
        assert column["status"] == a["status"] + b["status"]
        assert column["value"] == a["value"] + b["value"]
    assert set(document) == {"catalogue_version", "ranking", "cases", "candidates", "checks",
                             "models"}  # fmt: skip
