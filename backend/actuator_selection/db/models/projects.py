"""Stored machine projects: several axes on one DC bus (issue 31), request and answer."""

from __future__ import annotations

from datetime import datetime
from typing import Any

from sqlalchemy import DateTime, Index, Integer, LargeBinary, String
from sqlalchemy.orm import Mapped, mapped_column

from actuator_selection.db.models.base import Base
from actuator_selection.db.models.selections import JSONDocument


class ProjectRow(Base):
    """One machine project: its axes and bus as sent, and its sizing as answered."""

    __tablename__ = "projects"
    __table_args__ = (Index("ix_projects_created_at_id", "created_at", "id"),)

    id: Mapped[str] = mapped_column(String(36), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    updated_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    catalogue_version: Mapped[int] = mapped_column(Integer)
    """The catalogue version the stored sizing used."""
    request: Mapped[dict[str, Any]] = mapped_column(JSONDocument)
    answer_gzip: Mapped[bytes] = mapped_column(LargeBinary)
    """The sizing's JSON bytes as answered, gzip-compressed."""
