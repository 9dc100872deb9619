"""A selection answers the ranking's first candidates and a cursor; the rest is paged.

POST /selections?top=N lists the first N candidates with the whole ranking's count and
counts per verdict; GET /selections/{id}/candidates pages the rest from ``next_cursor``
(or gives it whole as JSON lines). Paging returns every candidate of the whole ranking
exactly once, in its order, with the same figures and checks; a cursor reads the ranking
stored with the selection, so a catalogue change does not move it.
"""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.schemas.selections import CandidatePageOut, SelectionOut
from actuator_selection.services.presenters.selection import DEFAULT_TOP, TOP_MAX
from actuator_selection.services.selections import cursor

__all__ = ["api", "sales_api_with"]

CASE: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}


def _post(client: TestClient, top: int | None = None) -> dict[str, Any]:
    params = {} if top is None else {"top": top}
    response = client.post("/api/v1/selections", json=CASE, params=params)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    SelectionOut.model_validate(answer)
    return answer


def _without_drive(candidate: dict[str, Any]) -> dict[str, Any]:
    return {**candidate, "drive_options": None}


def _pages(client: TestClient, answer: dict[str, Any], limit: int) -> list[dict[str, Any]]:
    """The answer's candidates, then every page from its cursor on."""
    out = list(answer["candidates"])
    token = answer["next_cursor"]
    while token is not None:
        response = client.get(
            f"/api/v1/selections/{answer['id']}/candidates",
            params={"cursor": token, "limit": limit},
        )
        assert response.status_code == 200, response.text
        page = response.json()
        CandidatePageOut.model_validate(page)
        assert page["start"] == len(out)
        assert page["total_candidates"] == answer["total_candidates"]
        assert 0 < len(page["candidates"]) <= limit
        out += page["candidates"]
        token = page["next_cursor"]
    return out


@pytest.mark.parametrize("limit", [1, 7, 1000])
def test_pages_give_every_candidate_once_in_rank_order(client: TestClient, limit: int) -> None:
    whole = _post(client, top=1000)
    assert whole["next_cursor"] is None
    assert whole["total_candidates"] == len(whole["candidates"]) > 20
    lean = _post(client, top=5)
    assert len(lean["candidates"]) == 5
    assert lean["total_candidates"] == whole["total_candidates"]
    paged = _pages(client, lean, limit)
    assert [c["model"] for c in paged] == [c["model"] for c in whole["candidates"]]
    # The same figures and checks; drive options beyond the answer's own: in the detail.
    assert lean["candidates"] == whole["candidates"][:5]
    assert [_without_drive(c) for c in paged] == [_without_drive(c) for c in whole["candidates"]]
    assert all(c["drive_options"] is None for c in paged[5:])


def test_counts_per_verdict_are_the_whole_rankings(client: TestClient) -> None:
    whole = _post(client, top=1000)
    lean = _post(client, top=3)
    counted = Counter(c["verdict"] for c in whole["candidates"])
    expected = {v: counted[v] for v in ("suitable", "unconfirmed", "unsuitable")}
    assert lean["verdict_counts"] == whole["verdict_counts"] == expected
    assert sum(lean["verdict_counts"].values()) == lean["total_candidates"]


def test_the_default_lists_the_pages_first_screen_and_a_cursor(client: TestClient) -> None:
    """Unless asked, an answer lists DEFAULT_TOP candidates (the starter catalogue has
    more), and the first page of its ranking is the same with the same cursor on."""
    answer = _post(client)
    assert len(answer["candidates"]) == DEFAULT_TOP < answer["total_candidates"]
    assert answer["next_cursor"] == cursor(answer["id"], DEFAULT_TOP)
    first = client.get(f"/api/v1/selections/{answer['id']}/candidates").json()
    assert first["candidates"] == answer["candidates"]
    assert first["start"] == 0
    assert first["next_cursor"] == answer["next_cursor"]
    whole = _post(client, top=TOP_MAX)
    assert whole["next_cursor"] is None
    assert len(whole["candidates"]) == whole["total_candidates"] == answer["total_candidates"]


def test_the_stored_answer_is_the_lean_one(client: TestClient) -> None:
    lean = _post(client, top=4)
    stored = client.get(f"/api/v1/selections/{lean['id']}")
    assert stored.json() == lean


def test_json_lines_give_the_rest_whole(client: TestClient) -> None:
    lean = _post(client, top=6)
    response = client.get(
        f"/api/v1/selections/{lean['id']}/candidates",
        params={"cursor": lean["next_cursor"], "format": "jsonl"},
    )
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("application/x-ndjson")
    lines = [json.loads(line) for line in response.text.splitlines()]
    assert lines == _pages(client, lean, 1000)[6:]
    everything = client.get(
        f"/api/v1/selections/{lean['id']}/candidates", params={"format": "jsonl"}
    )
    assert len(everything.text.splitlines()) == lean["total_candidates"]


def test_readers_of_the_stored_selection_see_the_whole_ranking(client: TestClient) -> None:
    lean = _post(client, top=2)
    last = _pages(client, lean, 1000)[-1]["model"]
    diagram = client.get(f"/api/v1/selections/{lean['id']}/candidates/{last}/diagram")
    assert diagram.status_code == 200, diagram.text
    report = client.get(f"/api/v1/selections/{lean['id']}/report.csv")
    assert report.status_code == 200
    assert last in report.text


@pytest.mark.parametrize(
    "token",
    [
        "nonsense",
        "",
        "%%%",
        cursor("00000000-0000-0000-0000-000000000000", 3),  # another selection's
        "LTE6",  # "-1:"
    ],
)
def test_a_cursor_that_is_not_the_selections_is_refused(client: TestClient, token: str) -> None:
    lean = _post(client, top=3)
    response = client.get(f"/api/v1/selections/{lean['id']}/candidates", params={"cursor": token})
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert error["loc"] == ["query", "cursor"]
    assert error["code"] == "invalid_cursor"


def test_a_cursor_beyond_the_ranking_is_refused(client: TestClient) -> None:
    lean = _post(client, top=3)
    beyond = cursor(lean["id"], lean["total_candidates"])
    response = client.get(f"/api/v1/selections/{lean['id']}/candidates", params={"cursor": beyond})
    assert response.status_code == 422
    assert response.json()["detail"][0]["code"] == "invalid_cursor"


def test_bounds_and_unknown_selection(client: TestClient) -> None:
    assert client.post("/api/v1/selections", json=CASE, params={"top": 0}).status_code == 422
    assert client.post("/api/v1/selections", json=CASE, params={"top": 1001}).status_code == 422
    lean = _post(client, top=3)
    path = f"/api/v1/selections/{lean['id']}/candidates"
    assert client.get(path, params={"limit": 0}).status_code == 422
    assert client.get(path, params={"format": "xml"}).status_code == 422
    unknown = client.get("/api/v1/selections/00000000-0000-0000-0000-000000000000/candidates")
    assert unknown.status_code == 404
    assert unknown.json()["detail"][0]["code"] == "unknown_selection"


def test_a_cursor_reads_the_same_ranking_after_a_catalogue_change(api: SalesApi) -> None:
    """The rule: a selection's ranking is stored as it was sized, so its cursors read the
    ranking of the catalogue version it names, whatever changed since (a candidate's
    detail, computed again, then answers 409)."""
    client = api.client
    lean = _post(client, top=4)
    before = _pages(client, lean, 10)
    gone = before[-1]["model"]
    admin = api.headers("admin")
    assert client.delete(f"/api/v1/actuators/{gone}", headers=admin).status_code == 204
    after = _pages(client, lean, 10)
    assert after == before
    assert gone not in {c["model"] for c in _post(client, top=1000)["candidates"]}
    detail = client.get(f"/api/v1/selections/{lean['id']}/candidates/{before[0]['model']}")
    assert detail.status_code == 409
