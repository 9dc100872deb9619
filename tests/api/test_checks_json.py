"""A large selection writes its candidates' checks as JSON text, rule by rule; the text is
the one orjson writes for the same checks as dicts, byte for byte."""

from __future__ import annotations

import dataclasses
import random

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from tests.oracle.test_engine_parity import (
    applications,
    boundary_actuators,
    catalogues,
    random_actuator,
    random_case,
)

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.services.presenters.selection import (
    _LISTED_UP_TO,
    CHECKS_AS_DICTS_UP_TO,
    RankedChecks,
    checks_as_dicts,
    checks_as_json,
    checks_of,
    dump_json,
)
from actuator_selection.sizing.checks import rules_for
from actuator_selection.sizing.engine import evaluate_batch
from actuator_selection.sizing.selection import Application


def assert_same_text(actuators: list[Actuator], app: Application) -> None:
    ev = evaluate_batch(actuators, [app], rules=rules_for(app))
    as_dicts = dump_json(checks_as_dicts(ev))
    assert dump_json(checks_as_json(ev)) == as_dicts
    assert dump_json(checks_of(ev)) == as_dicts


@pytest.mark.parametrize("seed", range(8))
def test_random_catalogues_write_the_same_text(seed: int) -> None:
    """Missing data (null, no_data with `missing`), zones (`approximate`), fails on a
    lower bound, limits met at equality; with and without a brake."""
    rng = random.Random(seed)
    actuators = [random_actuator(rng, k) for k in range(60)]
    apps = [random_case(rng, actuators) for _ in range(6)]
    actuators += boundary_actuators(apps)
    for app in apps:
        assert_same_text(actuators, app)
        assert_same_text(actuators, dataclasses.replace(app, brake=True))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(actuators=catalogues(), app=applications)
def test_any_catalogue_writes_the_same_text(actuators: list[Actuator], app: Application) -> None:
    assert_same_text(actuators, app)


def test_a_large_catalogue_takes_the_json_writer() -> None:
    rng = random.Random(5)
    actuators = [random_actuator(rng, k) for k in range(CHECKS_AS_DICTS_UP_TO + 1)]
    ev = evaluate_batch(actuators, [random_case(rng, actuators)])
    checks = checks_of(ev)
    assert all(not isinstance(c, list) for c in checks)  # orjson.Fragment, not dicts
    assert dump_json(checks) == dump_json(checks_as_dicts(ev))


@pytest.mark.parametrize("seed", range(4))
def test_a_few_candidates_checks_are_their_rows_of_many(seed: int) -> None:
    """A few candidates' checks (a one-model selection's) are read in Python, many with
    numpy: the same dicts, ``approximate`` and ``missing`` where they belong."""
    rng = random.Random(300 + seed)
    actuators = [random_actuator(rng, k) for k in range(60)]
    apps = [random_case(rng, actuators) for _ in range(4)]
    actuators += boundary_actuators(apps)
    seen = set()
    for app in apps:
        ev = evaluate_batch(actuators, [app], rules=rules_for(app))
        ranked = RankedChecks.of(ev, np.arange(len(actuators)))
        whole = ranked.dicts(0, len(actuators))
        assert ranked.first_missing.size > _LISTED_UP_TO  # the whole: numpy's reading
        for j in range(len(actuators)):
            assert ranked.dicts(j, j + 1) == whole[j : j + 1]
            assert dump_json(ranked.dicts(j, j + 1)) == dump_json(whole[j : j + 1])
        seen |= {key for row in whole for check in row for key in check}
    assert {"approximate", "missing"} <= seen
