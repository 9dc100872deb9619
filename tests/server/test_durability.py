"""A 2xx answer means committed: read back at once, and still there after SIGKILL."""

from __future__ import annotations

import re

from sqlalchemy import text
from tests.server.conftest import StartServer, quote_body, stored_selection

ROUNDS = 300
KILLS = 6
QUOTE_NUMBER = re.compile(r"Q-(\d{4})-(\d{5})")


def test_a_selection_is_readable_as_soon_as_it_is_answered(start_server: StartServer) -> None:
    server, _ = start_server()
    missing = []
    with server.client() as client:
        for i in range(ROUNDS):
            selection_id = stored_selection(client)
            got = client.get(f"/api/v1/selections/{selection_id}")
            if got.status_code != 200:
                missing.append((i, got.status_code))
    assert missing == []


def test_a_quote_is_readable_as_soon_as_it_is_answered(start_server: StartServer) -> None:
    server, _ = start_server()
    missing = []
    with server.client("sales") as client:
        selection_id = stored_selection(client)
        for i in range(ROUNDS):
            created = client.post("/api/v1/quotes", json=quote_body(selection_id))
            assert created.status_code == 201, created.text
            got = client.get(created.headers["Location"])
            if got.status_code != 200:
                missing.append((i, got.status_code))
    assert missing == []


def test_a_quote_answered_201_survives_sigkill_and_its_number_is_never_reissued(
    start_server: StartServer,
) -> None:
    server, engine = start_server()
    answered: list[str] = []
    with server.client("sales") as client:
        selection_id = stored_selection(client)
    for _ in range(KILLS):
        with server.client("sales") as client:
            created = client.post("/api/v1/quotes", json=quote_body(selection_id))
        assert created.status_code == 201, created.text
        server.kill()  # at once after the answer: nothing may be left to do
        answered.append(created.json()["number"])
        server.start()
    with server.client("sales") as client:
        for number in answered:
            assert client.get(f"/api/v1/quotes/{number}").status_code == 200, number
    with engine.connect() as conn:
        stored = list(conn.execute(text("SELECT number FROM quotes ORDER BY number")).scalars())
    assert stored == answered  # each there once, in the order given, none issued twice
    sequence = [int(QUOTE_NUMBER.fullmatch(n).group(2)) for n in answered]  # type: ignore[union-attr]
    assert sequence == list(range(1, KILLS + 1))
