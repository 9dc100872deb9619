"""Lower bounds of an actuator's utilisation between the ratio study's grid values
(:mod:`~actuator_selection.sizing.ratio`), from the checks whose share is monotone in the
free value and from a bound of the peak torque: an actuator whose bound exceeds what the
listed ones reach is neither evaluated on the grid nor refined, and the answer is that of
the exhaustive study."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence

import numpy as np

from actuator_selection.sizing.checks import Operands, Rule
from actuator_selection.sizing.engine import CatalogueArrays, FloatArray, IndexArray
from actuator_selection.sizing.engine.block import operands_of
from actuator_selection.sizing.engine.cases import Cases, case_operands
from actuator_selection.sizing.engine.codes import ARRAY_OPS
from actuator_selection.sizing.ratio_search import REACH


def monotone_shares(
    rules: Sequence[Rule], monotone: Mapping[str, int], cases: Cases, cat: CatalogueArrays
) -> list[tuple[FloatArray, int]]:
    """The shares (value/limit; NaN where the limit is not positive) of the checks that
    ``monotone`` names, cases × actuators, each with its direction (+1: rising with the
    free value): the rule's own value and limit on the case's and the catalogue's
    operands, as the engine computes them (such a check reads no cell's quantity)."""
    chosen = [(rule, monotone[rule.name]) for rule in rules if rule.name in monotone]
    if not chosen:
        return []
    case = case_operands(cases)
    cell = {n: math.nan for n in Operands._fields if n not in case and n not in cat.operands}
    q = operands_of(case, cat.operands, cell)
    shape = (cases.size, cat.size)
    found = []
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for rule, direction in chosen:
            value = np.broadcast_to(rule.value(q, ARRAY_OPS), shape)
            limit = np.broadcast_to(rule.limit(q, ARRAY_OPS), shape)
            found.append((np.where(limit > 0, value / limit, np.nan), direction))
    return found


def interval_floors(shares: Sequence[tuple[FloatArray, int]]) -> FloatArray:
    """A lower bound of each actuator's utilisation between neighbouring grid values
    (intervals × actuators), from the checks whose share is monotone in the free value
    (``shares``: grid × actuators, each with its direction, +1 rising;
    :func:`monotone_shares`): between grid values k and k + 1 a rising share is at least
    its value at k, a falling one at k + 1, and the utilisation, the largest share, at
    least the larger. A share counts where it is finite at every grid value (the
    utilisation counts it there and between them).

    The bound of the analytic sizing methods (H.-J. Van de Straete et al. 1999;
    Giberti et al. 2011): the motor speed i·n_L rises with the ratio i and the reflected
    load inertia J_L/i² falls, against limits that depend on the actuator alone."""
    lower = np.full((shares[0][0].shape[0] - 1, shares[0][0].shape[1]), -np.inf)
    for share, direction in shares:
        bound = share[:-1] if direction > 0 else share[1:]
        counts = np.isfinite(share).all(axis=0)
        np.copyto(lower, bound, where=counts & (bound > lower))
    return lower


def peak_torque_floors(torque: FloatArray, cat: CatalogueArrays) -> FloatArray:
    """The ``peak_torque`` check's share |T_1|/T_max bounded from below between grid
    values (intervals × actuators), from a lower bound of |T_1| there (``torque``:
    :func:`~actuator_selection.sizing.ratio_cases.geared_torque_floor`, divided in
    place): a correctly rounded ÷ by T_max > 0 is monotone, so the bound's share is at
    most the engine's; NaN where there is none (no bound, T_max not positive). Where
    |T_1| overflows the engine counts no share, but the check fails there: no passing
    value is bounded wrongly."""
    limit = cat.operands["max_torque_nm"]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        share: FloatArray = np.divide(torque, np.where(limit > 0, limit, np.nan), out=torque)
    return share


def likeliest_index(shares: Sequence[tuple[FloatArray, int]], columns: IndexArray) -> IndexArray:
    """For each of the actuators ``columns``, the grid value (its index) where the
    largest of the ``shares`` is least: where it most likely passes."""
    least = np.full((shares[0][0].shape[0], columns.size), -np.inf)
    for share, _direction in shares:
        np.fmax(least, share[:, columns], out=least)
    found: IndexArray = np.argmin(least, axis=0)
    return found


FIRST = 2
"""A ranked study with floors (:func:`interval_floors`) evaluates the grid on the
``FIRST × top`` actuators of least floor first, then on twice as many each time: the
``top``-th best grid utilisation so far bounds the listed ones', and an actuator whose
floor exceeds it is not evaluated on the grid."""


def floor_about(floors: FloatArray, best_k: IndexArray) -> FloatArray:
    """A lower bound of each actuator's best utilisation after the parabolic steps: the
    least of its ``floors`` (:func:`interval_floors`) over the intervals within :data:`REACH`
    grid steps of its best grid value ``best_k``, where the refined value lies."""
    every = np.arange(best_k.size)
    last = floors.shape[0] - 1
    floor = floors[np.clip(best_k - REACH, 0, last), every]
    for step in range(1 - REACH, REACH):
        np.fmin(floor, floors[np.clip(best_k + step, 0, last), every], out=floor)
    return floor
