"""A block's T_1, T_2, T_3 (``sizing.engine.block._extremes``): for each extreme the
signed torque of largest magnitude among the piece ends that count for it, the first of
equals, a NaN counting for none; 0, NaN, 0 where no end counts. Checked against that
definition written out end by end, for blocks below and above the size from which the
ends are taken one at a time (``_EACH_END_CELLS``), over several groups of pieces."""

from __future__ import annotations

import math

import numpy as np
import pytest

from actuator_selection.sizing.engine import block

DEFAULTS = (0.0, math.nan, 0.0)


def _by_definition(groups: list[tuple[np.ndarray, np.ndarray]]) -> np.ndarray:
    """T_1, T_2, T_3 (extremes × cases × actuators) over ``groups`` of (ends, counts)."""
    ends0 = groups[0][0]
    cases, actuators = ends0.shape[0], ends0.shape[2]
    out = np.empty((3, cases, actuators))
    for k in range(3):
        for i in range(cases):
            for j in range(actuators):
                best, size = DEFAULTS[k], -1.0
                for ends, counts in groups:
                    for e in range(ends.shape[1]):
                        torque = float(ends[i, e, j])
                        if counts[k, i, e, 0] and not math.isnan(torque) and abs(torque) > size:
                            best, size = torque, abs(torque)
                out[k, i, j] = best
    return out


@pytest.mark.parametrize(
    ("cases", "ends", "actuators", "groups", "one_at_a_time"),
    [
        (1, 4, 64, 1, False),  # a whole-catalogue selection
        (3, 8, 5, 2, False),
        (200, 4, 64, 1, True),  # a per-case batch's slice
        (70, 2, 64, 3, True),
        (100, 1, 64, 2, True),
    ],
)
def test_the_extremes_are_the_first_largest_counted_end(
    cases: int, ends: int, actuators: int, groups: int, one_at_a_time: bool
) -> None:
    assert (cases * actuators >= block._EACH_END_CELLS) is one_at_a_time
    rng = np.random.default_rng(cases * 100 + ends)
    values = [0.0, -0.0, 1.5, -1.5, 2.0, -2.0, math.nan, 7.25, -7.25]
    given = [
        (
            rng.choice(values, size=(cases, ends, actuators)),
            rng.random((3, cases, ends, 1)) < 0.5,
        )
        for _ in range(groups)
    ]
    found, found_abs = None, block._NO_EXTREME
    for group_ends, counts in given:
        found, found_abs = block._extremes(found, found_abs, group_ends, counts)
    expected = _by_definition(given)
    assert found is not None
    np.testing.assert_array_equal(found, expected)  # NaN where NaN
    assert (np.signbit(found) == np.signbit(expected)).all()  # −0 where the first is −0
