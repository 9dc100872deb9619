"""Stored selections: the request, and the answer exactly as it was sent (gzip)."""

from __future__ import annotations

from datetime import datetime
from typing import Any

from sqlalchemy import JSON, DateTime, Integer, LargeBinary, String
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
    answer_gzip: Mapped[bytes] = mapped_column(LargeBinary)
    """The answer's JSON bytes as sent, gzip-compressed (~8× smaller than the JSON)."""
    answer_version: Mapped[int] = mapped_column(Integer)
    """The shape of the answer (``services.presenters.selection.ANSWER_VERSION``): the
    answers of older shapes were upgraded to the current one by a migration, once."""
    ranking_zstd: Mapped[bytes | None] = mapped_column(LargeBinary, nullable=True)
    """The ranking beyond the answer's candidates, as columns (JSON, zstd-compressed:
    ``services.presenters.selection.ranking_rest``); null when the answer lists it whole."""
