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
   engine call where the pairs are few, one where they are many
   (:data:`~actuator_selection.sizing.ratio_search.MANY_PAIRS`),
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
actuator's utilisation from below between grid values
(:func:`~actuator_selection.sizing.ratio_floors.interval_floors`): over the range,
an actuator whose bound exceeds the ``top``-th best grid utilisation found cannot be
listed and is not evaluated on the grid (only whether it fits somewhere, asked first
where it most likely does: :func:`likeliest_index`); about its best grid value
(:func:`floor_about`), one whose bound exceeds it is not refined.

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
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing import ratio_search
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.candidates import Verdict
from actuator_selection.sizing.checks import Rule
from actuator_selection.sizing.engine import (
    VERDICT_BY_CODE,
    BoolArray,
    CatalogueArrays,
    CodeArray,
    FloatArray,
    IndexArray,
    catalogue_arrays,
)
from actuator_selection.sizing.engine.block import blocks, evaluate_block
from actuator_selection.sizing.engine.cases import (
    Cases,
    cases_of,
    zone_limits,
    zone_table,
)
from actuator_selection.sizing.engine.evaluation import rules_of
from actuator_selection.sizing.engine.pairs import catalogue_part
from actuator_selection.sizing.ratio_floors import (
    FIRST,
    Floors,
    floor_about,
    likeliest_index,
)
from actuator_selection.sizing.ratio_search import (
    FAIL,
    Best,
    Brackets,
    Pairs,
    block_cells,
    depth_for,
    refinement,
)

GRID_POINTS = 48
"""Grid values over the range (geometric): neighbours 6.5 % apart over 1–20."""
AT_ONCE_ROUNDS = 3
AT_ONCE_LEAST = 1_000
"""Whether the actuators a ranked study leaves off the grid fit somewhere is asked at
one value for all of them (the one most of them most likely pass at, a block of one
case: a pair costs some cells of such a block, ~1.6 µs against ~0.3 µs at 6,400), up to
``AT_ONCE_ROUNDS`` times while at least ``AT_ONCE_LEAST`` are left (fewer: the block's
fixed cost exceeds what it spares, ~1 ms more for 440 at 640 actuators); the rest each
at its own value, as pairs."""
MAX_SERIES = 200
"""The most values of a standard series."""


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


GUESSED = 2
"""A ranked study bisects, beside the parabolic steps, the ends of the first
``GUESSED × top`` actuators by their best grid value; the listed ones the steps move up
from further down are bisected after."""


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
    rms_floor: Callable[[FloatArray, FloatArray], FloatArray] | None = None,
) -> RankedStudy:
    """:func:`ratio_study`'s first ``top`` results in the ranking's order (best value
    first, by best utilisation, then by model; those without a best value last, by model),
    each equal to its result of the whole study: the best value of every actuator that
    could be listed is searched (the ranking reads it), only the listed actuators'
    interval ends are bisected.

    ``monotone``: checks whose share (value/limit) ``vary`` makes non-decreasing (+1) or
    non-increasing (−1) in the free value, by name (:data:`~actuator_selection.sizing.
    ratio_cases.MONOTONE_SHARES`); they bound each best value's utilisation from below
    (:func:`interval_floors`), and an actuator whose bound exceeds the ``top``-th best grid
    utilisation cannot be listed: its best value is not refined. ``torque_floor``: a
    lower bound of |T_1| between neighbouring values, given the values and J_A
    (:func:`~actuator_selection.sizing.ratio_cases.geared_torque_floor`), raising those
    bounds by the ``peak_torque`` check's (:func:`peak_torque_floors`; with
    ``monotone`` only). ``rms_floor``: a lower bound of T_rms between neighbouring
    values, given the same (:func:`~actuator_selection.sizing.ratio_cases.
    geared_rms_floor`), raising them by the ``continuous_duty`` check's
    (:func:`continuous_floors`; with ``monotone`` only)."""
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
        rms_floor,
    )


def _ranking(model_rank: IndexArray, has_best: BoolArray, best: Best) -> IndexArray:
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
    rms_floor: Callable[[FloatArray, FloatArray], FloatArray] | None = None,
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
    verdicts = np.full(shape, FAIL, dtype=np.int8)
    util, which = np.full(shape, np.nan), np.zeros(shape, dtype=np.intp)
    failing_grid = np.zeros((*shape, len(rules)), dtype=np.bool_)
    grid_cells = (
        verdicts.reshape(-1),
        util.reshape(-1),
        which.reshape(-1),
        failing_grid.reshape(-1, len(rules)),
    )

    seen = np.zeros(shape[1], dtype=np.bool_)  # the columns evaluated on the grid

    def zones_of(sub: CatalogueArrays, part: IndexArray) -> FloatArray:
        """The zones' edges (grid × zone columns) of ``sub``, the actuators ``part``."""
        zones: FloatArray = limits_of_zones[
            :, np.searchsorted(cat.zone_columns, part[sub.zone_columns])
        ]
        return zones

    def evaluate(part: IndexArray | None) -> None:
        """The grid × the actuators ``part`` (ascending; None: all), block by block;
        only what the search reads is kept."""
        sub, zones = cat, limits_of_zones
        at: slice | IndexArray = slice(None)
        if part is not None:
            sub, at = catalogue_part(cat, part), part
            zones = zones_of(sub, part)
        seen[at] = True
        width = sub.size
        for start, stop in blocks(range(width), grid):
            block = evaluate_block(
                sub, cases.rows(start, stop), zones[start:stop], rules, detail=True, overload=False
            )
            codes, u, w, f = block_cells(block)
            verdicts[start:stop, at] = codes.reshape(-1, width)
            util[start:stop, at] = u.reshape(-1, width)
            which[start:stop, at] = w.reshape(-1, width)
            failing_grid[start:stop, at] = f.reshape(-1, width, len(rules))

    def at_value(k: int, part: IndexArray) -> CodeArray:
        """The verdicts of the actuators ``part`` (ascending) at grid value ``k``."""
        sub = catalogue_part(cat, part)
        zones = zones_of(sub, part)[k : k + 1]
        block = evaluate_block(sub, cases.rows(k, k + 1), zones, rules, overload=False)
        verdicts: CodeArray = block.verdicts()[0]
        return verdicts

    # a ranked study: the monotone checks' shares bound the utilisations from below
    unlisted: IndexArray = np.zeros(0, dtype=np.intp)
    fits_apart = 0  # those not evaluated on the grid that fit
    search = Pairs(cat, zone_table(actuators), cases_at, rules, grid, grid_cells)
    floors = None
    if top is not None and grid.size > 1 and any(name in monotone for name in names):
        floors = Floors(rules, monotone, cases, grid, cat, torque_floor, rms_floor)
    if top is not None and top < shape[1] and floors is not None:
        # by least floor, FIRST × top first, twice as many each time after: those whose
        # floor exceeds the top-th best grid utilisation so far cannot be listed, and
        # are not evaluated on the grid; the floors first between every COARSE-th grid
        # value, then between neighbours for those still in the running
        coarse = floors.coarse()
        bounds, shares = floors.between(coarse, None)
        floor = bounds.min(axis=0)  # over the whole range
        tightened = np.full(shape[1], coarse.size == grid.size)  # between neighbours
        rest = np.argsort(floor, kind="stable")
        least = np.full(shape[1], np.inf)  # the best grid utilisation of those evaluated
        size = FIRST * top
        while rest.size:
            part, rest = np.sort(rest[:size]), rest[size:]
            size *= 2
            evaluate(part)
            passing = (verdicts[:, part] != FAIL) & np.isfinite(util[:, part])
            least[part] = np.where(passing, util[:, part], np.inf).min(axis=0)
            bar = np.partition(least, top - 1)[top - 1]
            loose = np.sort(rest[~tightened[rest] & (floor[rest] <= bar)])
            if loose.size:  # both are bounds: the larger
                fine = floors.within(coarse, bounds, loose, bar)
                floor[loose] = np.maximum(floor[loose], fine)
                tightened[loose] = True
                rest = rest[np.argsort(floor[rest], kind="stable")]
            cut = np.searchsorted(floor[rest], bar, side="right")  # floors ascending
            unlisted, rest = np.concatenate([unlisted, rest[cut:]]), rest[:cut]
        # whether those fit somewhere: asked where they most likely pass, those that fail
        # there evaluated on the grid (as if listable: the same answer)
        if unlisted.size:
            unlisted = np.sort(unlisted)
            likeliest = likeliest_index(shares, unlisted)
            # those left at the commonest of those values, as one case (a pair costs
            # some cells of a case's block), while they are many; then each at its own
            passes = np.zeros(unlisted.size, dtype=np.bool_)
            asked = np.zeros(unlisted.size, dtype=np.bool_)  # at its own value
            left = np.arange(unlisted.size)
            for _round in range(AT_ONCE_ROUNDS):
                if not left.size or left.size < AT_ONCE_LEAST:
                    break
                common = int(np.bincount(likeliest[left]).argmax())
                passes[left] = at_value(coarse[common], unlisted[left]) != FAIL
                asked[left[likeliest[left] == common]] = True
                left = left[~passes[left] & ~asked[left]]
            if left.size:
                own = grid[coarse[likeliest[left]]]
                passes[left] = search.evaluated(own, unlisted[left])[0] != FAIL
            fits_apart = int(passes.sum())
            if not passes.all():
                evaluate(np.sort(unlisted[~passes]))
    else:
        evaluate(None)
    ok = verdicts != FAIL  # grid × actuators; those not evaluated fail everywhere
    every = np.arange(len(actuators))
    on_grid = every if seen.all() else np.flatnonzero(seen)  # only those read below
    seen_ok, seen_util = (ok, util) if seen.all() else (ok[:, on_grid], util[:, on_grid])

    # brackets: (actuator, ok value, bad value) at each change of the verdict
    change_k, change_at = np.nonzero(seen_ok[1:] != seen_ok[:-1])
    change_j = on_grid[change_at]

    # the best grid value per actuator among the passing ones, then a finer grid about it
    masked = np.where(seen_ok & np.isfinite(seen_util), seen_util, np.inf)
    best_k = np.zeros(shape[1], dtype=np.intp)
    best_k[on_grid] = np.argmin(masked, axis=0)
    least_util = np.full(shape[1], np.inf)
    least_util[on_grid] = masked[best_k[on_grid], np.arange(on_grid.size)]
    has_best = np.isfinite(least_util)
    best = Best(
        value=grid[best_k].astype(float),
        utilisation=least_util,
        code=verdicts[best_k, every],
        which=which[best_k, every],
    )
    columns = np.nonzero(has_best)[0]
    refine = series is None and columns.size > 0

    def brackets(of: BoolArray | None) -> Brackets:
        """The brackets of the actuators ``of`` (None: all): (actuator, ok value, bad
        value) at each change of the verdict, and the checks failing at the bad one."""
        k, j = (
            (change_k, change_j) if of is None else (change_k[of[change_j]], change_j[of[change_j]])
        )
        passes = ok[k, j]
        return Brackets(
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
            searches = [found.bisection(depth_for(pairs, as_columns))] if found.k.size else []
            if refine:
                ahead = pairs < ratio_search.MANY_PAIRS
                searches.append(refinement(best, columns, grid, ahead=ahead))
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
            if coarse.size == grid.size:  # between neighbours already
                about = floor_about(bounds[:, columns], best_k[columns])
            else:
                about = floors.about(best_k[columns], columns)
            bar = np.partition(best.utilisation[columns], top - 1)[top - 1]
            columns = columns[~(about > bar)]
        if series is None:
            searches = []
            if found.k.size:
                searches.append(found.bisection(depth_for(6 * found.k.size, as_columns)))
            if refine:
                ahead = 12 * columns.size < ratio_search.MANY_PAIRS
                searches.append(refinement(best, columns, grid, ahead=ahead))
            search.run(*searches)
        chosen = _ranking(model_rank, has_best, best)[:top]
        late = brackets(listed(chosen) & ~guess)
        if late.k.size and series is None:
            search.run(late.bisection(depth_for(6 * late.k.size, as_columns)))
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
    best: Best,
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
