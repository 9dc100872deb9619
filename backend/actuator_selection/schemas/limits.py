"""The inverse solve's contract: how far a load case may go for one actuator."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import ConfigDict, Field

from actuator_selection.schemas.common import ResponseModel
from actuator_selection.schemas.selections import (
    WORKED_EXAMPLE,
    ModelName,
    SelectionRequest,
)


class LimitsRequest(SelectionRequest):
    """A load case and the actuator to solve it for (``models`` is not used here)."""

    model_config = ConfigDict(
        json_schema_extra={"examples": [WORKED_EXAMPLE | {"model": "FHA-25C-50-L"}]}
    )

    model: ModelName = Field(description="the actuator, as the catalogue names it")


class LimitingCheck(ResponseModel):
    """A check that fails just beyond the limit, with its reference and its message there."""

    name: str
    reference: str
    message: str = Field(description="the check in words there, in the answer's language")
    message_code: str | None = Field(
        default=None, description="stable code of the message, as a check's `message_code`"
    )
    message_params: dict[str, Any] | None = Field(
        default=None, description="the values the message names, as a check's `message_params`"
    )


class LimitOut(ResponseModel):
    """How far one quantity may go with every check passing (or lacking data)."""

    quantity: Literal["pause_s", "accel_s", "load_inertia_kgm2"] = Field(
        description="t_p (the last dwell of a cycle of segments), t_1, or J_L at the output"
    )
    bound: Literal["min", "max"]
    value: float | None = Field(
        description="the shortest (min) or largest (max) value with no check failing; null "
        "where a check fails at every value searched"
    )
    unit: str
    verdict: Literal["suitable", "unconfirmed", "unsuitable"] | None = Field(
        description="the flowchart's verdict at the limit: unconfirmed where a check lacks data"
    )
    limiting_checks: list[LimitingCheck] = Field(
        description="the checks that fail just beyond the limit"
    )
    note: str
    reason: str | None = Field(
        default=None,
        description="why `value` is null, in the answer's language (null where it is not)",
    )
    reason_code: str | None = Field(
        default=None,
        description="stable code of `reason`: limit.none.min (a check still fails at the "
        "range's far end), limit.none.max (a check fails already at its start) or "
        "limit.accel_no_ramp (the cycle has no t_1: it does not start with an acceleration "
        "from standstill)",
    )
    reason_params: dict[str, Any] | None = Field(
        default=None, description="the values `reason` names, as a check's `message_params`"
    )


class LimitsOut(ResponseModel):
    """The limits of a load case for one actuator, found over the same rules as a selection."""

    model: str
    catalogue_version: int
    limits: list[LimitOut]
