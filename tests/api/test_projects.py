"""Machine projects over the API (issue 31): several axes on one DC bus, sized, stored,
edited, listed; a three-axis pick-and-place gives the bus's peak power, its regenerative
energy per cycle and a braking resistor."""

from __future__ import annotations

import copy
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests.api.test_mechanism_selections import PICK_AND_PLACE

from actuator_selection.schemas.projects import ProjectOut

API = "/api/v1/projects"

VERTICAL_BELT: dict[str, Any] = {"name": "Z", "offset_s": 0.0, **PICK_AND_PLACE}
"""Down 180 mm to pick, up to place: 2.4 s (tests/api/test_mechanism_selections.py)."""

HORIZONTAL_RACK: dict[str, Any] = {
    "name": "X",
    "offset_s": 0.9,
    "load": {
        "type": "rack_pinion",
        "mass_kg": 12.0,
        "pinion_diameter_mm": 80,
        "friction_coefficient": 0.05,
        "efficiency": 0.95,
    },
    "cycle": {
        "segments": [  # 300 mm across and back, in mm/s
            {"speed": 600, "duration_s": 0.2},
            {"duration_s": 0.3},
            {"speed": 0, "duration_s": 0.2},
            {"duration_s": 0.5},
            {"speed": -600, "duration_s": 0.2},
            {"duration_s": 0.3},
            {"speed": 0, "duration_s": 0.2},
            {"duration_s": 0.5},
        ]
    },
}

ROTARY_WRIST: dict[str, Any] = {
    "name": "C",
    "offset_s": 1.1,
    "load": {"type": "rotary", "inertia_kgm2": 0.08, "friction_torque_nm": 0.5},
    "cycle": {
        "segments": [  # a quarter turn and back
            {"speed": 60, "duration_s": 0.1},
            {"duration_s": 0.15},
            {"speed": 0, "duration_s": 0.1},
            {"duration_s": 0.85},
            {"speed": -60, "duration_s": 0.1},
            {"duration_s": 0.15},
            {"speed": 0, "duration_s": 0.1},
            {"duration_s": 0.85},
        ]
    },
}

PICK_AND_PLACE_CELL: dict[str, Any] = {
    "name": "Pick-and-place cell",
    "bus": {"bus_class": "560vdc", "chopper_voltage_v": 780},
    "axes": [VERTICAL_BELT, HORIZONTAL_RACK, ROTARY_WRIST],
}


def created(client: TestClient, body: dict[str, Any]) -> dict[str, Any]:
    response = client.post(API, json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    assert response.headers["location"] == f"{API}/{answer['id']}"
    return answer


def test_a_three_axis_pick_and_place_gives_peak_regeneration_and_a_braking_resistor(
    client: TestClient,
) -> None:
    answer = created(client, PICK_AND_PLACE_CELL)
    assert answer["cycle_time_s"] == pytest.approx(2.4)
    assert [a["name"] for a in answer["axes"]] == ["Z", "X", "C"]
    assert [a["verdict"] for a in answer["axes"]] == ["suitable"] * 3
    bus = answer["bus"]
    assert bus["nominal_voltage_v"] == 560
    power = bus["power"]
    assert power["peak_w"] > 0
    assert power["regen_energy_j"] > 0
    assert power["regen_peak_w"] > 0
    # the bus's net energy is the axes' electrical energies summed
    net = sum(a["energies"]["electrical_j"] for a in answer["axes"])
    assert power["mean_w"] * answer["cycle_time_s"] == pytest.approx(net, rel=1e-9)
    for a in answer["axes"]:
        e = a["energies"]
        assert e["electrical_j"] == pytest.approx(
            e["mechanical_j"] + e["no_load_j"] + e["copper_j"], rel=1e-9
        )
    resistor = bus["braking_resistor"]
    assert resistor["needed"] is True
    assert resistor["peak_power_w"] == power["regen_peak_w"]
    assert resistor["continuous_power_w"] == pytest.approx(power["regen_energy_j"] / 2.4)
    assert resistor["max_resistance_ohm"] == pytest.approx(780**2 / power["regen_peak_w"])
    assert resistor["min_resistance_ohm"] is None  # no data
    # no capacitance or highest voltage given: the capacitor says no data
    assert bus["capacitor"]["energy_j"] is None
    phasing = bus["random_phasing"]
    assert phasing["worst_peak_w"] == pytest.approx(
        sum(a["power"]["peak_w"] for a in answer["axes"])
    )
    assert phasing["worst_peak_w"] >= power["peak_w"]
    assert len(answer["curve"]["axes_w"]) == 3
    assert len(answer["curve"]["times_s"]) == len(answer["curve"]["axes_w"][0])
    # the presenter writes its contract: the model reads it and writes the same JSON
    assert ProjectOut.model_validate(answer).model_dump(mode="json") == answer
    # stored: read back unchanged
    again = client.get(f"{API}/{answer['id']}")
    assert again.status_code == 200
    assert again.json() == answer


def test_one_axis_alone_equals_its_own_selection(client: TestClient) -> None:
    project = created(
        client, {"name": "one", "bus": {"bus_class": "560vdc"}, "axes": [VERTICAL_BELT]}
    )
    selection = client.post("/api/v1/selections", json=PICK_AND_PLACE).json()
    axis = project["axes"][0]
    first = next(c for c in selection["candidates"] if c["model"] == axis["model"])
    assert first is selection["candidates"][0] or axis["verdict"] == first["verdict"]
    for name in ("verdict", "accel_torque_nm", "decel_torque_nm", "rms_torque_nm"):
        assert axis[name] == first[name]
    # the bus of one axis is that axis
    for name, value in axis["power"].items():
        assert project["bus"]["power"][name] == pytest.approx(value, rel=1e-9, abs=1e-9)


def test_the_bus_capacitance_absorbs_what_it_can(client: TestClient) -> None:
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    body["bus"] |= {"capacitance_uf": 2000, "max_voltage_v": 760}
    answer = created(client, body)
    cap = answer["bus"]["capacitor"]
    assert cap["energy_j"] == pytest.approx(0.5 * 2000e-6 * (760**2 - 560**2))
    assert cap["absorbs_every_pulse"] == (
        answer["bus"]["power"]["regen_pulse_energy_j"] <= cap["energy_j"]
    )


def test_edit_size_again_and_list_in_pages(client: TestClient) -> None:
    first = created(client, PICK_AND_PLACE_CELL)
    second = created(
        client, {"name": "wrist", "bus": {"bus_class": "320vdc"}, "axes": [ROTARY_WRIST]}
    )
    edited = copy.deepcopy(PICK_AND_PLACE_CELL)
    edited["name"] = "Cell, wrist later"
    edited["axes"][2]["offset_s"] = 1.5
    response = client.put(f"{API}/{first['id']}", json=edited)
    assert response.status_code == 200, response.text
    changed = response.json()
    assert changed["id"] == first["id"]
    assert changed["created_at"] == first["created_at"]
    assert changed["request"]["name"] == "Cell, wrist later"
    assert client.get(f"{API}/{first['id']}").json() == changed
    sized = client.post(f"{API}/{second['id']}/size")
    assert sized.status_code == 200, sized.text
    assert sized.json()["bus"] == second["bus"]
    seen: list[str] = []
    cursor = None
    while True:
        params: dict[str, Any] = {"limit": 1} | ({"cursor": cursor} if cursor else {})
        page = client.get(API, params=params)
        assert page.status_code == 200, page.text
        body = page.json()
        seen += [p["id"] for p in body["projects"]]
        cursor = body["next_cursor"]
        if cursor is None:
            break
    assert seen[-2:] == [first["id"], second["id"]]


@pytest.mark.parametrize(
    ("change", "loc"),
    [
        (lambda b: b["axes"][1].update(model="NO-SUCH-1"), ["body", "axes", 1, "model"]),
        (lambda b: b["axes"][2].update(offset_s=-1), ["body", "axes", 2, "offset_s"]),
        (lambda b: b["bus"].update(bus_class="48vdc"), ["body", "bus", "bus_class"]),
        (lambda b: b.update(axes=[]), ["body", "axes"]),
        (
            lambda b: b["axes"][2]["cycle"]["segments"][3].update(duration_s=2.0),
            ["body", "axes", 2, "cycle"],
        ),
        (
            lambda b: b["bus"].update(capacitance_uf=1000, max_voltage_v=500),
            ["body", "bus", "max_voltage_v"],
        ),
    ],
)
def test_bad_input_is_422_naming_the_field(
    client: TestClient, change: Any, loc: list[str | int]
) -> None:
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    change(body)
    response = client.post(API, json=body)
    assert response.status_code == 422, response.text
    errors = response.json()["detail"]
    # a core error's dotted field gives its list index as text, as for a cycle's segments
    want = [str(x) for x in loc]
    assert any([str(x) for x in e["loc"][: len(loc)]] == want for e in errors), errors


def test_unknown_project_and_cursor(client: TestClient) -> None:
    assert client.get(f"{API}/no-such").status_code == 404
    assert client.post(f"{API}/no-such/size").status_code == 404
    assert client.put(f"{API}/no-such", json=PICK_AND_PLACE_CELL).status_code == 404
    bad = client.get(API, params={"cursor": "nonsense"})
    assert bad.status_code == 422
    assert bad.json()["detail"][0]["loc"] == ["query", "cursor"]
