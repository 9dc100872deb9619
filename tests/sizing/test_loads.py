"""Eq. 515.4 and 515.6 against energy balances and direct integration."""

from __future__ import annotations

import math

import pytest

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.loads import (
    BallScrew,
    RotaryTable,
    ball_screw_load,
    rotary_table_load,
)


def test_ball_screw_inertia_from_kinetic_energy() -> None:
    """½·J_L·ω² = ½·J_S·ω² + ½·m·v² with v = P·ω/2π: the reflected inertia of the slide."""
    screw = BallScrew(
        mass_kg=250,
        lead_m=0.02,
        friction_coefficient=0.05,
        efficiency=0.9,
        screw_inertia_kgm2=0.004,
    )
    omega = 100.0  # any speed: the ratio is independent of it
    v = screw.lead_m * omega / (2 * math.pi)
    energy = 0.5 * screw.screw_inertia_kgm2 * omega**2 + 0.5 * screw.mass_kg * v**2
    assert ball_screw_load(screw).inertia_kgm2 == pytest.approx(2 * energy / omega**2, rel=1e-12)


def test_ball_screw_torque_from_power_balance() -> None:
    """Friction power μ·m·g·v must come from the shaft through η: T·ω·η = μ·m·g·v."""
    screw = BallScrew(mass_kg=250, lead_m=0.02, friction_coefficient=0.05, efficiency=0.9)
    omega = 10.0
    v = screw.lead_m * omega / (2 * math.pi)
    friction_power = 0.05 * 250 * 9.81 * v
    assert ball_screw_load(screw).torque_nm == pytest.approx(friction_power / (omega * 0.9))
    # 250 kg, 20 mm, μ 0.05, η 0.9 by hand: 122.625 N · 3.18310 mm / 0.9 = 0.433697 Nm.
    assert ball_screw_load(screw).torque_nm == pytest.approx(0.433697, abs=1e-6)


def test_rotary_table_inertia_by_integrating_rings() -> None:
    """J of a uniform disc, ∫ r² dm over thin rings, equals m·D²/8."""
    mass, diameter = 80.0, 0.6
    radius = diameter / 2
    rings = 20_000
    density = mass / (math.pi * radius**2)
    integral = 0.0
    for k in range(rings):
        r = (k + 0.5) * radius / rings
        integral += r**2 * density * 2 * math.pi * r * (radius / rings)
    table = RotaryTable(
        mass_kg=mass, diameter_m=diameter, friction_coefficient=0.01, friction_radius_m=0.25
    )
    assert rotary_table_load(table).inertia_kgm2 == pytest.approx(integral, rel=1e-6)
    assert rotary_table_load(table).torque_nm == pytest.approx(0.01 * 80 * 9.81 * 0.25)


def test_frictionless_mechanisms_have_no_load_torque() -> None:
    assert (
        ball_screw_load(
            BallScrew(mass_kg=10, lead_m=0.01, friction_coefficient=0, efficiency=1)
        ).torque_nm
        == 0
    )
    assert (
        rotary_table_load(
            RotaryTable(mass_kg=10, diameter_m=1, friction_coefficient=0, friction_radius_m=0.4)
        ).torque_nm
        == 0
    )


@pytest.mark.parametrize(
    ("field", "changes"),
    [
        ("efficiency", {"efficiency": 0}),
        ("efficiency", {"efficiency": 1.2}),
        ("lead_m", {"lead_m": 0}),
        ("mass_kg", {"mass_kg": -1}),
        ("friction_coefficient", {"friction_coefficient": -0.1}),
        ("screw_inertia_kgm2", {"screw_inertia_kgm2": math.inf}),
    ],
)
def test_ball_screw_rejects_bad_values(field: str, changes: dict[str, float]) -> None:
    values = {"mass_kg": 1.0, "lead_m": 0.01, "friction_coefficient": 0.1, "efficiency": 0.9}
    values.update(changes)
    with pytest.raises(InvalidInputError) as caught:
        BallScrew(**values)
    assert caught.value.field == field


def test_rotary_table_rejects_zero_diameter() -> None:
    with pytest.raises(InvalidInputError) as caught:
        RotaryTable(mass_kg=1, diameter_m=0, friction_coefficient=0.1, friction_radius_m=0.1)
    assert caught.value.field == "diameter_m"


def test_ball_screw_overflow_names_efficiency() -> None:
    """η = 1e-300 is > 0, but T_L = μ·m·P·g/(2π·η) then exceeds every float: a domain error."""
    screw = BallScrew(mass_kg=1e6, lead_m=100, friction_coefficient=10, efficiency=1e-300)
    with pytest.raises(InvalidInputError) as caught:
        ball_screw_load(screw)
    assert caught.value.field == "efficiency"
    assert "Eq. 515.4" in caught.value.message


def test_ball_screw_inertia_overflow_names_lead() -> None:
    """(P/2π)² overflows Python's float power (OverflowError): a domain error instead."""
    screw = BallScrew(mass_kg=1, lead_m=1e200, friction_coefficient=0, efficiency=1)
    with pytest.raises(InvalidInputError) as caught:
        ball_screw_load(screw)
    assert caught.value.field == "lead_m"


def test_rotary_table_overflow_names_diameter() -> None:
    table = RotaryTable(mass_kg=1e10, diameter_m=1e155, friction_coefficient=0, friction_radius_m=0)
    with pytest.raises(InvalidInputError) as caught:
        rotary_table_load(table)
    assert caught.value.field == "diameter_m"
