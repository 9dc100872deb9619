"""Stored selections: a row is written only with the catalogue version it was sized against."""

from __future__ import annotations

from datetime import UTC, datetime

from sqlalchemy import Engine, func, select
from sqlalchemy.orm import Session

from actuator_selection.db.models import SelectionRow
from actuator_selection.db.repositories import (
    CatalogueVersionRepository,
    NewSelection,
    SelectionRepository,
)

NOW = datetime(2026, 11, 23, 12, 0, tzinfo=UTC)


def _row(id: str, version: int) -> NewSelection:
    return NewSelection(
        id=id,
        created_at=NOW,
        catalogue_version=version,
        request={"load": {"speed_rpm": 40.0}, "models": None},
        answer_gzip=b"\x1f\x8b stored as sent",
        answer_version=2,
    )


def test_a_selection_is_stored_at_the_current_version_only(session: Session) -> None:
    versions = CatalogueVersionRepository(session)
    repository = SelectionRepository(session)
    current = versions.current()
    assert repository.add_at_version(_row("at-current", current))
    assert not repository.add_at_version(_row("one-behind", current - 1))
    assert not repository.add_at_version(_row("one-ahead", current + 1))
    raised = versions.bump()  # a catalogue change lands
    assert not repository.add_at_version(_row("stale", current))
    assert repository.add_at_version(_row("fresh", raised))
    stored = dict(session.execute(select(SelectionRow.id, SelectionRow.catalogue_version)).all())
    assert stored == {"at-current": current, "fresh": raised}
    assert session.scalar(select(SelectionRow.request).where(SelectionRow.id == "fresh")) == {
        "load": {"speed_rpm": 40.0},
        "models": None,
    }
    assert repository.answer_gzip("fresh") == b"\x1f\x8b stored as sent"


def test_a_catalogue_never_written_is_version_zero(empty_engine: Engine) -> None:
    with Session(empty_engine) as empty:
        repository = SelectionRepository(empty)
        assert CatalogueVersionRepository(empty).current() == 0
        assert not repository.add_at_version(_row("ahead", 1))
        assert repository.add_at_version(_row("zero", 0))
        assert empty.scalar(select(func.count()).select_from(SelectionRow)) == 1
