"""The batch answer is streamed slice by slice by the real server, and reads as one document."""

from __future__ import annotations

import gzip
import json
import random
from typing import Any

import zstandard
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


def test_a_streamed_table_comes_in_the_encoding_the_client_accepts(
    start_server: StartServer,
) -> None:
    """zstd where the client accepts it, else gzip, else none; each is the same
    document as sent uncompressed, byte for byte."""
    server, _ = start_server()
    cases = _cases(400)
    body = {
        "speed_rpm": [c["load"]["speed_rpm"] for c in cases],
        "torque_nm": [c["load"]["torque_nm"] for c in cases],
        "inertia_kgm2": [c["load"]["inertia_kgm2"] for c in cases],
        **{name: [c["cycle"][name] for c in cases] for name in cases[0]["cycle"]},
        "top": 3,
    }
    url = "/api/v1/selections/batch/columns"
    answers: dict[str, tuple[str | None, bytes]] = {}
    with server.client() as client:
        for accepted in ("identity", "gzip", "gzip, deflate, br, zstd", "zstd;q=0, gzip"):
            with client.stream(
                "POST", url, json=body, headers={"Accept-Encoding": accepted}
            ) as response:
                assert response.status_code == 200
                assert response.headers.get("transfer-encoding") == "chunked"
                wire = b"".join(response.iter_raw())
                answers[accepted] = (response.headers.get("content-encoding"), wire)
    plain_encoding, plain = answers["identity"]
    assert plain_encoding is None
    assert len(json.loads(plain)["cases"]["cycle_time_s"]) == len(cases)
    assert answers["gzip"][0] == "gzip"
    assert gzip.decompress(answers["gzip"][1]) == plain
    assert answers["gzip, deflate, br, zstd"][0] == "zstd"
    assert (
        zstandard.ZstdDecompressor()
        .decompressobj()
        .decompress(answers["gzip, deflate, br, zstd"][1])
        == plain
    )
    assert answers["zstd;q=0, gzip"][0] == "gzip"  # a refused coding is not used
    assert len(answers["gzip, deflate, br, zstd"][1]) < len(plain) / 2
