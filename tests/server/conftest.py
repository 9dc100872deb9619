"""The real server: ``python -m actuator_selection serve`` in a subprocess on a loopback port.

The in-process test client runs a request's teardown before it returns, so it cannot
show what happens after an answer is sent: transactions still open, commits that
fail, connections reset, a process killed. These tests talk HTTP to uvicorn as a
client would, on SQLite and on PostgreSQL (the ``backend`` fixture of
``tests/conftest.py``), each server on a database of its own.
"""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from datetime import UTC, date, datetime, timedelta
from pathlib import Path
from typing import Any

import httpx
import pytest
from sqlalchemy import Engine
from tests import worked_example
from tests.api._sales_fixtures import EXAMPLE_PRICE_LIST, create_keys, load_example_prices
from tests.server.jobs_harness import Worker, registered_workers, wait_for

from actuator_selection.config import REPO_ROOT, SEED_DIR
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.seed import load_seed

START_TIMEOUT_S = 90.0
"""A deadline, not an expectation: with `--workers 2` on a loaded two-core machine each
worker imports the app in turn (18 s seen at a load average of 12)."""
WORKED_EXAMPLE: dict[str, Any] = {**worked_example.request(), "high_dynamics": True}
"""The chapter's worked example (Table 516.1) for the whole catalogue."""


def free_port() -> int:
    """A loopback port nobody listens on now (the server binds it a moment later)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


@dataclass
class LiveServer:
    """One server process on its own database; ``kill`` and ``start`` it again at will."""

    database_url: str
    log_path: Path
    keys: dict[str, str]
    env: dict[str, str] = field(default_factory=dict)
    app: str | None = None
    """``module:attribute`` of another ASGI app to serve with uvicorn (default: the service's
    own ``serve`` command)."""
    port: int = 0
    process: subprocess.Popen[bytes] | None = None

    @property
    def url(self) -> str:
        """``http://127.0.0.1:<port>``."""
        return f"http://127.0.0.1:{self.port}"

    def start(self, port: int | None = None) -> None:
        """Start the server (on ``port``, default a free one) and wait until
        ``/api/v1/health`` answers."""
        assert self.process is None, "already running"
        self.port = port or free_port()
        env = {
            **os.environ,
            "DATABASE_URL": self.database_url,
            "HOST": "127.0.0.1",
            "PORT": str(self.port),
            **self.env,
        }
        command = (
            [sys.executable, "-m", "actuator_selection", "serve"]
            if self.app is None
            else [sys.executable, "-m", "uvicorn", self.app, "--port", str(self.port)]
        )
        with self.log_path.open("ab") as log:
            self.process = subprocess.Popen(
                command,
                cwd=REPO_ROOT,
                env=env,
                stdout=log,
                stderr=subprocess.STDOUT,
            )
        deadline = time.monotonic() + START_TIMEOUT_S
        while time.monotonic() < deadline:
            if self.process.poll() is not None:
                pytest.fail(f"the server exited at start:\n{self.log()}", pytrace=False)
            try:
                if httpx.get(f"{self.url}/api/v1/health", timeout=1).status_code == 200:
                    return
            except httpx.TransportError:
                pass
            time.sleep(0.05)
        self.stop()
        pytest.fail(f"the server did not start in {START_TIMEOUT_S:g} s:\n{self.log()}")

    def kill(self) -> None:
        """SIGKILL: no shutdown, no teardown, nothing flushed that was not already."""
        assert self.process is not None
        self.process.send_signal(signal.SIGKILL)
        self.process.wait(10)
        self.process = None

    def stop(self) -> None:
        """An orderly shutdown (SIGTERM), or SIGKILL after 10 s."""
        if self.process is None:
            return
        self.process.terminate()
        try:
            self.process.wait(10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait(10)
        self.process = None

    def log(self) -> str:
        """The server's output so far (for failure messages)."""
        return self.log_path.read_text(errors="replace")[-5000:]

    def client(self, role: str | None = None, **kwargs: Any) -> httpx.Client:
        """A keep-alive HTTP client, with ``role``'s API key when given."""
        headers = {"Authorization": f"Bearer {self.keys[role]}"} if role else {}
        return httpx.Client(base_url=self.url, headers=headers, timeout=60, **kwargs)


def seeded_database(url: str) -> tuple[dict[str, str], Engine]:
    """Migrate and seed ``url``, add API keys and the example prices; the keys and an engine."""
    upgrade(url=url)
    engine = make_engine(url)
    with make_session_factory(engine).begin() as session:
        load_seed(session, SEED_DIR)
        keys, _ = create_keys(session)
        load_example_prices(session)
    return keys, engine


StartServer = Callable[..., tuple[LiveServer, Engine]]
"""``start_server(**env)``: a running server on a fresh seeded database, and an engine on it."""


@pytest.fixture
def start_server(
    backend: str, new_database: Callable[[str], str], tmp_path: Path
) -> Iterator[StartServer]:
    """Factory: ``start_server(**env)`` serves a fresh seeded database on ``backend``.

    Returns the running server and an engine on its database, for looking behind
    the API. Every server is stopped at the end of the test.
    """
    servers: list[LiveServer] = []
    engines: list[Engine] = []

    def start(**env: str) -> tuple[LiveServer, Engine]:
        url = new_database(backend)
        keys, engine = seeded_database(url)
        engines.append(engine)
        server = LiveServer(
            database_url=url,
            log_path=tmp_path / f"server-{len(servers)}.log",
            keys=keys,
            env=env,
        )
        servers.append(server)
        server.start()
        return server, engine

    yield start
    for server in servers:
        server.stop()
    for engine in engines:
        engine.dispose()


def quote_body(selection_id: str, **changes: Any) -> dict[str, Any]:
    """A valid quote of FHA-25C-50-L from a stored worked-example selection."""
    valid_until: date = datetime.now(UTC).date() + timedelta(days=30)
    body: dict[str, Any] = {
        "selection_id": selection_id,
        "customer": {"name": "Muster GmbH", "address": "Hauptstr. 1\n12345 Musterstadt"},
        "actuator": {"model": "FHA-25C-50-L", "quantity": 1},
        "price_list": EXAMPLE_PRICE_LIST,
        "valid_until": valid_until.isoformat(),
    }
    body.update(changes)
    return body


def stored_selection(client: httpx.Client, **changes: Any) -> str:
    """Store a worked-example selection restricted to FHA-25C-50-L; its id."""
    body = {**WORKED_EXAMPLE, "models": ["FHA-25C-50-L"], **changes}
    response = client.post("/api/v1/selections", json=body)
    assert response.status_code == 201, response.text
    selection_id: str = response.json()["id"]
    return selection_id


CHUNK_CASES = 100
"""``JOB_CHUNK_CASES`` of the servers a :class:`Deployment` starts."""


class Deployment:
    """Servers and workers on one fresh seeded database; all stopped at the end."""

    def __init__(self, url: str, tmp_path: Path) -> None:
        self.url = url
        self.tmp_path = tmp_path
        self.keys, self.engine = seeded_database(url)
        self.servers: list[LiveServer] = []
        self.workers: list[Worker] = []

    def server(self, **env: str) -> LiveServer:
        server = LiveServer(
            database_url=self.url,
            log_path=self.tmp_path / f"server-{len(self.servers)}.log",
            keys=self.keys,
            env={"JOB_CHUNK_CASES": str(CHUNK_CASES), **env},
        )
        self.servers.append(server)
        server.start()
        return server

    def worker(self) -> Worker:
        """A started worker, once procrastinate has registered it."""
        before = len(registered_workers(self.engine))
        worker = Worker(self.url, self.tmp_path / f"worker-{len(self.workers)}.log")
        self.workers.append(worker)
        worker.start()
        wait_for(lambda: len(registered_workers(self.engine)) > before, "the worker to register")
        return worker

    def close(self) -> None:
        for worker in self.workers:
            worker.stop()
        for server in self.servers:
            server.stop()
        self.engine.dispose()


Deploy = Callable[[str], Deployment]


@pytest.fixture
def deploy(new_database: Callable[[str], str], tmp_path: Path) -> Iterator[Deploy]:
    """``deploy(backend)``: a :class:`Deployment` on a fresh database of ``backend``."""
    made: list[Deployment] = []

    def make(backend: str) -> Deployment:
        made.append(Deployment(new_database(backend), tmp_path))
        return made[-1]

    yield make
    for deployment in made:
        deployment.close()
