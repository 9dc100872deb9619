"""Liveness and readiness, each with a database round trip.

While the database cannot be reached both answer 503 with ``Retry-After`` in the
error shape, the entry naming the dependency that is down (``code``
``database_unreachable``, ``params.dependency``), and both answer again as soon as it
is back (``db.availability``).
"""

from __future__ import annotations

from typing import Any

from fastapi import APIRouter
from sqlalchemy import text

from actuator_selection.http.deps import SessionDep
from actuator_selection.schemas.health import HealthOut, ReadyOut

router = APIRouter(tags=["health"])

_DOWN: dict[int | str, dict[str, Any]] = {
    503: {
        "description": "the database is unreachable (`database_unreachable`, "
        "`params.dependency`), or the service is at capacity; with Retry-After"
    }
}


@router.get("/health", responses=_DOWN)
def health(session: SessionDep) -> HealthOut:
    """``{"status": "ok"}`` once the database has answered a query."""
    session.execute(text("SELECT 1"))
    return HealthOut(status="ok")


@router.get("/health/ready", responses=_DOWN)
def readiness(session: SessionDep) -> ReadyOut:
    """Readiness for a load balancer or proxy: 200 ``{"status": "ready"}`` when this
    process can serve requests (the database has answered a query), else 503. Send
    traffic elsewhere while it answers 503; it turns 200 by itself when the database is
    back, without a restart."""
    session.execute(text("SELECT 1"))
    return ReadyOut(status="ready")
