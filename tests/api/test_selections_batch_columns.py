"""POST /api/v1/selections/batch/columns: the batch as tables, the per-case batch's numbers."""

from __future__ import annotations

import json
import math
import random
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient
from tests import worked_example

from actuator_selection.app import API_PREFIX
from actuator_selection.schemas.batch import MAX_BATCH_CANDIDATES, MAX_BATCH_CASES
from actuator_selection.schemas.batch_columns import COLUMNS_EXAMPLE, BatchColumnsOut
from actuator_selection.services.batch_columns import _coalesced, _json_pieces
from actuator_selection.services.presenters.selection import dump_json

URL = f"{API_PREFIX}/selections/batch/columns"
COLUMNS = ("speed_rpm", "torque_nm", "inertia_kgm2", "accel_s", "constant_s", "decel_s", "pause_s")
TORQUES = ("accel_torque_nm", "constant_torque_nm", "decel_torque_nm", "rms_torque_nm")
MODEL_KEYS = (
    "family",
    "gear_ratio",
    "controllers_excluded",
    "controllers_note",
    "controllers_note_code",
    "controllers_note_params",
)


def random_columns(n: int, seed: int) -> dict[str, list[Any]]:
    """n load cases of the chapter's shorthand, some beyond every actuator."""
    rng = random.Random(seed)
    return {
        "speed_rpm": [rng.choice([rng.uniform(1, 300), rng.randint(5, 120)]) for _ in range(n)],
        "torque_nm": [rng.choice([0.0, rng.uniform(0, 80)]) for _ in range(n)],
        "inertia_kgm2": [rng.uniform(0, 6) for _ in range(n)],
        "accel_s": [rng.uniform(0.01, 1) for _ in range(n)],
        "constant_s": [rng.choice([0.0, rng.uniform(0, 2)]) for _ in range(n)],
        "decel_s": [rng.uniform(0.01, 1) for _ in range(n)],
        "pause_s": [rng.choice([0.0, rng.uniform(0, 3)]) for _ in range(n)],
        "high_dynamics": [rng.random() < 0.6 for _ in range(n)],
    }  # fmt: skip


def as_cases(columns: dict[str, list[Any]]) -> list[dict[str, Any]]:
    """The same cases as the per-case batch takes them."""
    return [
        {
            "load": {"speed_rpm": n2, "torque_nm": tl, "inertia_kgm2": jl},
            "cycle": {"accel_s": t1, "constant_s": t2, "decel_s": t3, "pause_s": tp},
            "high_dynamics": dyn,
        }
        for n2, tl, jl, t1, t2, t3, tp, dyn in zip(
            *(columns[name] for name in (*COLUMNS, "high_dynamics")), strict=True
        )
    ]


def rows(table: dict[str, list[Any]]) -> list[dict[str, Any]]:
    """A table's columns as rows."""
    return [dict(zip(table, values, strict=True)) for values in zip(*table.values(), strict=True)]


def test_columns_equal_the_per_case_batch(client: TestClient) -> None:
    """The same cases as columns and as cases: every case's figures, every candidate's
    model, verdict and torques, every check's numbers, and each model's fields equal."""
    columns = random_columns(40, seed=5)
    for top in (1, 4):
        got = client.post(URL, json={**columns, "top": top})
        assert got.status_code == 200, got.text
        answer = BatchColumnsOut.model_validate(got.json()).model_dump(mode="json")
        batch = client.post(
            f"{API_PREFIX}/selections/batch",
            json={"cases": as_cases(columns), "top": top, "include_messages": True},
        )
        assert batch.status_code == 200, batch.text
        results = batch.json()["results"]
        assert answer["catalogue_version"] == batch.json()["catalogue_version"]
        assert answer["ranking"] == batch.json()["ranking"]
        for key in ("cycle_time_s", "mean_speed_rpm", "duty_cycle_percent"):
            assert answer["cases"][key] == [r[key] for r in results], key

        expected = [(i, c) for i, r in enumerate(results) for c in r["candidates"]]
        candidates = rows(answer["candidates"])
        assert len(candidates) == len(expected) == len(results) * top
        models = {m["model"]: m for m in rows(answer["models"])}
        assert sorted(models) == sorted({c["model"] for _, c in expected})
        checks = answer["checks"]
        for row, (got_row, (case, want)) in enumerate(zip(candidates, expected, strict=True)):
            assert got_row["case"] == case
            for key in ("model", "verdict", *TORQUES):
                assert got_row[key] == want[key], key
            for key in MODEL_KEYS:
                assert models[want["model"]][key] == want[key], key
            assert [c["name"] for c in checks] == [c["name"] for c in want["checks"]]
            for column, check in zip(checks, want["checks"], strict=True):
                assert column["reference"] == check["reference"]
                assert column["unit"] == check["unit"]
                for key in ("status", "value", "limit", "approximate"):
                    assert column[key][row] == check[key], (check["name"], key)
                # what is missing: named for no data (the core's tests compare it with
                # the scalar check's), never for a check that passes
                missing = column["missing"][row]
                if check["status"] == "no_data":
                    assert missing is not None
                elif check["status"] in ("pass", "warn"):
                    assert missing is None


def test_the_worked_example_as_columns(client: TestClient) -> None:
    """Table 516.1 against the FHA-25C-50-L: T_1, T_3, T_rms as the chapter computes them
    (Eq. 514.1, 514.2), and n_av, ED (Eq. 514.3, 514.4)."""
    example = worked_example.request()
    load, cycle = example["load"], example["cycle"]
    body = {name: [value] for name, value in {**load, **cycle}.items()}
    models = ["FHA-25C-50-L", "CHA-25A-50"]
    response = client.post(URL, json={**body, "top": 10, "models": models})
    assert response.status_code == 200, response.text
    answer = response.json()
    assert sorted(answer["candidates"]["model"]) == sorted(models)
    row = answer["candidates"]["model"].index("FHA-25C-50-L")
    assert round(answer["candidates"]["accel_torque_nm"][row], 2) == 95.48
    assert round(answer["candidates"]["decel_torque_nm"][row], 2) == -85.48
    assert round(answer["candidates"]["rms_torque_nm"][row], 2) == 35.57
    assert round(answer["cases"]["mean_speed_rpm"][0], 2) == 6.15
    assert round(answer["cases"]["duty_cycle_percent"][0], 2) == 23.08


def test_without_checks_and_in_german(client: TestClient) -> None:
    response = client.post(
        URL, json={**COLUMNS_EXAMPLE, "include_checks": False}, headers={"Accept-Language": "de"}
    )
    assert response.status_code == 200, response.text
    assert response.headers["content-language"] == "de"
    answer = response.json()
    assert answer["checks"] is None
    english = client.post(URL, json={**COLUMNS_EXAMPLE, "include_checks": False}).json()
    assert answer["candidates"] == english["candidates"]
    assert answer["models"]["controllers_note_code"] == english["models"]["controllers_note_code"]
    assert answer["models"]["controllers_note"] != english["models"]["controllers_note"]


def test_one_high_dynamics_for_every_case_or_one_per_case(client: TestClient) -> None:
    columns = random_columns(12, seed=8)
    del columns["high_dynamics"]
    for flag in (True, False):
        one = client.post(URL, json={**columns, "high_dynamics": flag}).json()
        each = client.post(URL, json={**columns, "high_dynamics": [flag] * 12}).json()
        assert one == each


# --- what it refuses --------------------------------------------------------------------------


def _errors(response: Any) -> list[tuple[list[Any], str]]:
    assert response.status_code == 422, response.text
    return [(e["loc"], e["type"]) for e in response.json()["detail"]]


@pytest.mark.parametrize(
    ("field", "value", "rule"),
    [
        ("speed_rpm", 0, "greater_than"),
        ("accel_s", 0, "greater_than_equal"),
        ("pause_s", -1, "greater_than_equal"),
        ("torque_nm", 1e9, "less_than_equal"),
        ("inertia_kgm2", "1", "float_type"),
        ("constant_s", None, "float_type"),
    ],
)
def test_a_bad_value_is_named_by_column_and_case(
    client: TestClient, field: str, value: Any, rule: str
) -> None:
    body = {**COLUMNS_EXAMPLE, field: [COLUMNS_EXAMPLE[field][0], value]}
    assert _errors(client.post(URL, json=body)) == [(["body", field, 1], rule)]


def test_columns_of_other_lengths_are_named(client: TestClient) -> None:
    body = {**COLUMNS_EXAMPLE, "pause_s": [1.0], "high_dynamics": [True, False, True]}
    assert _errors(client.post(URL, json=body)) == [
        (["body", "pause_s"], "length_mismatch"),
        (["body", "high_dynamics"], "length_mismatch"),
    ]
    # in the request's language, the same code and params in both
    english, german = (
        client.post(URL, json=body, headers={"Accept-Language": lang}).json()["detail"][0]
        for lang in ("en", "de")
    )
    assert english["params"] == german["params"] == {"cases": 2, "length": 1}
    assert english["msg"] == ("needs one value per load case: 2, as many as speed_rpm has, got 1")
    assert german["msg"] == (
        "braucht einen Wert je Lastfall: 2, so viele wie speed_rpm hat, erhalten 1"
    )


def test_unknown_models_are_named(client: TestClient) -> None:
    body = {**COLUMNS_EXAMPLE, "models": ["FHA-25C-50-L", "NOPE-1"]}
    response = client.post(URL, json=body)
    assert _errors(response) == [(["body", "models", 1], "unknown_actuator")]
    assert response.json()["detail"][0]["code"] == "unknown_actuator"


def test_limits(client: TestClient) -> None:
    n = MAX_BATCH_CANDIDATES // 10 + 1
    body = {name: [COLUMNS_EXAMPLE[name][0]] * n for name in COLUMNS}
    assert _errors(client.post(URL, json={**body, "top": 10})) == [
        (["body", "top"], "too_many_candidates")
    ]
    body = {name: [COLUMNS_EXAMPLE[name][0]] * (MAX_BATCH_CASES + 1) for name in COLUMNS}
    assert {loc[1] for loc, rule in _errors(client.post(URL, json=body))} == set(COLUMNS)
    assert _errors(client.post(URL, json={**COLUMNS_EXAMPLE, "speed_rpm": []})) == [
        (["body", "speed_rpm"], "too_short")
    ]


@pytest.mark.parametrize(
    "raw",
    [
        "[]",
        "{",
        json.dumps({**COLUMNS_EXAMPLE, "colour": "red"}),
        json.dumps({k: v for k, v in COLUMNS_EXAMPLE.items() if k != "decel_s"}),
        json.dumps({**COLUMNS_EXAMPLE, "top": 0}),
        json.dumps({**COLUMNS_EXAMPLE, "thermal_time_constant_s": 0}),
        json.dumps({**COLUMNS_EXAMPLE, "speed_rpm": 40}),
        '{"speed_rpm": [NaN, 40]}',
    ],
)
def test_malformed_bodies_are_422(client: TestClient, raw: str) -> None:
    response = client.post(URL, content=raw, headers={"content-type": "application/json"})
    assert response.status_code == 422, response.text
    assert all({"loc", "msg", "type"} <= set(e) for e in response.json()["detail"])


def test_nan_is_not_json(client: TestClient) -> None:
    """The batch routes parse with jiter, which reads JSON only: NaN is a decode error
    (the standard library would read it as a number for validation to refuse)."""
    raw = json.dumps({**COLUMNS_EXAMPLE, "speed_rpm": [math.nan, 40]})
    for url, body in ((URL, raw), (f"{API_PREFIX}/selections/batch", '{"cases": [NaN]}')):
        response = client.post(url, content=body, headers={"content-type": "application/json"})
        assert [e["type"] for e in response.json()["detail"]] == ["json_invalid"], url


@pytest.mark.parametrize(
    "value",
    [
        {},
        [],
        {"a": [], "b": {}, "c": [{"x": np.arange(3.0)}, {"y": None}], "d": np.array([np.nan])},
        [{"a": 1}, {"b": [1, 2]}],
        [{"a": 1}, 2],
    ],
)
def test_the_streamed_json_is_the_documents(value: Any) -> None:
    """The pieces of a table's answer join to the one document orjson writes."""
    assert b"".join(_json_pieces(value)) == dump_json(value)
    assert b"".join(_coalesced(_json_pieces(value), 4)) == dump_json(value)


def test_openapi_documents_the_columns_contract(client: TestClient) -> None:
    spec = client.get("/openapi.json").json()
    operation = spec["paths"][URL]["post"]
    body = operation["requestBody"]["content"]["application/json"]["schema"]["$ref"]
    assert body.endswith("/BatchColumnsRequest")
    answer = operation["responses"]["200"]["content"]["application/json"]["schema"]["$ref"]
    assert answer.endswith("/BatchColumnsOut")
    assert "422" in operation["responses"]


def test_case_ids_come_back_as_a_column(client: TestClient) -> None:
    ids = ["order 4711/10", "order 4711/20"]
    response = client.post(URL, json={**COLUMNS_EXAMPLE, "case_id": ids})
    assert response.status_code == 200, response.text
    cases = response.json()["cases"]
    assert cases["case_id"] == ids
    without = client.post(URL, json=COLUMNS_EXAMPLE).json()["cases"]
    assert without["case_id"] is None
    assert {k: v for k, v in cases.items() if k != "case_id"} == {
        k: v for k, v in without.items() if k != "case_id"
    }


@pytest.mark.parametrize(
    ("case_id", "loc", "type_"),
    [
        (["one"], ["body", "case_id"], "length_mismatch"),
        (["one", ""], ["body", "case_id", 1], "string_too_short"),
        (["one", "x" * 101], ["body", "case_id", 1], "string_too_long"),
    ],
)
def test_a_bad_case_id_column_is_named(
    client: TestClient, case_id: list[str], loc: list[Any], type_: str
) -> None:
    response = client.post(URL, json={**COLUMNS_EXAMPLE, "case_id": case_id})
    assert _errors(response) == [(loc, type_)]
