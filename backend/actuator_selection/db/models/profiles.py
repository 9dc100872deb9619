"""Stored motion profiles: a measured cycle read from a file, as the segments it sizes."""

from __future__ import annotations

from datetime import datetime
from typing import Any

from sqlalchemy import DateTime, String
from sqlalchemy.orm import Mapped, mapped_column

from actuator_selection.db.models.base import Base
from actuator_selection.db.models.selections import JSONDocument


class ProfileRow(Base):
    """One uploaded profile: its kind and its answer (the cycle, figures, preview)."""

    __tablename__ = "motion_profiles"

    id: Mapped[str] = mapped_column(String(36), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    kind: Mapped[str] = mapped_column(String(10))
    """``rotary`` (speeds in rpm, loads in Nm) or ``linear`` (mm/s, N)."""
    answer: Mapped[dict[str, Any]] = mapped_column(JSONDocument)
