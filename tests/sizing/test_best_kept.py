"""A block's best candidates picked one by one equal the full sort's first ones."""

from __future__ import annotations

import math

import numpy as np
import pytest

from actuator_selection.sizing.engine.evaluation import _best


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("keep", [1, 3, 8, 9])
def test_the_best_picked_one_by_one_are_the_sorts_first(seed: int, keep: int) -> None:
    """Ties everywhere (three verdicts, few overloads), ∞, cells left out by a case's
    models (code 3, with any overload: they come last, and every caller drops them), and
    as many actuators as are kept: the same columns kept as lexsort's, in its order."""
    rng = np.random.default_rng(seed)
    cases, actuators = 40, int(rng.choice([keep, 9, 64]))
    verdicts = rng.integers(0, 4 if seed % 2 else 3, (cases, actuators)).astype(np.int8)
    overload = np.where(
        verdicts == 2, rng.choice([1.0, 1.5, 2.0, math.inf], (cases, actuators)), 0.0
    )
    left_out = verdicts == 3  # such a cell keeps the overload it had
    overload[left_out] = rng.choice([0.0, 1.5, math.inf], int(left_out.sum()))
    position = rng.permutation(actuators).astype(np.int32)
    keep = min(keep, actuators)
    expected = np.lexsort((np.broadcast_to(position, verdicts.shape), overload, verdicts))
    best = _best(verdicts, overload, position, np.argsort(position), keep)

    def kept(order: np.ndarray) -> list[list[int]]:
        return [[j for j in row if verdicts[i, j] < 3] for i, row in enumerate(order.tolist())]

    assert kept(best) == kept(expected[:, :keep])
    assert (np.take_along_axis(verdicts, best, axis=1) == 3).sum() == (
        np.take_along_axis(verdicts, expected[:, :keep], axis=1) == 3
    ).sum()


def test_an_overload_of_nan_is_sorted_as_lexsort_sorts_it() -> None:
    verdicts = np.array([[2, 2, 2, 0]], dtype=np.int8)
    overload = np.array([[math.nan, math.inf, 1.0, 0.0]])
    position = np.array([0, 1, 2, 3], dtype=np.int32)
    assert _best(verdicts, overload, position, np.argsort(position), 4).tolist() == [[3, 2, 1, 0]]
