"""Where batch jobs' chunks wait for a worker: procrastinate on PostgreSQL, a thread on SQLite.

**PostgreSQL.** Each chunk is a task of procrastinate's queue (its tables are created by
``migrate``, migration 0010), deferred when the job is accepted. ``python -m
actuator_selection worker`` runs a worker: on any number of machines, each takes the
next task (``FOR UPDATE SKIP LOCKED``), computes the chunk (``services.jobs.run_chunk``)
and reports every third of ``JOB_STALLED_AFTER_S``. A worker silent for longer is taken
for dead: every worker looks for such stalled tasks as often and puts them back in the
queue, so a chunk whose worker was killed runs again elsewhere. No new server to run:
the queue is the database's.

**SQLite** (the embedded default) has no queue of its own: each server process runs a
thread that computes the chunks still without an answer, oldest job first, woken when a
job is accepted and once a second otherwise. The API is the same.
"""

from __future__ import annotations

import asyncio
import logging
import threading
from collections.abc import Callable
from typing import Protocol

import procrastinate
from procrastinate.types import JSONValue
from sqlalchemy.engine import make_url
from sqlalchemy.orm import Session, sessionmaker

from actuator_selection.config import EngineLimits
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.schemas.checks import Localize
from actuator_selection.services import jobs
from actuator_selection.services.catalogue import CatalogueCache

TASK_NAME = "actuator_selection.run_chunk"
QUEUE_NAME = "batch_jobs"
RETRY = procrastinate.RetryStrategy(max_attempts=10, wait=2)
"""A chunk whose run fails (the database away for a moment) is tried again; a fault in
the computation itself fails the job instead (``services.jobs.run_chunk``)."""
IDLE_POLL_S = 1.0
"""How often the in-process queue looks for work when nobody wakes it."""

log = logging.getLogger(__name__)


class JobQueue(Protocol):
    """Takes the chunks of an accepted job."""

    def enqueue(self, job_id: str, chunks: int) -> None: ...

    def close(self) -> None: ...


def libpq_url(database_url: str) -> str:
    """A SQLAlchemy PostgreSQL URL as libpq reads it.

    >>> libpq_url("postgresql+psycopg://postgres@127.0.0.1:5432/test")
    'postgresql://postgres@127.0.0.1:5432/test'
    """
    url = make_url(database_url).set(drivername="postgresql")
    return url.render_as_string(hide_password=False)


def procrastinate_app(database_url: str) -> procrastinate.App:
    """The procrastinate app on ``database_url`` (not opened)."""
    connector = procrastinate.PsycopgConnector(conninfo=libpq_url(database_url))
    return procrastinate.App(connector=connector)


class ProcrastinateQueue:
    """Defers each chunk as a task of procrastinate's queue (PostgreSQL)."""

    def __init__(self, database_url: str) -> None:
        self._app = procrastinate_app(database_url)
        self._opened = False
        self._lock = threading.Lock()

    def enqueue(self, job_id: str, chunks: int) -> None:
        with self._lock:
            if not self._opened:
                self._app.open()
                self._opened = True
        task = self._app.configure_task(TASK_NAME, queue=QUEUE_NAME)
        args: list[dict[str, JSONValue]] = [{"job_id": job_id, "chunk": k} for k in range(chunks)]
        task.batch_defer(*args)

    def close(self) -> None:
        with self._lock:
            if self._opened:
                self._app.close()
                self._opened = False


class InProcessQueue:
    """Computes the chunks in a thread of this process (SQLite)."""

    def __init__(
        self,
        database_url: str,
        catalogue: CatalogueCache,
        localizer: Callable[[str], Localize],
    ) -> None:
        # An engine of its own: the thread reads and writes committed state only, as a
        # worker elsewhere would, never a request's transaction.
        self._engine = make_engine(database_url, EngineLimits(pool_size=2))
        factory = self._factory = make_session_factory(self._engine)
        self._catalogue = catalogue
        self._localizer = localizer
        self._wake = threading.Event()
        self._stop = threading.Event()
        self._lock = threading.Lock()
        self._thread: threading.Thread | None = None
        try:  # work left by a process that ended: resume it now
            with factory.begin() as session:
                if jobs.pending_chunks(session, limit=1):
                    self._start()
        except Exception:
            log.exception("batch jobs: could not look for unfinished jobs at start")

    def _start(self) -> None:
        """The thread, started at the first job (a process that never gets one has none)."""
        with self._lock:
            if self._thread is None:
                self._thread = threading.Thread(target=self._run, name="batch-jobs", daemon=True)
                self._thread.start()

    def enqueue(self, job_id: str, chunks: int) -> None:
        self._start()
        self._wake.set()

    def close(self) -> None:
        self._stop.set()
        self._wake.set()
        if self._thread is not None:
            self._thread.join(30)
        self._engine.dispose()

    def _run(self) -> None:
        while not self._stop.is_set():
            try:
                with self._factory.begin() as session:
                    work = jobs.pending_chunks(session)
                for job_id, chunk in work:
                    if self._stop.is_set():
                        return
                    jobs.run_chunk(self._factory, self._catalogue, self._localizer, job_id, chunk)
            except Exception:  # the database away: log, and look again later
                log.exception("batch jobs: a chunk could not be run; trying again")
                work = []
            if not work:
                self._wake.wait(IDLE_POLL_S)
                self._wake.clear()


def job_queue(
    database_url: str, catalogue: CatalogueCache, localizer: Callable[[str], Localize]
) -> JobQueue:
    """procrastinate's queue on PostgreSQL, the in-process one otherwise."""
    if make_url(database_url).get_backend_name() == "postgresql":
        return ProcrastinateQueue(database_url)
    return InProcessQueue(database_url, catalogue, localizer)


def run_worker(
    database_url: str,
    factory: sessionmaker[Session],
    localizer: Callable[[str], Localize],
    *,
    concurrency: int,
    stalled_after_s: float,
) -> None:
    """Run a procrastinate worker for batch jobs until SIGINT or SIGTERM."""
    app = procrastinate_app(database_url)
    catalogue = CatalogueCache()

    @app.task(name=TASK_NAME, queue=QUEUE_NAME, retry=RETRY)
    def run_chunk(job_id: str, chunk: int) -> None:
        jobs.run_chunk(factory, catalogue, localizer, job_id, chunk)

    async def main() -> None:
        async with app.open_async():
            sweeper = asyncio.create_task(_retry_stalled(app, stalled_after_s))
            try:
                await app.run_worker_async(
                    queues=[QUEUE_NAME],
                    concurrency=concurrency,
                    update_heartbeat_interval=stalled_after_s / 3,
                    stalled_worker_timeout=stalled_after_s,
                    delete_jobs="successful",
                )
            finally:
                sweeper.cancel()

    asyncio.run(main())


async def _retry_stalled(app: procrastinate.App, stalled_after_s: float) -> None:
    """Put the tasks of workers silent for ``stalled_after_s`` back in the queue, every
    third of that (procrastinate's recipe for stalled jobs)."""
    while True:
        await asyncio.sleep(stalled_after_s / 3)
        try:
            for job in await app.job_manager.get_stalled_jobs(
                queue=QUEUE_NAME, seconds_since_heartbeat=stalled_after_s
            ):
                log.warning("batch jobs: task %s stalled (worker gone); queued again", job.id)
                await app.job_manager.retry_job(job)
        except Exception:
            log.exception("batch jobs: stalled tasks could not be looked for")
