"""Writing validated catalogue rows: upsert by natural key, count what changed.

Shared by every catalogue file (``db/seed.py``, ``db/seed_controllers.py``), so
seeding, importing and the admin API count and apply changes the same way; the
counts are :class:`~actuator_selection.catalogue.changes.FileChanges`.
"""

from __future__ import annotations

import itertools
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from datetime import datetime
from typing import Any

from sqlalchemy import bindparam, insert, select, update
from sqlalchemy.orm import Session

from actuator_selection.catalogue.changes import FileChanges


def set_values(row: Any, values: Mapping[str, Any]) -> bool:
    """Set ``values`` on ``row``; True when anything changed."""
    changed = False
    for name, value in values.items():
        if getattr(row, name) != value:
            setattr(row, name, value)
            changed = True
    return changed


BATCH_ROWS = 1000
"""Rows per INSERT or UPDATE statement of a sync (an executemany each)."""


def batches(rows: Sequence[Any], size: int = BATCH_ROWS) -> Iterator[Sequence[Any]]:
    """``rows`` in slices of at most ``size``."""
    for start in range(0, len(rows), size):
        yield rows[start : start + size]


def sync_rows(
    session: Session,
    model: type[Any],
    key: tuple[str, ...],
    rows: Iterable[Mapping[str, Any]],
    changes: FileChanges,
    *,
    withdraw: Callable[[Any], bool] | None = None,
) -> list[tuple[Any, ...]]:
    """Upsert ``rows`` of ``model`` matched on the attributes ``key``, counting into
    ``changes``; the keys of the rows inserted, changed or withdrawn.

    ``withdraw``, when given, is called with every stored row the given rows do
    not hold (the file is the whole table): it retires or deletes the row and
    returns True when it did (False: left alone, e.g. already retired).

    The stored rows are compared as plain tuples and written by batched INSERTs and
    UPDATEs (no ORM object per row), so that importing 64,000 actuators holds no
    64,000 tracked objects; only the rows withdrawn are loaded as objects. ``rows`` is
    consumed once, each batch written as it fills, so a generator of rows is never held
    whole. Every row holds the same attributes (one file's columns), which are the
    table's columns.
    """
    session.flush()
    table = model.__table__
    given = iter(rows)
    first = next(given, None)
    names = [] if first is None else list(first)
    existing: dict[tuple[Any, ...], tuple[int, tuple[Any, ...]]] = {}
    found = session.execute(
        select(table.c.id, *(table.c[k] for k in key), *(table.c[n] for n in names))
    )
    width = len(key)
    for row in found:
        existing[tuple(row[1 : 1 + width])] = (row[0], tuple(row[1 + width :]))
    inserts: list[Mapping[str, Any]] = []
    updates: list[dict[str, Any]] = []
    touched: list[tuple[Any, ...]] = []
    adding, changing = insert(table), update(table).where(table.c.id == bindparam("_row_id"))
    for values in itertools.chain(() if first is None else (first,), given):
        its = tuple(values[k] for k in key)
        stored = existing.pop(its, None)
        if stored is None:
            inserts.append(values)
            touched.append(its)
            changes.inserted += 1
        else:
            changed = tuple(values[n] for n in names) != stored[1]
            if changed:
                updates.append({"_row_id": stored[0], **values})
                touched.append(its)
            changes.count(is_new=False, changed=changed)
        for statement, pending in ((adding, inserts), (changing, updates)):
            if len(pending) >= BATCH_ROWS:
                session.execute(statement, pending)
                pending.clear()
    for statement, pending in ((adding, inserts), (changing, updates)):
        if pending:
            session.execute(statement, pending)
    if withdraw is not None and existing:
        keys = {row_id: its for its, (row_id, _) in existing.items()}
        for batch in batches(list(keys)):
            for row in session.scalars(select(model).where(table.c.id.in_(batch))):
                if withdraw(row):
                    changes.retired += 1
                    touched.append(keys[row.id])
    session.flush()
    return touched


def retire_at(now: datetime) -> Callable[[Any], bool]:
    """A ``withdraw`` for soft-deleted rows: sets ``retired_at`` unless already retired."""

    def withdraw(row: Any) -> bool:
        if row.retired_at is not None:
            return False
        row.retired_at = now
        return True

    return withdraw


def delete_in(
    session: Session, keep: Callable[[Any], bool] = lambda _: False
) -> Callable[[Any], bool]:
    """A ``withdraw`` that deletes a row unless ``keep(row)``."""

    def withdraw(row: Any) -> bool:
        if keep(row):
            return False
        session.delete(row)
        return True

    return withdraw
