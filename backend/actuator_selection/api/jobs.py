"""Batch jobs: a million load cases accepted at once (202), computed by workers, read back.

The use case is ``services/jobs.py``, the queue ``job_queue.py``. The cases are the body
as JSON lines, one :class:`~actuator_selection.schemas.batch.BatchCaseIn` a line; every
line is checked before anything is stored, and an error names the line's index (from 0)
in ``loc``: ``["body", 12, "load", "speed_rpm"]``.
"""

from __future__ import annotations

from collections.abc import AsyncIterator
from email.message import Message
from typing import Any, Literal

import anyio
from fastapi import APIRouter, Query, Request, Response
from fastapi.exceptions import RequestValidationError
from fastapi.responses import JSONResponse, StreamingResponse
from pydantic import ValidationError

from actuator_selection.api.selections import unknown_models
from actuator_selection.db.engine import begin_write
from actuator_selection.errors import DomainError
from actuator_selection.http.deps import SessionDep, read_transaction, route_path
from actuator_selection.http.errors import RequestFieldError, domain_entry, language_of
from actuator_selection.http.media_types import unsupported_media_type
from actuator_selection.schemas.batch import MAX_TOP, BatchCaseIn
from actuator_selection.schemas.jobs import JOB_MEDIA_TYPES, NDJSON, BatchJobOut
from actuator_selection.services import jobs
from actuator_selection.services.jobs import JobIntake, JobOptions

router = APIRouter(tags=["batch jobs"])

MAX_ERRORS = 100
"""Errors answered for one job at most; the lines after the hundredth error are not
checked (fix these and send it again)."""

_JOB_PATH = "/batch-jobs/{job_id}"


def _media_type(request: Request) -> None:
    header = request.headers.get("content-type", "")
    message = Message()
    message["content-type"] = header
    media_type = message.get_content_type() if header.strip() else ""
    if media_type not in JOB_MEDIA_TYPES:
        raise unsupported_media_type(media_type, JOB_MEDIA_TYPES)


async def _line_batches(request: Request, size: int) -> AsyncIterator[list[bytes]]:
    """The body's non-blank lines, ``size`` at a time, as they arrive."""
    rest = b""
    batch: list[bytes] = []
    async for piece in request.stream():
        *complete, rest = (rest + piece).split(b"\n")
        for line in complete:
            if line.strip():
                batch.append(line)
                if len(batch) == size:
                    yield batch
                    batch = []
    if rest.strip():
        batch.append(rest)
    if batch:
        yield batch


class _Checker:
    """Each line as a case: pydantic's errors and the core's, each at its line's index."""

    def __init__(self, known: set[str], intake: JobIntake) -> None:
        self.known = known
        self.intake = intake
        self.index = 0
        self.invalid: list[dict[str, Any]] = []  # pydantic's error dicts
        self.refused: list[dict[str, Any]] = []  # entries of the error shape

    @property
    def full(self) -> bool:
        return len(self.invalid) + len(self.refused) >= MAX_ERRORS

    def check(self, lines: list[bytes]) -> None:
        for line in lines:
            i = self.index
            self.index += 1
            if self.full:
                return
            try:
                case = BatchCaseIn.model_validate_json(line)
            except ValidationError as exc:
                self.invalid += [
                    {**e, "loc": ("body", i, *e["loc"])} for e in exc.errors(include_url=False)
                ]
                continue
            before = len(self.refused)
            if case.models is not None:
                self.refused += unknown_models(["body", i, "models"], case.models, self.known)
            try:
                case.to_core()
            except DomainError as exc:
                self.refused.append(domain_entry(["body", i, *exc.field.split(".")], exc))
            if len(self.refused) == before:
                self.intake.add(line)


@router.post(
    "/batch-jobs",
    status_code=202,
    response_model=BatchJobOut,
    openapi_extra={
        "requestBody": {
            "required": True,
            "content": {
                NDJSON: {
                    "schema": {"$ref": "#/components/schemas/BatchCaseIn"},
                    "example": '{"load":{"speed_rpm":40,"torque_nm":5,"inertia_kgm2":1.3},'
                    '"cycle":{"accel_s":0.1,"constant_s":0.1,"decel_s":0.1,"pause_s":1.0}}\n',
                }
            },
        }
    },
    responses={
        202: {"description": "accepted; `Location` names the job, which workers now compute"},
        415: {"description": "a body that is not JSON lines"},
        422: {"description": "an invalid case (`loc` names its line, from 0), or no case"},
    },
    description="Accepts a batch of any size as a job: the body is JSON lines, each a load "
    "case exactly as one of POST /selections/batch's `cases`. Every case is checked before "
    "the job is stored; the job is then split into chunks that workers compute "
    "(GET the `Location` for the progress, GET its `/results` once done).",
)
async def create_batch_job(
    request: Request,
    top: int = Query(3, ge=1, le=MAX_TOP, description="best candidates answered per case"),
    include_checks: bool = Query(False, description="true adds each candidate's `checks`"),
) -> Response:
    """Start a batch job."""
    _media_type(request)
    settings = request.app.state.settings
    factory = request.app.state.session_factory

    def read_catalogue() -> tuple[int, set[str]]:
        with read_transaction(request) as session:
            snapshot = request.app.state.catalogue.snapshot(session)
            return snapshot.version, {a.model for a in snapshot.actuators}

    version, known = await anyio.to_thread.run_sync(read_catalogue)
    intake = JobIntake(settings.job_chunk_cases)
    checker = _Checker(known, intake)
    async for lines in _line_batches(request, settings.job_chunk_cases):
        await anyio.to_thread.run_sync(checker.check, lines)
    if checker.invalid:
        raise RequestValidationError(checker.invalid)
    if checker.refused:
        raise RequestFieldError(checker.refused)
    intake.close()
    options = JobOptions(
        top=top, include_checks=include_checks, language=language_of(request.scope)
    )

    def store() -> dict[str, Any]:
        # The answer is the job as committed, read before it is queued: once queued, a
        # worker (in this process on SQLite) may already have started it, and a 202
        # reading it back raced that worker ("running" in one CI run).
        with factory.begin() as session:
            begin_write(session)
            job = jobs.create_job(session, intake, options, version)
            job_id, chunks = job.id, job.chunks
            body = jobs.job_body(session, job)
        request.app.state.job_queue.enqueue(job_id, chunks)
        return body

    body = await anyio.to_thread.run_sync(store)
    location = route_path(request, "get_batch_job", job_id=body["id"])
    return JSONResponse(
        BatchJobOut.model_validate(body).model_dump(mode="json"),
        status_code=202,
        headers={"Location": location},
    )


@router.get(_JOB_PATH, response_model=BatchJobOut, responses={404: {"description": "no such job"}})
def get_batch_job(job_id: str, session: SessionDep) -> dict[str, Any]:
    """A batch job's state, progress and expected time to finish."""
    return jobs.job_body(session, jobs.get_job(session, job_id))


@router.get(
    f"{_JOB_PATH}/results",
    response_class=StreamingResponse,
    responses={
        200: {
            "description": "one line per case in the order sent: `case` (its line's index) "
            "and its result as in POST /selections/batch's `results`",
            "content": {NDJSON: {}, "text/csv": {}},
        },
        404: {"description": "no such job"},
        409: {"description": "the job is not done"},
    },
)
def get_batch_job_results(
    job_id: str,
    request: Request,
    session: SessionDep,
    format: Literal["jsonl", "csv"] = Query(
        "jsonl",
        description="`jsonl`: each case's result as one JSON line; `csv`: a row per "
        "candidate with the case's and the candidate's figures",
    ),
) -> Response:
    """A done job's answers as JSON lines or CSV, streamed."""
    job = jobs.get_job(session, job_id)
    jobs.require_done(job)
    session.commit()
    lines = jobs.result_lines(request.app.state.session_factory, job)
    body, media_type = (jobs.result_csv(lines), "text/csv") if format == "csv" else (lines, NDJSON)
    return StreamingResponse(
        body,
        media_type=media_type,
        headers={"Content-Disposition": f'attachment; filename="batch-job-{job.id}.{format}"'},
    )


@router.post(
    f"{_JOB_PATH}/cancel",
    response_model=BatchJobOut,
    responses={404: {"description": "no such job"}, 409: {"description": "the job has ended"}},
)
def cancel_batch_job(job_id: str, session: SessionDep) -> dict[str, Any]:
    """Stop a queued or running job; its cases and partial answers are dropped."""
    job = jobs.cancel_job(session, job_id)
    session.flush()
    return jobs.job_body(session, job)


@router.delete(_JOB_PATH, status_code=204, responses={404: {"description": "no such job"}})
def delete_batch_job(job_id: str, session: SessionDep) -> Response:
    """Delete a job with its cases and answers; a running one stops."""
    jobs.delete_job(session, job_id)
    return Response(status_code=204)
