"""Instructions a request costs, against ``GET /health``: a measure the machine's load
does not move.

On the shared machine the CPU time of one request varies from run to run by more than
the differences worth knowing (a one-model selection's 2.0–3.3 ms in one half hour).
Valgrind's callgrind counts the instructions a process executes instead, which repeat
to within a few per mille whatever else runs. This runs the app in process (Starlette's
``TestClient``, a seeded SQLite database), warms it, then sends ``--requests`` requests
of one kind; the count of a run of ``/health`` is subtracted from the count of a run of
each other kind (the start-up, identical in both, cancels), and the difference is
printed per request and as a ratio to ``/health``'s own count per request (a run of
``/health`` minus a run with no requests).

    python -m bench.instructions               # needs valgrind (Debian's package)
    python -m bench.instructions --requests 50

It measures the tree it runs in; to compare two commits, run it in a worktree of each.
Instructions are not time (numpy's inner loops run more instructions per cycle than
the interpreter), so read them beside ``bench.http``'s CPU times, not instead.
"""

from __future__ import annotations

import argparse
import os
import re
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

WORKED_EXAMPLE: dict[str, object] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}
MODEL = "FHA-25C-50-L"
KINDS: dict[str, tuple[str, str, dict[str, object] | None, int]] = {
    "none": ("", "", None, 0),
    "health": ("GET", "/api/v1/health", None, 200),
    "one model": ("POST", "/api/v1/selections", {**WORKED_EXAMPLE, "models": [MODEL]}, 201),
    "whole catalogue": ("POST", "/api/v1/selections", WORKED_EXAMPLE, 201),
    "a 422": ("POST", "/api/v1/selections", {**WORKED_EXAMPLE, "load": {"torque_nm": -1}}, 422),
}
WARM = 20


def serve(kind: str, requests: int) -> None:
    """In this process: warm the app with every kind, then send ``requests`` of ``kind``."""
    from fastapi.testclient import TestClient

    from actuator_selection.app import create_app
    from actuator_selection.config import SEED_DIR, Settings
    from actuator_selection.db.engine import make_engine, make_session_factory
    from actuator_selection.db.migrate import upgrade
    from actuator_selection.db.seed import load_seed

    with tempfile.TemporaryDirectory() as tmp:
        url = f"sqlite:///{Path(tmp) / 'bench.sqlite3'}"
        upgrade(url=url)
        with make_session_factory(make_engine(url)).begin() as session:
            load_seed(session, SEED_DIR)
        with TestClient(create_app(Settings(database_url=url))) as client:

            def send(name: str) -> None:
                method, path, body, status = KINDS[name]
                answer = client.request(method, path, json=body)
                assert answer.status_code == status, answer.text[:300]

            for name in KINDS:
                if name != "none":
                    for _ in range(WARM):
                        send(name)
            for _ in range(requests if kind != "none" else 0):
                send(kind)


def count(kind: str, requests: int) -> int:
    """The instructions of a process that serves ``requests`` of ``kind`` (callgrind)."""
    with tempfile.TemporaryDirectory() as tmp:
        out = Path(tmp) / "callgrind.out"
        subprocess.run(
            [
                "valgrind",
                "--tool=callgrind",
                f"--callgrind-out-file={out}",
                sys.executable,
                "-m",
                "bench.instructions",
                "--serve",
                kind,
                "--requests",
                str(requests),
            ],
            check=True,
            capture_output=True,
            env={**os.environ, "PYTHONHASHSEED": "0"},
        )
        found = re.search(r"^summary: (\d+)$", out.read_text(errors="replace"), re.MULTILINE)
        assert found, "callgrind wrote no summary"
        return int(found.group(1))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--requests", type=int, default=100)
    parser.add_argument("--serve", choices=list(KINDS), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.serve:
        serve(args.serve, args.requests)
        return
    n = args.requests
    print(f"callgrind, {n} requests a run after {WARM} of each kind; instructions per request")
    with ThreadPoolExecutor(len(KINDS)) as pool:  # each a process of its own
        totals = dict(zip(KINDS, pool.map(lambda kind: count(kind, n), KINDS), strict=True))
    health = (totals["health"] - totals["none"]) / n
    print(f"GET /health: {health / 1e6:.3f} M")
    for kind in KINDS:
        if kind in ("none", "health"):
            continue
        more = (totals[kind] - totals["health"]) / n
        print(
            f"{kind}: /health + {more / 1e6:.3f} M = {(health + more) / 1e6:.3f} M "
            f"= {(health + more) / health:.2f}× /health"
        )


if __name__ == "__main__":
    main()
