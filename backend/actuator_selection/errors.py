"""Domain errors raised by the core.

Each error names the input ``field`` it concerns (dotted, as in the API's request
body where there is one, or in the path or query where ``where`` says so) and
carries a message an engineer understands. Each kind carries the HTTP status it
answers with (``http_status``); one handler in ``http/errors.py`` writes the answer.

An error raised with a ``code`` (a rule of ``phrases/messages.py``) takes its message from
that rule's template and its ``params``; the API sends code and params beside the text
and renders the text in the request's language. An error raised with a message alone
has no template: its text stays English, and its code is its type.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any, Self

from actuator_selection.phrases.messages import MESSAGES, english


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
    code
        The rule broken, a key of ``phrases.messages.MESSAGES``: its template is the
        message (``message`` is then left out).
    params
        The values the template names (``{"max": 200}``).

    >>> str(InvalidInputError("segments", code="segments_too_many", params={"max": 200}))
    'segments: must hold at most 200 segments'
    """

    http_status = 422
    error_type: str | None = None
    """The error's ``type`` in the API; None: the class name."""

    def __init__(
        self,
        field: str,
        message: str | None = None,
        *,
        where: str = "body",
        code: str | None = None,
        params: Mapping[str, Any] | None = None,
    ) -> None:
        self.template: str | None = None
        self.params: dict[str, Any] = dict(params or {})
        if message is None:
            if code is None:
                raise TypeError("a DomainError needs a message or a code")
            self.template = MESSAGES[code]
            message = english(self.template, self.params)
        super().__init__(f"{field}: {message}")
        self.field = field
        self.message = message
        self.where = where
        self.code = code

    def moved(self, field: str) -> Self:
        """The same error naming ``field`` (a core input's name as the request has it)."""
        moved = type(self).__new__(type(self))
        moved.__dict__.update(self.__dict__)
        moved.field = field
        moved.args = (f"{field}: {self.message}",)
        return moved


class InvalidInputError(DomainError):
    """A value outside the domain of an equation (maps to 422)."""


class OutOfRangeError(InvalidInputError):
    """A value outside the range a published table or characteristic covers (maps to 422)."""


class NotFoundError(DomainError):
    """A named item that does not exist (maps to 404)."""

    http_status = 404
    error_type = "not_found"


class ConflictError(DomainError):
    """A request that the stored state no longer allows (maps to 409)."""

    http_status = 409
    error_type = "conflict"


class MissingDataError(DomainError):
    """The catalogue has no published value that a calculation needs (maps to 422).

    The service says "no data" rather than guessing a number.
    """
