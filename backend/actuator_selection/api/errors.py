"""The one place where errors become HTTP responses.

Every error body is JSON of the form ``{"detail": [{"loc": [...], "msg": ..., "type": ...}]}``
(FastAPI's validation shape) or ``{"detail": "..."}`` for a missing resource, so a
client always learns which field broke which rule. Nothing answers with a stack trace.
"""

from __future__ import annotations

import logging
from typing import Any
from urllib.parse import parse_qsl

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from sqlalchemy.exc import IntegrityError
from starlette.types import ASGIApp, Receive, Scope, Send

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


def _unexpected(_: Request, exc: Exception) -> JSONResponse:
    log.exception("unhandled error", exc_info=exc)
    return JSONResponse(status_code=500, content={"detail": "internal error; it has been logged"})


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
    app.add_exception_handler(RequestValidationError, _validation)
    app.add_exception_handler(DomainError, _domain)
    app.add_exception_handler(RequestFieldError, _request_field_error)
    app.add_exception_handler(IntegrityError, _conflict)
    app.add_exception_handler(Exception, _unexpected)
