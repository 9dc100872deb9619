"""Stored machine projects (issue 31): written, replaced when edited or sized again, listed
by creation in pages."""

from __future__ import annotations

from dataclasses import dataclass
from datetime import UTC, datetime
from typing import Any

from sqlalchemy import and_, or_, select, update
from sqlalchemy.orm import Session

from actuator_selection.db.models.projects import ProjectRow


@dataclass(frozen=True, slots=True, kw_only=True)
class StoredProject:
    """A project as stored: its request, the catalogue version of its sizing, and the
    sizing as answered (gzip-compressed JSON)."""

    id: str
    created_at: datetime
    updated_at: datetime
    catalogue_version: int
    request: dict[str, Any]
    answer_gzip: bytes


def _aware(at: datetime) -> datetime:
    """A stored time in UTC (SQLite gives it back without its zone)."""
    return at if at.tzinfo is not None else at.replace(tzinfo=UTC)


def _stored(row: ProjectRow) -> StoredProject:
    return StoredProject(
        id=row.id,
        created_at=_aware(row.created_at),
        updated_at=_aware(row.updated_at),
        catalogue_version=row.catalogue_version,
        request=row.request,
        answer_gzip=row.answer_gzip,
    )


class ProjectRepository:
    """Machine projects."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def add(self, project: StoredProject) -> None:
        """Store a new project."""
        self._session.add(
            ProjectRow(
                id=project.id,
                created_at=project.created_at,
                updated_at=project.updated_at,
                catalogue_version=project.catalogue_version,
                request=project.request,
                answer_gzip=project.answer_gzip,
            )
        )
        self._session.flush()

    def replace(self, project: StoredProject) -> bool:
        """Replace a project's request and sizing; False where there is no such project."""
        done = self._session.execute(
            update(ProjectRow)
            .where(ProjectRow.id == project.id)
            .values(
                updated_at=project.updated_at,
                catalogue_version=project.catalogue_version,
                request=project.request,
                answer_gzip=project.answer_gzip,
            )
            .returning(ProjectRow.id)
        ).first()
        return done is not None

    def get(self, id: str) -> StoredProject | None:
        """One project, or None."""
        row = self._session.get(ProjectRow, id)
        return None if row is None else _stored(row)

    def page(self, *, limit: int, after: tuple[datetime, str] | None = None) -> list[StoredProject]:
        """Up to ``limit`` projects, oldest first, after the (created_at, id) ``after``."""
        query = select(ProjectRow).order_by(ProjectRow.created_at, ProjectRow.id).limit(limit)
        if after is not None:
            at, id = after
            query = query.where(
                or_(
                    ProjectRow.created_at > at,
                    and_(ProjectRow.created_at == at, ProjectRow.id > id),
                )
            )
        return [_stored(r) for r in self._session.scalars(query)]
