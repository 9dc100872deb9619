"""Who is calling: the API key's public identity, never its secret."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from actuator_selection.schemas.common import ResponseModel


class PrincipalOut(ResponseModel):
    """The caller as the service sees it; anonymous callers have no key."""

    authenticated: bool
    key_id: str | None = Field(description="the key's public prefix, as `keys list` shows it")
    name: str | None
    role: Literal["admin", "sales"] | None
    require_api_key: bool = Field(description="true when every endpoint needs a key")
