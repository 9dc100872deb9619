"""Batch jobs: a large batch split into chunks that workers compute one at a time.

A job's cases are stored with it, chunk by chunk, as the client sent them (one JSON
case a line, zlib-compressed); each chunk's answer is a row of its own keyed by
``(job_id, chunk)``, written once: a chunk that runs again (its worker was killed
before it finished) finds its row and writes nothing (``services/jobs.py``).
"""

from __future__ import annotations

from datetime import datetime
from typing import Any

from sqlalchemy import JSON, DateTime, ForeignKey, Integer, LargeBinary, String, Text
from sqlalchemy.orm import Mapped, mapped_column

from actuator_selection.db.models.base import Base


class BatchJobRow(Base):
    """One job: its options, its size, and where it stands."""

    __tablename__ = "batch_jobs"

    id: Mapped[str] = mapped_column(String(36), primary_key=True)
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    started_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True), nullable=True)
    finished_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True), nullable=True)
    state: Mapped[str] = mapped_column(String(16))
    """``queued``, ``running``, ``done``, ``failed`` or ``cancelled``."""
    options: Mapped[dict[str, Any]] = mapped_column(JSON)
    """``top``, ``include_checks`` and ``language`` of every chunk's batch."""
    catalogue_version: Mapped[int] = mapped_column(Integer)
    """The catalogue's version when the job was accepted."""
    cases: Mapped[int] = mapped_column(Integer)
    chunks: Mapped[int] = mapped_column(Integer)
    error: Mapped[str | None] = mapped_column(Text, nullable=True)


class BatchJobChunkRow(Base):
    """A chunk's load cases, as sent: one JSON case a line, zlib-compressed."""

    __tablename__ = "batch_job_chunks"

    job_id: Mapped[str] = mapped_column(
        String(36), ForeignKey("batch_jobs.id", ondelete="CASCADE"), primary_key=True
    )
    chunk: Mapped[int] = mapped_column(Integer, primary_key=True)
    first_case: Mapped[int] = mapped_column(Integer)
    cases: Mapped[int] = mapped_column(Integer)
    input_zlib: Mapped[bytes] = mapped_column(LargeBinary)


class BatchJobResultRow(Base):
    """A chunk's answer, written once: one JSON result a line, zlib-compressed."""

    __tablename__ = "batch_job_results"

    job_id: Mapped[str] = mapped_column(
        String(36), ForeignKey("batch_jobs.id", ondelete="CASCADE"), primary_key=True
    )
    chunk: Mapped[int] = mapped_column(Integer, primary_key=True)
    cases: Mapped[int] = mapped_column(Integer)
    catalogue_version: Mapped[int] = mapped_column(Integer)
    worker: Mapped[str] = mapped_column(String(200))
    """Who computed it (``host:pid``)."""
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    lines_zlib: Mapped[bytes] = mapped_column(LargeBinary)
