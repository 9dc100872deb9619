"""A linear axis's study cases built as columns (``sizing/linear_cases.py:
linear_cases``, what the service's ``columns_of`` gives for a screw's lead, a pinion's
or a belt pulley's diameter) against the cases of the applications a selection builds
at each value (``varied``, then ``cases_of``): every array the same, bit for bit, for
random screws, racks and belts (incline up and down, counterweight, efficiency 1 or
not, rotating inertia, an idler's diameter, friction force) and random values."""

from __future__ import annotations

from dataclasses import fields
from typing import Any

import numpy as np
import pytest

from actuator_selection.schemas.ratio import RatioStudyRequest
from actuator_selection.services.ratio import columns_of, varied
from actuator_selection.sizing.engine.cases import Cases, cases_of


def _arrays(cases: Cases) -> dict[str, Any]:
    """Every array of ``cases`` by name (those of its pieces and figures flattened)."""
    out: dict[str, Any] = {}
    for f in fields(Cases):
        value = getattr(cases, f.name)
        if hasattr(value, "__dataclass_fields__"):
            out |= {f"{f.name}.{g.name}": getattr(value, g.name) for g in fields(value)}
        else:
            out[f.name] = value
    return out


def _random_axis(rng: np.random.Generator, kind: str) -> dict[str, Any]:
    """A random screw, rack or belt on a random trapezoid, its study over its length."""

    def some(low: float, high: float) -> float:
        return float(10 ** rng.uniform(np.log10(low), np.log10(high)))

    def maybe(low: float, high: float) -> float:
        return float(rng.choice([0.0, some(low, high)]))

    common = {
        "mass_kg": some(0.1, 500),
        "friction_coefficient": maybe(0.001, 0.5),
        "efficiency": float(rng.choice([1.0, rng.uniform(0.3, 1.0)])),
        "incline_deg": float(rng.choice([0.0, 90.0, -90.0, rng.uniform(-90, 90)])),
        "counterweight_kg": maybe(0.1, 500),
        "friction_force_n": maybe(0.1, 500),
        "speed": some(1, 3000),
    }
    own: dict[str, Any] = {
        "ball_screw_incline": {"lead_mm": some(1, 100), "screw_inertia_kgm2": maybe(1e-6, 1e-2)},
        "rack_pinion": {"pinion_diameter_mm": some(10, 300), "pinion_inertia_kgm2": maybe(1e-6, 1)},
        "belt": {
            "pulley_diameter_mm": some(10, 300),
            "pulley_inertia_kgm2": maybe(1e-6, 1),
            "idler_inertia_kgm2": maybe(1e-6, 1),
            "belt_mass_kg": maybe(0.01, 10),
        }
        | ({"idler_diameter_mm": some(10, 300)} if rng.random() < 0.5 else {}),
    }[kind]
    return {
        "load": {"type": kind} | common | own,
        "cycle": {
            "accel_s": some(0.01, 2),
            "constant_s": maybe(0.01, 5),
            "decel_s": some(0.01, 2),
            "pause_s": maybe(0.01, 5),
        },
        "ratio_study": {"variable": VARIABLE[kind], "min": 1, "max": 1000},
    }


VARIABLE = {
    "ball_screw_incline": "lead_mm",
    "rack_pinion": "pinion_diameter_mm",
    "belt": "pulley_diameter_mm",
}


@pytest.mark.parametrize("kind", list(VARIABLE))
@pytest.mark.parametrize("seed", range(30))
def test_the_columns_are_the_cases_of_an_application_per_value(kind: str, seed: int) -> None:
    rng = np.random.default_rng(seed)
    request = RatioStudyRequest.model_validate(_random_axis(rng, kind))
    columns = columns_of(request, request.ratio_study)
    assert columns is not None
    vary = varied(request, request.ratio_study)
    values = np.concatenate(
        [10 ** rng.uniform(0, 4, 200), [1.0, 5.0, 10.0, 1000.0, 10_000.0, 2 * np.pi * 1000]]
    )
    built, each = _arrays(columns(values)), _arrays(cases_of([vary(float(x)) for x in values]))
    assert built.keys() == each.keys()
    for name, value in built.items():
        other = each[name]
        assert (value.dtype, value.shape) == (other.dtype, other.shape), name
        assert value.tobytes() == other.tobytes(), name  # bit for bit, signed zeros too


def test_a_screw_behind_a_transmission_is_built_value_by_value() -> None:
    """Where the mechanism has its own transmission the columns do not apply (None: the
    study builds an application per value)."""
    body = _random_axis(np.random.default_rng(0), "ball_screw_incline")
    body["load"]["transmission"] = {"ratio": 3.0}
    request = RatioStudyRequest.model_validate(body)
    assert columns_of(request, request.ratio_study) is None
