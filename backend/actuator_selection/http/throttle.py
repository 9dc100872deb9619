"""Back-off for wrong API keys: a token bucket per client address, in the process.

A client may send :attr:`KeyFailureThrottle.capacity` wrong keys (unknown, revoked or
malformed) in a burst; the bucket then refills at ``capacity``
per ``window_s``. While it is empty, every request from that address that presents a
key is answered 429 with ``Retry-After`` at once, before the key is looked up
(so a correct guess cannot be told from a wrong one while blocked); requests without a
key are not affected. Nothing sleeps: the answer is immediate and holds no worker.

The buckets live in each server process (``--workers 2``: each has its own, so an
address gets up to ``capacity`` × workers wrong keys per window in all); they are not
shared between replicas. The client address is the connection's, or the proxy's
``X-Forwarded-For`` where uvicorn trusts the proxy (``FORWARDED_ALLOW_IPS``).
At most :data:`MAX_ADDRESSES` addresses are tracked; the longest untouched go first.
"""

from __future__ import annotations

import math
import time
from collections import OrderedDict
from collections.abc import Callable
from dataclasses import dataclass

from actuator_selection.http.errors import ApiError, service_error

MAX_ADDRESSES = 10_000


class TooManyRequestsError(ApiError):
    """429."""

    status_code = 429


@dataclass(slots=True)
class _Bucket:
    tokens: float
    at: float


class KeyFailureThrottle:
    """Wrong keys per client address (see the module docstring). Used from the event
    loop's thread alone, so it needs no lock."""

    def __init__(
        self, capacity: int, window_s: float, clock: Callable[[], float] = time.monotonic
    ) -> None:
        self.capacity = capacity
        self.rate = capacity / window_s
        """Tokens regained per second."""
        self._clock = clock
        self._buckets: OrderedDict[str, _Bucket] = OrderedDict()

    def _refilled(self, address: str) -> _Bucket | None:
        bucket = self._buckets.get(address)
        if bucket is None:
            return None
        now = self._clock()
        bucket.tokens = min(self.capacity, bucket.tokens + (now - bucket.at) * self.rate)
        bucket.at = now
        if bucket.tokens >= self.capacity:
            del self._buckets[address]  # full again: nothing to remember
            return None
        return bucket

    def check(self, address: str) -> None:
        """429 with ``Retry-After`` when ``address`` has no wrong key left to send."""
        bucket = self._refilled(address)
        if bucket is None or bucket.tokens >= 1:
            return
        retry_after_s = max(1, math.ceil((1 - bucket.tokens) / self.rate))
        entry = service_error(
            ["header", "Authorization"],
            "too_many_failed_keys",
            "too_many_failed_keys",
            retry_after_s=retry_after_s,
        )
        raise TooManyRequestsError([entry], headers={"Retry-After": str(retry_after_s)})

    def failed(self, address: str) -> None:
        """Count a wrong key from ``address``."""
        bucket = self._refilled(address)
        if bucket is None:
            bucket = _Bucket(tokens=float(self.capacity), at=self._clock())
            self._buckets[address] = bucket
        bucket.tokens = max(0.0, bucket.tokens - 1)
        self._buckets.move_to_end(address)
        while len(self._buckets) > MAX_ADDRESSES:
            self._buckets.popitem(last=False)
