"""The Alembic migrations build the schema from an empty database, on both backends."""

from __future__ import annotations

from collections.abc import Callable

from alembic import command
from alembic.autogenerate import compare_metadata
from alembic.migration import MigrationContext
from sqlalchemy import inspect

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
