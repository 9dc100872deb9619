"""One cell's floats equal the block's arrays, bit for bit.

A block of one case × one actuator (a one-model selection's) runs the block's formulas on
Python floats (``engine.formulas.FLOAT_MATH``); any other block on arrays. These tests
run both on the same cells, including cells whose inputs make numpy give ±∞ and NaN where
Python's floats would raise, and compare every result by its bits.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import random
from collections.abc import Sequence
from typing import Any

import numpy as np
import pytest
from tests.oracle.test_engine_parity import (
    random_actuator,
    random_case,
    random_motion_case,
    with_gear_stiffness_brake,
)

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.bearing import OutputLoad
from actuator_selection.sizing.checks import ALL_RULES, Operands, Rule
from actuator_selection.sizing.engine.block import (
    _block_cycle,
    _cell_cycle,
    evaluate_block,
    operands_of,
)
from actuator_selection.sizing.engine.cases import Cases, cases_of, zone_limit_float, zone_limits
from actuator_selection.sizing.engine.catalogue import CatalogueArrays, catalogue_arrays
from actuator_selection.sizing.engine.codes import cell_codes
from actuator_selection.sizing.engine.formulas import float_divide, float_maximum, float_sqrt
from actuator_selection.sizing.engine.one_case import OneCase, case_floats
from actuator_selection.sizing.selection import Application

SPECIAL = (0.0, -0.0, 1.0, -2.5, 3.0, 5e-324, 1e-300, 1e300, -1e300, math.inf, -math.inf, math.nan)
"""Inputs where floats and arrays part most easily: signed zeros, subnormals, overflow."""

DURATIONS = tuple(x for x in SPECIAL if not x < 0.0)
"""Of :data:`SPECIAL`, those a duration may take (``heating_gain`` overflows on a
negative one, in both paths alike: the inputs' validation refuses them)."""


def same_bits(a: Any, b: Any) -> bool:
    """Equal IEEE doubles (−0.0 ≠ 0.0), any NaN equal to any NaN (JSON has no payload)."""
    x, y = np.asarray(a, dtype=np.float64), np.asarray(b, dtype=np.float64)
    if x.shape != y.shape:
        return False
    both_nan = np.isnan(x) & np.isnan(y)
    return bool(np.all(both_nan | (x.view(np.uint64) == y.view(np.uint64))))


def assert_cell_equals_block(cat: CatalogueArrays, cases: Cases) -> None:
    with np.errstate(all="ignore"):
        block = _block_cycle(cat, cases, (1, 1), True)
        cell = _cell_cycle(cat, case_floats(cases), True)
    assert len(cell) == len(block)
    for k, (x, y) in enumerate(zip(cell, block, strict=True)):
        column = np.broadcast_to(y, (1, 1))[0, 0]
        assert type(x) is (bool if column.dtype == np.bool_ else float), k
        assert same_bits(x, column), (k, x, y)


def heated(rng: random.Random, actuator: Actuator) -> Actuator:
    """``actuator`` with what makes its heating follow the current, or a published τ_th."""
    changes: dict[str, Any] = {}
    if rng.random() < 0.5:
        changes |= {
            "stall_torque_nm": rng.uniform(1, 800),
            "zone": None,
            "torque_constant_nm_per_a": rng.uniform(0.1, 20),
            "no_load_current_constant_30c_a_per_rpm": rng.uniform(1e-4, 1e-2),
        }
    if rng.random() < 0.4:
        changes["thermal_time_constant_s"] = rng.choice([1.0, 600.0, rng.uniform(1, 3000)])
    return dataclasses.replace(actuator, **changes)


def cells(seed: int, count: int) -> list[tuple[Actuator, Application]]:
    rng = random.Random(seed)
    out = []
    for k in range(count):
        actuator = heated(rng, random_actuator(rng, k))
        app = random_motion_case(rng) if rng.random() < 0.5 else random_case(rng, [actuator])
        out.append((actuator, app))
    return out


@pytest.mark.parametrize("seed", range(4))
def test_one_cell_on_floats_equals_the_block_on_arrays(seed: int) -> None:
    for actuator, app in cells(seed, 60):
        assert_cell_equals_block(catalogue_arrays([actuator]), cases_of([app]))


def with_inputs(cases: Cases, rng: random.Random) -> Cases:
    """``cases`` (one) with its pieces' and cycle's numbers drawn from :data:`SPECIAL`."""
    p, f = cases.pieces, cases.figures
    p.duration[0] = [rng.choice(DURATIONS) for _ in range(p.duration.shape[1])]
    for column in (p.start_rpm, p.end_rpm, p.accel_start, p.accel_end, p.static, p.inertia):
        column[0] = [rng.choice(SPECIAL) for _ in range(column.shape[1])]
    f.cycle_s[0] = rng.choice(DURATIONS)
    f.mean_speed_rpm[0] = rng.choice(SPECIAL)
    return cases


@pytest.mark.parametrize("seed", range(4))
def test_zero_durations_overflow_and_nan_agree(seed: int) -> None:
    """0 s cycles and pieces, ±∞, NaN and overflowing products: where numpy gives ±∞ or
    NaN the floats give the same, never ZeroDivisionError or ValueError."""
    rng = random.Random(seed)
    for actuator, app in cells(100 + seed, 80):
        cat = catalogue_arrays([actuator])
        cat.inertia[...] = rng.choice([*SPECIAL[:-1], float(cat.inertia[0])])
        cat.heating_slope[...] = np.where(
            np.isnan(cat.heating_slope), math.nan, rng.choice(SPECIAL[:-1])
        )
        assert_cell_equals_block(cat, with_inputs(cases_of([app]), rng))


def test_a_cycle_of_zero_time_gives_nan_not_an_error() -> None:
    """The case the float helpers are for: 0/0 and √(negative) on floats raise in Python."""
    actuator, app = cells(7, 1)[0]
    cases = cases_of([app])
    cases.pieces.duration[...] = 0.0
    cases.figures.cycle_s[...] = 0.0
    cases.pieces.static[0, 0] = -math.inf
    assert_cell_equals_block(catalogue_arrays([actuator]), cases)


def pairs(values: Sequence[float]) -> list[tuple[float, float]]:
    return list(itertools.product(values, values))


def test_float_helpers_are_numpys_operations() -> None:
    with np.errstate(all="ignore"):
        for a, b in pairs(SPECIAL):
            assert same_bits(float_divide(a, b), np.divide(a, b)), (a, b)
            assert same_bits(float_maximum(a, b), np.maximum(a, b)), (a, b)
        for x in SPECIAL:
            assert same_bits(float_sqrt(x), np.sqrt(x)), x


def assert_cell_block_equals_array_block(
    actuator: Actuator, app: Application, rules: Sequence[Rule] = ALL_RULES, **kw: Any
) -> bool:
    """The block of one cell (on floats) equals the first column of the block of the
    actuator twice (on arrays: each cell computed on its own), every array and every
    operand; whether the floats decided the codes (rather than a formula raising on them,
    leaving them to the arrays)."""
    cases = cases_of([app])
    twice = catalogue_arrays([actuator, actuator])
    cat = catalogue_arrays([actuator])
    with np.errstate(all="ignore"):
        cell = evaluate_block(
            cat, cases, zone_limits([actuator], cat.zone_columns, cases.mean_speed), rules, **kw
        )
        zones = zone_limits([actuator, actuator], twice.zone_columns, cases.mean_speed)
        arrays = evaluate_block(twice, cases, zones, rules, **kw)
    for name in ("accel_torque", "constant_torque", "decel_torque", "rms_torque", "overload"):
        x, y = getattr(cell, name), getattr(arrays, name)
        if y.shape:  # (the overload where none is asked for: 0, of no shape, in both)
            y = y[:, :1]
        assert x.shape == y.shape, name
        assert same_bits(x, y), name
    assert cell.statuses.dtype == arrays.statuses.dtype
    assert np.array_equal(cell.statuses, arrays.statuses[:, :, :1])
    if arrays.checks is None:
        assert cell.checks is None
    else:
        assert cell.checks is not None
        for name in ("values", "limits", "approximate", "first_missing"):
            x, y = getattr(cell.checks, name), getattr(arrays.checks, name)[:, :, :1]
            assert x.dtype == y.dtype, name
            assert x.shape == y.shape, name
            assert same_bits(x, y) if x.dtype == np.float64 else np.array_equal(x, y), name
    if arrays.operands is None:
        assert cell.operands is None
        return True
    q = cell.operands
    assert q is not None
    for name, x, y in zip(q._fields, q, arrays.operands, strict=True):
        column = np.broadcast_to(y, (1, 2))[0, 0]
        assert type(x) is (bool if column.dtype == np.bool_ else float), name
        assert same_bits(x, column) if isinstance(x, float) else x == column, name
    lack = cat.lacking[tuple(rules)]  # found by the block of one cell
    return cell_codes(rules, q, lack, detail=True, overload=True) is not None


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize(("detail", "overload"), [(True, True), (False, True), (False, False)])
def test_one_cells_codes_on_floats_equal_the_arrays(
    seed: int, detail: bool, overload: bool
) -> None:
    rng = random.Random(seed)
    on_floats = 0
    for actuator, app in cells(200 + seed, 40):
        actuator = with_gear_stiffness_brake(rng, actuator) if rng.random() < 0.5 else actuator
        on_floats += assert_cell_block_equals_array_block(
            actuator, app, detail=detail, overload=overload
        )
    if detail:
        assert on_floats >= 30  # the floats decide (a formula seldom raises on them)


def test_one_trapezoid_on_floats_equals_its_arrays_read_back() -> None:
    """A one-model selection's case built on floats straight from the application equals
    its arrays read back, bit for bit: pieces, figures, τ_th, every operand."""
    rng = random.Random(11)
    built = swung = 0
    for _, plain in cells(300, 120):
        app = plain
        if rng.random() < 0.6:  # an output load, τ_th and the request's further inputs
            app = dataclasses.replace(
                plain,
                thermal_time_constant_s=rng.choice([None, 60.0, 900.0]),
                min_natural_frequency_hz=rng.choice([None, 15.0]),
                emergency_stops=rng.choice([None, 150.0]),
                brake_safety_factor=rng.choice([1.5, 2.0]),
                output_load=OutputLoad(
                    radial_force_n=rng.uniform(0, 1.5e4),
                    axial_force_n=rng.uniform(-3e4, 3e4),
                    radial_lever_m=rng.uniform(0, 0.1),
                    axial_lever_m=rng.uniform(0, 0.05),
                ),
            )
        app.profile  # noqa: B018 - the figures are the profile's
        one = OneCase.of(app)
        if one._cases is not None:  # not a trapezoid: from its arrays
            continue
        built += 1
        x, y = one.floats, case_floats(cases_of([app]))
        for name in ("duration", "start_rpm", "end_rpm", "accel_start", "accel_end"):
            assert same_bits(getattr(x, name), getattr(y, name)), name
        for name in ("static", "inertia", "figures"):
            assert same_bits(getattr(x, name), getattr(y, name)), name
        assert (x.braking, x.constant_speed) == (y.braking, y.constant_speed)
        assert x.thermal_assumed is y.thermal_assumed
        assert same_bits(x.thermal_time_constant, y.thermal_time_constant)
        assert x.operands.keys() == y.operands.keys()
        swung += x.operands["swing_deg"] == x.operands["swing_deg"]
        for name, value in x.operands.items():
            assert type(value) is type(y.operands[name]), name
            assert same_bits(value, y.operands[name]), name
    assert built > 20
    assert swung > 10


@pytest.mark.parametrize("seed", range(4))
def test_one_cells_zone_edge_on_floats_equals_the_arrays(seed: int) -> None:
    """``zone_limit_float`` (a one-model selection's zone edge) equals ``zone_limits``'
    array bit for bit: at the zone's corners, between them, beyond the zone, at ±0,
    negative, infinite and NaN n_av, and without a zone."""
    rng = random.Random(400 + seed)
    for actuator, _ in cells(400 + seed, 40):
        cat = catalogue_arrays([actuator])
        corners = [p.speed_rpm for p in actuator.zone.points] if actuator.zone else []
        speeds = [
            *SPECIAL,
            *corners,
            *(rng.uniform(-10, 1.2 * max(corners, default=1)) for _ in range(8)),
        ]
        for speed in speeds:
            array = zone_limits([actuator], cat.zone_columns, np.array([speed], dtype=np.float64))
            edge = array.item() if array.size else math.nan
            assert same_bits(zone_limit_float(actuator, speed), edge), (speed, corners)


def test_operands_by_position_equal_them_by_name_and_refuse_as_before() -> None:
    """``operands_of`` takes the merged names by position; the same operands as by
    keyword, and a name given twice, missing or unknown still refused (TypeError)."""
    names: tuple[str, ...] = Operands._fields
    case = {n: float(k) for k, n in enumerate(names[:20])}
    cat = {n: float(k) for k, n in enumerate(names[20:60], start=20)}
    cell = {n: float(k) for k, n in enumerate(names[60:], start=60)}
    assert operands_of(case, cat, cell) == Operands(**case, **cat, **cell)
    assert list(operands_of(cell, case, cat)) == [float(k) for k in range(len(names))]
    twice = {**cell, names[0]: -1.0}
    missing = {n: v for n, v in cell.items() if n != names[-1]}
    unknown = {**missing, "no_such_operand": 1.0}
    for bad in (twice, missing, unknown):
        with pytest.raises(TypeError):
            operands_of(case, cat, bad)
