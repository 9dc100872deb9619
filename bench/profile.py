"""A measured profile of 100,000 samples: upload (read, fit, store) and size, over HTTP.

Two profiles, each 100,000 rows of time and speed at 1 ms: a CAM table of 25 moves
(its segments fit exactly) and a noisy trace (a smooth move with 0.5 % noise,
where the fit stops at 200 segments). Prints the time of the upload and of the selection
that names it, the rows per second of the upload, and the segments fitted. Runs on a
throw-away SQLite database seeded with the starter catalogue, through ``TestClient``.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path

import numpy as np
from fastapi.testclient import TestClient

from actuator_selection.app import create_app
from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.seed import load_seed

SAMPLES = 100_000


def _csv(t: np.ndarray, v: np.ndarray) -> bytes:
    rows = "\n".join(f"{a:.6f};{b:.6f}" for a, b in zip(t.tolist(), v.tolist(), strict=True))
    return ("Time [s];AngularVelocity [rpm]\n" + rows + "\n").encode()


def cam_table() -> bytes:
    """A 100 s cycle of 25 moves of Fig. 516.2's shape (40 rpm, 0.1 s ramps and run, then
    3.7 s at rest; every other one the other way), sampled at 1 ms: 100 segments."""
    t = np.arange(SAMPLES) * 0.001
    phase = np.mod(t, 4.0)
    v = np.interp(phase, [0.0, 0.1, 0.2, 0.3, 4.0], [0.0, 40.0, 40.0, 0.0, 0.0])
    v *= np.where(np.mod(t // 4.0, 2) == 0, 1.0, -1.0)
    v[-1] = 0.0
    return _csv(t, v)


def noisy_trace() -> bytes:
    """A smooth move out and back with 0.5 % noise (a PLC trace), 100,000 samples."""
    rng = np.random.default_rng(7)
    t = np.arange(SAMPLES) * 0.001
    v = 40 * np.sin(2 * np.pi * t / t[-1]) + rng.normal(0, 0.2, SAMPLES)
    v[0] = v[-1] = 0.0
    return _csv(t, v)


def run() -> None:
    with tempfile.TemporaryDirectory() as tmp:
        url = f"sqlite:///{Path(tmp) / 'bench.sqlite3'}"
        upgrade(url=url)
        engine = make_engine(url)
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
        with TestClient(create_app(Settings(database_url=url))) as client:
            warm = b"Time [s];AngularVelocity [rpm]\n0;0\n0.1;1\n0.2;0\n"  # pint's first load
            client.post("/api/v1/profiles", content=warm, headers={"Content-Type": "text/csv"})
            for name, content in (
                ("CAM table", cam_table()),
                ("noisy trace", noisy_trace()),
            ):
                start = time.perf_counter()
                created = client.post(
                    "/api/v1/profiles", content=content, headers={"Content-Type": "text/csv"}
                )
                uploaded = time.perf_counter()
                assert created.status_code == 201, created.text[:500]
                profile = created.json()
                sized = client.post(
                    "/api/v1/selections",
                    json={
                        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
                        "cycle": {"profile_id": profile["id"]},
                    },
                )
                done = time.perf_counter()
                assert sized.status_code == 201, sized.text[:500]
                print(
                    f"{name}: {len(content) / 1e6:.1f} MB, {SAMPLES} samples: upload "
                    f"{uploaded - start:.2f} s ({SAMPLES / (uploaded - start):,.0f} rows/s), "
                    f"selection {done - uploaded:.2f} s, total {done - start:.2f} s; "
                    f"{len(profile['cycle']['segments'])} segments, exact "
                    f"{profile['fit']['exact']}, deviation "
                    f"{profile['fit']['speed_deviation']:.3g} rpm"
                )


if __name__ == "__main__":
    run()
