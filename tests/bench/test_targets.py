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


def test_a_judged_measure_is_kept_for_the_run_summary(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    results = tmp_path / "results.jsonl"
    monkeypatch.setenv(targets.RESULTS, str(results))
    assert targets.BATCH_PER_CASE.judged(5.7, "numpy 204 ms") == "target ≤ 5×: not met"
    assert targets.BATCH_PER_CASE.judged(4.9, "numpy 190 ms") == "target ≤ 5×: met"
    assert targets.PAGE.judged(6.3) == "target ≤ 5×: not met"  # equal to BATCH_PER_CASE
    assert targets.PAGE_SLOWED.judged(2977.4, "bare page 582 ms") == "target ≤ 2500 ms: not met"
    rows = targets.summary(results.read_text(encoding="utf-8").splitlines())
    by_label = {row.split("  ")[0].strip(): row for row in rows}
    assert len(rows) == len(targets.declared())
    assert by_label["batch per case"].endswith(
        "5.7× (numpy 204 ms), 4.9× (numpy 190 ms); target ≤ 5×: met"
    )  # each measure of the run, the last one judged
    assert by_label["page"].endswith("6.3×; target ≤ 5×: not met")
    assert by_label["page slowed"].endswith(
        "2,977 ms (bare page 582 ms); target ≤ 2500 ms: not met"
    )
    assert by_label["whole catalogue"].endswith("not measured in this run")


def test_a_measure_is_judged_without_a_results_file(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv(targets.RESULTS, raising=False)
    monkeypatch.chdir(tmp_path)
    assert targets.SELECTION_6400.judged(5.3) == "target ≤ 20 ms: met"
    assert list(tmp_path.iterdir()) == []


def test_only_a_declared_target_is_kept_for_the_summary(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv(targets.RESULTS, str(tmp_path / "results.jsonl"))
    with pytest.raises(ValueError, match="not one of issue 32's targets"):
        targets.Target(5, "×").judged(4.0)  # equal to BATCH_PER_CASE, not it
    assert not (tmp_path / "results.jsonl").exists()
