"""Fixtures of the sales tests (auth, admin, prices, quotes): the app with API keys and prices.

Requests run in the test's rolled-back transaction, as with ``tests/conftest.py``'s
``client``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from datetime import UTC, date, datetime, timedelta
from typing import Any

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from sqlalchemy import Connection, Engine
from sqlalchemy.orm import Session, sessionmaker
from tests import worked_example

from actuator_selection.api.quotes import Clock, get_clock
from actuator_selection.app import create_app
from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.sales import ApiKeyRepository, PriceRepository, parse_prices

EXAMPLE_PRICE_LIST = "EXAMPLE — not real prices"

WORKED_EXAMPLE: dict[str, Any] = {**worked_example.request(), "high_dynamics": True}
"""The chapter's worked example (Table 516.1), without a model restriction."""


class FakeClock(Clock):
    """A clock the test moves: starts now (UTC), ``advance`` steps forward."""

    def __init__(self) -> None:
        self.current = datetime.now(UTC)

    def now(self) -> datetime:
        return self.current

    def advance(self, days: int) -> None:
        """Move the clock ``days`` forward."""
        self.current += timedelta(days=days)


@dataclass
class SalesApi:
    """A client of the wired app, API keys of each role, and the app's clock."""

    client: TestClient
    keys: dict[str, str]
    clock: FakeClock
    key_ids: dict[str, str] = field(default_factory=dict)

    def headers(self, role: str | None, **extra: str) -> dict[str, str]:
        """Headers with the ``role``'s key (None: anonymous)."""
        out = dict(extra)
        if role is not None:
            out["Authorization"] = f"Bearer {self.keys[role]}"
        return out

    def get(self, path: str, role: str | None = "sales", **kwargs: Any) -> Any:
        return self.client.get(path, headers=self.headers(role), **kwargs)

    def post(
        self,
        path: str,
        role: str | None = "sales",
        extra: dict[str, str] | None = None,
        **kw: Any,
    ) -> Any:
        return self.client.post(path, headers=self.headers(role, **(extra or {})), **kw)

    def selection(self, models: list[str] | None = None, **changes: Any) -> dict[str, Any]:
        """A stored selection of the worked example (anonymous, as an engineer would)."""
        body = {**WORKED_EXAMPLE, **changes}
        if models is not None:
            body["models"] = models
        response = self.client.post("/api/v1/selections", json=body)
        assert response.status_code == 201, response.text
        result: dict[str, Any] = response.json()
        return result

    def quote_body(self, selection_id: str, /, **changes: Any) -> dict[str, Any]:
        """A valid quote request for the worked example's FHA-25C-50-L."""
        body: dict[str, Any] = {
            "selection_id": selection_id,
            "customer": {"name": "Muster GmbH", "address": "Hauptstr. 1\n12345 Musterstadt"},
            "actuator": {"model": "FHA-25C-50-L", "quantity": 2},
            "controller": {
                "type_name": "SINAMICS S120, 400 V",
                "item_code": "CTRL-SINAMICS-S120",
                "quantity": 2,
            },
            "price_list": EXAMPLE_PRICE_LIST,
            "discount_percent": "7.5",
            "valid_until": (self.clock.now().date() + timedelta(days=30)).isoformat(),
        }
        body.update(changes)
        return body


def create_keys(session: Session) -> tuple[dict[str, str], dict[str, str]]:
    """One key per role plus a revoked sales key; returns keys and their public ids."""
    repository = ApiKeyRepository(session)
    now = datetime.now(UTC)
    keys: dict[str, str] = {}
    ids: dict[str, str] = {}
    for role in ("admin", "sales"):
        record, key = repository.create(name=f"test {role}", role=role, now=now)
        keys[role], ids[role] = key, record.prefix
    record, key = repository.create(name="revoked", role="sales", now=now)
    repository.revoke(record.prefix, now=now)
    keys["revoked"], ids["revoked"] = key, record.prefix
    return keys, ids


def load_example_prices(session: Session) -> None:
    """The starter data's example price list."""
    text = (SEED_DIR / "example_prices.csv").read_text(encoding="utf-8")
    PriceRepository(session).replace(parse_prices(text), now=datetime.now(UTC))


def sales_api_factory(
    seeded_engine: Engine, connection: Connection
) -> Iterator[Callable[..., SalesApi]]:
    """Factory of ``SalesApi`` for given settings, all on the test's connection."""
    with Session(bind=connection, join_transaction_mode="create_savepoint") as session:
        keys, ids = create_keys(session)
        load_example_prices(session)
        session.commit()
    clients: list[TestClient] = []
    apps: list[FastAPI] = []

    def make(**settings: Any) -> SalesApi:
        url = seeded_engine.url.render_as_string(hide_password=False)
        app = create_app(Settings(database_url=url, **settings))
        app.state.session_factory = sessionmaker(
            bind=connection, join_transaction_mode="create_savepoint", expire_on_commit=False
        )
        clock = FakeClock()
        app.dependency_overrides[get_clock] = lambda: clock
        client = TestClient(app, raise_server_exceptions=False)
        client.__enter__()
        clients.append(client)
        apps.append(app)
        return SalesApi(client=client, keys=keys, clock=clock, key_ids=ids)

    yield make
    for client in clients:
        client.__exit__(None, None, None)
    for app in apps:
        app.state.engine.dispose()


@pytest.fixture
def sales_api_with(
    seeded_engine: Engine, connection: Connection
) -> Iterator[Callable[..., SalesApi]]:
    """``sales_api_with(require_api_key=True)`` etc.: the wired app for other settings."""
    yield from sales_api_factory(seeded_engine, connection)


@pytest.fixture
def api(sales_api_with: Callable[..., SalesApi]) -> SalesApi:
    """The wired app with default settings (anonymous catalogue reads allowed)."""
    return sales_api_with()


def today_plus(days: int) -> str:
    """An ISO date ``days`` from today (UTC)."""
    return (datetime.now(UTC).date() + timedelta(days=days)).isoformat()


def iso(d: date) -> str:
    """``d`` as YYYY-MM-DD."""
    return d.isoformat()
