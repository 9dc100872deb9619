"""The answers of ``/health`` and ``/health/ready`` (a 503 has the one error shape)."""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict


class HealthOut(BaseModel):
    """The process answers and its database has answered a query."""

    model_config = ConfigDict(extra="forbid")

    status: Literal["ok"]


class ReadyOut(BaseModel):
    """This process can serve requests: send it traffic."""

    model_config = ConfigDict(extra="forbid")

    status: Literal["ready"]
