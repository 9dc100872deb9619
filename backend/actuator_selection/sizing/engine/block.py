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
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence, Sized
from dataclasses import dataclass
from typing import Any

import numpy as np

from actuator_selection.sizing.checks import RULES, Operands, Rule
from actuator_selection.sizing.checks.rules.gear import AVERAGE_TORQUE_RULES
from actuator_selection.sizing.engine.arrays import (
    PASS,
    WARN,
    BoolArray,
    CodeArray,
    FloatArray,
    IndexArray,
)
from actuator_selection.sizing.engine.cases import Cases, case_operands
from actuator_selection.sizing.engine.catalogue import CatalogueArrays
from actuator_selection.sizing.engine.codes import RuleArrays, RuleDetail, status_codes
from actuator_selection.sizing.motion import PieceArrays, heating_gain, mean_abs_speed_rpm

CHECK_NAMES = tuple(rule.name for rule in RULES)
"""The chapter's checks in flowchart order (:data:`~actuator_selection.sizing.checks.RULES`)."""


_KEPT_PIECES = 16
"""Cycles of up to this many pieces keep each piece's mean T² between the heating check's
two passes (16 arrays of a block: 8 MiB); longer ones recompute it."""

_BLOCK_CELLS = 1 << 16
"""Cases × actuators evaluated per block: the block's arrays stay in the CPU cache,
and memory stays bounded whatever the number of cases."""


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


class _HeatingGains:
    """g = 1 − e^(−t/τ_th) of each piece and of the whole cycle for a block, case ×
    actuator (:meth:`~actuator_selection.sizing.motion.Profile.heating_gains`).

    τ_th is the actuator's catalogue value where published, else the case's (given or
    assumed). The gains are computed with ``math.expm1`` on Python floats
    (:func:`~actuator_selection.sizing.motion.heating_gain`), as Python's floats
    compute them: numpy's ``expm1`` may differ from the C library's in the last bit. Only
    the distinct τ_th values are computed: the case's, and each published one.
    """

    def __init__(self, cat: CatalogueArrays, cases: Cases) -> None:
        published = cat.thermal_time_constant
        known = ~np.isnan(published)
        # The distinct published τ_th, sorted, and each actuator's place among them (at
        # once: one Python step per actuator cost more than the heating at 64,000).
        distinct, where = np.unique(published[known], return_inverse=True)
        values = distinct.tolist()
        # Per case, gains for its own τ_th (column 0) and each published τ_th (1, 2, …).
        taus = [cases.thermal_time_constant, *(np.full(cases.size, v) for v in values)]
        gains = [_case_gains(cases.pieces.duration, cases.figures.cycle_s, tau) for tau in taus]
        self._pieces = np.array([piece for piece, _ in gains], dtype=np.float64).reshape(
            len(taus), cases.size, cases.pieces.duration.shape[1]
        )
        self._cycle = np.array([cycle for _, cycle in gains], dtype=np.float64).reshape(
            len(taus), cases.size
        )
        self._index = np.zeros(published.shape, dtype=np.intp)
        self._index[known] = where.ravel() + 1
        self._mixed = bool(values)
        shape = (cases.size, published.size)
        case_tau = cases.thermal_time_constant[:, np.newaxis]
        self.time_constant: FloatArray = np.where(np.isnan(published), case_tau, published)
        self.assumed: BoolArray = np.isnan(published) & cases.thermal_assumed[:, np.newaxis]
        self._shape = shape
        # Each piece's gains picked once: the heating's two passes and the speed's read them.
        self._piece = [
            self._pick(self._pieces[:, :, k]) for k in range(cases.pieces.duration.shape[1])
        ]

    def _pick(self, table: FloatArray) -> FloatArray:
        """Cases × actuators from a (τ_th columns × cases) table; where no actuator
        publishes τ_th, cases × 1 (broadcast by the arithmetic that uses it)."""
        if not self._mixed:
            column: FloatArray = table[0][:, np.newaxis]
            return column
        return table[self._index].T

    def piece(self, k: int) -> FloatArray:
        """The gains of piece ``k``, cases × actuators."""
        return self._piece[k]

    def cycle(self) -> FloatArray:
        """The gains of the whole cycle, cases × actuators."""
        return self._pick(self._cycle)


def _gains(durations: list[float], tau: float) -> list[float]:
    return [heating_gain(t, tau) for t in durations]


def _distinct_rows(key: FloatArray) -> tuple[FloatArray, IndexArray]:
    """The distinct rows of ``key`` and where each row is among them: grouped by a sum of
    the columns weighted (a sort of floats, not of rows), the grouping then checked row by
    row; sorted as rows where two rows share a sum."""
    with np.errstate(all="ignore"):
        projection = np.zeros(key.shape[0])
        for k in range(key.shape[1]):
            projection = projection + key[:, k] * (1.0 + k / 7.0)
    _, first, where = np.unique(projection, return_index=True, return_inverse=True)
    distinct = key[first]
    if np.array_equal(distinct[where], key):
        return distinct, where.ravel()
    rows = np.ascontiguousarray(key)
    view = rows.view(np.dtype((np.void, rows.itemsize * rows.shape[1]))).ravel()
    _, first, where = np.unique(view, return_index=True, return_inverse=True)
    return rows[first], where.ravel()


def _case_gains(
    durations: FloatArray, cycles: FloatArray, taus: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Per case, the gains of its pieces and of its cycle at its τ_th, each computed once
    per distinct (pieces' durations, cycle, τ_th): cases repeat where the engine runs on
    pairs (:mod:`~actuator_selection.sizing.engine.pairs`), one row per pair."""
    key = np.column_stack([durations, cycles, taus])
    where: IndexArray = np.zeros(key.shape[0], dtype=np.intp)
    if key.shape[0] > 1:
        if (key == key[0]).all():  # one case repeated (pairs of a trapezoid: often)
            key = key[:1]
        else:
            key, where = _distinct_rows(key)
    rows = key.tolist()
    pieces = np.array([_gains(r[:-2], r[-1]) for r in rows], dtype=np.float64)
    cycle = np.array([heating_gain(r[-2], r[-1]) for r in rows], dtype=np.float64)
    return pieces.reshape(len(rows), durations.shape[1])[where], cycle[where]


def _piece_torques(
    cat: CatalogueArrays, p: PieceArrays, k: int
) -> tuple[tuple[FloatArray, ...], FloatArray]:
    """The torques at the ends of piece ``k``, T = c + (J_A + J)·α (one array where the
    acceleration is constant along the piece in every case: a trapezoid's pieces), and
    the mean of T² over the piece (:meth:`~actuator_selection.sizing.motion.Profile.
    thermal_torque_nm`): T_a² where the torque is constant, else (T_a² + T_a·T_b + T_b²)/3.

    Where α is constant the end torque equals the start torque (at most the sign of a
    zero differs), so it is not computed: it could not be of larger magnitude."""
    col = np.newaxis
    inertia = cat.inertia + p.inertia[:, k, col]
    static = p.static[:, k, col]
    t0 = static + inertia * p.accel_start[:, k, col]
    constant = p.accel_start[:, k] == p.accel_end[:, k]
    if constant.all():
        return (t0,), t0 * t0
    t1 = static + inertia * p.accel_end[:, k, col]
    square = np.where(constant[:, col], t0 * t0, (t0 * t0 + t0 * t1 + t1 * t1) / 3.0)
    return (t0, t1), square


def _piece_speeds(p: PieceArrays) -> list[FloatArray]:
    """Each piece's mean |n| (a column of cases), computed once per block for the
    heating (:func:`_heating_square`) and the heating's speed (:func:`_thermal_speed`):
    for every piece at once (the same operations on each element as piece by piece, in
    a sixth of the numpy calls), then a column per piece."""
    speed = mean_abs_speed_rpm(p.duration, p.start_rpm, p.end_rpm, p.accel_start, p.accel_end)
    return [speed[:, k, np.newaxis] for k in range(p.duration.shape[1])]


def _heating_square(cat: CatalogueArrays, speed: FloatArray, square: FloatArray) -> FloatArray:
    """The mean T² of piece ``k`` as the winding's heating counts it
    (:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm` with its
    ``no_load_slope``): (√m + k_T·K_INL·|n̄|)² where :attr:`CatalogueArrays.heating_slope`
    is published, else m; ``speed`` the piece's mean |n| (:func:`_piece_speeds`)."""
    torque = np.sqrt(square) + cat.heating_slope * speed
    return np.where(np.isnan(cat.heating_slope), square, torque * torque)


def _thermal_torque(
    cat: CatalogueArrays,
    cases: Cases,
    gains: _HeatingGains,
    heat: FloatArray,
    energy: FloatArray,
    squares: list[FloatArray] | None,
    speeds: list[FloatArray],
) -> FloatArray:
    """:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm` on arrays: the
    periodic start x_0 = B/(1 − A) from the first pass's ``heat`` (B), then the peak of x
    over the pieces' ends, the torques recomputed piece by piece as in the first pass."""
    col = np.newaxis
    p = cases.pieces
    cycle_gain = gains.cycle()
    cycle_s = cases.figures.cycle_s[:, col]
    start = np.where(
        cycle_gain > 0, heat / np.where(cycle_gain > 0, cycle_gain, 1.0), energy / cycle_s
    )
    peak = heat = start
    on_current = not np.isnan(cat.heating_slope).all()
    for k in range(p.duration.shape[1]):
        if squares is None:
            square = _piece_torques(cat, p, k)[1]
            if on_current:
                square = _heating_square(cat, speeds[k], square)
        else:
            square = squares[k]
        heat = heat + (square - heat) * gains.piece(k)
        peak = np.where(heat > peak, heat, peak)
    return np.sqrt(peak)


def _thermal_speed(cases: Cases, gains: _HeatingGains, speeds: list[FloatArray]) -> FloatArray:
    """:meth:`~actuator_selection.sizing.motion.Profile.thermal_speed_rpm` on arrays: each
    piece's mean |n| (a column of cases), the periodic start y_0 = B/(1 − A), the peak of
    y over the pieces' ends, never below n_av; cases × actuators (or cases × 1 where no
    actuator publishes τ_th)."""
    mean = cases.figures.mean_speed_rpm[:, np.newaxis]
    heat: FloatArray = np.zeros_like(mean)
    for k, speed in enumerate(speeds):
        heat = heat + (speed - heat) * gains.piece(k)
    cycle_gain = gains.cycle()
    start = np.where(cycle_gain > 0, heat / np.where(cycle_gain > 0, cycle_gain, 1.0), mean)
    peak = heat = start
    for k, speed in enumerate(speeds):
        heat = heat + (speed - heat) * gains.piece(k)
        peak = np.where(heat > peak, heat, peak)
    return np.where(peak > mean, peak, mean)


def evaluate_block(
    cat: CatalogueArrays,
    cases: Cases,
    zone_limits: FloatArray,
    rules: Sequence[Rule],
    *,
    detail: bool = False,
    overload: bool = True,
) -> Block:
    """The flowchart for ``cases`` × every actuator (rows × columns); ``detail``: the
    checks' values and limits too; without ``overload``, the block's overload is 0 (not
    computed: a search that reads verdicts and utilisations only).

    The torques are :meth:`~actuator_selection.sizing.motion.Profile.torques` on arrays,
    piece by piece: T = c + (J_A + J)·α at both ends of each piece, ∫T² dt summed in
    order, T_1, T_2, T_3 the signed torques of largest magnitude (the first one on a tie).
    """
    col = np.newaxis
    p = cases.pieces
    # cases × actuators; cases × 1 where the catalogue is a column of pairs (engine.pairs)
    shape = (cases.size, cat.inertia.shape[-1])
    gains = _HeatingGains(cat, cases)
    energy = np.zeros(shape)
    heat = np.zeros(shape)
    # The heating counts the winding current where the catalogue allows (_heating_square).
    on_current = not np.isnan(cat.heating_slope).all()
    heat_energy = np.zeros(shape) if on_current else energy
    # Each piece's mean T², kept for the second pass where the cycle has few pieces (else
    # recomputed there, so that memory stays bounded).
    squares: list[FloatArray] | None = [] if p.duration.shape[1] <= _KEPT_PIECES else None
    accel, accel_abs = np.zeros(shape), np.full(shape, -1.0)
    decel, decel_abs = np.zeros(shape), np.full(shape, -1.0)
    constant, constant_abs = np.full(shape, math.nan), np.full(shape, -1.0)
    # The gear's T_av (rules.gear), summed only where a rule reads it.
    averaged = any(r.name in AVERAGE_TORQUE_RULES for r in rules)
    cube, weight = np.zeros(shape), np.zeros(cases.size)
    # Which extremes each piece can change (a piece brakes, or not, in every case of a
    # trapezoid): an update where no case takes part changes nothing. Per piece: whether
    # any case brakes, any drives, any runs steadily (three calls for all the pieces).
    brakes: list[bool] = np.asarray(p.braking.any(axis=0)).tolist()
    drives: list[bool] = np.asarray(~p.braking.all(axis=0)).tolist()
    runs: list[bool] = np.asarray(p.constant_speed.any(axis=0)).tolist()
    changes = list(zip(brakes, drives, runs, strict=True))
    with np.errstate(all="ignore"):  # as in Python floats: overflow gives inf, masked NaN
        speeds = _piece_speeds(p)  # each piece's mean |n|, for the heating
        for k in range(p.duration.shape[1]):
            torques, square = _piece_torques(cat, p, k)
            # ∫T² dt of the piece: its mean T² times its duration, in the pieces' order.
            energy = energy + square * p.duration[:, k, col]
            if on_current:
                square = _heating_square(cat, speeds[k], square)
                heat_energy = heat_energy + square * p.duration[:, k, col]
            else:
                heat_energy = energy
            heat = heat + (square - heat) * gains.piece(k)
            if squares is not None:
                squares.append(square)
            braking = p.braking[:, k, col]
            steady = p.constant_speed[:, k, col]
            piece_brakes, piece_drives, piece_runs = changes[k]
            if averaged:  # Σ|n|·t·|T|³: at the piece's mean |n|, |T| its larger end
                w = (np.abs(p.start_rpm[:, k]) + np.abs(p.end_rpm[:, k])) / 2.0 * p.duration[:, k]
                largest = np.abs(torques[0])
                if len(torques) > 1:
                    largest = np.maximum(largest, np.abs(torques[1]))
                cube = cube + w[:, col] * (largest * largest * largest)
                weight = weight + w
            for torque in torques:
                magnitude = np.abs(torque)
                if piece_brakes:
                    take = braking & (magnitude > decel_abs)
                    decel = np.where(take, torque, decel)
                    decel_abs = np.where(take, magnitude, decel_abs)
                if piece_drives:
                    take = ~braking & (magnitude > accel_abs)
                    accel = np.where(take, torque, accel)
                    accel_abs = np.where(take, magnitude, accel_abs)
                if piece_runs:
                    take = steady & (magnitude > constant_abs)
                    constant = np.where(take, torque, constant)
                    constant_abs = np.where(take, magnitude, constant_abs)
        rms_torque = np.sqrt(energy / cases.figures.cycle_s[:, col])
        gear_cube = cube / weight[:, col]
        thermal_torque = _thermal_torque(cat, cases, gains, heat, heat_energy, squares, speeds)
        thermal_speed = _thermal_speed(cases, gains, speeds)
    unknown = np.isnan(cat.inertia)  # no J_A: no torques (the candidate's None)
    accel_torque, decel_torque, constant_torque = accel, decel, constant
    if unknown.any():  # each array is of the block's shape: unchanged where J_A is known
        accel_torque = np.where(unknown, math.nan, accel)
        decel_torque = np.where(unknown, math.nan, decel)
        rms_torque = np.where(unknown, math.nan, rms_torque)
        thermal_torque = np.where(unknown, math.nan, thermal_torque)
        constant_torque = np.where(unknown, math.nan, constant)
        gear_cube = np.where(unknown, math.nan, gear_cube)
    zone_torque: FloatArray | float = math.nan  # no zone in the catalogue: NaN everywhere
    if cat.zone_columns.size:
        zone_torque = np.full(shape, math.nan)
        zone_torque[:, cat.zone_columns] = zone_limits
    q = operands_of(
        case_operands(cases),
        cat.operands,
        {
            "accel_torque_nm": accel_torque,
            "decel_torque_nm": decel_torque,
            "rms_torque_nm": rms_torque,
            "zone_torque_nm": zone_torque,
            "thermal_time_constant_s": gains.time_constant,
            "thermal_time_constant_assumed": gains.assumed,
            "thermal_torque_nm": thermal_torque,
            "thermal_speed_rpm": thermal_speed,
            "gear_torque_cube_nm3": gear_cube,
        },
    )
    with np.errstate(all="ignore"):  # NaN where data is missing: masked by the codes
        statuses, worst, checks = status_codes(
            rules, q, cat, shape, detail=detail, overload=overload
        )
    return Block(
        accel_torque=accel_torque,
        constant_torque=constant_torque,
        decel_torque=decel_torque,
        rms_torque=rms_torque,
        statuses=statuses,
        overload=worst,
        checks=checks,
        operands=q if detail else None,
    )


def operands_of(
    case: Mapping[str, Any], catalogue: Mapping[str, Any], cell: Mapping[str, Any]
) -> Operands:
    """The rules' operands, built by name in this one place: the case's
    (:func:`~actuator_selection.sizing.engine.cases.case_operands`, columns of cases), the
    catalogue's (:data:`~actuator_selection.sizing.engine.catalogue.CATALOGUE_OPERANDS`,
    rows of actuators) and the cell's (cases × actuators: the cycle's torques on each
    actuator, the zone's edge, the heating). A name given twice, or one missing, raises."""
    return Operands(**case, **catalogue, **cell)


def blocks(actuators: Sized, apps: Sized) -> list[tuple[int, int]]:
    rows = max(1, _BLOCK_CELLS // max(1, len(actuators)))
    return [(start, min(start + rows, len(apps))) for start in range(0, len(apps), rows)]
