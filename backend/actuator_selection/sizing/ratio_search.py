"""The ratio study's numeric search on the engine (:mod:`~actuator_selection.sizing.ratio`):
what the search reads of a block's cells, the engine on (value, actuator) pairs with a
grid value's pairs read from the grid, the bisection of the verdict's brackets, and the
parabolic steps about each actuator's best value, run side by side so that every engine
call serves all of them."""

from __future__ import annotations

import math
from collections.abc import Callable, Generator, Sequence
from dataclasses import dataclass
from typing import cast

import numpy as np

from actuator_selection.sizing.candidates import Verdict
from actuator_selection.sizing.checks import Rule, Status
from actuator_selection.sizing.engine import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BoolArray,
    CatalogueArrays,
    CodeArray,
    FloatArray,
    IndexArray,
)
from actuator_selection.sizing.engine.block import Block
from actuator_selection.sizing.engine.cases import Cases, ZoneTable
from actuator_selection.sizing.engine.pairs import evaluate_pairs

BISECTION_STEPS = 12
"""Halvings of every bracket: a grid step of 6.5 % narrowed to 1.6·10⁻⁵ relative."""
BISECTION_DEPTH = 2
"""Halvings per engine call (:func:`bisection`) where the pairs are few: 3 values a
bracket, 6 calls, the parabolic steps' beside them, each asked ahead for both outcomes
(:func:`refinement`); fewer calls, each paying the engine's fixed cost once."""
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

FAIL = VERDICT_BY_CODE.index(Verdict.UNSUITABLE)
"""The verdict code of a cell where a check fails."""
CODE_FAIL = np.int8(STATUS_BY_CODE.index(Status.FAIL))
"""The status code of a check that fails."""
Cells = tuple[CodeArray, FloatArray, IndexArray, BoolArray]
"""Per cell: the verdict code, the binding utilisation (max value/limit over the checks
with both; NaN where none has), its check's index, and which checks fail (cells ×
checks)."""


def block_cells(block: Block) -> Cells:
    """What the search reads of a block (run with ``detail``), its cells flattened in
    order; the status codes and each check's value and limit, no check worded. The
    binding check is the first of the largest share (a share where the limit is positive
    and it finite), as ``argmax`` takes it, every check at once (rules × cells)."""
    checks = block.checks
    assert checks is not None
    rules = checks.values.shape[0]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        share = checks.values / checks.limits
        counted = (checks.limits > 0) & np.isfinite(share)
    np.copyto(share, -np.inf, where=~counted)
    which = share.argmax(axis=0)
    best = np.take_along_axis(share, which[np.newaxis], axis=0)[0]
    util = np.where(np.isfinite(best), best, np.nan)
    failing = np.moveaxis(block.statuses == CODE_FAIL, 0, -1)
    return (
        block.verdicts().ravel(),
        util.ravel(),
        which.ravel(),
        failing.reshape(-1, rules),
    )


Request = tuple[FloatArray, IndexArray]
"""Pairs to evaluate: the free value and the actuator's column, pair by pair."""
Search = Generator[Request, Cells, None]


class Pairs:
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
        return block_cells(block)

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


def bisection(
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
            fails = codes[every, node] == FAIL
            ok_side[:] = np.where(fails, ok_side, m)
            bad_side[:] = np.where(fails, m, bad_side)
            bad_fail[:] = np.where(fails[:, None], failing[every, node], bad_fail)
            node = np.where(fails, 2 * node + 1, 2 * node + 2)


@dataclass(slots=True, kw_only=True)
class Best:
    """Per actuator, the value of least binding utilisation found so far, updated in place."""

    value: FloatArray
    utilisation: FloatArray
    code: CodeArray
    which: IndexArray


def _asked(best: Best, values: FloatArray, columns: IndexArray) -> Generator[Request, Cells, Cells]:
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


def refinement(best: Best, columns: IndexArray, grid: FloatArray, ahead: bool) -> Search:
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
            (codes[:n] != FAIL) & np.isfinite(at_vertex) & (at_vertex < best.utilisation[columns])
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


REACH = 2
"""Grid steps the parabolic steps can move a best value (:func:`refinement`): at most
1 + 1/4 + 1/16 + … < 4/3 of a step, whatever :data:`REFINE_ROUNDS`."""


def depth_for(pairs: int, as_columns: bool) -> int:
    """Halvings per engine call for a search of about ``pairs`` pairs: few pairs, fewer
    calls; many, fewer pairs."""
    if pairs >= MANY_PAIRS:
        return 1
    return FEWEST_DEPTH if as_columns and pairs < FEW_PAIRS else BISECTION_DEPTH


@dataclass(frozen=True, slots=True, kw_only=True)
class Brackets:
    """Brackets of the verdict's changes: grid index ``k`` (between k and k + 1) and
    actuator ``j``, each bracket's ends and the checks failing at its bad end (bisected
    in place)."""

    k: IndexArray
    j: IndexArray
    ok_side: FloatArray
    bad_side: FloatArray
    bad_fail: BoolArray

    def bisection(self, depth: int) -> Search:
        return bisection(self.ok_side, self.bad_side, self.j, self.bad_fail, depth)

    def joined(self, other: Brackets) -> Brackets:
        return Brackets(
            k=np.concatenate([self.k, other.k]),
            j=np.concatenate([self.j, other.j]),
            ok_side=np.concatenate([self.ok_side, other.ok_side]),
            bad_side=np.concatenate([self.bad_side, other.bad_side]),
            bad_fail=np.concatenate([self.bad_fail, other.bad_fail]),
        )
