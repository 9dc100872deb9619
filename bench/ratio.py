"""The whole-catalogue ratio study (issue 31 part 1) against a plain whole-catalogue
selection of the same load case, in the same run: the study's time as a ratio of the
selection's (the issue's target: at most 5×). Server side, no database or HTTP: what
POST /selections and POST /selections/ratio-study compute after reading the request.
Runs on a throw-away SQLite database seeded with the starter catalogue, and on 10 × and
100 × its copies (renamed, a size to measure with, not data).

Times are CPU times of this process (``time.process_time``), the least of several
rounds, the selection and the study of a case measured alternately in each round: on a
machine shared with other work the wall time measures the others too. ``--rounds``
sets the rounds (5 by default), ``--copies`` the sizes (1 10 100)."""

from __future__ import annotations

import argparse
import tempfile
import time
from collections.abc import Callable
from datetime import UTC, datetime
from functools import partial
from pathlib import Path
from typing import Any

from actuator_selection.app import tune_gc
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.schemas.ratio import RatioStudyRequest
from actuator_selection.schemas.selections import SelectionRequest
from actuator_selection.services.catalogue import CatalogueCache
from actuator_selection.services.ratio import study
from actuator_selection.services.selections import size_selection
from bench.selection import copied_catalogue, starter_catalogue

CASES: dict[str, dict[str, Any]] = {
    "vertical screw, lead 5–1000 mm": {
        "load": {
            "type": "ball_screw_incline",
            "mass_kg": 25.0,
            "lead_mm": 10.0,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
            "incline_deg": 90,
            "speed": 300,
        },
        "cycle": {"accel_s": 0.1, "constant_s": 0.3, "decel_s": 0.1, "pause_s": 0.5},
        "ratio_study": {"variable": "lead_mm", "min": 5, "max": 1000},
    },
    "worked example, ratio 1–20": {
        "load": {"speed_rpm": 4, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
        "ratio_study": {"variable": "ratio", "min": 1, "max": 20},
    },
    "worked example, ratio 0.05–2000": {
        "load": {"speed_rpm": 4, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
        "ratio_study": {"variable": "ratio", "min": 0.05, "max": 2000},
    },
    "worked example, ratio 1–20, η_tr 0.9": {
        "load": {"speed_rpm": 4, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
        "ratio_study": {
            "variable": "ratio",
            "min": 1,
            "max": 20,
            "transmission_efficiency": 0.9,
            "transmission_inertia_kgm2": 1e-4,
        },
    },
    "vertical belt, pulley 20–200 mm": {
        "load": {
            "type": "belt",
            "mass_kg": 5.0,
            "pulley_diameter_mm": 50.0,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
            "incline_deg": 90,
            "speed": 1000,
        },
        "cycle": {"accel_s": 0.1, "constant_s": 0.3, "decel_s": 0.1, "pause_s": 0.5},
        "ratio_study": {"variable": "pulley_diameter_mm", "min": 20, "max": 200},
    },
    "horizontal rack, pinion 20–200 mm": {
        "load": {
            "type": "rack_pinion",
            "mass_kg": 200.0,
            "pinion_diameter_mm": 80.0,
            "friction_coefficient": 0.1,
            "efficiency": 0.95,
            "speed": 500,
        },
        "cycle": {"accel_s": 0.2, "constant_s": 0.6, "decel_s": 0.2, "pause_s": 1.0},
        "ratio_study": {"variable": "pinion_diameter_mm", "min": 20, "max": 200},
    },
}


def _cpu(run: Callable[[], object]) -> float:
    started = time.process_time()
    run()
    return time.process_time() - started


def main() -> None:
    """Run the benchmark and print its table."""
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--copies", type=int, nargs="+", default=[1, 10, 100])
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        url = f"sqlite:///{Path(tmp) / 'bench.sqlite3'}"
        starter_catalogue(url)
        with make_session_factory(make_engine(url))() as session:
            starter = CatalogueCache().snapshot(session)
    tune_gc()
    for copies in args.copies:
        catalogue = copied_catalogue(starter, copies)
        actuators = catalogue.actuators
        for name, body in CASES.items():
            request = RatioStudyRequest.model_validate(body)
            plain = SelectionRequest.model_validate(
                {k: v for k, v in body.items() if k != "ratio_study"}
            )
            app = plain.to_core()
            select = partial(size_selection, plain, app, actuators, catalogue, datetime.now(UTC))
            solve = partial(study, request, catalogue)
            select(), solve()  # warm the caches
            rounds = [(_cpu(select), _cpu(solve)) for _ in range(args.rounds)]
            selection = min(s for s, _ in rounds)
            ratio = min(r for _, r in rounds)
            print(
                f"{len(actuators):>5} actuators, {name:<38} selection {selection * 1e3:7.1f} ms, "
                f"ratio study {ratio * 1e3:7.1f} ms = {ratio / selection:5.1f}× "
                f"(rounds {' '.join(f'{r / s:.1f}' for s, r in rounds)}; target ≤ 5×)",
                flush=True,
            )


if __name__ == "__main__":
    main()
