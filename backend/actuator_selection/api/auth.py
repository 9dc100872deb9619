"""``GET /auth/me``: who the caller is. The API keys themselves, their roles and the
dependencies that admit them, live with the rest the routes share (``http/auth.py``)."""

from __future__ import annotations

from typing import Annotated, Literal, cast

from fastapi import APIRouter, Depends, Request

from actuator_selection.http.auth import request_settings, require_reader
from actuator_selection.sales.records import ApiKeyRecord
from actuator_selection.schemas.auth import PrincipalOut

router = APIRouter(tags=["auth"])


@router.get("/auth/me", responses={401: {"description": "a bad API key"}})
def who_am_i(
    request: Request, principal: Annotated[ApiKeyRecord | None, Depends(require_reader)]
) -> PrincipalOut:
    """The caller's key (its public id, name and role), or anonymous."""
    return PrincipalOut(
        authenticated=principal is not None,
        key_id=principal.prefix if principal else None,
        name=principal.name if principal else None,
        role=cast(Literal["admin", "sales"], principal.role) if principal else None,
        require_api_key=request_settings(request).require_api_key,
    )
