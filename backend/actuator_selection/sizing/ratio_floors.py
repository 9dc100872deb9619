"""Lower bounds of an actuator's utilisation between the ratio study's grid values
(:mod:`~actuator_selection.sizing.ratio`), from the checks whose share is monotone in the
free value and from a bound of the peak torque: an actuator whose bound exceeds what the
listed ones reach is neither evaluated on the grid nor refined, and the answer is that of
the exhaustive study."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence

import numpy as np

from actuator_selection.sizing.checks import Operands, Rule
from actuator_selection.sizing.engine import CatalogueArrays, FloatArray, IndexArray
from actuator_selection.sizing.engine.block import operands_of
from actuator_selection.sizing.engine.cases import Cases, case_operands
from actuator_selection.sizing.engine.codes import ARRAY_OPS
from actuator_selection.sizing.engine.pairs import catalogue_part
from actuator_selection.sizing.ratio_search import REACH

NON_NEGATIVE = (
    "gear_ratio",
    "motor_voltage_constant_v_per_krpm",
    "max_current_a",
    "resistance_line_ohm",
    "inductance_line_h",
    "pole_pairs",
)
"""The catalogue operands a share's monotony takes as ≥ 0 (``drive_voltage``'s, :data:`~
actuator_selection.sizing.ratio_cases.MONOTONE_SHARES`): an actuator with one of them
negative counts no monotone share (NaN), whatever the check."""


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
    q = _grid_operands(cases, cat)
    shape = (cases.size, cat.size)
    negative = np.zeros(cat.size, dtype=np.bool_)
    for name in NON_NEGATIVE:
        negative |= cat.operands[name] < 0
    found = []
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for rule, direction in chosen:
            value = np.broadcast_to(rule.value(q, ARRAY_OPS), shape)
            limit = np.broadcast_to(rule.limit(q, ARRAY_OPS), shape)
            counted = (limit > 0) & ~negative
            found.append((np.where(counted, value / limit, np.nan), direction))
    return found


def _grid_operands(cases: Cases, cat: CatalogueArrays) -> Operands:
    """The case's and the catalogue's operands at the grid's values, as the engine reads
    them; NaN for every quantity of a cell (the cycle's torques, a zone's edge)."""
    case = case_operands(cases)
    cell = {n: math.nan for n in Operands._fields if n not in case and n not in cat.operands}
    return operands_of(case, cat.operands, cell)


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


def continuous_floors(
    rms: FloatArray, rule: Rule, cases: Cases, cat: CatalogueArrays
) -> FloatArray:
    """The ``continuous_duty`` check's share T_rms/T_c bounded from below between grid
    values (intervals × actuators), from a lower bound of T_rms there (``rms``:
    :func:`~actuator_selection.sizing.ratio_cases.geared_rms_floor`, divided in place)
    and an upper bound of the continuous limit T_c: the larger of its values at the
    two grid values (``rule``'s own limit on the grid's operands, as the engine's).
    Without a zone T_c is monotone in the free value: T_0 or the allowable torque (a
    constant), or max(T_0 − k_T·K_INL·n_av, 0) with n_av = Σ|n̄_k|·t_k/t_0 monotone in
    the ratio as computed (each speed n_L·i, a correctly rounded × by a constant);
    with one (its edge at n_av, not monotone) no bound is claimed (NaN). Where T_c at a
    value between is not positive the engine counts no share: a passing value there has
    T_rms = 0, at most the bound's 0."""
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        limit = np.broadcast_to(
            rule.limit(_grid_operands(cases, cat), ARRAY_OPS), (cases.size, cat.size)
        )
        upper = np.maximum(limit[:-1], limit[1:])  # NaN where either is
        upper = np.where((upper > 0) & np.logical_not(cat.operands["has_zone"]), upper, np.nan)
        share: FloatArray = np.divide(rms, upper, out=rms)
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


COARSE = 8
"""A ranked study's floors over the range are first bounded on every ``COARSE``-th grid
value for the whole catalogue (:meth:`Floors.between`; a bound between any two grid
values holds between any pair of values in it), then between neighbouring values for
the actuators that bound leaves in the running, inside the coarse intervals where it
does (:meth:`Floors.within`): at 6,400 actuators ~2 ms where the floors between
neighbours cost ~12 ms (ratio 0.05–2000)."""

FINE_CELLS = 100_000
"""Up to this many grid values × actuators (~2,000 actuators) the floors are computed
between neighbouring values at once: the coarse ones' ordering and the second pass
cost more than they spare."""

Bound = Callable[[FloatArray, FloatArray], FloatArray]
"""A bound between neighbouring values (``geared_torque_floor``, ``geared_rms_floor``),
given the values and the actuators' J_A."""


class Floors:
    """Lower bounds of the actuators' utilisation between grid values, computed where
    asked: the monotone checks' (:func:`interval_floors`), raised by the ``peak_torque``
    check's (:func:`peak_torque_floors`, with ``torque``) and the ``continuous_duty``
    check's (:func:`continuous_floors`, with ``rms``)."""

    def __init__(
        self,
        rules: Sequence[Rule],
        monotone: Mapping[str, int],
        cases: Cases,
        grid: FloatArray,
        cat: CatalogueArrays,
        torque: Bound | None,
        rms: Bound | None,
    ) -> None:
        self.rules, self.monotone, self.cases, self.grid, self.cat = (
            rules,
            monotone,
            cases,
            grid,
            cat,
        )
        names = [rule.name for rule in rules]
        self.torque = torque if "peak_torque" in names else None
        self.continuous = None if rms is None or "continuous_duty" not in names else rms
        self.continuous_rule = rules[names.index("continuous_duty")] if self.continuous else None

    def coarse(self) -> IndexArray:
        """Every :data:`COARSE`-th grid value's index, the last one too; every one where
        the grid × the catalogue is at most :data:`FINE_CELLS`."""
        last = self.grid.size - 1
        step = 1 if self.grid.size * self.cat.size <= FINE_CELLS else COARSE
        rows: IndexArray = np.unique(np.append(np.arange(0, last, step), last))
        return rows

    def between(
        self, rows: IndexArray | None, part: IndexArray | None
    ) -> tuple[FloatArray, list[tuple[FloatArray, int]]]:
        """The floors between neighbouring values of the grid's ``rows`` (ascending;
        None: all) for the actuators ``part`` (ascending; None: all), intervals × them,
        and the monotone shares at those values."""
        cat = self.cat if part is None else catalogue_part(self.cat, part)
        cases = self.cases if rows is None else self.cases.take(rows)
        values = self.grid if rows is None else self.grid[rows]
        shares = monotone_shares(self.rules, self.monotone, cases, cat)
        floors = interval_floors(shares)
        if self.torque is not None:  # fmax: a NaN (no bound) leaves the floor as it is
            np.fmax(floors, peak_torque_floors(self.torque(values, cat.inertia), cat), out=floors)
        if self.continuous is not None and self.continuous_rule is not None:
            rms = self.continuous(values, cat.inertia)
            np.fmax(floors, continuous_floors(rms, self.continuous_rule, cases, cat), out=floors)
        return floors, shares

    def within(
        self, coarse: IndexArray, bounds: FloatArray, part: IndexArray, bar: float
    ) -> FloatArray:
        """A lower bound of the utilisation of the actuators ``part`` (ascending) over
        the range, from ``bounds`` between the ``coarse`` grid values (:meth:`between`)
        and, inside each coarse interval where that bound is at most ``bar``, the
        floors between neighbouring values there: the least over the intervals of the
        larger of the two, the coarse bound alone where it exceeds ``bar``."""
        least = np.full(part.size, np.inf)
        for c in range(coarse.size - 1):
            bound = bounds[c, part]
            near = np.flatnonzero(bound <= bar)
            if near.size:  # both are bounds there: the larger
                rows = np.arange(coarse[c], coarse[c + 1] + 1)
                fine = self.between(rows, part[near])[0].min(axis=0)
                bound[near] = np.maximum(bound[near], fine)
            np.minimum(least, bound, out=least)
        return least

    def about(self, best_k: IndexArray, part: IndexArray) -> FloatArray:
        """:func:`floor_about` of the actuators ``part`` (ascending), their best grid
        values ``best_k``: the floors computed on the band of grid values their
        intervals about them span, no wider."""
        last = self.grid.size - 2  # the last interval
        low = max(int(best_k.min()) - REACH, 0)
        high = min(int(best_k.max()) + REACH - 1, last)
        floors = self.between(np.arange(low, high + 2), part)[0]
        return floor_about(floors, best_k - low)
