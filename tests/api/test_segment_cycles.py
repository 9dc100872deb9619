"""Cycles of segments over the API: the trapezoid written as segments answers as the
shorthand does, a vertical two-way cycle is sized, batch equals single, stored selections
and candidate details carry the segments, and every bad segment is a 422 naming it."""

from __future__ import annotations

import csv
import io
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example
from tests.api._ranking import whole_ranking

API = "/api/v1/selections"

TRAPEZOID_AS_SEGMENTS: dict[str, Any] = {
    "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {
        "segments": [
            {"speed": 40, "duration_s": 0.1},
            {"duration_s": 0.1},
            {"speed": 0, "duration_s": 0.1},
            {"duration_s": 1.0},
        ]
    },
}

VERTICAL_TWO_MOVES: dict[str, Any] = {
    "load": {
        "torque_nm": 2.0,
        "inertia_kgm2": 0.9,
        "gravity_torque_nm": 30.0,
        "efficiency": 0.9,
    },
    "cycle": {
        "segments": [
            {"speed": 30, "accel": 300, "jerk_share": 0.5},
            {"duration_s": 0.4, "process_load": 10},
            {"speed": 0, "accel": 300, "jerk_share": 0.5},
            {"duration_s": 0.3},
            {"speed": -30, "duration_s": 0.1},
            {"duration_s": 0.4},
            {"speed": 0, "duration_s": 0.1},
            {"duration_s": 0.5},
        ]
    },
    "brake": True,
}


def created(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    return answer


def comparable(answer: dict[str, Any]) -> dict[str, Any]:
    """What the engineering decides: figures and candidates, not ids or the echoed cycle."""
    keep = ("cycle_time_s", "mean_speed_rpm", "duty_cycle_percent", "candidates", "load")
    return {k: answer[k] for k in keep}


def test_the_trapezoid_written_as_segments_answers_as_the_shorthand(client: TestClient) -> None:
    shorthand = created(client, worked_example.request())
    segments = created(client, TRAPEZOID_AS_SEGMENTS)
    assert comparable(segments) == comparable(shorthand)
    assert [s["duration_s"] for s in segments["segments"]] == [0.1, 0.1, 0.1, 1.0]
    assert [s["start_s"] for s in shorthand["segments"]] == [0.0, 0.1, 0.2, 0.30000000000000004]


def test_a_vertical_two_way_cycle_is_sized_with_its_segments(client: TestClient) -> None:
    answer = created(client, VERTICAL_TWO_MOVES)
    assert answer["load"]["gravity_torque_nm"] == 30.0
    assert answer["load"]["speed_rpm"] == 30.0  # the highest |speed|
    # accel 300 rpm/s to 30 rpm: 0.1 s; durations add up to t_0
    assert answer["cycle_time_s"] == pytest.approx(0.1 + 0.4 + 0.1 + 0.3 + 0.1 + 0.4 + 0.1 + 0.5)
    first = answer["candidates"][0]
    assert first["verdict"] in ("suitable", "unconfirmed")
    assert [c["name"] for c in first["checks"]][-1] == "brake_holding"
    # the brake holds |T_G| + T_F at standstill
    brake = next(c for c in first["checks"] if c["name"] == "brake_holding")
    assert brake["value"] == 32.0
    # Lowering at constant speed the weight drives back: T = (T_G + T_F·(−1))·η at the
    # output; lifting with the process load: (T_G + T_F + 10)/η.
    model = first["model"]
    detail = client.get(f"{API}/{answer['id']}/candidates/{model}").json()
    by_segment = {s["segment"]: s["torques_nm"] for s in detail["segment_torques"]}
    assert by_segment[5][0] == pytest.approx((30.0 - 2.0) * 0.9)
    assert by_segment[1][0] == pytest.approx((30.0 + 2.0 + 10.0) / 0.9)
    assert by_segment[3] == [30.0, 30.0]  # the dwell holds the weight, no losses
    stored = client.get(f"{API}/{answer['id']}").json()
    assert stored["cycle"] == VERTICAL_TWO_MOVES["cycle"] | {
        "start_speed": 0.0,
        "segments": stored["cycle"]["segments"],
    }
    assert stored["candidates"] == answer["candidates"]


def test_a_batch_takes_segment_cycles_and_answers_as_single(client: TestClient) -> None:
    cases = [worked_example.request(), VERTICAL_TWO_MOVES, TRAPEZOID_AS_SEGMENTS]
    response = client.post(f"{API}/batch", json={"cases": cases, "top": 3})
    assert response.status_code == 200, response.text
    results = response.json()["results"]
    for case, result in zip(cases, results, strict=True):
        single = created(client, case)
        assert result["load"] == single["load"]
        assert result["cycle_time_s"] == single["cycle_time_s"]
        assert result["mean_speed_rpm"] == single["mean_speed_rpm"]
        assert [c["model"] for c in result["candidates"]] == [
            c["model"] for c in single["candidates"][:3]
        ]
        for got, want in zip(result["candidates"], single["candidates"], strict=False):
            assert got["rms_torque_nm"] == want["rms_torque_nm"]
            assert got["accel_torque_nm"] == want["accel_torque_nm"]


def segments_with(*segments: dict[str, Any]) -> dict[str, Any]:
    return {"load": {"torque_nm": 5, "inertia_kgm2": 1.3}, "cycle": {"segments": list(segments)}}


@pytest.mark.parametrize(
    ("body", "loc"),
    [
        (
            segments_with({"speed": 40, "duration_s": 0}),
            ["body", "cycle", "segments", "0", "duration_s"],
        ),
        (segments_with({"speed": 40}), ["body", "cycle", "segments", "0", "duration_s"]),
        (
            segments_with({"speed": 40, "duration_s": 1, "accel": 5}),
            ["body", "cycle", "segments", "0", "duration_s"],
        ),
        (segments_with({"accel": 5}), ["body", "cycle", "segments", "0", "accel"]),
        (
            segments_with({"speed": 40, "duration_s": 1}, {"speed": -40, "duration_s": 1}),
            ["body", "cycle", "segments", "1", "speed"],
        ),
        (segments_with({"speed": 40, "duration_s": 1}), ["body", "cycle", "segments"]),
        (
            segments_with({"speed": 40, "duration_s": 1, "jerk_share": 2}),
            ["body", "cycle", "segments", 0, "jerk_share"],
        ),
        (
            {
                **segments_with({"duration_s": 1}),
                "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1},
            },
            ["body", "load", "speed_rpm"],
        ),
        (
            {**worked_example.request(), "load": {"torque_nm": 5, "inertia_kgm2": 1.3}},
            ["body", "load", "speed_rpm"],
        ),
        ({**segments_with(), "cycle": {"segments": []}}, ["body", "cycle", "segments"]),
        (
            {**worked_example.request(), "cycle": {"segments": "up and down"}},
            ["body", "cycle", "segments"],
        ),
    ],
)
def test_a_bad_segment_is_a_422_naming_it(
    client: TestClient, body: dict[str, Any], loc: list[Any]
) -> None:
    response = client.post(API, json=body)
    assert response.status_code == 422, response.text
    errors = response.json()["detail"]
    assert [str(x) for x in errors[0]["loc"]] == [str(x) for x in loc], errors
    assert errors[0]["msg"]


def test_reports_of_a_segment_cycle_list_its_segments(client: TestClient) -> None:
    answer = created(client, VERTICAL_TWO_MOVES)
    csv_text = client.get(f"{API}/{answer['id']}/report.csv").text
    rows = list(csv.DictReader(io.StringIO(csv_text.removeprefix("\ufeff"))))
    ranking = whole_ranking(client, answer)  # the report lists the whole ranking
    assert len(rows) == sum(len(c["checks"]) for c in ranking)
    for row in rows:  # every row stands alone: the segments on each
        for k, segment in enumerate(answer["segments"], start=1):
            assert float(row[f"segment_{k}_duration_s"]) == segment["duration_s"]
            assert float(row[f"segment_{k}_start_rpm"]) == segment["start_rpm"]
            assert float(row[f"segment_{k}_end_rpm"]) == segment["end_rpm"]
        assert row["accel_s"] == row["pause_s"] == ""
    pdf = client.get(f"{API}/{answer['id']}/report.pdf")
    assert pdf.status_code == 200
    assert pdf.headers["content-type"] == "application/pdf"
