"""Errors a use case finds in a request: one or more entries of the one error shape.

A use case knows no HTTP, but it knows which rule a request breaks and where: each
entry names its place (``loc``: ``["body", "actuator", "model"]``, ``["path",
"number"]``, ``["header", "Idempotency-Key"]``), the rule in words (``msg``) and for
programs (``type``); where the rule is the service's own, also its code and params
(``services/messages.py``), so that the API words it in the request's language. Like
the core's domain errors (a :class:`DomainError` subclass, so the one handler of
``http/errors.py`` answers it), it carries its status: 422 for a request that breaks a
rule, 404 for an unknown resource, 409 for a state that does not allow the request.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from actuator_selection.catalogue.csvio import CatalogueFileError, Problem
from actuator_selection.errors import DomainError
from actuator_selection.phrases.messages import english
from actuator_selection.services.messages import USE_CASE_MESSAGES

Loc = list[str | int]


def entry(loc: Loc, type_: str, code: str, **params: Any) -> dict[str, Any]:
    """One entry of an error answer: the rule ``code`` (a key of ``USE_CASE_MESSAGES``)
    over ``params``. ``msg`` is its English text; the API renders the template in the
    request's language (the private key ``_template``)."""
    template = USE_CASE_MESSAGES[code]
    return {
        "loc": loc,
        "msg": english(template, params),
        "type": type_,
        "code": code,
        "params": params,
        "_template": template,
    }


def ruled(loc: Loc, exc: DomainError, type_: str) -> dict[str, Any]:
    """The entry of a core rule broken at ``loc``: its code, params and template where the
    core names the rule by code, else its text as it is (:func:`worded`)."""
    if exc.template is None or exc.code is None:
        return worded(loc, exc.message, type_)
    return {
        "loc": loc,
        "msg": exc.message,
        "type": type_,
        "code": exc.code,
        "params": exc.params,
        "_template": exc.template,
    }


def worded(loc: Loc, msg: str, type_: str) -> dict[str, Any]:
    """An entry in words found elsewhere (a file's problem, the core's free text): ``msg``
    as it is, in English."""
    return {"loc": loc, "msg": msg, "type": type_}


class UseCaseError(DomainError):
    """What is wrong with a request, as entries of the error shape, with its status."""

    def __init__(self, entries: Sequence[dict[str, Any]], *, http_status: int = 422) -> None:
        first = entries[0]
        where, *field = first["loc"]
        super().__init__(".".join(str(f) for f in field), first["msg"], where=str(where))
        self.entries = list(entries)
        self.http_status = http_status
        self.error_type = first["type"]


def invalid(loc: Loc, code: str, type_: str | None = None, **params: Any) -> UseCaseError:
    """422: the request breaks the rule ``code`` at ``loc`` (its ``type``: ``type_``, else
    the code)."""
    return UseCaseError([entry(loc, type_ or code, code, **params)])


def not_found(loc: Loc, code: str, **params: Any) -> UseCaseError:
    """404: the resource named at ``loc`` does not exist (``type`` ``not_found``)."""
    return UseCaseError([entry(loc, "not_found", code, **params)], http_status=404)


def conflict(loc: Loc, code: str, type_: str, **params: Any) -> UseCaseError:
    """409: the stored state does not allow the request."""
    return UseCaseError([entry(loc, type_, code, **params)], http_status=409)


def invalid_rule(loc: Loc, exc: DomainError, type_: str) -> UseCaseError:
    """422: the request breaks the core's rule ``exc`` at ``loc`` (:func:`ruled`)."""
    return UseCaseError([ruled(loc, exc, type_)])


def conflict_rule(loc: Loc, exc: DomainError, type_: str) -> UseCaseError:
    """409: the stored state does not allow the request by the core's rule ``exc``."""
    return UseCaseError([ruled(loc, exc, type_)], http_status=409)


def problem_entry(problem: Problem) -> dict[str, Any]:
    """One entry of a 422 body for a catalogue or price file problem."""
    loc: Loc = ["body", problem.file, problem.line]
    if problem.column:
        loc.append(problem.column)
    return {
        "loc": loc,
        "msg": str(problem),
        "type": "invalid_file",
        "file": problem.file,
        "line": problem.line,
        "column": problem.column,
    }


def file_problems(exc: CatalogueFileError) -> UseCaseError:
    """The 422 for every problem of a file."""
    return UseCaseError([problem_entry(p) for p in exc.problems])
