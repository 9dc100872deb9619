"""Throughput of the selection flowchart: the pure core against the whole HTTP path.

Prints cases per second for each and their ratio, so a change can be judged on
any machine: the ratio says how much of a request's time the engineering takes.
Runs on a throw-away SQLite database seeded with the starter catalogue.
"""

from __future__ import annotations

import random
import tempfile
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from fastapi.testclient import TestClient

from actuator_selection.app import create_app, tune_allocator, tune_gc
from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.repositories import CatalogueRepository
from actuator_selection.db.seed import load_seed
from actuator_selection.schemas.selections import SelectionRequest
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot
from actuator_selection.services.presenters.selection import DEFAULT_TOP
from actuator_selection.services.selections import size_selection
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.selection import Application, select
from bench import targets
from bench.reference import numpy_reference


def random_cases(n: int, seed: int = 7) -> list[Application]:
    """``n`` plausible load cases, the same for the same seed."""
    rng = random.Random(seed)
    return [
        Application(
            pattern=SpeedPattern(
                speed_rpm=rng.uniform(5, 150),
                accel_s=rng.uniform(0.05, 0.5),
                constant_s=rng.uniform(0, 1),
                decel_s=rng.uniform(0.05, 0.5),
                pause_s=rng.uniform(0, 2),
            ),
            load=Load(torque_nm=rng.uniform(0, 50), inertia_kgm2=rng.uniform(0, 5)),
            high_dynamics=rng.random() < 0.5,
        )
        for _ in range(n)
    ]


def http_columns(apps: Sequence[Application]) -> dict[str, Any]:
    """The JSON body of POST /selections/batch/columns for ``apps`` (the chapter's cycle)."""
    patterns = [a.pattern for a in apps if a.pattern is not None]
    loads = [a.load for a in apps if a.load is not None]
    assert len(patterns) == len(loads) == len(apps), "the bench sizes the chapter's cycle"
    return {
        "speed_rpm": [p.speed_rpm for p in patterns],
        "torque_nm": [x.torque_nm for x in loads],
        "inertia_kgm2": [x.inertia_kgm2 for x in loads],
        "accel_s": [p.accel_s for p in patterns],
        "constant_s": [p.constant_s for p in patterns],
        "decel_s": [p.decel_s for p in patterns],
        "pause_s": [p.pause_s for p in patterns],
        "high_dynamics": [a.high_dynamics for a in apps],
    }


def http_case(app: Application) -> dict[str, Any]:
    """The JSON body of a selection request for ``app``."""
    p, load = app.pattern, app.load
    assert p is not None, "the bench sizes the chapter's cycle"
    assert load is not None
    return {
        "load": {
            "speed_rpm": p.speed_rpm,
            "torque_nm": load.torque_nm,
            "inertia_kgm2": load.inertia_kgm2,
        },
        "cycle": {
            "accel_s": p.accel_s,
            "constant_s": p.constant_s,
            "decel_s": p.decel_s,
            "pause_s": p.pause_s,
        },
        "high_dynamics": app.high_dynamics,
    }


def starter_catalogue(url: str) -> list[Actuator]:
    """Migrate and seed the database at ``url``; its actuators."""
    upgrade(url=url)
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
        with make_session_factory(engine)() as session:
            return [r.actuator for r in CatalogueRepository(session).actuators()]
    finally:
        engine.dispose()


def _rate(label: str, n: int, run: Callable[[], None]) -> float:
    start = time.perf_counter()
    run()
    elapsed = time.perf_counter() - start
    print(f"{label:<44} {n:>6} cases in {elapsed:7.3f} s = {n / elapsed:10.0f} cases/s")
    return n / elapsed


def main() -> None:
    """Run the benchmark and print its table."""
    with tempfile.TemporaryDirectory() as tmp:
        url = f"sqlite:///{Path(tmp) / 'bench.sqlite3'}"
        actuators = starter_catalogue(url)

        core_cases = random_cases(2000)

        def select_all() -> None:
            for app in core_cases:
                select(actuators, app)

        core = _rate(f"core select() over {len(actuators)} actuators", len(core_cases), select_all)

        http_cases = random_cases(200)
        app = create_app(Settings(database_url=url))
        with TestClient(app) as client:

            def post_all() -> None:
                for c in http_cases:
                    response = client.post("/api/v1/selections", json=http_case(c))
                    response.raise_for_status()

            http = _rate("POST /api/v1/selections (stored)", len(http_cases), post_all)
        print(
            f"ratio core / HTTP: {core / http:.1f}× (engineering share of a request "
            f"≈ {http / core:.0%})"
        )
        with make_session_factory(make_engine(url))() as session:
            starter = CatalogueCache().snapshot(session)
    for copies in (100, 1000):  # 6,400 and 64,000 actuators (issue 32: ≤ 20 / ≤ 100 ms)
        large_catalogue(starter, copies=copies)


def copied_catalogue(starter: CatalogueSnapshot, copies: int) -> CatalogueSnapshot:
    """``starter`` with its actuators ``copies`` times, renamed (``CHA-25A-50~017``): a
    catalogue of that size to measure with, not data; ``starter`` itself for 1."""
    if copies == 1:
        return starter
    actuators = tuple(
        replace(a, model=f"{a.model}~{k:03d}") for k in range(copies) for a in starter.actuators
    )
    interfaces = {
        f"{model}~{k:03d}": interface
        for k in range(copies)
        for model, interface in starter.interfaces.items()
    }
    by_model = {a.model: a for a in actuators}
    return replace(starter, actuators=actuators, interfaces=interfaces, _by_model=by_model)


def large_catalogue(starter: CatalogueSnapshot, copies: int) -> None:
    """One whole-catalogue selection over ``copies`` × the starter catalogue, server side.

    The copies are the starter's actuators renamed (``CHA-25A-50~017``): a catalogue of
    that size to measure with, not data. Timed is what the server computes for POST
    /selections after reading the request: the flowchart, the answer's JSON and its
    gzip (the database insert and HTTP come on top; see bench/http.py).
    """
    catalogue = copied_catalogue(starter, copies)
    actuators = catalogue.actuators
    tune_gc()  # as served (app.serve_app): the collector's and the allocator's settings
    tune_allocator()
    body = SelectionRequest.model_validate(http_case(random_cases(1, seed=3)[0]))
    app = body.to_core()
    size_selection(body, app, actuators, catalogue, datetime.now(UTC))  # warm the caches
    times, reference = [], []
    for _ in range(5):  # interleaved with the reference: a change in load shifts both
        started = time.perf_counter()
        sized = size_selection(body, app, actuators, catalogue, datetime.now(UTC))
        times.append(time.perf_counter() - started)
        started = time.perf_counter()
        numpy_reference(actuators, [app], DEFAULT_TOP)
        reference.append(time.perf_counter() - started)
    stored = len(sized.ranking or b"")
    target = {100: targets.SELECTION_6400, 1000: targets.SELECTION_64000}.get(copies)
    print(
        f"one selection over {len(actuators)} actuators (server side, no DB/HTTP): "
        f"{min(times) * 1e3:.1f} ms (best of 5), numpy reference {min(reference) * 1e3:.1f} ms: "
        f"{min(times) / min(reference):.1f}× the reference; answer (top {DEFAULT_TOP}) "
        f"{len(sized.answer) / 1e6:.2f} MB, {len(sized.answer_gzip) / 1e3:.0f} kB gzip; the "
        f"rest of the ranking stored {stored / 1e3:.0f} kB"
        + (
            f"; {target.judged(min(times) * 1e3, f'numpy {min(reference) * 1e3:.1f} ms')}"
            if target
            else ""
        )
    )


if __name__ == "__main__":
    main()
