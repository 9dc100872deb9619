"""A flowchart check as the API reports it."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Literal

from pydantic import Field

from actuator_selection.phrases.check_messages import Phrase, jsonable_params
from actuator_selection.schemas.common import ResponseModel
from actuator_selection.sizing.selection import Check

Localize = Callable[[str], str]
"""A check's message in the answer's language (``i18n.localize.render_check``)."""


def english(message: str) -> str:
    """The message as the core words it (English)."""
    return message


def message_code(message: str) -> str | None:
    """The stable code of a check's message; None for free text (a rule without codes)."""
    return message.code if isinstance(message, Phrase) else None


CheckStatus = Literal["pass", "fail", "warn", "no_data", "not_applicable"]
"""A check's status (``sizing.checks.Status``): ``no_data`` where a catalogue value it needs
is not published, ``not_applicable`` where its premise does not hold for the actuator or
the case (it neither passes nor fails the verdict; docs/decisions/0025)."""


class CheckOut(ResponseModel):
    """One step of the flowchart; ``value ≤ limit`` passes."""

    name: str
    status: CheckStatus
    value: float | None
    limit: float | None
    unit: str
    reference: str = Field(description="the chapter's equation, table or figure")
    message: str = Field(
        description="the check in words, in the answer's language (Content-Language)"
    )
    message_code: str | None = Field(
        default=None,
        description="stable code of the message (e.g. `peak_torque.pass`), the same in every "
        "language; null for a rule without one",
    )
    message_params: dict[str, Any] | None = Field(
        default=None,
        description="the values the message names, the same in every language: numbers "
        "(`value`, `limit` in the check's unit, others with their unit in the name), words "
        "(English), clauses as `{code, params}`; null where `message_code` is",
    )
    approximate: bool = Field(description="true when a simplified limit stood in for the zone")
    margin_percent: float | None = Field(description="(limit − value)/limit · 100")
    utilisation: float | None = Field(
        description="value/limit: the share of the limit used, > 1 when it is exceeded"
    )

    @classmethod
    def from_core(cls, check: Check, localize: Localize = english) -> CheckOut:
        """The response body of one check, its message in words by ``localize``."""
        return cls(
            name=check.name,
            status=check.status.value,
            value=check.value,
            limit=check.limit,
            unit=check.unit,
            reference=check.reference,
            message=localize(check.message),
            message_code=message_code(check.message),
            message_params=jsonable_params(check.message),
            approximate=check.approximate,
            margin_percent=check.margin_percent,
            utilisation=check.utilisation,
        )
