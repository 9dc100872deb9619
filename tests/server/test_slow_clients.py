"""Clients that send their request body slowly hold no place of admission control.

A body is received whole before the request is admitted (``http.admission``), within
``BODY_TIMEOUT_S``; a client that takes longer is answered 408 and its connection closed.
"""

from __future__ import annotations

import contextlib
import json
import select
import socket
import statistics
import threading
import time

from tests.server.conftest import WORKED_EXAMPLE, LiveServer, StartServer

SLOW_CLIENTS = 8
"""More than the server admits and queues together (2 + 2 below)."""
BODY_TIMEOUT_S = 5
RATIO = 50
"""A request beside the slow clients takes less than this many unloaded selections.
Generous: the machine running the suite is shared by other tests, and the fault it
guards against waits for a queue or connect timeout of seconds."""


def _slow_client(server: LiveServer, body: bytes) -> socket.socket:
    """A connection that has sent the headers of a selection and the body's first byte."""
    sock = socket.create_connection(("127.0.0.1", server.port), timeout=30)
    head = (
        "POST /api/v1/selections HTTP/1.1\r\n"
        "Host: 127.0.0.1\r\n"
        "Content-Type: application/json\r\n"
        f"Content-Length: {len(body)}\r\n\r\n"
    )
    sock.sendall(head.encode() + body[:1])
    return sock


def _dribble(sockets: list[socket.socket], body: bytes, stop: threading.Event) -> None:
    """One more byte of the body on each connection every 0.2 s, never the last one."""
    for i in range(1, len(body) - 1):
        if stop.wait(0.2):
            return
        for sock in sockets:
            with contextlib.suppress(OSError):  # answered and closed by the server
                sock.sendall(body[i : i + 1])


def _has_answer(sock: socket.socket) -> bool:
    """True when the server has sent something on ``sock`` (or closed it), without waiting."""
    readable, _, _ = select.select([sock], [], [], 0)
    return bool(readable)


def _answer(sock: socket.socket) -> tuple[str, dict[str, str], bytes]:
    """The status line, headers and body the server sent before closing the connection.

    The server closes the connection with the rest of the body unread, so the client's
    next bytes are answered with a reset: the answer is what came before it.
    """
    data = b""
    try:
        while chunk := sock.recv(65536):
            data += chunk
    except ConnectionResetError:
        pass
    head, _, content = data.partition(b"\r\n\r\n")
    status, *lines = head.decode("latin-1").split("\r\n")
    headers = {k.lower(): v.strip() for k, v in (line.split(":", 1) for line in lines)}
    return status, headers, content


def test_slow_bodies_leave_health_and_selections_answering_and_get_408(
    start_server: StartServer,
) -> None:
    server, _ = start_server(
        MAX_CONCURRENT_REQUESTS="2",
        MAX_QUEUED_REQUESTS="2",
        QUEUE_TIMEOUT_S="30",
        BODY_TIMEOUT_S=str(BODY_TIMEOUT_S),
    )
    body = json.dumps(WORKED_EXAMPLE).encode()
    unloaded = []
    with server.client() as client:
        for _ in range(3):
            started = time.monotonic()
            assert client.post("/api/v1/selections", json=WORKED_EXAMPLE).status_code == 201
            unloaded.append(time.monotonic() - started)
    reference = statistics.median(unloaded)

    sockets = [_slow_client(server, body) for _ in range(SLOW_CLIENTS)]
    stop = threading.Event()
    dribbler = threading.Thread(target=_dribble, args=(sockets, body, stop))
    dribbler.start()
    try:
        time.sleep(0.5)  # the slow requests have reached the application
        with server.client() as client:
            for method, path, json_body, expected in [
                ("GET", "/api/v1/health", None, 200),
                ("POST", "/api/v1/selections", WORKED_EXAMPLE, 201),
            ]:
                started = time.monotonic()
                response = client.request(method, path, json=json_body)
                took = time.monotonic() - started
                assert response.status_code == expected, response.text
                assert took < RATIO * reference, (path, took, reference)
        # ... while every slow client still waits for its answer
        assert not any(_has_answer(sock) for sock in sockets)
        answers = [_answer(sock) for sock in sockets]
    finally:
        stop.set()
        dribbler.join()
        for sock in sockets:
            sock.close()
    for status, headers, content in answers:
        assert status.split()[1] == "408", (status, content)
        assert headers["connection"] == "close"
        assert headers["content-type"] == "application/json"
        (entry,) = json.loads(content)["detail"]
        assert entry["loc"] == ["body"]
        assert entry["code"] == "request_timeout"
        assert entry["params"] == {"timeout_s": BODY_TIMEOUT_S}
