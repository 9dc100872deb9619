"""A catalogue import of 20,000 actuators through the real server: streamed, atomic, seen
by every worker; a bad row is named by line and column; an upload cut off commits nothing.

The catalogue is the bench's synthetic one (``bench/catalogue.py``: made-up ``SYN-…``
actuators, not data); its actuators.csv unpacks to about 29 MB, beyond the 20 MiB a member
was once held whole in memory.
"""

from __future__ import annotations

import socket
from collections.abc import Iterator

import httpx
from bench.catalogue import catalogue_zip
from sqlalchemy import Engine, select
from tests.server.conftest import WORKED_EXAMPLE, LiveServer, StartServer

from actuator_selection.db.models import ActuatorRow, CatalogueStateRow

ROWS = 20_000
TRIES = 12
LAST = f"SYN-{ROWS - 1:04d}"
IMPORT = "/api/v1/catalogue/import"
ZIP = {"Content-Type": "application/zip"}


def _chunks(body: bytes, size: int = 64 << 10) -> Iterator[bytes]:
    """The body in pieces: httpx sends it chunked, without a Content-Length."""
    for start in range(0, len(body), size):
        yield body[start : start + size]


def _state(engine: Engine) -> tuple[int, int]:
    """The catalogue version and the number of actuators stored."""
    with engine.connect() as conn:
        version = conn.scalar(select(CatalogueStateRow.version)) or 0
        count = len(conn.execute(select(ActuatorRow.id)).all())
    return version, count


def _select(server: LiveServer, model: str) -> httpx.Response:
    with server.client() as client:  # a new connection each time: any worker
        return client.post("/api/v1/selections", json={**WORKED_EXAMPLE, "models": [model]})


def test_a_large_import_is_streamed_committed_and_seen_by_every_worker(
    start_server: StartServer,
) -> None:
    server, engine = start_server(WORKERS="2", BODY_TIMEOUT_S="120")
    for _ in range(2 * TRIES):  # each worker holds the starter catalogue
        assert _select(server, "FHA-25C-50-L").status_code == 201
    before, seeded = _state(engine)
    with server.client("admin") as admin:
        answer = admin.post(IMPORT, content=_chunks(catalogue_zip(ROWS)), headers=ZIP, timeout=600)
    assert answer.status_code == 200, answer.text
    body = answer.json()
    assert body["files"]["actuators.csv"]["inserted"] == ROWS
    assert body["catalogue_version"] == before + 1
    assert _state(engine) == (before + 1, seeded + ROWS)
    answers = [_select(server, LAST) for _ in range(TRIES)]
    assert [a.status_code for a in answers] == [201] * TRIES, answers[0].text
    assert all(a.json()["candidates"][0]["model"] == LAST for a in answers)


def test_a_bad_row_is_named_and_nothing_is_written(start_server: StartServer) -> None:
    server, engine = start_server()
    before = _state(engine)
    line = 15_001
    with server.client("admin") as admin:
        answer = admin.post(
            IMPORT, content=catalogue_zip(ROWS, bad_line=line), headers=ZIP, timeout=600
        )
    assert answer.status_code == 422, answer.text
    (entry,) = answer.json()["detail"]
    assert entry["loc"] == ["body", "actuators.csv", line, "max_torque_nm"]
    assert entry["line"] == line
    assert "must be a finite number > 0" in entry["msg"]
    assert _state(engine) == before


def test_an_upload_cut_off_commits_nothing(start_server: StartServer) -> None:
    server, engine = start_server(BODY_TIMEOUT_S="5")
    before = _state(engine)
    body = catalogue_zip(ROWS)
    head = (
        f"POST {IMPORT} HTTP/1.1\r\nHost: 127.0.0.1\r\n"
        f"Authorization: Bearer {server.keys['admin']}\r\n"
        f"Content-Type: application/zip\r\nContent-Length: {len(body)}\r\n\r\n"
    )
    for cut in (len(body) // 2, len(body) - 1):
        with socket.create_connection(("127.0.0.1", server.port), timeout=30) as sock:
            sock.sendall(head.encode() + body[:cut])
        # the client has gone; whatever the server did with the half, nothing is stored
        assert _select(server, "FHA-25C-50-L").status_code == 201
        assert _state(engine) == before
    with server.client("admin") as admin:  # the whole body still imports
        assert admin.post(IMPORT, content=body, headers=ZIP, timeout=600).status_code == 200
    assert _state(engine)[1] == before[1] + ROWS
