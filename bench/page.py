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

Between the two, the user's clicks (form ready to submit) and the server's answers as the
page had them (its Resource Timing: the selection, then the best candidate's detail and
figures) are printed too, so that the page's own share of the way is seen (``Answers``).

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

Wall-clock times swing with whatever else the machine runs. So each charts load is also
traced (Chromium's trace, categories ``toplevel`` and ``blink.user_timing``: light), and
*main thread to both charts* is the CPU time of the page's main thread from navigation
to both charts drawn (each task's thread time, ``MainThread``), with its tasks' wall clock
beside it; the paused load gives the CPU time from the submit on. A CPU slowed by
DevTools' throttling shows in that CPU time too: the slowed runs' CPU is 4–7 times the
other's here, so compare CPU times within one condition. ``--baseline DIR`` serves
another tree's ``frontend/`` (e.g. ``git archive main frontend | tar -x -C /tmp/base``)
from a second server of this tree's code, alternates its runs with this tree's (the order
turned each round) and reports both: an A/B of the page alone. With ``--baseline-backend
DIR`` (another tree's ``backend/``, e.g. ``/work/main/backend``) that server runs that
tree's code: an A/B of the page and the API's figures it draws.

Needs Debian's Chromium (``CHROMIUM_PATH``, else ``chromium`` on the PATH, else
``/usr/bin/chromium``); no browser is downloaded.
"""

from __future__ import annotations

import argparse
import json
import math
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
from contextlib import ExitStack, contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, cast
from urllib.parse import urlsplit

import httpx
from playwright.sync_api import Browser, BrowserContext, Page, sync_playwright

import actuator_selection
from actuator_selection.config import SEED_DIR
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.seed import load_seed
from bench import targets

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
TRACE_CATEGORIES = ["toplevel", "blink.user_timing"]
"""Chromium's trace of each charts load: the renderer's tasks (with their thread CPU
time) and the page's ``performance.mark`` calls, little else (a light trace)."""

# Runs before the page's own scripts (Playwright's init scripts are not subject to the
# page's Content-Security-Policy): notes when the page's script has set the page up (the
# results area shows its first notice) and when both charts first report "ready". Noted
# in the page, so that a busy main thread (plotly.js running) does not shift the times.
WATCH_PAGE = """
(() => {
  const charts = () => ["chart-cycle", "chart-diagram"].every(
    (id) => document.getElementById(id)?.dataset.state === "ready");
  document.addEventListener("submit", () => {
    if (window.__submittedAt === undefined) {
      window.__submittedAt = performance.now();
      performance.mark("bench:submitted");
    }
  }, true);
  new MutationObserver((_, observer) => {
    if (window.__formReadyAt === undefined && document.querySelector("#results-body .notice")) {
      window.__formReadyAt = performance.now();
    }
    if (window.__chartsDrawnAt === undefined && charts()) {
      window.__chartsDrawnAt = performance.now();
      performance.mark("bench:charts-drawn");
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
    partial where the user's click came between its figures, skipped, failed; then what
    the one while the answer is awaited did, ``warmWhileWaiting``)."""
    paused_submit_to_charts_ms: float
    """The second load, its form left untouched for ``PAUSE_MS``: submit to both charts."""
    paused_warm_up: str
    """What the page's plotly warm-up did in that load (done, partial, skipped, failed)."""
    charts_cpu_ms: float
    """The first load's main-thread CPU time, navigation to both charts drawn (``MainThread``)."""
    charts_task_ms: float
    """The same tasks' wall-clock time (the CPU time and the waits of a busy machine)."""
    paused_cpu_after_submit_ms: float
    """The second load's main-thread CPU time from the submit to both charts drawn."""
    submitted_ms: float
    """The first load's submit (the user's two clicks come between form ready and it)."""
    paused_clicks_ms: float
    """The second load's two clicks, from the end of its pause to its submit: what the
    clicks take where the page has had its time (its start and warm-up done)."""
    answers: Answers
    """The first load's waits for the server after the submit (:class:`Answers`)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Answers:
    """What a load waited for the server after its submit, as the page's Resource Timing
    has it (``performance.getEntriesByType("resource")``, in ms since navigation start):
    the selection (``POST /api/v1/selections``), from its request to its last byte; then
    the best candidate's detail and figures, asked once it answered, from the first's
    request to the last one's last byte. Neither is the server's time alone: an answer
    the page's busy main thread reads late counts as late."""

    selection_ms: float
    detail_ms: float

    @classmethod
    def of(cls, entries: list[dict[str, Any]], submitted_ms: float) -> Answers:
        """From the page's API resource entries (``name``, ``start``, ``end``)."""
        after = [e for e in entries if e["start"] >= submitted_ms]
        selection = next(
            (e for e in after if urlsplit(e["name"]).path == "/api/v1/selections"), None
        )
        if selection is None:
            return cls(selection_ms=math.nan, detail_ms=math.nan)
        later = [e for e in after if e["start"] >= selection["end"]]
        return cls(
            selection_ms=selection["end"] - selection["start"],
            detail_ms=max(e["end"] for e in later) - min(e["start"] for e in later)
            if later
            else math.nan,
        )


@dataclass(frozen=True, slots=True, kw_only=True)
class MainThread:
    """The page's main thread in a Chromium trace, up to the page's mark ``bench:charts-drawn``:
    the tasks it ran (each task's thread CPU time, and its wall-clock time). The task
    the mark falls in is counted up to the mark. CPU time is what the page asks of the
    processor, whatever else runs on the machine; a CPU slowed by
    ``Emulation.setCPUThrottlingRate`` leaves it as it is (the thread is paused, not
    made to work longer)."""

    cpu_ms: float
    task_ms: float
    cpu_after_submit_ms: float
    """CPU time from the mark ``bench:submitted`` on (NaN without that mark)."""

    @classmethod
    def of(cls, trace: dict[str, Any]) -> MainThread:
        """Read from the trace's events (Chromium's JSON trace format)."""
        events: list[dict[str, Any]] = trace["traceEvents"]
        marks = {e["name"]: e for e in events if e.get("name", "").startswith("bench:")}
        end = marks["bench:charts-drawn"]
        submitted = marks.get("bench:submitted")
        main = {
            (e["pid"], e["tid"])
            for e in events
            if e.get("ph") == "M"
            and e.get("name") == "thread_name"
            and e["args"].get("name") == "CrRendererMain"
            and e["pid"] == end["pid"]
        }
        tasks = sorted(
            (
                e
                for e in events
                if e.get("ph") == "X"
                and e.get("cat") == "toplevel"
                and (e["pid"], e["tid"]) in main
                and e["ts"] <= end["ts"]
            ),
            key=lambda e: (e["ts"], -e.get("dur", 0)),
        )
        cpu = wall = after = 0.0
        task_end = -1.0
        for task in tasks:
            if task["ts"] < task_end:
                continue  # a task nested in one counted (outermost tasks only)
            task_end = task["ts"] + task.get("dur", 0)
            dur = float(task.get("dur", 0))
            share = 1.0 if task_end <= end["ts"] or dur == 0 else (end["ts"] - task["ts"]) / dur
            task_cpu = float(task.get("tdur", 0)) * share
            cpu += task_cpu
            wall += dur * share
            if submitted is not None and task_end > submitted["ts"]:
                before = max(0.0, submitted["ts"] - task["ts"]) / dur if dur else 0.0
                after += task_cpu * (1 - min(before, 1.0))
        return cls(
            cpu_ms=cpu / 1000,
            task_ms=wall / 1000,
            cpu_after_submit_ms=after / 1000 if submitted is not None else math.nan,
        )


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


# The app under uvicorn, its pages from the directory given (the server's code is this tree's).
SERVE = """
import sys
from pathlib import Path

import uvicorn

import actuator_selection.config as config

config.FRONTEND_DIR = Path(sys.argv[1])
uvicorn.run("actuator_selection.app:create_app", factory=True, host="127.0.0.1",
            port=int(sys.argv[2]), log_level="warning", access_log=False)
"""


@contextmanager
def served(
    database_url: str, frontend: Path | None = None, code: Path | None = None
) -> Iterator[str]:
    """The app under uvicorn in a subprocess, its pages from ``frontend`` (default: this
    tree's ``frontend/``), its code from the ``backend/`` directory ``code`` (default: this
    tree's); yields its base URL."""
    port = free_port()
    ours = Path(actuator_selection.__file__).resolve().parents[1]
    backend = str(code.resolve() if code is not None else ours)
    path = os.pathsep.join(p for p in (backend, os.environ.get("PYTHONPATH", "")) if p)
    env = {**os.environ, "DATABASE_URL": database_url, "PYTHONPATH": path}
    pages = frontend or ours.parent / "frontend"
    command = [sys.executable, "-c", SERVE, str(pages.resolve()), str(port)]
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
        browser.start_tracing(page=page, categories=TRACE_CATEGORIES)
        page.goto("/", wait_until="commit")
        page.wait_for_selector("#results-body .notice", state="attached")
        if pause_ms:
            page.wait_for_timeout(pause_ms)
        page.locator("#example").click()
        page.locator("#submit").click()
        page.wait_for_function("() => window.__chartsDrawnAt !== undefined", polling=10)
        times = cast(
            dict[str, Any],
            page.evaluate(
                """() => ({form: window.__formReadyAt, submitted: window.__submittedAt,
                           charts: window.__chartsDrawnAt,
                           api: performance.getEntriesByType("resource")
                                .filter((e) => new URL(e.name).pathname.startsWith("/api/"))
                                .map((e) => ({name: e.name, start: e.startTime,
                                              end: e.responseEnd})),
                           warm: [document.documentElement.dataset.chartsWarm ?? "none",
                                 document.documentElement.dataset.chartsWarmSubmit]
                                .filter(Boolean).join(", at submit ")})"""
            ),
        )
        times["main"] = MainThread.of(json.loads(browser.stop_tracing()))
        return times
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
        charts_cpu_ms=eager["main"].cpu_ms,
        charts_task_ms=eager["main"].task_ms,
        paused_cpu_after_submit_ms=paused["main"].cpu_after_submit_ms,
        submitted_ms=float(eager["submitted"]),
        paused_clicks_ms=float(paused["submitted"]) - float(paused["form"]) - PAUSE_MS,
        answers=Answers.of(eager["api"], float(eager["submitted"])),
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
    parser.add_argument(
        "--baseline",
        type=Path,
        help="another tree's frontend/ directory (A/B): served by a second server of this "
        "tree's code, its runs alternate with this tree's, and both are reported",
    )
    parser.add_argument(
        "--baseline-backend",
        type=Path,
        help="with --baseline: the baseline's server runs this backend/ directory's code "
        "(another tree's), not this tree's",
    )
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="bench-page-") as tmp, ExitStack() as stack:
        trees = (
            {"this tree": None}
            if args.baseline is None
            else {"this tree": None, f"baseline {args.baseline}": args.baseline}
        )
        sites = {}
        for n, (name, frontend) in enumerate(trees.items()):
            directory = Path(tmp) / str(n)
            directory.mkdir()
            code = args.baseline_backend if frontend is not None else None
            sites[name] = stack.enter_context(served(seeded_database(directory), frontend, code))
        p = stack.enter_context(sync_playwright())
        url, raw, packed = plotly_size(next(iter(sites.values())))
        print(f"plotly.js {url}: {raw / 1e6:.2f} MB raw, {packed / 1e6:.2f} MB gzip")
        browser = p.chromium.launch(
            executable_path=chromium_path(), args=CHROMIUM_ARGS, headless=True
        )
        try:
            for base_url in sites.values():
                measure(browser, base_url)  # warm-up: server caches, Chromium's start
            runs = _alternated(browser, sites, args.runs, 1)
            slowed = _alternated(browser, sites, args.runs, args.slowdown)
        finally:
            browser.close()
    for name in sites:
        heading = f"{name}: " if len(sites) > 1 else ""
        ours = name == "this tree"  # a baseline's figures are not this tree's results
        _report(runs[name], heading, "", targets.PAGE, ours)
        _report(  # the bound is for a CPU slowed 4×
            slowed[name],
            heading,
            f", CPU slowed {args.slowdown:g}×",
            targets.PAGE_SLOWED if args.slowdown == 4 else None,
            ours,
        )


def _alternated(
    browser: Browser, sites: dict[str, str], count: int, slowdown: float
) -> dict[str, list[Run]]:
    """``count`` rounds, each a run of every site, the order turned round each round."""
    runs: dict[str, list[Run]] = {name: [] for name in sites}
    order = list(sites)
    for _ in range(count):
        for name in order:
            runs[name].append(measure(browser, sites[name], slowdown))
        order.reverse()
    return runs


def _report(
    runs: list[Run],
    heading: str,
    condition: str,
    target: targets.Target | None,
    ours: bool = True,
) -> None:
    """Print the medians of ``runs``, and the range of the main figures, with ``target``
    (a ratio to the bare page, or milliseconds to both charts) met or not; ``ours``: the
    figure is this tree's, kept for the run's results (:meth:`targets.Target.judged`)."""
    form = statistics.median(r.form_ready_ms for r in runs)
    charts = statistics.median(r.charts_ms for r in runs)
    reference = statistics.median(r.reference_ms for r in runs)
    ratio = statistics.median(r.charts_ms / r.reference_ms for r in runs)
    print(f"{heading}cold load{condition}, median of {len(runs)} runs (ms since navigation start):")
    print(f"  reference: bare index.html, no script, to load   {reference:8.1f} ms")
    print(f"  engineer's page: form ready                      {form:8.1f} ms")
    print(f"  engineer's page: worked example, both charts     {charts:8.1f} ms")
    print(f"  charts / reference                               {ratio:8.1f}")
    if target is not None:
        measured = ratio if target.unit == "×" else charts
        bare = f"bare page {reference:.0f} ms"
        print(f"  {target.judged(measured, bare) if ours else target.verdict(measured)}")
    print(
        "  all runs (charts ms): "
        + ", ".join(f"{r.charts_ms:.0f}" for r in runs)
        + f"  (plotly warm-up: {_counted(r.warm_up for r in runs)})"
    )
    print(f"  ratios: {_spread([r.charts_ms / r.reference_ms for r in runs], '.1f')}")
    cpu = [r.charts_cpu_ms for r in runs]
    print(
        f"  main thread to both charts: CPU {statistics.median(cpu):6.1f} ms "
        f"({_spread(cpu, '.0f')}), its tasks' wall clock "
        f"{statistics.median(r.charts_task_ms for r in runs):6.1f} ms"
    )
    clicks = statistics.median(r.submitted_ms - r.form_ready_ms for r in runs)
    selection = statistics.median(r.answers.selection_ms for r in runs)
    detail = statistics.median(r.answers.detail_ms for r in runs)
    idle_clicks = statistics.median(r.paused_clicks_ms for r in runs)
    print(
        f"  of the way to both charts: the user's clicks (form ready to submit) {clicks:.0f} "
        f"ms, {idle_clicks:.0f} ms after the pause below; then the server's answers as "
        f"the page had them: the selection {selection:.0f} ms, the best candidate's detail "
        f"and figures {detail:.0f} ms"
    )
    paused = statistics.median(r.paused_submit_to_charts_ms for r in runs)
    print(
        f"  form untouched for {PAUSE_MS} ms, then submit to both charts   {paused:8.1f} ms"
        f"  (plotly warm-up: {_counted(r.paused_warm_up for r in runs)})"
    )
    after = [r.paused_cpu_after_submit_ms for r in runs]
    print(
        f"    its main-thread CPU, submit to both charts {statistics.median(after):6.1f} ms "
        f"({_spread(after, '.0f')})"
    )


def _spread(values: Iterable[float], spec: str) -> str:
    """``12–15`` (the least and the greatest)."""
    listed = list(values)
    return f"{min(listed):{spec}}–{max(listed):{spec}}"


def _counted(values: Iterable[str]) -> str:
    """``done 6, skipped 1``."""
    return ", ".join(f"{k} {v}" for k, v in sorted(Counter(values).items()))


if __name__ == "__main__":
    main()
