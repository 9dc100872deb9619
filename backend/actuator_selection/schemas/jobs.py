"""The batch job contract: a large batch accepted at once and computed by workers."""

from __future__ import annotations

from datetime import datetime
from typing import Literal

from pydantic import Field

from actuator_selection.schemas.common import ResponseModel

JobState = Literal["queued", "running", "done", "failed", "cancelled"]

NDJSON = "application/x-ndjson"
"""The media type of a job's cases and of its results: one JSON value a line."""
JOB_MEDIA_TYPES = (NDJSON, "application/jsonl")
"""The media types a job's cases may be sent as (JSON lines under either name)."""


class BatchJobOut(ResponseModel):
    """A batch job: where it stands."""

    id: str
    state: JobState = Field(
        description="`queued` (no chunk started), `running`, `done` (every answer written, "
        "`results` can be read), `failed` (`error` says why) or `cancelled`"
    )
    cases: int = Field(description="load cases of the job")
    cases_done: int = Field(description="cases whose answers are written")
    chunks: int = Field(description="chunks the cases were split into (the unit a worker computes)")
    chunks_done: int
    progress: float = Field(ge=0, le=1, description="cases_done / cases")
    eta_s: float | None = Field(
        description="seconds until done at the pace so far (time per case since the first "
        "chunk started × cases left); null before a chunk is done, 0 once done"
    )
    top: int
    include_checks: bool
    catalogue_version: int = Field(description="the catalogue's version when the job was accepted")
    catalogue_versions: list[int] = Field(
        description="the versions the chunks done were computed against (one, unless the "
        "catalogue changed while the job ran)"
    )
    created_at: datetime
    started_at: datetime | None
    finished_at: datetime | None
    error: str | None
