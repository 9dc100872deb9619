"""A selection matches Table 521.1 once per distinct actuator interface, not once per candidate.

The candidates' controller lists must still be what each actuator's own matching says.
"""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example

from actuator_selection.api import drive
from actuator_selection.core.compatibility import CompatibilityResult, match_controllers


def _interface(model_controllers: dict[str, Any]) -> str:
    """What the matching knows of an actuator (its family column and options), as a key."""
    i = model_controllers["interface"]
    return repr(
        [
            i[k]
            for k in ("family_column", "dc_bus_classes", "temperature_sensors", "feedback_systems")
        ]
    )


def test_candidates_list_what_their_actuator_matches(client: TestClient) -> None:
    selection = client.post("/api/v1/selections", json=worked_example.request()).json()
    assert len(selection["candidates"]) > 10
    for candidate in selection["candidates"]:
        own = client.get(f"/api/v1/actuators/{candidate['model']}/controllers").json()
        usable = [c for c in own["controllers"] if c["level"] != "excluded"]
        listed = [{k: v for k, v in c.items() if k != "voltage"} for c in candidate["controllers"]]
        assert listed == usable, candidate["model"]
        assert candidate["controllers_excluded"] == len(own["controllers"]) - len(usable)


def test_matching_runs_once_per_distinct_interface(
    client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    calls: list[object] = []

    def counted(**kwargs: Any) -> CompatibilityResult:
        calls.append(kwargs["actuator"])
        return match_controllers(**kwargs)

    monkeypatch.setattr(drive, "match_controllers", counted)
    selection = client.post("/api/v1/selections", json=worked_example.request()).json()
    models = [c["model"] for c in selection["candidates"]]
    interfaces = {
        _interface(client.get(f"/api/v1/actuators/{m}/controllers").json()) for m in models
    }
    assert len(calls) == len(interfaces) < len(models)
