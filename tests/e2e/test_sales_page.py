"""The sales page in Chromium: key once, quote from a selection, status, printable document.

The app is served with the sales routers wired (``build_app``, as ``main.py`` is to
be), on a database of its own holding the starter catalogue, the example price
list and a sales key. The browser fixtures come from ``tests/e2e/conftest.py``.
"""

from __future__ import annotations

import socket
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path

import httpx
import pytest
import uvicorn
from playwright.sync_api import Browser, Page, expect
from tests.api._sales_fixtures import WORKED_EXAMPLE, build_app, load_example_prices

from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.sales import ApiKeyRepository
from actuator_selection.db.seed import load_seed

pytestmark = pytest.mark.browser
SLOW_MS = 20_000
"""Timeout for steps that wait for the server or for plotly.js (≈ 4.8 MB) under a loaded CI."""


@dataclass(frozen=True)
class SalesSite:
    """The served app, a sales key and an admin key."""

    url: str
    sales_key: str
    admin_key: str


class _Server(uvicorn.Server):
    def install_signal_handlers(self) -> None:  # the main thread keeps its handlers
        pass


def _database(directory: Path) -> tuple[str, str, str]:
    url = f"sqlite:///{directory / 'sales.sqlite3'}"
    upgrade(url=url)
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
            load_example_prices(session)
            keys = ApiKeyRepository(session)
            _, sales = keys.create(name="Anna Vertrieb", role="sales", now=datetime.now(UTC))
            _, admin = keys.create(name="Admin", role="admin", now=datetime.now(UTC))
    finally:
        engine.dispose()
    return url, sales, admin


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory, chromium_executable: str) -> Iterator[SalesSite]:
    url, sales, admin = _database(tmp_path_factory.mktemp("sales-e2e"))
    app = build_app(Settings(database_url=url))
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    server = _Server(uvicorn.Config(app, log_level="warning", access_log=False))
    thread = threading.Thread(target=server.run, kwargs={"sockets": [sock]}, daemon=True)
    thread.start()
    deadline = time.monotonic() + 20
    while not server.started:
        if time.monotonic() > deadline or not thread.is_alive():
            pytest.fail("the sales app did not start", pytrace=False)
        time.sleep(0.02)
    try:
        yield SalesSite(url=f"http://127.0.0.1:{port}", sales_key=sales, admin_key=admin)
    finally:
        server.should_exit = True
        thread.join(10)
        sock.close()
        app.state.engine.dispose()


@pytest.fixture
def sales_page(browser: Browser, site: SalesSite) -> Iterator[Page]:
    context = browser.new_context(viewport={"width": 1280, "height": 900}, base_url=site.url)
    context.set_default_timeout(15_000)
    foreign: list[str] = []
    context.on(
        "request",
        lambda r: (
            None if r.url.startswith((site.url, "about:", "data:")) else foreign.append(r.url)
        ),
    )
    try:
        yield context.new_page()
    finally:
        context.close()
    assert not foreign, f"requests left the app: {foreign}"


def selection_id(site: SalesSite, models: list[str] | None = None) -> str:
    body = {**WORKED_EXAMPLE, **({"models": models} if models else {})}
    response = httpx.post(f"{site.url}/api/v1/selections", json=body, timeout=30)
    assert response.status_code == 201
    return str(response.json()["id"])


def sign_in(page: Page, key: str) -> None:
    page.fill("#api-key", key)
    page.click("#key-form button[type=submit]")


def test_quote_from_a_selection_to_the_printed_document(sales_page: Page, site: SalesSite) -> None:
    page = sales_page
    chosen = selection_id(site, ["FHA-25C-50-L", "FHA-8C-30"])
    page.goto(f"/sales.html?selection={chosen}")
    expect(page.locator("#key-panel")).to_be_visible()
    sign_in(page, "asel_0123456789ab_" + "A" * 43)
    expect(page.locator("#key-error")).to_contain_text("not accepted")
    sign_in(page, site.admin_key)
    expect(page.locator("#key-error")).to_contain_text("sales key")
    sign_in(page, site.sales_key)
    expect(page.locator("#who")).to_contain_text("Anna Vertrieb")
    expect(page.locator("#quote-form")).to_be_visible(timeout=SLOW_MS)
    # the unsuitable candidate is listed but cannot be chosen
    expect(page.locator("#f-model option[value='FHA-8C-30']")).to_be_disabled()
    expect(page.locator("#f-model")).to_have_value("FHA-25C-50-L")
    expect(page.locator("#hint-model")).to_contain_text("Unconfirmed")
    expect(page.locator("#example-warning")).to_be_visible()

    hostile = '<img src=x onerror="window.__xss = 1">Muster GmbH'
    page.fill("#f-customer", hostile)
    page.fill("#f-ctrl-name", "SINAMICS S120, 400 V")
    page.fill("#f-ctrl-code", "CTRL-SINAMICS-S120")
    page.fill("#f-qty", "2")
    page.fill("#f-ctrl-qty", "2")
    page.fill("#f-discount", "7.5")
    page.click("#create-quote")
    created = page.locator("#created")
    expect(created).to_contain_text("8,861.50 EUR", timeout=SLOW_MS)
    number = page.locator("#created .quote-number").inner_text()
    assert number.startswith("Q-")
    row = page.locator(f"#quotes tr[data-number='{number}']")
    expect(row).to_contain_text(hostile)  # shown as text, not markup
    assert page.evaluate("window.__xss") is None
    expect(row.locator(".status")).to_have_text("draft")

    row.get_by_role("button", name="Mark sent").click()
    expect(row.locator(".status")).to_have_text("sent")
    row.get_by_role("button", name="Accepted").click()
    expect(row.locator(".status")).to_have_text("accepted")
    expect(row.get_by_role("button", name="Mark sent")).to_have_count(0)

    with page.expect_popup() as popup:
        row.get_by_role("button", name="Open document").click()
    document = popup.value
    expect(document.locator("html[data-figure=ready]")).to_have_count(1, timeout=SLOW_MS)
    expect(document.locator("[data-field=number]")).to_have_text(number)
    expect(document.locator("[data-field=example-prices]")).to_be_visible()
    expect(document.locator("[data-field=total]")).to_have_text("8,861.50 EUR")
    expect(document.locator("#speed-torque .main-svg").first).to_be_visible()
    assert document.evaluate("window.__xss") is None
    assert hostile not in document.content()


def test_the_key_is_asked_once_per_tab_and_bad_input_is_named(
    sales_page: Page, site: SalesSite
) -> None:
    page = sales_page
    chosen = selection_id(site, ["FHA-25C-50-L"])
    page.goto(f"/sales.html?selection={chosen}")
    sign_in(page, site.sales_key)
    expect(page.locator("#quote-form")).to_be_visible()
    page.reload()
    expect(page.locator("#quote-form")).to_be_visible()  # no second prompt
    expect(page.locator("#key-panel")).to_be_hidden()
    page.fill("#f-customer", "Beispiel AG")
    page.fill("#f-discount", "150")
    page.click("#create-quote")
    expect(page.locator("#err-discount_percent")).to_be_visible()
    expect(page.locator("#f-discount")).to_have_attribute("aria-invalid", "true")
    page.fill("#f-discount", "5")
    page.fill("#f-ctrl-name", "Unknown drive")
    page.fill("#f-ctrl-code", "NO-SUCH-CODE")
    page.click("#create-quote")
    expect(page.locator("#err-controller-item_code")).to_contain_text("no controller price")
    page.click("#sign-out")
    expect(page.locator("#key-panel")).to_be_visible()
    page.reload()
    expect(page.locator("#key-panel")).to_be_visible()


def test_an_unknown_selection_is_named(sales_page: Page, site: SalesSite) -> None:
    page = sales_page
    page.goto("/sales.html?selection=no-such-selection")
    sign_in(page, site.sales_key)
    expect(page.locator("#err-selection_id")).to_contain_text("no stored selection")
    expect(page.locator("#quote-form")).to_be_hidden()
