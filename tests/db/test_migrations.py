"""The Alembic migrations build the schema from an empty database, on both backends."""

from __future__ import annotations

import gzip
import json
from collections.abc import Callable
from datetime import UTC, datetime

from alembic import command
from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext
from sqlalchemy import JSON, column, insert, inspect, select, table, text

from actuator_selection.db.engine import make_engine
from actuator_selection.db.migrate import alembic_config, upgrade
from actuator_selection.db.models import Base


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
            diff = compare_metadata(MigrationContext.configure(conn), Base.metadata)
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
