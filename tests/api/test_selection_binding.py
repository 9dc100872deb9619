"""When nothing fits (issue 29 item 7): the selection says what binds across the catalogue,
from the candidates' own checks, and what a longer t_1 or pause would change, from the
inverse solve; on SQLite and PostgreSQL (the ``client`` fixture)."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient
from tests import worked_example
from tests.api._ranking import whole_ranking

API = "/api/v1/selections"

# The vertical screw: 25 kg, lead 10 mm, 0.3 m/s, so n_2 = 300/10·60 = 1800 rpm.
VERTICAL_SCREW: dict[str, Any] = {
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
}


def created(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    return answer


def test_nothing_fits_says_the_speed_binds_against_the_largest_n_max(
    client: TestClient,
) -> None:
    answer = created(client, VERTICAL_SCREW)
    candidates = whole_ranking(client, answer)  # the binding is the whole ranking's
    assert {c["verdict"] for c in candidates} == {"unsuitable"}
    binding = answer["binding"]
    assert binding["candidates"] == len(candidates)
    speed = next(k for k in binding["checks"] if k["name"] == "max_speed")
    # every candidate fails the speed: n_2 against the largest n_max of the catalogue
    n_max = {
        a["model"]: a["max_speed_rpm"] for a in client.get("/api/v1/actuators").json()["actuators"]
    }
    assert speed["failing"] == len(candidates)
    assert speed["value"] == answer["load"]["speed_rpm"] == 1800
    assert speed["limit"] == max(n_max[c["model"]] for c in candidates)
    assert n_max[speed["model"]] == speed["limit"]
    # the counts are the candidates' own: each check's failures counted in the answer
    for kind in binding["checks"]:
        fails = [
            c
            for c in candidates
            for k in c["checks"]
            if k["name"] == kind["name"] and k["status"] == "fail"
        ]
        assert kind["failing"] == len(fails)
    assert binding["checks"][0]["failing"] >= binding["checks"][-1]["failing"]
    # no longer t_1 or pause helps a speed above n_max: the inverse solve says so
    changes = {c["quantity"]: c for c in binding["changes"]}
    assert set(changes) == {"accel_s", "pause_s"}
    for change in changes.values():
        assert change["model"] == candidates[0]["model"]
        assert change["value"] is None
        assert change["reason_code"] == "limit.none.min"
        assert "max_speed" in change["limiting_checks"]
    # stored as answered
    assert client.get(f"{API}/{answer['id']}").json()["binding"] == binding


def test_a_too_short_pause_is_answered_with_the_pause_that_fits(client: TestClient) -> None:
    """The worked example on the FHA-25C-50 with no pause fails T_rms (thermal); the
    inverse solve's shortest pause is offered, and at it the candidate passes."""
    body = worked_example.request() | {"models": ["FHA-25C-50"]}
    body["cycle"] = body["cycle"] | {"pause_s": 0.0}
    answer = created(client, body)
    assert answer["candidates"][0]["verdict"] == "unsuitable"
    changes = {c["quantity"]: c for c in answer["binding"]["changes"]}
    pause = changes["pause_s"]
    assert pause["value"] is not None
    assert pause["value"] > 0
    limits = client.post(f"{API}/limits", json=body | {"model": "FHA-25C-50"}).json()
    assert pause["value"] == {x["quantity"]: x for x in limits["limits"]}["pause_s"]["value"]
    at_pause = body | {"cycle": body["cycle"] | {"pause_s": pause["value"] * (1 + 1e-6)}}
    assert created(client, at_pause)["candidates"][0]["verdict"] != "unsuitable"


def test_a_selection_with_a_fit_has_no_binding(client: TestClient) -> None:
    assert created(client, worked_example.request())["binding"] is None
