"""Signed document links: a new browser window loads the quote document with its own CSP."""

from __future__ import annotations

from datetime import UTC, datetime
from typing import Any

from sqlalchemy import Connection
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.api.quotes import DOCUMENT_LINK_TTL_S
from actuator_selection.db.sales import ApiKeyRepository

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
