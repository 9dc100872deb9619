"""The two pages work in Chromium under the security headers' Content-Security-Policy.

The app is served as ``main.py`` builds it (``create_app`` installs the headers), by
the ``site`` fixture of ``conftest.py``. Chromium reports every blocked load, inline
script, style or eval on the console ("… violates the following Content Security
Policy directive"); the tests fail on any such message, from the pages and from the
quote document, which its window loads through a signed link under its own policy. A
canary test makes sure such a violation is seen at all.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from datetime import UTC, datetime, timedelta

import httpx
import pytest
from playwright.sync_api import Browser, BrowserContext, ConsoleMessage, Page, expect
from tests.api._sales_fixtures import EXAMPLE_PRICE_LIST, WORKED_EXAMPLE

from actuator_selection.http.security_headers import PAGE_CSP

from .conftest import DESKTOP, SalesSite

pytestmark = pytest.mark.browser
SLOW_MS = 20_000
"""Timeout for steps that wait for the server or for plotly.js (≈ 1.2 MB) under a loaded CI."""
FHA = "FHA-25C-50-L"
REDOC_BRANDING = "https://cdn.redoc.ly/redoc/logo-mini.svg"


@dataclass
class Console:
    """Console errors of every page of a context (popups included)."""

    errors: list[str] = field(default_factory=list)

    def on_console(self, message: ConsoleMessage) -> None:
        if message.type == "error":
            self.errors.append(message.text)

    @property
    def csp_violations(self) -> list[str]:
        return [text for text in self.errors if "Content Security Policy" in text]


@pytest.fixture
def context(browser: Browser, site: SalesSite) -> Iterator[tuple[BrowserContext, Console]]:
    context = browser.new_context(viewport=DESKTOP, locale="en-US", base_url=site.url)
    context.set_default_timeout(15_000)
    console = Console()
    context.on("console", console.on_console)
    context.on("weberror", lambda web_error: console.errors.append(f"uncaught: {web_error.error}"))
    try:
        yield context, console
    finally:
        context.close()


def _open(page: Page, path: str) -> None:
    response = page.goto(path)
    assert response is not None
    assert response.status == 200
    assert response.headers.get("content-security-policy") == PAGE_CSP  # not vacuous


def test_a_violation_is_seen(context: tuple[BrowserContext, Console]) -> None:
    """The canary: an inline script added to the page is refused and reported."""
    browser_context, console = context
    page = browser_context.new_page()
    _open(page, "/")
    page.evaluate(
        """() => {
            const script = document.createElement("script");
            script.textContent = "window.__inline = 1";
            document.head.append(script);
        }"""
    )
    page.wait_for_timeout(200)
    assert page.evaluate("window.__inline") is None
    assert console.csp_violations, console.errors


def test_engineer_page_draws_its_charts_under_the_policy(
    context: tuple[BrowserContext, Console],
) -> None:
    browser_context, console = context
    page = browser_context.new_page()
    _open(page, "/")
    page.locator("#example").click()
    page.locator("#submit").click()
    page.locator(f'#ranking-table tr[data-model="{FHA}"] td[data-field="rms"]').click()
    for chart in ("#chart-cycle", "#chart-diagram"):
        page.wait_for_selector(f'{chart}[data-state="ready"][data-model="{FHA}"]', timeout=SLOW_MS)
        expect(page.locator(f"{chart} .main-svg").first).to_be_visible()
    page.get_by_role("button", name="Deutsch").click()  # redraws in the other language
    page.wait_for_selector(f'#chart-diagram[data-state="ready"][data-model="{FHA}"]')
    assert page.evaluate("typeof window.Plotly.react") == "function"
    assert console.csp_violations == []
    assert console.errors == []


def _quote(site: SalesSite) -> str:
    headers = {"Authorization": f"Bearer {site.sales_key}"}
    selection = httpx.post(f"{site.url}/api/v1/selections", json=WORKED_EXAMPLE, timeout=30)
    assert selection.status_code == 201, selection.text
    body = {
        "selection_id": selection.json()["id"],
        "customer": {"name": "Muster GmbH", "address": "Hauptstr. 1\n12345 Musterstadt"},
        "actuator": {"model": FHA, "quantity": 1},
        "price_list": EXAMPLE_PRICE_LIST,
        "valid_until": (datetime.now(UTC).date() + timedelta(days=30)).isoformat(),
    }
    quote = httpx.post(f"{site.url}/api/v1/quotes", json=body, headers=headers, timeout=30)
    assert quote.status_code == 201, quote.text
    return str(quote.json()["number"])


def test_sales_page_and_its_quote_document_under_the_policy(
    context: tuple[BrowserContext, Console], site: SalesSite
) -> None:
    browser_context, console = context
    number = _quote(site)
    page = browser_context.new_page()
    _open(page, "/sales.html")
    page.fill("#api-key", site.sales_key)
    page.click("#key-form button[type=submit]")
    row = page.locator(f"#quotes tr[data-number='{number}']")
    expect(row).to_be_visible(timeout=SLOW_MS)
    with page.expect_popup() as popup:
        row.get_by_role("button", name="Open document").click()
    document = popup.value
    expect(document.locator("html[data-figure=ready]")).to_have_count(1, timeout=SLOW_MS)
    expect(document.locator("#speed-torque .main-svg").first).to_be_visible()
    assert console.csp_violations == []
    assert console.errors == []


@pytest.mark.parametrize(
    ("path", "drawn"),
    [("/docs", ".swagger-ui .opblock"), ("/redoc", "[data-section-id]")],
    ids=["swagger-ui", "redoc"],
)
def test_api_docs_render_offline_under_their_policy(
    context: tuple[BrowserContext, Console], site: SalesSite, path: str, drawn: str
) -> None:
    """The docs load nothing from outside the app (they once loaded from a CDN)."""
    browser_context, console = context
    requested: list[str] = []
    browser_context.on("request", lambda request: requested.append(request.url))
    page = browser_context.new_page()
    page.goto(path)
    expect(page.locator(drawn).first).to_be_visible(timeout=SLOW_MS)
    assert requested
    # ReDoc's search worker comes from a blob: URL of the page's own origin.
    outside = {u for u in requested if not u.removeprefix("blob:").startswith(site.url)}
    # The one exception: ReDoc's bundle asks for its vendor's logo in the footer; the
    # policy refuses it (nothing but the app's own origin is allowed) and the page works.
    assert outside <= {REDOC_BRANDING}
    violations = console.csp_violations
    assert all(REDOC_BRANDING in v for v in violations), violations
