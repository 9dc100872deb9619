"""Whether the database can be reached: which errors say it cannot, and one log line per change.

A database that cannot be reached (PostgreSQL refusing or dropping connections, a
SQLite file whose folder is gone) is an outage of a dependency, not a fault of the
request: the API answers 503 with ``Retry-After`` (``http.errors``), and the service
recovers by itself when the database is back, since every request tries again (a
pooled PostgreSQL connection is pinged before use; a pooled SQLite connection is
checked against the file at its path, ``db.engine``).

:class:`Availability` watches an engine: the first such error after the database
answered logs one line, ``database unreachable: …``, and the first connection handed
out after that logs one line, ``database reachable again after … s``. Nothing else is
logged for the requests in between, and no traceback.
"""

from __future__ import annotations

import logging
import threading
import time
from typing import Any

from sqlalchemy import Engine, event
from sqlalchemy.engine import ExceptionContext
from sqlalchemy.exc import DBAPIError

log = logging.getLogger(__name__)

_CONNECTION_SQLSTATES = frozenset(
    {
        "57P01",  # admin_shutdown
        "57P02",  # crash_shutdown
        "57P03",  # cannot_connect_now (starting up, shutting down, in recovery)
    }
)
"""PostgreSQL states of a server going away; class 08 (connection exception) too."""

_SQLITE_UNREACHABLE = ("SQLITE_CANTOPEN", "SQLITE_IOERR")
"""SQLite's error names (and their extended forms) of a file that cannot be opened or read."""


def unreachable(exc: BaseException | None) -> bool:
    """True when ``exc`` (a SQLAlchemy or DBAPI error) says the database cannot be reached.

    - SQLAlchemy found the connection broken (``connection_invalidated``);
    - psycopg: an ``OperationalError`` without SQLSTATE is the client's own (connection
      refused, timed out or lost: the server never answered); with one, class 08 or the
      server shutting down or starting;
    - sqlite3: the file cannot be opened (``SQLITE_CANTOPEN``) or read (``SQLITE_IOERR``).
    """
    if isinstance(exc, DBAPIError):
        if exc.connection_invalidated:
            return True
        exc = exc.orig
    if exc is None:
        return False
    module = type(exc).__module__
    if module.startswith("psycopg"):
        sqlstate = getattr(exc, "sqlstate", None)
        if sqlstate is None:
            return type(exc).__name__ in ("OperationalError", "InterfaceError")
        return str(sqlstate).startswith("08") or sqlstate in _CONNECTION_SQLSTATES
    if module == "sqlite3":
        name = str(getattr(exc, "sqlite_errorname", ""))
        return name.startswith(_SQLITE_UNREACHABLE)
    return False


def first_line(exc: BaseException) -> str:
    """``exc``'s message on one line (a log line per state change, not a traceback)."""
    cause = exc.orig if isinstance(exc, DBAPIError) and exc.orig is not None else exc
    text = str(cause).strip().splitlines()
    return f"{type(cause).__name__}: {text[0] if text else ''}".strip()


class Availability:
    """The database's state as this process last saw it; logs each change once."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._down_since: float | None = None

    @property
    def down(self) -> bool:
        """True from an error saying the database cannot be reached until a connection
        is handed out again."""
        return self._down_since is not None

    def lost(self, exc: BaseException) -> None:
        """The database could not be reached (``exc`` says why)."""
        with self._lock:
            if self._down_since is not None:
                return
            self._down_since = time.monotonic()
        log.warning("database unreachable: %s", first_line(exc))

    def regained(self) -> None:
        """A connection was handed out: the database answers (again)."""
        if self._down_since is None:  # the common case, without the lock
            return
        with self._lock:
            since, self._down_since = self._down_since, None
        if since is not None:
            log.warning("database reachable again after %.1f s", time.monotonic() - since)

    def watch(self, engine: Engine) -> None:
        """Follow ``engine``: its errors that say the database is unreachable mark
        SQLAlchemy's exception as a disconnect (so that the connection is replaced)
        and the database as lost; a connection checked out marks it regained."""

        @event.listens_for(engine, "handle_error")
        def _error(context: ExceptionContext) -> None:
            if context.is_pre_ping:  # the pool reconnects; that attempt tells
                return
            if context.is_disconnect or unreachable(context.original_exception):
                context.is_disconnect = True
                self.lost(context.original_exception)

        @event.listens_for(engine, "checkout")
        def _checkout(*_: Any) -> None:
            self.regained()
