"""The deployment's topology with real processes (issue 32 item 5): nginx in front of two
app replicas on one PostgreSQL, with a batch job worker beside each.

CI has no container engine, so nginx (Debian's ``nginx-light``) runs as a process of the
test with ``deploy/nginx-replicas.conf.template`` filled in: a free port, and its pid,
logs and buffers in a temporary folder, so it needs no root.
"""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import threading
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import httpx
import pytest
from sqlalchemy import text
from tests.server.conftest import (
    CHUNK_CASES,
    WORKED_EXAMPLE,
    Deploy,
    Deployment,
    LiveServer,
    free_port,
)
from tests.server.jobs_harness import (
    assert_each_case_once,
    cases,
    finished,
    result_cases,
    submit,
    wait_for,
)

from actuator_selection.config import REPO_ROOT

TEMPLATE = REPO_ROOT / "deploy" / "nginx-replicas.conf.template"
COPIED = "FHA-25C-50-L"
NEW_MODEL = "FHA-25C-50-L-REPLICA"
CLIENTS = 4
"""Threads writing through nginx at once while a replica is killed."""
WRITES_BEFORE_KILL = 40
WRITES_AFTER_KILL = 80
SETTLED = 40
"""The last writes, all of which must be acknowledged: nginx has left the dead replica out."""


def nginx_path() -> str | None:
    """Debian's nginx (``nginx-light``), or None."""
    found = shutil.which("nginx") or "/usr/sbin/nginx"
    return found if Path(found).is_file() else None


def _as_whoever_runs() -> list[str]:
    """Started by root (CI), nginx's worker would switch to ``nobody``, who may not write
    the test's temporary folder (request bodies are buffered there): it stays root."""
    return ["-g", "user root;"] if os.geteuid() == 0 else []


def _filled(line: str, values: dict[str, str]) -> str:
    """A line of the template with its placeholders filled (comments stay as they are)."""
    if line.lstrip().startswith("#"):
        return line
    for name, value in values.items():
        line = line.replace(name, value)
    assert "@" not in line, f"a placeholder left unfilled: {line}"
    return line


@dataclass
class Nginx:
    """nginx in front of ``servers``, from the template, in a folder of its own."""

    binary: str
    run_dir: Path
    servers: list[LiveServer]
    port: int = 0
    process: subprocess.Popen[bytes] | None = None

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.port}"

    def start(self) -> None:
        self.port = free_port()
        self.run_dir.mkdir(parents=True, exist_ok=True)
        upstreams = "\n".join(
            f"        server 127.0.0.1:{s.port} max_fails=1 fail_timeout=10s;" for s in self.servers
        )
        values = {
            "@RUN_DIR@": str(self.run_dir),
            "@LISTEN@": f"127.0.0.1:{self.port}",
            "@SERVERS@": upstreams,
        }
        config = "\n".join(_filled(line, values) for line in TEMPLATE.read_text().splitlines())
        path = self.run_dir / "nginx.conf"
        path.write_text(config)
        with (self.run_dir / "stdout.log").open("ab") as log:
            self.process = subprocess.Popen(
                [self.binary, "-p", str(self.run_dir), "-c", str(path), *_as_whoever_runs()],
                stdout=log,
                stderr=subprocess.STDOUT,
            )

        def up() -> bool:
            assert self.process is not None
            if self.process.poll() is not None:
                pytest.fail(f"nginx exited:\n{self.log()}", pytrace=False)
            try:
                return httpx.get(f"{self.url}/api/v1/health", timeout=2).status_code == 200
            except httpx.TransportError:
                return False

        wait_for(up, "nginx to answer", 30)

    def stop(self) -> None:
        if self.process is not None and self.process.poll() is None:
            self.process.send_signal(signal.SIGQUIT)  # graceful shutdown
            try:
                self.process.wait(10)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(10)

    def errors(self) -> str:
        """nginx's error log so far."""
        return (self.run_dir / "error.log").read_text(errors="replace")

    def log(self) -> str:
        parts = [
            (self.run_dir / name).read_text(errors="replace")[-3000:]
            for name in ("stdout.log", "error.log")
            if (self.run_dir / name).exists()
        ]
        return "\n".join(parts)


@dataclass
class Topology:
    deployment: Deployment
    replicas: list[LiveServer]
    nginx: Nginx

    def client(self, role: str | None = None) -> httpx.Client:
        keys = self.deployment.keys
        headers = {"Authorization": f"Bearer {keys[role]}"} if role else {}
        return httpx.Client(base_url=self.nginx.url, headers=headers, timeout=60)


@pytest.fixture
def topology(deploy: Deploy, tmp_path: Path) -> Iterator[Topology]:
    """Two replicas on one fresh PostgreSQL database behind nginx."""
    binary = nginx_path()
    if binary is None:
        message = "the replica tests need nginx (Debian: apt-get install nginx-light)"
        if os.environ.get("CI") == "true":
            pytest.fail(f"{message}; CI=true, so this is a failure", pytrace=False)
        pytest.skip(message)
    deployment = deploy("postgresql")
    replicas = [deployment.server(), deployment.server()]
    nginx = Nginx(binary, tmp_path / "nginx", replicas)
    try:
        nginx.start()
        yield Topology(deployment, replicas, nginx)
    finally:
        nginx.stop()


def _served(replica: LiveServer, request_line: str) -> int:
    """How many requests ``request_line`` (``POST /api/v1/selections``) the replica's
    access log shows."""
    return replica.log_path.read_text(errors="replace").count(f'"{request_line} HTTP/1.1"')


def test_load_through_nginx_is_shared_by_both_replicas(topology: Topology) -> None:
    body = {**WORKED_EXAMPLE, "models": [COPIED]}
    with topology.client() as client:
        answers = [client.post("/api/v1/selections", json=body) for _ in range(60)]
        reads = [client.get(f"/api/v1/selections/{a.json()['id']}") for a in answers]
    assert [a.status_code for a in answers] == [201] * 60
    assert [r.status_code for r in reads] == [200] * 60
    assert all(_served(r, "POST /api/v1/selections") > 0 for r in topology.replicas)


def test_a_catalogue_change_through_one_replica_is_seen_by_the_other_at_once(
    topology: Topology,
) -> None:
    first, second = topology.replicas
    with second.client() as client:  # the second holds the catalogue before the change
        selected = client.post("/api/v1/selections", json={**WORKED_EXAMPLE, "models": [COPIED]})
        assert selected.status_code == 201
    with first.client("admin") as admin:
        exported = admin.get("/api/v1/catalogue/export", params={"format": "json"}).json()
        (row,) = [r for r in exported["actuators"] if r["model"] == COPIED]
        created = admin.post("/api/v1/actuators", json={**row, "model": NEW_MODEL})
        assert created.status_code == 201, created.text
    with second.client() as client:  # the very next request of the other replica
        answer = client.post("/api/v1/selections", json={**WORKED_EXAMPLE, "models": [NEW_MODEL]})
    assert answer.status_code == 201, answer.text
    assert [c["model"] for c in answer.json()["candidates"]] == [NEW_MODEL]
    with topology.client() as client:  # and whichever replica nginx picks
        found = [client.get(f"/api/v1/actuators/{NEW_MODEL}").status_code for _ in range(10)]
    assert found == [200] * 10


CUT_OFF = "201 cut off"
"""A write whose answer nginx had begun passing on when its replica died (see
:func:`_write_selection`)."""


def _write_selection(client: httpx.Client, body: dict[str, Any]) -> tuple[int | str, str | None]:
    """POST ``body`` to ``/selections`` through nginx: the answer's status, or
    :data:`CUT_OFF`, and the id of the selection it names, if any.

    A replica SIGKILLed after writing an answer's head (uvicorn writes the status line and
    headers, then the body) leaves nginx with a 201 it has already passed on and no body to
    follow: nginx logs "upstream prematurely closed connection while reading upstream" and
    can only close the client's connection, which httpx reports as a RemoteProtocolError
    while reading the body. HTTP/1.1 cannot take a status back, so no setting of nginx
    makes that a 502; seen under load (a busy replica is often descheduled between the two
    writes). The write was committed before its head was sent, so the ``Location`` it
    carries names a stored selection, as a complete 201's id does. A connection broken
    before the head arrived is not this: its error propagates.
    """
    with client.stream("POST", "/api/v1/selections", json=body) as answer:
        try:
            answer.read()
        except httpx.RemoteProtocolError:
            location = answer.headers.get("location", "")
            return f"{answer.status_code} cut off", location.rsplit("/", 1)[-1] or None
    return answer.status_code, answer.json()["id"] if answer.status_code == 201 else None


def test_a_replica_killed_under_load_costs_no_acknowledged_write(topology: Topology) -> None:
    """Writers keep storing selections through nginx while one replica is SIGKILLed: every
    201 names a selection that is in the database, a write that failed was answered as
    failed (502, never a 2xx) or cut off after a 201's head (:data:`CUT_OFF`, and then
    stored too), and nginx then sends everything to the replica left."""
    body = {**WORKED_EXAMPLE, "models": [COPIED]}
    acknowledged: list[str] = []
    cut_off: list[str | None] = []
    statuses: list[int | str] = []
    lock = threading.Lock()
    killed = threading.Event()
    done = threading.Event()

    def write() -> None:
        with topology.client() as client:
            while not done.is_set():
                try:
                    status, stored_id = _write_selection(client, body)
                except httpx.TransportError as error:  # recorded for the assertion below
                    status, stored_id = f"{type(error).__name__}: {error}", None
                with lock:
                    statuses.append(status)
                    if status == 201:
                        acknowledged.append(str(stored_id))
                    elif status == CUT_OFF:
                        cut_off.append(stored_id)
                    after = sum(1 for s in statuses[kill_at:] if s == 201) if killed.is_set() else 0
                    if after >= WRITES_AFTER_KILL:
                        done.set()

    kill_at = 0
    threads = [threading.Thread(target=write) for _ in range(CLIENTS)]
    for thread in threads:
        thread.start()
    try:
        wait_for(lambda: len(acknowledged) >= WRITES_BEFORE_KILL, "writes before the kill")
        with lock:
            kill_at = len(statuses)
            topology.replicas[0].kill()
            killed.set()
        assert done.wait(300), "the writes after the kill did not finish"
    finally:
        done.set()
        for thread in threads:
            thread.join(60)
    nginx_errors = topology.nginx.errors()
    seen = f"{statuses}\nnginx's error log:\n{nginx_errors[-3000:]}"
    assert set(statuses) <= {201, 502, CUT_OFF}, seen
    assert len(cut_off) <= nginx_errors.count(" while reading upstream,"), seen
    assert statuses[-SETTLED:] == [201] * SETTLED, seen
    with topology.deployment.engine.connect() as conn:
        stored = set(
            conn.scalars(
                text("SELECT id FROM selections WHERE id = ANY(:ids)"),
                {"ids": [*acknowledged, *cut_off]},
            )
        )
    assert stored == {*acknowledged, *cut_off}, seen
    assert len(acknowledged) >= WRITES_BEFORE_KILL + WRITES_AFTER_KILL


def test_a_batch_job_through_nginx_is_computed_by_workers_beside_both_replicas(
    topology: Topology,
) -> None:
    deployment = topology.deployment
    workers = [deployment.worker(), deployment.worker()]  # one beside each replica
    n = 20 * CHUNK_CASES
    with topology.client() as client:
        location = submit(client, cases(n), top=5, include_checks="true")
        job = finished(client, location)
        assert job["state"] == "done", job
        assert_each_case_once(result_cases(client, location), n)
    with deployment.engine.connect() as conn:
        writers = set(conn.scalars(text("SELECT DISTINCT worker FROM batch_job_results")))
    assert writers == {f"{socket.gethostname()}:{w.pid}" for w in workers}
