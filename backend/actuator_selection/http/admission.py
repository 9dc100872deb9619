"""Admission control: a bounded number of API requests at work, a bounded queue, then 503.

Without it, every request gets a worker thread at once (anyio's pool holds 40)
and waits inside the database pool; past the pool's size, threads time out there
after long waits and answer 500. With it, at most ``max_concurrent`` requests are
worked on per process (the database pool has a connection for each, and as many
again in spare), up to ``max_queued`` more wait in arrival order, and a request
that finds the queue full, or waits longer than ``timeout_s``, is answered 503
with ``Retry-After`` at once: overload is an answer, never a hang.

A request is admitted only once its body is in. The body is received first, whole,
within ``body_timeout_s`` (else 408, and the connection is closed), and replayed to
the application from memory: a client that sends its headers and then dribbles the
body holds no place and makes no one wait. Bodies declared larger than
``max_body_bytes`` (the largest route limit; ``larger_bodies`` names the paths with a
larger one, the batch jobs') are not received here; their route
answers 413 from the declared length. Receiving happens before admission, so it is
not bounded by the number of places: in front of the service, a reverse proxy that
buffers request bodies (nginx does by default) bounds it by its own limits.

Only ``/api/`` is admitted this way; the page's static files cost nothing to serve.
"""

from __future__ import annotations

import math
from collections import deque

import anyio
from starlette.datastructures import Headers
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from actuator_selection.http.errors import body_timeout, language_of, service_unavailable


class AdmissionControl:
    """Pure ASGI middleware around the API (see the module docstring)."""

    def __init__(
        self,
        app: ASGIApp,
        *,
        max_concurrent: int,
        max_queued: int,
        timeout_s: float,
        body_timeout_s: float,
        max_body_bytes: int,
        larger_bodies: tuple[tuple[str, int], ...] = (),
        prefix: str = "/api/",
    ) -> None:
        self.app = app
        self._max_concurrent = max_concurrent
        self._max_queued = max_queued
        self._timeout_s = timeout_s
        self._body_timeout_s = body_timeout_s
        self._max_body_bytes = max_body_bytes
        self._larger_bodies = larger_bodies  # (path prefix, its limit): batch jobs
        self._prefix = prefix
        self._slots: anyio.Semaphore | None = None  # made in the server's event loop
        self._queued = 0

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or not scope["path"].startswith(self._prefix):
            await self.app(scope, receive, send)
            return
        received = await self._receive_body(scope, receive)
        if received is None:
            response = body_timeout(self._body_timeout_s, language=language_of(scope))
            await response(scope, receive, send)
            return
        if received and received[-1]["type"] == "http.disconnect":
            return  # the client has gone: nothing to answer
        receive = _replay(received, receive)
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

    async def _receive_body(self, scope: Scope, receive: Receive) -> list[Message] | None:
        """The body's messages, received within the body timeout; None when it ran out.

        Stops early past ``max_body_bytes``: the route refuses the body (413) as it reads
        on, so no more of it is held here.
        """
        limit = next(
            (n for prefix, n in self._larger_bodies if scope["path"].startswith(prefix)),
            self._max_body_bytes,
        )
        declared = Headers(scope=scope).get("content-length", "")
        if declared.isdigit() and int(declared) > limit:
            return []
        messages: list[Message] = []
        size = 0
        with anyio.move_on_after(self._body_timeout_s):
            while True:
                message = await receive()
                messages.append(message)
                if message["type"] != "http.request" or not message.get("more_body", False):
                    return messages
                size += len(message.get("body", b""))
                if size > limit:
                    return messages
        return None

    async def _reject(self, scope: Scope, receive: Receive, send: Send, reason: str) -> None:
        retry_after = max(1, math.ceil(self._timeout_s / 10))
        response = service_unavailable(
            reason, retry_after_s=retry_after, language=language_of(scope)
        )
        await response(scope, receive, send)


def _replay(messages: list[Message], receive: Receive) -> Receive:
    """``receive`` that gives ``messages`` first, then what the server sends (the end of a
    body too large to hold, a disconnect that a streamed answer watches for)."""
    pending = deque(messages)

    async def replayed() -> Message:
        return pending.popleft() if pending else await receive()

    return replayed
