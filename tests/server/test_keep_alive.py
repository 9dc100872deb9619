"""An idle keep-alive connection stays open longer than a proxy keeps its own.

nginx keeps idle connections to the app for 60 s (``keepalive_timeout``) and sends the
next request on one of them; a server that closes an idle connection sooner can close it
just as that request arrives, and the request fails without an answer (a 502 behind
nginx, ``RemoteProtocolError`` for a direct client). uvicorn's default closed after 5 s;
the service keeps idle connections ``KEEP_ALIVE_S`` (75 s).
"""

from __future__ import annotations

import socket
import time

from tests.server.conftest import LiveServer, StartServer

IDLE_S = 6.0
"""Longer than uvicorn's default keep-alive (5 s), far shorter than the service's."""


def _get(sock: socket.socket, path: str) -> tuple[int, bytes]:
    """One GET on ``sock`` (kept alive): the status and the body; (0, b"") if the server
    had closed the connection."""
    request = f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: keep-alive\r\n\r\n"
    try:
        sock.sendall(request.encode("ascii"))
    except OSError:  # reset by a server that closed it
        return 0, b""
    received = b""
    while b"\r\n\r\n" not in received:
        chunk = sock.recv(65536)
        if not chunk:
            return 0, b""
        received += chunk
    head, _, body = received.partition(b"\r\n\r\n")
    lines = head.decode("latin-1").split("\r\n")
    headers = dict(line.lower().split(": ", 1) for line in lines[1:])
    length = int(headers["content-length"])
    while len(body) < length:
        chunk = sock.recv(65536)
        assert chunk, "the server closed the connection inside an answer"
        body += chunk
    return int(lines[0].split()[1]), body


def _connection(server: LiveServer) -> socket.socket:
    return socket.create_connection(("127.0.0.1", server.port), timeout=30)


def test_an_idle_keep_alive_connection_takes_the_next_request(
    start_server: StartServer,
) -> None:
    server, _ = start_server()
    with _connection(server) as sock:
        assert _get(sock, "/api/v1/health")[0] == 200
        time.sleep(IDLE_S)
        status, _body = _get(sock, "/api/v1/health")
    assert status == 200, "the server closed an idle keep-alive connection after 6 s"


def test_the_keep_alive_is_a_setting(start_server: StartServer) -> None:
    """``KEEP_ALIVE_S`` shorter than the idle time: the server closes the connection (so the
    test above measures the setting, not a client's retry)."""
    server, _ = start_server(KEEP_ALIVE_S="2")
    with _connection(server) as sock:
        assert _get(sock, "/api/v1/health")[0] == 200
        time.sleep(IDLE_S)
        status, _body = _get(sock, "/api/v1/health")
    assert status == 0
