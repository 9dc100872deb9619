"""Cold page load of the engineer's page, to both charts drawn, in headless Chromium.

The app runs under uvicorn in a subprocess on a free loopback port, on a throw-away
SQLite database seeded with the starter catalogue. Each run opens a fresh browser
context (an empty HTTP cache: nothing is reused from the run before), goes to ``/``,
puts in the chapter's worked example (Table 516.1), submits it and waits until
both charts say ``data-state="ready"``. Times are the page's own clock
(``performance.now()``, 0 = navigation start):

- *form ready*: the page's script has run (the results area shows its first notice),
  so the form can be used;
- *charts drawn*: both charts of the best candidate are drawn.

The user of this run clicks as soon as the form can be used, which leaves the page no
time of its own. A second cold load waits ``PAUSE_MS`` with the form untouched (a person
reading it; the page warms plotly.js up meanwhile, ``warmCharts`` in app.js) and times
*submit to both charts*: from the form's submit event to both charts drawn.

A reference load (the bare ``index.html`` with JavaScript off: HTML and CSS, to the
``load`` event) is timed the same way in each run, and *charts / reference* is printed
as a ratio, so figures from different machines can be compared. Each figure is the
median of ``--runs`` runs (after one warm-up run that also warms the server). Then the
same runs again with the page's CPU slowed ``--slowdown`` times (4: Chrome DevTools'
``Emulation.setCPUThrottlingRate``, a slow laptop or phone), reference included.

Needs Debian's Chromium (``CHROMIUM_PATH``, else ``chromium`` on the PATH, else
``/usr/bin/chromium``); no browser is downloaded.
"""

from __future__ import annotations

import argparse
import os
import shutil
import socket
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, cast

import httpx
from playwright.sync_api import Browser, BrowserContext, Page, sync_playwright

import actuator_selection
from actuator_selection.config import SEED_DIR
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
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
START_TIMEOUT_S = 120.0
STEP_TIMEOUT_MS = 60_000
PAUSE_MS = 1500
"""How long the second load's user reads the form before using it."""

# Runs before the page's own scripts (Playwright's init scripts are not subject to the
# page's Content-Security-Policy): notes when the page's script has set the page up (the
# results area shows its first notice) and when both charts first report "ready". Noted
# in the page, so that a busy main thread (plotly.js running) does not shift the times.
WATCH_PAGE = """
(() => {
  const charts = () => ["chart-cycle", "chart-diagram"].every(
    (id) => document.getElementById(id)?.dataset.state === "ready");
  document.addEventListener("submit", () => {
    if (window.__submittedAt === undefined) window.__submittedAt = performance.now();
  }, true);
  new MutationObserver((_, observer) => {
    if (window.__formReadyAt === undefined && document.querySelector("#results-body .notice")) {
      window.__formReadyAt = performance.now();
    }
    if (window.__chartsDrawnAt === undefined && charts()) {
      window.__chartsDrawnAt = performance.now();
      observer.disconnect();
    }
  }).observe(document, {subtree: true, childList: true, attributes: true,
                         attributeFilter: ["data-state"]});
})();
"""


@dataclass(frozen=True, slots=True, kw_only=True)
class Run:
    """One cold load, in milliseconds since navigation start."""

    form_ready_ms: float
    charts_ms: float
    reference_ms: float
    warm_up: str
    """What the page's plotly warm-up did in the first load (``warmCharts`` in app.js: done,
    partial where the user's click came between its figures, skipped, failed)."""
    paused_submit_to_charts_ms: float
    """The second load, its form left untouched for ``PAUSE_MS``: submit to both charts."""
    paused_warm_up: str
    """What the page's plotly warm-up did in that load (done, partial, skipped, failed)."""


def chromium_path() -> str:
    """The Chromium to drive, found as the browser tests find it."""
    configured = os.environ.get("CHROMIUM_PATH")
    found = configured or shutil.which("chromium") or "/usr/bin/chromium"
    if not Path(found).is_file():
        sys.exit(f"bench.page needs Chromium ({found} not found; Debian: apt-get install chromium)")
    return found


def free_port() -> int:
    """A loopback port nobody listens on now (the server binds it a moment later)."""
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as sock:
        sock.bind(("127.0.0.1", 0))
        port: int = sock.getsockname()[1]
        return port


def seeded_database(directory: Path) -> str:
    """A migrated SQLite database with the starter catalogue, as ``seed`` makes it."""
    url = f"sqlite:///{directory / 'bench.sqlite3'}"
    upgrade(url=url)
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
    finally:
        engine.dispose()
    return url


@contextmanager
def served(database_url: str) -> Iterator[str]:
    """The app under uvicorn in a subprocess; yields its base URL."""
    port = free_port()
    backend = str(Path(actuator_selection.__file__).resolve().parents[1])
    path = os.pathsep.join(p for p in (backend, os.environ.get("PYTHONPATH", "")) if p)
    env = {**os.environ, "DATABASE_URL": database_url, "PYTHONPATH": path}
    command = [
        sys.executable,
        "-m",
        "uvicorn",
        "--factory",
        "actuator_selection.app:create_app",
        "--host",
        "127.0.0.1",
        "--port",
        str(port),
        "--log-level",
        "warning",
        "--no-access-log",
    ]
    process = subprocess.Popen(command, env=env)
    url = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + START_TIMEOUT_S
        while True:
            if process.poll() is not None:
                sys.exit("bench.page: the server exited at start")
            try:
                if httpx.get(f"{url}/api/v1/health", timeout=1).status_code == 200:
                    break
            except httpx.TransportError:
                pass
            if time.monotonic() > deadline:
                sys.exit(f"bench.page: the server did not start in {START_TIMEOUT_S:g} s")
            time.sleep(0.05)
        yield url
    finally:
        process.terminate()
        try:
            process.wait(10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait(10)


def _slowed(context: BrowserContext, page: Page, slowdown: float) -> None:
    """Slow ``page``'s CPU ``slowdown`` times (1: as it is)."""
    if slowdown != 1:
        context.new_cdp_session(page).send("Emulation.setCPUThrottlingRate", {"rate": slowdown})


def reference_load(browser: Browser, base_url: str, slowdown: float = 1) -> float:
    """The bare index.html (HTML and CSS, no script) to its ``load`` event, cold."""
    context = browser.new_context(base_url=base_url, java_script_enabled=False)
    try:
        page = context.new_page()
        _slowed(context, page, slowdown)
        page.goto("/index.html", wait_until="load")
        # the page's scripts are off, not Playwright's evaluation
        timing = page.evaluate("() => performance.getEntriesByType('navigation')[0].loadEventEnd")
        return float(timing)
    finally:
        context.close()


def charts_load(
    browser: Browser, base_url: str, pause_ms: int = 0, slowdown: float = 1
) -> dict[str, Any]:
    """``/`` cold, the worked example submitted (after ``pause_ms`` with the form
    untouched): the page's times in ms and what its plotly warm-up did."""
    context = browser.new_context(
        base_url=base_url, locale="en-US", viewport={"width": 1280, "height": 900}
    )
    context.set_default_timeout(STEP_TIMEOUT_MS)
    try:
        context.add_init_script(WATCH_PAGE)
        page = context.new_page()
        _slowed(context, page, slowdown)
        page.goto("/", wait_until="commit")
        page.wait_for_selector("#results-body .notice", state="attached")
        if pause_ms:
            page.wait_for_timeout(pause_ms)
        page.locator("#example").click()
        page.locator("#submit").click()
        page.wait_for_function("() => window.__chartsDrawnAt !== undefined", polling=10)
        return cast(
            dict[str, Any],
            page.evaluate(
                """() => ({form: window.__formReadyAt, submitted: window.__submittedAt,
                           charts: window.__chartsDrawnAt,
                           warm: document.documentElement.dataset.chartsWarm ?? "none"})"""
            ),
        )
    finally:
        context.close()


def measure(browser: Browser, base_url: str, slowdown: float = 1) -> Run:
    """One run: the reference load, the page to both charts at once, and after a pause."""
    reference = reference_load(browser, base_url, slowdown)
    eager = charts_load(browser, base_url, slowdown=slowdown)
    paused = charts_load(browser, base_url, PAUSE_MS, slowdown)
    return Run(
        form_ready_ms=float(eager["form"]),
        charts_ms=float(eager["charts"]),
        reference_ms=reference,
        warm_up=str(eager["warm"]),
        paused_submit_to_charts_ms=float(paused["charts"]) - float(paused["submitted"]),
        paused_warm_up=str(paused["warm"]),
    )


def plotly_size(base_url: str) -> tuple[str, int, int]:
    """The plotly.js URL the app serves, and its size as sent raw and with gzip."""
    where = httpx.get(f"{base_url}/vendor/plotly.js").json()
    url = f"{base_url}{where['url']}"
    raw = httpx.get(url, headers={"Accept-Encoding": "identity"})
    packed = httpx.get(url, headers={"Accept-Encoding": "gzip"})
    packed_size = int(packed.headers.get("content-length", len(packed.content)))
    return where["url"], len(raw.content), packed_size


def main() -> None:
    """Run the benchmark and print its figures."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=7, help="measured runs (median), default 7")
    parser.add_argument(
        "--slowdown", type=float, default=4, help="CPU slowdown of the second set, default 4"
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="bench-page-") as tmp:
        database_url = seeded_database(Path(tmp))
        with served(database_url) as base_url, sync_playwright() as p:
            url, raw, packed = plotly_size(base_url)
            print(f"plotly.js {url}: {raw / 1e6:.2f} MB raw, {packed / 1e6:.2f} MB gzip")
            browser = p.chromium.launch(
                executable_path=chromium_path(), args=CHROMIUM_ARGS, headless=True
            )
            try:
                measure(browser, base_url)  # warm-up: server caches, Chromium's start
                runs = [measure(browser, base_url) for _ in range(args.runs)]
                slowed = [measure(browser, base_url, args.slowdown) for _ in range(args.runs)]
            finally:
                browser.close()
    _report(runs, "")
    _report(slowed, f", CPU slowed {args.slowdown:g}×")


def _report(runs: list[Run], condition: str) -> None:
    """Print the medians of ``runs``."""
    form = statistics.median(r.form_ready_ms for r in runs)
    charts = statistics.median(r.charts_ms for r in runs)
    reference = statistics.median(r.reference_ms for r in runs)
    ratio = statistics.median(r.charts_ms / r.reference_ms for r in runs)
    print(f"cold load{condition}, median of {len(runs)} runs (ms since navigation start):")
    print(f"  reference: bare index.html, no script, to load   {reference:8.1f} ms")
    print(f"  engineer's page: form ready                      {form:8.1f} ms")
    print(f"  engineer's page: worked example, both charts     {charts:8.1f} ms")
    print(f"  charts / reference                               {ratio:8.1f}")
    print(
        "  all runs (charts ms): "
        + ", ".join(f"{r.charts_ms:.0f}" for r in runs)
        + f"  (plotly warm-up: {_counted(r.warm_up for r in runs)})"
    )
    paused = statistics.median(r.paused_submit_to_charts_ms for r in runs)
    print(
        f"  form untouched for {PAUSE_MS} ms, then submit to both charts   {paused:8.1f} ms"
        f"  (plotly warm-up: {_counted(r.paused_warm_up for r in runs)})"
    )


def _counted(values: Iterable[str]) -> str:
    """``done 6, skipped 1``."""
    return ", ".join(f"{k} {v}" for k, v in sorted(Counter(values).items()))


if __name__ == "__main__":
    main()
