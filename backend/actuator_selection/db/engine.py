"""Engine and session factory for SQLite (embedded default) and PostgreSQL (production).

Both are set up for concurrent clients (the README's "Durability and concurrency"):

- **SQLite** runs in WAL mode, so readers never block the writer nor the writer the
  readers; ``synchronous=FULL`` makes a commit durable before it returns; a busy
  timeout makes a second writer wait for the lock instead of failing at once; and a
  write transaction takes the write lock when it begins (``BEGIN IMMEDIATE``, see
  :func:`begin_write`), because a deferred transaction that has read and then
  writes fails at once ("database is locked") when another writer committed in
  between, whatever the timeout.
- **PostgreSQL** gets a statement timeout, a lock timeout and an idle-in-transaction
  timeout on every connection, and a pool as large as the requests the service
  admits at once (``http.admission``), so no thread ever waits long for a connection.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pydantic_core
from sqlalchemy import Engine, create_engine, event
from sqlalchemy.engine import make_url
from sqlalchemy.exc import DisconnectionError
from sqlalchemy.orm import Session, sessionmaker

from actuator_selection.config import EngineLimits

WRITE_INTENT = "actuator_selection_writes"
"""Execution option: the transaction will write (SQLite: ``BEGIN IMMEDIATE``)."""


def normalise_url(url: str) -> str:
    """Use psycopg 3 for ``postgresql://`` URLs (SQLAlchemy would default to psycopg2).

    >>> normalise_url("postgresql://root@127.0.0.1:5432/test")
    'postgresql+psycopg://root@127.0.0.1:5432/test'
    >>> normalise_url("sqlite:///x.db")
    'sqlite:///x.db'
    """
    for prefix in ("postgresql://", "postgres://"):
        if url.startswith(prefix):
            return "postgresql+psycopg://" + url[len(prefix) :]
    return url


def _sqlite_file_guard(engine: Engine, path: Path) -> None:
    """Hand out a pooled connection only while its file is still the one at ``path``.

    An open SQLite connection keeps reading and writing its file after the file (or its
    folder) has been moved, deleted or replaced: the service would go on with a database
    that is no longer the one configured. The file's identity is taken when the
    connection is made and compared on every checkout (one ``stat``); when it differs,
    the connection is replaced, and opening the path again says whether the database
    can be reached (``db.availability``). This is SQLite's counterpart of PostgreSQL's
    pre-ping.

    Once the file exists, connections open it without creating it (``mode=rw``): a
    database deleted under the service is unreachable, not silently a new empty one.
    """

    def identity() -> tuple[int, int] | None:
        try:
            found = os.stat(path)
        except OSError:
            return None
        return found.st_dev, found.st_ino

    existing_only = f"{path.absolute().as_uri()}?mode=rw"
    created = [path.exists()]  # once true, stays true

    @event.listens_for(engine, "do_connect")
    def _open(_dialect: Any, _record: Any, cargs: list[Any], cparams: dict[str, Any]) -> None:
        if created[0] and not cparams.get("uri") and cargs == [str(path)]:
            cargs[0] = existing_only
            cparams["uri"] = True

    @event.listens_for(engine, "connect")
    def _remember(_dbapi_connection: Any, record: Any) -> None:
        record.info[_SQLITE_FILE] = identity()
        created[0] = True

    @event.listens_for(engine, "checkout")
    def _check(_dbapi_connection: Any, record: Any, _proxy: Any) -> None:
        if record.info.get(_SQLITE_FILE) != identity():
            raise DisconnectionError(f"the database file {path} has moved or gone")


_SQLITE_FILE = "actuator_selection_sqlite_file"
"""Key of a pooled SQLite connection's file identity in its record's ``info``."""


def _sqlite_setup(engine: Engine) -> None:
    """WAL, durable commits, foreign keys; SQLAlchemy, not pysqlite, begins transactions.

    pysqlite's own transaction handling breaks SAVEPOINTs and cannot begin
    IMMEDIATE; this is the recipe of SQLAlchemy's SQLite dialect documentation
    ("Serializable isolation / Savepoints / Transactional DDL"), with the BEGIN
    chosen by :data:`WRITE_INTENT`. Foreign keys are off by default in SQLite.
    """

    @event.listens_for(engine, "connect")
    def _connect(dbapi_connection: Any, _record: Any) -> None:
        dbapi_connection.isolation_level = None
        cursor = dbapi_connection.cursor()
        cursor.execute("PRAGMA foreign_keys=ON")
        cursor.execute("PRAGMA journal_mode=WAL")
        cursor.execute("PRAGMA synchronous=FULL")
        cursor.close()

    @event.listens_for(engine, "begin")
    def _begin(connection: Any) -> None:
        writes = connection.get_execution_options().get(WRITE_INTENT, False)
        connection.exec_driver_sql("BEGIN IMMEDIATE" if writes else "BEGIN")


def _to_json(value: Any) -> str:
    """JSON columns' text: pydantic's Rust encoder, ~2× ``json.dumps`` on a stored
    selection (≈ 1 MB for a whole catalogue); stored values are JSON-ready already."""
    return pydantic_core.to_json(value).decode()


def _milliseconds(seconds: float) -> int:
    return max(1, round(seconds * 1000))


def make_engine(url: str, limits: EngineLimits | None = None) -> Engine:
    """An engine for ``url``; creates the folder of a file-based SQLite database."""
    limits = limits or EngineLimits()
    url = normalise_url(url)
    parsed = make_url(url)
    if parsed.get_backend_name() == "sqlite":
        in_memory = parsed.database in (None, "", ":memory:")
        if not in_memory:
            Path(str(parsed.database)).parent.mkdir(parents=True, exist_ok=True)
        # An in-memory database lives in one connection (SQLAlchemy's SingletonThreadPool).
        pool: dict[str, Any] = (
            {}
            if in_memory
            else {
                "pool_size": limits.pool_size,
                "max_overflow": limits.pool_size,
                "pool_timeout": limits.pool_timeout_s,
            }
        )
        engine = create_engine(
            url,
            # pysqlite's ``timeout`` is SQLite's busy timeout: how long to wait for a lock.
            connect_args={"check_same_thread": False, "timeout": limits.lock_timeout_s},
            json_serializer=_to_json,
            **pool,
        )
        _sqlite_setup(engine)
        if not in_memory:
            _sqlite_file_guard(engine, Path(str(parsed.database)))
        return engine
    options = " ".join(
        f"-c {name}={_milliseconds(value)}"
        for name, value in (
            ("statement_timeout", limits.statement_timeout_s),
            ("lock_timeout", limits.lock_timeout_s),
            ("idle_in_transaction_session_timeout", limits.statement_timeout_s),
        )
    )
    return create_engine(
        url,
        connect_args={"options": options, "connect_timeout": limits.connect_timeout_s},
        json_serializer=_to_json,
        pool_pre_ping=True,
        pool_size=limits.pool_size,
        max_overflow=limits.pool_size,
        pool_timeout=limits.pool_timeout_s,
    )


def make_session_factory(engine: Engine) -> sessionmaker[Session]:
    """Sessions that keep loaded values after commit (responses are built after it)."""
    return sessionmaker(bind=engine, expire_on_commit=False)


def begin_write(session: Session) -> Session:
    """Begin ``session``'s transaction as a writer; call before its first statement.

    On SQLite the transaction takes the database's write lock at once (``BEGIN
    IMMEDIATE``, waiting up to the busy timeout for it), so it cannot fail later on
    upgrading a read lock; on PostgreSQL it is an ordinary transaction.
    """
    session.connection(execution_options={WRITE_INTENT: True})
    return session
