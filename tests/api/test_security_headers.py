"""Security headers (``http/security_headers.py``) on every kind of response.

The app is built here with ``create_app`` and the middleware installed by
``security_headers.install``, which does nothing a second time, so these tests
hold whether or not ``create_app`` installs it itself.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from html.parser import HTMLParser
from typing import Any

import pytest
from fastapi import FastAPI
from fastapi.responses import HTMLResponse
from fastapi.testclient import TestClient
from sqlalchemy import Connection, Engine
from sqlalchemy.orm import Session, sessionmaker
from tests.api._sales_fixtures import FakeClock, SalesApi, create_keys, load_example_prices

from actuator_selection.api.quotes import get_clock
from actuator_selection.app import create_app
from actuator_selection.config import FRONTEND_DIR, Settings
from actuator_selection.http import security_headers
from actuator_selection.http.security_headers import PAGE_CSP, inline_script_hashes

EVERY_RESPONSE = {
    "x-content-type-options": "nosniff",
    "referrer-policy": "no-referrer",
}


def _before_the_static_files(app: FastAPI) -> None:
    """Move the route added last before the frontend's mount at ``/``, which takes every path."""
    app.router.routes.insert(0, app.router.routes.pop())


def _app(seeded_engine: Engine, connection: Connection) -> FastAPI:
    app = create_app(Settings(database_url=seeded_engine.url.render_as_string(hide_password=False)))
    app.state.session_factory = sessionmaker(
        bind=connection, join_transaction_mode="create_savepoint", expire_on_commit=False
    )
    clock = FakeClock()
    app.dependency_overrides[get_clock] = lambda: clock

    @app.get("/test-only/boom", include_in_schema=False)
    def boom() -> None:
        raise RuntimeError("an unexpected error, answered by the error middleware")

    _before_the_static_files(app)

    security_headers.install(app)
    security_headers.install(app)  # a second call (e.g. create_app's own) changes nothing
    return app


@pytest.fixture
def secured(seeded_engine: Engine, connection: Connection) -> Iterator[SalesApi]:
    """The app with the security headers, API keys and example prices, rolled back after."""
    with Session(bind=connection, join_transaction_mode="create_savepoint") as session:
        keys, ids = create_keys(session)
        load_example_prices(session)
        session.commit()
    app = _app(seeded_engine, connection)
    with TestClient(app, raise_server_exceptions=False) as client:
        yield SalesApi(client=client, keys=keys, clock=FakeClock(), key_ids=ids)


def _assert_every_response_headers(response: Any) -> None:
    for name, value in EVERY_RESPONSE.items():
        assert response.headers.get_list(name) == [value], (name, response.headers)


def _directives(csp: str) -> dict[str, list[str]]:
    out: dict[str, list[str]] = {}
    for part in csp.split(";"):
        name, *values = part.split()
        assert name not in out, f"{name} twice in {csp}"
        out[name] = values
    return out


@pytest.mark.parametrize(
    ("method", "path", "status"),
    [
        ("GET", "/api/v1/health", 200),
        ("GET", "/api/v1/actuators/NO-SUCH-MODEL", 404),
        ("POST", "/api/v1/selections", 422),
        ("GET", "/api/v1/catalogue/export", 401),
        ("GET", "/vendor/plotly.js", 200),
        ("GET", "/pages/engineer/app.js", 200),
        ("GET", "/lib/api.js", 200),
        ("GET", "/css/base.css", 200),
        ("GET", "/no-such-file.txt", 404),
        ("GET", "/openapi.json", 200),
        ("GET", "/test-only/boom", 500),
    ],
)
def test_every_response_has_the_headers_and_non_html_no_csp(
    secured: SalesApi, method: str, path: str, status: int
) -> None:
    response = secured.client.request(method, path, json={} if method == "POST" else None)
    assert response.status_code == status
    _assert_every_response_headers(response)
    assert response.headers.get_list("x-frame-options") == ["DENY"]
    assert "content-security-policy" not in response.headers


@pytest.mark.parametrize("path", ["/", "/index.html", "/sales.html"])
def test_pages_get_the_page_policy(secured: SalesApi, path: str) -> None:
    response = secured.client.get(path)
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/html")
    _assert_every_response_headers(response)
    assert response.headers.get_list("x-frame-options") == ["DENY"]
    assert response.headers.get_list("content-security-policy") == [PAGE_CSP]
    policy = _directives(PAGE_CSP)
    assert policy["script-src"] == ["'self'"]  # no inline code, no eval, no other origin
    assert policy["default-src"] == ["'self'"]
    assert policy["frame-ancestors"] == ["'none'"]
    assert policy["object-src"] == ["'none'"]


class _Page(HTMLParser):
    """Inline scripts, event-handler attributes and ``javascript:`` URLs of a page."""

    def __init__(self) -> None:
        super().__init__()
        self.problems: list[str] = []
        self._in_inline_script = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        names = dict(attrs)
        if tag == "script" and "src" not in names and names.get("type") != "application/json":
            self._in_inline_script = True
        for name, value in attrs:
            if name.startswith("on"):
                self.problems.append(f"<{tag} {name}=…>: an inline event handler")
            if value is not None and value.strip().lower().startswith("javascript:"):
                self.problems.append(f"<{tag} {name}={value!r}>: a javascript: URL")

    def handle_endtag(self, tag: str) -> None:
        self._in_inline_script = False

    def handle_data(self, data: str) -> None:
        if self._in_inline_script and data.strip():
            self.problems.append(f"inline script {data.strip()[:40]!r}")


@pytest.mark.parametrize("page", sorted(p.name for p in FRONTEND_DIR.glob("*.html")))
def test_pages_hold_no_code_the_policy_would_block(page: str) -> None:
    """The page policy's ``script-src 'self'`` relies on this: no inline code in the pages."""
    parser = _Page()
    parser.feed((FRONTEND_DIR / page).read_text(encoding="utf-8"))
    assert parser.problems == []
    modules = sorted(FRONTEND_DIR.rglob("*.js"))
    assert modules, "no page scripts found"
    scripts = "\n".join(p.read_text(encoding="utf-8") for p in modules)
    # eval and its relatives would need 'unsafe-eval'; innerHTML with handlers 'unsafe-inline'.
    assert not re.search(r"\beval\(|new Function\(|setTimeout\(\s*['\"`]", scripts)
    assert not re.search(r"""\bon[a-z]+\s*=\s*['"]""", scripts)


def _external_sources(html: str) -> dict[str, list[str]]:
    """The URLs of a page's scripts, stylesheets and icons, by the directive that governs them."""
    found: dict[str, list[str]] = {"script-src": [], "style-src": [], "img-src": []}

    class Collector(HTMLParser):
        def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
            names = dict(attrs)
            if tag == "script" and names.get("src"):
                found["script-src"].append(str(names["src"]))
            elif tag == "link" and names.get("href"):
                rel = (names.get("rel") or "").lower()
                key = "style-src" if "stylesheet" in rel else "img-src" if "icon" in rel else None
                if key:
                    found[key].append(str(names["href"]))

    Collector().feed(html)
    return found


@pytest.mark.parametrize("path", ["/docs", "/redoc", "/docs/oauth2-redirect"])
@pytest.mark.parametrize("encoding", ["identity", "gzip"])
def test_docs_pages_allow_exactly_what_they_load(
    secured: SalesApi, path: str, encoding: str
) -> None:
    response = secured.client.get(path, headers={"Accept-Encoding": encoding})
    assert response.status_code == 200
    _assert_every_response_headers(response)
    assert response.headers.get_list("x-frame-options") == ["DENY"]
    policy = _directives(response.headers["content-security-policy"])
    assert "'unsafe-inline'" not in policy["script-src"]
    assert "'unsafe-eval'" not in policy["script-src"]
    # Every inline script of the page, by its hash, and nothing else inline.
    hashes = inline_script_hashes(response.content)
    inline = [source for source in policy["script-src"] if source.startswith("'sha256-")]
    assert sorted(inline) == sorted(hashes)
    if path == "/docs":
        assert len(hashes) == 1  # Swagger UI's start: the test must see the hash it checks
    # Everything the page loads comes from the app itself (works offline), and is there.
    for urls in _external_sources(response.text).values():
        for url in urls:
            assert url.startswith("/"), url
            assert secured.client.get(url).status_code == 200, url
    assert "https:" not in response.headers["content-security-policy"]


def test_docs_policy_is_only_on_the_docs(secured: SalesApi) -> None:
    """The docs' inline-script hashes are allowed on the docs pages, not on the app's own."""
    assert "'sha256-" in secured.client.get("/docs").headers["content-security-policy"]
    for path in ("/", "/sales.html"):
        assert "'sha256-" not in secured.client.get(path).headers["content-security-policy"]


def test_a_route_sets_its_own_policy_is_kept(secured: SalesApi) -> None:
    """The quote document's own CSP stays, and no X-Frame-Options contradicts its framing rule."""
    selection = secured.selection()
    body = secured.quote_body(selection["id"])
    created = secured.post("/api/v1/quotes", json=body)
    assert created.status_code == 201, created.text
    number = created.json()["number"]
    response = secured.get(f"/api/v1/quotes/{number}/document")
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/html")
    _assert_every_response_headers(response)
    [policy] = response.headers.get_list("content-security-policy")
    assert policy != PAGE_CSP
    assert _directives(policy)["frame-ancestors"] == ["'self'"]
    assert "x-frame-options" not in response.headers


def test_headers_set_by_a_route_are_not_overridden(
    seeded_engine: Engine, connection: Connection
) -> None:
    app = _app(seeded_engine, connection)

    @app.get("/test-only/own-headers", include_in_schema=False)
    def own_headers() -> HTMLResponse:
        return HTMLResponse(
            "<p>framed</p>",
            headers={"X-Frame-Options": "SAMEORIGIN", "Referrer-Policy": "same-origin"},
        )

    _before_the_static_files(app)

    with TestClient(app) as client:
        response = client.get("/test-only/own-headers")
    assert response.headers.get_list("x-frame-options") == ["SAMEORIGIN"]
    assert response.headers.get_list("referrer-policy") == ["same-origin"]
    assert response.headers.get_list("content-security-policy") == [PAGE_CSP]
