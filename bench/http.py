"""HTTP throughput of the real server under concurrent clients, against its own /health.

Starts ``python -m actuator_selection serve`` (uvicorn) on a free loopback port on a
fresh database seeded with the starter catalogue, runs ``--clients`` keep-alive
clients for ``--seconds`` against each endpoint, in ``--rounds`` interleaved windows
(each round every endpoint in turn), and prints the median requests per second, the
median of the rounds' ratios to ``GET /api/v1/health`` and each round's, the server
process's CPU time per request and /health's divided by it (with workers > 1: the
master's only), and every answer that was not 2xx (there should be none). Then, with
one worker, batches of random cases, per case and as columns, each against the numpy
reference (``bench/reference.py``) timed right after it, and the per-case batch of
10,000 cases in ``--rounds`` rounds as the server's CPU time ÷ the reference's
(:func:`batch_server_cpu`, issue 32's figure).

    python -m bench.http                       # PostgreSQL at $TEST_POSTGRES_URL if it answers
    python -m bench.http --database sqlite     # the embedded default
"""

from __future__ import annotations

import argparse
import gzip
import json
import math
import os
import socket
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from collections import Counter
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any

import httpx
import orjson
import zstandard
from sqlalchemy import create_engine, text
from sqlalchemy.engine import make_url

from actuator_selection.app import GZIP_LEVEL, ZSTD_LEVEL
from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.config import REPO_ROOT
from actuator_selection.db.engine import normalise_url
from bench import targets
from bench.reference import disagreements, numpy_reference, snapshot_actuators
from bench.selection import http_case, http_columns, random_cases, starter_catalogue

WORKED_EXAMPLE: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}
POSTGRES_URL = os.environ.get("TEST_POSTGRES_URL", "postgresql://postgres@127.0.0.1:5432/test")


def _postgres_database() -> tuple[str, Callable[[], None]] | None:
    """A throw-away PostgreSQL database and how to drop it; None without a server."""
    admin = create_engine(normalise_url(POSTGRES_URL), isolation_level="AUTOCOMMIT")
    try:
        with admin.connect() as conn:
            name = f"actuator_bench_{uuid.uuid4().hex[:12]}"
            conn.execute(text(f'CREATE DATABASE "{name}"'))
    except Exception:  # any failure to connect means "no server here"
        admin.dispose()
        return None

    def drop() -> None:
        with admin.connect() as conn:
            conn.execute(text(f'DROP DATABASE IF EXISTS "{name}" WITH (FORCE)'))
        admin.dispose()

    url = make_url(normalise_url(POSTGRES_URL)).set(database=name)
    return url.render_as_string(hide_password=False), drop


def _serve(url: str, env: dict[str, str]) -> tuple[subprocess.Popen[bytes], str]:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        port = sock.getsockname()[1]
    process = subprocess.Popen(
        [sys.executable, "-m", "actuator_selection", "serve", "--port", str(port)],
        cwd=REPO_ROOT,
        env={**os.environ, "DATABASE_URL": url, **env},
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    base = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 120  # a loaded shared machine starts it slowly
    while time.monotonic() < deadline:
        try:
            if httpx.get(f"{base}/api/v1/health", timeout=1).status_code == 200:
                return process, base
        except httpx.TransportError:
            time.sleep(0.05)
    process.kill()
    raise SystemExit("the server did not start")


def _load(
    base: str, method: str, path: str, body: dict[str, Any] | None, *, clients: int, seconds: float
) -> tuple[float, Counter[str], int]:
    """Requests per second, the non-2xx outcomes, and the mean answer size [bytes]."""
    outcomes: Counter[str] = Counter()
    sizes: list[int] = []
    lock = threading.Lock()
    deadline = time.monotonic() + seconds

    def client() -> None:
        with httpx.Client(base_url=base, timeout=60) as c:
            while time.monotonic() < deadline:
                try:
                    r = c.request(method, path, json=body)
                    key, size = str(r.status_code), len(r.content)
                except httpx.TransportError as exc:
                    key, size = type(exc).__name__, 0
                with lock:
                    outcomes[key] += 1
                    sizes.append(size)

    started = time.monotonic()
    with ThreadPoolExecutor(clients) as pool:
        for future in [pool.submit(client) for _ in range(clients)]:
            future.result()
    elapsed = time.monotonic() - started
    total = sum(outcomes.values())
    failures = Counter({k: n for k, n in outcomes.items() if not k.startswith("2")})
    return total / elapsed, failures, sum(sizes) // max(1, len(sizes))


def _cpu_s(pid: int) -> float:
    """CPU time the process has used so far, user + system [s] (Linux /proc)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _peak_rss_mb(pid: int) -> float:
    """The process's peak resident memory [MB] (Linux /proc)."""
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmHWM:"):
            return int(line.split()[1]) / 1024
    return float("nan")


def _batch(
    base: str, pid: int, n: int, actuators: list[Actuator], checks: bool, *, columns: bool
) -> None:
    """One batch of ``n`` random cases (top 3), as cases (POST /selections/batch) or as
    columns (POST /selections/batch/columns, the best of three): time, answer size, the
    server's peak RSS, and the time of the numpy reference for the same cases (the best
    of three), measured right after."""
    apps = random_cases(n)
    options = {"top": 3, "include_checks": checks}
    if columns:
        path, body = "/selections/batch/columns", {**http_columns(apps), **options}
    else:
        path, body = "/selections/batch", {"cases": [http_case(app) for app in apps], **options}
    before = _peak_rss_mb(pid)
    # A table takes a fraction of a second: the best of three, as the reference's.
    elapsed = math.inf
    for _ in range(3 if columns else 1):
        started = time.monotonic()
        response = httpx.post(f"{base}/api/v1{path}", json=body, timeout=600)
        elapsed = min(elapsed, time.monotonic() - started)
    reference_s = min(_timed(lambda: numpy_reference(actuators, apps, 3)) for _ in range(3))
    answer = response.json()
    service: list[list[str]] = [[] for _ in apps]
    if columns:
        table = answer["candidates"]
        for case, model in zip(table["case"], table["model"], strict=True):
            service[case].append(model)
    else:
        service = [[c["model"] for c in r["candidates"]] for r in answer["results"]]
    differ = disagreements(actuators, numpy_reference(actuators, apps, 3), service)
    ratio = elapsed / reference_s
    verdict = ""
    if columns and checks:
        judged = targets.BATCH_COLUMNS.judged(ratio, f"numpy {reference_s * 1e3:.0f} ms")
        verdict = f"; {judged}"
    print(
        f"  POST {path}, {n} cases, checks {'yes' if checks else 'no '}  "
        f"{elapsed:6.2f} s  HTTP {response.status_code}  answer "
        f"{len(response.content) / 1e6:5.1f} MB  server peak RSS {before:.0f} → "
        f"{_peak_rss_mb(pid):.0f} MB\n"
        f"    numpy reference {reference_s * 1e3:6.1f} ms "
        f"(top 3 differs in {differ} of {n} cases): "
        f"the request takes {ratio:4.1f}× the reference{verdict}"
    )
    if not columns:
        coding = response.headers.get("content-encoding")
        floor_s = _json_and_coding_s(body, answer, coding=coding)
        print(
            f"    the request's and the answer's JSON and {coding or 'no'} coding alone "
            f"{floor_s * 1e3:6.1f} ms: "
            f"{floor_s / reference_s:4.1f}× the reference"
        )


BATCH_VARIANTS: tuple[tuple[str, dict[str, bool]], ...] = (
    ("checks no ", {"include_checks": False}),
    ("checks yes", {"include_checks": True}),
    ("checks yes, messages yes", {"include_checks": True, "include_messages": True}),
)
"""The per-case batch's options measured against the reference: without checks, with
checks (their messages as codes and parameters; issue 32's figure), and with words."""


def batch_server_cpu(
    base: str,
    pid: int,
    actuators: list[Actuator],
    *,
    n: int = 10_000,
    rounds: int = 3,
    variants: tuple[tuple[str, dict[str, bool]], ...] = BATCH_VARIANTS,
    top: int = 3,
) -> None:
    """POST /selections/batch with ``n`` random cases (seed 8), each of ``variants`` in
    turn in each of ``rounds`` rounds, to the server ``pid`` at ``base``: the server
    process's CPU time for the request (its JSON parsed, the cases sized, the answer
    written; uncompressed, ``accept-encoding: identity``) divided by the CPU time of the
    numpy reference for the same cases in this process (the best of three) measured right
    after it, each round's and the range; and the cases whose best three differ from the
    reference's (a count). The client's writing and reading are not in it."""
    print(
        f"POST /api/v1/selections/batch, {n} cases, top {top}, {rounds} rounds: server "
        "CPU ÷ the numpy reference's CPU (bench/reference.py), measured right after"
    )
    apps = random_cases(n, seed=8)
    payload = [http_case(app) for app in apps]
    expected = numpy_reference(actuators, apps, top)
    ratios: dict[str, list[float]] = {}
    references: dict[str, list[float]] = {}
    with httpx.Client(base_url=f"{base}/api/v1", timeout=600) as client:
        for _ in range(rounds):
            for name, options in variants:
                body = json.dumps({"cases": payload, "top": top, **options}).encode()
                headers = {"content-type": "application/json", "accept-encoding": "identity"}
                cpu = _cpu_s(pid)
                started = time.monotonic()
                response = client.post("/selections/batch", content=body, headers=headers)
                seconds = time.monotonic() - started
                cpu = _cpu_s(pid) - cpu
                response.raise_for_status()
                reference = min(
                    _cpu(lambda: numpy_reference(actuators, apps, top)) for _ in range(3)
                )
                results = response.json()["results"]
                service = [[c["model"] for c in r["candidates"]] for r in results]
                differ = disagreements(actuators, expected, service)
                ratios.setdefault(name, []).append(cpu / reference)
                references.setdefault(name, []).append(reference)
                print(
                    f"  {name:<25} {len(response.content) / 1e6:5.1f} MB  {seconds:6.2f} s, "
                    f"server CPU {cpu:6.2f} s, reference CPU {reference * 1e3:5.0f} ms: "
                    f"{cpu / reference:5.1f}×; top {top} differs in {differ} of {n} cases"
                )
    for (name, options), measured in zip(variants, ratios.values(), strict=True):
        median = statistics.median(measured)
        target = targets.BATCH_PER_CASE if options == {"include_checks": True} else None
        print(
            f"  {name:<25} server CPU × the reference's: {min(measured):.1f}–"
            f"{max(measured):.1f} (median {median:.1f})"
            + (f"; {target.judged(median, _numpy(references[name]))}" if target else "")
        )


def _numpy(references: list[float]) -> str:
    """The numpy reference's CPU times [s] as the results of ``make bench`` name them."""
    return f"numpy {statistics.median(references) * 1e3:.0f} ms"


def _cpu(run: Callable[[], object]) -> float:
    """The CPU time of this process while ``run`` runs [s]."""
    started = time.process_time()
    run()
    return time.process_time() - started


def _httpx_json(body: Any) -> bytes:
    """The request's body as httpx writes ``json=`` (httpx._content.encode_json)."""
    return json.dumps(body, ensure_ascii=False, separators=(",", ":"), allow_nan=False).encode()


def _json_and_coding_s(body: dict[str, Any], answer: Any, *, coding: str | None) -> float:
    """What moving this request and answer costs before any engineering, best of 3 [s]:
    the client writing the request (httpx's encoder), the framework parsing it (FastAPI
    parses with the standard library), the answer written (orjson, as the service
    writes it) and, where it came compressed (``coding``: zstd or gzip), compressed at
    the service's level and decompressed by the client. A floor for this contract over
    HTTP in Python."""
    encoded = _httpx_json(body)
    written = orjson.dumps(answer)
    codecs: dict[str, tuple[Callable[[bytes], bytes], Callable[[bytes], bytes]]] = {
        "gzip": (lambda b: gzip.compress(b, GZIP_LEVEL), gzip.decompress),
        "zstd": (
            lambda b: zstandard.ZstdCompressor(level=ZSTD_LEVEL).compress(b),
            lambda b: zstandard.ZstdDecompressor().decompressobj().decompress(b),
        ),
    }
    codec = codecs.get(coding or "")
    compressed = codec[0](written) if codec else b""

    def moved() -> None:
        _httpx_json(body)
        json.loads(encoded)
        orjson.dumps(answer)
        if codec is not None:
            codec[0](written)
            codec[1](compressed)

    return min(_timed(moved) for _ in range(3))


def _timed(run: Callable[[], object]) -> float:
    started = time.perf_counter()
    run()
    return time.perf_counter() - started


def _stored_row_bytes(url: str) -> float:
    """Mean size of a stored selection row's data (answer and request) [bytes]."""
    engine = create_engine(normalise_url(url))
    request = "octet_length(request::text)" if url.startswith("postgresql") else "length(request)"
    try:
        with engine.connect() as conn:
            return float(
                conn.execute(
                    text(f"SELECT avg(length(answer_gzip) + {request}) FROM selections")
                ).scalar_one()
            )
    finally:
        engine.dispose()


def main() -> None:
    """Measure and print; see the module docstring."""
    parser = argparse.ArgumentParser(prog="python -m bench.http")
    parser.add_argument("--database", choices=["postgresql", "sqlite"], default="postgresql")
    parser.add_argument("--clients", type=int, default=32)
    parser.add_argument("--seconds", type=float, default=8.0)
    parser.add_argument("--workers", type=int, default=1)
    parser.add_argument("--rounds", type=int, default=3, help="windows per endpoint, interleaved")
    parser.add_argument("--batch-cases", type=int, default=20_000)
    args = parser.parse_args()
    drop: Callable[[], None] = lambda: None  # noqa: E731
    found = _postgres_database() if args.database == "postgresql" else None
    with tempfile.TemporaryDirectory() as folder:
        if found is None:
            url = f"sqlite:///{Path(folder) / 'bench.sqlite3'}"
            if args.database == "postgresql":
                print("PostgreSQL unreachable: measuring on SQLite")
        else:
            url, drop = found
        starter_catalogue(url)
        actuators = snapshot_actuators(url)
        process, base = _serve(url, {"WORKERS": str(args.workers)})
        try:
            print(
                f"{make_url(url).get_backend_name()}, {args.workers} worker(s), "
                f"{args.clients} clients, {args.seconds:g} s each in {args.rounds} rounds"
            )
            # Each endpoint with the target of its requests per second ÷ /health's.
            cases: list[tuple[str, str, str, dict[str, Any] | None, targets.Target | None]] = [
                ("GET /health", "GET", "/api/v1/health", None, None),
                ("POST /selections, one model", "POST", "/api/v1/selections",
                 {**WORKED_EXAMPLE, "models": ["FHA-25C-50-L"]}, targets.ONE_MODEL),
                ("POST /selections, whole catalogue", "POST", "/api/v1/selections",
                 WORKED_EXAMPLE, targets.WHOLE_CATALOGUE),
            ]  # fmt: skip
            # a file of the page (a cold load of the engineer's page asks for 21 of them)
            cases.append(("GET a page file, /pages/engineer/app.js", "GET",
                          "/pages/engineer/app.js", None, None))  # fmt: skip
            stored = httpx.post(f"{base}/api/v1/selections", json=WORKED_EXAMPLE).json()["id"]
            cases.append(("GET /selections/{id}, whole catalogue", "GET",
                          f"/api/v1/selections/{stored}", None, None))  # fmt: skip
            for _, method, path, body, _ in cases:  # warm up: routes built, caches filled
                _load(base, method, path, body, clients=4, seconds=1.0)
            # Rounds, each endpoint in turn within each: a change in the machine's load
            # (it is shared) then shifts every endpoint of a round alike, and the median
            # of the rounds' ratios is not carried by one slow window.
            window = args.seconds / args.rounds
            runs: dict[str, list[tuple[float, float, Counter[str], int]]] = {}
            for _ in range(args.rounds):
                for name, method, path, body, _ in cases:
                    cpu = _cpu_s(process.pid)
                    rate, failures, size = _load(
                        base, method, path, body, clients=args.clients, seconds=window
                    )
                    cpu_ms = (_cpu_s(process.pid) - cpu) / (rate * window) * 1e3
                    runs.setdefault(name, []).append((rate, cpu_ms, failures, size))
            health = [rate for rate, _, _, _ in runs[cases[0][0]]]
            health_cpu = statistics.median(c for _, c, _, _ in runs[cases[0][0]])
            for (name, *_, target), measured in zip(cases, runs.values(), strict=True):
                rates = [rate for rate, _, _, _ in measured]
                ratios = [rate / h for rate, h in zip(rates, health, strict=True)]
                cpu_ms = statistics.median(c for _, c, _, _ in measured)
                failures = sum((f for _, _, f, _ in measured), Counter())
                verdict = ""
                if target:
                    against = f"/health {statistics.median(health):.0f} req/s"
                    verdict = f"; {target.judged(statistics.median(ratios), against)}"
                # The CPU ratio leaves out the clients, which share the machine and spend
                # more on a larger answer (its gzip and JSON).
                print(
                    f"  {name:36s} {statistics.median(rates):8.1f} req/s  "
                    f"{statistics.median(ratios):5.2f}× /health (rounds "
                    f"{' '.join(f'{r:.2f}' for r in ratios)})  server CPU "
                    f"{cpu_ms:5.2f} ms/req ({health_cpu / cpu_ms:4.2f}× /health's)  answer "
                    f"{measured[0][3] / 1024:6.1f} KiB  non-2xx {dict(failures) or 0}{verdict}"
                )
            print(f"  stored selection row (answer gzip + request): "
                  f"{_stored_row_bytes(url) / 1024:.1f} KiB on average")  # fmt: skip
            if args.workers == 1:  # the peak RSS is the served process's own
                # Each form of the batch on a server of its own: its peak memory is its.
                for columns in (False, True):
                    if columns:
                        process.terminate()
                        process.wait(10)
                        process, base = _serve(url, {"WORKERS": "1"})
                    sizes = ((10_000, False), (10_000, True), (args.batch_cases, True))
                    for n, checks in sizes[: 3 if args.batch_cases else 2]:  # 0: none more
                        _batch(base, process.pid, n, actuators, checks, columns=columns)
                    if not columns:
                        batch_server_cpu(base, process.pid, actuators, rounds=args.rounds)
        finally:
            process.terminate()
            process.wait(10)
            drop()


if __name__ == "__main__":
    main()
