"""Domain errors raised by the core.

Each error names the input ``field`` it concerns (dotted, as in the API's request
body where there is one, or in the path or query where ``where`` says so) and
carries a message an engineer understands. Each kind carries the HTTP status it
answers with (``http_status``); one handler in ``api/errors.py`` writes the answer.
"""

from __future__ import annotations


class DomainError(ValueError):
    """An input that the engineering cannot work with.

    Parameters
    ----------
    field
        Dotted name of the offending input, e.g. ``"cycle.accel_s"``.
    message
        What rule the input breaks and why the rule exists.
    where
        Which part of a request holds the field: ``body``, ``path`` or ``query``.
    """

    http_status = 422
    code: str | None = None
    """The error's ``type`` in the API; None: the class name."""

    def __init__(self, field: str, message: str, *, where: str = "body") -> None:
        super().__init__(f"{field}: {message}")
        self.field = field
        self.message = message
        self.where = where


class InvalidInputError(DomainError):
    """A value outside the domain of an equation (maps to 422)."""


class OutOfRangeError(InvalidInputError):
    """A value outside the range a published table or characteristic covers (maps to 422)."""


class NotFoundError(DomainError):
    """A named item that does not exist (maps to 404)."""

    http_status = 404
    code = "not_found"


class ConflictError(DomainError):
    """A request that the stored state no longer allows (maps to 409)."""

    http_status = 409
    code = "conflict"


class MissingDataError(DomainError):
    """The catalogue has no published value that a calculation needs (maps to 422).

    The service says "no data" rather than guessing a number.
    """
