"""Errors a use case finds in a request: one or more entries of the one error shape.

A use case knows no HTTP, but it knows which rule a request breaks and where: each
entry names its place (``loc``: ``["body", "actuator", "model"]``, ``["path",
"number"]``, ``["header", "Idempotency-Key"]``), the rule in words (``msg``) and for
programs (``type``). Like the core's domain errors (a :class:`DomainError` subclass,
so the one handler of ``api/errors.py`` answers it), it carries its status: 422 for
a request that breaks a rule, 404 for an unknown resource, 409 for a state that
does not allow the request.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from actuator_selection.core.csvio import CatalogueFileError, Problem
from actuator_selection.core.errors import DomainError

Loc = list[str | int]


def entry(loc: Loc, msg: str, type_: str) -> dict[str, Any]:
    """One entry of an error answer."""
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

    @classmethod
    def at(cls, loc: Loc, msg: str, type_: str, *, http_status: int = 422) -> UseCaseError:
        """The error with one entry."""
        return cls([entry(loc, msg, type_)], http_status=http_status)


def invalid(loc: Loc, msg: str, type_: str) -> UseCaseError:
    """422: the request breaks the rule ``type_`` at ``loc``."""
    return UseCaseError.at(loc, msg, type_)


def not_found(loc: Loc, msg: str) -> UseCaseError:
    """404: the resource named at ``loc`` does not exist."""
    return UseCaseError.at(loc, msg, "not_found", http_status=404)


def conflict(loc: Loc, msg: str, type_: str) -> UseCaseError:
    """409: the stored state does not allow the request."""
    return UseCaseError.at(loc, msg, type_, http_status=409)


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
