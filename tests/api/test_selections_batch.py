"""POST /api/v1/selections/batch: many load cases, the same answers as single selections."""

from __future__ import annotations

import json
import random
from typing import Any

import pytest
from fastapi.testclient import TestClient
from sqlalchemy import Connection, func, select
from tests import worked_example

from actuator_selection.app import API_PREFIX
from actuator_selection.db.models import SelectionRow
from actuator_selection.schemas.batch import (
    MAX_BATCH_CANDIDATES,
    MAX_BATCH_CASES,
    MAX_CANDIDATES_WITH_CONTROLLERS,
    MAX_CASE_ID_LENGTH,
    MAX_STORED_CASES,
    BatchCandidateOut,
    BatchSelectionOut,
)
from actuator_selection.schemas.selections import CandidateDetailOut

URL = f"{API_PREFIX}/selections/batch"
DETAIL_KEYS = ("checks", "controllers")

WORKED_EXAMPLE: dict[str, Any] = worked_example.request()


@pytest.fixture
def batch_client(client: TestClient) -> TestClient:
    """The app as main.py builds it (the batch router is mounted there)."""
    return client


def catalogue_models(client: TestClient) -> list[str]:
    return [a["model"] for a in client.get(f"{API_PREFIX}/actuators").json()["actuators"]]


def random_cases(n: int, models: list[str], seed: int) -> list[dict[str, Any]]:
    """Load cases of every kind the API takes: direct loads, ball screws, rotary tables."""
    rng = random.Random(seed)
    cases = []
    for i in range(n):
        speed = rng.choice([rng.uniform(1, 300), float(rng.randint(5, 120))])
        kind = rng.choice(["direct", "direct", "ball_screw", "rotary_table"])
        if kind == "direct":
            load: dict[str, Any] = {
                "speed_rpm": speed,
                "torque_nm": rng.choice([0.0, rng.uniform(0, 80)]),
                "inertia_kgm2": rng.uniform(0, 6),
            }
        elif kind == "ball_screw":
            load = {
                "type": "ball_screw",
                "speed_rpm": speed,
                "mass_kg": rng.uniform(1, 500),
                "lead_m": rng.choice([0.005, 0.01, 0.02]),
                "friction_coefficient": rng.uniform(0, 0.2),
                "efficiency": rng.uniform(0.5, 1),
                "screw_inertia_kgm2": rng.uniform(0, 0.01),
            }
        else:
            load = {
                "type": "rotary_table",
                "speed_rpm": speed,
                "mass_kg": rng.uniform(1, 300),
                "diameter_m": rng.uniform(0.1, 1.5),
                "friction_coefficient": rng.uniform(0, 0.1),
                "friction_radius_m": rng.uniform(0, 0.5),
            }
        case: dict[str, Any] = {
            "load": load,
            "cycle": {
                "accel_s": rng.uniform(0.01, 1),
                "constant_s": rng.choice([0.0, rng.uniform(0, 2)]),
                "decel_s": rng.uniform(0.01, 1),
                "pause_s": rng.choice([0.0, rng.uniform(0, 3)]),
            },
            "high_dynamics": rng.random() < 0.6,
        }
        if i % 4 == 3:
            case["models"] = rng.sample(models, rng.randint(1, 8))
        cases.append(case)
    return cases


def post(client: TestClient, cases: list[dict[str, Any]], **options: Any) -> Any:
    return client.post(URL, json={"cases": cases, **options})


def without(candidate: dict[str, Any], *keys: str) -> dict[str, Any]:
    return {k: v for k, v in candidate.items() if k not in keys}


SELECTION_KEYS = ("selection_id", "catalogue_version", "actuator", "segment_torques")
"""What a single selection's candidate detail adds to a candidate."""


def single_candidates(client: TestClient, case: dict[str, Any], top: int) -> Any:
    """POST /selections for ``case``: its answer, and its best ``top`` candidates in full,
    as the scalar flowchart gives them (GET /selections/{id}/candidates/{model})."""
    response = client.post(f"{API_PREFIX}/selections", json=case)
    assert response.status_code == 201, response.text
    single = response.json()
    details = []
    for lean in single["candidates"][:top]:
        url = f"{API_PREFIX}/selections/{single['id']}/candidates/{lean['model']}"
        detail = client.get(url).json()
        assert detail["verdict"] == lean["verdict"]
        assert detail["accel_torque_nm"] == lean["accel_torque_nm"]
        details.append(without(detail, *SELECTION_KEYS))
    return single, details


# --- the same answers as single selections ---------------------------------------------------


WORDS = ("reasons", "controllers_note")
"""A candidate's words, left out of a batch without ``include_messages`` (and each
check's ``message``)."""


def coded(candidate: dict[str, Any]) -> dict[str, Any]:
    """A candidate in words as a batch without ``include_messages`` gives it: no words, the
    names of the checks that do not pass (``reason_checks``) instead."""
    out = without(candidate, *WORDS)
    if "checks" in out:
        out["checks"] = [without(c, "message") for c in out["checks"]]
    return out | {"reason_checks": open_checks(candidate)}


def open_checks(candidate: dict[str, Any]) -> list[str]:
    """The names of a candidate's checks that fail, warn or lack data."""
    return [c["name"] for c in candidate["checks"] if c["status"] in ("fail", "warn", "no_data")]


@pytest.mark.slow
def test_batch_equals_single_selections(batch_client: TestClient) -> None:
    """N random cases posted one by one and as one batch: equal candidates and figures; in
    words (``include_messages``) the same words, else their codes and params alone."""
    cases = random_cases(24, catalogue_models(batch_client), seed=1)
    worded = post(batch_client, cases, top=3, include_controllers=True, include_messages=True)
    full = post(batch_client, cases, top=3, include_controllers=True)
    brief = post(batch_client, cases, top=4, include_checks=False)
    for answer in (worded, full, brief):
        assert answer.status_code == 200, answer.text
    worded_results = worded.json()["results"]
    full_results = full.json()["results"]
    brief_results = brief.json()["results"]
    assert len(worded_results) == len(full_results) == len(brief_results) == len(cases)
    for case, got_worded, got, got_brief in zip(
        cases, worded_results, full_results, brief_results, strict=True
    ):
        single, details = single_candidates(batch_client, case, 4)
        for key in ("load", "mean_speed_rpm", "duty_cycle_percent", "cycle_time_s"):
            assert got[key] == single[key], key
            assert got_brief[key] == single[key], key
            assert got_worded[key] == single[key], key
        assert got["id"] is None
        assert [without(c, "reason_checks") for c in got_worded["candidates"]] == details[:3]
        assert [c["reason_checks"] for c in got_worded["candidates"]] == [
            open_checks(c) for c in details[:3]
        ]
        assert got["candidates"] == [coded(c) for c in details[:3]]
        assert got_brief["candidates"] == [without(coded(c), *DETAIL_KEYS) for c in details]
        assert full.json()["catalogue_version"] == single["catalogue_version"]


def test_batch_in_german_words_as_the_single_selection(batch_client: TestClient) -> None:
    """With ``include_messages`` and ``Accept-Language: de`` the words are the German of
    the gettext catalogue, as a single selection's candidate detail words them."""
    cases = random_cases(6, catalogue_models(batch_client), seed=4)
    german = {"Accept-Language": "de"}
    answer = batch_client.post(URL, json={"cases": cases, "include_messages": True}, headers=german)
    assert answer.status_code == 200, answer.text
    assert answer.headers["content-language"] == "de"
    for case, result in zip(cases, answer.json()["results"], strict=True):
        single = batch_client.post(f"{API_PREFIX}/selections", json=case).json()
        for candidate in result["candidates"]:
            url = f"{API_PREFIX}/selections/{single['id']}/candidates/{candidate['model']}"
            detail = batch_client.get(url, headers=german).json()
            assert without(candidate, "reason_checks") == without(
                detail, *SELECTION_KEYS, "controllers"
            )
    # the codes and params are the same in every language; the words differ
    english = post(batch_client, cases, include_messages=True).json()["results"]
    worded = answer.json()["results"]
    assert [[coded(c) for c in r["candidates"]] for r in english] == [
        [coded(c) for c in r["candidates"]] for r in worded
    ]
    assert english != worded


def test_batch_without_messages_has_no_words(batch_client: TestClient) -> None:
    """The default answer carries no text in any language: every message is its code and
    params; the request's language changes nothing in it."""
    cases = random_cases(8, catalogue_models(batch_client), seed=6)
    answers = [
        batch_client.post(URL, json={"cases": cases}, headers={"Accept-Language": language})
        for language in ("en", "de")
    ]
    assert answers[0].content == answers[1].content
    for result in answers[0].json()["results"]:
        for c in result["candidates"]:
            assert not set(WORDS) & set(c)
            assert c["reason_checks"] == open_checks(c)
            assert c["controllers_note_code"]
            for check in c["checks"]:
                assert "message" not in check
                assert check["message_code"]


def test_batch_response_validates_against_its_schema(batch_client: TestClient) -> None:
    cases = random_cases(12, catalogue_models(batch_client), seed=2)
    for options in (
        {"include_checks": True, "include_controllers": True, "include_messages": True},
        {"include_checks": True, "include_controllers": True},
        {"include_checks": True},
        {"include_checks": True, "include_messages": True},
        {"include_checks": False},
        {"include_checks": False, "include_messages": True},
        {"include_checks": False, "include_controllers": True},
    ):
        response = post(batch_client, cases, **options)
        assert response.status_code == 200, response.text
        assert response.headers["content-type"] == "application/json"
        body = response.json()
        parsed = BatchSelectionOut.model_validate(body)
        assert parsed.model_dump(mode="json", exclude_unset=True) == body
        for result in body["results"]:
            for c in result["candidates"]:
                assert ("checks" in c) is options["include_checks"]
                assert ("controllers" in c) is options.get("include_controllers", False)
                assert ("reasons" in c) is options.get("include_messages", False)
                if "checks" in c and "controllers" in c and "reasons" in c:
                    c = without(c, "reason_checks")
                    actuator = batch_client.get(f"{API_PREFIX}/actuators/{c['model']}").json()
                    added = {"selection_id": "x", "catalogue_version": 1, "actuator": actuator}
                    parsed_candidate = CandidateDetailOut.model_validate(c | added)
                    dumped = parsed_candidate.model_dump(mode="json", exclude=set(SELECTION_KEYS))
                    assert dumped == c


def test_batch_candidate_schema_has_candidate_out_fields() -> None:
    """BatchCandidateOut copies a candidate's detail (CandidateDetailOut, less what the
    selection adds), with ``reason_checks`` after ``reasons``; a field added there must come
    here. The detail lists and the words are optional (asked for)."""
    fields = {k: v for k, v in CandidateDetailOut.model_fields.items() if k not in SELECTION_KEYS}
    names = list(fields)
    names.insert(names.index("reasons") + 1, "reason_checks")
    assert list(BatchCandidateOut.model_fields) == names
    for name, field in fields.items():
        batch_field = BatchCandidateOut.model_fields[name]
        optional = name in DETAIL_KEYS or name in WORDS
        assert batch_field.is_required() is (field.is_required() and not optional)
    assert BatchCandidateOut.model_fields["reason_checks"].is_required()


def test_openapi_documents_the_batch_contract(batch_client: TestClient) -> None:
    spec = batch_client.get("/openapi.json").json()
    operation = spec["paths"][URL]["post"]
    schema = operation["responses"]["200"]["content"]["application/json"]["schema"]
    assert schema == {"$ref": "#/components/schemas/BatchSelectionOut"}
    assert "201" in operation["responses"]
    request = spec["components"]["schemas"]["BatchSelectionRequest"]
    assert request["properties"]["cases"]["maxItems"] == MAX_BATCH_CASES
    # optional, its default in words (a `default` would read as "always sent", http/openapi.py)
    assert "top" not in request["required"]
    assert request["properties"]["top"]["description"].endswith("omitted: 3")


def test_worked_example_in_a_batch(batch_client: TestClient) -> None:
    case = {**WORKED_EXAMPLE, "models": ["FHA-25C-50-L", "FHA-25C-50-L"]}
    response = post(batch_client, [case, WORKED_EXAMPLE], top=2)
    assert response.status_code == 200
    first, second = response.json()["results"]
    (c,) = first["candidates"]  # one model named twice: one candidate
    assert c["model"] == "FHA-25C-50-L"
    assert c["verdict"] == "unconfirmed"
    assert c["accel_torque_nm"] == pytest.approx(95.48, abs=0.005)
    assert first["mean_speed_rpm"] == pytest.approx(6.15, abs=0.005)
    assert first["load"] == {
        "speed_rpm": 40,
        "torque_nm": 5,
        "inertia_kgm2": 1.3,
        "gravity_torque_nm": 0,
        "efficiency": 1,
    }
    assert len(second["candidates"]) == 2
    assert second["candidates"][0]["verdict"] == "suitable"


def test_ten_thousand_cases_in_one_request(batch_client: TestClient) -> None:
    cases = random_cases(10_000, catalogue_models(batch_client), seed=3)
    response = post(batch_client, cases, include_checks=False)
    assert response.status_code == 200, response.text[:500]
    results = response.json()["results"]
    assert len(results) == 10_000
    assert all(1 <= len(r["candidates"]) <= 3 for r in results)
    for i in (0, 4_999, 9_999):  # the order of the cases is kept
        single, details = single_candidates(batch_client, cases[i], 3)
        assert results[i]["load"] == single["load"]
        assert results[i]["candidates"] == [without(coded(c), *DETAIL_KEYS) for c in details]


def stored_count(connection: Connection) -> int:
    return int(connection.execute(select(func.count()).select_from(SelectionRow)).scalar_one())


def test_nothing_is_stored_unless_asked(batch_client: TestClient, connection: Connection) -> None:
    before = stored_count(connection)
    response = post(batch_client, random_cases(5, catalogue_models(batch_client), seed=4))
    assert response.status_code == 200
    assert stored_count(connection) == before


def test_store_keeps_each_case_as_a_selection(
    batch_client: TestClient, connection: Connection
) -> None:
    cases = random_cases(4, catalogue_models(batch_client), seed=5)
    before = stored_count(connection)
    response = post(
        batch_client, cases, store=True, include_controllers=True, include_messages=True
    )
    assert response.status_code == 201, response.text
    results = response.json()["results"]
    assert stored_count(connection) == before + len(cases)
    assert len({r["id"] for r in results}) == len(cases)
    for case, result in zip(cases, results, strict=True):
        stored = batch_client.get(f"{API_PREFIX}/selections/{result['id']}")
        assert stored.status_code == 200
        body = stored.json()
        assert [c["model"] for c in body["candidates"][:3]] == [
            c["model"] for c in result["candidates"]
        ]
        for c in result["candidates"]:
            url = f"{API_PREFIX}/selections/{result['id']}/candidates/{c['model']}"
            assert without(batch_client.get(url).json(), *SELECTION_KEYS) == without(
                c, "reason_checks"
            )
        assert body["cycle"] == case["cycle"]
        assert body["load"] == result["load"]


# --- validation ------------------------------------------------------------------------------


def locs(response: Any) -> list[list[str | int]]:
    assert response.status_code == 422, response.text[:500]
    assert response.headers["content-type"].startswith("application/json")
    detail = response.json()["detail"]
    assert all(e["msg"] for e in detail)
    return [e["loc"] for e in detail]


@pytest.mark.parametrize(
    ("path", "value", "loc"),
    [
        ("cycle.accel_s", 0, ["cycle", "accel_s"]),
        ("cycle.pause_s", -1, ["cycle", "pause_s"]),
        ("cycle.accel_s", None, ["cycle", "accel_s"]),
        ("load.speed_rpm", 0, ["load", "speed_rpm"]),
        ("load.torque_nm", "five", ["load", "torque_nm"]),
        ("load.type", "crane", ["load"]),
        ("high_dynamics", "maybe", ["high_dynamics"]),
        ("models", [], ["models"]),
        ("cycle.acel_s", 0.1, ["cycle", "acel_s"]),
    ],
)
def test_a_bad_case_is_named_by_its_index(
    batch_client: TestClient, path: str, value: Any, loc: list[str]
) -> None:
    cases = [json.loads(json.dumps(WORKED_EXAMPLE)) for _ in range(20)]
    *parents, leaf = path.split(".")
    target = cases[17]
    for p in parents:
        target = target[p]
    if value is None:
        del target[leaf]
    else:
        target[leaf] = value
    assert ["body", "cases", 17, *loc] in locs(post(batch_client, cases))


def test_unknown_models_are_named_by_case_and_position(batch_client: TestClient) -> None:
    cases = [
        WORKED_EXAMPLE,
        {**WORKED_EXAMPLE, "models": ["FHA-25C-50-L", "NOPE-9"]},
        {**WORKED_EXAMPLE, "models": ["CHA-99"]},
    ]
    response = post(batch_client, cases)
    assert locs(response) == [["body", "cases", 1, "models", 1], ["body", "cases", 2, "models", 0]]
    assert "NOPE-9" in response.json()["detail"][0]["msg"]
    rules = {(e["type"], e["code"]) for e in response.json()["detail"]}
    assert rules == {("unknown_actuator", "unknown_actuator")}


@pytest.mark.parametrize(
    ("options", "loc"),
    [
        ({"top": 0}, ["body", "top"]),
        ({"top": 11}, ["body", "top"]),
        ({"top": "three"}, ["body", "top"]),
        ({"include_checks": "maybe"}, ["body", "include_checks"]),
        ({"store": "perhaps"}, ["body", "store"]),
        ({"colour": "red"}, ["body", "colour"]),
    ],
)
def test_bad_options_are_422(
    batch_client: TestClient, options: dict[str, Any], loc: list[str]
) -> None:
    assert loc in locs(post(batch_client, [WORKED_EXAMPLE], **options))


def test_limits(batch_client: TestClient) -> None:
    assert ["body", "cases"] in locs(post(batch_client, []))
    assert ["body", "store"] in locs(
        post(batch_client, [WORKED_EXAMPLE] * (MAX_STORED_CASES + 1), store=True)
    )
    too_many_with_controllers = MAX_CANDIDATES_WITH_CONTROLLERS // 3 + 1
    assert ["body", "include_controllers"] in locs(
        post(batch_client, [WORKED_EXAMPLE] * too_many_with_controllers, include_controllers=True)
    )
    assert ["body", "top"] in locs(
        post(batch_client, [WORKED_EXAMPLE] * (MAX_BATCH_CANDIDATES // 10 + 1), top=10)
    )


def test_more_cases_than_the_limit_are_422(batch_client: TestClient) -> None:
    response = post(batch_client, [WORKED_EXAMPLE] * (MAX_BATCH_CASES + 1), include_checks=False)
    assert ["body", "cases"] in locs(response)


@pytest.mark.parametrize(
    "raw",
    [
        "",
        "{",
        "[]",
        '{"cases": {}}',
        '{"cases": [null]}',
        '{"cases": [{"load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": NaN},'
        ' "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1}}]}',
    ],
)
def test_malformed_bodies_are_422_json(batch_client: TestClient, raw: str) -> None:
    response = batch_client.post(URL, content=raw, headers={"content-type": "application/json"})
    assert locs(response)


def test_extreme_but_allowed_values_stay_finite(batch_client: TestClient) -> None:
    case = {
        "load": {"speed_rpm": 100_000, "torque_nm": 1e6, "inertia_kgm2": 1e6},
        "cycle": {"accel_s": 1e-4, "constant_s": 86_400, "decel_s": 1e-4, "pause_s": 86_400},
    }
    response = post(batch_client, [case, WORKED_EXAMPLE], top=10, include_controllers=True)
    assert response.status_code == 200, response.text
    (first, _) = response.json()["results"]
    assert all(c["verdict"] == "unsuitable" for c in first["candidates"])


# --- the client's own case ids ---------------------------------------------------------------


def test_each_result_echoes_its_case_id(batch_client: TestClient) -> None:
    cases = [
        {**WORKED_EXAMPLE, "case_id": "order 4711/10"},
        WORKED_EXAMPLE,
        {**WORKED_EXAMPLE, "case_id": "order 4711/10"},  # the client's ids, not checked unique
        {**WORKED_EXAMPLE, "case_id": "ä" * MAX_CASE_ID_LENGTH},
    ]
    response = post(batch_client, cases, top=1)
    assert response.status_code == 200, response.text
    results = response.json()["results"]
    assert [r["case_id"] for r in results] == [c.get("case_id") for c in cases]
    assert len({json.dumps(r["candidates"]) for r in results}) == 1  # the id changes nothing


def test_a_stored_case_keeps_its_selection_request_alone(
    batch_client: TestClient, connection: Connection
) -> None:
    response = post(batch_client, [{**WORKED_EXAMPLE, "case_id": "A-1"}], store=True, top=1)
    assert response.status_code == 201, response.text
    (result,) = response.json()["results"]
    assert result["case_id"] == "A-1"
    model = result["candidates"][0]["model"]
    # The detail is computed again from the stored request, which a selection must accept.
    detail = batch_client.get(f"{API_PREFIX}/selections/{result['id']}/candidates/{model}")
    assert detail.status_code == 200, detail.text
    where = SelectionRow.id == result["id"]
    stored = connection.execute(select(SelectionRow.request).where(where)).scalar_one()
    assert stored["cycle"] == WORKED_EXAMPLE["cycle"]
    assert "case_id" not in stored


@pytest.mark.parametrize(
    ("case_id", "code"),
    [
        ("", "string_too_short"),
        ("x" * (MAX_CASE_ID_LENGTH + 1), "string_too_long"),
        (17, "string_type"),
        ("line\nbreak", "value_error"),
    ],
)
def test_a_bad_case_id_is_named(batch_client: TestClient, case_id: Any, code: str) -> None:
    response = post(batch_client, [WORKED_EXAMPLE, {**WORKED_EXAMPLE, "case_id": case_id}])
    assert locs(response) == [["body", "cases", 1, "case_id"]]
    assert response.json()["detail"][0]["code"] == code
