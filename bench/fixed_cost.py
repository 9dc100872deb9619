"""The engine's fixed cost: one selection of one model, and one of the whole catalogue,
in process, as POST /api/v1/selections sizes them (``size_selection``, no database or
HTTP), against a reference computed in the same run.

The reference is 100 numpy additions on 1 × 1 arrays: what the machine charges for
numpy's per-call overhead, which a one-model selection is mostly made of. Times are the
process's CPU time, the best of many runs per round (other processes on the machine
disturb the wall clock far more), and each is printed with its ratio to the reference,
so that runs on different machines, or at different loads, compare.
"""

from __future__ import annotations

import tempfile
import time
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import numpy as np
import orjson

from actuator_selection.app import tune_gc
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.schemas.selections import SelectionRequest
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot
from actuator_selection.services.selections import size_selection
from bench.selection import http_case, random_cases, starter_catalogue

ROUNDS = 5


def reference() -> None:
    """100 numpy additions on a 1 × 1 array."""
    a = np.ones((1, 1))
    for _ in range(100):
        a = np.add(a, a)


def best(run: Callable[[], None], n: int) -> float:
    """The least CPU time of ``n`` runs [s]."""
    times = []
    for _ in range(n):
        started = time.process_time()
        run()
        times.append(time.process_time() - started)
    return min(times)


def sizer(catalogue: CatalogueSnapshot, body: SelectionRequest) -> Callable[[], None]:
    """One selection of ``body`` as the route sizes it (with the ratio study's guide)."""
    now = datetime.now(UTC)

    def run() -> None:
        actuators = catalogue.actuators_of(body.models)
        size_selection(body, body.to_core(), actuators, catalogue, now, guide=True)

    return run


def main() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        url = f"sqlite:///{Path(tmp) / 'bench.sqlite3'}"
        starter_catalogue(url)
        with make_session_factory(make_engine(url))() as session:
            catalogue = CatalogueCache().snapshot(session)
    tune_gc()  # as served
    case = http_case(random_cases(1, seed=3)[0])
    whole_body = SelectionRequest.model_validate(case)
    whole = sizer(catalogue, whole_body)
    # The model: the whole catalogue's best candidate (one that fits: no guide computed).
    answer = orjson.loads(
        size_selection(
            whole_body, whole_body.to_core(), catalogue.actuators, catalogue, datetime.now(UTC)
        ).answer
    )
    model = answer["candidates"][0]["model"]
    one = sizer(catalogue, SelectionRequest.model_validate({**case, "models": [model]}))
    for run in (one, whole, reference):  # warm the caches
        for _ in range(50):
            run()
    print(f"{len(catalogue.actuators)} actuators; one model: {model}; CPU time, best of runs")
    for k in range(ROUNDS):
        ref, t_one, t_whole = best(reference, 300), best(one, 300), best(whole, 60)
        print(
            f"round {k}: reference {ref * 1e6:6.1f} µs | one model {t_one * 1e3:6.3f} ms "
            f"= {t_one / ref:5.1f}× | whole catalogue {t_whole * 1e3:6.3f} ms "
            f"= {t_whole / ref:5.1f}×"
        )


if __name__ == "__main__":
    main()
