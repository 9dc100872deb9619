"""Request bodies' media types: JSON endpoints take UTF-8 JSON alone; 415 otherwise.

FastAPI parses a body as JSON only when ``Content-Type`` says JSON; any other type (or
none) hands the endpoint the raw bytes, which fail validation as "a valid dictionary"
(422), and a JSON body in UTF-16 or UTF-32 is decoded as it comes (``json.loads``
detects the encoding). RFC 8259 §8.1 requires UTF-8 between systems, and the API
documents 415 for a media type it does not take: :func:`require_json_body` (an app-wide
dependency) answers 415 in the error shape, naming the header and what to send, for

- a body without ``Content-Type``, or with one that is not ``application/json`` (or
  ``application/<name>+json``): ``text/plain``, form data, …;
- a ``charset`` other than UTF-8, or a body that is UTF-16 or UTF-32 by its first bytes.

Endpoints that take files (catalogue and price imports) read the body themselves
(``api/uploads.py``) and check their own media types, with :func:`unsupported_media_type`.
"""

from __future__ import annotations

import json
from email.message import Message
from functools import lru_cache

from fastapi import Request

from actuator_selection.http.errors import UnsupportedMediaTypeError, service_error

JSON_MEDIA_TYPE = "application/json"
UTF8 = ("utf-8", "utf8")
"""The ``charset`` values a JSON body may declare (``json.detect_encoding`` reads a
UTF-8 byte-order mark as UTF-8 too)."""
_LOC: list[str | int] = ["header", "Content-Type"]
_TYPE = "unsupported_media_type"


def unsupported_media_type(given: str, accepted: tuple[str, ...]) -> UnsupportedMediaTypeError:
    """415 naming the media type sent (``given``, empty: none) and those ``accepted``."""
    send = " | ".join(accepted)
    entry = (
        service_error(_LOC, _TYPE, "unsupported_media_type", given=given, accepted=send)
        if given
        else service_error(_LOC, _TYPE, "media_type_missing", accepted=send)
    )
    return UnsupportedMediaTypeError([entry])


def _is_json(media_type: str) -> bool:
    main, _, sub = media_type.partition("/")
    return main == "application" and (sub == "json" or sub.endswith("+json"))


@lru_cache(maxsize=64)
def _content_type(header: str) -> tuple[str, str | None]:
    """A ``Content-Type`` header's media type (empty: none) and ``charset`` (lower case,
    None: none), as the standard library's e-mail parser reads them. Clients send one or
    two headers over and over: they are parsed once (a bounded cache)."""
    if not header.strip():
        return "", None
    message = Message()
    message["content-type"] = header
    charset = message.get_param("charset")
    return message.get_content_type(), charset.lower() if isinstance(charset, str) else None


async def require_json_body(request: Request) -> None:
    """415 when the endpoint parses a JSON body and the request's is not UTF-8 JSON."""
    route = request.scope.get("route")
    if getattr(route, "body_field", None) is None or getattr(route, "is_body_form", False):
        return
    body = await request.body()  # FastAPI has read it already (the same Request)
    if not body:
        return  # nothing to parse: the endpoint's validation names a missing body
    media_type, declared = _content_type(request.headers.get("content-type", ""))
    if not _is_json(media_type):
        raise unsupported_media_type(media_type, (JSON_MEDIA_TYPE,))
    detected = json.detect_encoding(body[:4])
    encoding = declared if declared not in (None, *UTF8) else detected
    if encoding not in (*UTF8, "utf-8-sig"):
        entry = service_error(_LOC, _TYPE, "unsupported_charset", charset=encoding)
        raise UnsupportedMediaTypeError([entry])
