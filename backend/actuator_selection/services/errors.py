"""Errors a use case finds in a request: one or more entries of the one error shape.

A use case knows no HTTP, but it knows which rule a request breaks and where: each
entry names its place (``loc``: ``["body", "actuator", "model"]``, ``["path",
"number"]``, ``["header", "Idempotency-Key"]``), the rule in words (``msg``) and for
programs (``type``); where the rule is the service's own, also its code and params
(``services/messages.py``), so that the API words it in the request's language. Like
the core's domain errors (a :class:`DomainError` subclass, so the one handler of
``api/errors.py`` answers it), it carries its status: 422 for a request that breaks a
rule, 404 for an unknown resource, 409 for a state that does not allow the request.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from actuator_selection.core.csvio import CatalogueFileError, Problem
from actuator_selection.core.errors import DomainError
from actuator_selection.services.messages import USE_CASE_MESSAGES

Loc = list[str | int]


def entry(loc: Loc, type_: str, code: str, **params: Any) -> dict[str, Any]:
    """One entry of an error answer: the rule ``code`` (a key of ``USE_CASE_MESSAGES``)
    over ``params``. ``msg`` is its English text; the API renders the template in the
    request's language (the private key ``_template``)."""
    template = USE_CASE_MESSAGES[code]
    shown = {k: listed(v) if isinstance(v, list) else v for k, v in params.items()}
    return {
        "loc": loc,
        "msg": template.format_map(shown),
        "type": type_,
        "code": code,
        "params": params,
        "_template": template,
    }


def listed(values: Sequence[object], shown: Callable[[Any], str] = str) -> str:
    """A list as a message shows it: words quoted, other values as ``shown`` writes them,
    no value as a dash.

    >>> listed(["EUR", "USD"]), listed([3, 7]), listed([])
    ("'EUR', 'USD'", '3, 7', '–')
    """
    return ", ".join(f"'{v}'" if isinstance(v, str) else shown(v) for v in values) or "–"


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


def invalid_worded(loc: Loc, msg: str, type_: str) -> UseCaseError:
    """422 in words found elsewhere (:func:`worded`)."""
    return UseCaseError([worded(loc, msg, type_)])


def conflict_worded(loc: Loc, msg: str, type_: str) -> UseCaseError:
    """409 in words found elsewhere (:func:`worded`)."""
    return UseCaseError([worded(loc, msg, type_)], http_status=409)


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
