"""Fixtures of the database tests."""

from __future__ import annotations

from collections.abc import Callable, Iterator

import pytest
from sqlalchemy import Engine

from actuator_selection.db.engine import make_engine
from actuator_selection.db.migrate import upgrade


@pytest.fixture
def empty_engine(backend: str, new_database: Callable[[str], str]) -> Iterator[Engine]:
    """A fresh database of ``backend``, migrated and empty."""
    url = new_database(backend)
    upgrade(url=url)
    engine = make_engine(url)
    yield engine
    engine.dispose()
