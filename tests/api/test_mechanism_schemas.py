"""Mechanism request models and quantities with units, at the pydantic level (no server).

Expected conversions come from the definitions of the units (1 in = 25.4 mm exactly,
1 lb = 0.45359237 kg exactly, 1 rev = 2π rad), not from pint.
"""

from __future__ import annotations

import math
import subprocess
import sys
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pydantic import TypeAdapter, ValidationError

from actuator_selection.errors import InvalidInputError
from actuator_selection.schemas.common import StrictModel
from actuator_selection.schemas.mechanisms import (
    MECHANISM_TYPES,
    BeltIn,
    LiftIn,
    MechanismIn,
    TransmissionIn,
)
from actuator_selection.sizing.mechanisms import (
    BeltDrive,
    Hoist,
    Transmission,
    belt_axis,
    hoist_axis,
    with_transmission,
)

INCH_MM = 25.4
POUND_KG = 0.45359237


class Request(StrictModel):
    """A body with a mechanism at ``load``, as the selection request will hold it."""

    load: MechanismIn


def _belt(**changes: Any) -> dict[str, Any]:
    body: dict[str, Any] = {
        "type": "belt",
        "mass_kg": 5,
        "pulley_diameter_mm": 50,
        "friction_coefficient": 0.1,
        "efficiency": 0.9,
        "incline_deg": 90,
    }
    return {**body, **changes}


def _errors(body: dict[str, Any]) -> list[dict[str, Any]]:
    with pytest.raises(ValidationError) as caught:
        Request.model_validate({"load": body})
    return [dict(e) for e in caught.value.errors(include_url=False)]


def _one_error(body: dict[str, Any], field: str) -> dict[str, Any]:
    """The only error of ``body``; its ``loc`` ends at ``field`` (the union tag before it)."""
    errors = _errors(body)
    assert len(errors) == 1, errors
    assert tuple(errors[0]["loc"][-len(field.split(".")) :]) == tuple(field.split("."))
    return errors[0]


# --- units at the edge ----------------------------------------------------------------------


@pytest.mark.parametrize(
    ("field", "text", "expected"),
    [
        ("speed", "300 mm/s", 300.0),
        ("speed", "12 in/s", 12 * INCH_MM),
        ("speed", "0.3 m/s", 300.0),
        ("speed", "18 m/min", 300.0),
        ("pulley_diameter_mm", "50 mm", 50.0),
        ("pulley_diameter_mm", "0.5 in", 0.5 * INCH_MM),
        ("pulley_diameter_mm", "2in", 2 * INCH_MM),
        ("pulley_diameter_mm", "5 cm", 50.0),
        ("mass_kg", "22 lb", 22 * POUND_KG),
        ("mass_kg", "500 g", 0.5),
        ("belt_mass_kg", "8 oz", 0.5 * POUND_KG),
        ("pulley_inertia_kgm2", "3 lb*in^2", 3 * POUND_KG * (INCH_MM / 1000) ** 2),
        ("pulley_inertia_kgm2", "2 kg·m²", 2.0),
        ("pulley_inertia_kgm2", "20 kg cm**2", 0.002),
        ("incline_deg", "-0.25 turn", -90.0),
        ("incline_deg", "1.25e-1 turn", 45.0),
        ("friction_force_n", "2 lbf", 2 * POUND_KG * 9.80665),
    ],
)
def test_text_with_a_unit_converts_to_the_fields_unit(
    field: str, text: str, expected: float
) -> None:
    belt = Request.model_validate({"load": _belt(**{field: text})}).load
    assert getattr(belt, field) == pytest.approx(expected, rel=1e-12)


def test_numbers_are_read_in_the_fields_unit_exactly() -> None:
    belt = Request.model_validate({"load": _belt(speed=300, mass_kg=5.25)}).load
    assert isinstance(belt, BeltIn)
    assert (belt.speed, belt.mass_kg, belt.pulley_diameter_mm) == (300, 5.25, 50)


def test_rotary_speed_takes_angles_per_time() -> None:
    adapter = TypeAdapter(MechanismIn)
    for text, rpm in [("40 rpm", 40.0), ("40 rev/min", 40.0), ("2 rev/s", 120.0)]:
        load = adapter.validate_python({"type": "rotary", "inertia_kgm2": 1.3, "speed": text})
        assert load.speed == pytest.approx(rpm, rel=1e-12)
    load = adapter.validate_python({"type": "rotary", "inertia_kgm2": 1, "speed": "1 rad/s"})
    assert load.speed == pytest.approx(60 / (2 * math.pi), rel=1e-12)
    for ambiguous in ("1 Hz", "60 min^-1", "1 s**-1"):
        with pytest.raises(ValidationError) as caught:
            adapter.validate_python({"type": "rotary", "inertia_kgm2": 1, "speed": ambiguous})
        (error,) = caught.value.errors()
        assert error["loc"][-1] == "speed"
        assert "angle per time" in error["msg"]


def test_request_in_mm_and_lb_is_the_core_in_si() -> None:
    """The model's axis is the core's axis of the same mechanism given in SI."""
    body = _belt(
        mass_kg="11 lb",
        pulley_diameter_mm="2 in",
        idler_diameter_mm=40,
        idler_inertia_kgm2=1e-5,
        transmission={"ratio": 5, "inertia_kgm2": 1e-4, "efficiency": 0.95},
    )
    axis = Request.model_validate({"load": body}).load.to_axis()
    core = with_transmission(
        belt_axis(
            BeltDrive(
                mass_kg=11 * POUND_KG,
                pulley_diameter_m=2 * INCH_MM / 1000,
                friction_coefficient=0.1,
                efficiency=0.9,
                incline_deg=90,
                idler_inertia_kgm2=1e-5,
                idler_diameter_m=0.04,
            )
        ),
        Transmission(ratio=5, inertia_kgm2=1e-4, efficiency=0.95),
    )
    for name in ("inertia_kgm2", "gravity_torque_nm", "speed_rpm_per_unit", "efficiency"):
        assert getattr(axis, name) == pytest.approx(getattr(core, name), rel=1e-12), name
    assert (axis.speed_unit, axis.force_unit) == ("mm/s", "N")


def test_lift_in_mm_resolves_exactly_as_the_core() -> None:
    lift = LiftIn(
        type="lift",
        load_mass_kg=100,
        drum_diameter_mm=200,
        efficiency=0.9,
        counterweight_kg=60,
        drum_inertia_kgm2=0.05,
    )
    core = hoist_axis(
        Hoist(
            load_mass_kg=100,
            drum_diameter_m=200 / 1000,
            efficiency=0.9,
            counterweight_kg=60,
            drum_inertia_kgm2=0.05,
        )
    )
    assert lift.to_axis() == core


# --- bad values answered with the field named ----------------------------------------------


@pytest.mark.parametrize(
    ("field", "value", "error_type"),
    [
        ("speed", "3 kg", "quantity_unit"),
        ("speed", "300 rpm", "quantity_unit"),  # a rotary speed for a linear axis
        ("pulley_diameter_mm", "50 mm/s", "quantity_unit"),
        ("mass_kg", "22 lbf", "quantity_unit"),  # a force, not a mass
        ("pulley_inertia_kgm2", "3 kg m", "quantity_unit"),
        ("incline_deg", "30 %", "quantity_text"),
        ("incline_deg", "30 percent", "quantity_unit"),
        ("incline_deg", "30", "quantity_text"),  # text needs a unit; send 30 as a number
        ("mass_kg", "5 blorp", "quantity_unit"),
        ("mass_kg", "kg", "quantity_text"),
        ("mass_kg", "2**10 kg", "quantity_text"),
        ("mass_kg", "3 kg + 2 kg", "quantity_text"),
        ("mass_kg", "5 kg" + " " * 70, "quantity_text"),
        ("mass_kg", "1e400 kg", "finite_number"),
        ("mass_kg", "nan kg", "quantity_text"),
        ("mass_kg", -1, "greater_than_equal"),
        ("mass_kg", "-3 kg", "greater_than_equal"),
        ("mass_kg", "2e6 kg", "less_than_equal"),
        ("mass_kg", True, "float_type"),
        ("mass_kg", None, "float_type"),
        ("pulley_diameter_mm", 0, "greater_than_equal"),
        ("pulley_diameter_mm", "1e9 mile", "less_than_equal"),
        ("speed", 0, "greater_than"),
        ("speed", "1e6 m/s", "less_than_equal"),
        ("incline_deg", 90.5, "less_than_equal"),
        ("incline_deg", "-2 rad", "greater_than_equal"),
        ("efficiency", 1.2, "less_than_equal"),
        ("efficiency", "0.9", "float_type"),  # a plain quantity: no text
        ("friction_coefficient", -0.1, "greater_than_equal"),
        ("friction_force_n", "-5 N", "greater_than_equal"),
    ],
)
def test_bad_values_name_the_field_and_the_rule(field: str, value: Any, error_type: str) -> None:
    error = _one_error(_belt(**{field: value}), field)
    assert error["type"] == error_type
    assert error["msg"]


def test_a_broken_bound_shows_the_converted_value() -> None:
    error = _one_error(_belt(mass_kg="3000 t"), "mass_kg")
    assert "less than or equal to 1000000" in error["msg"]
    assert "'3000 t' is 3e+06 kg" in error["msg"]


def test_wrong_dimension_message_says_what_the_field_wants() -> None:
    error = _one_error(_belt(pulley_diameter_mm="50 kg"), "pulley_diameter_mm")
    assert "must be a length" in error["msg"]
    assert "mm" in error["msg"]


@pytest.mark.parametrize(
    ("field", "value", "error_type"),
    [
        ("ratio", 0, "greater_than_equal"),
        ("ratio", 1e5, "less_than_equal"),
        ("ratio", "5", "float_type"),
        ("efficiency", 0, "greater_than_equal"),
        ("inertia_kgm2", "1 kg", "quantity_unit"),
        ("inertia_kgm2", -1, "greater_than_equal"),
    ],
)
def test_bad_transmission_values_name_their_field(field: str, value: Any, error_type: str) -> None:
    body = _belt(transmission={"ratio": 5, field: value})
    error = _one_error(body, f"transmission.{field}")
    assert error["type"] == error_type


def test_unknown_fields_are_errors() -> None:
    error = _one_error(_belt(lead_mm=10), "lead_mm")
    assert error["type"] == "extra_forbidden"


@pytest.mark.parametrize("kind", ["nope", "ball_screw", "", 3, None])
def test_unknown_type_names_the_allowed_ones(kind: object) -> None:
    errors = _errors({**_belt(), "type": kind})
    assert [e["type"] for e in errors] == ["mechanism_type"]
    for allowed in MECHANISM_TYPES:
        assert f"'{allowed}'" in errors[0]["msg"]


@pytest.mark.parametrize("kind", MECHANISM_TYPES)
def test_every_type_validates_its_minimal_body(kind: str) -> None:
    minimal: dict[str, dict[str, Any]] = {
        "ball_screw_incline": {
            "mass_kg": 20,
            "lead_mm": 10,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
        },
        "belt": {
            "mass_kg": 5,
            "pulley_diameter_mm": 50,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
        },
        "rack_pinion": {
            "mass_kg": 200,
            "pinion_diameter_mm": 80,
            "friction_coefficient": 0.05,
            "efficiency": 0.95,
        },
        "conveyor": {
            "load_mass_kg": 30,
            "belt_mass_kg": 10,
            "roller_diameter_mm": 100,
            "friction_coefficient": 0.2,
            "efficiency": 0.9,
        },
        "lift": {"load_mass_kg": 100, "drum_diameter_mm": 200, "efficiency": 0.9},
        "rotary": {"inertia_kgm2": 1.3},
    }
    load = Request.model_validate({"load": {"type": kind, **minimal[kind]}}).load
    axis = load.to_axis()
    assert axis.inertia_kgm2 > 0
    assert axis.speed_unit == ("rpm" if kind == "rotary" else "mm/s")
    # Every field but type and the minimal ones is optional.
    assert load.model_fields_set == {"type", *minimal[kind]}


# --- core errors under the request's names ---------------------------------------------------


def test_core_errors_are_renamed_to_the_request_fields() -> None:
    """Values past the schema (``model_construct``) reach the core, whose error names the
    request's field, in mm, under the path given."""
    belt = BeltIn.model_construct(**{**_belt(), "pulley_diameter_mm": -1.0})
    with pytest.raises(InvalidInputError) as caught:
        belt.to_axis(at="cases.3.load")
    assert caught.value.field == "cases.3.load.pulley_diameter_mm"

    geared = BeltIn.model_construct(
        **_belt(), transmission=TransmissionIn.model_construct(ratio=-2.0)
    )
    with pytest.raises(InvalidInputError) as caught:
        geared.to_axis()
    assert caught.value.field == "load.transmission.ratio"


# --- the quantity type against text of any kind ----------------------------------------------

_UNITISH = st.text(alphabet="0123456789.eE+-*/^()·² abcdfgiklmnorstuwµ°%_", max_size=24)


@settings(max_examples=300, deadline=None)
@given(text=st.one_of(st.text(max_size=80), _UNITISH))
def test_any_text_is_a_value_or_a_validation_error(text: str) -> None:
    """Whatever the text, a finite value within bounds or a ValidationError, never another
    exception (pint's parser raises many kinds) and never a hang."""
    try:
        belt = Request.model_validate({"load": _belt(pulley_diameter_mm=text)}).load
    except ValidationError as exc:
        (error,) = exc.errors()
        assert error["loc"][-1] == "pulley_diameter_mm"
    else:
        assert isinstance(belt, BeltIn)
        assert 1e-3 <= belt.pulley_diameter_mm <= 1e5


def test_exponent_towers_are_refused_at_once() -> None:
    """pint evaluates ``m^9^9^9`` with Python integers (9^387420489: no end). The text rule
    refuses chained exponents before pint sees them; in a subprocess, so that a regression
    fails here instead of hanging the run."""
    code = (
        "from actuator_selection.schemas.quantities import LENGTH_MM, to_unit\n"
        "from pydantic_core import PydanticCustomError\n"
        "for text in ['1 m^9^9^9', '1 m**9**9**9', '1 m⁹⁹⁹⁹', '1 (m^9)^9^9', '1 m²³²³²³']:\n"
        "    try:\n"
        "        to_unit(text, LENGTH_MM)\n"
        "    except PydanticCustomError as e:\n"
        "        assert e.type == 'quantity_text', (text, e.type)\n"
        "    else:\n"
        "        raise AssertionError(text)\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, timeout=60)


def test_json_schema_offers_a_number_with_its_bounds_or_text() -> None:
    schema = TypeAdapter(MechanismIn).json_schema()
    lead = schema["$defs"]["BallScrewInclineIn"]["properties"]["lead_mm"]
    number, text = lead["anyOf"]
    assert number == {"type": "number", "minimum": pytest.approx(1e-3), "maximum": 1e5}
    assert text["type"] == "string"
    assert "[mm" in lead["description"]
