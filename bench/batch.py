"""Throughput of batch selection: the scalar flowchart per case against the vectorised batch.

Prints cases per second of ``sizing.selection.select`` run case by case and of
``sizing.engine.select_batch`` (best 3 per case) on the starter catalogue and on a
synthetic catalogue of 1,000 actuators, their ratio, and the end-to-end time of
POST /api/v1/selections/batch for 10,000 cases without checks, with checks and with
checks in words (JSON both ways included), each as a ratio to the numpy reference
(``bench/reference.py``) timed in the same run, with the count of cases whose best three
differ from it. Runs on a throw-away SQLite database seeded with the starter catalogue.

The synthetic actuators are made up (model names ``SYN-…``): plausible magnitudes
only, so that the scaling with catalogue size can be measured. They are not data.
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import random
import statistics
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from fastapi.testclient import TestClient

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.config import Settings
from actuator_selection.http.app import API_PREFIX, create_app, tune_gc
from actuator_selection.sizing.engine import evaluate_batch, rank_batch, select_batch
from actuator_selection.sizing.selection import select
from bench.reference import disagreements, numpy_reference, snapshot_actuators
from bench.selection import http_case, random_cases, starter_catalogue

TOP = 3
BATCH_CASES = 10_000


def synthetic_catalogue(n: int, seed: int = 11) -> list[Actuator]:
    """``n`` made-up actuators: sizes log-uniform, inertia and continuous torque scaled with
    the peak torque, a third with a continuous-duty zone, a few without J_A or T_0."""
    rng = random.Random(seed)
    out = []
    for k in range(n):
        t_max = math.exp(rng.uniform(math.log(5), math.log(2000)))
        n_max = rng.uniform(20, 500)
        stall = t_max * rng.uniform(0.3, 0.6)
        zone = None
        if rng.random() < 1 / 3:
            zone = ContinuousDutyZone(
                points=(
                    ZonePoint(speed_rpm=0.0, torque_nm=stall),
                    ZonePoint(speed_rpm=n_max * 0.6, torque_nm=stall * 0.9),
                    ZonePoint(speed_rpm=n_max, torque_nm=stall * 0.5),
                )
            )
        out.append(
            Actuator(
                model=f"SYN-{k:04d}",
                family="SYNTHETIC",
                gear_ratio=rng.choice([30.0, 50.0, 80.0, 100.0, 120.0, 160.0]),
                max_torque_nm=t_max,
                max_speed_rpm=n_max,
                inertia_kgm2=None if rng.random() < 0.05 else t_max * rng.uniform(1e-3, 1e-2),
                stall_torque_nm=None if rng.random() < 0.1 else stall,
                zone=zone,
            )
        )
    return out


def _timed(run: Callable[[], object]) -> float:
    start = time.perf_counter()
    run()
    return time.perf_counter() - start


def _cpu(run: Callable[[], object]) -> float:
    """The CPU time of this process while ``run`` runs [s]."""
    start = time.process_time()
    run()
    return time.process_time() - start


def _line(label: str, n: int, seconds: float) -> float:
    print(f"  {label:<46} {n:>6} cases in {seconds:7.3f} s = {n / seconds:10.0f} cases/s")
    return n / seconds


def _served_gc(run: Callable[[], object]) -> Callable[[], object]:
    """``run`` with the collector's thresholds of a served process (``main.tune_gc``)."""

    def tuned() -> object:
        before = gc.get_threshold()
        tune_gc()
        try:
            return run()
        finally:
            gc.set_threshold(*before)

    return tuned


def compare(name: str, actuators: list[Actuator], scalar_cases: int) -> None:
    """Scalar select() per case against the batch functions on one catalogue."""
    print(f"{name}: {len(actuators)} actuators")
    apps = random_cases(BATCH_CASES)
    scalar_apps = apps[:scalar_cases]

    def scalar_run() -> None:
        for app in scalar_apps:  # each result dropped, as a server answering case by case
            select(actuators, app)

    scalar = _line("scalar select() per case", len(scalar_apps), _timed(scalar_run))
    _line(
        "evaluate_batch(): all arrays, every cell",
        len(apps),
        _timed(lambda: evaluate_batch(actuators, apps)),
    )
    ranking = _line(
        f"rank_batch(top={TOP}): flowchart + ranking",
        len(apps),
        _timed(lambda: rank_batch(actuators, apps, top=TOP)),
    )
    vectorised = _line(
        f"select_batch(top={TOP}): + {TOP} candidates a case",
        len(apps),
        _timed(lambda: select_batch(actuators, apps, top=TOP)),
    )
    _line(
        "  the same, GC thresholds as served (tune_gc)",
        len(apps),
        _timed(_served_gc(lambda: select_batch(actuators, apps, top=TOP))),
    )
    print(
        f"  ratio to scalar select(): select_batch {vectorised / scalar:.0f}×, "
        f"rank_batch {ranking / scalar:.0f}×"
    )


HTTP_ROUNDS = 3
"""Rounds of the per-case batch against the numpy reference, each variant in turn."""

HTTP_VARIANTS: tuple[tuple[str, dict[str, bool]], ...] = (
    ("checks no ", {"include_checks": False}),
    ("checks yes", {"include_checks": True}),
    ("checks yes, messages yes", {"include_checks": True, "include_messages": True}),
)
"""The per-case batch's options timed against the reference: without checks, with
checks (their messages as codes and parameters), and with checks and their words."""


def http(url: str) -> None:
    """POST /selections/batch with 10,000 cases, end to end through the ASGI app, each
    variant of :data:`HTTP_VARIANTS` in each of :data:`HTTP_ROUNDS` rounds, against the
    numpy reference (``bench/reference.py``) timed right after it (the best of three):
    the ratio, and the cases whose best three differ from the service's (a count)."""
    print(
        f"HTTP POST {API_PREFIX}/selections/batch, {BATCH_CASES} cases, top {TOP}, "
        f"{HTTP_ROUNDS} rounds (TestClient: the request's JSON and the answer's bytes "
        "included, not the client's parsing of them; no compression), "
        "each against the numpy reference for the same cases (bench/reference.py)"
    )
    apps = random_cases(BATCH_CASES, seed=8)
    payload = [http_case(a) for a in apps]
    actuators = snapshot_actuators(url)
    ratios: dict[str, list[float]] = {}
    cpu_ratios: dict[str, list[float]] = {}
    with TestClient(create_app(Settings(database_url=url))) as client:
        for _ in range(HTTP_ROUNDS):
            for name, options in HTTP_VARIANTS:
                body = json.dumps({"cases": payload, "top": TOP, **options}).encode()
                start, cpu = time.perf_counter(), time.process_time()
                response = client.post(
                    f"{API_PREFIX}/selections/batch",
                    content=body,
                    headers={"content-type": "application/json", "accept-encoding": "identity"},
                )
                if response.status_code == 422:  # a service without the option
                    print(f"  {name}: refused (422), skipped")
                    continue
                seconds = time.perf_counter() - start  # the answer received, not yet parsed
                cpu = time.process_time() - cpu  # the server's thread and the client's
                response.raise_for_status()
                results = response.json()["results"]
                assert len(results) == BATCH_CASES
                reference = min(
                    _timed(lambda: numpy_reference(actuators, apps, TOP)) for _ in range(3)
                )
                reference_cpu = min(
                    _cpu(lambda: numpy_reference(actuators, apps, TOP)) for _ in range(3)
                )
                service = [[c["model"] for c in r["candidates"]] for r in results]
                differ = disagreements(actuators, numpy_reference(actuators, apps, TOP), service)
                ratios.setdefault(name, []).append(seconds / reference)
                cpu_ratios.setdefault(name, []).append(cpu / reference_cpu)
                print(
                    f"  {name:<25} {len(response.content) / 1e6:5.1f} MB out {seconds:6.2f} s "
                    f"(CPU {cpu:6.2f} s), reference {reference * 1e3:5.0f} ms "
                    f"(CPU {reference_cpu * 1e3:5.0f} ms): {seconds / reference:5.1f}× "
                    f"(CPU {cpu / reference_cpu:5.1f}×); top {TOP} differs in {differ} of "
                    f"{BATCH_CASES} cases"
                )
    # On a shared machine the wall clock moves with the neighbours' load; the process's
    # CPU time (TestClient serves in a thread of this process) much less.
    for name, measured in ratios.items():
        spent = cpu_ratios[name]
        print(
            f"  {name:<25} × the reference: {min(measured):.1f}–{max(measured):.1f} "
            f"(median {statistics.median(measured):.1f}); CPU time "
            f"{min(spent):.1f}–{max(spent):.1f} (median {statistics.median(spent):.1f})"
        )


def main() -> None:
    """Run the benchmark and print its table."""
    parser = argparse.ArgumentParser(prog="python -m bench.batch")
    parser.add_argument("--http-only", action="store_true", help="only the HTTP batch")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        url = f"sqlite:///{Path(tmp) / 'bench.sqlite3'}"
        starter = starter_catalogue(url)
        if args.http_only:
            http(url)
            return

        compare("starter catalogue", starter, scalar_cases=2_000)
        compare("synthetic catalogue", synthetic_catalogue(1_000), scalar_cases=200)
        http(url)


if __name__ == "__main__":
    main()
