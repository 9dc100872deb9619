"""The page's files from the real server: many clients at once on a fresh process, each file
answered with its own bytes (``http/static.py``: ``FrontendFiles`` holds each file as found)."""

from __future__ import annotations

import gzip
import random
import re
import socket
from concurrent.futures import ThreadPoolExecutor

from tests.server.conftest import StartServer

from actuator_selection.config import FRONTEND_DIR

CLIENTS = 8
ROUNDS = 3


def test_clients_loading_the_pages_at_once_each_get_each_file_as_on_disk(
    start_server: StartServer,
) -> None:
    server, _ = start_server()
    files = {
        p.relative_to(FRONTEND_DIR).as_posix(): p.read_bytes()
        for p in FRONTEND_DIR.rglob("*")
        if p.is_file()
    }
    assert len(files) > 20

    def load(seed: int) -> list[str]:
        """Every file, ``ROUNDS`` times in an order of the client's own; what differed."""
        order = [name for _ in range(ROUNDS) for name in files]
        random.Random(seed).shuffle(order)
        wrong = []
        # httpx decodes zstd and gzip with the codecs' own libraries
        with server.client() as client:
            for name in order:
                answer = client.get(f"/{name}", headers={"Accept-Encoding": "zstd, gzip"})
                if answer.status_code != 200 or answer.content != files[name]:
                    wrong.append(f"{name}: {answer.status_code}")
        return wrong

    with ThreadPoolExecutor(CLIENTS) as pool:
        wrong = [w for found in pool.map(load, range(CLIENTS)) for w in found]
    assert wrong == []


def test_a_head_of_a_held_file_sends_its_headers_and_no_body(start_server: StartServer) -> None:
    """HEAD then GET on one connection: the HEAD's answer has the GET's length and coding
    and no body (the next bytes are the GET's answer)."""
    server, _ = start_server()
    with server.client() as client:  # held by a first request
        assert client.get("/lib/api.js").status_code == 200
    with socket.create_connection(("127.0.0.1", server.port), timeout=30) as sock:
        sock.sendall(
            b"HEAD /lib/api.js HTTP/1.1\r\nHost: t\r\nAccept-Encoding: gzip\r\n\r\n"
            b"GET /lib/api.js HTTP/1.1\r\nHost: t\r\nAccept-Encoding: gzip\r\n"
            b"Connection: close\r\n\r\n"
        )
        received = b""
        while chunk := sock.recv(65536):
            received += chunk
    head, _, rest = received.partition(b"\r\n\r\n")
    assert head.startswith(b"HTTP/1.1 200")
    assert rest.startswith(b"HTTP/1.1 200")  # no body between the two answers
    got_head, _, body = rest.partition(b"\r\n\r\n")
    length = re.search(rb"(?im)^content-length: (\d+)", got_head)
    assert length is not None
    assert re.search(rb"(?im)^content-length: " + length.group(1) + rb"\r?$", head)
    assert b"content-encoding: gzip" in head.lower()
    assert gzip.decompress(body) == (FRONTEND_DIR / "lib" / "api.js").read_bytes()
