"""Signed document links: a new browser window loads the quote document with its own CSP."""

from __future__ import annotations

import hashlib
import hmac
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path
from typing import Any
from urllib.parse import parse_qs, urlsplit

import pytest
from sqlalchemy import Connection, select
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.api.quotes import DOCUMENT_LINK_MAX_TTL_S, DOCUMENT_LINK_TTL_S
from actuator_selection.db.models.sales import ApiKeyRow
from actuator_selection.db.sales import ApiKeyRepository
from actuator_selection.sales.records import ApiKeyRecord
from actuator_selection.services.quotes import document_resource

__all__ = ["api", "sales_api_with"]


def _quote(api: SalesApi) -> str:
    selection = api.selection(models=["FHA-25C-50-L"])
    created = api.post("/api/v1/quotes", json=api.quote_body(selection["id"]))
    assert created.status_code == 201, created.text
    number: str = created.json()["number"]
    return number


def _link(api: SalesApi, number: str, role: str | None = "sales") -> Any:
    return api.post(f"/api/v1/quotes/{number}/document-link", role=role)


def test_a_link_opens_the_document_without_a_key_and_with_its_csp(api: SalesApi) -> None:
    number = _quote(api)
    link = _link(api, number)
    assert link.status_code == 200, link.text
    body = link.json()
    assert body["url"].startswith(f"/api/v1/quotes/{number}/document?access=")
    expires = datetime.fromisoformat(body["expires_at"])
    assert (expires - api.clock.now()).total_seconds() <= DOCUMENT_LINK_TTL_S
    document = api.get(body["url"], role=None)
    assert document.status_code == 200
    assert document.headers["content-type"].startswith("text/html")
    assert "default-src 'none'" in document.headers["content-security-policy"]
    assert number in document.text


def test_a_link_is_for_its_own_quote_only_and_cannot_be_altered(api: SalesApi) -> None:
    first, second = _quote(api), _quote(api)
    url = _link(api, first).json()["url"]
    other = url.replace(first, second)
    assert api.get(other, role=None).status_code == 401
    forged = url[:-1] + ("0" if url[-1] != "0" else "1")
    assert api.get(forged, role=None).status_code == 401
    assert api.get(url, role=None).status_code == 200


def test_a_link_expires(api: SalesApi) -> None:
    number = _quote(api)
    url = _link(api, number).json()["url"]
    api.clock.advance(days=1)
    response = api.get(url, role=None)
    assert response.status_code == 401
    (entry,) = response.json()["detail"]
    assert (entry["loc"], entry["type"]) == (["query", "access"], "link_invalid")
    assert "expired" in entry["msg"]


def test_revoking_the_key_revokes_its_links(api: SalesApi, connection: Connection) -> None:
    number = _quote(api)
    url = _link(api, number).json()["url"]
    with Session(bind=connection, join_transaction_mode="create_savepoint") as session:
        ApiKeyRepository(session).revoke(api.key_ids["sales"], now=datetime.now(UTC))
        session.commit()
    assert api.get(url, role=None).status_code == 401


def test_only_sales_keys_get_links(api: SalesApi) -> None:
    number = _quote(api)
    assert _link(api, number, role="admin").status_code == 403
    assert _link(api, number, role=None).status_code == 401
    assert _link(api, "Q-2000-99999").status_code == 404


# --- the signing secret and the lifetime cap (issue 26 item 6) -------------------------


def _access(url: str) -> tuple[str, str, str]:
    """``(prefix, expires_at, mac)`` of a link's token."""
    token = parse_qs(urlsplit(url).query)["access"][0]
    prefix, expires_at, mac = token.split(".")
    return prefix, expires_at, mac


def _with_token(url: str, token: str) -> str:
    path, query = url.split("?", 1)
    rest = [p for p in query.split("&") if not p.startswith("access=")]
    return f"{path}?{'&'.join([f'access={token}', *rest])}"


def test_the_stored_key_hash_does_not_sign_links(api: SalesApi, connection: Connection) -> None:
    """Whoever reads the api_keys table cannot mint a link: a token keyed with the stored
    hash (how links were signed until now, so such links stop working) is refused."""
    number = _quote(api)
    url = _link(api, number).json()["url"]
    prefix, _, _ = _access(url)
    key_sha256 = connection.execute(
        select(ApiKeyRow.key_sha256).where(ApiKeyRow.prefix == prefix)
    ).scalar_one()
    expires_at = int(api.clock.now().timestamp()) + 3600
    message = f"{document_resource(number)}|{expires_at}".encode()
    mac = hmac.new(key_sha256.encode("ascii"), message, hashlib.sha256).hexdigest()
    response = api.get(_with_token(url, f"{prefix}.{expires_at}.{mac}"), role=None)
    assert response.status_code == 401
    assert api.get(url, role=None).status_code == 200  # the service's own link works


def test_a_link_longer_than_the_cap_is_refused_when_presented(api: SalesApi) -> None:
    """Even signed with the server's secret, a token that expires further ahead than
    DOCUMENT_LINK_MAX_TTL_S was not made by this service: refused."""
    number = _quote(api)
    url = _link(api, number).json()["url"]
    prefix, _, _ = _access(url)
    secret: bytes = api.client.app.state.link_secret  # type: ignore[attr-defined]
    key = ApiKeyRecord(
        id=0,
        prefix=prefix,
        name="",
        role="sales",
        created_at=api.clock.now(),
        revoked_at=None,
    )
    now = int(api.clock.now().timestamp())

    def token(lifetime_s: int) -> str:
        return ApiKeyRepository.sign_access(
            key, document_resource(number), expires_at=now + lifetime_s, secret=secret
        )

    thirty_years = 30 * 365 * 24 * 3600
    assert api.get(_with_token(url, token(thirty_years)), role=None).status_code == 401
    over = DOCUMENT_LINK_MAX_TTL_S + 60
    assert api.get(_with_token(url, token(over)), role=None).status_code == 401
    under = DOCUMENT_LINK_MAX_TTL_S - 60
    assert api.get(_with_token(url, token(under)), role=None).status_code == 200


def test_a_link_asked_for_longer_than_the_cap_is_422(api: SalesApi) -> None:
    number = _quote(api)
    response = api.post(
        f"/api/v1/quotes/{number}/document-link",
        params={"lifetime_s": DOCUMENT_LINK_MAX_TTL_S + 1},
    )
    assert response.status_code == 422
    (entry,) = response.json()["detail"]
    assert entry["loc"] == ["query", "lifetime_s"]
    assert entry["code"] == "less_than_equal"
    assert entry["params"]["le"] == DOCUMENT_LINK_MAX_TTL_S


def test_a_link_works_for_the_lifetime_asked_for(api: SalesApi) -> None:
    number = _quote(api)
    week = 7 * 24 * 3600
    link = api.post(f"/api/v1/quotes/{number}/document-link", params={"lifetime_s": week})
    assert link.status_code == 200, link.text
    expires = datetime.fromisoformat(link.json()["expires_at"])
    assert (expires - api.clock.now()).total_seconds() == pytest.approx(week, abs=1)
    api.clock.advance(days=6)
    assert api.get(link.json()["url"], role=None).status_code == 200
    api.clock.advance(days=2)
    assert api.get(link.json()["url"], role=None).status_code == 401


def test_a_link_survives_a_restart(sales_api_with: Callable[..., SalesApi], tmp_path: Path) -> None:
    """The generated secret is kept in DATA_DIR: an app built again (a restart, another
    worker) accepts the first one's links; an app with another secret does not."""
    first = sales_api_with(data_dir=tmp_path)
    number = _quote(first)
    url = _link(first, number).json()["url"]
    again = sales_api_with(data_dir=tmp_path)
    assert again.get(url, role=None).status_code == 200
    other = sales_api_with(data_dir=tmp_path / "other")
    assert other.get(url, role=None).status_code == 401
