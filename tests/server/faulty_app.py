"""The service with one route that fails unexpectedly, served by the real server in a test."""

from __future__ import annotations

from fastapi.routing import APIRoute

from actuator_selection.app import create_app

app = create_app()


def deliberate_fault() -> None:
    """Fails as a bug would."""
    raise RuntimeError("a deliberate fault of the test app")


# Ahead of the catch-all mount of the static page.
app.router.routes.insert(0, APIRoute("/api/v1/deliberate-fault", deliberate_fault))
