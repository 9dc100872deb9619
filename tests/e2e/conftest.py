"""Browser tests: the app served by uvicorn on a free port, driven by Debian's Chromium.

One server and one browser are shared by the whole session. The server's database
is a temporary SQLite file built by the migrations and seeded with the starter
catalogue, controllers included, as ``python -m actuator_selection seed`` does.
Every test gets a fresh browser context, so localStorage and history start empty.

Chromium is found by ``CHROMIUM_PATH``, else ``chromium`` on the PATH, else
``/usr/bin/chromium``. Without it the tests are skipped, except in CI
(``CI=true``) where a missing browser is a failure. No browser is ever downloaded.
"""

from __future__ import annotations

import os
import shutil
import socket
import threading
import time
from collections.abc import Iterator
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path

import pytest
import uvicorn
from playwright.sync_api import (
    Browser,
    ConsoleMessage,
    Page,
    Playwright,
    Request,
    ViewportSize,
    expect,
    sync_playwright,
)
from tests.api._sales_fixtures import load_example_prices

from actuator_selection.app import create_app
from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.sales import ApiKeyRepository
from actuator_selection.db.seed import load_seed

CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]
DESKTOP: ViewportSize = {"width": 1280, "height": 900}

WAIT_MS = 15_000
"""How long an action or an assertion waits: Playwright's assertions wait 5 s by
default, which a loaded CI machine sometimes needs more than."""
expect.set_options(timeout=WAIT_MS)
PHONE: ViewportSize = {"width": 375, "height": 800}
SERVER_START_TIMEOUT_S = 20.0


def chromium_path() -> str | None:
    """The Chromium executable to drive, or None when there is none."""
    configured = os.environ.get("CHROMIUM_PATH")
    if configured:
        return configured if Path(configured).is_file() else None
    found = shutil.which("chromium")
    if found:
        return found
    fallback = Path("/usr/bin/chromium")
    return str(fallback) if fallback.is_file() else None


@pytest.fixture(scope="session")
def screenshot_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Where screenshots go: $E2E_SCREENSHOT_DIR, else a pytest temp dir under /tmp."""
    configured = os.environ.get("E2E_SCREENSHOT_DIR")
    if configured:
        path = Path(configured)
        path.mkdir(parents=True, exist_ok=True)
        return path
    return tmp_path_factory.mktemp("screenshots")


@pytest.fixture(scope="session")
def chromium_executable() -> str:
    """Chromium's path; skip (or fail in CI) when it is missing."""
    path = chromium_path()
    if path is None:
        message = (
            "browser tests need Chromium: none found via CHROMIUM_PATH, `chromium` on the "
            "PATH or /usr/bin/chromium (Debian: apt-get install chromium)"
        )
        if os.environ.get("CI") == "true":
            pytest.fail(f"{message}; CI=true, so this is a failure", pytrace=False)
        pytest.skip(message)
    return path


class _ThreadedServer(uvicorn.Server):
    """uvicorn in a background thread (signal handlers stay with the main thread)."""

    def __init__(self, config: uvicorn.Config) -> None:
        super().__init__(config)
        self.failure: BaseException | None = None

    def run_in_thread(self, sock: socket.socket) -> None:
        try:
            self.run(sockets=[sock])
        except BaseException as exc:  # reported by the fixture, not lost in the thread
            self.failure = exc


def _seeded_database(directory: Path) -> str:
    url = f"sqlite:///{directory / 'e2e.sqlite3'}"
    upgrade(url=url)
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
    finally:
        engine.dispose()
    return url


@pytest.fixture(scope="session")
def base_url(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """The app on 127.0.0.1 and a free port, e.g. ``http://127.0.0.1:41234``."""
    url = _seeded_database(tmp_path_factory.mktemp("e2e-db"))
    app = create_app(Settings(database_url=url))
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="on")
    server = _ThreadedServer(config)
    thread = threading.Thread(
        target=server.run_in_thread, args=(sock,), name="e2e-uvicorn", daemon=True
    )
    thread.start()
    deadline = time.monotonic() + SERVER_START_TIMEOUT_S
    while not server.started:
        if server.failure is not None or not thread.is_alive():
            sock.close()
            pytest.fail(f"the app did not start: {server.failure!r}", pytrace=False)
        if time.monotonic() > deadline:
            server.should_exit = True
            thread.join(5)
            sock.close()
            pytest.fail("the app did not start within 20 s", pytrace=False)
        time.sleep(0.02)
    try:
        yield f"http://127.0.0.1:{port}"
    finally:
        server.should_exit = True
        thread.join(10)
        sock.close()  # already closed by uvicorn's shutdown; closing twice is harmless


@pytest.fixture(scope="session")
def playwright_session(chromium_executable: str) -> Iterator[Playwright]:
    """Playwright's driver for the session."""
    with sync_playwright() as p:
        yield p


@pytest.fixture(scope="session")
def browser(playwright_session: Playwright, chromium_executable: str) -> Iterator[Browser]:
    """Debian's Chromium, headless, shared by all tests."""
    browser = playwright_session.chromium.launch(
        executable_path=chromium_executable, args=CHROMIUM_ARGS, headless=True
    )
    try:
        yield browser
    finally:
        browser.close()


@dataclass
class Traffic:
    """What a page asked for and complained about."""

    requests: list[str] = field(default_factory=list)
    console_errors: list[str] = field(default_factory=list)

    def on_request(self, request: Request) -> None:
        self.requests.append(request.url)

    def on_console(self, message: ConsoleMessage) -> None:
        if message.type == "error":
            self.console_errors.append(message.text)

    def on_page_error(self, error: Exception) -> None:
        self.console_errors.append(f"uncaught: {error}")


@pytest.fixture
def traffic() -> Traffic:
    """Every request URL and console error of the test's browser context."""
    return Traffic()


@pytest.fixture
def page(browser: Browser, base_url: str, traffic: Traffic) -> Iterator[Page]:
    """A fresh context (empty localStorage, English browser) at desktop width."""
    context = browser.new_context(viewport=DESKTOP, locale="en-US", base_url=base_url)
    context.set_default_timeout(WAIT_MS)
    context.on("request", traffic.on_request)
    context.on("console", traffic.on_console)
    context.on("weberror", lambda web_error: traffic.on_page_error(web_error.error))
    try:
        yield context.new_page()
    finally:
        context.close()


@dataclass(frozen=True)
class SalesSite:
    """The served app, a sales key and an admin key."""

    url: str
    sales_key: str
    admin_key: str


class _QuietServer(uvicorn.Server):
    def install_signal_handlers(self) -> None:  # the main thread keeps its handlers
        pass


def _sales_database(directory: Path) -> tuple[str, str, str]:
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
    """The app as ``main.py`` builds it, with the example prices, a sales and an admin key."""
    url, sales, admin = _sales_database(tmp_path_factory.mktemp("sales-e2e"))
    app = create_app(Settings(database_url=url))
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    server = _QuietServer(uvicorn.Config(app, log_level="warning", access_log=False))
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
