"""The ratio study (issue 31 part 1): for every actuator of the catalogue, the interval(s)
of a free transmission value (an external gear ratio i, a screw lead, a pulley or pinion
diameter) for which no check fails, and the value that minimises the binding utilisation.

The free value enters as the load case does today: ``vary(x)`` builds the application at
``x`` through the mechanisms' own reflection (:func:`~actuator_selection.sizing.mechanisms.
with_transmission` for a ratio: speed ×i, torque ÷i, inertia ÷i² plus J_tr, η by the power
flow; the mechanism's own lead or diameter otherwise), so the study and a selection at
that value are the same flowchart on the same numbers.

The search runs on the engine, vectorised over cases × actuators:

1. a geometric grid of the range (or the standard series given) as the cases, the whole
   catalogue as the columns, block by block (:func:`~actuator_selection.sizing.engine.
   block.evaluate_block`), keeping per cell only the verdict, the binding utilisation
   and which checks fail, no check worded;
2. every change of the verdict between neighbouring grid values, for every actuator, is
   a bracket; all brackets are bisected together, on the engine's pairs
   (:func:`~actuator_selection.sizing.engine.pairs.evaluate_pairs`: each bracket's midpoint
   on its own actuator, not every midpoint on every actuator), several halvings to an
   engine call where the pairs are few, one where they are many (:data:`MANY_PAIRS`),
   so several intervals per actuator are found where the checks are not monotonic;
3. the grid value of least binding utilisation (max value/limit over the checks,
   :func:`~actuator_selection.sizing.checks.rule.utilisation`) is refined by parabolic
   steps in log x (a passing value only, and only where it lowers the utilisation), all
   actuators together, in the same engine calls as the bisection.

A pair whose value is a grid value or the actuator's best value so far is read from
that cell, not asked again. :func:`ranked_ratio_study` (the API's answer) refines the
best value of every actuator that can be listed (its ranking reads them) and bisects only
the listed actuators' brackets. Where the free value makes some checks' shares monotone
(an external ratio: the speed i·n_L rises, the reflected inertia J_L/i² falls; the
bounds of Van de Straete et al. and Giberti et al. below), those shares bound each
actuator's utilisation from below between grid values (:func:`_floors`): over the range,
an actuator whose bound exceeds the ``top``-th best grid utilisation found cannot be
listed and is not evaluated on the grid (only whether it fits somewhere, asked first
where it most likely does: :func:`_likeliest`); about its best grid value
(:func:`_floor_about`), one whose bound exceeds it is not refined.

The numbers are those of evaluating every value on every actuator
(``tests/oracle/ratio_exhaustive.py``, the study as first written, which the tests
compare with this one, ``==``): only fewer cells are computed. Where the caller can build
the load cases at many values as columns (:func:`~actuator_selection.sizing.ratio_cases.
geared_cases`: an external ratio on the chapter's trapezoid, any η_tr), no application is
built per value.

Analytic cross-check (H.-J. Van de Straete, J. De Schutter, R. Belmans, "An efficient procedure for
checking performance limits in servo drive selection and optimization", IEEE/ASME Trans.
Mechatronics 4(4), 1999, pp. 378–386; Giberti, Cinquemani, Legnani, "A practical approach
to the selection of the motor-reducer unit in electric drive systems", Mech. Based Des.
Struct. Mach. 39(3), 2011, pp. 303–319): for a pure inertia load J_L driven at the load
acceleration ε_L through a ratio i, the motor-side torque is T(i) = (J_A·i + J_L/i)·ε_L,
minimal at i* = √(J_L/J_A) (Giberti's "optimal transmission ratio"); the peak-torque
condition T(i) ≤ T_max bounds i to the roots of J_A·ε_L·i² − T_max·i + J_L·ε_L = 0.
:func:`inertia_matched_ratio` gives i*; the tests check the numeric search against both.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Generator, Mapping, Sequence
from dataclasses import dataclass
from typing import cast

import numpy as np

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.candidates import Verdict
from actuator_selection.sizing.checks import Operands, Rule, Status
from actuator_selection.sizing.engine import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BoolArray,
    CatalogueArrays,
    CodeArray,
    FloatArray,
    IndexArray,
    catalogue_arrays,
)
from actuator_selection.sizing.engine.block import Block, blocks, evaluate_block, operands_of
from actuator_selection.sizing.engine.cases import (
    Cases,
    ZoneTable,
    case_operands,
    cases_of,
    zone_limits,
    zone_table,
)
from actuator_selection.sizing.engine.codes import ARRAY_OPS
from actuator_selection.sizing.engine.evaluation import rules_of
from actuator_selection.sizing.engine.pairs import catalogue_part, evaluate_pairs

GRID_POINTS = 48
"""Grid values over the range (geometric): neighbours 6.5 % apart over 1–20."""
BISECTION_STEPS = 12
"""Halvings of every bracket: a grid step of 6.5 % narrowed to 1.6·10⁻⁵ relative."""
BISECTION_DEPTH = 2
"""Halvings per engine call (:func:`_bisection`) where the pairs are few: 3 values a
bracket, 6 calls, the parabolic steps' beside them, each asked ahead for both outcomes
(:func:`_refinement`); fewer calls, each paying the engine's fixed cost once."""
FEWEST_DEPTH = 3
"""Halvings per engine call where the pairs are fewer than :data:`FEW_PAIRS` and the
load cases come as columns (no application built per value): 7 values a bracket, 4
calls."""
FEW_PAIRS = 2_000
MANY_PAIRS = 20_000
"""From how many pairs saved one halving per call (12 calls, 1 value a bracket) and the
parabolic steps not asked ahead (3 values a step fewer) cost less than the 6 calls more:
a call's fixed cost is that of some thousand pairs (``python -m bench.ratio``)."""
REFINE_ROUNDS = 3
"""Parabolic steps for the best value (one engine call each, after the first, beside the
bisection's)."""
MAX_SERIES = 200
"""The most values of a standard series."""

_FAIL = VERDICT_BY_CODE.index(Verdict.UNSUITABLE)
_CHECK_FAIL = STATUS_BY_CODE.index(Status.FAIL)
_CODE_FAIL = np.int8(_CHECK_FAIL)


def inertia_matched_ratio(load_inertia_kgm2: float, actuator_inertia_kgm2: float) -> float:
    """i* = √(J_L/J_A): the ratio of least peak torque for a pure inertia load, the inertia
    match (Giberti et al. 2011; Van de Straete et al. 1999).

    >>> inertia_matched_ratio(0.5, 0.02)
    5.0
    """
    return math.sqrt(load_inertia_kgm2 / actuator_inertia_kgm2)


@dataclass(frozen=True, slots=True, kw_only=True)
class Interval:
    """A range of the free value in which no check fails."""

    low: float
    high: float
    low_binding: tuple[str, ...]
    """The checks that fail just below ``low``; empty where ``low`` is the range's end."""
    high_binding: tuple[str, ...]
    """The checks that fail just above ``high``; empty where ``high`` is the range's end."""


@dataclass(frozen=True, slots=True, kw_only=True)
class RatioResult:
    """One actuator's answer."""

    actuator: Actuator
    intervals: tuple[Interval, ...]
    best: float | None
    """The value of least binding utilisation where no check fails; None: no interval."""
    best_utilisation: float | None
    best_binding: str | None
    """The check whose utilisation is the largest at ``best``."""
    verdict: Verdict | None
    """The flowchart's verdict at ``best`` (``unconfirmed``: a check lacks data)."""
    grid: tuple[float, ...]
    utilisation: tuple[float | None, ...]
    """The binding utilisation at each grid value (for the chart)."""


Cells = tuple[CodeArray, FloatArray, IndexArray, BoolArray]
"""Per cell: the verdict code, the binding utilisation (max value/limit over the checks
with both; NaN where none has), its check's index, and which checks fail (cells ×
checks)."""


def _cells(block: Block) -> Cells:
    """What the search reads of a block (run with ``detail``), its cells flattened in
    order; the status codes and each check's value and limit, no check worded."""
    assert block.details is not None
    shape = block.accel_torque.shape
    best = np.full(shape, -np.inf)
    which = np.zeros(shape, dtype=np.intp)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        for k, d in enumerate(block.details):
            share = d.values / d.limits  # a share where the limit is positive and it finite
            take = (d.limits > 0) & np.isfinite(share) & (share > best)
            np.copyto(best, share, where=take)  # the first check of the largest, as argmax
            np.copyto(which, k, where=take)
    util = np.where(np.isfinite(best), best, np.nan)
    failing = np.empty((*shape, len(block.statuses)), dtype=np.bool_)
    for k, codes in enumerate(block.statuses):
        np.equal(codes, _CODE_FAIL, out=failing[..., k])
    return (
        block.verdicts().ravel(),
        util.ravel(),
        which.ravel(),
        failing.reshape(-1, len(block.statuses)),
    )


Request = tuple[FloatArray, IndexArray]
"""Pairs to evaluate: the free value and the actuator's column, pair by pair."""
Search = Generator[Request, Cells, None]


class _Pairs:
    """The engine on pairs (value, actuator): the distinct values as the cases, each pair
    its own cell (:func:`~actuator_selection.sizing.engine.pairs.evaluate_pairs`); a pair
    whose value is a grid value (a parabolic step's about the best grid value, its
    neighbours) read from the grid's cells, the same numbers."""

    def __init__(
        self,
        cat: CatalogueArrays,
        zones: ZoneTable,
        cases_at: Callable[[FloatArray], Cases],
        rules: Sequence[Rule],
        grid: FloatArray,
        cells: Cells,
    ) -> None:
        self.cat, self.zones, self.cases_at, self.rules = cat, zones, cases_at, rules
        self.grid, self.cells = grid, cells  # the grid's, grid × actuators (cells raveled)

    def __call__(self, values: FloatArray, columns: IndexArray) -> Cells:
        k = np.minimum(np.searchsorted(self.grid, values), self.grid.size - 1)
        on_grid = self.grid[k] == values
        if not on_grid.any():
            return self.evaluated(values, columns)
        width = self.cells[0].size // self.grid.size
        at = k[on_grid] * width + columns[on_grid]
        off = ~on_grid
        found = self.evaluated(values[off], columns[off]) if off.any() else None
        out = []
        grid_parts: tuple[np.ndarray, ...] = self.cells
        for n, grid_part in enumerate(grid_parts):
            part = np.empty((values.size, *grid_part.shape[1:]), dtype=grid_part.dtype)
            part[on_grid] = grid_part[at]
            if found is not None:
                part[off] = found[n]
            out.append(part)
        return cast(Cells, tuple(out))

    def evaluated(self, values: FloatArray, columns: IndexArray) -> Cells:
        """The cells of the pairs, each evaluated (none read from the grid's)."""
        xs, rows = np.unique(values, return_inverse=True)
        cases = self.cases_at(xs)
        block = evaluate_pairs(
            self.cat, self.zones, cases, rows, columns, self.rules, overload=False
        )
        return _cells(block)

    def run(self, *searches: Search) -> None:
        """Run ``searches`` side by side: each engine call evaluates the pairs that every
        search still running asks for, in one block."""
        asked: dict[int, Request] = {}
        running = dict(enumerate(searches))
        for n, search in list(running.items()):
            request = next(search, None)
            if request is None:
                del running[n]
            else:
                asked[n] = request
        while running:
            order = list(running)
            sizes = [asked[n][0].size for n in order]
            answer = self(
                np.concatenate([asked[n][0] for n in order]),
                np.concatenate([asked[n][1] for n in order]),
            )
            at = 0
            for n, size in zip(order, sizes, strict=True):
                part = cast(Cells, tuple(a[at : at + size] for a in answer))
                at += size
                try:
                    asked[n] = running[n].send(part)
                except StopIteration:
                    del running[n], asked[n]


def _bisection(
    ok_side: FloatArray,
    bad_side: FloatArray,
    columns: IndexArray,
    bad_fail: BoolArray,
    depth: int,
) -> Search:
    """:data:`BISECTION_STEPS` halvings of every bracket (ok value, failing value) in
    log x, in rounds of ``depth``: each round evaluates the midpoints of
    every interval the round's halvings could reach (a tree of 2^depth − 1 values per
    bracket, each the geometric mean of its interval's ends, as one halving computes
    it) and then follows each bracket's halvings through it. The arrays are updated in
    place: the last ok value, the first failing one, and the checks failing there."""
    width = 2**depth - 1
    for _ in range(BISECTION_STEPS // depth):
        low = np.empty((ok_side.size, width))
        high = np.empty((ok_side.size, width))
        middle = np.empty((ok_side.size, width))
        low[:, 0], high[:, 0] = ok_side, bad_side
        for k in range(width):
            middle[:, k] = np.sqrt(low[:, k] * high[:, k])
            left, right = 2 * k + 1, 2 * k + 2
            if right < width:  # left: the middle failed; right: it passed
                low[:, left], high[:, left] = low[:, k], middle[:, k]
                low[:, right], high[:, right] = middle[:, k], high[:, k]
        codes, _u, _w, failing = yield middle.ravel(), np.repeat(columns, width)
        codes = codes.reshape(middle.shape)
        failing = failing.reshape((*middle.shape, -1))
        node: IndexArray = np.zeros(ok_side.size, dtype=np.intp)
        every = np.arange(ok_side.size)
        for _step in range(depth):
            m = middle[every, node]
            fails = codes[every, node] == _FAIL
            ok_side[:] = np.where(fails, ok_side, m)
            bad_side[:] = np.where(fails, m, bad_side)
            bad_fail[:] = np.where(fails[:, None], failing[every, node], bad_fail)
            node = np.where(fails, 2 * node + 1, 2 * node + 2)


@dataclass(slots=True, kw_only=True)
class _Best:
    """Per actuator, the value of least binding utilisation found so far, updated in place."""

    value: FloatArray
    utilisation: FloatArray
    code: CodeArray
    which: IndexArray


def _asked(
    best: _Best, values: FloatArray, columns: IndexArray
) -> Generator[Request, Cells, Cells]:
    """The cells of the pairs (``values``, ``columns``), those at an actuator's best value
    so far (the middle of a step about it, a vertex that does not move) taken from the
    best's, the same numbers, the rest asked; the failing checks are not read (False)."""
    known = values == best.value[columns]
    if not known.any():
        return (yield values, columns)
    codes, utilisation = best.code[columns], best.utilisation[columns]
    which, failing = best.which[columns], np.zeros((values.size, 0), dtype=np.bool_)
    ask = ~known
    if ask.any():
        asked = yield values[ask], columns[ask]
        codes[ask], utilisation[ask], which[ask] = asked[0], asked[1], asked[2]
    return codes, utilisation, which, failing


def _refinement(best: _Best, columns: IndexArray, grid: FloatArray, ahead: bool) -> Search:
    """:data:`REFINE_ROUNDS` parabolic steps in log x about each best value: a parabola
    through the best and its neighbours, its vertex evaluated; each round about the best
    so far, a quarter as wide.

    ``ahead``: the next round's three values are asked with the vertex, for both outcomes
    (about the vertex, should it be better; about the best so far, should it not), so
    that the rounds take one engine call each, not two, for twice the values."""
    step = math.log(grid[1] / grid[0])

    def about(centre: FloatArray, half: FloatArray) -> FloatArray:
        values: FloatArray = np.exp(centre[:, None] + half[:, None] * np.array([-1.0, 0.0, 1.0]))
        return values

    def vertex_of(centre: FloatArray, half: FloatArray, u: FloatArray) -> FloatArray:
        left, mid, right = u[:, 0], u[:, 1], u[:, 2]
        with np.errstate(divide="ignore", invalid="ignore"):
            shift = 0.5 * half * (left - right) / (left - 2 * mid + right)
        convex = np.isfinite(shift) & (left - 2 * mid + right > 0)
        vertex = np.exp(centre + np.where(convex, np.clip(shift, -half, half), 0.0))
        return np.asarray(np.clip(vertex, grid[0], grid[-1]))  # within the range searched

    n = columns.size
    centre, half = np.log(best.value[columns]), np.full(n, step)
    points = about(centre, half)
    u = (yield from _asked(best, points.ravel(), np.repeat(columns, 3)))[1].reshape(points.shape)
    for r in range(REFINE_ROUNDS):
        vertex = vertex_of(centre, half, u)
        last = r + 1 == REFINE_ROUNDS
        values, asked = [vertex], [columns]
        if not last and ahead:  # the next round about either centre
            moved, stayed = about(np.log(vertex), half / 4), about(centre, half / 4)
            values += [moved.ravel(), stayed.ravel()]
            asked += [np.repeat(columns, 3)] * 2
        codes, got, w, _f = yield from _asked(best, np.concatenate(values), np.concatenate(asked))
        at_vertex = got[:n]
        better = (
            (codes[:n] != _FAIL) & np.isfinite(at_vertex) & (at_vertex < best.utilisation[columns])
        )
        chosen = columns[better]
        best.value[chosen] = vertex[better]
        best.utilisation[chosen] = at_vertex[better]
        best.code[chosen] = codes[:n][better]
        best.which[chosen] = w[:n][better]
        if last:
            break
        if ahead:
            u = np.where(better[:, None], got[n : 4 * n].reshape(n, 3), got[4 * n :].reshape(n, 3))
        centre, half = np.log(best.value[columns]), half / 4
        if not ahead:
            points = about(centre, half)
            u = (yield from _asked(best, points.ravel(), np.repeat(columns, 3)))[1].reshape(
                points.shape
            )


def _monotone_shares(
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


def _floors(shares: Sequence[tuple[FloatArray, int]]) -> FloatArray:
    """A lower bound of each actuator's utilisation between neighbouring grid values
    (intervals × actuators), from the checks whose share is monotone in the free value
    (``shares``: grid × actuators, each with its direction, +1 rising;
    :func:`_monotone_shares`): between grid values k and k + 1 a rising share is at least
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


def _peak_torque_floors(torque: FloatArray, cat: CatalogueArrays) -> FloatArray:
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


def _likeliest(shares: Sequence[tuple[FloatArray, int]], columns: IndexArray) -> IndexArray:
    """For each of the actuators ``columns``, the grid value (its index) where the
    largest of the ``shares`` is least: where it most likely passes."""
    least = np.full((shares[0][0].shape[0], columns.size), -np.inf)
    for share, _direction in shares:
        np.fmax(least, share[:, columns], out=least)
    found: IndexArray = np.argmin(least, axis=0)
    return found


FIRST = 2
"""A ranked study with floors (:func:`_floors`) evaluates the grid on the
``FIRST × top`` actuators of least floor first, then on twice as many each time: the
``top``-th best grid utilisation so far bounds the listed ones', and an actuator whose
floor exceeds it is not evaluated on the grid."""

REACH = 2
"""Grid steps the parabolic steps can move a best value (:func:`_refinement`): at most
1 + 1/4 + 1/16 + … < 4/3 of a step, whatever :data:`REFINE_ROUNDS`."""


def _floor_about(floors: FloatArray, best_k: IndexArray) -> FloatArray:
    """A lower bound of each actuator's best utilisation after the parabolic steps: the
    least of its ``floors`` (:func:`_floors`) over the intervals within :data:`REACH`
    grid steps of its best grid value ``best_k``, where the refined value lies."""
    every = np.arange(best_k.size)
    last = floors.shape[0] - 1
    floor = floors[np.clip(best_k - REACH, 0, last), every]
    for step in range(1 - REACH, REACH):
        np.fmin(floor, floors[np.clip(best_k + step, 0, last), every], out=floor)
    return floor


GUESSED = 2
"""A ranked study bisects, beside the parabolic steps, the ends of the first
``GUESSED × top`` actuators by their best grid value; the listed ones the steps move up
from further down are bisected after."""


def _depth(pairs: int, as_columns: bool) -> int:
    """Halvings per engine call for a search of about ``pairs`` pairs: few pairs, fewer
    calls; many, fewer pairs."""
    if pairs >= MANY_PAIRS:
        return 1
    return FEWEST_DEPTH if as_columns and pairs < FEW_PAIRS else BISECTION_DEPTH


@dataclass(frozen=True, slots=True, kw_only=True)
class _Brackets:
    """Brackets of the verdict's changes: grid index ``k`` (between k and k + 1) and
    actuator ``j``, each bracket's ends and the checks failing at its bad end (bisected
    in place)."""

    k: IndexArray
    j: IndexArray
    ok_side: FloatArray
    bad_side: FloatArray
    bad_fail: BoolArray

    def bisection(self, depth: int) -> Search:
        return _bisection(self.ok_side, self.bad_side, self.j, self.bad_fail, depth)

    def joined(self, other: _Brackets) -> _Brackets:
        return _Brackets(
            k=np.concatenate([self.k, other.k]),
            j=np.concatenate([self.j, other.j]),
            ok_side=np.concatenate([self.ok_side, other.ok_side]),
            bad_side=np.concatenate([self.bad_side, other.bad_side]),
            bad_fail=np.concatenate([self.bad_fail, other.bad_fail]),
        )


def _grid(lower: float, upper: float, series: Sequence[float] | None) -> FloatArray:
    if series is not None:
        values = np.unique(np.asarray([s for s in series if lower <= s <= upper], dtype=float))
        if values.size == 0:
            raise InvalidInputError("ratio_study.series", code="study_series_out_of_range")
        return values
    return np.geomspace(lower, upper, GRID_POINTS)


def ratio_study(
    actuators: Sequence[Actuator],
    vary: Callable[[float], Application],
    lower: float,
    upper: float,
    *,
    series: Sequence[float] | None = None,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
    cases_at: Callable[[FloatArray], Cases] | None = None,
) -> list[RatioResult]:
    """Each actuator's feasible intervals of the free value in [lower, upper] and its best
    value, in the catalogue's order; with ``series``, only the series' values (an
    interval: neighbouring series values that all pass). ``cases_at``: the load cases of
    ``vary`` at many values at once, where the caller can build them as columns
    (:func:`~actuator_selection.sizing.ratio_cases.geared_cases`)."""
    found = _study(actuators, vary, lower, upper, series, rules, arrays, cases_at, None, {})
    return found.results


@dataclass(frozen=True, slots=True, kw_only=True)
class RankedStudy:
    """The ranking's first actuators (:func:`ranked_ratio_study`) and how many there were."""

    results: list[RatioResult]
    """In the ranking's order: those with a best value first, by their best utilisation,
    then by model."""
    total: int
    """The actuators studied."""
    fitting: int
    """Those with an interval."""


def ranked_ratio_study(
    actuators: Sequence[Actuator],
    vary: Callable[[float], Application],
    lower: float,
    upper: float,
    *,
    top: int,
    series: Sequence[float] | None = None,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
    cases_at: Callable[[FloatArray], Cases] | None = None,
    monotone: Mapping[str, int] | None = None,
    torque_floor: Callable[[FloatArray, FloatArray], FloatArray] | None = None,
) -> RankedStudy:
    """:func:`ratio_study`'s first ``top`` results in the ranking's order (best value
    first, by best utilisation, then by model; those without a best value last, by model),
    each equal to its result of the whole study: the best value of every actuator that
    could be listed is searched (the ranking reads it), only the listed actuators'
    interval ends are bisected.

    ``monotone``: checks whose share (value/limit) ``vary`` makes non-decreasing (+1) or
    non-increasing (−1) in the free value, by name (:data:`~actuator_selection.sizing.
    ratio_cases.MONOTONE_SHARES`); they bound each best value's utilisation from below
    (:func:`_floors`), and an actuator whose bound exceeds the ``top``-th best grid
    utilisation cannot be listed: its best value is not refined. ``torque_floor``: a
    lower bound of |T_1| between neighbouring values, given the values and J_A
    (:func:`~actuator_selection.sizing.ratio_cases.geared_torque_floor`), raising those
    bounds by the ``peak_torque`` check's (:func:`_peak_torque_floors`; with
    ``monotone`` only)."""
    return _study(
        actuators,
        vary,
        lower,
        upper,
        series,
        rules,
        arrays,
        cases_at,
        top,
        monotone or {},
        torque_floor,
    )


def _ranking(model_rank: IndexArray, has_best: BoolArray, best: _Best) -> IndexArray:
    """The columns in the ranking's order (:func:`ranked_ratio_study`)."""
    utilisation = np.where(has_best, best.utilisation, 0.0)
    order: IndexArray = np.lexsort((model_rank, utilisation, ~has_best))
    return order


def _study(
    actuators: Sequence[Actuator],
    vary: Callable[[float], Application],
    lower: float,
    upper: float,
    series: Sequence[float] | None,
    rules: Sequence[Rule] | None,
    arrays: CatalogueArrays | None,
    cases_at: Callable[[FloatArray], Cases] | None,
    top: int | None,
    monotone: Mapping[str, int],
    torque_floor: Callable[[FloatArray, FloatArray], FloatArray] | None = None,
) -> RankedStudy:
    """The study; ``top`` None: every actuator in the catalogue's order, else the
    ranking's first ``top``."""
    if not (0 < lower < upper and math.isfinite(upper)):
        raise InvalidInputError("ratio_study.min", code="study_range")
    if not actuators:
        return RankedStudy(results=[], total=0, fitting=0)
    grid = _grid(lower, upper, series)
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    as_columns = cases_at is not None
    if cases_at is None:

        def cases_at(values: FloatArray) -> Cases:
            return cases_of([vary(float(x)) for x in values])

        apps = [vary(float(x)) for x in grid]
    else:
        apps = [vary(float(grid[0]))]
    rules = rules_of(apps, rules)
    names = tuple(rule.name for rule in rules)
    cases = cases_at(grid)
    limits_of_zones = zone_limits(actuators, cat.zone_columns, cases.mean_speed)
    # the grid × the catalogue; a column left out (a ranked study's, that cannot be
    # listed) fails everywhere here, whether it fits found apart
    shape = (grid.size, len(actuators))
    verdicts = np.full(shape, _FAIL, dtype=np.int8)
    util, which = np.full(shape, np.nan), np.zeros(shape, dtype=np.intp)
    failing_grid = np.zeros((*shape, len(rules)), dtype=np.bool_)
    grid_cells = (
        verdicts.reshape(-1),
        util.reshape(-1),
        which.reshape(-1),
        failing_grid.reshape(-1, len(rules)),
    )

    def evaluate(part: IndexArray | None) -> None:
        """The grid × the actuators ``part`` (ascending; None: all), block by block;
        only what the search reads is kept."""
        sub, zones = cat, limits_of_zones
        at: slice | IndexArray = slice(None)
        if part is not None:
            sub, at = catalogue_part(cat, part), part
            zones = limits_of_zones[:, np.searchsorted(cat.zone_columns, part[sub.zone_columns])]
        width = sub.size
        for start, stop in blocks(range(width), grid):
            block = evaluate_block(
                sub, cases.rows(start, stop), zones[start:stop], rules, detail=True, overload=False
            )
            codes, u, w, f = _cells(block)
            verdicts[start:stop, at] = codes.reshape(-1, width)
            util[start:stop, at] = u.reshape(-1, width)
            which[start:stop, at] = w.reshape(-1, width)
            failing_grid[start:stop, at] = f.reshape(-1, width, len(rules))

    # a ranked study: the monotone checks' shares bound the utilisations from below
    shares = [] if top is None else _monotone_shares(rules, monotone, cases, cat)
    unlisted: IndexArray = np.zeros(0, dtype=np.intp)
    fits_apart = 0  # those not evaluated on the grid that fit
    search = _Pairs(cat, zone_table(actuators), cases_at, rules, grid, grid_cells)
    floors = _floors(shares) if shares and grid.size > 1 else None
    if floors is not None and torque_floor is not None and "peak_torque" in names:
        # fmax: a NaN (no bound) leaves the floor as it is
        np.fmax(floors, _peak_torque_floors(torque_floor(grid, cat.inertia), cat), out=floors)
    if top is not None and top < shape[1] and floors is not None:
        # by least floor, FIRST × top first, twice as many each time after: those whose
        # floor exceeds the top-th best grid utilisation so far cannot be listed, and
        # are not evaluated on the grid
        floor = floors.min(axis=0)  # over the whole range
        rest = np.argsort(floor, kind="stable")
        least = np.full(shape[1], np.inf)  # the best grid utilisation of those evaluated
        size = FIRST * top
        while rest.size:
            part, rest = np.sort(rest[:size]), rest[size:]
            size *= 2
            evaluate(part)
            passing = (verdicts[:, part] != _FAIL) & np.isfinite(util[:, part])
            least[part] = np.where(passing, util[:, part], np.inf).min(axis=0)
            bar = np.partition(least, top - 1)[top - 1]
            cut = np.searchsorted(floor[rest], bar, side="right")  # floors ascending
            unlisted, rest = np.concatenate([unlisted, rest[cut:]]), rest[:cut]
        # whether those fit somewhere: asked where they most likely pass, those that fail
        # there evaluated on the grid (as if listable: the same answer)
        if unlisted.size:
            likeliest = grid[_likeliest(shares, unlisted)]
            passes = search.evaluated(likeliest, unlisted)[0] != _FAIL
            fits_apart = int(passes.sum())
            if not passes.all():
                evaluate(np.sort(unlisted[~passes]))
    else:
        evaluate(None)
    ok = verdicts != _FAIL  # grid × actuators

    # brackets: (actuator, ok value, bad value) at each change of the verdict
    change_k, change_j = np.nonzero(ok[1:] != ok[:-1])

    # the best grid value per actuator among the passing ones, then a finer grid about it
    masked = np.where(ok & np.isfinite(util), util, np.inf)
    best_k = np.argmin(masked, axis=0)
    every = np.arange(len(actuators))
    has_best = np.isfinite(masked[best_k, every])
    best = _Best(
        value=grid[best_k].astype(float),
        utilisation=masked[best_k, every],
        code=verdicts[best_k, every],
        which=which[best_k, every],
    )
    columns = np.nonzero(has_best)[0]
    refine = series is None and columns.size > 0

    def brackets(of: BoolArray | None) -> _Brackets:
        """The brackets of the actuators ``of`` (None: all): (actuator, ok value, bad
        value) at each change of the verdict, and the checks failing at the bad one."""
        k, j = (
            (change_k, change_j) if of is None else (change_k[of[change_j]], change_j[of[change_j]])
        )
        passes = ok[k, j]
        return _Brackets(
            k=k,
            j=j,
            ok_side=np.where(passes, grid[k], grid[k + 1]),
            bad_side=np.where(passes, grid[k + 1], grid[k]),
            bad_fail=np.where(passes[:, None], failing_grid[k + 1, j], failing_grid[k, j]),
        )

    def listed(which: IndexArray) -> BoolArray:
        out = np.zeros(len(actuators), dtype=np.bool_)
        out[which] = True
        return out

    if top is None:
        chosen = every
        found = brackets(None)
        if series is None:
            # few pairs: fewer engine calls; many: fewer pairs
            pairs = 6 * found.k.size + (12 * columns.size if refine else 0)
            searches = [found.bisection(_depth(pairs, as_columns))] if found.k.size else []
            if refine:
                ahead = pairs < MANY_PAIRS
                searches.append(_refinement(best, columns, grid, ahead=ahead))
            search.run(*searches)
    else:
        # every best value refined (the ranking reads them); beside it, the ends of the
        # actuators the grid ranks first (:data:`GUESSED` × top), then any other listed
        model_rank = cat.model_rank
        guess = listed(_ranking(model_rank, has_best, best)[: GUESSED * top])
        found = brackets(guess)
        if floors is not None and columns.size > top:
            # those that cannot be listed: a floor above the top-th best grid utilisation
            # (the top-th best value is at most that), their grid value kept
            floor = _floor_about(floors, best_k)
            bar = np.partition(best.utilisation[columns], top - 1)[top - 1]
            columns = columns[~(floor[columns] > bar)]
        if series is None:
            searches = []
            if found.k.size:
                searches.append(found.bisection(_depth(6 * found.k.size, as_columns)))
            if refine:
                ahead = 12 * columns.size < MANY_PAIRS
                searches.append(_refinement(best, columns, grid, ahead=ahead))
            search.run(*searches)
        chosen = _ranking(model_rank, has_best, best)[:top]
        late = brackets(listed(chosen) & ~guess)
        if late.k.size and series is None:
            search.run(late.bisection(_depth(6 * late.k.size, as_columns)))
        found = found.joined(late)
    change_k, change_j = found.k, found.j
    ok_side, bad_fail = found.ok_side, found.bad_fail
    # the failing checks' names once per distinct set of them (a handful)
    sets, set_of = np.unique(bad_fail.reshape(-1, len(names)), axis=0, return_inverse=True)
    named = [tuple(n for n, f in zip(names, row, strict=True) if f) for row in sets.tolist()]
    ends = dict(
        zip(
            zip(change_j.tolist(), change_k.tolist(), strict=True),
            zip(ok_side.tolist(), [named[s] for s in set_of.ravel().tolist()], strict=True),
            strict=True,
        )
    )
    results = _results(actuators, chosen, grid, ok, util, ends, has_best, best, names)
    fitting = int(ok.any(axis=0).sum()) + fits_apart
    return RankedStudy(results=results, total=len(actuators), fitting=fitting)


def _results(
    actuators: Sequence[Actuator],
    chosen: IndexArray,
    grid: FloatArray,
    ok: BoolArray,
    util: FloatArray,
    ends: dict[tuple[int, int], tuple[float, tuple[str, ...]]],
    has_best: BoolArray,
    best: _Best,
    names: tuple[str, ...],
) -> list[RatioResult]:
    """The results of the actuators ``chosen``, in that order: their intervals (each run
    of passing grid values, its ends bisected), best values and curves."""
    picked = chosen.tolist()
    grid_values = tuple(float(x) for x in grid)
    shown = util[:, chosen].astype(object)
    shown[np.isnan(util[:, chosen])] = None
    curves = shown.T.tolist()
    # each run of passing grid values, per actuator in order: [start, stop)
    edges = np.diff(np.pad(ok[:, chosen].T.astype(np.int8), ((0, 0), (1, 1))), axis=1)
    run_n, run_start = np.nonzero(edges == 1)
    _n, run_stop = np.nonzero(edges == -1)
    runs: dict[int, list[Interval]] = {}
    for n, start, stop in zip(run_n.tolist(), run_start.tolist(), run_stop.tolist(), strict=True):
        j = picked[n]
        low, low_binding = ends[(j, start - 1)] if start > 0 else (float(grid[0]), ())
        high, high_binding = ends[(j, stop - 1)] if stop < grid.size else (float(grid[-1]), ())
        runs.setdefault(j, []).append(
            Interval(low=low, high=high, low_binding=low_binding, high_binding=high_binding)
        )
    found = has_best[chosen].tolist()
    return [
        RatioResult(
            actuator=actuators[j],
            intervals=tuple(runs.get(j, ())),
            best=value if fits else None,
            best_utilisation=u if fits else None,
            best_binding=names[w] if fits else None,
            verdict=VERDICT_BY_CODE[c] if fits else None,
            grid=grid_values,
            utilisation=tuple(curve),
        )
        for j, fits, value, u, w, c, curve in zip(
            picked,
            found,
            best.value[chosen].tolist(),
            best.utilisation[chosen].tolist(),
            best.which[chosen].tolist(),
            best.code[chosen].tolist(),
            curves,
            strict=True,
        )
    ]
