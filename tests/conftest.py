"""Shared fixtures: the same database tests run on SQLite and on PostgreSQL.

Each database is built by the Alembic migrations and seeded with the starter
catalogue once per test session; every test then runs inside a transaction that
is rolled back afterwards (SQLAlchemy's "joining a session into an external
transaction" recipe), so tests never see each other's writes.

PostgreSQL: ``TEST_POSTGRES_URL`` (default ``postgresql://postgres@127.0.0.1:5432/test``)
names a server where a throw-away database is created per run. When it cannot be
reached the PostgreSQL tests are skipped with a message, unless
``REQUIRE_POSTGRES=1`` (set by ``.ci/run``), which turns that into a failure.
"""

from __future__ import annotations

import os
import uuid
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from fastapi.testclient import TestClient
from sqlalchemy import Connection, Engine, create_engine, text
from sqlalchemy.engine import make_url
from sqlalchemy.orm import Session, sessionmaker

from actuator_selection.app import create_app
from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.engine import make_engine, make_session_factory, normalise_url
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.seed import load_seed

POSTGRES_URL = normalise_url(
    os.environ.get("TEST_POSTGRES_URL", "postgresql://postgres@127.0.0.1:5432/test")
)
REQUIRE_POSTGRES = os.environ.get("REQUIRE_POSTGRES") == "1"
BACKENDS = ["sqlite", "postgresql"]


def _postgres_admin() -> Engine:
    engine = create_engine(POSTGRES_URL, isolation_level="AUTOCOMMIT")
    try:
        with engine.connect() as conn:
            conn.execute(text("SELECT 1"))
    except Exception as exc:  # any connection failure means "no server here"
        engine.dispose()
        message = f"PostgreSQL at {make_url(POSTGRES_URL).render_as_string()} unreachable: {exc}"
        if REQUIRE_POSTGRES:
            pytest.fail(f"{message} (REQUIRE_POSTGRES=1)", pytrace=False)
        pytest.skip(message)
    return engine


@pytest.fixture(scope="session")
def new_database(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Callable[[str], str]]:
    """Factory: an empty database on the given backend; returns its URL. Dropped at the end."""
    created: list[str] = []
    admin: Engine | None = None

    def make(backend: str) -> str:
        nonlocal admin
        if backend == "sqlite":
            path = tmp_path_factory.mktemp("db") / f"{uuid.uuid4().hex}.sqlite3"
            return f"sqlite:///{path}"
        if admin is None:
            admin = _postgres_admin()
        name = f"actuator_test_{uuid.uuid4().hex[:12]}"
        with admin.connect() as conn:
            conn.execute(text(f'CREATE DATABASE "{name}"'))
        created.append(name)
        return make_url(POSTGRES_URL).set(database=name).render_as_string(hide_password=False)

    yield make
    if admin is not None:
        with admin.connect() as conn:
            for name in created:
                conn.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))
        admin.dispose()


@pytest.fixture(scope="session", params=BACKENDS)
def backend(request: pytest.FixtureRequest) -> str:
    """The database backend a test runs on."""
    return str(request.param)


@pytest.fixture(scope="session")
def seeded_engine(backend: str, new_database: Callable[[str], str]) -> Iterator[Engine]:
    """A migrated database holding the starter catalogue, shared by the session's tests."""
    url = new_database(backend)
    upgrade(url=url)
    engine = make_engine(url)
    with make_session_factory(engine).begin() as session:
        load_seed(session, SEED_DIR)
    yield engine
    engine.dispose()


@pytest.fixture
def connection(seeded_engine: Engine) -> Iterator[Connection]:
    """A connection inside a transaction that is rolled back after the test."""
    with seeded_engine.connect() as conn:
        transaction = conn.begin()
        try:
            yield conn
        finally:
            transaction.rollback()


@pytest.fixture
def session(connection: Connection) -> Iterator[Session]:
    """A session whose commits only release savepoints of the test's transaction."""
    with Session(bind=connection, join_transaction_mode="create_savepoint") as db:
        yield db


@pytest.fixture
def client(seeded_engine: Engine, connection: Connection) -> Iterator[TestClient]:
    """The API on the seeded database; its requests run in the test's rolled-back transaction.

    The app's own session dependency (commit on success, rollback on error) stays in
    place; only its session factory is bound to the test's connection.
    """
    app = create_app(Settings(database_url=seeded_engine.url.render_as_string(hide_password=False)))
    app.state.session_factory = sessionmaker(
        bind=connection, join_transaction_mode="create_savepoint", expire_on_commit=False
    )
    with TestClient(app, raise_server_exceptions=False) as test_client:
        yield test_client


@pytest.fixture
def seed_dir(tmp_path: Path) -> Path:
    """A writable copy of the starter catalogue, for tests that break it."""
    target = tmp_path / "seed"
    target.mkdir()
    for csv_file in SEED_DIR.glob("*.csv"):
        (target / csv_file.name).write_bytes(csv_file.read_bytes())
    return target
