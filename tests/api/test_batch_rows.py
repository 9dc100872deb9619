"""A batch's cases written as rows of pieces (``services/presenters/batch_rows.py``) are
the text ``dump_json`` writes of the cases' dicts (``case_body`` of
``coded_candidate_body``s), each case after a comma: with and without checks and
controllers, as many candidates in every case or not, none at all; and the loads of the
chapter's shorthand written without an axis load per case."""

from __future__ import annotations

import random
from typing import Any

import numpy as np
import orjson
import pytest

from actuator_selection.services.presenters.batch import case_body, coded_candidate_body
from actuator_selection.services.presenters.batch_rows import (
    candidate_columns,
    case_loads,
    case_rows,
    json_texts,
    pieces,
    rows,
)
from actuator_selection.services.presenters.selection import LOAD_KEYS, dump_json, load_columns
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.cycle import Load, SpeedPattern


def _candidate(rng: random.Random, rules: int | None, controllers: bool) -> dict[str, Any]:
    checks = None
    if rules is not None:
        checks = [
            {"name": f"rule{k}", "status": rng.choice(["pass", "fail"]), "value": rng.random()}
            for k in range(rules)
        ]
    return coded_candidate_body(
        {
            "model": f"M-{rng.randint(1, 9)}",
            "family": "F",
            "gear_ratio": rng.choice([50.0, 100.0]),
            "verdict": rng.choice(["suitable", "unsuitable"]),
            "accel_torque_nm": rng.random(),
            "constant_torque_nm": rng.choice([None, rng.random()]),
            "decel_torque_nm": -rng.random(),
            "rms_torque_nm": rng.random(),
        },
        rng.sample(["a", "b", "c"], rng.randint(0, 2)),
        checks,
        [{"model": "D"}] if controllers else None,
        {"controllers_excluded": rng.randint(0, 3), "controllers_note_code": None},
    )


def _members(body: dict[str, Any]) -> bytes:
    return dump_json(body)[1:-1]


@pytest.mark.parametrize(
    ("counts", "rules", "controllers"),
    [
        ([3, 3, 3, 3], 8, False),
        ([2, 2], None, True),
        ([3, 1, 0, 2], 9, True),
        ([1], 0, False),
    ],
)
def test_rows_are_the_cases_dicts_written(
    counts: list[int], rules: int | None, controllers: bool
) -> None:
    rng = random.Random(sum(counts))
    cells = [_candidate(rng, rules, controllers) for _ in range(sum(counts))]
    firsts = ("verdict", "accel_torque_nm", "constant_torque_nm", "decel_torque_nm")
    candidates = candidate_columns(
        [_members({k: c[k] for k in ("model", "family", "gear_ratio")}) for c in cells],
        [dump_json(c["verdict"]) for c in cells],
        [[dump_json(c[k]) for c in cells] for k in (*firsts[1:], "rms_torque_nm")],
        [dump_json(c["reason_checks"]) for c in cells],
        None if rules is None else [dump_json(c["checks"]) for c in cells],
        [dump_json(c["controllers"]) for c in cells] if controllers else None,
        [
            b"," + _members({k: c[k] for k in ("controllers_excluded", "controllers_note_code")})
            for c in cells
        ],
    )
    cases = []
    end = 0
    for i, n in enumerate(counts):
        cases.append(
            case_body(
                id=None,
                case_id=f"c{i}" if i % 2 else None,
                load={k: rng.random() for k in LOAD_KEYS},
                figures=(rng.random(), rng.random(), rng.random()),
                candidates=cells[end : end + n],
            )
        )
        end += n
    columns = case_rows(
        [dump_json(c["id"]) for c in cases],
        [dump_json(c["case_id"]) for c in cases],
        [[dump_json(c["load"][k]) for c in cases] for k in LOAD_KEYS],
        [
            [dump_json(c[k]) for c in cases]
            for k in ("cycle_time_s", "mean_speed_rpm", "duty_cycle_percent")
        ],
        candidates,
        counts,
    )
    expected = b"".join(b"," + dump_json(c) for c in cases)
    assert b"".join(pieces(columns, len(cases))) == expected
    assert [b"".join(row) for row in rows(columns, len(cases))] == [
        b"," + dump_json(c) for c in cases
    ]
    assert orjson.loads(b"[" + expected[1:] + b"]") == cases


def test_shorthand_loads_are_their_axis_loads_written() -> None:
    rng = random.Random(5)
    apps = [
        Application(
            pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0, decel_s=0.1, pause_s=1),
            load=Load(torque_nm=rng.choice([0, 2, rng.random()]), inertia_kgm2=rng.random()),
        )
        for _ in range(20)
    ]
    peaks = np.array([rng.uniform(1, 100) for _ in apps])
    expected = load_columns([app.axis_load for app in apps], peaks)
    assert case_loads(apps, peaks) == expected
    assert case_loads(apps[:1], peaks[:1]) == [column[:1] for column in expected]


def test_ids_are_written_as_dump_json_writes_them() -> None:
    values = [None, "c1", 'a "b", c', "Ω\u2028", "", None]
    assert json_texts(values) == [dump_json(v) for v in values]
