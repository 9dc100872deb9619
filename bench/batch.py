"""Throughput of batch selection: the scalar flowchart per case against the vectorised batch.

Prints cases per second of ``sizing.selection.select`` run case by case and of
``sizing.engine.select_batch`` (best 3 per case) on the starter catalogue and on a
synthetic catalogue of 1,000 actuators, their ratio, and the end-to-end time of
POST /api/v1/selections/batch for 10,000 cases without checks, with checks and with
checks in words, sent to a real server process (``bench.http``'s): its CPU time as a
ratio to the numpy reference's (``bench/reference.py``) timed in the same run, with the
count of cases whose best three differ from it; and how long ``/health`` waits while the
same server validates the largest batch body (:func:`health_while_validating`). Runs on
a throw-away SQLite database seeded with the starter catalogue.

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
import threading
import time
from collections.abc import Callable
from pathlib import Path

import httpx

from actuator_selection.app import tune_gc
from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.schemas.batch import MAX_BATCH_CASES
from actuator_selection.sizing.engine import evaluate_batch, rank_batch, select_batch
from actuator_selection.sizing.selection import select
from bench.http import _serve, batch_server_cpu
from bench.reference import snapshot_actuators
from bench.selection import random_cases, starter_catalogue

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


def http(url: str) -> None:
    """POST /selections/batch with 10,000 cases to a real server (``bench.http``'s, on
    the database at ``url``), each variant in each of :data:`HTTP_ROUNDS` rounds: the
    server process's CPU time ÷ the numpy reference's (:func:`bench.http.batch_server_cpu`).
    """
    process, base = _serve(url, {"WORKERS": "1"})
    try:
        batch_server_cpu(
            base, process.pid, snapshot_actuators(url), n=BATCH_CASES, rounds=HTTP_ROUNDS, top=TOP
        )
        health_while_validating(base)
    finally:
        process.terminate()
        process.wait(10)


SEGMENTS = [
    {"speed": 30, "duration_s": 0.2},
    {"duration_s": 0.4},
    {"speed": 0, "duration_s": 0.2},
    {"duration_s": 0.3},
] * 10
"""A cycle of 40 segments."""


def slow_to_validate() -> tuple[int, bytes]:
    """A per-case batch that takes seconds to validate, within the limits: 20,000 cases
    of 40 segments (21 MB against the bulk limit of 32 MiB), the last one refused (T_L
    below 0), so that a server answers 422 when it has validated them all. The number of
    cases and the body."""
    case: dict[str, object] = {
        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"segments": SEGMENTS},
    }
    refused = {**case, "load": {"torque_nm": -1, "inertia_kgm2": 1.3}}
    cases = [case] * (MAX_BATCH_CASES - 1) + [refused]
    return len(cases), json.dumps({"cases": cases, "top": 1}, separators=(",", ":")).encode()


def health_while_validating(base: str, rounds: int = HTTP_ROUNDS) -> None:
    """``GET /health`` asked again and again (5 ms apart) while the server at ``base``
    validates :func:`slow_to_validate`'s batch (a 422: the validation is all the request
    does): the slowest answer meanwhile and the median, in each of ``rounds`` rounds. A
    process validating on its event loop answers nothing else until it is done."""
    n, body = slow_to_validate()
    print(
        f"GET /api/v1/health while POST /api/v1/selections/batch is validated ({n} cases of "
        f"{len(SEGMENTS)} segments, {len(body) / 1e6:.0f} MB, refused at its last case), "
        f"{rounds} rounds:"
    )
    headers = {"content-type": "application/json"}
    for _ in range(rounds):
        waits: list[float] = []
        done = threading.Event()
        asker = threading.Thread(target=_ask_health, args=(base, waits, done))
        asker.start()
        with httpx.Client(base_url=base, timeout=600) as client:
            started = time.perf_counter()
            answer = client.post("/api/v1/selections/batch", content=body, headers=headers)
            seconds = time.perf_counter() - started
        done.set()
        asker.join()
        print(
            f"  the batch {answer.status_code} in {seconds:5.2f} s; /health answered "
            f"{len(waits)} times, the slowest in {max(waits) * 1e3:6.0f} ms "
            f"(median {statistics.median(waits) * 1e3:4.1f} ms)"
        )


def _ask_health(base: str, waits: list[float], done: threading.Event) -> None:
    """``GET /health`` until ``done``, each answer's time into ``waits`` [s]."""
    with httpx.Client(base_url=base, timeout=600) as client:
        while not done.is_set():
            started = time.perf_counter()
            client.get("/api/v1/health").raise_for_status()
            waits.append(time.perf_counter() - started)
            time.sleep(0.005)


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
