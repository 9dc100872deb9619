"""The one place where errors become HTTP responses.

Every error body is JSON of the form ``{"detail": [{"loc": [...], "msg": ..., "type": ...}]}``
(FastAPI's validation shape) or ``{"detail": "..."}`` for a missing resource, so a
client always learns which field broke which rule. Nothing answers with a stack trace.

A database that is busy past its limits (a lock or statement timeout, no free
connection, a serialisation conflict) is an overload, not a fault: 503 with
``Retry-After``, and the transaction has been rolled back. Any other unexpected
error is a logged 500 that leaves the connection usable: Starlette's own handler
for ``Exception`` re-raises after answering, and the server then resets the
keep-alive connection, failing the client's next request too.
"""

from __future__ import annotations

import logging
from typing import Any
from urllib.parse import parse_qsl

from fastapi import FastAPI, Request
from fastapi.exception_handlers import http_exception_handler
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from sqlalchemy.exc import IntegrityError, OperationalError
from sqlalchemy.exc import TimeoutError as PoolTimeoutError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.middleware.body_limit import MAX_BODY_SIZE_SCOPE_KEY
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from actuator_selection.core.errors import DomainError, NotFoundError
from actuator_selection.db.csvio import NUL_RULE

log = logging.getLogger(__name__)


def field_error(loc: list[str | int], msg: str, type_: str) -> dict[str, Any]:
    """One entry of an error body."""
    return {"loc": loc, "msg": msg, "type": type_}


class RequestFieldError(Exception):
    """Request errors found by an endpoint (e.g. models the catalogue lacks): 422."""

    def __init__(self, errors: list[dict[str, Any]]) -> None:
        super().__init__(errors)
        self.errors = errors


def _request_field_error(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, RequestFieldError)
    return JSONResponse(status_code=422, content={"detail": exc.errors})


def _validation(_: Request, exc: Exception) -> JSONResponse:
    # Rebuilt rather than passed through: pydantic's entries echo the input, and an
    # input of NaN or ±Infinity cannot be written as JSON.
    assert isinstance(exc, RequestValidationError)
    detail = [field_error([*e["loc"]], str(e["msg"]), str(e["type"])) for e in exc.errors()]
    return JSONResponse(status_code=422, content={"detail": detail})


def _domain(_: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, DomainError)
    status = 404 if isinstance(exc, NotFoundError) else 422
    loc: list[str | int] = ["body", *exc.field.split(".")]
    return JSONResponse(
        status_code=status,
        content={"detail": [field_error(loc, exc.message, type(exc).__name__)]},
    )


def _conflict(_: Request, exc: Exception) -> JSONResponse:
    # A concurrent request wrote the same key first (e.g. two admins creating the next
    # controller row at once): the transaction has been rolled back, a retry succeeds.
    log.info("write conflict: %s", exc)
    return JSONResponse(
        status_code=409,
        content={
            "detail": "a concurrent change wrote the same record first; nothing was "
            "changed by this request, send it again"
        },
    )


def body_too_large(limit: int | None) -> JSONResponse:
    """413 in the error shape, naming the limit (``MAX_BODY_BYTES`` / ``MAX_BULK_BODY_BYTES``)."""
    size = f"{limit} bytes" if limit is not None else "the limit"
    return JSONResponse(
        status_code=413,
        content={
            "detail": [
                field_error(
                    ["body"],
                    f"the request body is larger than {size}; send less per request",
                    "body_too_large",
                )
            ]
        },
    )


async def _http_error(request: Request, exc: Exception) -> JSONResponse | Any:
    """Errors FastAPI raises before an endpoint runs, in the error shape where they concern
    the body: 413 (too large) and 400 (a body JSON cannot parse, e.g. nested past the
    parser's recursion limit). Others keep FastAPI's ``{"detail": "..."}``."""
    assert isinstance(exc, StarletteHTTPException)
    if exc.status_code == 413:
        return body_too_large(request.scope.get(MAX_BODY_SIZE_SCOPE_KEY))
    if exc.status_code == 400 and isinstance(exc.detail, str):
        message = "the body could not be parsed as JSON (malformed, or nested too deeply)"
        return JSONResponse(
            status_code=400,
            content={"detail": [field_error(["body"], message, "json_invalid")]},
        )
    return await http_exception_handler(request, exc)


class UniformBodyTooLarge:
    """Starlette's body limit answers a request whose Content-Length is over the limit with a
    plain-text 413 of its own; this gives that answer the error shape too."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        replaced = False

        async def reshape(message: Message) -> None:
            nonlocal replaced
            if message["type"] == "http.response.start" and message["status"] == 413:
                headers = dict(message.get("headers", []))
                if headers.get(b"content-type", b"").startswith(b"text/plain"):
                    replaced = True
                    limit = scope.get(MAX_BODY_SIZE_SCOPE_KEY)
                    await body_too_large(limit if isinstance(limit, int) else None)(
                        scope, receive, send
                    )
                    return
            if not replaced:
                await send(message)

        await self.app(scope, receive, reshape)


RETRY_AFTER_S = 1
"""``Retry-After`` [s] of a 503 caused by a busy database."""

_BUSY_SQLSTATES = frozenset(
    {
        "40001",  # serialization_failure
        "40P01",  # deadlock_detected
        "55P03",  # lock_not_available (lock_timeout)
        "57014",  # query_canceled (statement_timeout)
        "53300",  # too_many_connections
    }
)


def service_unavailable(reason: str, *, retry_after_s: int = RETRY_AFTER_S) -> JSONResponse:
    """503 with ``Retry-After``: nothing was changed, the same request may be sent again."""
    return JSONResponse(
        status_code=503,
        content={"detail": f"{reason}; nothing was changed, retry after {retry_after_s} s"},
        headers={"Retry-After": str(retry_after_s)},
    )


def database_busy(exc: BaseException) -> bool:
    """True when ``exc`` says the database was too busy, not that the request was wrong."""
    if isinstance(exc, PoolTimeoutError):
        return True
    if not isinstance(exc, OperationalError):
        return False
    sqlstate = getattr(exc.orig, "sqlstate", None)
    if sqlstate is not None:
        return sqlstate in _BUSY_SQLSTATES
    message = str(exc.orig).lower()  # sqlite3 has no codes in its exception types
    return "database is locked" in message or "database is busy" in message


def _operational(_: Request, exc: Exception) -> JSONResponse:
    if database_busy(exc):
        log.warning("database busy: %s", exc)
        return service_unavailable("the database is busy")
    return _internal_error(exc)


def _internal_error(exc: BaseException) -> JSONResponse:
    log.error("unhandled error", exc_info=exc)
    return JSONResponse(status_code=500, content={"detail": "internal error; it has been logged"})


class AnswerUnexpectedErrors:
    """500 for an exception no handler took, without re-raising it (see the module docstring).

    An exception after the answer has started cannot be answered any more; it is
    re-raised, and the server ends that connection.
    """

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        started = False

        async def watch(message: Message) -> None:
            nonlocal started
            started = started or message["type"] == "http.response.start"
            await send(message)

        try:
            await self.app(scope, receive, watch)
        except Exception as exc:
            if started:
                raise
            response = (
                service_unavailable("the database is busy")
                if database_busy(exc)
                else _internal_error(exc)
            )
            await response(scope, receive, send)


class RejectNulInUrl:
    """422 for a path or query parameter holding U+0000 (``%00``), before any route runs.

    Bodies are guarded where they are parsed (``schemas.common.StrictModel`` and the
    catalogue files' cell rules), so that the error names the field.
    """

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http":
            loc = self._nul_at(scope)
            if loc is not None:
                body = {"detail": [field_error(loc, NUL_RULE, "value_error")]}
                await JSONResponse(status_code=422, content=body)(scope, receive, send)
                return
        await self.app(scope, receive, send)

    @staticmethod
    def _nul_at(scope: Scope) -> list[str | int] | None:
        if "\x00" in scope["path"]:
            return ["path"]
        query = scope.get("query_string", b"").decode("latin-1")
        for name, value in parse_qsl(query, keep_blank_values=True):
            if "\x00" in name or "\x00" in value:
                return ["query", name.replace("\x00", "")]
        return None


def install(app: FastAPI) -> None:
    """Register the handlers (and the URL guard) on ``app``."""
    app.add_middleware(RejectNulInUrl)
    app.add_middleware(AnswerUnexpectedErrors)
    app.add_middleware(UniformBodyTooLarge)
    app.add_exception_handler(StarletteHTTPException, _http_error)
    app.add_exception_handler(RequestValidationError, _validation)
    app.add_exception_handler(DomainError, _domain)
    app.add_exception_handler(RequestFieldError, _request_field_error)
    app.add_exception_handler(IntegrityError, _conflict)
    app.add_exception_handler(OperationalError, _operational)
    app.add_exception_handler(PoolTimeoutError, _operational)
