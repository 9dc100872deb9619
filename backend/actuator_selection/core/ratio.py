"""The ratio study (issue 31 part 1): for every actuator of the catalogue, the interval(s)
of a free transmission value (an external gear ratio i, a screw lead, a pulley or pinion
diameter) for which no check fails, and the value that minimises the binding utilisation.

The free value enters as the load case does today: ``vary(x)`` builds the application at
``x`` through the mechanisms' own reflection (:func:`~actuator_selection.core.mechanisms.
with_transmission` for a ratio: speed ×i, torque ÷i, inertia ÷i² plus J_tr, η by the power
flow; the mechanism's own lead or diameter otherwise), so the study and a selection at
that value are the same flowchart on the same numbers.

The search runs on the engine, vectorised over cases × actuators:

1. a geometric grid of the range (or the standard series given) as the cases, the whole
   catalogue as the columns, one :func:`~actuator_selection.core.engine.evaluate_batch`;
2. every change of the verdict between neighbouring grid values, for every actuator, is
   a bracket; all brackets are bisected together (the midpoints of all brackets as the
   cases, the actuators that have one as the columns, each bracket's own cell read), so
   several intervals per actuator are found where the checks are not monotonic;
3. the grid value of least binding utilisation (max value/limit over the checks,
   :func:`~actuator_selection.core.checks.rule.utilisation`) is refined by parabolic
   steps in log x (a passing value only, and only where it lowers the utilisation), all
   actuators together.

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

import dataclasses
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.application import Application
from actuator_selection.core.candidates import Verdict
from actuator_selection.core.checks import Rule, Status
from actuator_selection.core.cycle import Load
from actuator_selection.core.engine import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BatchEvaluation,
    CatalogueArrays,
    FloatArray,
    catalogue_arrays,
    evaluate_batch,
)
from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.loads import _square
from actuator_selection.core.mechanisms import Transmission, with_transmission
from actuator_selection.core.motion import Motion

GRID_POINTS = 48
"""Grid values over the range (geometric): neighbours 6.5 % apart over 1–20."""
BISECTION_STEPS = 12
"""Halvings of every bracket (one engine call each): a grid step of 6.5 % narrowed to
1.6·10⁻⁵ relative."""
REFINE_ROUNDS = 3
"""Parabolic steps for the best value (two engine calls each)."""
MAX_SERIES = 200
"""The most values of a standard series."""

_FAIL = VERDICT_BY_CODE.index(Verdict.UNSUITABLE)
_CHECK_FAIL = STATUS_BY_CODE.index(Status.FAIL)


def inertia_matched_ratio(load_inertia_kgm2: float, actuator_inertia_kgm2: float) -> float:
    """i* = √(J_L/J_A): the ratio of least peak torque for a pure inertia load, the inertia
    match (Giberti et al. 2011; Van de Straete et al. 1999).

    >>> inertia_matched_ratio(0.5, 0.02)
    5.0
    """
    return math.sqrt(load_inertia_kgm2 / actuator_inertia_kgm2)


def geared(app: Application, transmission: Transmission) -> Application:
    """``app`` behind an external ratio i (between the actuator output and the load, in
    series with any the mechanism has): the cycle's speeds ×i and process torques ÷i, the
    load through :func:`~actuator_selection.core.mechanisms.with_transmission` (J_L/i² +
    J_tr, T/i, η_tr·η by the power flow). At i = 1 with J_tr = 0 and η = 1 it is ``app``'s
    own load case."""
    i = transmission.ratio
    if app.pattern is not None and app.load is not None and transmission.efficiency == 1:
        # the chapter's shorthand stays one (T_L as friction, η = 1): the numbers of
        # with_transmission, and the engine's trapezoid columns
        pattern, load = app.pattern, app.load
        return dataclasses.replace(
            app,
            pattern=dataclasses.replace(pattern, speed_rpm=pattern.speed_rpm * i),
            load=Load(
                torque_nm=load.torque_nm / i,
                inertia_kgm2=transmission.inertia_kgm2 + load.inertia_kgm2 / _square(i),
            ),
        )
    motion = app.cycle
    segments = tuple(
        dataclasses.replace(
            s,
            start_rpm=s.start_rpm * transmission.ratio,
            end_rpm=s.end_rpm * transmission.ratio,
            process_torque_nm=s.process_torque_nm / transmission.ratio,
        )
        for s in motion.segments
    )
    axis = with_transmission(motion.load, transmission)
    return dataclasses.replace(
        app, pattern=None, load=None, motion=Motion(segments=segments, load=axis)
    )


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
        failing = ev.statuses[rows, at] == _CHECK_FAIL
        return ev.verdicts[rows, at], util[rows, at], which[rows, at], failing


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
    ok = ev.verdicts != _FAIL  # grid × actuators
    util, which = _utilisation(ev)
    cells = _Cells(actuators, vary, rules)
    failing_grid = ev.statuses == _CHECK_FAIL

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
            fails = codes == _FAIL
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
            better = (codes != _FAIL) & np.isfinite(u) & (u < best_util[columns])
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
