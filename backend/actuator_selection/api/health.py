"""Liveness with a database round trip."""

from __future__ import annotations

from fastapi import APIRouter
from sqlalchemy import text

from actuator_selection.api.deps import SessionDep

router = APIRouter(tags=["health"])


@router.get("/health")
def health(session: SessionDep) -> dict[str, str]:
    """``{"status": "ok"}`` once the database has answered a query."""
    session.execute(text("SELECT 1"))
    return {"status": "ok"}
