"""Stored selections: the request and the response, kept exactly as answered."""

from __future__ import annotations

from datetime import datetime
from typing import Any

from sqlalchemy import JSON, DateTime, Integer, String
from sqlalchemy.dialects.postgresql import JSONB
from sqlalchemy.orm import Mapped, mapped_column

from actuator_selection.db.models.base import Base

JSONDocument = JSON().with_variant(JSONB(), "postgresql")


class SelectionRow(Base):
    """One run of the selection flowchart over the catalogue."""

    __tablename__ = "selections"

    id: Mapped[str] = mapped_column(String(36), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    catalogue_version: Mapped[int] = mapped_column(Integer)
    request: Mapped[dict[str, Any]] = mapped_column(JSONDocument)
    response: Mapped[dict[str, Any]] = mapped_column(JSONDocument)
