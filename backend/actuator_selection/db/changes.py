"""Writing validated catalogue rows: upsert by natural key, count what changed.

Shared by every catalogue file (``db/seed.py``, ``db/seed_controllers.py``), so
seeding, importing and the admin API count and apply changes the same way; the
counts are :class:`~actuator_selection.core.changes.FileChanges`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from datetime import datetime
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from actuator_selection.core.changes import FileChanges


def set_values(row: Any, values: Mapping[str, Any]) -> bool:
    """Set ``values`` on ``row``; True when anything changed."""
    changed = False
    for name, value in values.items():
        if getattr(row, name) != value:
            setattr(row, name, value)
            changed = True
    return changed


def sync_rows(
    session: Session,
    model: type[Any],
    key: tuple[str, ...],
    rows: Iterable[Mapping[str, Any]],
    changes: FileChanges,
    *,
    withdraw: Callable[[Any], bool] | None = None,
) -> None:
    """Upsert ``rows`` of ``model`` matched on the attributes ``key``, counting into ``changes``.

    ``withdraw``, when given, is called with every stored row the given rows do
    not hold (the file is the whole table): it retires or deletes the row and
    returns True when it did (False: left alone, e.g. already retired).
    """
    existing = {tuple(getattr(r, k) for k in key): r for r in session.scalars(select(model))}
    for values in rows:
        row = existing.pop(tuple(values[k] for k in key), None)
        if row is None:
            session.add(model(**values))
            changes.inserted += 1
        else:
            changes.count(is_new=False, changed=set_values(row, values))
    if withdraw is not None:
        # Flush the inserts and updates first, so a deletion never meets them half-done.
        session.flush()
        changes.retired += sum(1 for row in existing.values() if withdraw(row))
    session.flush()


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
