"""Running the Alembic migrations from code (the CLI and the tests use this)."""

from __future__ import annotations

from typing import Any

from alembic import command
from alembic.config import Config
from sqlalchemy import Connection

from actuator_selection.config import REPO_ROOT

QUEUE_TABLE_PREFIX = "procrastinate_"
"""Tables of procrastinate's own schema (PostgreSQL, migration 0010): its, not our models'."""


def ours(name: str | None, type_: str, _parents: Any) -> bool:
    """Alembic's ``include_name``: compare our tables only, not the task queue's."""
    return not (type_ == "table" and name is not None and name.startswith(QUEUE_TABLE_PREFIX))


def alembic_config(*, url: str | None = None, connection: Connection | None = None) -> Config:
    """Alembic configuration of this repository, for ``url`` or an open ``connection``."""
    config = Config(str(REPO_ROOT / "alembic.ini"))
    config.set_main_option("script_location", str(REPO_ROOT / "migrations"))
    if url is not None:
        config.attributes["url"] = url
    if connection is not None:
        config.attributes["connection"] = connection
    return config


def upgrade(*, url: str | None = None, connection: Connection | None = None) -> None:
    """Migrate the database to the newest revision."""
    command.upgrade(alembic_config(url=url, connection=connection), "head")
