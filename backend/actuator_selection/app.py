"""The ASGI application: API routers, error handlers, the static web page."""

from __future__ import annotations

import ctypes
import gc
from collections.abc import AsyncIterator
from contextlib import asynccontextmanager
from types import ModuleType

from fastapi import Depends, FastAPI
from fastapi_offline import FastAPIOffline
from starlette_compress import CompressMiddleware, add_compress_type

from actuator_selection import __version__
from actuator_selection.api import (
    aas,
    actuators,
    admin,
    auth,
    batch,
    controllers,
    health,
    jobs,
    mechanisms,
    prices,
    profiles,
    projects,
    quotes,
    selections,
    tools,
)
from actuator_selection.config import FRONTEND_DIR, Settings, get_settings
from actuator_selection.db.availability import Availability
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.http import (
    admission,
    errors,
    media_types,
    methods,
    openapi,
    security_headers,
    static,
    throttle,
)
from actuator_selection.http.auth import require_reader
from actuator_selection.i18n.localize import localizer
from actuator_selection.job_queue import job_queue
from actuator_selection.services.catalogue import CatalogueCache
from actuator_selection.services.link_secret import link_secret
from actuator_selection.supervision import exit_with_supervisor

API_PREFIX = "/api/v1"
DOCS_PATHS = ("/docs", "/redoc", "/docs/oauth2-redirect")
"""The API documentation pages (fastapi-offline's defaults)."""


GC_THRESHOLDS = (50_000, 20, 100)
"""The cyclic garbage collector's thresholds in a served process (Python's are 700, 10, 10).

A batch of 20,000 cases allocates about 10⁶ container objects that live until their
slice of the answer is written, and a whole-catalogue selection about 2·10⁴; at the
default thresholds the collector walked them again and again (a 20,000-case batch:
3.6 s, against 2.6 s with collection paused). These thresholds make collections rare
but keep them, so cycles are still freed: 2.7 s.
"""


ZSTD_LEVEL = 1
"""zstd level of answers compressed on the way out, for clients that accept zstd
(browsers since 2024; httpx with ``zstandard``). The 10,000-case batch as columns with
its checks, 11.5 MB of JSON: 13 ms for 2.7 MB, against 67 ms for 3.1 MB with gzip at
level 1 (a fifth of the request's server time)."""

GZIP_LEVEL = 1
"""gzip level of answers compressed on the way out for clients that accept gzip but not
zstd: the fastest, as the stored selections' (``services.selections.STORE_COMPRESSION``).
On a 58.5 MB batch answer 0.2 s for 7.2 MB, against 0.64 s for 4.9 MB at level 9."""

COMPRESSED_TYPES = ("text/csv",)
"""Media types compressed beside starlette-compress's own list (JSON, HTML, CSS,
JavaScript, plain text): the candidates as CSV."""


_M_TRIM_THRESHOLD, _M_MMAP_THRESHOLD = -1, -3  # glibc's malloc.h
MALLOC_OPTIONS = ((_M_MMAP_THRESHOLD, 32 << 20), (_M_TRIM_THRESHOLD, 16 << 20))
"""glibc ``mallopt`` settings of a served process: ``M_MMAP_THRESHOLD`` 32 MiB (the
largest glibc's own adjustment reaches) and ``M_TRIM_THRESHOLD`` 16 MiB. The engine's
temporaries of a block (65,536 cells: 512 KiB each) were handed back to the kernel and
faulted in again, page by page, numpy call after numpy call: the 10,000-case batch as
columns with its checks spent about a tenth of its time there (in process: 176 → 153 ms
with a 64 MiB trim threshold; peak RSS unchanged). A block's temporaries (a few MiB) stay below
the trim threshold; free memory above a heap's top beyond 16 MiB is handed back, and
arrays over 32 MiB are still mapped on their own. 64 MiB, the first setting, kept each
arena's freed top: a served process idle after 30 s of mixed load by 32 clients (per-case
and columns batches, whole-catalogue selections) held 598–609 MB against 339–408 MB
untuned and 360–399 MB with 16 MiB, for the same columns batch time (2026-11-28)."""


def tune_gc() -> None:
    """Set ``GC_THRESHOLDS`` for this process; the collector stays on."""
    gc.set_threshold(*GC_THRESHOLDS)


def tune_allocator() -> bool:
    """Set :data:`MALLOC_OPTIONS` for this process where the C library is glibc (True);
    elsewhere leave the allocator as it is (False)."""
    try:
        mallopt = ctypes.CDLL(None).mallopt
    except (AttributeError, OSError):
        return False
    return all(mallopt(option, value) == 1 for option, value in MALLOC_OPTIONS)


def tune_process() -> bool:
    """The collector and the allocator tuned once for a process that sizes batches
    (:func:`tune_gc`, :func:`tune_allocator`): each of ``serve``'s worker processes
    (:func:`serve_app`) and each job ``worker``, whose chunks are the same batch engine's
    work (a chunk of 2,000 cases without checks, in process: 0.42 → 0.32 s of CPU). True
    where the allocator was tuned (glibc)."""
    tune_gc()
    return tune_allocator()


def serve_app() -> FastAPI:
    """The app as ``serve`` runs it, in each worker process: the process tuned
    (:func:`tune_process`), the worker bound to its supervisor's life
    (:func:`~actuator_selection.supervision.exit_with_supervisor`), then :func:`create_app`."""
    tune_process()
    exit_with_supervisor()
    return create_app()


def create_app(settings: Settings | None = None) -> FastAPI:
    """Build the application for ``settings`` (default: from the environment)."""
    settings = settings or get_settings()
    engine = make_engine(settings.database_url, settings.engine_limits())
    Availability().watch(engine)  # one log line per outage and per recovery

    @asynccontextmanager
    async def lifespan(app: FastAPI) -> AsyncIterator[None]:
        # batch jobs' chunks: procrastinate's queue (PostgreSQL) or a thread here (SQLite)
        app.state.job_queue = job_queue(settings.database_url, app.state.catalogue, localizer)
        yield
        app.state.job_queue.close()
        engine.dispose()

    # Swagger UI (/docs) and ReDoc (/redoc) from the assets fastapi-offline ships: the
    # documentation works without internet, like the pages.
    app = FastAPIOffline(
        title="Actuator selection service",
        version=__version__,
        summary="Sizes Harmonic Drive servo actuators for a motion cycle "
        "(Engineering Data for Harmonic Drive Servo Actuators, Eq. 514.1–522.3).",
        lifespan=lifespan,
        # operationIds are the endpoints' names (create_selection), for client generators.
        generate_unique_id_function=openapi.operation_id,
        # 415 for a JSON body sent as another media type or in UTF-16/32 (http/media_types.py)
        dependencies=[Depends(media_types.require_json_body)],
        servers=openapi.servers(settings.public_base_url),
    )
    app.state.engine = engine
    app.state.session_factory = make_session_factory(engine)
    app.state.catalogue = CatalogueCache()  # selections read the catalogue from here
    app.state.settings = settings  # require_reader reads REQUIRE_API_KEY from here
    app.state.key_failures = throttle.KeyFailureThrottle(  # wrong keys per address: 429
        settings.max_key_failures, settings.key_failure_window_s
    )
    app.state.link_secret = link_secret(settings)  # signs document links (api/quotes.py)
    errors.install(app)
    app.include_router(health.router, prefix=API_PREFIX)
    # Catalogue reads, selections and tools: open unless REQUIRE_API_KEY; batch before
    # selections so that /selections/batch is not read as a selection id. Selections
    # first: FastAPI asks the routes in turn (with the catalogue's before them, a
    # one-model selection spent ~0.3 M instructions finding its route, docs/benchmarks.md).
    # Body limits per router (413 above): bulk endpoints (batch, catalogue and price
    # imports) take larger bodies. Set on the routers rather than the app so that the
    # 413 passes through errors.UniformBodyTooLarge, which gives it the error shape.
    bulk = {batch, admin, prices, profiles}

    def body_limit(module: ModuleType) -> int:
        if module is jobs:  # a million cases as JSON lines
            return settings.max_job_body_bytes
        return settings.max_bulk_body_bytes if module in bulk else settings.max_body_bytes

    for module in (
        batch,
        selections,
        actuators,
        controllers,
        mechanisms,
        jobs,
        aas,
        profiles,
        tools,
        projects,
    ):
        app.include_router(
            module.router,
            prefix=API_PREFIX,
            dependencies=[Depends(require_reader)],
            max_body_size=body_limit(module),
        )
    # Keys, catalogue changes, prices, quotes: each route names the role it needs.
    for module in (auth, admin, prices, quotes):
        app.include_router(
            module.router,
            prefix=API_PREFIX,
            max_body_size=body_limit(module),
        )
    app.include_router(static.router)
    # zstd where the client accepts it, else gzip; answers compressed when they were
    # stored (a selection's, the plotly bundle) carry their encoding and pass as they are
    for media_type in COMPRESSED_TYPES:
        add_compress_type(media_type)
    app.add_middleware(
        CompressMiddleware,
        minimum_size=1024,
        zstd_level=ZSTD_LEVEL,
        brotli=False,
        gzip_level=GZIP_LEVEL,
    )
    # Outermost, so that a request waiting for its turn holds nothing else.
    app.add_middleware(
        admission.AdmissionControl,
        max_concurrent=settings.max_concurrent_requests,
        max_queued=settings.max_queued_requests,
        timeout_s=settings.queue_timeout_s,
        body_timeout_s=settings.body_timeout_s,
        max_body_bytes=max(settings.max_body_bytes, settings.max_bulk_body_bytes),
        larger_bodies=((f"{API_PREFIX}/batch-jobs", settings.max_job_body_bytes),),
    )
    # 405 and OPTIONS from the routes, not from the static mount; CORS where configured.
    app.add_middleware(methods.AllowedMethods, router=app.router, api_prefix=API_PREFIX)
    if settings.cors_origins():
        app.add_middleware(methods.PreflightForListedOrigins, origins=settings.cors_origins())
    if FRONTEND_DIR.is_dir():
        app.mount("/", static.FrontendFiles(directory=FRONTEND_DIR, html=True), name="frontend")
    security_headers.install(app, docs_paths=DOCS_PATHS)
    openapi.install(app)  # one error schema, security, examples (see http/openapi.py)
    return app
