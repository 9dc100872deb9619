"""Batch jobs: a large batch accepted at once, computed chunk by chunk by workers.

A job's load cases arrive as JSON lines (one :class:`BatchCaseIn` a line), are checked
whole before anything is stored (``api/jobs.py``), and are stored in chunks of
``JOB_CHUNK_CASES`` cases. Each chunk is a task of a queue: procrastinate's on
PostgreSQL, so that workers on any number of machines share the work
(``python -m actuator_selection worker``), a thread of the server on SQLite
(``services/job_queue.py``). Either way a chunk is computed by :func:`run_chunk`.

A chunk's answer is written once: its row is keyed by ``(job_id, chunk)`` and inserted
only by a transaction that holds the job's row lock and finds no row yet. A worker
killed mid-chunk has written nothing; the queue hands the chunk to another worker, which
computes it again. A chunk that is computed twice (a worker taken for dead that was only
slow) is written by the first to finish; the other's answer is dropped.
"""

from __future__ import annotations

import csv
import io
import os
import socket
import uuid
import zlib
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from datetime import UTC, datetime
from typing import Any

import pydantic_core
from sqlalchemy import delete, func, select
from sqlalchemy.orm import Session, sessionmaker

from actuator_selection.db.engine import begin_write
from actuator_selection.db.models.jobs import BatchJobChunkRow, BatchJobResultRow, BatchJobRow
from actuator_selection.schemas.batch import BatchCaseIn, BatchSelectionRequest
from actuator_selection.schemas.checks import Localize
from actuator_selection.schemas.selections import CandidateFigures
from actuator_selection.services.batch import worded_results
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot
from actuator_selection.services.errors import UseCaseError, conflict, entry, not_found

ACTIVE = ("queued", "running")
"""States of a job whose chunks are still to be computed."""
ZLIB_LEVEL = 1
"""zlib level of stored cases and answers: the fastest; JSON shrinks about 8×."""


@dataclass(frozen=True, slots=True)
class JobOptions:
    """What every chunk's batch is asked: the best ``top``, with checks or not, in
    ``language``."""

    top: int
    include_checks: bool
    language: str

    def as_json(self) -> dict[str, Any]:
        return {"top": self.top, "include_checks": self.include_checks, "language": self.language}


class JobIntake:
    """A job's cases, checked line by line elsewhere, packed into compressed chunks."""

    def __init__(self, chunk_cases: int) -> None:
        self.chunk_cases = chunk_cases
        self.chunks: list[tuple[int, int, bytes]] = []  # (first case, cases, zlib lines)
        self.cases = 0
        self._pending: list[bytes] = []

    def add(self, line: bytes) -> None:
        """One case's JSON (valid: checked before)."""
        self._pending.append(line)
        if len(self._pending) == self.chunk_cases:
            self._pack()

    def close(self) -> None:
        """Pack the last, shorter chunk; refuse a job without cases (422)."""
        if self._pending:
            self._pack()
        if not self.cases:
            raise UseCaseError([entry(["body"], "job_without_cases", "job_without_cases")])

    def _pack(self) -> None:
        data = zlib.compress(b"\n".join(self._pending), ZLIB_LEVEL)
        self.chunks.append((self.cases, len(self._pending), data))
        self.cases += len(self._pending)
        self._pending = []


def create_job(
    session: Session, intake: JobIntake, options: JobOptions, catalogue_version: int
) -> BatchJobRow:
    """Store the job and its chunks (in ``session``'s write transaction); its row."""
    job = BatchJobRow(
        id=str(uuid.uuid4()),
        created_at=datetime.now(UTC),
        state="queued",
        options=options.as_json(),
        catalogue_version=catalogue_version,
        cases=intake.cases,
        chunks=len(intake.chunks),
    )
    session.add(job)
    session.flush()
    for k, (first, cases, data) in enumerate(intake.chunks):
        session.add(
            BatchJobChunkRow(job_id=job.id, chunk=k, first_case=first, cases=cases, input_zlib=data)
        )
    return job


def get_job(session: Session, job_id: str) -> BatchJobRow:
    """The job, or 404."""
    job = session.get(BatchJobRow, job_id)
    if job is None:
        raise not_found(["path", "job_id"], "unknown_job", job_id=job_id)
    return job


def job_body(session: Session, job: BatchJobRow, *, now: datetime | None = None) -> dict[str, Any]:
    """The job resource (``schemas.jobs.BatchJobOut``): where it stands, and when it
    will be done at the pace so far (``eta_s``: the time taken per case since it
    started, times the cases left)."""
    chunks_done, cases_done = session.execute(
        select(func.count(), func.coalesce(func.sum(BatchJobResultRow.cases), 0)).where(
            BatchJobResultRow.job_id == job.id
        )
    ).one()
    versions = session.scalars(
        select(BatchJobResultRow.catalogue_version)
        .where(BatchJobResultRow.job_id == job.id)
        .distinct()
    ).all()
    now = now or datetime.now(UTC)
    eta_s: float | None = None
    if job.state == "running" and job.started_at is not None and cases_done:
        elapsed = (now - _aware(job.started_at)).total_seconds()
        eta_s = round(elapsed / cases_done * (job.cases - cases_done), 1)
    elif job.state == "done":
        eta_s = 0.0
    return {
        "id": job.id,
        "state": job.state,
        "cases": job.cases,
        "cases_done": int(cases_done),
        "chunks": job.chunks,
        "chunks_done": int(chunks_done),
        "progress": round(int(cases_done) / job.cases, 4) if job.cases else 1.0,
        "eta_s": eta_s,
        "top": job.options["top"],
        "include_checks": job.options["include_checks"],
        "catalogue_version": job.catalogue_version,
        "catalogue_versions": sorted(versions),
        "created_at": _aware(job.created_at),
        "started_at": _aware(job.started_at) if job.started_at else None,
        "finished_at": _aware(job.finished_at) if job.finished_at else None,
        "error": job.error,
    }


def _aware(moment: datetime) -> datetime:
    """SQLite gives back naive datetimes; they were written in UTC."""
    return moment if moment.tzinfo is not None else moment.replace(tzinfo=UTC)


def cancel_job(session: Session, job_id: str) -> BatchJobRow:
    """Stop a queued or running job: no chunk is computed or written after this
    commits, and its cases and partial answers are dropped. A finished job: 409."""
    job = session.execute(
        select(BatchJobRow).where(BatchJobRow.id == job_id).with_for_update()
    ).scalar_one_or_none()
    if job is None:
        raise not_found(["path", "job_id"], "unknown_job", job_id=job_id)
    if job.state not in ACTIVE:
        raise conflict(["path", "job_id"], "job_finished", "job_finished", state=job.state)
    job.state = "cancelled"
    job.finished_at = datetime.now(UTC)
    _drop_data(session, job_id)
    return job


def delete_job(session: Session, job_id: str) -> None:
    """Delete the job with its cases and answers (a running one stops: its chunks find
    no job)."""
    job = session.execute(
        select(BatchJobRow).where(BatchJobRow.id == job_id).with_for_update()
    ).scalar_one_or_none()
    if job is None:
        raise not_found(["path", "job_id"], "unknown_job", job_id=job_id)
    _drop_data(session, job_id)
    session.delete(job)


def _drop_data(session: Session, job_id: str) -> None:
    session.execute(delete(BatchJobChunkRow).where(BatchJobChunkRow.job_id == job_id))
    session.execute(delete(BatchJobResultRow).where(BatchJobResultRow.job_id == job_id))


def require_done(job: BatchJobRow) -> None:
    """409 unless the job's answers are all written."""
    if job.state != "done":
        raise conflict(["path", "job_id"], "job_not_done", "job_not_done", state=job.state)


def result_lines(factory: sessionmaker[Session], job: BatchJobRow) -> Iterator[bytes]:
    """The answers of a done job as JSON lines, chunk by chunk in the order of the cases,
    each read in a short transaction of its own: memory stays at one chunk."""
    for chunk in range(job.chunks):
        with factory.begin() as session:
            data = session.scalar(
                select(BatchJobResultRow.lines_zlib).where(
                    BatchJobResultRow.job_id == job.id, BatchJobResultRow.chunk == chunk
                )
            )
        if data is None:  # deleted while it was read
            return
        yield zlib.decompress(data)


CSV_CASE_FIELDS = ("case", "case_id", "cycle_time_s", "mean_speed_rpm", "duty_cycle_percent")
"""The CSV's columns of the case (the JSON lines' names)."""
CSV_CANDIDATE_FIELDS = ("rank", *CandidateFigures.model_fields, "controllers_excluded")
"""The CSV's columns of each candidate: its rank in the case (1 the best), and the figures
every form of a candidate states first."""


def result_csv(lines: Iterator[bytes]) -> Iterator[bytes]:
    """:func:`result_lines` as CSV, a row per candidate (a case without one: a row with
    its candidate's columns empty), chunk by chunk."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow((*CSV_CASE_FIELDS, *CSV_CANDIDATE_FIELDS))
    for chunk in lines:
        for line in chunk.splitlines():
            result = pydantic_core.from_json(line)
            case = [result[name] for name in CSV_CASE_FIELDS]
            candidates = result["candidates"] or [None]
            for rank, candidate in enumerate(candidates, start=1):
                if candidate is None:
                    writer.writerow(case)
                else:
                    figures = [candidate[name] for name in CSV_CANDIDATE_FIELDS[1:]]
                    writer.writerow((*case, rank, *figures))
        yield buffer.getvalue().encode()
        buffer.seek(0)
        buffer.truncate()


WORKER_NAME = f"{socket.gethostname()}:{os.getpid()}"
"""Who computes a chunk, as its answer's row records it."""


def run_chunk(
    factory: sessionmaker[Session],
    catalogue: CatalogueCache,
    localizer: Callable[[str], Localize],
    job_id: str,
    chunk: int,
) -> bool:
    """Compute chunk ``chunk`` of the job and write its answer unless it is written
    already or the job is no longer active; True when this call wrote it.

    The answer is computed (and compressed) outside any transaction and written in a
    short one, which marks the job done when its last chunk is in.
    """
    with factory.begin() as session:
        begin_write(session)
        job = session.get(BatchJobRow, job_id)
        if job is None or job.state not in ACTIVE:
            return False
        if session.get(BatchJobResultRow, (job_id, chunk)) is not None:
            return False
        row = session.get(BatchJobChunkRow, (job_id, chunk))
        if row is None:
            return False
        if job.state == "queued":
            job.state = "running"
            job.started_at = datetime.now(UTC)
        options = dict(job.options)
        first, data = row.first_case, row.input_zlib
        snapshot = catalogue.snapshot(session)
    try:
        lines = chunk_answer(snapshot, options, zlib.decompress(data), first, localizer)
    except Exception as exc:  # a fault in the computation fails the job, not the queue
        _fail(factory, job_id, f"chunk {chunk}: {type(exc).__name__}: {exc}")
        return False
    # compressed before the job's row is locked: another worker's chunk waits on that lock
    packed, cases = zlib.compress(lines, ZLIB_LEVEL), lines.count(b"\n")
    with factory.begin() as session:
        begin_write(session)
        job = session.execute(
            select(BatchJobRow).where(BatchJobRow.id == job_id).with_for_update()
        ).scalar_one_or_none()
        if job is None or job.state not in ACTIVE:
            return False
        if session.get(BatchJobResultRow, (job_id, chunk)) is not None:
            return False
        session.add(
            BatchJobResultRow(
                job_id=job_id,
                chunk=chunk,
                cases=cases,
                catalogue_version=snapshot.version,
                worker=WORKER_NAME,
                created_at=datetime.now(UTC),
                lines_zlib=packed,
            )
        )
        session.flush()
        written = session.scalar(select(func.count()).where(BatchJobResultRow.job_id == job_id))
        if written == job.chunks:
            job.state = "done"
            job.finished_at = datetime.now(UTC)
    return True


def _fail(factory: sessionmaker[Session], job_id: str, error: str) -> None:
    with factory.begin() as session:
        begin_write(session)
        job = session.get(BatchJobRow, job_id)
        if job is not None and job.state in ACTIVE:
            job.state = "failed"
            job.error = error[:2000]
            job.finished_at = datetime.now(UTC)


def chunk_answer(
    catalogue: CatalogueSnapshot,
    options: dict[str, Any],
    cases_json: bytes,
    first_case: int,
    localizer: Callable[[str], Localize],
) -> bytes:
    """A chunk's answer as JSON lines: each case's result of the batch engine in the
    job's language (``services.batch.worded_results``, the one place a job calls it),
    with ``case``, the case's index in the job, first."""
    cases = [BatchCaseIn.model_validate_json(line) for line in cases_json.split(b"\n")]
    body = BatchSelectionRequest(
        cases=cases,
        top=options["top"],
        include_checks=options["include_checks"],
        include_messages=True,  # a job's results are in its language (options["language"])
    )
    apps = [case.to_core() for case in body.cases]
    results = worded_results(
        body, apps, catalogue=catalogue, localize=localizer(options["language"])
    )
    # each result is a JSON object: "case" goes in after its brace
    return b"".join(
        b'{"case":%d,%b\n' % (first_case + k, result[1:]) for k, result in enumerate(results)
    )


def pending_chunks(session: Session, limit: int = 64) -> list[tuple[str, int]]:
    """Chunks of active jobs without an answer, oldest job first (the in-process queue's
    work list)."""
    rows = session.execute(
        select(BatchJobChunkRow.job_id, BatchJobChunkRow.chunk)
        .join(BatchJobRow, BatchJobRow.id == BatchJobChunkRow.job_id)
        .outerjoin(
            BatchJobResultRow,
            (BatchJobResultRow.job_id == BatchJobChunkRow.job_id)
            & (BatchJobResultRow.chunk == BatchJobChunkRow.chunk),
        )
        .where(BatchJobRow.state.in_(ACTIVE), BatchJobResultRow.job_id.is_(None))
        .order_by(BatchJobRow.created_at, BatchJobChunkRow.chunk)
        .limit(limit)
    ).all()
    return [(job_id, chunk) for job_id, chunk in rows]
