"""What binds when nothing fits (``binding.checks``), read from the ranking's arrays, against
the candidates' checks read one by one as the answer lists them (the first way it was
computed, kept here as the oracle): random rankings with failing, passing and missing
checks, NaN values and limits, zero limits and ties."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

from actuator_selection.services.presenters.selection import RankedChecks, binding_checks
from actuator_selection.sizing.engine import STATUS_BY_CODE

NAMES = ("peak_torque", "decel_torque", "max_speed", "inertia_ratio", "continuous_duty")


def oracle(models: list[str], checks: RankedChecks) -> list[dict[str, Any]]:
    """Each candidate's checks as dicts, each failing one's value/limit (∞ without a value
    or a non-zero limit), the least per check, the first on a tie."""
    failing: dict[str, list[tuple[float, dict[str, Any], str]]] = {}
    for model, checks_ in zip(models, checks.dicts(0, len(models)), strict=True):
        for check in checks_:
            if check["status"] != "fail":
                continue
            value, limit = check["value"], check["limit"]
            ratio = value / limit if value is not None and limit else math.inf
            failing.setdefault(check["name"], []).append((ratio, check, model))
    kinds = []
    for name, misses in failing.items():
        _, nearest, model = min(misses, key=lambda miss: miss[0])
        kinds.append(
            {
                "name": name,
                "failing": len(misses),
                "value": nearest["value"],
                "limit": nearest["limit"],
                "model": model,
            }
        )
    kinds.sort(key=lambda kind: -kind["failing"])
    return kinds


def ranking(rng: np.random.Generator, n: int) -> RankedChecks:
    shape = (n, len(NAMES))
    statuses = rng.integers(0, len(STATUS_BY_CODE), size=shape, dtype=np.int8)
    # few distinct values, so that ties are common; NaN and zero limits among them
    values = rng.choice([0.5, 1.0, 2.0, 3.0, math.nan], size=shape)
    limits = rng.choice([1.0, 2.0, 0.0, -1.0, math.nan], size=shape)
    return RankedChecks(
        names=NAMES,
        missing_what=[("J_A",)] * len(NAMES),
        statuses=statuses,
        values=values,
        limits=limits,
        approximate=np.zeros(shape, dtype=np.bool_),
        first_missing=np.where(statuses == STATUS_BY_CODE.index("no_data"), 0, -1).astype(np.int8),
    )


@pytest.mark.parametrize("seed", range(40))
def test_binding_checks_equal_the_checks_read_one_by_one(seed: int) -> None:
    rng = np.random.default_rng(seed)
    n = int(rng.integers(1, 60))
    checks = ranking(rng, n)
    models = [f"M-{j}" for j in range(n)]
    assert binding_checks(models, checks) == oracle(models, checks)


def test_a_tie_names_the_first_in_the_ranking() -> None:
    checks = ranking(np.random.default_rng(0), 3)
    checks.statuses[:] = STATUS_BY_CODE.index("pass")
    checks.statuses[:, 0] = STATUS_BY_CODE.index("fail")
    checks.values[:, 0], checks.limits[:, 0] = 2.0, 1.0
    found = binding_checks(["first", "second", "third"], checks)
    assert found == [
        {"name": "peak_torque", "failing": 3, "value": 2.0, "limit": 1.0, "model": "first"}
    ]
