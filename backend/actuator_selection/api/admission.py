"""Admission control: a bounded number of API requests at work, a bounded queue, then 503.

Without it, every request gets a worker thread at once (anyio's pool holds 40)
and waits inside the database pool; past the pool's size, threads time out there
after long waits and answer 500. With it, at most ``max_concurrent`` requests are
worked on per process (the database pool has a connection for each, and as many
again in spare), up to ``max_queued`` more wait in arrival order, and a request
that finds the queue full, or waits longer than ``timeout_s``, is answered 503
with ``Retry-After`` at once: overload is an answer, never a hang.

Only ``/api/`` is admitted this way; the page's static files cost nothing to serve.
"""

from __future__ import annotations

import math

import anyio
from starlette.types import ASGIApp, Receive, Scope, Send

from actuator_selection.api.errors import language_of, service_unavailable


class AdmissionControl:
    """Pure ASGI middleware around the API (see the module docstring)."""

    def __init__(
        self,
        app: ASGIApp,
        *,
        max_concurrent: int,
        max_queued: int,
        timeout_s: float,
        prefix: str = "/api/",
    ) -> None:
        self.app = app
        self._max_concurrent = max_concurrent
        self._max_queued = max_queued
        self._timeout_s = timeout_s
        self._prefix = prefix
        self._slots: anyio.Semaphore | None = None  # made in the server's event loop
        self._queued = 0

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or not scope["path"].startswith(self._prefix):
            await self.app(scope, receive, send)
            return
        if self._slots is None:
            self._slots = anyio.Semaphore(self._max_concurrent, fast_acquire=True)
        slots = self._slots
        if slots.value == 0 and self._queued >= self._max_queued:
            await self._reject(scope, receive, send, "the service is at capacity")
            return
        self._queued += 1
        try:
            with anyio.move_on_after(self._timeout_s) as waited:
                await slots.acquire()
        finally:
            self._queued -= 1
        if waited.cancelled_caught:
            await self._reject(
                scope, receive, send, f"no capacity became free within {self._timeout_s:g} s"
            )
            return
        try:
            await self.app(scope, receive, send)
        finally:
            slots.release()

    async def _reject(self, scope: Scope, receive: Receive, send: Send, reason: str) -> None:
        retry_after = max(1, math.ceil(self._timeout_s / 10))
        response = service_unavailable(
            reason, retry_after_s=retry_after, language=language_of(scope)
        )
        await response(scope, receive, send)
