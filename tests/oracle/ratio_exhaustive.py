"""The ratio study as it was first written: the grid, then every bracket bisected one
engine call at a time over the product of its values × actuators (``_Cells``), then
the parabolic steps one call each. Kept as the oracle of the fast search in
:mod:`actuator_selection.sizing.ratio`, which must find the same intervals and best values."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

import numpy as np

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.checks import Rule
from actuator_selection.sizing.engine import (
    VERDICT_BY_CODE,
    BatchEvaluation,
    CatalogueArrays,
    FloatArray,
    catalogue_arrays,
    evaluate_batch,
)
from actuator_selection.sizing.ratio import Interval, RatioResult, _grid
from actuator_selection.sizing.ratio_search import (
    BISECTION_STEPS,
    CODE_FAIL,
    FAIL,
    REFINE_ROUNDS,
)


def _utilisation(ev: BatchEvaluation) -> tuple[FloatArray, np.ndarray]:
    """The binding utilisation (max value/limit over the checks with both) per cell, and
    the index of its check."""
    with np.errstate(divide="ignore", invalid="ignore"):
        share = np.where(ev.limits > 0, ev.values / ev.limits, np.nan)
    share = np.where(np.isfinite(share), share, -np.inf)
    which = np.argmax(share, axis=-1)
    top = np.take_along_axis(share, which[..., None], axis=-1)[..., 0]
    return np.where(np.isfinite(top), top, np.nan), which


class _Cells:
    """The engine on pairs (value, actuator): the distinct values as cases, the distinct
    actuators as columns, each pair's own cell read."""

    def __init__(
        self,
        actuators: Sequence[Actuator],
        vary: Callable[[float], Application],
        rules: Sequence[Rule] | None,
    ) -> None:
        self.actuators, self.vary, self.rules = actuators, vary, rules
        self.names: tuple[str, ...] = ()

    def __call__(
        self, values: FloatArray, columns: np.ndarray
    ) -> tuple[np.ndarray, FloatArray, np.ndarray, np.ndarray]:
        """Per pair: the verdict code, the utilisation, its check's index, the failing
        checks (mask)."""
        xs, rows = np.unique(values, return_inverse=True)
        cols, at = np.unique(columns, return_inverse=True)
        chosen = [self.actuators[int(c)] for c in cols]
        ev = evaluate_batch(chosen, [self.vary(float(x)) for x in xs], rules=self.rules)
        self.names = ev.check_names
        util, which = _utilisation(ev)
        failing = ev.statuses[rows, at] == CODE_FAIL
        return ev.verdicts[rows, at], util[rows, at], which[rows, at], failing


def exhaustive_ratio_study(
    actuators: Sequence[Actuator],
    vary: Callable[[float], Application],
    lower: float,
    upper: float,
    *,
    series: Sequence[float] | None = None,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> list[RatioResult]:
    """Each actuator's feasible intervals of the free value in [lower, upper] and its best
    value; with ``series``, only the series' values (an interval: neighbouring series
    values that all pass)."""
    if not (0 < lower < upper and math.isfinite(upper)):
        raise InvalidInputError("ratio_study.min", code="study_range")
    if not actuators:
        return []
    grid = _grid(lower, upper, series)
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    ev = evaluate_batch(actuators, [vary(float(x)) for x in grid], rules=rules, arrays=cat)
    names = ev.check_names
    ok = ev.verdicts != FAIL  # grid × actuators
    util, which = _utilisation(ev)
    cells = _Cells(actuators, vary, rules)
    failing_grid = ev.statuses == CODE_FAIL

    # brackets: (actuator, ok value, bad value) at each change of the verdict
    change_k, change_j = np.nonzero(ok[1:] != ok[:-1])
    ok_side = np.where(ok[change_k, change_j], grid[change_k], grid[change_k + 1])
    bad_side = np.where(ok[change_k, change_j], grid[change_k + 1], grid[change_k])
    bad_fail = np.where(
        ok[change_k, change_j][:, None],
        failing_grid[change_k + 1, change_j],
        failing_grid[change_k, change_j],
    )
    if series is None and change_k.size:
        for _ in range(BISECTION_STEPS):
            middle = np.sqrt(ok_side * bad_side)
            codes, _u, _w, failing = cells(middle, change_j)
            fails = codes == FAIL
            ok_side = np.where(fails, ok_side, middle)
            bad_side = np.where(fails, middle, bad_side)
            bad_fail = np.where(fails[:, None], failing, bad_fail)
    ends = {
        (int(j), int(k)): (float(o), tuple(n for n, f in zip(names, row, strict=True) if f))
        for j, k, o, row in zip(change_j, change_k, ok_side, bad_fail, strict=True)
    }

    # the best grid value per actuator among the passing ones, then a finer grid about it
    masked = np.where(ok & np.isfinite(util), util, np.inf)
    best_k = np.argmin(masked, axis=0)
    every = np.arange(len(actuators))
    has_best = np.isfinite(masked[best_k, every])
    best = grid[best_k].astype(float)
    best_util = masked[best_k, every]
    best_code = ev.verdicts[best_k, every]
    best_which = which[best_k, every]
    columns = np.nonzero(has_best)[0]
    if series is None and columns.size:
        # a parabola in log x through the best and its neighbours, its vertex evaluated;
        # each round about the best so far, a quarter as wide
        centre = np.log(best[columns])
        half = np.full(columns.size, math.log(grid[1] / grid[0]))
        for _ in range(REFINE_ROUNDS):
            points = np.exp(centre[:, None] + half[:, None] * np.array([-1.0, 0.0, 1.0]))
            u = cells(points.ravel(), np.repeat(columns, 3))[1].reshape(points.shape)
            left, mid, right = u[:, 0], u[:, 1], u[:, 2]
            with np.errstate(divide="ignore", invalid="ignore"):
                shift = 0.5 * half * (left - right) / (left - 2 * mid + right)
            convex = np.isfinite(shift) & (left - 2 * mid + right > 0)
            vertex = np.exp(centre + np.where(convex, np.clip(shift, -half, half), 0.0))
            vertex = np.clip(vertex, grid[0], grid[-1])  # within the range searched
            codes, u, w, _f = cells(vertex, columns)
            better = (codes != FAIL) & np.isfinite(u) & (u < best_util[columns])
            chosen = columns[better]
            best[chosen] = vertex[better]
            best_util[chosen] = u[better]
            best_code[chosen] = codes[better]
            best_which[chosen] = w[better]
            centre, half = np.log(best[columns]), half / 4
    verdict_at = {int(c): VERDICT_BY_CODE[int(best_code[c])] for c in columns}
    binding_at = {int(c): names[int(best_which[c])] for c in columns}

    results = []
    for j, actuator in enumerate(actuators):
        intervals = []
        k = 0
        while k < grid.size:
            if not ok[k, j]:
                k += 1
                continue
            start = k
            while k + 1 < grid.size and ok[k + 1, j]:
                k += 1
            low, low_binding = ends[(j, start - 1)] if start > 0 else (float(grid[0]), ())
            high, high_binding = ends[(j, k)] if k + 1 < grid.size else (float(grid[-1]), ())
            intervals.append(
                Interval(low=low, high=high, low_binding=low_binding, high_binding=high_binding)
            )
            k += 1
        found = bool(has_best[j])
        results.append(
            RatioResult(
                actuator=actuator,
                intervals=tuple(intervals),
                best=float(best[j]) if found else None,
                best_utilisation=float(best_util[j]) if found else None,
                best_binding=binding_at.get(j),
                verdict=verdict_at.get(j),
                grid=tuple(float(x) for x in grid),
                utilisation=tuple(
                    None if not np.isfinite(u) else float(u) for u in util[:, j].tolist()
                ),
            )
        )
    return results
