"""A selection matches Table 521.1 once per distinct actuator interface, not once per candidate.

The candidates' drive options, grouped in the answer and listed in full in a
candidate's detail, must still be what each actuator's own matching says.
"""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example

from actuator_selection.services import catalogue as drive
from actuator_selection.services.presenters.selection import TOP_MAX
from actuator_selection.sizing.compatibility import CompatibilityResult, match_controllers


def _interface(model_controllers: dict[str, Any]) -> str:
    """What the matching knows of an actuator (its family column and options), as a key."""
    i = model_controllers["interface"]
    return repr(
        [
            i[k]
            for k in ("family_column", "dc_bus_classes", "temperature_sensors", "feedback_systems")
        ]
    )


def _expanded(selection: dict[str, Any], candidate: dict[str, Any]) -> list[dict[str, Any]]:
    """A candidate's grouped drive options as one list: (row, level, missing) per controller,
    best first as the groups list them."""
    rows = selection["controllers"]
    return [
        {**rows[i], "level": group["level"], "missing": group["missing"]}
        for group in candidate["drive_options"]
        for i in group["controllers"]
    ]


_ROW = ("manufacturer", "type", "variant", "source_row", "level", "missing")


def test_candidates_list_what_their_actuator_matches(client: TestClient) -> None:
    selection = client.post("/api/v1/selections", json=worked_example.request()).json()
    assert len(selection["candidates"]) > 10
    listed_any = False
    for candidate in selection["candidates"]:
        model = candidate["model"]
        own = client.get(f"/api/v1/actuators/{model}/controllers").json()
        usable = [c for c in own["controllers"] if c["level"] != "excluded"]
        assert candidate["controllers_excluded"] == len(own["controllers"]) - len(usable)
        detail = client.get(f"/api/v1/selections/{selection['id']}/candidates/{model}").json()
        in_detail = [{k: v for k, v in c.items() if k != "voltage"} for c in detail["controllers"]]
        assert in_detail == usable, model
        if candidate["verdict"] == "unsuitable":
            assert candidate["drive_options"] is None
            continue
        listed_any = True
        assert _expanded(selection, candidate) == [{k: c[k] for k in _ROW} for c in usable]
        # each group's voltage check is the one the detail gives its controllers
        voltages = {
            (c["manufacturer"], c["type"], c["variant"]): c["voltage"]
            for c in detail["controllers"]
        }
        for group in candidate["drive_options"]:
            for i in group["controllers"]:
                row = selection["controllers"][i]
                full = voltages[(row["manufacturer"], row["type"], row["variant"])]
                assert group["voltage"] == {
                    k: full[k] for k in ("status", "value", "limit", "reference")
                }
    assert listed_any


def test_matching_runs_once_per_distinct_interface(
    client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[object] = []

    def counted(**kwargs: Any) -> CompatibilityResult:
        calls.append(kwargs["actuator"])
        return match_controllers(**kwargs)

    monkeypatch.setattr(drive, "match_controllers", counted)
    whole = {"top": TOP_MAX}  # every candidate listed, each with its drive options
    selection = client.post("/api/v1/selections", json=worked_example.request(), params=whole)
    models = [c["model"] for c in selection.json()["candidates"]]
    interfaces = {
        _interface(client.get(f"/api/v1/actuators/{m}/controllers").json()) for m in models
    }
    assert len(calls) == len(interfaces) < len(models)
