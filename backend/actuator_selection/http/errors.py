"""The one place where errors become HTTP responses, all in one shape.

Every error answer, whatever its status, is JSON of the form
``{"detail": [{"loc": [...], "msg": "...", "type": "..."}, ...]}`` (FastAPI's
validation shape): ``loc`` says where the problem is (``["body", "cycle",
"accel_s"]``, ``["path", "model"]``, ``["query", "offset"]``, ``["header",
"Authorization"]``, or ``["request"]`` for the request as a whole), ``msg`` says
what rule it breaks in words, ``type`` names the rule for programs. Catalogue file
errors add ``file``, ``line`` and ``column``. Nothing answers with a stack trace.

Every entry also has ``code`` and ``params`` (``i18n/localize.py``): the rule's stable
name and the values its message names, so that a client can word the message itself;
``msg`` is in the language ``Accept-Language`` asks for (English or German).

Endpoints raise :class:`ApiError` (or a subclass naming its status); core raises
``DomainError``; both end in a handler here.

A database that is busy past its limits (a lock or statement timeout, no free
connection, a serialisation conflict) is an overload, not a fault: 503 with
``Retry-After``, and the transaction has been rolled back. So is a database that
cannot be reached (``db.availability``): 503 naming the dependency, without a
traceback, on every request until it answers again. Any other unexpected
error is a logged 500 that leaves the connection usable: Starlette's own handler
for ``Exception`` re-raises after answering, and the server then resets the
keep-alive connection, failing the client's next request too.
"""

from __future__ import annotations

import logging
from collections.abc import Mapping, Sequence
from types import UnionType
from typing import Annotated, Any, Literal, Self, Union, get_args, get_origin
from urllib.parse import parse_qsl

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse
from pydantic import BaseModel, Discriminator, Tag
from pydantic.fields import FieldInfo
from sqlalchemy.exc import DBAPIError, IntegrityError, OperationalError
from sqlalchemy.exc import TimeoutError as PoolTimeoutError
from starlette.exceptions import HTTPException as StarletteHTTPException
from starlette.middleware.body_limit import MAX_BODY_SIZE_SCOPE_KEY
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from actuator_selection.db.availability import unreachable
from actuator_selection.errors import DomainError
from actuator_selection.i18n.localize import (
    DEFAULT_LANGUAGE,
    SERVICE_MESSAGES,
    localized,
    negotiate,
    pydantic_message,
)
from actuator_selection.phrases.messages import Text
from actuator_selection.text import NUL_RULE

log = logging.getLogger(__name__)


def field_error(
    loc: list[str | int],
    msg: str,
    type_: str,
    *,
    code: str | None = None,
    params: Mapping[str, Any] | None = None,
    template: str | None = None,
) -> dict[str, Any]:
    """One entry of an error body: ``msg`` in English; with a ``template`` (English, over
    ``params``) it is rendered in the request's language when it is sent. ``code`` is the
    rule's name (default: ``type_``)."""
    entry: dict[str, Any] = {"loc": loc, "msg": msg, "type": type_}
    entry["code"] = code or type_
    entry["params"] = dict(params or {})
    if template is not None:
        entry["_template"] = template
    return entry


def service_error(loc: list[str | int], type_: str, code: str, **params: Any) -> dict[str, Any]:
    """An entry worded by one of the service's templates (``SERVICE_MESSAGES[code]``)."""
    template = SERVICE_MESSAGES[code]
    msg = template.format(**params)
    return field_error(loc, msg, type_, code=code, params=params, template=template)


def domain_entry(loc: list[str | int], exc: DomainError) -> dict[str, Any]:
    """The entry of a domain error at ``loc``: its rule's code and params where it has a
    template, else its type as its code and its text as it is."""
    type_ = exc.error_type or type(exc).__name__
    return field_error(
        loc, exc.message, type_, code=exc.code, params=exc.params, template=exc.template
    )


def language_of(scope: Scope) -> str:
    """The language of the messages to ``scope``'s request (``Accept-Language``)."""
    for name, value in scope.get("headers") or ():
        if name == b"accept-language":
            return negotiate(value.decode("latin-1"))
    return DEFAULT_LANGUAGE


def error_response(
    status_code: int,
    errors: list[dict[str, Any]],
    headers: Mapping[str, str] | None = None,
    *,
    language: str = DEFAULT_LANGUAGE,
) -> JSONResponse:
    """An error answer in the one shape, its messages in ``language``."""
    content = {"detail": [localized(e, language) for e in errors]}
    response_headers = {"Content-Language": language, **(headers or {})}
    return JSONResponse(status_code=status_code, content=content, headers=response_headers)


class ApiError(Exception):
    """An error answer an endpoint raises: its status, its entries, extra headers."""

    status_code = 422

    def __init__(
        self, errors: list[dict[str, Any]], *, headers: Mapping[str, str] | None = None
    ) -> None:
        super().__init__(errors)
        self.errors = errors
        self.headers = dict(headers or {})

    @classmethod
    def at(
        cls, loc: list[str | int], msg: str, type_: str, *, headers: Mapping[str, str] | None = None
    ) -> Self:
        """The error with one entry."""
        return cls([field_error(loc, msg, type_)], headers=headers)


class RequestFieldError(ApiError):
    """Request errors found by an endpoint (e.g. models the catalogue lacks): 422."""


class UnauthorizedError(ApiError):
    """No valid credentials: 401."""

    status_code = 401


class ForbiddenError(ApiError):
    """Valid credentials without the right: 403."""

    status_code = 403


class ResourceNotFoundError(ApiError):
    """The resource the path names does not exist: 404."""

    status_code = 404


class ConflictError(ApiError):
    """The request conflicts with the resource's state: 409."""

    status_code = 409


class PayloadTooLargeError(ApiError):
    """413."""

    status_code = 413


class UnsupportedMediaTypeError(ApiError):
    """415."""

    status_code = 415


def _api_error(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, ApiError)
    return error_response(
        exc.status_code, exc.errors, exc.headers or None, language=language_of(request.scope)
    )


def _members(annotation: Any) -> tuple[Any, list[Any]]:
    """``annotation`` without ``Annotated``, and the metadata that wrapped it."""
    metadata: list[Any] = []
    while get_origin(annotation) is Annotated:
        annotation, *extra = get_args(annotation)
        metadata.extend(extra)
    return annotation, metadata


def _union_tags(members: tuple[Any, ...], discriminator: object) -> dict[str, Any]:
    """The tags pydantic puts into ``loc`` for a discriminated union, with their member:
    ``Tag(...)`` metadata, else the ``Literal`` values of a named discriminator field."""
    tags: dict[str, Any] = {}
    for member in members:
        bare, metadata = _members(member)
        for item in metadata:
            if isinstance(item, Tag):
                tags[item.tag] = bare
        if (
            isinstance(discriminator, str)
            and isinstance(bare, type)
            and issubclass(bare, BaseModel)
        ):
            field = bare.model_fields.get(discriminator)
            literal, _ = _members(field.annotation) if field is not None else (None, [])
            if get_origin(literal) is Literal:
                tags.update({str(value): bare for value in get_args(literal)})
    return tags


def field_loc(
    annotation: Any, loc: Sequence[str | int], discriminator: object = None
) -> list[str | int]:
    """``loc`` (below a value of type ``annotation``) without the tags that pydantic inserts
    for tagged and discriminated unions: ``["load", "direct", "torque_nm"]`` becomes
    ``["load", "torque_nm"]``, since ``direct`` names no field of the body.

    Walks models (by field name or alias), lists and dicts along ``loc``; where the type
    cannot be followed, the rest of ``loc`` is kept as it is.
    """
    out: list[str | int] = []
    i = 0
    while i < len(loc):
        annotation, metadata = _members(annotation)
        for item in metadata:  # Discriminator(...) or Field(discriminator=...)
            if isinstance(item, Discriminator | FieldInfo) and item.discriminator is not None:
                discriminator = item.discriminator
        origin = get_origin(annotation)
        if origin in (Union, UnionType):
            members = tuple(m for m in get_args(annotation) if m is not type(None))
            if len(members) == 1:
                annotation = members[0]
                continue
            tags = _union_tags(members, discriminator)
            tag = loc[i]
            if not isinstance(tag, str) or tag not in tags:
                break
            annotation, discriminator, i = tags[tag], None, i + 1
            continue
        discriminator = None
        key = loc[i]
        if isinstance(annotation, type) and issubclass(annotation, BaseModel):
            fields = annotation.model_fields
            field = fields.get(str(key)) or next(
                (f for f in fields.values() if f.alias == key), None
            )
            if field is None:
                break
            annotation = field.annotation
            discriminator = field.discriminator
            if discriminator is None:
                found = (m for m in field.metadata if isinstance(m, Discriminator))
                discriminator = next((m.discriminator for m in found), None)
        elif origin in (list, tuple, set, frozenset) and get_args(annotation):
            annotation = get_args(annotation)[0]
        elif origin is dict and len(get_args(annotation)) == 2:
            annotation = get_args(annotation)[1]
        else:
            break
        out.append(key)
        i += 1
    return [*out, *loc[i:]]


def _body_loc(request: Request, loc: Sequence[str | int]) -> list[str | int]:
    """``loc`` of a body error as the body's fields alone (see :func:`field_loc`)."""
    route = request.scope.get("route")
    dependant = getattr(route, "dependant", None)
    params = getattr(dependant, "body_params", None) or []
    if not loc or loc[0] != "body" or len(params) != 1:
        return [*loc]
    (param,) = params
    if getattr(param.field_info, "embed", False):
        if len(loc) < 2 or loc[1] != param.alias:
            return [*loc]
        return ["body", loc[1], *field_loc(param.field_info.annotation, loc[2:])]
    return ["body", *field_loc(param.field_info.annotation, loc[1:])]


def _validation(request: Request, exc: Exception) -> JSONResponse:
    # Rebuilt rather than passed through: pydantic's entries echo the input, and an
    # input of NaN or ±Infinity cannot be written as JSON. Body locations lose the union
    # tags pydantic inserts (``loc`` names body fields only).
    # pydantic's ``type`` is the code and its ``ctx`` the params (bounds gain the unit).
    assert isinstance(exc, RequestValidationError)
    language = language_of(request.scope)
    detail = []
    for e in exc.errors():
        loc = _body_loc(request, e["loc"])
        code, params, msg = pydantic_message(loc, e, language)
        detail.append(field_error(loc, msg, str(e["type"]), code=code, params=params))
    return error_response(422, detail, language=language)


def _domain(request: Request, exc: Exception) -> JSONResponse:
    assert isinstance(exc, DomainError)
    language = language_of(request.scope)
    entries = getattr(exc, "entries", None)  # services.errors.UseCaseError: all its entries
    if entries:
        return error_response(exc.http_status, entries, language=language)
    loc: list[str | int] = [exc.where, *exc.field.split(".")]
    return error_response(exc.http_status, [domain_entry(loc, exc)], language=language)


def _conflict(request: Request, exc: Exception) -> JSONResponse:
    # A concurrent request wrote the same key first (e.g. two admins creating the next
    # controller row at once): the transaction has been rolled back, a retry succeeds.
    log.info("write conflict: %s", exc)
    entry = service_error(["request"], "write_conflict", "write_conflict")
    return error_response(409, [entry], language=language_of(request.scope))


def body_too_large(limit: int | None, *, language: str = DEFAULT_LANGUAGE) -> JSONResponse:
    """413 in the error shape, naming the limit (``MAX_BODY_BYTES`` / ``MAX_BULK_BODY_BYTES``)."""
    entry = (
        service_error(["body"], "body_too_large", "body_too_large", limit=limit)
        if limit is not None
        else service_error(["body"], "body_too_large", "body_too_large_no_limit")
    )
    return error_response(413, [entry], language=language)


def body_timeout(timeout_s: float, *, language: str = DEFAULT_LANGUAGE) -> JSONResponse:
    """408 in the error shape: the body did not arrive within ``timeout_s`` (``BODY_TIMEOUT_S``).
    The connection is closed after it (the rest of the body is never read)."""
    entry = service_error(["body"], "request_timeout", "request_timeout", timeout_s=timeout_s)
    return error_response(408, [entry], {"Connection": "close"}, language=language)


_FASTAPI_BODY_ERROR = "There was an error parsing the body"
"""FastAPI's 400 for a body its JSON parser gave up on (e.g. nested past its depth)."""

_HTTP_ERRORS: dict[int, tuple[list[str | int], str]] = {
    400: (["body"], "json_invalid"),
    404: (["path"], "not_found"),
    405: (["request"], "method_not_allowed"),
    413: (["body"], "body_too_large"),
}


def _http_error(request: Request, exc: Exception) -> JSONResponse:
    """Errors the framework raises before an endpoint runs (no such route, a method not
    allowed, a body too large or that JSON cannot parse), in the one shape."""
    assert isinstance(exc, StarletteHTTPException)
    language = language_of(request.scope)
    if exc.status_code == 413:
        return body_too_large(request.scope.get(MAX_BODY_SIZE_SCOPE_KEY), language=language)
    loc, type_ = _HTTP_ERRORS.get(exc.status_code, (["request"], f"http_{exc.status_code}"))
    allowed = (exc.headers or {}).get("Allow", "")
    if exc.detail == _FASTAPI_BODY_ERROR:
        entry = service_error(loc, type_, "json_invalid")
    elif exc.status_code == 404 and exc.detail == "Not Found":
        entry = service_error(loc, type_, "route_not_found", path=request.url.path)
    elif exc.status_code == 405 and allowed:
        entry = service_error(
            loc, type_, "method_not_allowed", method=request.method, allowed=allowed
        )
    else:
        entry = field_error(loc, str(exc.detail), type_)
    return error_response(exc.status_code, [entry], exc.headers, language=language)


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
                    response = body_too_large(
                        limit if isinstance(limit, int) else None, language=language_of(scope)
                    )
                    await response(scope, receive, send)
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


def service_unavailable(
    reason: str, *, retry_after_s: int = RETRY_AFTER_S, language: str = DEFAULT_LANGUAGE
) -> JSONResponse:
    """503 with ``Retry-After``: nothing was changed, the same request may be sent again.
    ``reason`` is translated where it is one of ``i18n.localize.REASONS``."""
    entry = service_error(
        ["request"],
        "service_unavailable",
        "service_unavailable",
        reason=Text(reason),
        retry_after_s=retry_after_s,
    )
    return error_response(503, [entry], {"Retry-After": str(retry_after_s)}, language=language)


DATABASE_RETRY_AFTER_S = 5
"""``Retry-After`` [s] of a 503 while the database cannot be reached."""


def database_unavailable(*, language: str = DEFAULT_LANGUAGE) -> JSONResponse:
    """503 with ``Retry-After`` while the database cannot be reached; the entry names the
    dependency that is down (``params.dependency``)."""
    entry = service_error(
        ["request"],
        "service_unavailable",
        "database_unreachable",
        dependency="database",
        retry_after_s=DATABASE_RETRY_AFTER_S,
    )
    headers = {"Retry-After": str(DATABASE_RETRY_AFTER_S)}
    return error_response(503, [entry], headers, language=language)


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


def _database_error(exc: BaseException, language: str) -> JSONResponse:
    """503 for a database that cannot be reached (logged once per outage by
    ``db.availability``) or is busy; 500 for any other error."""
    if unreachable(exc):
        return database_unavailable(language=language)
    if database_busy(exc):
        log.warning("database busy: %s", exc)
        return service_unavailable("the database is busy", language=language)
    return _internal_error(exc, language)


def _operational(request: Request, exc: Exception) -> JSONResponse:
    return _database_error(exc, language_of(request.scope))


def _internal_error(exc: BaseException, language: str = DEFAULT_LANGUAGE) -> JSONResponse:
    log.error("unhandled error", exc_info=exc)
    entry = service_error(["request"], "internal_error", "internal_error")
    return error_response(500, [entry], language=language)


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
            response = _database_error(exc, language_of(scope))
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
                response = error_response(
                    422, [field_error(loc, NUL_RULE, "value_error")], language=language_of(scope)
                )
                await response(scope, receive, send)
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
    app.add_exception_handler(ApiError, _api_error)
    app.add_exception_handler(IntegrityError, _conflict)
    app.add_exception_handler(OperationalError, _operational)
    app.add_exception_handler(DBAPIError, _operational)  # e.g. InterfaceError: connection lost
    app.add_exception_handler(PoolTimeoutError, _operational)
