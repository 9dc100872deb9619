"""A flowchart check as the API reports it."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from actuator_selection.core.selection import Check
from actuator_selection.schemas.common import ResponseModel


class CheckOut(ResponseModel):
    """One step of the flowchart; ``value ≤ limit`` passes."""

    name: str
    status: Literal["pass", "fail", "warn", "no_data"]
    value: float | None
    limit: float | None
    unit: str
    reference: str = Field(description="the chapter's equation, table or figure")
    message: str
    approximate: bool = Field(description="true when a simplified limit stood in for the zone")
    margin_percent: float | None = Field(description="(limit − value)/limit · 100")
    utilisation: float | None = Field(
        description="value/limit: the share of the limit used, > 1 when it is exceeded"
    )

    @classmethod
    def from_core(cls, check: Check) -> CheckOut:
        """The response body of one check."""
        return cls(
            name=check.name,
            status=check.status.value,
            value=check.value,
            limit=check.limit,
            unit=check.unit,
            reference=check.reference,
            message=check.message,
            approximate=check.approximate,
            margin_percent=check.margin_percent,
            utilisation=check.utilisation,
        )
