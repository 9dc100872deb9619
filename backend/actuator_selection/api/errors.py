"""The one place where errors become HTTP responses.

Every error body is JSON of the form ``{"detail": [{"loc": [...], "msg": ..., "type": ...}]}``
(FastAPI's validation shape) or ``{"detail": "..."}`` for a missing resource, so a
client always learns which field broke which rule. Nothing answers with a stack trace.
"""

from __future__ import annotations

import logging
from typing import Any

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse

from actuator_selection.core.errors import DomainError, NotFoundError

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


def _unexpected(_: Request, exc: Exception) -> JSONResponse:
    log.exception("unhandled error", exc_info=exc)
    return JSONResponse(status_code=500, content={"detail": "internal error; it has been logged"})


def install(app: FastAPI) -> None:
    """Register the handlers on ``app``."""
    app.add_exception_handler(RequestValidationError, _validation)
    app.add_exception_handler(DomainError, _domain)
    app.add_exception_handler(RequestFieldError, _request_field_error)
    app.add_exception_handler(Exception, _unexpected)
