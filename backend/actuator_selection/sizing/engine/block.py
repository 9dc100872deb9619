"""One block of the engine: the flowchart for cases × actuators as arrays.

The cycle's torques on every actuator (:meth:`~actuator_selection.sizing.motion.Profile.
torques` on arrays: T = c + (J_A + J)·α piece by piece, ∫T² dt summed in order), the
winding's heating over the repeating cycle, the operands by name (:func:`operands_of`),
and the rules' status codes (:func:`~actuator_selection.sizing.engine.codes.status_codes`,
every rule at once): no data where a requirement is missing, else pass, fail or warn,
and the overload that ranks what does not fit.

The rules are not written here: those of :mod:`actuator_selection.sizing.checks` compute
their values and limits on the arrays of :class:`~actuator_selection.sizing.checks.Operands`
with numpy's operations (:data:`~actuator_selection.sizing.engine.codes.ARRAY_OPS`).
Every expression performs the same IEEE operations in the same order as the
plain-float flowchart that the tests keep as the oracle (``tests/oracle``; numpy adds no
fused multiply-add, squares are ``x * x``), so both agree bit for bit, which the tests
check with ``==``.

Why a cycle's pieces as one array: a one-model selection is a block of one cell, where
each numpy call costs its fixed overhead whatever the size of its arrays; piece by piece,
its torques, sums and extremes took some fifteen calls a piece. Cases × pieces ×
actuators, they take a fixed few: every element's operations as before, the sums over
the pieces cumulative (``np.add.accumulate`` adds in the pieces' order, where a reduction
may add pairwise), the extremes by ``argmax`` (the first on a tie, as a strict ``>``
piece after piece). Only the heating stays piece by piece (each piece starts from the
last one's heat), T² and |n| in one array in a small block. Facts about the actuators
(the published τ_th, current-based heating, a missing J_A) are found once per catalogue
(:class:`~actuator_selection.sizing.engine.catalogue.CatalogueArrays`).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Mapping, Sequence, Sized
from dataclasses import dataclass
from typing import Any, NamedTuple

import numpy as np

from actuator_selection.sizing.checks import RULES, Operands, Rule
from actuator_selection.sizing.checks.rules.gear import AVERAGE_TORQUE_RULES
from actuator_selection.sizing.engine.arrays import (
    PASS,
    WARN,
    BoolArray,
    CodeArray,
    FloatArray,
)
from actuator_selection.sizing.engine.cases import Cases, case_operands
from actuator_selection.sizing.engine.catalogue import CatalogueArrays
from actuator_selection.sizing.engine.codes import (
    RuleArrays,
    RuleDetail,
    cell_codes,
    lacking,
    status_codes,
)
from actuator_selection.sizing.engine.formulas import (
    ARRAY_MATH,
    FLOAT_MATH,
    faster,
    gear_weight,
    heated_square,
    mean_square,
)
from actuator_selection.sizing.engine.heating import (
    CellGains,
    HeatingGains,
    by_piece,
    heated_over,
    periodic_peak,
)
from actuator_selection.sizing.engine.one_case import CaseFloats, OneCase
from actuator_selection.sizing.motion import PieceArrays, mean_abs_speed_rpm

CHECK_NAMES = tuple(rule.name for rule in RULES)
"""The chapter's checks in flowchart order (:data:`~actuator_selection.sizing.checks.RULES`)."""


_KEPT_PIECES = 16
"""Cycles of up to this many pieces keep each piece's mean T² between the heating check's
two passes (16 arrays of a block: 8 MiB); longer ones recompute it."""

_STACKED_CELLS = 1 << 12
"""Blocks of up to this many cells heat T² and |n| as one array (rather than |n| per
case, cases × 1): half the numpy calls, where a call's fixed cost outweighs its work."""

_BLOCK_CELLS = 1 << 16
"""Cases × actuators evaluated per block: the block's arrays stay in the CPU cache,
and memory stays bounded whatever the number of cases."""

_EACH_END_CELLS = 4096
"""Cells (cases × actuators) from which :func:`_extremes` takes a group's piece ends one
at a time rather than by ``argmax`` over them: about where the two cost the same (50
cases × 64 actuators × 4 ends: 227 µs against 207 µs)."""


@dataclass(frozen=True, slots=True, eq=False)
class Block:
    """The flowchart's results for a block of cases × actuators."""

    accel_torque: FloatArray
    constant_torque: FloatArray
    decel_torque: FloatArray
    rms_torque: FloatArray
    statuses: CodeArray
    """The status codes, rules × cases × actuators (one rule's: ``statuses[k]``)."""
    overload: FloatArray
    """The largest :func:`~actuator_selection.sizing.checks.overload` of the checks."""
    checks: RuleArrays | None = None
    """With ``detail``: each rule's value, limit, approximation and missing requirement,
    rules × cases × actuators."""
    operands: Operands | None = None
    """With ``detail``: what the rules computed from (for the words of their checks)."""

    @property
    def details(self) -> tuple[RuleDetail, ...] | None:
        """:attr:`checks` rule by rule, or None without ``detail``."""
        return None if self.checks is None else tuple(self.checks)

    def verdicts(self) -> CodeArray:
        """The verdict codes, cases × actuators: the largest status code of the checks
        (NOT_APPLICABLE/PASS/WARN → suitable, NO_DATA → unconfirmed, FAIL → unsuitable)."""
        worst: CodeArray = np.maximum.reduce(self.statuses, axis=0, initial=PASS)
        np.subtract(worst, WARN, out=worst)
        np.maximum(worst, 0, out=worst)
        return worst


def _spread(row: FloatArray) -> FloatArray:
    """A catalogue's values (actuators, or a column of pairs: :mod:`~actuator_selection.
    sizing.engine.pairs`) as they broadcast against cases × pieces × actuators."""
    return row[:, np.newaxis, :] if row.ndim == 2 else row


def _piece_torques(
    cat: CatalogueArrays, p: PieceArrays, pieces: slice
) -> tuple[FloatArray, FloatArray]:
    """The torques at the ends of the pieces ``pieces``, T = c + (J_A + J)·α, cases ×
    ends × actuators in the pieces' order (each piece's start, then its end; the starts
    only where the acceleration is constant along every piece in every case: a
    trapezoid's), and the mean of T² over each piece, cases × pieces × actuators
    (:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm`): T_a² where the
    torque is constant, else (T_a² + T_a·T_b + T_b²)/3.

    Where α is constant the end torque equals the start torque (at most the sign of a
    zero differs): it cannot be of larger magnitude, so it changes no extreme."""
    col = np.newaxis
    accel_start, accel_end = p.accel_start[:, pieces], p.accel_end[:, pieces]
    static = p.static[:, pieces, col]
    inertia = _spread(cat.inertia) + p.inertia[:, pieces, col]
    t0 = static + inertia * accel_start[:, :, col]
    constant = accel_start == accel_end
    if constant.all():
        return t0, t0 * t0
    t1 = static + inertia * accel_end[:, :, col]
    square = mean_square(t0, t1, constant[:, :, col], ARRAY_MATH)
    ends = np.stack((t0, t1), axis=2).reshape(t0.shape[0], -1, t0.shape[2])
    return ends, square


def _heating_square(cat: CatalogueArrays, speed: FloatArray, square: FloatArray) -> FloatArray:
    """The mean T² of each piece as the winding's heating counts it
    (:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm` with its
    ``no_load_slope``): (√m + k_T·K_INL·|n̄|)² where :attr:`CatalogueArrays.heating_slope`
    is published, else m; ``speed`` the pieces' mean |n|, cases × pieces × 1."""
    heated: FloatArray = heated_square(square, _spread(cat.heating_slope), speed, ARRAY_MATH)
    return heated


def _added_in_order(total: Any, terms: FloatArray) -> FloatArray:
    """``total`` plus the pieces' ``terms`` (cases × pieces × …, overwritten), added one
    piece after the other as a loop adds them: a cumulative sum along the pieces, whose
    last is the sum (``np.add.reduce`` may add pairwise: another rounding). Where the
    pieces' slices are large, one add per piece instead: the same sums, where
    ``accumulate`` along a middle axis loops over every cell for a few pieces (a block
    of 1,024 cases × 64 actuators, 4 pieces: 9 ms against 0.6 ms)."""
    total_in_order: FloatArray = terms[:, 0]
    np.add(total, total_in_order, out=total_in_order)
    if total_in_order.size < _ADDED_CELLS * terms.shape[1]:
        return np.add.accumulate(terms, axis=1)[:, -1]
    for k in range(1, terms.shape[1]):
        np.add(total_in_order, terms[:, k], out=total_in_order)
    return total_in_order


_ADDED_CELLS = 64
"""Cells of a piece's slice, per piece, from which :func:`_added_in_order` adds piece by
piece rather than by ``np.add.accumulate`` (measured: the two cost alike near it)."""


def _extremes(
    found: FloatArray | None, found_abs: FloatArray, ends: FloatArray, counts: BoolArray
) -> tuple[FloatArray, FloatArray]:
    """T_1, T_2, T_3 (``found``, extremes × cases × actuators, None before the first
    group; their magnitudes ``found_abs``, −1 where none yet) updated with the torques
    ``ends`` (cases × ends × actuators, in the pieces' order) where ``counts``
    (extremes × cases × ends × 1: a driving, a steady, a braking piece's end): the signed
    torque of largest magnitude, the first one on a tie (``argmax``; a NaN counts for
    none), for every extreme at once. Where each end has :data:`_EACH_END_CELLS` cells
    or more, the ends are taken one after the other instead (:func:`_extremes_of_one`;
    a later end replaces an extreme only where its magnitude is larger, so the first of
    equals stays, as ``argmax`` keeps it): the same values, in half the time for a
    block of 200 cases × 64 actuators × 4 ends, and a third more for 1 case."""
    if ends.shape[1] == 1 or ends[:, 0].size >= _EACH_END_CELLS:
        for j in range(ends.shape[1]):  # one end a case at a time
            found, found_abs = _extremes_of_one(found, found_abs, ends[:, j], counts[:, :, j, 0])
        assert found is not None, "a group has an end"
        return found, found_abs
    # |T| where counted, else −1 (a NaN too): two ufuncs over the broadcast shape, where
    # np.where's broadcasting of a scalar took its slow path (the same values)
    magnitude = np.fmax(np.abs(ends), -1.0)
    candidates = np.minimum(magnitude, np.where(counts, math.inf, -1.0))
    largest = candidates.max(axis=2)
    # The torque at the first largest, by its place in ``ends`` flattened (one take, not
    # three index arrays broadcast; take_along_axis costs more in Python).
    n_cases, n_ends, n_actuators = ends.shape
    at = candidates.argmax(axis=2)  # extremes × cases × actuators
    at *= n_actuators
    at += (np.arange(n_cases) * (n_ends * n_actuators))[:, np.newaxis] + np.arange(n_actuators)
    torque = np.take(ends, at)
    if found is None:  # the first group: nothing found before
        return np.where(largest >= 0.0, torque, _NO_EXTREME), largest
    take = largest > found_abs
    return np.where(take, torque, found), np.where(take, largest, found_abs)


def _extremes_of_one(
    found: FloatArray | None, found_abs: FloatArray, ends: FloatArray, counts: BoolArray
) -> tuple[FloatArray, FloatArray]:
    """:func:`_extremes` where each case has one torque (``ends``, cases × actuators;
    ``counts`` extremes × cases): the largest of one is that one, so no maximum, argmax
    or take; an extreme no case counts is left as it is, and one every case counts takes
    |T| as it is. ``found`` and ``found_abs`` are updated in place, after the first group
    (None: the first, whose arrays are made here)."""
    magnitude = np.fmax(np.abs(ends), -1.0)  # |T|, −1 for a NaN: never taken
    if found is None:
        found = np.empty((len(_NO_EXTREMES), *ends.shape))
        found[...] = _NO_EXTREME
        found_abs = np.full(found.shape, -1.0)
    for k, counted in enumerate(counts):
        if not counted.any():
            continue
        largest = magnitude if counted.all() else np.where(counted[:, np.newaxis], magnitude, -1.0)
        take = largest > found_abs[k]
        np.copyto(found[k], ends, where=take)
        np.copyto(found_abs[k], largest, where=take)
    return found, found_abs


_NO_EXTREMES = (0.0, math.nan, 0.0)
"""T_1, T_2, T_3 where no piece counts: 0, NaN (no constant-speed piece), 0."""
_NO_EXTREME = np.array(_NO_EXTREMES)[:, np.newaxis, np.newaxis]


def _regrouped(
    cat: CatalogueArrays, p: PieceArrays, group: int
) -> Iterator[tuple[int, FloatArray]]:
    """Each ``group`` of pieces' mean T² as the heating counts it, recomputed (a long
    cycle's, not kept between the heating's two passes)."""
    for first in range(0, p.duration.shape[1], group):
        pieces = slice(first, first + group)
        square = _piece_torques(cat, p, pieces)[1]
        if cat.on_current:
            square = _heating_square(cat, _mean_speeds(p, pieces), square)
        yield first, by_piece(square)


def _mean_speeds(p: PieceArrays, pieces: slice = slice(None)) -> FloatArray:
    """The pieces' mean |n| (:func:`~actuator_selection.sizing.motion.mean_abs_speed_rpm`),
    cases × pieces × 1: every piece at once, the same operations on each element."""
    columns: tuple[FloatArray, ...] = (
        p.duration,
        p.start_rpm,
        p.end_rpm,
        p.accel_start,
        p.accel_end,
    )
    if pieces != slice(None):
        columns = tuple(c[:, pieces] for c in columns)
    speed: FloatArray = mean_abs_speed_rpm(*columns)
    return speed[:, :, np.newaxis]


def evaluate_block(
    cat: CatalogueArrays,
    cases: Cases | OneCase,
    zone_limits: FloatArray | float,
    rules: Sequence[Rule],
    *,
    detail: bool = False,
    overload: bool = True,
) -> Block:
    """The flowchart for ``cases`` × every actuator (rows × columns; one case as
    :class:`~actuator_selection.sizing.engine.one_case.OneCase`, its arrays built only for
    more than one actuator); ``detail``: the checks' values and limits too; without
    ``overload``, the block's overload is 0 (not computed: a search that reads verdicts
    and utilisations only).

    The torques are :meth:`~actuator_selection.sizing.motion.Profile.torques` on arrays,
    for a group of pieces at once (cases × pieces × actuators; as many pieces as keep a
    group within :data:`_BLOCK_CELLS`, at most :data:`_KEPT_PIECES`: a small block's
    whole cycle in one group, so that its numpy calls do not grow with its pieces):
    T = c + (J_A + J)·α at both ends of each piece, ∫T² dt summed in the pieces' order,
    T_1, T_2, T_3 the signed torques of largest magnitude (the first one on a tie).
    """
    # The gear's T_av (rules.gear), summed only where a rule reads it.
    averaged = any(r.name in AVERAGE_TORQUE_RULES for r in rules)
    with np.errstate(all="ignore"):  # as in Python floats: overflow gives inf, masked NaN
        if cases.size == 1 and cat.inertia.size == 1:  # one cell: on its floats
            one = cases if isinstance(cases, OneCase) else OneCase.of_cases(cases)
            return _cell_block(cat, one, zone_limits, rules, averaged, detail, overload)
        if isinstance(cases, OneCase):
            cases = cases.cases
        # cases × actuators; cases × 1 where the catalogue is a column of pairs (engine.pairs)
        shape = (cases.size, cat.inertia.shape[-1])
        cycle = _block_cycle(cat, cases, shape, averaged)
        zone_torque: FloatArray | float = math.nan  # no zone in the catalogue: NaN everywhere
        if cat.zone_columns.size:
            zone_torque = np.full(shape, math.nan)
            zone_torque[:, cat.zone_columns] = zone_limits
        q = operands_of(case_operands(cases), cat.operands, cycle.operands(zone_torque))
        # NaN where data is missing: masked by the codes
        statuses, worst, checks = status_codes(
            rules, q, cat, shape, detail=detail, overload=overload
        )
    return Block(
        accel_torque=cycle.accel_torque,
        constant_torque=cycle.constant_torque,
        decel_torque=cycle.decel_torque,
        rms_torque=cycle.rms_torque,
        statuses=statuses,
        overload=worst,
        checks=checks,
        operands=q if detail else None,
    )


class _Cycle(NamedTuple):
    """A block's cycle on its actuators (:func:`_block_cycle`: arrays, cases × actuators;
    :func:`_cell_cycle`: one cell's floats)."""

    accel_torque: Any
    constant_torque: Any
    decel_torque: Any
    rms_torque: Any
    thermal_torque: Any
    """The heating's torque over the repeating cycle."""
    thermal_speed: Any
    """The heating's speed over the repeating cycle, at least n_av."""
    gear_cube: Any
    """The gear's Σ|n|·t·|T|³/Σ|n|·t; NaN where no rule reads it."""
    time_constant: Any
    """τ_th: the actuator's published one, else the case's."""
    assumed: Any
    """Whether τ_th is assumed."""

    def operands(self, zone_torque: Any) -> dict[str, Any]:
        """The cell's operands by name (:func:`operands_of`), with the zone's edge."""
        return {
            "accel_torque_nm": self.accel_torque,
            "decel_torque_nm": self.decel_torque,
            "rms_torque_nm": self.rms_torque,
            "zone_torque_nm": zone_torque,
            "thermal_time_constant_s": self.time_constant,
            "thermal_time_constant_assumed": self.assumed,
            "thermal_torque_nm": self.thermal_torque,
            "thermal_speed_rpm": self.thermal_speed,
            "gear_torque_cube_nm3": self.gear_cube,
        }


def _cell_block(
    cat: CatalogueArrays,
    one: OneCase,
    zone_limits: FloatArray | float,
    rules: Sequence[Rule],
    averaged: bool,
    detail: bool,
    overload: bool,
) -> Block:
    """:func:`evaluate_block` of one case × one actuator on Python floats: the cycle
    (:func:`_cell_cycle`), the operands (the case's, the catalogue's and the cell's as
    floats) and the rules' codes (:func:`~actuator_selection.sizing.engine.codes.
    cell_codes`); on arrays of one cell where a rule's formula raises on floats (numpy
    gives ±∞ or NaN there). Its :attr:`Block.operands` are the floats (a check's words
    read them as floats). Called with numpy's errors ignored."""
    case = one.floats
    cycle = _cell_cycle(cat, case, averaged)
    if isinstance(zone_limits, float):  # the zone's edge as a float (zone_limit_float)
        zone_torque = zone_limits
    elif cat.zone_columns.size:  # 1 × 1: the one actuator's
        zone_torque = float(zone_limits.item())
    else:
        zone_torque = math.nan
    cell = cycle.operands(zone_torque)
    q = operands_of(case.operands, cat.operand_floats(), cell)

    def on_arrays() -> Operands:
        column = {name: np.full((1, 1), value) for name, value in cell.items()}
        return operands_of(case_operands(one.cases), cat.operands, column)

    lack = cat.lacking.get(tuple(rules))
    if lack is None:  # the first time for these actuators and rules
        lack = lacking(rules, on_arrays(), cat)
    found = cell_codes(rules, q, lack, detail=detail, overload=overload)
    if found is None:  # a formula raised on floats: the arrays' ±∞ and NaN
        found = status_codes(rules, on_arrays(), cat, (1, 1), detail=detail, overload=overload)
    statuses, worst, checks = found
    torques = np.array(cycle[:4]).reshape(4, 1, 1)  # T_1, T_2, T_3, T_rms
    return Block(
        accel_torque=torques[0],
        constant_torque=torques[1],
        decel_torque=torques[2],
        rms_torque=torques[3],
        statuses=statuses,
        overload=worst,
        checks=checks,
        operands=q if detail else None,
    )


def _block_cycle(
    cat: CatalogueArrays, cases: Cases, shape: tuple[int, int], averaged: bool
) -> _Cycle:
    """:func:`evaluate_block`'s cycle on arrays: T_1, T_2, T_3, T_rms, the heating's
    torque and speed, the gear's Σ|n|·t·|T|³/Σ|n|·t (NaN where no rule reads it), τ_th
    and whether it is assumed, cases × actuators. Called with numpy's errors ignored."""
    col = np.newaxis
    p = cases.pieces
    count = p.duration.shape[1]
    group = max(1, min(_KEPT_PIECES, _BLOCK_CELLS // max(1, shape[0] * shape[1])))
    gains = HeatingGains(cat, cases)
    # The heating counts the winding current where the catalogue allows (_heating_square).
    on_current = cat.on_current
    energy: Any = 0.0
    heat_energy: Any = 0.0
    heat: Any = 0.0
    # Each group's mean T², kept for the second pass where the cycle has few pieces (else
    # recomputed there, so that memory stays bounded).
    squares: list[FloatArray] | None = [] if count <= _KEPT_PIECES else None
    found: FloatArray | None = None  # T_1, T_2, T_3 (extremes × cases × actuators)
    found_abs: FloatArray = _NO_EXTREME  # their magnitudes
    cube: Any = 0.0
    weight: Any = 0.0
    # Which extremes each piece's torques count for: driving, steady, braking.
    counting = np.stack((~p.braking, p.constant_speed, p.braking))[..., col]
    speeds = _mean_speeds(p)  # each piece's mean |n|, for the heating
    for first in range(0, count, group):
        pieces = slice(first, first + group)
        ends, square = _piece_torques(cat, p, pieces)
        duration = p.duration[:, pieces]
        # ∫T² dt of the pieces: each one's mean T² times its duration, in order.
        energy = _added_in_order(energy, square * duration[:, :, col])
        if on_current:
            square = _heating_square(cat, speeds[:, pieces], square)
            heat_energy = _added_in_order(heat_energy, square * duration[:, :, col])
        else:
            heat_energy = energy
        if squares is None:  # a long cycle: its first heating pass group by group
            heat, _ = heated_over(heat, by_piece(square), gains, first)
        else:
            squares.append(square)
        counts = counting[:, :, pieces]
        if ends.shape[1] > square.shape[1]:  # a start and an end per piece
            counts = counts.repeat(2, axis=2)
        found, found_abs = _extremes(found, found_abs, ends, counts)
        if averaged:  # Σ|n|·t·|T|³: at the piece's mean |n|, |T| its larger end
            w = gear_weight(p.start_rpm[:, pieces], p.end_rpm[:, pieces], duration)
            largest = np.abs(ends)
            if ends.shape[1] > square.shape[1]:
                largest = np.maximum(largest[:, 0::2], largest[:, 1::2])
            cube = _added_in_order(cube, w[:, :, col] * (largest * largest * largest))
            weight = _added_in_order(weight, w.copy())
    assert found is not None
    accel, constant, decel = found
    rms_torque = np.sqrt(energy / cases.figures.cycle_s[:, col])
    gear_cube = cube / weight[:, col] if averaged else math.nan  # no rule reads it
    # The heating's peaks (Profile.thermal_torque_nm, .thermal_speed_rpm): of T², and
    # of |n| (at least n_av), over the repeating cycle.
    mean = cases.figures.mean_speed_rpm[:, col]
    torque_fallback = heat_energy / cases.figures.cycle_s[:, col]
    if squares is None:  # the second pass recomputes each group's mean T²
        torque_peak = periodic_peak(
            heat,
            lambda: _regrouped(cat, p, group),
            gains,
            torque_fallback,
        )
    else:
        square = squares[0] if len(squares) == 1 else np.concatenate(squares, axis=1)
        if shape[0] * shape[1] <= _STACKED_CELLS:  # T² and |n| heated as one array
            sources = np.empty((2, *square.shape))
            sources[0], sources[1] = square, speeds
            fallback = np.empty((2, *shape))
            fallback[0], fallback[1] = torque_fallback, mean
            split = by_piece(sources)
            torque_peak, speed_peak = periodic_peak(
                heated_over(0.0, split, gains)[0],
                lambda: ((0, split),),
                gains,
                fallback,
            )
        else:
            split = by_piece(square)
            torque_peak = periodic_peak(
                heated_over(0.0, split, gains)[0],
                lambda: ((0, split),),
                gains,
                torque_fallback,
            )
    if squares is None or shape[0] * shape[1] > _STACKED_CELLS:
        split = by_piece(speeds)
        speed_peak = periodic_peak(
            heated_over(0.0, split, gains)[0], lambda: ((0, split),), gains, mean
        )
    thermal_torque = np.sqrt(torque_peak)
    thermal_speed = faster(speed_peak, mean, ARRAY_MATH)
    accel_torque, decel_torque, constant_torque = accel, decel, constant
    if cat.inertia_unknown:  # no J_A: no torques (the candidate's None); each array is
        unknown = np.isnan(cat.inertia)  # of the block's shape: unchanged where J_A is known
        accel_torque = np.where(unknown, math.nan, accel)
        decel_torque = np.where(unknown, math.nan, decel)
        rms_torque = np.where(unknown, math.nan, rms_torque)
        thermal_torque = np.where(unknown, math.nan, thermal_torque)
        constant_torque = np.where(unknown, math.nan, constant)
        gear_cube = np.where(unknown, math.nan, gear_cube)
    return _Cycle(
        accel_torque,
        constant_torque,
        decel_torque,
        rms_torque,
        thermal_torque,
        thermal_speed,
        gear_cube,
        gains.time_constant,
        gains.assumed,
    )


def _cell_cycle(cat: CatalogueArrays, case: CaseFloats, averaged: bool) -> _Cycle:
    """:func:`_block_cycle` for one case × one actuator, on Python floats: the same
    formulas (:mod:`~actuator_selection.sizing.engine.formulas` with
    :data:`~actuator_selection.sizing.engine.formulas.FLOAT_MATH`, :func:`heated_over`,
    :func:`periodic_peak`), piece after piece, each sum in the pieces' order and each
    extreme the first of largest magnitude, as the arrays' cumulative sums and ``argmax``
    take them; the results as arrays of one cell. A piece whose acceleration is constant
    counts its start torque only (its end's is equal, at most the sign of a zero differs:
    never a larger magnitude, never the first)."""
    m = FLOAT_MATH
    t, n0, n1 = case.duration, case.start_rpm, case.end_rpm
    a0, a1 = case.accel_start, case.accel_end
    static, load_inertia = case.static, case.inertia
    braking, steady = case.braking, case.constant_speed
    cell = cat.cell_floats()
    j_a, slope = cell.inertia, cell.heating_slope
    cycle, mean = case.cycle_s, case.mean_speed_rpm
    gains = CellGains(cell, case)
    inertia = [j_a + j for j in load_inertia]
    t0 = [c + j * a for c, j, a in zip(static, inertia, a0, strict=True)]
    t1 = [c + j * a for c, j, a in zip(static, inertia, a1, strict=True)]
    constant = [x == y for x, y in zip(a0, a1, strict=True)]
    squares = [mean_square(x, y, c, m) for x, y, c in zip(t0, t1, constant, strict=True)]
    speeds = [mean_abs_speed_rpm(*piece) for piece in zip(*(t, n0, n1, a0, a1), strict=True)]
    energy = heat_energy = 0.0
    for square, duration in zip(squares, t, strict=True):
        energy = energy + square * duration
    heating = squares
    if cat.on_current:
        heating = [heated_square(x, slope, n, m) for x, n in zip(squares, speeds, strict=True)]
        for square, duration in zip(heating, t, strict=True):
            heat_energy = heat_energy + square * duration
    else:
        heat_energy = energy
    # T_1, T_2, T_3: the first end of largest magnitude among the driving, steady, braking
    # pieces' (a strict >, as argmax takes the first; a NaN magnitude never counts, as a
    # candidate of −1 in the arrays: every counted magnitude is ≥ 0 > −1)
    ends = [(x,) if c else (x, y) for x, y, c in zip(t0, t1, constant, strict=True)]
    found = list(_NO_EXTREMES)
    largest = [-1.0, -1.0, -1.0]
    for piece_ends, brakes, steady_piece in zip(ends, braking, steady, strict=True):
        counting = (not brakes, steady_piece, brakes)
        for end in piece_ends:
            magnitude = abs(end)
            for k in (0, 1, 2):
                if counting[k] and magnitude > largest[k]:
                    found[k], largest[k] = end, magnitude
    accel, constant_torque, decel = found
    gear_cube = math.nan  # no rule reads it
    if averaged:  # Σ|n|·t·|T|³: at the piece's mean |n|, |T| its larger end
        cube = weight = 0.0
        for x, y, start, end, duration in zip(t0, t1, n0, n1, t, strict=True):
            w = gear_weight(start, end, duration)
            larger = m.maximum(abs(x), abs(y))
            cube = cube + w * (larger * larger * larger)
            weight = weight + w
        gear_cube = m.divide(cube, weight)
    rms_torque = m.sqrt(m.divide(energy, cycle))
    torque_peak = periodic_peak(
        heated_over(0.0, heating, gains, math_=m)[0],
        lambda: ((0, heating),),
        gains,
        m.divide(heat_energy, cycle),
        m,
    )
    speed_peak = periodic_peak(
        heated_over(0.0, speeds, gains, math_=m)[0], lambda: ((0, speeds),), gains, mean, m
    )
    thermal_torque = m.sqrt(torque_peak)
    if j_a != j_a:  # no J_A: no torques (the candidate's None)
        accel = decel = rms_torque = thermal_torque = constant_torque = gear_cube = math.nan
    return _Cycle(
        accel,
        constant_torque,
        decel,
        rms_torque,
        thermal_torque,
        faster(speed_peak, mean, m),
        gear_cube,
        gains.time_constant,
        gains.assumed,
    )


def operands_of(
    case: Mapping[str, Any], catalogue: Mapping[str, Any], cell: Mapping[str, Any]
) -> Operands:
    """The rules' operands, built by name in this one place: the case's
    (:func:`~actuator_selection.sizing.engine.cases.case_operands`, columns of cases), the
    catalogue's (:data:`~actuator_selection.sizing.engine.catalogue.CATALOGUE_OPERANDS`,
    rows of actuators) and the cell's (cases × actuators: the cycle's torques on each
    actuator, the zone's edge, the heating). A name given twice, or one missing, raises.

    Taken by position from the three merged (``Operands._make``): some eighty keywords
    bound by name cost a one-model selection more than its numpy calls do; where the
    names do not match the fields one to one, by keyword, which raises."""
    merged = {**case, **catalogue, **cell}
    if len(merged) == len(_OPERAND_FIELDS) == len(case) + len(catalogue) + len(cell):
        try:
            return Operands._make(map(merged.__getitem__, _OPERAND_FIELDS))
        except KeyError:  # a name that is not a field, and so one missing
            pass
    return Operands(**case, **catalogue, **cell)


_OPERAND_FIELDS: tuple[str, ...] = Operands._fields


def blocks(actuators: Sized, apps: Sized) -> list[tuple[int, int]]:
    rows = max(1, _BLOCK_CELLS // max(1, len(actuators)))
    return [(start, min(start + rows, len(apps))) for start in range(0, len(apps), rows)]
