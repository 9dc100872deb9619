"""The ratio study through the API (issue 31 part 1): the vertical screw that fits
nowhere gets a lead range and a best lead per candidate, and each end is re-checked by a
plain selection at that lead; on SQLite and PostgreSQL (the ``client`` fixture)."""

from __future__ import annotations

from typing import Any

from fastapi.testclient import TestClient
from tests.api.test_selection_binding import VERTICAL_SCREW

API = "/api/v1/selections"


def _study(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(f"{API}/ratio-study", json=body)
    assert response.status_code == 200, response.text
    answer: dict[str, Any] = response.json()
    return answer


def _verdict(client: TestClient, model: str, lead_mm: float) -> str:
    body = VERTICAL_SCREW | {"models": [model]}
    body["load"] = VERTICAL_SCREW["load"] | {"lead_mm": lead_mm}
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    (candidate,) = response.json()["candidates"]
    verdict: str = candidate["verdict"]
    return verdict


def test_the_vertical_screw_gets_a_lead_range_and_a_best_lead(client: TestClient) -> None:
    nothing = client.post(API, json=VERTICAL_SCREW).json()
    assert nothing["verdict_counts"]["unsuitable"] == nothing["total_candidates"]
    # the catalogue's actuators turn at most a few hundred rpm: 300 mm/s needs a long lead
    study = {"variable": "lead_mm", "min": 5, "max": 1000}
    answer = _study(client, VERTICAL_SCREW | {"ratio_study": study})
    assert (answer["variable"], answer["unit"], answer["min"], answer["max"]) == (
        "lead_mm",
        "mm",
        5.0,
        1000.0,
    )
    fitting = [a for a in answer["actuators"] if a["intervals"]]
    assert fitting, "some actuator fits at some lead"
    assert len(answer["actuators"]) == nothing["total_candidates"]
    utilisations = [a["best_utilisation"] for a in fitting]
    assert utilisations == sorted(utilisations)
    for entry in fitting:
        assert any(i["low"] <= entry["best"] <= i["high"] for i in entry["intervals"])
        assert entry["verdict"] in ("suitable", "unconfirmed")
    assert fitting[0]["curve"] is not None
    assert len(fitting[0]["curve"]["values"]) == len(fitting[0]["curve"]["utilisation"])
    # each end with a binding check, re-checked by a plain selection at that lead
    checked = 0
    for best in fitting[:3]:
        for interval in best["intervals"]:
            for end, binding, outside in (
                (interval["low"], interval["low_binding"], 1 - 1e-4),
                (interval["high"], interval["high_binding"], 1 + 1e-4),
            ):
                if binding:
                    assert _verdict(client, best["model"], end) != "unsuitable"
                    assert _verdict(client, best["model"], end * outside) == "unsuitable"
                    checked += 1
    assert checked


def test_a_series_checks_only_its_values(client: TestClient) -> None:
    series = [5, 10, 16, 20, 25, 32, 40, 50]
    leads = [*series, 200, 400, 800]
    study = {"variable": "lead_mm", "min": 5, "max": 1000, "series": leads}
    answer = _study(client, VERTICAL_SCREW | {"ratio_study": study})
    assert any(entry["intervals"] for entry in answer["actuators"])
    for entry in answer["actuators"]:
        if entry["best"] is not None:
            assert entry["best"] in leads
        for interval in entry["intervals"]:
            assert interval["low"] in leads
            assert interval["high"] in leads


def test_bad_studies_are_refused_naming_the_field(client: TestClient) -> None:
    for study, field in (
        ({"variable": "pulley_diameter_mm"}, "ratio_study.variable"),
        ({"variable": "lead_mm", "min": 30, "max": 10}, "ratio_study"),
        ({"variable": "ratio", "min": -1}, "ratio_study.min"),
        ({"variable": "speed"}, "ratio_study.variable"),
        ({"variable": "ratio", "series": []}, "ratio_study.series"),
    ):
        response = client.post(f"{API}/ratio-study", json=VERTICAL_SCREW | {"ratio_study": study})
        assert response.status_code == 422, (study, response.text)
        (error, *_) = response.json()["detail"]
        assert ".".join(map(str, error["loc"][1:])).startswith(field), (study, response.text)


def test_nothing_fits_names_the_leads_that_make_an_actuator_fit(client: TestClient) -> None:
    """The selection's `binding` says which lead makes which actuator fit, from the study."""
    answer = client.post(API, json=VERTICAL_SCREW).json()
    guided = answer["binding"]["transmissions"]
    assert guided
    assert {g["variable"] for g in guided} == {"lead_mm"}
    for entry in guided:
        assert entry["low"] <= entry["best"] <= entry["high"]
        assert _verdict(client, entry["model"], entry["best"]) != "unsuitable"
    assert client.get(f"{API}/{answer['id']}").json()["binding"] == answer["binding"]


def test_the_chart_draws_the_studys_curves_and_bands(client: TestClient) -> None:
    study = {"variable": "lead_mm", "min": 5, "max": 1000, "curves": 3}
    plain = _study(client, VERTICAL_SCREW | {"ratio_study": study})
    assert plain["figure"] is None
    response = client.post(
        f"{API}/ratio-study",
        params={"figure": "true", "lang": "de"},
        json=VERTICAL_SCREW | {"ratio_study": study},
    )
    assert response.status_code == 200, response.text
    answer = response.json()
    figure = answer["figure"]
    by_uid = {trace["uid"]: trace for trace in figure["data"]}
    with_curve = [a for a in answer["actuators"] if a["curve"] is not None]
    assert len(with_curve) == 3
    assert answer["actuators"] == plain["actuators"]  # the same study, with its chart
    for entry in with_curve:
        curve = by_uid[f"ratio-curve-{entry['model']}"]
        assert (curve["x"], curve["y"]) == (
            entry["curve"]["values"],
            entry["curve"]["utilisation"],
        )
        if entry["intervals"]:
            band = by_uid[f"ratio-band-{entry['model']}"]
            assert band["fill"] == "toself"
            corners = [x for x in band["x"] if x is not None]
            assert corners == [
                x
                for i in entry["intervals"]
                for x in (i["low"], i["low"], i["high"], i["high"], i["low"])
            ]
            assert {y for y in band["y"] if y is not None} == {0.0, 1.0}
            best = by_uid[f"ratio-best-{entry['model']}"]
            assert (best["x"], best["y"]) == ([entry["best"]], [entry["best_utilisation"]])
    assert by_uid["ratio-limit"]["y"] == [1.0, 1.0]
    assert figure["layout"]["xaxis"]["type"] == "log"
    assert figure["layout"]["xaxis"]["title"]["text"] == "Steigung [mm]"
    assert figure["layout"]["separators"] == ",."


def test_the_answer_lists_the_rankings_first_top_and_counts_the_rest(
    client: TestClient,
) -> None:
    """`top` as a selection's: the first of the ranking, each as the whole study lists it
    (only theirs ends bisected), and how many were studied and fit."""
    body = VERTICAL_SCREW | {"ratio_study": {"variable": "lead_mm", "min": 5, "max": 1000}}
    whole = client.post(f"{API}/ratio-study", params={"top": 1000}, json=body).json()
    assert whole["total_actuators"] == len(whole["actuators"]) == 64
    assert whole["fitting_actuators"] == sum(1 for a in whole["actuators"] if a["intervals"])
    assert 3 < whole["fitting_actuators"] < 64
    first = client.post(f"{API}/ratio-study", params={"top": 3}, json=body).json()
    assert first["actuators"] == whole["actuators"][:3]
    assert (first["total_actuators"], first["fitting_actuators"]) == (
        whole["total_actuators"],
        whole["fitting_actuators"],
    )
    for top in (0, 1001):
        response = client.post(f"{API}/ratio-study", params={"top": top}, json=body)
        assert response.status_code == 422, response.text
        assert response.json()["detail"][0]["loc"] == ["query", "top"]
