"""``serve --workers 2`` when its supervisor is killed: the workers end with it and free
the port, so the service starts again at once (issue 26 item 6)."""

from __future__ import annotations

import os
import signal
import socket
import time
from pathlib import Path

import httpx
from tests.server.conftest import StartServer

WORKERS = 2
DEADLINE_S = 20.0
"""Generous bound for the workers to go (they look every 0.25 s; the port is free as soon
as they have closed the socket)."""


def _children(pid: int) -> set[int]:
    """The live processes whose parent is ``pid`` (read from /proc)."""
    found: set[int] = set()
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit() and _parent_and_state(int(entry.name))[0] == pid:
            found.add(int(entry.name))
    return found


def _is_worker(pid: int) -> bool:
    """A process ``multiprocessing`` spawned to run a worker (not its resource tracker)."""
    try:
        return b"spawn_main" in Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return False


def _parent_and_state(pid: int) -> tuple[int, str]:
    """``(ppid, state)`` of ``pid``; ``(0, "gone")`` once it has ended (zombies too)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return 0, "gone"
    state, ppid = stat.rsplit(")", 1)[1].split()[:2]
    return (0, "gone") if state in ("Z", "X") else (int(ppid), state)


def _port_is_free(port: int) -> bool:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as probe:
        probe.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as uvicorn binds
        try:
            probe.bind(("127.0.0.1", port))
        except OSError:
            return False
        return True


def test_killing_the_supervisor_ends_its_workers(start_server: StartServer) -> None:
    server, _ = start_server(WORKERS=str(WORKERS))
    assert server.process is not None
    supervisor, port = server.process.pid, server.port
    deadline = time.monotonic() + DEADLINE_S
    workers: set[int] = set()
    while len(workers) < WORKERS and time.monotonic() < deadline:
        time.sleep(0.1)
        workers = {pid for pid in _children(supervisor) if _is_worker(pid)}
    assert len(workers) == WORKERS, workers
    workers = _children(supervisor)  # and multiprocessing's resource tracker: all must go
    try:
        server.kill()  # SIGKILL: the supervisor cannot pass anything on
        while time.monotonic() < deadline and not (
            all(_parent_and_state(pid)[1] == "gone" for pid in workers) and _port_is_free(port)
        ):
            time.sleep(0.1)
        orphans = {pid for pid in workers if _parent_and_state(pid)[1] != "gone"}
        assert not orphans, f"workers still running: {orphans}"
        assert _port_is_free(port)
        server.start(port=port)  # no "Address already in use"
        assert httpx.get(f"{server.url}/api/v1/health", timeout=5).status_code == 200
    finally:
        for pid in workers:  # a failing run leaves no orphans behind
            if _parent_and_state(pid)[1] != "gone":
                os.kill(pid, signal.SIGKILL)


def test_a_single_process_server_is_not_a_watched_worker(start_server: StartServer) -> None:
    """Without --workers there is no supervisor: the server is the process itself, and it
    stays up (its parent, here the test, is not watched)."""
    server, _ = start_server(WORKERS="1")
    assert server.process is not None
    assert _children(server.process.pid) == set()
    time.sleep(1)
    assert httpx.get(f"{server.url}/api/v1/health", timeout=5).status_code == 200
