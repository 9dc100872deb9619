"""FastAPI dependencies: the request's database session, the settings, the catalogue."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Annotated, Any, Literal, TypeVar

from fastapi import Depends, Header, Query, Request
from fastapi.routing import RouteContext, iter_route_contexts
from sqlalchemy.orm import Session, sessionmaker

from actuator_selection.config import Settings
from actuator_selection.db.engine import begin_write
from actuator_selection.documents.quote_document_text import Language, negotiate_language
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot

SAFE_METHODS = frozenset({"GET", "HEAD", "OPTIONS"})
_READS_ONLY = "__reads_only__"

Endpoint = TypeVar("Endpoint", bound=Callable[..., Any])


def reads_only(endpoint: Endpoint) -> Endpoint:
    """Mark a POST endpoint that computes without writing (tools, an unstored batch).

    Its transaction then begins as a reader: on SQLite it does not take the write
    lock, so it neither waits for writers nor holds them up.
    """
    setattr(endpoint, _READS_ONLY, True)
    return endpoint


def is_reads_only(endpoint: object) -> bool:
    """True when ``endpoint`` is marked :func:`reads_only`."""
    return bool(getattr(endpoint, _READS_ONLY, False))


def _writes(request: Request) -> bool:
    endpoint = request.scope.get("endpoint")
    return request.method not in SAFE_METHODS and not getattr(endpoint, _READS_ONLY, False)


def get_session(request: Request) -> Iterator[Session]:
    """One transaction per request, committed before the answer is sent.

    The dependency has ``scope="function"``: FastAPI runs its teardown when the
    endpoint returns, before the response is sent (a default-scoped ``yield``
    dependency's teardown runs after the response has gone out, which would
    acknowledge writes not yet committed). A commit that fails is therefore an
    error answer, never a 2xx. Only this dependency commits; repositories flush at
    most. Requests that write (every method but GET/HEAD/OPTIONS, except endpoints
    marked :func:`reads_only`) begin as writers (:func:`~actuator_selection.db.engine.begin_write`).
    """
    factory: sessionmaker[Session] = request.app.state.session_factory
    with factory() as session:
        try:
            if _writes(request):
                begin_write(session)
            yield session
            session.commit()
        except BaseException:
            session.rollback()
            raise


SessionDep = Annotated[Session, Depends(get_session, scope="function")]


@contextmanager
def write_transaction(request: Request) -> Iterator[Session]:
    """A short write transaction of its own, committed when the block ends.

    For endpoints that compute from a read snapshot (:func:`reads_only`) and then
    store the result: the write lock (SQLite) or the row locks (PostgreSQL) are
    held for the inserts alone, not for the computation. The block ends before the
    endpoint returns, so its commit precedes the answer like the request's own.
    """
    factory: sessionmaker[Session] = request.app.state.session_factory
    with factory.begin() as session:
        yield begin_write(session)


@contextmanager
def read_transaction(request: Request) -> Iterator[Session]:
    """A short read transaction of its own, ended when the block ends."""
    factory: sessionmaker[Session] = request.app.state.session_factory
    with factory.begin() as session:
        yield session


async def document_language(
    lang: Annotated[
        Literal["de", "en"] | None,
        Query(description="the document's language; left out: from Accept-Language, else en"),
    ] = None,
    accept_language: Annotated[str | None, Header(include_in_schema=False)] = None,
) -> Language:
    """The language of a document (quote, report): ``?lang=``, else ``Accept-Language``."""
    return negotiate_language(lang, accept_language)


DocumentLanguageDep = Annotated[Language, Depends(document_language)]


def app_settings(request: Request) -> Settings:
    """The settings the app was built with (``create_app(settings)``)."""
    settings: Settings = request.app.state.settings
    return settings


SettingsDep = Annotated[Settings, Depends(app_settings)]


def catalogue_snapshot(request: Request, session: Session) -> CatalogueSnapshot:
    """The catalogue at the version ``session`` pins, from the app's in-memory cache.

    The read transaction ends here: the snapshot is in memory, and holding the
    version's share lock while a large batch computes would only hold up catalogue
    changes (they wait for it, up to the lock timeout).
    """
    cache: CatalogueCache = request.app.state.catalogue
    snapshot = cache.snapshot(session)
    session.commit()
    return snapshot


def route_path(request: Request, name: str, **params: str) -> str:
    """The path of the route called ``name`` with ``params`` (a 201's ``Location``), as
    ``app.url_path_for`` builds it; the route is found once per application, not by asking
    every route at each call (which cost as much as a small request's own work)."""
    named: dict[str, RouteContext] | None = getattr(request.app.state, "named_routes", None)
    if named is None:
        named = {}
        for route in iter_route_contexts(request.app.router.routes):
            if route.name is not None:
                named.setdefault(route.name, route)
        request.app.state.named_routes = named
    return str(named[name].url_path_for(name, **params))
