"""Security headers on every response, as a pure ASGI middleware.

Every response:

- ``X-Content-Type-Options: nosniff`` — a browser takes the declared type (a CSV
  or a JSON answer is never run as script or rendered as HTML).
- ``Referrer-Policy: no-referrer`` — the app reads neither ``Referer`` nor
  ``Origin`` (keys travel in ``Authorization``, not cookies, so there is no
  cross-site request to tell apart), and its URLs carry quote numbers and
  selection ids that have no business in another site's logs. The stricter
  policy costs nothing here; ``strict-origin-when-cross-origin`` would only give
  other sites the origin.
- ``X-Frame-Options: DENY`` — nothing in ``frontend/`` frames the app (the quote
  document opens in a window of its own). A response whose route set its own
  ``Content-Security-Policy`` with ``frame-ancestors`` keeps that decision alone:
  browsers let ``frame-ancestors`` override ``X-Frame-Options``, and two headers
  saying different things would only mislead a reader.

HTML responses (the engineer's page, the sales page) get :data:`PAGE_CSP`: scripts
only from the app itself (both pages load ES modules and the locally served
plotly.js; neither has inline code or inline event handlers). Styles also allow
``'unsafe-inline'``: plotly.js injects ``<style>`` elements and sets ``style``
attributes when it draws, and the sales page writes the quote document, whose
styles are inline, into a window that inherits the sales page's policy.
plotly.js needs no ``'unsafe-eval'`` for the 2-D charts the pages draw.

The API documentation pages (``/docs``, ``/redoc``, Swagger UI's OAuth2 redirect)
load Swagger UI and ReDoc from the app (fastapi-offline's assets), and Swagger UI
starts from an inline script. They get :func:`docs_csp`: each inline script of the
page by its SHA-256 hash, computed from the page as it is sent — no
``'unsafe-inline'`` for scripts — and nothing from elsewhere.

A ``Content-Security-Policy`` that a route sets itself (the quote document) is
left as it is. Every header is only added when the response lacks it.

The middleware wraps the whole application, outside Starlette's
``ServerErrorMiddleware``, so that a 500 answer gets the headers too.
"""

from __future__ import annotations

import base64
import hashlib
import re
from collections.abc import Iterable
from typing import Final

from fastapi import FastAPI
from starlette.datastructures import MutableHeaders
from starlette.types import ASGIApp, Message, Receive, Scope, Send

ALWAYS: Final[dict[str, str]] = {
    "X-Content-Type-Options": "nosniff",
    "Referrer-Policy": "no-referrer",
}
FRAME_OPTIONS: Final = "DENY"

PAGE_CSP: Final = (
    "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
    "img-src 'self' data: blob:; font-src 'self'; connect-src 'self'; object-src 'none'; "
    "base-uri 'none'; form-action 'self'; frame-ancestors 'none'"
)
"""The engineer's and the sales page (every HTML response outside the docs)."""

_INLINE_SCRIPT = re.compile(rb"<script(?P<attributes>[^>]*)>(?P<body>.*?)</script\s*>", re.S | re.I)
_SRC_ATTRIBUTE = re.compile(rb"\bsrc\s*=", re.I)


def inline_script_hashes(html: bytes) -> list[str]:
    """CSP source expressions (``'sha256-…'``) of the inline scripts in ``html``.

    >>> inline_script_hashes(b"<script src='/a.js'></script><script>x()</script>")
    ["'sha256-D6IGS8VMvCoyaR/l0h9tERrBTATY01CoPS7l6xDv0kI='"]
    """
    hashes: list[str] = []
    for match in _INLINE_SCRIPT.finditer(html):
        if _SRC_ATTRIBUTE.search(match["attributes"]):
            continue
        digest = base64.b64encode(hashlib.sha256(match["body"]).digest()).decode("ascii")
        hashes.append(f"'sha256-{digest}'")
    return hashes


def docs_csp(script_hashes: Iterable[str]) -> str:
    """The policy of the API documentation pages, allowing exactly these inline scripts."""
    scripts = " ".join(["'self'", *script_hashes])
    return (
        f"default-src 'self'; script-src {scripts}; style-src 'self' 'unsafe-inline'; "
        "img-src 'self' data: blob:; font-src 'self' data:; connect-src 'self'; "
        # ReDoc's search index runs in a worker made from a blob: URL.
        "worker-src 'self' blob:; object-src 'none'; base-uri 'none'; form-action 'self'; "
        "frame-ancestors 'none'"
    )


def _is_html(headers: MutableHeaders) -> bool:
    return headers.get("content-type", "").lower().startswith("text/html")


def _add_headers(headers: MutableHeaders, *, page_csp: str | None) -> None:
    """The headers of every response; ``page_csp`` for an HTML answer without its own."""
    for name, value in ALWAYS.items():
        headers.setdefault(name, value)
    own_csp = headers.get("content-security-policy")
    if own_csp is None and page_csp is not None and _is_html(headers):
        headers["Content-Security-Policy"] = page_csp
    elif own_csp is not None and "frame-ancestors" in own_csp.lower():
        return  # the route decided who may frame it
    headers.setdefault("X-Frame-Options", FRAME_OPTIONS)


class SecurityHeadersMiddleware:
    """Adds the security headers to every HTTP response of ``app`` (see the module)."""

    def __init__(self, app: ASGIApp, *, docs_paths: Iterable[str] = ()) -> None:
        self.app = app
        self.docs_paths = frozenset(docs_paths)

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
        elif scope["path"] in self.docs_paths:
            await self._docs_page(scope, receive, send)
        else:

            async def send_with_headers(message: Message) -> None:
                if message["type"] == "http.response.start":
                    _add_headers(MutableHeaders(scope=message), page_csp=PAGE_CSP)
                await send(message)

            await self.app(scope, receive, send_with_headers)

    async def _docs_page(self, scope: Scope, receive: Receive, send: Send) -> None:
        """A docs page, held back until its body is complete to hash its inline scripts.

        The request is passed on without ``Accept-Encoding``, so that the (small)
        page arrives uncompressed and its scripts can be read.
        """
        inner_scope = {
            **scope,
            "headers": [(k, v) for k, v in scope["headers"] if k.lower() != b"accept-encoding"],
        }
        start: Message | None = None
        body: list[bytes] = []

        async def hold(message: Message) -> None:
            nonlocal start
            if message["type"] == "http.response.start":
                start = message
                return
            if message["type"] != "http.response.body" or start is None:
                await send(message)
                return
            body.append(message.get("body", b""))
            if message.get("more_body", False):
                return
            headers = MutableHeaders(scope=start)
            page = b"".join(body)
            csp = docs_csp(inline_script_hashes(page)) if _is_html(headers) else None
            _add_headers(headers, page_csp=csp)
            await send(start)
            await send({"type": "http.response.body", "body": page, "more_body": False})

        await self.app(inner_scope, receive, hold)


def install(app: FastAPI, *, docs_paths: Iterable[str] = ()) -> None:
    """Wrap ``app`` (outermost, around its error handling) in the middleware; idempotent.

    ``docs_paths`` are the API documentation pages, which get :func:`docs_csp`.
    """
    if getattr(app.state, "security_headers", False):
        return
    app.state.security_headers = True
    build_stack = app.build_middleware_stack

    def build_with_headers() -> ASGIApp:
        return SecurityHeadersMiddleware(build_stack(), docs_paths=docs_paths)

    # Starlette builds the stack on the first request; the error middleware it puts
    # outermost answers unhandled exceptions itself, so add_middleware would miss 500s.
    app.build_middleware_stack = build_with_headers  # type: ignore[method-assign]
