"""The ratio study's search (``sizing/ratio.py``: the engine on pairs, the bisection in
rounds, beside the parabolic steps) against the study as first written
(``tests/oracle/ratio_exhaustive.py``: one engine call per halving over the product of
values × actuators): the same intervals, ends, binding checks and best values, with
3, 2 and 1 halvings to an engine call (``FEW_PAIRS``, ``MANY_PAIRS``), on the starter
catalogue (with zones and published τ_th on some of its actuators) and on the vertical
screw's lead; and the engine on pairs against its product, cell by cell."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from functools import cache

import numpy as np
import pytest
from tests.api.test_selection_binding import VERTICAL_SCREW
from tests.oracle.ratio_exhaustive import exhaustive_ratio_study
from tests.sizing.test_continuous import catalogue

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.schemas.ratio import RatioStudyRequest
from actuator_selection.services.ratio import columns_of, varied
from actuator_selection.sizing import ratio, ratio_floors, ratio_search
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import FloatArray, catalogue_arrays, evaluate_batch
from actuator_selection.sizing.engine.block import evaluate_block
from actuator_selection.sizing.engine.cases import Cases, cases_of, zone_limits, zone_table
from actuator_selection.sizing.engine.evaluation import rules_of
from actuator_selection.sizing.engine.pairs import evaluate_pairs
from actuator_selection.sizing.mechanisms import Transmission
from actuator_selection.sizing.ratio import RatioResult, ranked_ratio_study, ratio_study
from actuator_selection.sizing.ratio_cases import (
    MONOTONE_SHARES,
    GearedBounds,
    geared,
    geared_cases,
    geared_rms_floor,
    geared_torque_floor,
)


@cache
def actuators() -> tuple[Actuator, ...]:
    """The starter catalogue, every third actuator given a continuous-duty zone and every
    fifth a published τ_th (made up for the test, not data), so that the pairs carry both."""
    out = []
    for j, a in enumerate(catalogue()):
        if j % 3 == 0 and a.max_torque_nm is not None and a.max_speed_rpm is not None:
            zone = ContinuousDutyZone(
                points=(
                    ZonePoint(speed_rpm=0, torque_nm=0.4 * a.max_torque_nm),
                    ZonePoint(speed_rpm=0.5 * a.max_speed_rpm, torque_nm=0.3 * a.max_torque_nm),
                    ZonePoint(speed_rpm=a.max_speed_rpm, torque_nm=0.1 * a.max_torque_nm),
                )
            )
            a = dataclasses.replace(a, zone=zone)
        if j % 5 == 0:
            a = dataclasses.replace(a, thermal_time_constant_s=300.0 + j)
        out.append(a)
    return tuple(out)


Study = tuple[Callable[[float], Application], Callable[[FloatArray], Cases] | None]

TorqueFloor = Callable[[FloatArray, FloatArray], FloatArray]
_TORQUE_FLOORS: dict[Callable[[FloatArray], Cases], TorqueFloor] = {}
"""Each of :func:`_worked`'s cases as columns, its bound of |T_1| (as the service's)."""
_RMS_FLOORS: dict[Callable[[FloatArray], Cases], TorqueFloor] = {}
"""The same, its bound of T_rms."""


def _worked(speed_rpm: float, efficiency: float = 1.0) -> Study:
    """The worked example's load behind a ratio (J_tr 10⁻⁴ kgm²), its cases built as
    columns too (:func:`geared_cases`)."""
    pattern = SpeedPattern(
        speed_rpm=speed_rpm, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0
    )
    app = Application(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=1.3))
    transmission = Transmission(ratio=1, inertia_kgm2=1e-4, efficiency=efficiency)
    columns = geared_cases(app, 1e-4, efficiency)
    assert columns is not None
    floor = geared_torque_floor(app, 1e-4, efficiency)
    assert floor is not None
    _TORQUE_FLOORS[columns] = floor
    rms = geared_rms_floor(app, 1e-4, efficiency)
    assert rms is not None
    _RMS_FLOORS[columns] = rms
    return lambda i: geared(app, dataclasses.replace(transmission, ratio=i)), columns


def _screw(as_columns: bool = True) -> Study:
    """The vertical screw's lead, its cases built as columns as the service builds them
    (``columns_of``), or an application per value."""
    request = RatioStudyRequest.model_validate(
        VERTICAL_SCREW | {"ratio_study": {"variable": "lead_mm"}}
    )
    columns = columns_of(request, request.ratio_study) if as_columns else None
    return varied(request, request.ratio_study), columns


def _same(fast: list[RatioResult], old: list[RatioResult]) -> None:
    assert [r.actuator.model for r in fast] == [r.actuator.model for r in old]
    for a, b in zip(fast, old, strict=True):
        assert a.intervals == b.intervals, a.actuator.model
        assert (a.best, a.best_utilisation, a.best_binding, a.verdict) == (
            b.best,
            b.best_utilisation,
            b.best_binding,
            b.verdict,
        ), a.actuator.model
        assert a.grid == b.grid
        assert a.utilisation == b.utilisation


@pytest.mark.parametrize(
    ("study", "low", "high"),
    [
        (_worked(4.0), 1.0, 20.0),
        (_worked(4.0, 0.9), 1.0, 20.0),
        (_worked(4.0), 0.05, 2000.0),
        (_worked(40.0), 0.5, 5.0),
        (_screw(), 5.0, 1000.0),
        (_screw(), 20.0, 400.0),
        (_screw(as_columns=False), 5.0, 1000.0),
    ],
    ids=[
        "ratio 1-20",
        "ratio 1-20 eta 0.9",
        "ratio 0.05-2000",
        "fast load, ratio 0.5-5",
        "lead 5-1000",
        "lead 20-400",
        "lead 5-1000 by value",
    ],
)
@pytest.mark.parametrize(
    ("many_pairs", "few_pairs"),
    [(ratio_search.MANY_PAIRS, ratio_search.FEW_PAIRS), (ratio_search.MANY_PAIRS, 0), (0, 0)],
    ids=["as chosen", "2 halvings a call", "1 halving a call"],
)
def test_the_search_finds_what_the_exhaustive_study_finds(
    study: Study,
    low: float,
    high: float,
    many_pairs: int,
    few_pairs: int,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(ratio_search, "MANY_PAIRS", many_pairs)
    monkeypatch.setattr(ratio_search, "FEW_PAIRS", few_pairs)
    vary, columns = study
    found = ratio_study(actuators(), vary, low, high, cases_at=columns)
    assert any(r.intervals for r in found)
    assert any(r.intervals and r.intervals[0].low_binding for r in found)
    _same(found, exhaustive_ratio_study(actuators(), vary, low, high))


@cache
def _exhaustive(vary: Callable[[float], Application], low: float, high: float) -> list[RatioResult]:
    """The exhaustive study of one case, once for all the settings that rank it (the
    search's settings, patched below, are not the oracle's)."""
    return exhaustive_ratio_study(actuators(), vary, low, high)


def _ranking(results: list[RatioResult]) -> list[RatioResult]:
    """The answer's order, as the service sorted the whole study before (best value
    first, by best utilisation, then model)."""
    return sorted(
        results,
        key=lambda r: (
            r.best_utilisation is None,
            r.best_utilisation if r.best_utilisation is not None else 0.0,
            r.actuator.model,
        ),
    )


@pytest.mark.parametrize(
    ("study", "low", "high"),
    [
        (_worked(4.0), 1.0, 20.0),
        (_worked(4.0, 0.9), 0.05, 2000.0),
        (_worked(40.0), 0.5, 5.0),
        (_screw(), 5.0, 1000.0),
    ],
    ids=["ratio 1-20", "ratio 0.05-2000 eta 0.9", "fast load, ratio 0.5-5", "lead 5-1000"],
)
@pytest.mark.parametrize("top", [1, 7, 1000])
@pytest.mark.parametrize("many_pairs", [ratio_search.MANY_PAIRS, 0], ids=["as chosen", "1 halving"])
@pytest.mark.parametrize("guessed", [ratio.GUESSED, 0], ids=["guessed", "bisected after"])
@pytest.mark.parametrize(
    ("coarse", "fine_cells", "at_once"),
    [
        (ratio_floors.COARSE, ratio_floors.FINE_CELLS, ratio.AT_ONCE_LEAST),
        (4, 0, 0),
        (16, 0, 0),
    ],
    ids=["as chosen", "coarse floors first, fits at once", "coarser floors, fits at once"],
)
def test_the_ranking_s_first_are_those_of_the_exhaustive_study(
    study: Study,
    low: float,
    high: float,
    top: int,
    many_pairs: int,
    guessed: int,
    coarse: int,
    fine_cells: int,
    at_once: int,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Only the listed actuators' ends bisected (those the grid ranks first beside the
    parabolic steps, the rest after; or all after), and for a ratio, those that the
    floors show cannot be listed neither evaluated on the grid nor refined (the fast
    load's: some of them fit nowhere; the floors between neighbouring values, or first
    on every ``COARSE``-th value; whether those left off fit asked at one value for
    all, as blocks, or as pairs):
    the first ``top`` of the ranking, each equal to its result of the exhaustive study,
    and the counts of the whole."""
    monkeypatch.setattr(ratio_search, "MANY_PAIRS", many_pairs)
    monkeypatch.setattr(ratio, "GUESSED", guessed)
    monkeypatch.setattr(ratio_floors, "COARSE", coarse)
    monkeypatch.setattr(ratio_floors, "FINE_CELLS", fine_cells)
    monkeypatch.setattr(ratio, "AT_ONCE_LEAST", at_once)
    vary, columns = study
    # a ratio's columns have the ratio's shares and floors, as the service's; a lead's none
    monotone = MONOTONE_SHARES if columns in _TORQUE_FLOORS else None
    floor = _TORQUE_FLOORS.get(columns) if columns is not None else None
    ranked = ranked_ratio_study(
        actuators(),
        vary,
        low,
        high,
        top=top,
        cases_at=columns,
        monotone=monotone,
        torque_floor=floor,
        rms_floor=_RMS_FLOORS.get(columns) if columns is not None else None,
    )
    whole = _exhaustive(vary, low, high)
    expected = _ranking(whole)[:top]
    assert len(ranked.results) == min(top, len(whole))
    assert any(r.intervals for r in ranked.results)
    _same(ranked.results, expected)
    assert ranked.total == len(whole)
    assert ranked.fitting == sum(1 for r in whole if r.intervals)


@pytest.mark.parametrize("speed_rpm", [4.0, 40.0], ids=["worked", "fast load"])
@pytest.mark.parametrize("top", [1, 7])
def test_a_ranked_series_with_floors_as_before(speed_rpm: float, top: int) -> None:
    """A standard series: the floors between its values leave off the grid those that
    cannot be listed (the fast load's: most fit nowhere), the same first ``top`` and
    counts as the exhaustive study's."""
    series = [1.0, 1.5, 2.0, 3.0, 5.0, 8.0, 13.0, 20.0, 50.0]
    vary, columns = _worked(speed_rpm)
    ranked = ranked_ratio_study(
        actuators(),
        vary,
        1,
        50,
        top=top,
        series=series,
        cases_at=columns,
        monotone=MONOTONE_SHARES,
        torque_floor=None if columns is None else _TORQUE_FLOORS[columns],
        rms_floor=_RMS_FLOORS.get(columns) if columns is not None else None,
    )
    whole = exhaustive_ratio_study(actuators(), vary, 1, 50, series=series)
    _same(ranked.results, _ranking(whole)[:top])
    assert ranked.fitting == sum(1 for r in whole if r.intervals)


def test_a_series_as_before() -> None:
    series = [1.0, 1.5, 2.0, 3.0, 5.0, 8.0, 13.0, 20.0, 50.0]
    vary, columns = _worked(4.0)
    _same(
        ratio_study(actuators(), vary, 1, 50, series=series, cases_at=columns),
        exhaustive_ratio_study(actuators(), vary, 1, 50, series=series),
    )


def test_pairs_equal_their_cells_of_the_product() -> None:
    chosen = actuators()
    vary, _ = _worked(4.0, 0.9)
    xs = np.geomspace(0.3, 30.0, 9)
    apps = [vary(float(x)) for x in xs]
    rules = rules_of(apps, None)
    product = evaluate_batch(chosen, apps, rules=rules)
    rng = np.random.default_rng(7)
    rows = rng.integers(0, xs.size, 400)
    columns = rng.integers(0, len(chosen), 400)
    cat = catalogue_arrays(chosen)
    block = evaluate_pairs(cat, zone_table(chosen), cases_of(apps), rows, columns, rules)
    assert block.details is not None
    np.testing.assert_array_equal(block.verdicts()[:, 0], product.verdicts[rows, columns])
    for k, (codes, detail) in enumerate(zip(block.statuses, block.details, strict=True)):
        shape = block.accel_torque.shape
        np.testing.assert_array_equal(
            np.broadcast_to(codes, shape)[:, 0], product.statuses[rows, columns, k]
        )
        np.testing.assert_array_equal(
            np.broadcast_to(detail.values, shape)[:, 0], product.values[rows, columns, k]
        )
        np.testing.assert_array_equal(
            np.broadcast_to(detail.limits, shape)[:, 0], product.limits[rows, columns, k]
        )
    np.testing.assert_array_equal(block.rms_torque[:, 0], product.rms_torque_nm[rows, columns])


@pytest.mark.parametrize("efficiency", [1.0, 0.9, 0.5])
@pytest.mark.parametrize("torque_nm", [5.0, 0.0])
def test_geared_cases_are_the_geared_applications_cases(
    efficiency: float, torque_nm: float
) -> None:
    """The columns equal the applications' cases bit for bit, η_tr's factor on each piece
    too: 1/η driving, η where the load drives back (the fast deceleration), 1 at rest."""
    pattern = SpeedPattern(speed_rpm=4.0, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
    app = Application(pattern=pattern, load=Load(torque_nm=torque_nm, inertia_kgm2=1.3))
    columns = geared_cases(app, 1e-4, efficiency)
    assert columns is not None
    # i = 10.826958596122468: i·i and Python's i**2 differ in the last bit, as at ~0.08 %
    # of ratios; a selection at that ratio (geared) squares as Python's floats do.
    xs = np.concatenate(
        [
            np.geomspace(0.05, 2000.0, 40),
            [10.826958596122468],
            np.random.default_rng(11).uniform(0.05, 20.0, 2000),
        ]
    )
    built = columns(xs)
    transmission = Transmission(ratio=1, inertia_kgm2=1e-4, efficiency=efficiency)
    apps = [geared(app, dataclasses.replace(transmission, ratio=float(x))) for x in xs]
    expected = cases_of(apps)
    for part in ("pieces", "figures"):
        for field in dataclasses.fields(getattr(expected, part)):
            np.testing.assert_array_equal(
                getattr(getattr(built, part), field.name),
                getattr(getattr(expected, part), field.name),
                err_msg=f"{part}.{field.name}",
            )
    for field in dataclasses.fields(expected):
        if field.name not in ("pieces", "figures"):
            np.testing.assert_array_equal(
                getattr(built, field.name), getattr(expected, field.name), err_msg=field.name
            )


def test_a_block_without_its_overload_has_the_same_checks() -> None:
    """``overload=False`` (what the search asks) leaves out the overload alone: the same
    codes, values and limits, on a grid where checks fail."""
    vary, columns = _worked(4.0, 0.9)
    assert columns is not None
    chosen = actuators()
    cat = catalogue_arrays(chosen)
    cases = columns(np.geomspace(0.05, 2000.0, 20))
    rules = rules_of([vary(1.0)], None)
    zones = zone_limits(chosen, cat.zone_columns, cases.mean_speed)
    full = evaluate_block(cat, cases, zones, rules, detail=True)
    lean = evaluate_block(cat, cases, zones, rules, detail=True, overload=False)
    assert full.details is not None
    assert lean.details is not None
    assert (full.overload > 1).any()
    assert not np.asarray(lean.overload).any()
    np.testing.assert_array_equal(lean.verdicts(), full.verdicts())
    for lean_codes, codes in zip(lean.statuses, full.statuses, strict=True):
        np.testing.assert_array_equal(lean_codes, codes)
    for lean_detail, detail in zip(lean.details, full.details, strict=True):
        np.testing.assert_array_equal(lean_detail.values, detail.values)
        np.testing.assert_array_equal(lean_detail.limits, detail.limits)


@pytest.mark.parametrize(
    ("study", "low", "high"),
    [
        (_worked(4.0), 1.0, 20.0),
        (_worked(4.0, 0.9), 0.05, 2000.0),
        (_worked(40.0), 0.5, 5.0),
    ],
    ids=["ratio 1-20", "ratio 0.05-2000 eta 0.9", "fast load, ratio 0.5-5"],
)
def test_the_floors_bound_the_utilisation(study: Study, low: float, high: float) -> None:
    """The monotone checks' shares (``MONOTONE_SHARES``: n_max rising with i, 3·J_A
    falling) are the engine's, bit for bit; the floor over the range is at most every
    passing grid utilisation and every best utilisation of the exhaustive study, the
    floor about the best grid value at most the best utilisation; and each floor is
    above the 7th best grid utilisation for some actuators (those a ranked study of 7
    neither evaluates on the grid nor refines)."""
    vary, columns = study
    assert columns is not None
    chosen = actuators()
    cat = catalogue_arrays(chosen)
    grid = np.geomspace(low, high, ratio.GRID_POINTS)
    cases = columns(grid)
    rules = rules_of([vary(1.0)], None)
    block = evaluate_block(
        cat, cases, zone_limits(chosen, cat.zone_columns, cases.mean_speed), rules, detail=True
    )
    assert block.checks is not None
    shares = ratio_floors.monotone_shares(rules, MONOTONE_SHARES, cases, cat)
    names = [rule.name for rule in rules]
    for (share, direction), name in zip(shares, MONOTONE_SHARES, strict=True):
        assert direction == MONOTONE_SHARES[name]
        k = names.index(name)
        with np.errstate(divide="ignore", invalid="ignore"):
            engine = block.checks.values[k] / block.checks.limits[k]
        np.testing.assert_array_equal(share, np.where(block.checks.limits[k] > 0, engine, np.nan))
    codes, util, _which, _failing = ratio_search.block_cells(block)
    util = util.reshape(grid.size, -1)
    masked = np.where(
        (codes.reshape(util.shape) != ratio_search.FAIL) & np.isfinite(util), util, np.inf
    )
    whole = exhaustive_ratio_study(chosen, vary, low, high)
    refined = np.array(
        [np.inf if r.best_utilisation is None else r.best_utilisation for r in whole]
    )
    floors = ratio_floors.interval_floors(shares)
    about_best = ratio_floors.floor_about(floors, np.argmin(masked, axis=0))
    over_range = floors.min(axis=0)
    assert (about_best <= refined).all()
    assert (over_range <= refined).all()
    assert (over_range <= masked).all()
    assert (over_range > 0).all()
    fits = np.isfinite(masked.min(axis=0))
    seventh = np.sort(masked.min(axis=0)[fits])[6]
    assert (about_best[fits] > seventh).any()
    assert (over_range[fits] > seventh).any()


@pytest.mark.parametrize("seed", range(6))
def test_the_torque_floor_bounds_the_engine_s_peak_torque(seed: int) -> None:
    """The bound of |T_1| between neighbouring ratios (``geared_torque_floor``) and its
    share of T_max are never above the engine's at any ratio between them, sampled
    densely, over random loads: η_tr < 1, no load torque (T_L ≥ 0, Eq. 514.1), no load
    inertia (then, with η_tr < 1 and no torque, the factor is η: nothing drives), J_tr 0;
    and the bound is not void (it exceeds half the least |T_1| between for some)."""
    rng = np.random.default_rng(seed)
    chosen = actuators()
    cat = catalogue_arrays(chosen)
    peak = [r for r in rules_of([_worked(4.0)[0](1.0)], None) if r.name == "peak_torque"]
    tight = False
    for _ in range(4):
        torque = float(rng.choice([0.0, 1.0]) * rng.uniform(0, 40))
        inertia = float(rng.choice([0.0, 1.0]) * rng.uniform(0.01, 3))
        efficiency = float(rng.choice([1.0, 0.9, 0.5]))
        j_tr = float(rng.choice([0.0, 1e-4, 1e-2]))
        pattern = SpeedPattern(
            speed_rpm=float(rng.uniform(1, 60)),
            accel_s=float(rng.uniform(0.02, 0.5)),
            constant_s=0.1,
            decel_s=0.1,
            pause_s=1.0,
        )
        app = Application(pattern=pattern, load=Load(torque_nm=torque, inertia_kgm2=inertia))
        columns = geared_cases(app, j_tr, efficiency)
        floor = geared_torque_floor(app, j_tr, efficiency)
        assert columns is not None
        assert floor is not None
        grid = np.sort(rng.uniform(0.05, 200, 12))
        bound = floor(grid, cat.inertia)
        shares = ratio_floors.peak_torque_floors(bound, cat)
        for k in range(grid.size - 1):
            a, b = float(grid[k]), float(grid[k + 1])
            between = np.concatenate([[a, b], np.geomspace(a, b, 40), rng.uniform(a, b, 40)])
            cases = columns(between)
            zones = zone_limits(chosen, cat.zone_columns, cases.mean_speed)
            block = evaluate_block(cat, cases, zones, peak, detail=True)
            assert block.checks is not None
            engine = np.abs(block.accel_torque)
            known = ~np.isnan(bound[k])
            assert (bound[k][known] <= engine[:, known]).all()
            assert known.sum() > 0.9 * np.isfinite(cat.inertia).sum()
            with np.errstate(divide="ignore", invalid="ignore"):
                share = block.checks.values[0] / block.checks.limits[0]
            counted = (block.checks.limits[0] > 0) & np.isfinite(share)
            assert not (shares[k] > share)[counted].any()
            tight = tight or bool((bound[k][known] > 0.5 * engine[:, known].min(axis=0)).any())
    assert tight


@pytest.mark.parametrize("seed", range(6))
def test_the_rms_floor_bounds_the_engine_s_rms_torque(seed: int) -> None:
    """The bound of T_rms between neighbouring ratios (``geared_rms_floor``) and its
    share of the continuous limit's upper bound (``continuous_floors``) are never above
    the engine's T_rms and ``continuous_duty`` share at any ratio between them, sampled
    densely, over random loads as for the torque's (η_tr < 1, no T_L, no J_L, J_tr 0;
    a T_L that outweighs the braking; the actuators with a zone have no bound), the
    braking piece's T² too (the trapezoid's T_3); and the bound is close (within 5 % of the
    least T_rms between for some, the braking piece's square counted)."""
    rng = np.random.default_rng(seed)
    chosen = actuators()
    cat = catalogue_arrays(chosen)
    rules = rules_of([_worked(4.0)[0](1.0)], None)
    continuous = next(r for r in rules if r.name == "continuous_duty")
    close = False
    for _ in range(4):
        # up to 4,000 Nm: the braking piece's torque then keeps the load's sign
        torque = float(rng.choice([0.0, 1.0, 100.0]) * rng.uniform(0, 40))
        inertia = float(rng.choice([0.0, 1.0]) * rng.uniform(0.01, 3))
        efficiency = float(rng.choice([1.0, 0.9, 0.5]))
        j_tr = float(rng.choice([0.0, 1e-4, 1e-2]))
        pattern = SpeedPattern(
            speed_rpm=float(rng.uniform(1, 60)),
            accel_s=float(rng.uniform(0.02, 0.5)),
            constant_s=float(rng.uniform(0.0, 0.5)),
            decel_s=float(rng.uniform(0.02, 0.5)),
            pause_s=float(rng.uniform(0.0, 2.0)),
        )
        load = Load(torque_nm=torque, inertia_kgm2=inertia)
        app = Application(pattern=pattern, load=load)
        columns = geared_cases(app, j_tr, efficiency)
        floor = geared_rms_floor(app, j_tr, efficiency)
        assert columns is not None
        assert floor is not None
        grid = np.sort(rng.uniform(0.05, 200, 12))
        bound = floor(grid, cat.inertia)
        shares = ratio_floors.continuous_floors(bound.copy(), continuous, columns(grid), cat)
        factors = (1.0,) if efficiency == 1 else (1.0, 1.0 / efficiency, efficiency)
        braking = GearedBounds(pattern, load, j_tr, factors, grid).braking_square(cat.inertia)
        assert (braking > 0).any()
        for k in range(grid.size - 1):
            a, b = float(grid[k]), float(grid[k + 1])
            between = np.concatenate([[a, b], np.geomspace(a, b, 40), rng.uniform(a, b, 40)])
            cases = columns(between)
            zones = zone_limits(chosen, cat.zone_columns, cases.mean_speed)
            block = evaluate_block(cat, cases, zones, [continuous], detail=True)
            assert block.checks is not None
            engine = block.rms_torque
            assert (braking[k] <= block.decel_torque * block.decel_torque).all()
            known = ~np.isnan(bound[k])
            assert (bound[k][known] <= engine[:, known]).all()
            assert known.sum() > 0.9 * np.isfinite(cat.inertia).sum()
            with np.errstate(divide="ignore", invalid="ignore"):
                share = block.checks.values[0] / block.checks.limits[0]
            counted = (block.checks.limits[0] > 0) & np.isfinite(share)
            assert not (shares[k] > share)[counted].any()
            assert np.isnan(shares[k][cat.operands["has_zone"]]).all()
            least = engine[:, known].min(axis=0)
            close = close or bool((bound[k][known] > 0.95 * least).any())
    assert close
