"""The speed/torque diagram, defined once (``documents/figures.py``) for the page, the quote and
the report: the zone cases and the gaps (moved here from the page's figures.js test), and
the page's figure is the quote's, served by ``GET …/candidates/{model}/diagram``."""

from __future__ import annotations

import copy
from typing import Any

from fastapi.testclient import TestClient

from actuator_selection.documents.figures import DiagramPoints, diagram_figure
from actuator_selection.documents.quote_document_text import DocumentText

EN, DE = DocumentText("en"), DocumentText("de")
POINTS = DiagramPoints(
    n2=40, n_av=6.15, t1=95.48, t3=-85.48, trms=35.57, statuses={"continuous_duty": "pass"}
)
ZONE_ACTUATOR: dict[str, Any] = {
    "max_torque_nm": 151,
    "max_speed_rpm": 90,
    "stall_torque_nm": 58,
    "continuous_torque_nm": None,
    "continuous_duty_zone": [
        {"speed_rpm": 90, "torque_nm": 30},
        {"speed_rpm": 0, "torque_nm": 60},
        {"speed_rpm": 60, "torque_nm": 50},
    ],
}
CONTINUOUS_ACTUATOR: dict[str, Any] = {
    "max_torque_nm": 8.3,
    "max_speed_rpm": 116,
    "stall_torque_nm": None,
    "continuous_torque_nm": 2.9,
    "continuous_duty_zone": None,
    "continuous_speed_rpm": None,
    "rated_speed_rpm": 60,
}


def _by_uid(figure: dict[str, Any]) -> dict[str, dict[str, Any]]:
    return {t["uid"]: t for t in figure["data"]}


def test_a_published_zone_is_drawn_sorted_and_closed_down_to_zero() -> None:
    before = copy.deepcopy(ZONE_ACTUATOR)
    zone = _by_uid(diagram_figure(POINTS, ZONE_ACTUATOR, EN))
    assert before == ZONE_ACTUATOR, "the figure must not change its inputs"
    assert zone["zone"]["x"] == [0, 0, 60, 90, 90, 0]  # sorted by speed, closed at T = 0
    assert zone["zone"]["y"] == [0, 60, 50, 30, 0, 0]
    assert "zone-approx" not in zone
    assert zone["operating-point"]["x"] == [6.15]
    assert zone["operating-point"]["marker"]["color"] == "#1e7b3c"  # its check passed


def test_without_a_zone_the_checks_rectangle_up_to_the_rated_speed() -> None:
    """Not up to n_max = 116: the continuous_speed check bounds it by the rated speed."""
    figure = diagram_figure(POINTS, CONTINUOUS_ACTUATOR, DE)
    approx = _by_uid(figure)["zone-approx"]
    assert approx["y"] == [0, 2.9, 2.9, 0, 0]
    assert approx["x"] == [0, 0, 60, 60, 0]
    assert "näherungsweise" in approx["name"]
    assert "Nenndrehzahl" in approx["name"]
    assert figure["layout"]["separators"] == ",."
    assert figure["layout"]["meta"]["zone"] == "approximate"
    # T_0 before the allowable continuous torque, the continuous speed before the rated one
    both = {**CONTINUOUS_ACTUATOR, "stall_torque_nm": 3.1, "continuous_speed_rpm": 40}
    rectangle = _by_uid(diagram_figure(POINTS, both, EN))["zone-approx"]
    assert rectangle["y"] == [0, 3.1, 3.1, 0, 0]
    assert rectangle["x"] == [0, 0, 40, 40, 0]
    assert "and allowable continuous speed" in rectangle["name"]
    # its value as a text label just below the zone's edge, not an annotation (plotly.js
    # draws those twice on a chart's first draw)
    label = _by_uid(figure)["zone-label"]
    assert label["mode"] == "text"
    assert label["showlegend"] is False
    assert label["x"] == [30]
    assert label["y"] == [2.9]
    assert label["text"] == ["≈ zul. Dauerdrehmoment = 2,9 Nm (näherungsweise)"]
    assert figure["layout"]["annotations"] == []


def test_no_zone_says_no_data_and_no_catalogue_draws_no_limits() -> None:
    cases = {
        "no speed": {**CONTINUOUS_ACTUATOR, "rated_speed_rpm": None},
        "none": {"max_torque_nm": 151, "max_speed_rpm": 90},
        "no actuator": None,
    }
    for case, actuator in cases.items():
        figure = diagram_figure(POINTS, actuator, EN)
        assert not set(_by_uid(figure)) & {"zone", "zone-approx"}, case
        assert any("no data" in a["text"] for a in figure["layout"]["annotations"]), case
        assert figure["layout"]["meta"] == {"zone": "none"}
    assert {"t-max", "n-max"} <= set(_by_uid(diagram_figure(POINTS, cases["none"], EN)))
    missing = diagram_figure(POINTS, None, EN)
    assert not {"t-max", "n-max"} & set(_by_uid(missing))
    assert any("catalogue data" in a["text"] for a in missing["layout"]["annotations"])


def test_the_page_gets_the_figure_the_quote_prints(client: TestClient) -> None:
    """The page's diagram and the quote's are one definition: the API's figure for a
    candidate has the same traces, in the same order, as the printed one."""
    from actuator_selection.documents.quote_document import speed_torque_figure
    from actuator_selection.schemas.quotes import StoredSelection

    body = {
        "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1},
        "models": ["FHA-25C-50-L"],
    }
    created = client.post("/api/v1/selections", json=body)
    assert created.status_code == 201, created.text
    answer = created.json()
    url = f"/api/v1/selections/{answer['id']}/candidates/FHA-25C-50-L/diagram"
    served = client.get(url, params={"lang": "de"})
    assert served.status_code == 200
    assert served.headers["content-language"] == "de"
    actuator = client.get("/api/v1/actuators/FHA-25C-50-L").json()
    stored = StoredSelection.model_validate(client.get(f"/api/v1/selections/{answer['id']}").json())
    printed = speed_torque_figure(stored.candidates[0], stored, actuator, DE)
    assert served.json()["data"] == printed["data"]
    assert _by_uid(served.json())["t-max"]["y"] == [151, 151]
    without = client.get(url, params={"catalogue": "false"}).json()
    assert not {"t-max", "n-max"} & set(_by_uid(without))
    assert client.get(url.replace("FHA-25C-50-L", "NO-SUCH")).status_code == 404


WORKED = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1},
    "models": ["FHA-25C-50-L"],
}


def _stored(client: TestClient, body: dict[str, Any]) -> tuple[str, Any]:
    from actuator_selection.schemas.quotes import StoredSelection

    created = client.post("/api/v1/selections", json=body)
    assert created.status_code == 201, created.text
    ident = created.json()["id"]
    stored = client.get(f"/api/v1/selections/{ident}").json()
    return ident, StoredSelection.model_validate(stored)


def test_the_cycle_is_the_chapters_trapezoid_with_the_answers_torques(
    client: TestClient,
) -> None:
    """Fig. 516.2 from the stored answer: n(t) through t_1…t_p at n_2; T(t) the steps
    T_1, T_2, T_3 of the answer, T_rms a line; two panels on one time axis."""
    from actuator_selection.documents.figures import cycle_figure

    _, stored = _stored(client, WORKED)
    candidate = stored.candidates[0]
    figure = cycle_figure(stored, candidate, DE)
    traces = _by_uid(figure)
    assert list(traces) == ["cycle-speed", "cycle-torque", "cycle-rms", "cycle-phases"]
    assert traces["cycle-speed"]["x"] == [0.0, 0.1, 0.2, 0.30000000000000004, 1.3]
    assert traces["cycle-speed"]["y"] == [0.0, 40, 40, 0.0, 0.0]
    torque = traces["cycle-torque"]["y"]
    assert torque[1:7] == [
        candidate.accel_torque_nm,
        candidate.accel_torque_nm,
        candidate.constant_torque_nm,
        candidate.constant_torque_nm,
        candidate.decel_torque_nm,
        candidate.decel_torque_nm,
    ]
    assert traces["cycle-rms"]["y"] == [candidate.rms_torque_nm] * 2
    assert traces["cycle-torque"]["yaxis"] == "y2"
    layout = figure["layout"]
    assert layout["meta"] == {"torques": "steps"}
    assert layout["separators"] == ",."
    assert layout["xaxis"]["title"]["text"] == "Zeit t [s]"
    assert layout["yaxis"]["domain"][0] > layout["yaxis2"]["domain"][1]  # speed above
    # the phases named above the speed panel: text, drawn once (plotly.js draws an
    # annotation twice on a chart's first draw); the steps' T_1, T_2, T_3 annotations
    assert [a["text"] for a in layout["annotations"]] == [
        "T<sub>1</sub>",
        "T<sub>2</sub>",
        "T<sub>3</sub>",
    ]
    phases = traces["cycle-phases"]
    assert phases["text"] == ["t<sub>1</sub>", "t<sub>2</sub>", "t<sub>3</sub>", "t<sub>p</sub>"]
    assert phases["y"] == [layout["yaxis"]["range"][1]] * 4  # the speed panel's top
    # each panel's range given (no autorange to run when drawn), holding what it draws
    assert layout["yaxis"]["range"][0] == 0
    assert layout["yaxis"]["range"][1] > 40
    low, high = layout["yaxis2"]["range"]
    assert low < candidate.decel_torque_nm
    assert high > candidate.accel_torque_nm
    # a candidate without torques (no J_A): the speed, and a note why there is no torque
    bare = candidate.model_copy(
        update={
            "accel_torque_nm": None,
            "constant_torque_nm": None,
            "decel_torque_nm": None,
            "rms_torque_nm": None,
        }
    )
    empty = cycle_figure(stored, bare, DE)
    assert list(_by_uid(empty)) == ["cycle-speed", "cycle-phases"]
    assert empty["layout"]["meta"] == {"torques": "none"}
    assert any("keine Daten" in a["text"] for a in empty["layout"]["annotations"])


def test_the_served_cycle_carries_the_torque_along_each_segment(client: TestClient) -> None:
    """``GET …/cycle``: the torque along each segment as the candidate's detail gives it
    (its points joined), or the stored steps with ``torques=false``; in the document's
    language; 404 for a model that is no candidate."""
    from actuator_selection.documents.figures import cycle_figure

    ident, stored = _stored(client, WORKED)
    url = f"/api/v1/selections/{ident}/candidates/FHA-25C-50-L/cycle"
    served = client.get(url, params={"lang": "de"})
    assert served.status_code == 200, served.text
    assert served.headers["content-language"] == "de"
    figure = served.json()
    assert figure["layout"]["meta"] == {"torques": "segments"}
    # drawn in one pass: no annotation (plotly.js draws each twice on a chart's first draw,
    # once to measure it for the autorange) and no axis left to autorange
    assert figure["layout"]["annotations"] == []
    assert all(len(figure["layout"][axis]["range"]) == 2 for axis in ("xaxis", "yaxis", "yaxis2"))
    detail = client.get(f"/api/v1/selections/{ident}/candidates/FHA-25C-50-L").json()
    torque = _by_uid(figure)["cycle-torque"]
    assert torque["x"] == [x for s in detail["segment_torques"] for x in s["times_s"]]
    assert torque["y"] == [y for s in detail["segment_torques"] for y in s["torques_nm"]]
    lean = client.get(url, params={"torques": "false", "lang": "en"})
    assert lean.status_code == 200
    assert lean.json() == cycle_figure(stored, stored.candidates[0], EN)
    assert client.get(url.replace("FHA-25C-50-L", "NO-SUCH")).status_code == 404
    assert client.get(url, params={"torques": "maybe"}).status_code == 422
