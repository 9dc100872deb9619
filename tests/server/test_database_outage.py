"""The database goes away under the real server and comes back: 503 meanwhile, then service.

PostgreSQL is shared with others and is never stopped: the server reaches it through a
TCP forwarder (``tcp_proxy.py``), a process of the test's own that is killed (every
connection reset, new ones refused) and started again. SQLite's database folder is
moved away (the file cannot be opened) and back.
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from sqlalchemy.engine import make_url
from tests.server.conftest import WORKED_EXAMPLE, LiveServer, free_port, seeded_database

PROXY = Path(__file__).with_name("tcp_proxy.py")
RATIO = 50
"""An answer while the database is down takes less than this many unloaded selections.
Generous: the machine running the suite is shared by other tests, and the fault it
guards against waits for a queue or connect timeout of seconds."""

REQUESTS: list[tuple[str, str, str | None, dict[str, Any] | None]] = [
    ("GET", "/api/v1/health", None, None),
    ("GET", "/api/v1/health/ready", None, None),
    ("POST", "/api/v1/selections", None, WORKED_EXAMPLE),
    ("GET", "/api/v1/actuators", None, None),
    ("GET", "/api/v1/catalogue/version", None, None),
    ("GET", "/api/v1/quotes", "sales", None),
]
"""Method, path, the role whose key is sent, and the body of requests that need the database."""


@dataclass
class Forwarder:
    """``tcp_proxy.py`` on ``port`` to ``target``, killed and started again at will."""

    port: int
    target: str
    process: subprocess.Popen[bytes] | None = None

    def start(self) -> None:
        self.process = subprocess.Popen(
            [sys.executable, str(PROXY), str(self.port), self.target], stdout=subprocess.PIPE
        )
        assert self.process.stdout is not None
        with self.process.stdout:
            assert self.process.stdout.readline().strip() == b"ready"

    def kill(self) -> None:
        if self.process is not None:
            self.process.kill()
            self.process.wait(10)
            self.process = None


@dataclass
class Outage:
    """A running server, and how to take its database away and bring it back."""

    server: LiveServer
    take_away: Callable[[], None]
    bring_back: Callable[[], None]


@pytest.fixture
def outage(backend: str, new_database: Callable[[str], str], tmp_path: Path) -> Iterator[Outage]:
    url = new_database(backend)
    keys, engine = seeded_database(url)
    engine.dispose()
    cleanup: Callable[[], None]
    if backend == "sqlite":
        folder = Path(str(make_url(url).database)).parent
        away = folder.with_name(f"{folder.name}-away")
        served = url

        def take_away() -> None:
            folder.rename(away)

        def bring_back() -> None:
            away.rename(folder)

        def cleanup() -> None:
            if away.exists():
                bring_back()
    else:
        parsed = make_url(url)
        forwarder = Forwarder(free_port(), f"{parsed.host}:{parsed.port or 5432}")
        forwarder.start()
        served = parsed.set(host="127.0.0.1", port=forwarder.port).render_as_string(
            hide_password=False
        )
        take_away, bring_back, cleanup = forwarder.kill, forwarder.start, forwarder.kill
    server = LiveServer(database_url=served, log_path=tmp_path / "server.log", keys=keys)
    server.start()
    try:
        yield Outage(server, take_away, bring_back)
    finally:
        server.stop()
        cleanup()


def _lines(server: LiveServer, text: str) -> int:
    return sum(text in line for line in server.log_path.read_text().splitlines())


def test_a_database_outage_is_answered_503_at_once_and_ends_without_a_restart(
    outage: Outage,
) -> None:
    server = outage.server
    with server.client() as client:
        unloaded = []
        for _ in range(3):
            started = time.monotonic()
            assert client.post("/api/v1/selections", json=WORKED_EXAMPLE).status_code == 201
            unloaded.append(time.monotonic() - started)
        reference = statistics.median(unloaded)
        ready = client.get("/api/v1/health/ready")
        assert (ready.status_code, ready.json()) == (200, {"status": "ready"})

        outage.take_away()
        for _ in range(3):
            for method, path, role, body in REQUESTS:
                headers = {"Authorization": f"Bearer {server.keys[role]}"} if role else {}
                started = time.monotonic()
                response = client.request(method, path, json=body, headers=headers)
                took = time.monotonic() - started
                assert response.status_code == 503, (path, response.text)
                assert int(response.headers["Retry-After"]) >= 1
                (entry,) = response.json()["detail"]
                assert entry["code"] == "database_unreachable", entry
                assert entry["params"]["dependency"] == "database"
                assert took < RATIO * reference, (path, took, reference)
        german = client.get("/api/v1/health", headers={"Accept-Language": "de"})
        (entry,) = german.json()["detail"]
        assert entry["msg"].startswith("die Datenbank ist nicht erreichbar")

        outage.bring_back()
        assert client.get("/api/v1/health").json() == {"status": "ok"}
        assert client.get("/api/v1/health/ready").status_code == 200
        assert client.post("/api/v1/selections", json=WORKED_EXAMPLE).status_code == 201
        with server.client("sales") as sales:
            assert sales.get("/api/v1/quotes").status_code == 200

    assert "Traceback" not in server.log_path.read_text()
    assert _lines(server, "database unreachable") == 1, server.log()
    assert _lines(server, "database reachable again") == 1, server.log()


def test_a_sqlite_file_moved_away_is_unreachable_and_not_made_again_empty(
    new_database: Callable[[str], str], tmp_path: Path
) -> None:
    """Without the folder gone, opening the path would create a new, empty database."""
    url = new_database("sqlite")
    keys, engine = seeded_database(url)
    engine.dispose()
    path = Path(str(make_url(url).database))
    away = path.with_name(f"{path.name}-away")
    server = LiveServer(database_url=url, log_path=tmp_path / "server.log", keys=keys)
    server.start()
    try:
        with server.client() as client:
            assert client.post("/api/v1/selections", json=WORKED_EXAMPLE).status_code == 201
            path.rename(away)
            for route in ("/api/v1/health", "/api/v1/actuators"):
                response = client.get(route)
                assert response.status_code == 503, response.text
                assert response.json()["detail"][0]["code"] == "database_unreachable"
            assert not path.exists()
            away.rename(path)
            assert client.get("/api/v1/health").status_code == 200
            assert client.post("/api/v1/selections", json=WORKED_EXAMPLE).status_code == 201
    finally:
        server.stop()
        if away.exists():
            away.rename(path)
    assert "Traceback" not in server.log_path.read_text()
