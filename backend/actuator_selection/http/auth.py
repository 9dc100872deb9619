"""API keys on requests: ``Authorization: Bearer <key>``, roles ``admin`` and ``sales``.

- No key: anonymous. Anonymous callers may read the catalogue and run selections
  unless ``Settings.require_api_key`` (``REQUIRE_API_KEY``) is set.
- A key that is unknown, revoked or malformed: 401 with ``WWW-Authenticate:
  Bearer`` and one and the same body, so the answer never tells whether a key
  exists. A bad key is refused even on open endpoints.
- A valid key without the role an endpoint needs: 403. Roles do not include
  each other: an ``admin`` key manages the catalogue, prices and keys; a
  ``sales`` key makes quotes.

Mount ``dependencies=[Depends(require_reader)]`` on the open routers and use
``require_role("admin")`` / ``require_role("sales")`` on the others.
"""

from __future__ import annotations

from collections.abc import Awaitable, Callable
from typing import Annotated

from fastapi import Depends, Request
from starlette.concurrency import run_in_threadpool

from actuator_selection.config import Settings, get_settings
from actuator_selection.db.sales import ApiKeyRepository
from actuator_selection.http.deps import read_transaction
from actuator_selection.http.errors import ForbiddenError, UnauthorizedError, service_error
from actuator_selection.http.throttle import KeyFailureThrottle
from actuator_selection.sales.records import ApiKeyRecord

CHALLENGE = {"WWW-Authenticate": 'Bearer realm="actuator-selection"'}


def _unauthorized() -> UnauthorizedError:
    return UnauthorizedError(
        [service_error(["header", "Authorization"], "unauthorized", "unauthorized")],
        headers=CHALLENGE,
    )


def request_settings(request: Request) -> Settings:
    """The settings the app was built with (``app.state.settings``), else the environment's."""
    settings = getattr(request.app.state, "settings", None)
    return settings if isinstance(settings, Settings) else get_settings()


async def get_principal(request: Request) -> ApiKeyRecord | None:
    """The caller's API key; None without an Authorization header; 401 for a bad key,
    429 after too many from the client's address (``http/throttle.py``).

    Asynchronous, so that a request without a key costs no trip through the thread pool;
    a key is looked up in a short read transaction of its own, in the pool.
    """
    header = request.headers.get("authorization")
    if header is None:
        return None
    throttle: KeyFailureThrottle = request.app.state.key_failures
    address = request.client.host if request.client is not None else ""
    throttle.check(address)  # 429 while this address has sent too many wrong keys
    scheme, _, key = header.partition(" ")
    principal = None
    if scheme.lower() == "bearer" and key.strip():
        principal = await run_in_threadpool(_authenticate, request, key.strip())
    if principal is None:
        throttle.failed(address)
        raise _unauthorized()
    return principal


def _authenticate(request: Request, key: str) -> ApiKeyRecord | None:
    with read_transaction(request) as session:
        return ApiKeyRepository(session).authenticate(key)


PrincipalDep = Annotated[ApiKeyRecord | None, Depends(get_principal)]


async def require_reader(request: Request, principal: PrincipalDep) -> ApiKeyRecord | None:
    """Catalogue reads and selections: anyone, unless the settings require a key."""
    if principal is None and request_settings(request).require_api_key:
        raise _unauthorized()
    return principal


def authorize(principal: ApiKeyRecord | None, *roles: str) -> ApiKeyRecord:
    """``principal`` when it has one of ``roles``; 401 without a key, 403 otherwise."""
    if principal is None:
        raise _unauthorized()
    if principal.role not in roles:
        raise ForbiddenError(
            [
                service_error(
                    ["header", "Authorization"],
                    "forbidden",
                    "forbidden",
                    role=principal.role,
                    roles=list(roles),
                )
            ]
        )
    return principal


ROLES_ATTRIBUTE = "__api_key_roles__"
"""Set on each :func:`require_role` dependency: the roles it admits (read by
``http/openapi.py``, beside it)."""


def require_role(*roles: str) -> Callable[..., Awaitable[ApiKeyRecord]]:
    """A dependency admitting only keys of one of ``roles`` (401 without a key, 403 otherwise)."""

    async def dependency(principal: PrincipalDep) -> ApiKeyRecord:
        return authorize(principal, *roles)

    dependency.__name__ = f"require_{'_or_'.join(roles)}"
    setattr(dependency, ROLES_ATTRIBUTE, roles)
    return dependency


AdminDep = Annotated[ApiKeyRecord, Depends(require_role("admin"))]
SalesDep = Annotated[ApiKeyRecord, Depends(require_role("sales"))]
PriceReaderDep = Annotated[ApiKeyRecord, Depends(require_role("admin", "sales"))]
