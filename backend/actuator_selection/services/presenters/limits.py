"""The limits' answer (``LimitsOut``): how far t_p, t_1 and J_L may go for one actuator."""

from __future__ import annotations

from typing import Any

from actuator_selection.phrases.check_messages import jsonable_params
from actuator_selection.schemas.checks import Localize, english, message_code
from actuator_selection.schemas.limits import LimitsOut
from actuator_selection.sizing.checks import rules_for
from actuator_selection.sizing.inverse import Limit
from actuator_selection.sizing.selection import Application


def limits_answer(
    *,
    model: str,
    catalogue_version: int,
    app: Application,
    found: tuple[Limit, ...],
    localize: Localize = english,
) -> LimitsOut:
    """The answer from the core's limits; references from the application's rules;
    messages in words by ``localize``."""
    reference = {rule.name: rule.reference for rule in rules_for(app)}
    out: list[dict[str, Any]] = [
        {
            "quantity": limit.quantity,
            "bound": limit.bound,
            "value": limit.value,
            "unit": limit.unit,
            "verdict": None if limit.verdict is None else limit.verdict.value,
            "limiting_checks": [
                {
                    "name": name,
                    "reference": reference.get(name, ""),
                    "message": localize(message),
                    "message_code": message_code(message),
                    "message_params": jsonable_params(message),
                }
                for name, message in zip(limit.limiting_checks, limit.messages, strict=True)
            ],
            "note": limit.note,
            "reason": None if limit.reason is None else localize(limit.reason),
            "reason_code": None if limit.reason is None else message_code(limit.reason),
            "reason_params": None if limit.reason is None else jsonable_params(limit.reason),
        }
        for limit in found
    ]
    return LimitsOut.model_validate(
        {"model": model, "catalogue_version": catalogue_version, "limits": out}
    )
