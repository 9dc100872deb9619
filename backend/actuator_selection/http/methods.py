"""The methods a path allows: 405 and ``OPTIONS`` answered from the routes, and CORS.

Starlette's router answers a method a route does not take with the first route whose
path matched, unless a later route matches fully; the web page's static mount at ``/``
matches every path, so every 405 said ``Allow: GET, HEAD`` (the mount's methods) and
``OPTIONS`` on an API path was refused with that same wrong list.
:class:`AllowedMethods` answers before the router does, from every route whose path
matches (a path may be served by several routes, one per method):

- a method none of them takes: 405 in the error shape, ``Allow`` listing the methods
  they take and ``OPTIONS``;
- ``OPTIONS``: 204 with that ``Allow`` (RFC 9110 §9.3.7);
- ``HEAD`` where ``GET`` is served: the ``GET`` answer's status and headers without its
  body (RFC 9110 §9.3.2; FastAPI's routes take ``GET`` alone);
- a path below the API's prefix that no route serves: 404 in the error shape, whatever
  the method (the static mount answered a POST there with 405).

Cross-origin requests: the API reads its key from ``Authorization``, never from a
cookie, so a browser on another site cannot act with a user's key unless its page
holds the key itself. ``CORS_ALLOW_ORIGINS`` (comma-separated origins, or ``*``) names
the sites whose pages may call the API; a preflight from one of them is answered by
Starlette's ``CORSMiddleware`` (:class:`PreflightForListedOrigins`). The default is
none: the service's own pages are same-origin and need no CORS, and a preflight from
any other origin gets the ``OPTIONS`` answer above, without ``Access-Control-Allow-*``
headers, which a browser reads as a refusal.
"""

from __future__ import annotations

from collections.abc import Sequence

from fastapi.routing import RouteContext, iter_route_contexts
from starlette.middleware.cors import CORSMiddleware
from starlette.responses import Response
from starlette.routing import Match, Mount, Router
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from actuator_selection.http.errors import error_response, language_of, service_error

CORS_METHODS = ("GET", "POST", "PUT", "PATCH", "DELETE")
"""The methods a listed origin may send (a path still allows only its own)."""
CORS_REQUEST_HEADERS = ("Authorization", "Content-Type", "Accept-Language")
"""The request headers a listed origin may send."""
CORS_EXPOSED_HEADERS = (
    "Content-Disposition",
    "Content-Language",
    "Location",
    "Retry-After",
    "X-Catalogue-Version",
)
"""The answer headers a listed origin's page may read besides the CORS-safelisted ones."""
CORS_MAX_AGE_S = 600
"""How long a browser may keep a preflight answer [s]."""
KNOWN_PATHS = 4096
"""How many paths' allowed methods :class:`AllowedMethods` keeps (then it starts over):
matching a path against every route costs about as much as the rest of a small request."""


def allowed_methods(routes: Sequence[RouteContext], scope: Scope) -> set[str]:
    """The methods of ``routes`` whose path matches ``scope``'s."""
    methods: set[str] = set()
    for route in routes:
        match, _ = route.matches(scope)
        if match is not Match.NONE:
            methods |= route.methods or set()
    return methods


def method_routes(router: Router) -> list[RouteContext]:
    """The routes of ``router`` that name their methods (not mounts), as served."""
    return [
        route
        for route in iter_route_contexts(router.routes)
        if not isinstance(route.original_route, Mount) and route.methods
    ]


def _without_body(send: Send) -> Send:
    """``send`` passing on the answer's status and headers but not its body (HEAD)."""

    async def head(message: Message) -> None:
        if message["type"] == "http.response.body":
            if message.get("more_body", False):
                return
            message = {"type": "http.response.body", "body": b"", "more_body": False}
        await send(message)

    return head


class AllowedMethods:
    """405 and ``OPTIONS`` for the paths the routes serve (see the module docstring)."""

    def __init__(self, app: ASGIApp, router: Router, api_prefix: str) -> None:
        self.app = app
        self.router = router
        self.api_prefix = api_prefix.rstrip("/") + "/"
        self.routes: list[RouteContext] | None = None  # read once, at the first request
        # A path's methods depend on the path alone (the routes are fixed once served).
        self.known: dict[tuple[str, str], frozenset[str]] = {}

    def methods_of(self, scope: Scope) -> frozenset[str]:
        """:func:`allowed_methods` for ``scope``'s path, matched once per path."""
        key = (scope.get("root_path", ""), scope["path"])
        found = self.known.get(key)
        if found is None:
            if self.routes is None:
                self.routes = method_routes(self.router)
            if len(self.known) >= KNOWN_PATHS:  # bounded: paths with ids are many
                self.known.clear()
            found = self.known[key] = frozenset(allowed_methods(self.routes, scope))
        return found

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http":
            own = self.methods_of(scope)
            methods = own | {"HEAD"} if "GET" in own else own
            method = scope["method"]
            if method == "HEAD" and "HEAD" not in own and "GET" in own:
                await self.app({**scope, "method": "GET"}, receive, _without_body(send))
                return
            if not methods and scope["path"].startswith(self.api_prefix):
                entry = service_error(["path"], "not_found", "route_not_found", path=scope["path"])
                await error_response(404, [entry], language=language_of(scope))(
                    scope, receive, send
                )
                return
            if methods and method not in methods:
                allowed = ", ".join(sorted(methods | {"OPTIONS"}))
                if method == "OPTIONS":
                    response = Response(status_code=204, headers={"Allow": allowed})
                else:
                    entry = service_error(
                        ["request"],
                        "method_not_allowed",
                        "method_not_allowed",
                        method=method,
                        allowed=allowed,
                    )
                    language = language_of(scope)
                    response = error_response(405, [entry], {"Allow": allowed}, language=language)
                await response(scope, receive, send)
                return
        await self.app(scope, receive, send)


class PreflightForListedOrigins(CORSMiddleware):
    """Starlette's CORS for ``origins``; a preflight from any other origin passes on (to
    :class:`AllowedMethods`) instead of getting Starlette's plain-text 400."""

    def __init__(self, app: ASGIApp, origins: Sequence[str]) -> None:
        super().__init__(
            app,
            allow_origins=origins,
            allow_methods=CORS_METHODS,
            allow_headers=CORS_REQUEST_HEADERS,
            expose_headers=CORS_EXPOSED_HEADERS,
            max_age=CORS_MAX_AGE_S,
        )

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http" and scope["method"] == "OPTIONS":
            headers = dict(scope.get("headers") or ())
            origin = headers.get(b"origin", b"").decode("latin-1")
            if not self.is_allowed_origin(origin):
                await self.app(scope, receive, send)
                return
        await super().__call__(scope, receive, send)
