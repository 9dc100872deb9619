"""Wrong API keys against the real server: a burst is answered 401, the rest at once 429
with Retry-After, and nobody else waits (issue 26 item 6: "no back-off on wrong keys")."""

from __future__ import annotations

import statistics
import time

import httpx
from tests.server.conftest import StartServer

CAPACITY = 5
WINDOW_S = 3.0
"""5 wrong keys in a burst, then one more every 0.6 s."""
WRONG = {"Authorization": "Bearer asel_0123456789ab_" + "A" * 43}
ATTEMPTS = 60


def _timed(client: httpx.Client, headers: dict[str, str]) -> tuple[int, float]:
    start = time.perf_counter()
    status = client.get("/api/v1/auth/me", headers=headers).status_code
    return status, time.perf_counter() - start


def test_a_key_guesser_is_slowed_to_the_allowance(start_server: StartServer) -> None:
    server, _ = start_server(MAX_KEY_FAILURES=str(CAPACITY), KEY_FAILURE_WINDOW_S=str(WINDOW_S))
    right = {"Authorization": f"Bearer {server.keys['sales']}"}
    with server.client() as client:
        normal = [_timed(client, right) for _ in range(7)]
        assert {status for status, _ in normal} == {200}

        start = time.monotonic()
        answers = [_timed(client, WRONG) for _ in range(ATTEMPTS)]
        elapsed = time.monotonic() - start
        statuses = [status for status, _ in answers]
        assert set(statuses) == {401, 429}
        assert statuses[:CAPACITY] == [401] * CAPACITY
        # a guesser gets the burst and the refill over the time it spent, no more
        assert statuses.count(401) <= CAPACITY + elapsed * CAPACITY / WINDOW_S + 1

        blocked = client.get("/api/v1/auth/me", headers=right)  # the right key is refused too
        assert blocked.status_code == 429
        retry_after = int(blocked.headers["Retry-After"])
        assert 1 <= retry_after <= WINDOW_S
        (entry,) = blocked.json()["detail"]
        assert entry["code"] == "too_many_failed_keys"
        # answered at once, not by sleeping: no slower than a served request, with headroom
        refused = [seconds for status, seconds in answers if status == 429]
        served = statistics.median(seconds for _, seconds in normal)
        assert statistics.median(refused) < 5 * served

        # other clients are served meanwhile (nothing sleeps in the event loop)
        assert client.get("/api/v1/actuators").status_code == 200

        time.sleep(retry_after)
        assert client.get("/api/v1/auth/me", headers=right).status_code == 200
