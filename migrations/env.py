"""Alembic environment: the URL comes from the service settings, the metadata from the models.

A caller may hand over an open connection in ``config.attributes["connection"]``
(the tests do, to migrate inside their own transaction).
"""

from __future__ import annotations

from alembic import context
from sqlalchemy import Connection

from actuator_selection.config import get_settings
from actuator_selection.db.engine import make_engine, normalise_url
from actuator_selection.db.migrate import ours
from actuator_selection.db.models import Base

config = context.config
target_metadata = Base.metadata


def _run(connection: Connection) -> None:
    context.configure(
        connection=connection,
        target_metadata=target_metadata,
        render_as_batch=connection.dialect.name == "sqlite",
        compare_type=True,
        include_name=ours,  # procrastinate's tables are its own (migration 0010)
    )
    with context.begin_transaction():
        context.run_migrations()


def run_migrations_offline() -> None:
    """Emit SQL to stdout (``alembic upgrade head --sql``)."""
    url = config.attributes.get("url") or normalise_url(get_settings().database_url)
    context.configure(url=url, target_metadata=target_metadata, literal_binds=True)
    with context.begin_transaction():
        context.run_migrations()


def run_migrations_online() -> None:
    """Migrate the database of the given connection, or of the configured URL."""
    connection = config.attributes.get("connection")
    if connection is not None:
        _run(connection)
        return
    url = config.attributes.get("url") or get_settings().database_url
    engine = make_engine(url)
    try:
        with engine.connect() as conn:
            _run(conn)
    finally:
        engine.dispose()


if context.is_offline_mode():
    run_migrations_offline()
else:
    run_migrations_online()
