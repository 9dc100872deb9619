"""The lead study's cases built as columns (``sizing/lead_cases.py: screw_cases``, what
the service's ``columns_of`` gives for a screw's lead) against the cases of the
applications a selection builds at each lead (``varied``, then ``cases_of``): every
array the same, bit for bit, for random screws (incline up and down, counterweight,
efficiency 1 or not, screw inertia, friction force) and random leads."""

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


def _random_screw(rng: np.random.Generator) -> dict[str, Any]:
    def some(low: float, high: float) -> float:
        return float(10 ** rng.uniform(np.log10(low), np.log10(high)))

    return {
        "load": {
            "type": "ball_screw_incline",
            "mass_kg": some(0.1, 500),
            "lead_mm": some(1, 100),
            "friction_coefficient": float(rng.choice([0.0, some(0.001, 0.5)])),
            "efficiency": float(rng.choice([1.0, rng.uniform(0.3, 1.0)])),
            "incline_deg": float(rng.choice([0.0, 90.0, -90.0, rng.uniform(-90, 90)])),
            "screw_inertia_kgm2": float(rng.choice([0.0, some(1e-6, 1e-2)])),
            "counterweight_kg": float(rng.choice([0.0, some(0.1, 500)])),
            "friction_force_n": float(rng.choice([0.0, some(0.1, 500)])),
            "speed": some(1, 3000),
        },
        "cycle": {
            "accel_s": some(0.01, 2),
            "constant_s": float(rng.choice([0.0, some(0.01, 5)])),
            "decel_s": some(0.01, 2),
            "pause_s": float(rng.choice([0.0, some(0.01, 5)])),
        },
        "ratio_study": {"variable": "lead_mm", "min": 1, "max": 1000},
    }


@pytest.mark.parametrize("seed", range(40))
def test_the_lead_s_columns_are_the_cases_of_an_application_per_lead(seed: int) -> None:
    rng = np.random.default_rng(seed)
    request = RatioStudyRequest.model_validate(_random_screw(rng))
    columns = columns_of(request, request.ratio_study)
    assert columns is not None
    vary = varied(request, request.ratio_study)
    leads = np.concatenate(
        [10 ** rng.uniform(0, 4, 200), [1.0, 5.0, 10.0, 1000.0, 10_000.0, 2 * np.pi * 1000]]
    )
    built, each = _arrays(columns(leads)), _arrays(cases_of([vary(float(x)) for x in leads]))
    assert built.keys() == each.keys()
    for name, value in built.items():
        other = each[name]
        assert (value.dtype, value.shape) == (other.dtype, other.shape), name
        assert value.tobytes() == other.tobytes(), name  # bit for bit, signed zeros too


def test_a_screw_behind_a_transmission_is_built_value_by_value() -> None:
    """Where the mechanism has its own transmission the columns do not apply (None: the
    study builds an application per value)."""
    body = _random_screw(np.random.default_rng(0))
    body["load"]["transmission"] = {"ratio": 3.0}
    request = RatioStudyRequest.model_validate(body)
    assert columns_of(request, request.ratio_study) is None
