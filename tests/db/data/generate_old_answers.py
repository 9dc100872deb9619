"""How ``selection_answers_v0.json`` and ``…_v1.json`` were made: an old commit's own code
answers two load cases on a fresh SQLite database seeded with that commit's starter
catalogue, and the stored row's request and answer are printed as JSON.

    git archive 2cc9373^ | tar -x -C /tmp/v0      # the answer before the lean one
    git archive 2cc9373 | tar -x -C /tmp/v1       # the lean answer as first stored
    .venv/bin/python tests/db/data/generate_old_answers.py /tmp/v0 > selection_answers_v0.json

(the files add a note on where they came from; ``cases`` is this script's output).
"""

from __future__ import annotations

import gzip
import json
import os
import sys
import tempfile
from pathlib import Path
from typing import Any

MODELS = ["FHA-25C-50-L", "CHA-20A-30", "CHA-14A-E-100"]
CASES: dict[str, dict[str, Any]] = {
    "worked_example": {
        "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
        "models": MODELS,
    },
    "ball_screw": {
        "load": {
            "type": "ball_screw",
            "speed_rpm": 60,
            "mass_kg": 200,
            "lead_m": 0.01,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
        },
        "cycle": {"accel_s": 0.2, "constant_s": 0.5, "decel_s": 0.2, "pause_s": 0.5},
        "models": MODELS,
    },
}


def main(root: Path) -> None:
    sys.path.insert(0, str(root / "backend"))
    os.chdir(root)
    from fastapi.testclient import TestClient
    from sqlalchemy import text

    from actuator_selection.app import create_app
    from actuator_selection.config import SEED_DIR, Settings
    from actuator_selection.db.engine import make_engine, make_session_factory
    from actuator_selection.db.migrate import upgrade
    from actuator_selection.db.seed import load_seed

    url = f"sqlite:///{tempfile.mkdtemp()}/old.sqlite3"
    upgrade(url=url)
    engine = make_engine(url)
    with make_session_factory(engine).begin() as session:
        load_seed(session, SEED_DIR)
    out = {}
    with TestClient(create_app(Settings(database_url=url))) as client:
        for name, body in CASES.items():
            created = client.post("/api/v1/selections", json=body)
            assert created.status_code == 201, created.text
            with engine.connect() as conn:
                columns = [c[1] for c in conn.execute(text("PRAGMA table_info(selections)"))]
                column = "response" if "response" in columns else "answer_gzip"
                request, answer = conn.execute(
                    text(f"SELECT request, {column} FROM selections WHERE id = :id"),
                    {"id": created.json()["id"]},
                ).one()
            answer = answer if column == "response" else gzip.decompress(answer)
            out[name] = {"request": json.loads(request), "answer": json.loads(answer)}
    print(json.dumps(out, ensure_ascii=False, indent=1))


if __name__ == "__main__":
    main(Path(sys.argv[1]))
