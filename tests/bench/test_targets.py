"""The benches' targets (``bench/targets.py``): a bound judged as the issue states it."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from bench import targets


@pytest.mark.parametrize(
    ("target", "measured", "met"),
    [
        (targets.WHOLE_CATALOGUE, 0.7, True),  # "≥ 0.7×": the bound itself is met
        (targets.WHOLE_CATALOGUE, 0.69, False),
        (targets.ONE_MODEL, 0.95, True),
        (targets.BATCH_PER_CASE, 5.0, True),  # "≤ 5×"
        (targets.BATCH_PER_CASE, 5.1, False),
        (targets.SELECTION_64000, 48.7, True),
        (targets.PAGE_SLOWED, 3397.0, False),
        (targets.PEAK_RSS_64000, math.nan, False),  # a figure not measured is not met
        (targets.WHOLE_CATALOGUE, math.nan, False),
    ],
)
def test_a_bound_is_met_as_the_issue_states_it(
    target: targets.Target, measured: float, met: bool
) -> None:
    assert target.met(measured) is met
    assert target.verdict(measured).endswith(": met" if met else ": not met")


def test_the_verdict_names_the_bound_and_its_unit() -> None:
    assert targets.WHOLE_CATALOGUE.verdict(0.42) == "target ≥ 0.7×: not met"
    assert targets.SELECTION_6400.verdict(5.3) == "target ≤ 20 ms: met"
    assert targets.RELOAD_64000.verdict(0.08) == "target ≤ 1 s: met"
