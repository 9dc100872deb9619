"""A request's case as the core sees it (``SelectionRequest.to_core``): a case with every
option at its default is made without them (``_plain``), the same application as with
them written out; any option set goes the whole way, and a wrong one is refused as it was."""

from __future__ import annotations

from typing import Any

import pytest

from actuator_selection.errors import DomainError
from actuator_selection.schemas.selections import SelectionRequest
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.cycle import Load, SpeedPattern

BASE: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}
OPTIONS: list[dict[str, Any]] = [
    {"brake": True},
    {"drive": True},
    {"thermal_time_constant_s": 600.0},
    {"gear": {"required_life_h": 7000.0}},
    {"min_natural_frequency_hz": 10.0},
    {"brake_safety_factor": 1.5},
    {"emergency_stops": 100.0},
    {
        "output_load": {
            "radial_force_n": 100.0,
            "axial_force_n": 50.0,
            "radial_lever_m": 0.02,
            "axial_lever_m": 0.01,
        }
    },
]


@pytest.mark.parametrize("high_dynamics", [True, False])
def test_a_plain_case_is_the_application_with_its_defaults(high_dynamics: bool) -> None:
    request = SelectionRequest.model_validate({**BASE, "high_dynamics": high_dynamics})
    assert request._plain()
    assert request.to_core() == Application(
        pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0),
        load=Load(torque_nm=5, inertia_kgm2=1.3),
        **request._options(),
    )


@pytest.mark.parametrize("option", OPTIONS)
def test_a_case_with_an_option_is_not_plain(option: dict[str, Any]) -> None:
    request = SelectionRequest.model_validate({**BASE, **option})
    assert not request._plain()
    app = request.to_core()
    assert app == Application(pattern=app.pattern, load=app.load, **request._options())
    assert app != SelectionRequest.model_validate(BASE).to_core()


def test_a_plain_case_without_its_speed_is_refused_as_before() -> None:
    request = SelectionRequest.model_validate({**BASE, "load": {"torque_nm": 5, "inertia_kgm2": 1}})
    assert request._plain()
    with pytest.raises(DomainError) as raised:
        request.to_core()
    assert raised.value.field == "load.speed_rpm"
