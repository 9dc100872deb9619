"""The page's files from the real server: many clients at once on a fresh process, each file
answered with its own bytes (``http/static.py``: ``FrontendFiles`` holds each file as found)."""

from __future__ import annotations

import random
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
