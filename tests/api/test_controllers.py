"""Table 521.1 over HTTP: the controller list, matching, and controllers in selections."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example

WORKED_EXAMPLE: dict[str, Any] = worked_example.request()


def test_all_rows_of_table_521_1_with_corrections(client: TestClient) -> None:
    rows = client.get("/api/v1/controllers").json()
    assert len(rows) == 28
    assert [r["source_row"] for r in rows] == list(range(1, 29))
    by_type = {(r["type"], r["variant"]): r for r in rows}
    masterdrives = by_type[("MASTERDRIVES MC", None)]
    assert masterdrives["manufacturer"] == "SIEMENS"  # the row reads NUM AG
    assert "NUM AG" in masterdrives["correction"]
    assert by_type[("MOVIDRIVE B", None)]["manufacturer"] == "SEW"
    assert len([r for r in rows if r["type"] == "S 400"]) == 3  # variants kept apart
    assert all(r["source"] for r in rows)


@pytest.mark.parametrize(
    ("params", "check"),
    [
        ({"family": "FHA-C mini"}, lambda r: "fha_mini" in r["marks"]),
        ({"bus_class": "24vdc"}, lambda r: "bus_24vdc" in r["marks"]),
        ({"sensor": "ptc", "level": "tested"}, lambda r: r["marks"].get("sensor_ptc") == "tested"),
        ({"feedback": "endat"}, lambda r: "feedback_endat" in r["marks"]),
        ({"manufacturer": "elmo"}, lambda r: r["manufacturer"] == "ELMO"),
    ],
)
def test_controller_filters(client: TestClient, params: dict[str, str], check: Any) -> None:
    everything = client.get("/api/v1/controllers").json()
    filtered = client.get("/api/v1/controllers", params=params).json()
    assert filtered, params
    assert [r for r in everything if check(r)] == filtered


@pytest.mark.parametrize(
    ("params", "loc"),
    [
        ({"bus_class": "48vdc"}, ["query", "bus_class"]),
        ({"level": "maybe"}, ["query", "level"]),
        ({"family": "Nonesuch"}, ["body", "family"]),
    ],
)
def test_controller_filter_errors(
    client: TestClient, params: dict[str, str], loc: list[str]
) -> None:
    response = client.get("/api/v1/controllers", params=params)
    assert 400 <= response.status_code < 500
    assert loc[-1] in [e["loc"][-1] for e in response.json()["detail"]]


def test_actuator_controllers_of_a_cha(client: TestClient) -> None:
    body = client.get("/api/v1/actuators/CHA-25A-50/controllers").json()
    assert body["interface"]["dc_bus_classes"] == ["320vdc", "560vdc"]
    assert body["interface"]["feedback_systems"] is None
    levels = [c["level"] for c in body["controllers"]]
    order = {"tested": 0, "possible": 1, "unconfirmed": 2, "excluded": 3}
    assert [order[x] for x in levels] == sorted(order[x] for x in levels)
    for c in body["controllers"]:
        if c["level"] == "excluded":
            assert c["excluded_by"]
        else:
            assert c["missing"] == ["feedback_system"]  # unknown for the CHA
    # Cross-check against the raw marks: excluded exactly when a row lacks the CHA/CHM
    # column, both sensors the CHA offers, or both bus classes it runs on.
    marks = {r["source_row"]: r["marks"] for r in client.get("/api/v1/controllers").json()}

    def excluded(m: dict[str, str]) -> bool:
        return (
            "cha_chm" not in m
            or not {"sensor_ptc", "sensor_kty84_130"} & set(m)
            or not {"bus_320vdc", "bus_560vdc"} & set(m)
        )

    assert {c["source_row"] for c in body["controllers"] if c["level"] == "excluded"} == {
        row for row, m in marks.items() if excluded(m)
    }


def test_unknown_actuator_controllers_is_404(client: TestClient) -> None:
    assert client.get("/api/v1/actuators/NOPE/controllers").status_code == 404


def test_selection_candidates_carry_controllers_and_say_what_is_missing(
    client: TestClient,
) -> None:
    body = client.post(
        "/api/v1/selections", json={**WORKED_EXAMPLE, "models": ["FHA-25C-50-L", "CHA-25A-50"]}
    ).json()
    details = {
        c["model"]: client.get(f"/api/v1/selections/{body['id']}/candidates/{c['model']}").json()
        for c in body["candidates"]
    }
    example = details["FHA-25C-50-L"]
    assert example["controllers"], "the PTC and the FHA-C column leave some controllers"
    # the criteria without data, in words (the code's params name them; `missing` below
    # gives them by their identifiers)
    assert example["controllers_note_code"] == "controllers_note.unconfirmed"
    assert example["controllers_note_params"]["missing"] == ["DC bus voltage", "feedback system"]
    assert "DC bus voltage, feedback system" in example["controllers_note"]
    for option in example["controllers"]:
        assert set(option["missing"]) == {"bus_class", "feedback_system"}
        assert option["voltage"]["status"] == "no_data"
    lean = {c["model"]: c for c in body["candidates"]}["FHA-25C-50-L"]
    for group in lean["drive_options"]:  # the answer says the same, grouped
        assert set(group["missing"]) == {"bus_class", "feedback_system"}
        assert group["voltage"]["status"] == "no_data"
    cha = details["CHA-25A-50"]
    first = cha["controllers"][0]
    # Eq. 521.2 at n_2 = 40 rpm: 2000 rpm × 37 V/1000 rpm + 4.0 A × 3.7 Ω = 88.8 V, with
    # ω·L·I = 2π·6·2000/60 s⁻¹ × 6.0 mH × 4.0 A in quadrature.
    inductive = 2 * math.pi * 6 * 2000 / 60 * 6.0e-3 * 4.0
    assert first["voltage"]["value"] == pytest.approx(math.hypot(88.8, inductive))
    assert first["voltage"]["status"] == "pass"
    assert cha["controllers_excluded"] + len(cha["controllers"]) == 28


def test_an_unknown_family_filter_is_named_as_a_query_parameter(client: TestClient) -> None:
    response = client.get("/api/v1/controllers", params={"family": "XYZ"})
    assert response.status_code == 422
    (entry,) = response.json()["detail"]
    assert entry["loc"] == ["query", "family"]
    assert entry["type"] == "unknown_family"
    assert "'XYZ' is not an actuator family of Table 521.1" in entry["msg"]
