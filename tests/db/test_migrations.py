"""The Alembic migrations build the schema from an empty database, on both backends."""

from __future__ import annotations

import gzip
import json
from collections.abc import Callable
from datetime import UTC, date, datetime
from decimal import Decimal
from pathlib import Path
from typing import Any

from alembic import command
from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext
from sqlalchemy import (
    JSON,
    Date,
    DateTime,
    Numeric,
    column,
    insert,
    inspect,
    select,
    table,
    text,
)
from sqlalchemy.orm import Session

from actuator_selection.db.engine import make_engine
from actuator_selection.db.migrate import alembic_config, ours, upgrade
from actuator_selection.db.models import Base
from actuator_selection.db.sales import QuoteRepository

LEAN_ANSWER = json.dumps(
    json.loads((Path(__file__).parent / "data" / "selection_answers_v1.json").read_bytes())[
        "cases"
    ]["worked_example"]["answer"]
).encode()
"""A stored answer as the lean code of 2026-11-23 wrote it (``test_answer_upgrade.py``)."""


def test_upgrade_from_empty_creates_every_table(
    backend: str, new_database: Callable[[str], str]
) -> None:
    url = new_database(backend)
    upgrade(url=url)
    engine = make_engine(url)
    try:
        tables = set(inspect(engine).get_table_names())
        assert set(Base.metadata.tables) <= tables
        assert "alembic_version" in tables
        with engine.connect() as conn:
            context = MigrationContext.configure(conn, opts={"include_name": ours})
            diff = compare_metadata(context, Base.metadata)
        assert diff == [], f"models and migrations disagree: {diff}"
    finally:
        engine.dispose()


def test_downgrade_to_base_and_up_again(backend: str, new_database: Callable[[str], str]) -> None:
    url = new_database(backend)
    upgrade(url=url)
    command.downgrade(alembic_config(url=url), "base")
    engine = make_engine(url)
    try:
        assert set(inspect(engine).get_table_names()) <= {"alembic_version"}
    finally:
        engine.dispose()
    upgrade(url=url)


def test_stored_selections_keep_their_answer_across_0005(
    backend: str, new_database: Callable[[str], str]
) -> None:
    """A selection stored as JSON before 0005 is the same answer, compressed, after it, and
    JSON again after a downgrade."""
    url = new_database(backend)
    config = alembic_config(url=url)
    command.upgrade(config, "0004")
    answer = {"id": "s-1", "candidates": [{"model": "CHA-25A-50", "verdict": "suitable"}]}
    engine = make_engine(url)
    old = table("selections", column("id"), column("created_at"), column("catalogue_version"),
                column("request", JSON), column("response", JSON))  # fmt: skip
    try:
        with engine.begin() as conn:
            conn.execute(
                insert(old).values(
                    id="s-1",
                    created_at=datetime(2026, 11, 1, tzinfo=UTC),
                    catalogue_version=1,
                    request={"load": {}},
                    response=answer,
                )
            )
        command.upgrade(config, "0005")
        with engine.connect() as conn:
            stored = conn.execute(text("SELECT answer_gzip FROM selections")).scalar_one()
        assert json.loads(gzip.decompress(stored)) == answer
        command.downgrade(config, "0004")
        with engine.connect() as conn:
            back = conn.execute(select(old.c.response)).scalar_one()
        assert back == answer
    finally:
        engine.dispose()


def test_quotes_made_before_0008_keep_their_figures_and_read_without_terms(
    backend: str, new_database: Callable[[str], str]
) -> None:
    """A quote stored before 0008 reads after it with no VAT, terms or seller (all NULL),
    its net figures unchanged; a downgrade drops the new columns and keeps the quote."""
    url = new_database(backend)
    config = alembic_config(url=url)
    command.upgrade(config, "0007")
    now = datetime(2026, 11, 20, tzinfo=UTC)
    engine = make_engine(url)
    api_keys = table("api_keys", column("id"), column("prefix"), column("key_sha256"),
                     column("name"), column("role"), column("created_at"))  # fmt: skip
    selections = table("selections", column("id"), column("created_at"),
                       column("catalogue_version"), column("request", JSON),
                       column("answer_gzip"))  # fmt: skip
    old_quote = {
        "id": 1, "number": "Q-2026-00001", "year": 2026, "sequence": 1, "status": "sent",
        "created_at": now, "status_changed_at": now, "valid_until": date(2026, 12, 31),
        "api_key_id": 1, "idempotency_key": None, "request_sha256": "0" * 64,
        "selection_id": "s-1", "selection_catalogue_version": 1, "catalogue_version": 1,
        "customer_name": "Muster GmbH", "customer_address": None, "customer_reference": None,
        "notes": None, "actuator_model": "FHA-25C-50-L", "verdict": "suitable",
        "verdict_reasons": [], "actuator_snapshot": {"model": "FHA-25C-50-L"},
        "price_list_name": "list", "price_list_is_example": False,
        "price_date": date(2026, 11, 20), "currency": "EUR", "subtotal": Decimal("2950.00"),
        "discount_percent": Decimal("0.00"), "discount_amount": Decimal("0.00"),
        "total": Decimal("2950.00"),
    }  # fmt: skip
    types: dict[str, Any] = {
        "verdict_reasons": JSON(),
        "actuator_snapshot": JSON(),
        "created_at": DateTime(timezone=True),
        "status_changed_at": DateTime(timezone=True),
        "valid_until": Date(),
        "price_date": Date(),
        **{name: Numeric(14, 2) for name in ("subtotal", "discount_amount", "total")},
        "discount_percent": Numeric(5, 2),
    }
    quotes = table("quotes", *(column(name, types.get(name)) for name in old_quote))
    try:
        with engine.begin() as conn:
            conn.execute(
                insert(api_keys).values(
                    id=1, prefix="p", key_sha256="0" * 64, name="k", role="sales", created_at=now
                )
            )
            conn.execute(
                insert(selections).values(
                    id="s-1",
                    created_at=now,
                    catalogue_version=1,
                    request={},
                    answer_gzip=gzip.compress(LEAN_ANSWER),
                )
            )
            conn.execute(insert(quotes).values(**old_quote))
        # read by today's repository, so at head (0016 added the quotes' project columns)
        command.upgrade(config, "head")
        with Session(engine) as session:
            record = QuoteRepository(session).by_number("Q-2026-00001")
        assert record is not None
        assert (record.tax, record.seller, record.payment_terms, record.delivery_terms) == (
            None,
            None,
            None,
            None,
        )
        assert (record.subtotal, record.total) == (Decimal("2950.00"), Decimal("2950.00"))
        command.downgrade(config, "0007")
        columns = {c["name"] for c in inspect(engine).get_columns("quotes")}
        assert not columns & {"vat_percent", "vat_amount", "gross_total", "seller"}
        with engine.connect() as conn:
            assert conn.execute(select(quotes.c.total)).scalar_one() == Decimal("2950.00")
        command.upgrade(config, "head")
    finally:
        engine.dispose()
