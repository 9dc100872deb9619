"""Domain errors raised by the core.

Each error names the input ``field`` it concerns (dotted, as in the API's request
body where there is one) and carries a message an engineer understands. The API
maps them to HTTP status codes in one place (``api/errors.py``); the core never
knows about HTTP.
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
    """

    def __init__(self, field: str, message: str) -> None:
        super().__init__(f"{field}: {message}")
        self.field = field
        self.message = message


class InvalidInputError(DomainError):
    """A value outside the domain of an equation (maps to 422)."""


class OutOfRangeError(InvalidInputError):
    """A value outside the range a published table or characteristic covers (maps to 422)."""


class NotFoundError(DomainError):
    """A named catalogue item that does not exist (maps to 404)."""


class MissingDataError(DomainError):
    """The catalogue has no published value that a calculation needs (maps to 422).

    The service says "no data" rather than guessing a number.
    """
