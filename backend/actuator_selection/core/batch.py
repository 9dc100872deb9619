"""The selection flowchart for many load cases at once, vectorised with numpy.

An ERP sizes thousands of load cases against the same catalogue. This module runs
the flowchart of :mod:`actuator_selection.core.selection` for every case × actuator
as arrays: the cycle figures (Eq. 514.1–514.4), the status of each check, the verdicts
and the ranking (:func:`~actuator_selection.core.selection.ranking_key`), and then
details the :class:`~actuator_selection.core.selection.Candidate` of only the best
``top`` actuators of each case from the same arrays: each check is the rule's own
:meth:`~actuator_selection.core.checks.Rule.report` of the arrays' decision, value and
limit (the method the scalar flowchart's checks end in), built, with its words, when
first read. So they are those of a single selection as long as the arrays are, bit for
bit, which the tests check.

The checks are not written here: the rules of :mod:`actuator_selection.core.checks`
(the table the scalar flowchart runs) compute their values and limits on arrays of
:class:`~actuator_selection.core.checks.Operands` with numpy's operations
(:data:`ARRAY_OPS`); this module supplies the operands and turns each rule's
comparison into status codes.

That is only right if the arrays decide exactly as the scalar code does. They do,
bit for bit: every expression performs the same IEEE operations in the same order as
:meth:`~actuator_selection.core.motion.Profile.torques` (numpy adds no fused
multiply-add; squares are ``x * x`` on both sides), the figures that do not depend on the
actuator come from the one function :func:`~actuator_selection.core.motion.cycle_figures`
for both, and a catalogue value that is ``None`` is NaN here (as in the scalar operands)
and masked by the rule's requirements.

The tests compare every array with the scalar flowchart with ``==``.

Worked example (Table 516.1 against the FHA-25C-50-L of Table 516.3), two cases:

>>> from actuator_selection.core.cycle import Load, SpeedPattern
>>> fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50,
...                max_torque_nm=151, max_speed_rpm=90, inertia_kgm2=0.86)
>>> pattern = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1)
>>> apps = [Application(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=1.3)),
...         Application(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=3.0))]
>>> ev = evaluate_batch([fha], apps)
>>> [round(t, 2) for t in ev.accel_torque_nm[:, 0].tolist()]
[95.48, 166.69]
>>> [ev.verdict(i, 0).value for i in range(2)]
['unconfirmed', 'unsuitable']
>>> [s.candidates[0].verdict.value for s in select_batch([fha], apps, top=1)]
['unconfirmed', 'unsuitable']
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Collection, Iterator, Sequence, Sized
from dataclasses import dataclass, fields
from dataclasses import field as dataclasses_field
from itertools import repeat
from typing import Any

import numpy as np
import numpy.typing as npt

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.bearing import life_exponent, swing_deg
from actuator_selection.core.checks import (
    RULES,
    Check,
    DeferredChecks,
    Operands,
    Ops,
    Rule,
    Status,
)
from actuator_selection.core.cycle import Load, SpeedPattern
from actuator_selection.core.deferred import Deferred
from actuator_selection.core.electrical import no_load_torque_slope_nm_per_rpm
from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.motion import (
    CycleFigures,
    CycleTorques,
    Motion,
    PieceArrays,
    Profile,
    cycle_figures,
    figure_rows,
    figures_of,
    heating_gain,
    mean_abs_speed_rpm,
    piece_arrays,
    profile_from,
    trapezoid_piece_arrays,
)
from actuator_selection.core.selection import (
    Application,
    Candidate,
    Selection,
    Verdict,
    require_time_constant,
)
from actuator_selection.core.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S

FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]
CodeArray = npt.NDArray[np.int8]
IndexArray = npt.NDArray[np.intp]

CHECK_NAMES = tuple(rule.name for rule in RULES)
"""The chapter's checks in flowchart order (:data:`~actuator_selection.core.checks.RULES`)."""


def _python_pow(x: Any, exponent: float) -> Any:
    """``math.pow`` element by element: bit for bit what the scalar flowchart computes
    (numpy's power differs in the last bit for some inputs). The rules raise only case
    quantities to a power, so the arrays are one column of cases."""
    base = np.asarray(x, dtype=np.float64)
    flat = base.ravel().tolist()
    powers = np.fromiter(map(math.pow, flat, repeat(exponent)), np.float64, len(flat))
    return powers.reshape(base.shape)


ARRAY_OPS = Ops(where=np.where, isnan=np.isnan, not_=np.logical_not, sqrt=np.sqrt, pow=_python_pow)
"""The rules' operations on numpy arrays (the scalar flowchart uses
:data:`~actuator_selection.core.checks.FLOAT_OPS`)."""

STATUS_BY_CODE = (Status.PASS, Status.WARN, Status.NO_DATA, Status.FAIL)
"""Status codes of :attr:`BatchEvaluation.statuses`, ordered so that the largest code of
a candidate's checks decides its verdict (any fail, else any no data)."""

VERDICT_BY_CODE = (Verdict.SUITABLE, Verdict.UNCONFIRMED, Verdict.UNSUITABLE)
"""Verdict codes of :attr:`BatchEvaluation.verdicts`, in ranking order."""

_PASS, _WARN, _NO_DATA, _FAIL = (np.int8(c) for c in range(4))

_KEPT_PIECES = 16
"""Cycles of up to this many pieces keep each piece's mean T² between the heating check's
two passes (16 arrays of a block: 8 MiB); longer ones recompute it."""

_BLOCK_CELLS = 1 << 16
"""Cases × actuators evaluated per block: the block's arrays stay in the CPU cache,
and memory stays bounded whatever the number of cases."""


def _optional(values: Sequence[float | None]) -> FloatArray:
    return np.array([math.nan if v is None else v for v in values], dtype=np.float64)


@dataclass(frozen=True, slots=True, eq=False)
class CatalogueArrays:
    """The actuators as columns; NaN where the catalogue gives no value."""

    max_torque: FloatArray
    max_speed: FloatArray
    inertia: FloatArray
    stall: FloatArray
    continuous: FloatArray
    continuous_speed: FloatArray
    rated_speed: FloatArray
    brake_holding: FloatArray
    thermal_time_constant: FloatArray
    no_load_torque_slope: FloatArray
    """k_T·K_INL per actuator (:attr:`~actuator_selection.core.checks.Operands.
    no_load_torque_slope_nm_per_rpm`); NaN where not published."""
    heating_slope: FloatArray
    """k_T·K_INL where the heating follows the winding current (no zone, T_0 published:
    :meth:`~actuator_selection.core.motion.Profile.thermal_torque_nm`), else NaN."""
    has_zone: BoolArray
    drive: dict[str, FloatArray]
    """The drive's and the output bearing's values, by their :class:`Operands` name."""
    zone_max_speed: FloatArray
    zone_columns: IndexArray
    rank_position: npt.NDArray[np.int32]
    lacking: dict[Rule, tuple[CodeArray, BoolArray]] = dataclasses_field(default_factory=dict)
    """Per rule, where the catalogue misses its requirements (:func:`_lacking`), filled
    when the rule is first evaluated against these actuators."""


def catalogue_arrays(actuators: Sequence[Actuator]) -> CatalogueArrays:
    """The actuators as the vectorised flowchart reads them; build once per catalogue and
    pass to :func:`evaluate_batch` to spare it per request."""
    has_zone = np.array([a.zone is not None for a in actuators], dtype=np.bool_)
    # ranking_key after the verdict: T_max, then J_A (unknown last), then the model name;
    # the column index mirrors sorted()'s stability for equal keys.
    inf = math.inf
    order = sorted(
        range(len(actuators)),
        key=lambda j: (
            inf if actuators[j].max_torque_nm is None else actuators[j].max_torque_nm,
            inf if actuators[j].inertia_kgm2 is None else actuators[j].inertia_kgm2,
            actuators[j].model,
            j,
        ),
    )
    rank_position = np.empty(len(actuators), dtype=np.int32)
    rank_position[order] = np.arange(len(actuators), dtype=np.int32)
    slopes = [
        no_load_torque_slope_nm_per_rpm(
            torque_constant_nm_per_a=a.torque_constant_nm_per_a,
            constant_30c_a_per_rpm=a.no_load_current_constant_30c_a_per_rpm,
            constant_80c_a_per_rpm=a.no_load_current_constant_80c_a_per_rpm,
        )
        for a in actuators
    ]
    return CatalogueArrays(
        max_torque=_optional([a.max_torque_nm for a in actuators]),
        max_speed=_optional([a.max_speed_rpm for a in actuators]),
        inertia=_optional([a.inertia_kgm2 for a in actuators]),
        stall=_optional([a.stall_torque_nm for a in actuators]),
        continuous=_optional([a.continuous_torque_nm for a in actuators]),
        continuous_speed=_optional([a.continuous_speed_rpm for a in actuators]),
        rated_speed=_optional([a.rated_speed_rpm for a in actuators]),
        brake_holding=_optional([a.brake_holding_torque_nm for a in actuators]),
        thermal_time_constant=_optional([a.thermal_time_constant_s for a in actuators]),
        no_load_torque_slope=_optional(slopes),
        heating_slope=_optional(
            [
                s if a.zone is None and a.stall_torque_nm is not None else None
                for s, a in zip(slopes, actuators, strict=True)
            ]
        ),
        has_zone=has_zone,
        drive=_drive_columns(actuators),
        zone_max_speed=_optional([a.zone.max_speed_rpm if a.zone else None for a in actuators]),
        zone_columns=np.flatnonzero(has_zone),
        rank_position=rank_position,
    )


def _drive_columns(actuators: Sequence[Actuator]) -> dict[str, FloatArray]:
    """The actuators' drive and output bearing values as selection.operands reads them."""

    def milli(value: float | None) -> float | None:
        return None if value is None else value / 1000.0

    def column(values: Sequence[float | None]) -> FloatArray:
        return _optional(values)

    a = actuators
    return {
        "gear_ratio": column([x.gear_ratio for x in a]),
        "torque_constant_nm_per_a": column([x.torque_constant_nm_per_a for x in a]),
        "max_current_a": column([x.max_current_a for x in a]),
        "no_load_starting_current_a": column([x.no_load_starting_current_a for x in a]),
        "no_load_current_constant_a_per_rpm": column(
            [x.no_load_current_constant_30c_a_per_rpm for x in a]
        ),
        "motor_voltage_constant_v_per_krpm": column(
            [x.motor_voltage_constant_v_per_krpm for x in a]
        ),
        "resistance_line_ohm": column([x.resistance_line_ohm for x in a]),
        "inductance_line_h": column([milli(x.inductance_line_mh) for x in a]),
        "pole_pairs": column([x.pole_pairs for x in a]),
        "dc_bus_voltage_v": column([x.dc_bus_voltage_v for x in a]),
        "bearing_pitch_diameter_m": column([x.output_bearing_pitch_diameter_m for x in a]),
        "bearing_offset_m": column([x.output_bearing_offset_m for x in a]),
        "bearing_dynamic_load_rating_n": column(
            [x.output_bearing_dynamic_load_rating_n for x in a]
        ),
        "bearing_static_load_rating_n": column([x.output_bearing_static_load_rating_n for x in a]),
        "bearing_life_exponent": column([life_exponent(x.output_bearing_type) for x in a]),
        "bearing_moment_load_nm": column([x.output_bearing_moment_load_nm for x in a]),
        "bearing_dynamic_tilting_moment_nm": column(
            [x.output_bearing_dynamic_tilting_moment_nm for x in a]
        ),
    }


_OUTPUT_LOAD_FIELDS = (
    "radial_force_n",
    "axial_force_n",
    "radial_lever_m",
    "axial_lever_m",
    "load_factor",
    "static_safety_min",
    "required_life_h",
)
"""The output load's fields, as :class:`Operands` and ``OutputLoad`` name them."""


@dataclass(frozen=True, slots=True, eq=False)
class _Cases:
    """The load cases as rows: their cycles' pieces and figures."""

    pieces: PieceArrays
    figures: CycleFigures
    load_inertia: FloatArray
    high_dynamics: BoolArray
    output_load: FloatArray
    """The output load per case (cases × :data:`_OUTPUT_LOAD_FIELDS`); NaN where none."""
    thermal_time_constant: FloatArray
    """τ_th per case where the catalogue gives none: the case's, else the default."""
    thermal_assumed: BoolArray
    """Whether that τ_th is the assumed default."""

    @property
    def size(self) -> int:
        return self.load_inertia.size

    @property
    def mean_speed(self) -> FloatArray:
        return self.figures.mean_speed_rpm

    def rows(self, start: int, stop: int) -> _Cases:
        """The cases ``start:stop``."""
        if start == 0 and stop >= self.size:
            return self
        p, f = self.pieces, self.figures
        return _Cases(
            pieces=PieceArrays(**{x.name: getattr(p, x.name)[start:stop] for x in fields(p)}),
            figures=CycleFigures(**{x.name: getattr(f, x.name)[start:stop] for x in fields(f)}),
            load_inertia=self.load_inertia[start:stop],
            high_dynamics=self.high_dynamics[start:stop],
            output_load=self.output_load[start:stop],
            thermal_time_constant=self.thermal_time_constant[start:stop],
            thermal_assumed=self.thermal_assumed[start:stop],
        )


def _cases(apps: Sequence[Application]) -> _Cases:
    shorthand = [(a.pattern, a.load) for a in apps if a.pattern is not None and a.load]
    if len(shorthand) == len(apps):  # the chapter's trapezoids only: as columns

        def column(values: list[float]) -> FloatArray:
            return np.array(values, dtype=np.float64)

        inertia = column([load.inertia_kgm2 for _, load in shorthand])
        pieces = trapezoid_piece_arrays(
            speed_rpm=column([p.speed_rpm for p, _ in shorthand]),
            accel_s=column([p.accel_s for p, _ in shorthand]),
            constant_s=column([p.constant_s for p, _ in shorthand]),
            decel_s=column([p.decel_s for p, _ in shorthand]),
            pause_s=column([p.pause_s for p, _ in shorthand]),
            torque_nm=column([load.torque_nm for _, load in shorthand]),
            inertia_kgm2=inertia,
        )
    else:
        motions = [a.cycle for a in apps]
        pieces = piece_arrays(motions)
        inertia = np.array([m.load.inertia_kgm2 for m in motions], dtype=np.float64)
    # A profile already computed holds its cycle's figures (a single selection's).
    profiles = [p for p in (a.known_profile for a in apps) if p is not None]
    figures = figures_of(profiles) if len(profiles) == len(apps) else cycle_figures(pieces)
    return _Cases(
        pieces=pieces,
        figures=figures,
        load_inertia=inertia,
        high_dynamics=np.array([a.high_dynamics for a in apps], dtype=np.bool_),
        output_load=_output_loads(apps),
        thermal_time_constant=np.array(
            [
                DEFAULT_THERMAL_TIME_CONSTANT_S if tau is None else tau
                for tau in (a.thermal_time_constant_s for a in apps)
            ],
            dtype=np.float64,
        ),
        thermal_assumed=np.array([a.thermal_time_constant_s is None for a in apps], dtype=np.bool_),
    )


def _swing(cases: _Cases) -> FloatArray:
    """Each case's swing (:func:`~actuator_selection.core.bearing.swing_deg`) where it has
    an output load, NaN elsewhere, as the scalar flowchart's operands give it."""
    loaded = ~np.isnan(cases.output_load[:, 0])
    if not loaded.any():
        return np.full(cases.size, math.nan)
    p = cases.pieces
    columns = zip(
        p.duration.T, p.start_rpm.T, p.end_rpm.T, p.accel_start.T, p.accel_end.T, strict=True
    )
    with np.errstate(all="ignore"):
        swing = swing_deg(columns, np.where)
    return np.asarray(np.where(loaded, swing, math.nan), dtype=np.float64)


def _output_loads(apps: Sequence[Application]) -> FloatArray:
    nan = math.nan
    rows = [
        [nan] * len(_OUTPUT_LOAD_FIELDS)
        if a.output_load is None
        else [
            nan if v is None else v
            for v in (getattr(a.output_load, name) for name in _OUTPUT_LOAD_FIELDS)
        ]
        for a in apps
    ]
    return np.array(rows, dtype=np.float64).reshape(len(apps), len(_OUTPUT_LOAD_FIELDS))


def _zone_limits(
    actuators: Sequence[Actuator], columns: IndexArray, mean_speed: FloatArray
) -> FloatArray:
    """ContinuousDutyZone.torque_limit_nm(n_av) per case × zone column; NaN beyond the zone."""
    limits = np.full((mean_speed.size, columns.size), math.nan)
    for k, j in enumerate(columns.tolist()):
        zone = actuators[j].zone
        assert zone is not None
        speeds = np.array([p.speed_rpm for p in zone.points], dtype=np.float64)
        torques = np.array([p.torque_nm for p in zone.points], dtype=np.float64)
        last = speeds.size - 1
        i = np.searchsorted(speeds, mean_speed, side="right")  # bisect_right
        b = np.minimum(i, last)
        a = b - 1
        with np.errstate(all="ignore"):  # rows outside the zone are masked below
            share = (mean_speed - speeds[a]) / (speeds[b] - speeds[a])
            edge = torques[a] + share * (torques[b] - torques[a])
        edge = np.where(i > last, torques[last], edge)
        inside = (mean_speed >= 0) & (mean_speed <= speeds[last])
        limits[:, k] = np.where(inside, edge, math.nan)
    return limits


@dataclass(frozen=True, slots=True, eq=False)
class _RuleArrays:
    """What :meth:`~actuator_selection.core.checks.Rule.check` reports, for a block: each
    array broadcasts to the block's shape (cases × actuators)."""

    values: FloatArray
    """The value checked; NaN where unknown (the scalar reports None)."""
    limits: FloatArray
    """The limit; NaN where there is none (no data, or beyond a zone's last speed)."""
    approximate: BoolArray | np.bool_
    first_missing: CodeArray
    """Index into the rule's requirements of the first one missing; −1 where none is."""


@dataclass(frozen=True, slots=True, eq=False)
class _Block:
    accel_torque: FloatArray
    constant_torque: FloatArray
    decel_torque: FloatArray
    rms_torque: FloatArray
    statuses: tuple[CodeArray, ...]
    overload: FloatArray
    """The largest :func:`~actuator_selection.core.checks.overload` of the checks."""
    details: tuple[_RuleArrays, ...] | None = None
    operands: Operands | None = None
    """With ``detail``: what the rules computed from (for the words of their checks)."""

    def verdicts(self) -> CodeArray:
        worst = np.full(self.accel_torque.shape, _PASS)
        for codes in self.statuses:
            np.maximum(worst, codes, out=worst)
        # PASS/WARN → suitable, NO_DATA → unconfirmed, FAIL → unsuitable.
        np.subtract(worst, _WARN, out=worst)
        np.maximum(worst, 0, out=worst)
        return worst


def _lacking(rule: Rule, q: Operands, cat: CatalogueArrays) -> tuple[CodeArray, BoolArray]:
    """Per actuator, the index of the first of ``rule``'s requirements the catalogue does
    not meet (−1: none), and whether any requirement after the first is unmet.

    A requirement names catalogue values only (:class:`~actuator_selection.core.checks.
    Requirement`), so this is a fact about the actuators, computed once per catalogue
    and rule: six rules' requirements were a fifth of a whole-catalogue selection's
    vectorised flowchart."""
    found = cat.lacking.get(rule)
    if found is not None:
        return found
    n = cat.inertia.shape
    first_missing: CodeArray = np.full(n, -1, dtype=np.int8)
    others_missing: BoolArray = np.zeros(n, dtype=np.bool_)
    for k, need in enumerate(rule.requires):
        lacking = need.missing(q, ARRAY_OPS)
        assert np.shape(lacking) == n, f"{rule.name}: a requirement names a case's value"
        first_missing = np.where((first_missing < 0) & lacking, np.int8(k), first_missing)
        if k:
            others_missing = others_missing | lacking
    found = cat.lacking[rule] = (first_missing, others_missing)
    return found


def _status_codes(
    rule: Rule,
    q: Operands,
    cat: CatalogueArrays,
    *,
    detail: bool = False,
) -> tuple[CodeArray, FloatArray, _RuleArrays | None]:
    """The codes of one rule for the block (:meth:`~actuator_selection.core.checks.Rule.check`
    on arrays): no data where a requirement is missing, else pass, fail or warn; the
    overload (:func:`~actuator_selection.core.checks.overload`); with ``detail``, also the
    value, limit, approximation and missing requirement it reports. Each array is of the
    block's shape or broadcasts to it (a column of cases, a row of actuators, a
    scalar): its readers broadcast, and a whole-catalogue selection spared ~25
    ``np.broadcast_to`` calls.

    Called with numpy's floating-point errors ignored: NaN where data is missing is
    masked here."""
    xp = ARRAY_OPS
    first_missing, others_missing = _lacking(rule, q, cat)  # per actuator
    value, limit = rule.value(q, xp), rule.limit(q, xp)
    # numpy's True, not Python's: ~True is −2, which would make the masks integers.
    within = np.True_ if rule.within is None else rule.within(q, xp)
    ok = value <= limit if rule.within is None else (value <= limit) & within
    binding = np.True_ if rule.binding is None else rule.binding(q, xp)
    missing = first_missing >= 0
    if rule.lower_bound is not None:  # Rule.check's _floor_failure, on arrays
        floor = rule.lower_bound(q, xp)
        floor_fails = (first_missing == 0) & ~others_missing & ((floor > limit) | ~within) & binding
        value = np.where(floor_fails, floor, value)
        missing = missing & ~floor_fails
    fail = _FAIL if rule.binding is None else np.where(binding, _FAIL, _WARN)
    codes = np.where(missing, _NO_DATA, np.where(ok, _PASS, fail))  # cases × actuators
    if rule.lower_bound is not None:
        codes = np.where(floor_fails, _FAIL, codes)
    no_limit = np.isnan(limit) | (limit <= 0) | np.isnan(value)
    over = np.where(no_limit, math.inf, np.maximum(value / limit, 1.0))
    overload = np.where(codes == _FAIL, over, 0.0)
    if not detail:
        return codes, overload, None
    approximate = np.False_ if rule.approximate is None else rule.approximate(q, xp) & ~missing
    return (
        codes,
        overload,
        _RuleArrays(
            values=value,
            limits=np.where(missing, math.nan, limit),
            approximate=approximate,
            first_missing=first_missing,
        ),
    )


class _HeatingGains:
    """g = 1 − e^(−t/τ_th) of each piece and of the whole cycle for a block, case ×
    actuator (:meth:`~actuator_selection.core.motion.Profile.heating_gains`).

    τ_th is the actuator's catalogue value where published, else the case's (given or
    assumed). The gains are computed with ``math.expm1`` on Python floats
    (:func:`~actuator_selection.core.motion.heating_gain`), as the scalar flowchart
    computes them: numpy's ``expm1`` may differ from the C library's in the last bit. Only
    the distinct τ_th values are computed: the case's, and each published one.
    """

    def __init__(self, cat: CatalogueArrays, cases: _Cases) -> None:
        published = cat.thermal_time_constant
        values = sorted({float(v) for v in published.tolist() if v == v})
        # Per case, gains for its own τ_th (column 0) and each published τ_th (1, 2, …).
        taus = [cases.thermal_time_constant.tolist(), *([v] * cases.size for v in values)]
        durations = cases.pieces.duration.tolist()
        cycles = cases.figures.cycle_s.tolist()
        self._pieces = np.array(
            [
                [_gains(row, tau) for row, tau in zip(durations, column, strict=True)]
                for column in taus
            ],
            dtype=np.float64,
        ).reshape(len(taus), cases.size, cases.pieces.duration.shape[1])
        self._cycle = np.array(
            [
                [heating_gain(c, tau) for c, tau in zip(cycles, column, strict=True)]
                for column in taus
            ],
            dtype=np.float64,
        ).reshape(len(taus), cases.size)
        lookup = {v: i + 1 for i, v in enumerate(values)}
        self._index = np.array(
            [0 if v != v else lookup[float(v)] for v in published.tolist()], dtype=np.intp
        )
        self._mixed = bool(values)
        shape = (cases.size, published.size)
        case_tau = cases.thermal_time_constant[:, np.newaxis]
        self.time_constant: FloatArray = np.where(np.isnan(published), case_tau, published)
        self.assumed: BoolArray = np.isnan(published) & cases.thermal_assumed[:, np.newaxis]
        self._shape = shape

    def _pick(self, table: FloatArray) -> FloatArray:
        """Cases × actuators from a (τ_th columns × cases) table; where no actuator
        publishes τ_th, cases × 1 (broadcast by the arithmetic that uses it)."""
        if not self._mixed:
            column: FloatArray = table[0][:, np.newaxis]
            return column
        return table[self._index].T

    def piece(self, k: int) -> FloatArray:
        """The gains of piece ``k``, cases × actuators."""
        return self._pick(self._pieces[:, :, k])

    def cycle(self) -> FloatArray:
        """The gains of the whole cycle, cases × actuators."""
        return self._pick(self._cycle)


def _gains(durations: list[float], tau: float) -> list[float]:
    return [heating_gain(t, tau) for t in durations]


def _piece_torques(
    cat: CatalogueArrays, p: PieceArrays, k: int
) -> tuple[tuple[FloatArray, ...], FloatArray]:
    """The torques at the ends of piece ``k``, T = c + (J_A + J)·α (one array where the
    acceleration is constant along the piece in every case: a trapezoid's pieces), and
    the mean of T² over the piece (:meth:`~actuator_selection.core.motion.Profile.
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


def _heating_square(cat: CatalogueArrays, p: PieceArrays, k: int, square: FloatArray) -> FloatArray:
    """The mean T² of piece ``k`` as the winding's heating counts it
    (:meth:`~actuator_selection.core.motion.Profile.thermal_torque_nm` with its
    ``no_load_slope``): (√m + k_T·K_INL·|n̄|)² where :attr:`CatalogueArrays.heating_slope`
    is published, else m."""
    col = np.newaxis
    speed = mean_abs_speed_rpm(
        p.duration[:, k, col],
        p.start_rpm[:, k, col],
        p.end_rpm[:, k, col],
        p.accel_start[:, k, col],
        p.accel_end[:, k, col],
    )
    torque = np.sqrt(square) + cat.heating_slope * speed
    return np.where(np.isnan(cat.heating_slope), square, torque * torque)


def _thermal_torque(
    cat: CatalogueArrays,
    cases: _Cases,
    gains: _HeatingGains,
    heat: FloatArray,
    energy: FloatArray,
    squares: list[FloatArray] | None,
) -> FloatArray:
    """:meth:`~actuator_selection.core.motion.Profile.thermal_torque_nm` on arrays: the
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
    on_current = bool(np.any(~np.isnan(cat.heating_slope)))
    for k in range(p.duration.shape[1]):
        if squares is None:
            square = _piece_torques(cat, p, k)[1]
            if on_current:
                square = _heating_square(cat, p, k, square)
        else:
            square = squares[k]
        heat = heat + (square - heat) * gains.piece(k)
        peak = np.where(heat > peak, heat, peak)
    return np.sqrt(peak)


def _thermal_speed(cases: _Cases, gains: _HeatingGains) -> FloatArray:
    """:meth:`~actuator_selection.core.motion.Profile.thermal_speed_rpm` on arrays: each
    piece's mean |n| (a column of cases), the periodic start y_0 = B/(1 − A), the peak of
    y over the pieces' ends, never below n_av; cases × actuators (or cases × 1 where no
    actuator publishes τ_th)."""
    col = np.newaxis
    p = cases.pieces
    mean = cases.figures.mean_speed_rpm[:, col]
    speeds = [
        mean_abs_speed_rpm(
            p.duration[:, k, col],
            p.start_rpm[:, k, col],
            p.end_rpm[:, k, col],
            p.accel_start[:, k, col],
            p.accel_end[:, k, col],
        )
        for k in range(p.duration.shape[1])
    ]
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


def _evaluate_block(
    cat: CatalogueArrays,
    cases: _Cases,
    zone_limits: FloatArray,
    rules: Sequence[Rule],
    *,
    detail: bool = False,
) -> _Block:
    """The flowchart for ``cases`` × every actuator (rows × columns); ``detail``: the
    checks' values and limits too.

    The torques are :meth:`~actuator_selection.core.motion.Profile.torques` on arrays,
    piece by piece: T = c + (J_A + J)·α at both ends of each piece, ∫T² dt summed in
    order, T_1, T_2, T_3 the signed torques of largest magnitude (the first one on a tie).
    """
    col = np.newaxis
    p = cases.pieces
    shape = (cases.size, cat.inertia.size)
    gains = _HeatingGains(cat, cases)
    energy = np.zeros(shape)
    heat = np.zeros(shape)
    # The heating counts the winding current where the catalogue allows (_heating_square).
    on_current = bool(np.any(~np.isnan(cat.heating_slope)))
    heat_energy = np.zeros(shape) if on_current else energy
    # Each piece's mean T², kept for the second pass where the cycle has few pieces (else
    # recomputed there, so that memory stays bounded).
    squares: list[FloatArray] | None = [] if p.duration.shape[1] <= _KEPT_PIECES else None
    accel, accel_abs = np.zeros(shape), np.full(shape, -1.0)
    decel, decel_abs = np.zeros(shape), np.full(shape, -1.0)
    constant, constant_abs = np.full(shape, math.nan), np.full(shape, -1.0)
    with np.errstate(all="ignore"):  # as in Python floats: overflow gives inf, masked NaN
        for k in range(p.duration.shape[1]):
            torques, square = _piece_torques(cat, p, k)
            # ∫T² dt of the piece: its mean T² times its duration, as the scalar sums it.
            energy = energy + square * p.duration[:, k, col]
            if on_current:
                square = _heating_square(cat, p, k, square)
                heat_energy = heat_energy + square * p.duration[:, k, col]
            else:
                heat_energy = energy
            heat = heat + (square - heat) * gains.piece(k)
            if squares is not None:
                squares.append(square)
            braking = p.braking[:, k, col]
            steady = p.constant_speed[:, k, col]
            # Which extremes the piece can change (a piece brakes, or not, in every case
            # of a trapezoid): an update where no case takes part changes nothing.
            brakes, drives, runs = braking.any(), not braking.all(), steady.any()
            for torque in torques:
                magnitude = np.abs(torque)
                if brakes:
                    take = braking & (magnitude > decel_abs)
                    decel = np.where(take, torque, decel)
                    decel_abs = np.where(take, magnitude, decel_abs)
                if drives:
                    take = ~braking & (magnitude > accel_abs)
                    accel = np.where(take, torque, accel)
                    accel_abs = np.where(take, magnitude, accel_abs)
                if runs:
                    take = steady & (magnitude > constant_abs)
                    constant = np.where(take, torque, constant)
                    constant_abs = np.where(take, magnitude, constant_abs)
        rms_torque = np.sqrt(energy / cases.figures.cycle_s[:, col])
        thermal_torque = _thermal_torque(cat, cases, gains, heat, heat_energy, squares)
        thermal_speed = _thermal_speed(cases, gains)
    unknown = np.isnan(cat.inertia)  # no J_A: no torques (the scalar's None)
    accel_torque = np.where(unknown, math.nan, accel)
    decel_torque = np.where(unknown, math.nan, decel)
    rms_torque = np.where(unknown, math.nan, rms_torque)
    thermal_torque = np.where(unknown, math.nan, thermal_torque)
    constant_torque = np.where(unknown, math.nan, constant)
    f = cases.figures
    zone_torque: FloatArray | float = math.nan  # no zone in the catalogue: NaN everywhere
    if cat.zone_columns.size:
        zone_torque = np.full(shape, math.nan)
        zone_torque[:, cat.zone_columns] = zone_limits
    q = Operands(
        speed_rpm=f.peak_speed_rpm[:, col],
        load_inertia_kgm2=cases.load_inertia[:, col],
        high_dynamics=cases.high_dynamics[:, col],
        mean_speed_rpm=f.mean_speed_rpm[:, col],
        accel_torque_nm=accel_torque,
        decel_torque_nm=decel_torque,
        rms_torque_nm=rms_torque,
        max_torque_nm=cat.max_torque,
        max_speed_rpm=cat.max_speed,
        inertia_kgm2=cat.inertia,
        stall_torque_nm=cat.stall,
        continuous_torque_nm=cat.continuous,
        has_zone=cat.has_zone,
        zone_torque_nm=zone_torque,
        zone_max_speed_rpm=cat.zone_max_speed,
        accel_torque_floor_nm=f.accel_floor_nm[:, col],
        decel_torque_floor_nm=f.decel_floor_nm[:, col],
        rms_torque_floor_nm=f.rms_floor_nm[:, col],
        continuous_speed_rpm=cat.continuous_speed,
        rated_speed_rpm=cat.rated_speed,
        load_torque_nm=p.holding[:, col],
        brake_holding_torque_nm=cat.brake_holding,
        decel_s=f.braking_s[:, col],
        **cat.drive,
        **{name: cases.output_load[:, k, col] for k, name in enumerate(_OUTPUT_LOAD_FIELDS)},
        swing_deg=_swing(cases)[:, col],
        cycle_s=f.cycle_s[:, col],
        thermal_time_constant_s=gains.time_constant,
        thermal_time_constant_assumed=gains.assumed,
        thermal_torque_nm=thermal_torque,
        thermal_speed_rpm=thermal_speed,
        no_load_torque_slope_nm_per_rpm=cat.no_load_torque_slope,
    )
    with np.errstate(all="ignore"):  # NaN where data is missing: masked by the codes
        results = [_status_codes(r, q, cat, detail=detail) for r in rules]
    details = [d for _, _, d in results if d is not None]
    overload = np.zeros(shape)
    for _, over, _ in results:
        np.maximum(overload, over, out=overload)
    return _Block(
        accel_torque=accel_torque,
        constant_torque=constant_torque,
        decel_torque=decel_torque,
        rms_torque=rms_torque,
        statuses=tuple(codes for codes, _, _ in results),
        overload=overload,
        details=tuple(details) if detail else None,
        operands=q if detail else None,
    )


def _blocks(actuators: Sequence[Actuator], apps: Sized) -> list[tuple[int, int]]:
    rows = max(1, _BLOCK_CELLS // max(1, len(actuators)))
    return [(start, min(start + rows, len(apps))) for start in range(0, len(apps), rows)]


@dataclass(frozen=True, slots=True, eq=False, kw_only=True)
class BatchEvaluation:
    """The flowchart for every case (rows) × actuator (columns), as arrays.

    Torques are NaN where the actuator has no J_A (the scalar ``torques`` is None).
    Every number equals, bit for bit, what the scalar functions give.
    """

    mean_speed_rpm: FloatArray
    """n_av per case (Eq. 514.3) [rpm]."""
    duty_cycle_percent: FloatArray
    """ED per case (Eq. 514.4) [%]."""
    cycle_time_s: FloatArray
    """t_0 per case [s]."""
    accel_torque_nm: FloatArray
    """T_1 per case × actuator (Eq. 514.1) [Nm]."""
    constant_torque_nm: FloatArray
    """T_2 per case × actuator [Nm]; NaN where the cycle never runs at constant speed."""
    decel_torque_nm: FloatArray
    """T_3 per case × actuator [Nm]."""
    rms_torque_nm: FloatArray
    """T_rms per case × actuator (Eq. 514.2) [Nm]."""
    statuses: CodeArray
    """Status codes (:data:`STATUS_BY_CODE`), case × actuator × check (:attr:`check_names`)."""
    verdicts: CodeArray
    """Verdict codes (:data:`VERDICT_BY_CODE`), case × actuator."""
    values: FloatArray
    """Each check's value, case × actuator × check; NaN where unknown."""
    limits: FloatArray
    """Each check's limit, case × actuator × check; NaN where it has none."""
    approximate: BoolArray
    """Where a check's limit is a simplified stand-in, case × actuator × check."""
    first_missing: CodeArray
    """Per case × actuator × check, the index of the first requirement of the rule that
    the catalogue does not meet (its ``what`` in :attr:`missing_what`); −1: none."""
    worst_overload: FloatArray
    """Per case × actuator, the largest overload of its checks
    (:attr:`~actuator_selection.core.selection.Candidate.worst_overload`)."""
    missing_what: tuple[tuple[str, ...], ...] = ()
    """Per check, its requirements' ``what`` (:class:`~actuator_selection.core.checks.
    Requirement`), in order."""
    check_names: tuple[str, ...] = CHECK_NAMES
    """The checks (the rules' names) along the last axis of :attr:`statuses`."""
    rank_position: npt.NDArray[np.int32] = dataclasses_field(
        default_factory=lambda: np.empty(0, dtype=np.int32)
    )
    """Each actuator's place in the static order (T_max, J_A, model) that breaks ties."""

    def status(self, case: int, actuator: int, check: str) -> Status:
        """The status of one check of one case and actuator."""
        return STATUS_BY_CODE[int(self.statuses[case, actuator, self.check_names.index(check)])]

    def missing(self, case: int, actuator: int, check: str) -> str | None:
        """What the catalogue lacks for one check (``Check.missing``), or None."""
        k = self.check_names.index(check)
        index = int(self.first_missing[case, actuator, k])
        return None if index < 0 else self.missing_what[k][index]

    def verdict(self, case: int, actuator: int) -> Verdict:
        """The verdict of one case and actuator."""
        return VERDICT_BY_CODE[int(self.verdicts[case, actuator])]

    def ranking(self, case: int) -> list[int]:
        """The actuators of one case, best first
        (:func:`~actuator_selection.core.selection.ranking_key`: verdict, worst overload,
        then T_max, J_A and model)."""
        order = np.lexsort((self.rank_position, self.worst_overload[case], self.verdicts[case]))
        ranked: list[int] = order.tolist()
        return ranked


def evaluate_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> BatchEvaluation:
    """Run the flowchart for every case × actuator and keep every array.

    Parameters
    ----------
    actuators
        The catalogue, columns in this order.
    apps
        The load cases, rows in this order.
    rules
        The checks (:data:`~actuator_selection.core.checks.RULES`: the chapter's).
    arrays
        ``catalogue_arrays(actuators)``, where the caller keeps it.

    Memory grows with cases × actuators (about 40 bytes a cell); for ranking alone
    use :func:`select_batch`, which keeps only the best of each case.
    """
    rules = _rules_of(apps, rules)
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    cases = _cases(apps)
    zone_limits = _zone_limits(actuators, cat.zone_columns, cases.mean_speed)
    shape = (len(apps), len(actuators))
    accel, constant, decel, rms = (np.empty(shape) for _ in range(4))
    checks = (*shape, len(rules))
    statuses = np.empty(checks, dtype=np.int8)
    values, limits = np.empty(checks), np.empty(checks)
    approximate = np.empty(checks, dtype=np.bool_)
    first_missing = np.empty(checks, dtype=np.int8)
    verdicts = np.empty(shape, dtype=np.int8)
    worst_overload = np.empty(shape)
    for start, stop in _blocks(actuators, apps):
        rows = cases.rows(start, stop)
        block = _evaluate_block(cat, rows, zone_limits[start:stop], rules, detail=True)
        assert block.details is not None
        accel[start:stop] = block.accel_torque
        constant[start:stop] = block.constant_torque
        decel[start:stop] = block.decel_torque
        rms[start:stop] = block.rms_torque
        for k, (codes, detail) in enumerate(zip(block.statuses, block.details, strict=True)):
            statuses[start:stop, :, k] = codes
            values[start:stop, :, k] = detail.values
            limits[start:stop, :, k] = detail.limits
            approximate[start:stop, :, k] = detail.approximate
            first_missing[start:stop, :, k] = detail.first_missing
        verdicts[start:stop] = block.verdicts()
        worst_overload[start:stop] = block.overload
    return BatchEvaluation(
        mean_speed_rpm=cases.figures.mean_speed_rpm,
        duty_cycle_percent=cases.figures.duty_cycle_percent,
        cycle_time_s=cases.figures.cycle_s,
        accel_torque_nm=accel,
        constant_torque_nm=constant,
        decel_torque_nm=decel,
        rms_torque_nm=rms,
        statuses=statuses,
        verdicts=verdicts,
        values=values,
        limits=limits,
        approximate=approximate,
        first_missing=first_missing,
        worst_overload=worst_overload,
        missing_what=tuple(tuple(need.what for need in rule.requires) for rule in rules),
        check_names=tuple(rule.name for rule in rules),
        rank_position=cat.rank_position,
    )


def _allowed_columns(
    actuators: Sequence[Actuator], models: Sequence[Collection[str] | None]
) -> list[BoolArray | None]:
    """Per case, the columns its ``models`` list allows (None: every one)."""
    column_of: dict[str, list[int]] = {}
    for j, a in enumerate(actuators):
        column_of.setdefault(a.model, []).append(j)
    masks: dict[frozenset[str], BoolArray] = {}
    allowed: list[BoolArray | None] = []
    for names in models:
        if names is None:
            allowed.append(None)
            continue
        key = frozenset(names)
        if key not in masks:
            mask = np.zeros(len(actuators), dtype=np.bool_)
            mask[[j for name in key for j in column_of.get(name, ())]] = True
            masks[key] = mask
        allowed.append(masks[key])
    return allowed


@dataclass(frozen=True, slots=True, eq=False)
class _RankedBlock:
    """A block of cases ranked: its cases (from row ``start``), the flowchart's arrays, and
    each row's best ``top`` columns with where they are kept (False past the actuators a
    case's ``models`` allows)."""

    start: int
    cases: _Cases
    block: _Block
    verdicts: CodeArray
    """The block's verdict codes (:data:`VERDICT_BY_CODE`), beyond them where a case's
    ``models`` leave an actuator out."""
    order: IndexArray
    kept: BoolArray


def _ranked_blocks(
    actuators: Sequence[Actuator],
    cases: _Cases,
    *,
    top: int,
    models: Sequence[Collection[str] | None] | None,
    rules: Sequence[Rule],
    detail: bool,
    arrays: CatalogueArrays | None = None,
) -> Iterator[_RankedBlock]:
    """The cases ranked block by block (:func:`~actuator_selection.core.selection.
    ranking_key`); ``detail``: with each check's values for the candidates' detail. The
    arguments as :func:`select_batch` has checked them, ``rules`` resolved."""
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    zone_limits = _zone_limits(actuators, cat.zone_columns, cases.mean_speed)
    allowed = _allowed_columns(actuators, models) if models is not None else None
    excluded = np.int8(len(VERDICT_BY_CODE))  # a verdict code beyond every verdict
    keep = min(top, len(actuators))
    for start, stop in _blocks(actuators, range(cases.size)):
        rows = cases.rows(start, stop)
        block = _evaluate_block(cat, rows, zone_limits[start:stop], rules, detail=detail)
        # ranking_key: verdict, the worst overload (0 unless unsuitable), then the
        # actuator's place in the static order (T_max, J_A, model).
        verdicts = block.verdicts()
        if allowed is not None:
            for row, mask in enumerate(allowed[start:stop]):
                if mask is not None:
                    verdicts[row, ~mask] = excluded
        position = np.broadcast_to(cat.rank_position, verdicts.shape)
        order = np.lexsort((position, block.overload, verdicts), axis=-1)[:, :keep]
        kept = np.take_along_axis(verdicts, order, axis=1) < excluded
        yield _RankedBlock(
            start=start, cases=rows, block=block, verdicts=verdicts, order=order, kept=kept
        )


def _rules_of(apps: Sequence[Application], rules: Sequence[Rule] | None) -> Sequence[Rule]:
    """``rules``, or the rules the cases need (:attr:`Application.rules`), one set for all."""
    if rules is not None:
        return rules
    needed = {app.rules for app in apps}
    if len(needed) > 1:
        raise InvalidInputError(
            "brake",
            "cases with different checks (with and without a brake or an output load) "
            "need separate runs",
        )
    return needed.pop() if needed else RULES


def _check_arguments(cases: int, top: int, models: Sequence[Collection[str] | None] | None) -> None:
    if top < 1:
        raise InvalidInputError("top", "must be ≥ 1: the number of candidates kept per case")
    if models is not None and len(models) != cases:
        raise InvalidInputError("models", "needs one entry (or None) per load case")


def rank_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    top: int = 3,
    models: Sequence[Collection[str] | None] | None = None,
    rules: Sequence[Rule] | None = None,
) -> list[list[int]]:
    """Per case, the indexes into ``actuators`` of its best ``top``, best first.

    The ranking of :func:`select` (:func:`~actuator_selection.core.selection.ranking_key`)
    without building the candidates; arguments as for :func:`select_batch`.
    """
    _check_arguments(len(apps), top, models)
    rules = _rules_of(apps, rules)
    chosen: list[list[int]] = []
    for ranked in _ranked_blocks(
        actuators, _cases(apps), top=top, models=models, rules=rules, detail=False
    ):
        chosen.extend(
            [j for j, k in zip(row, row_kept, strict=True) if k]
            for row, row_kept in zip(ranked.order.tolist(), ranked.kept.tolist(), strict=True)
        )
    return chosen


_TRAPEZOID_FIELDS = (
    "speed_rpm",
    "accel_s",
    "constant_s",
    "decel_s",
    "pause_s",
    "torque_nm",
    "inertia_kgm2",
)
"""The chapter's figures of a load case (Table 516.1): n_2, t_1, t_2, t_3, t_p, T_L, J_L."""


@dataclass(frozen=True, slots=True, kw_only=True)
class TrapezoidColumns:
    """Load cases of the chapter's shorthand as columns, one row per case: the speed
    pattern of Fig. 516.2 at the output (n_2, t_1, t_2, t_3, t_p) and the load (T_L,
    J_L), as :class:`~actuator_selection.core.cycle.SpeedPattern` and
    :class:`~actuator_selection.core.cycle.Load` take them, for :func:`rank_columns`.

    A row those classes refuse is refused here with their error, its field named with
    the row (``speed_rpm.17``): the rules are theirs, checked for the whole column at
    once and worded by the scalar classes for the first row that breaks one.
    """

    speed_rpm: FloatArray
    accel_s: FloatArray
    constant_s: FloatArray
    decel_s: FloatArray
    pause_s: FloatArray
    torque_nm: FloatArray
    inertia_kgm2: FloatArray
    high_dynamics: BoolArray
    """J_L ≤ 3·J_A is binding where true, a warning where false."""
    thermal_time_constant_s: float | None = None
    """τ_th where the catalogue gives none (every case alike); None: the default, assumed."""

    def __post_init__(self) -> None:
        size = self.speed_rpm.size
        if size == 0:
            raise InvalidInputError("speed_rpm", "needs one value per load case, at least one")
        for name in (*_TRAPEZOID_FIELDS, "high_dynamics"):
            column = getattr(self, name)
            if column.ndim != 1 or column.size != size:
                raise ValueError(f"{name}: one value per case ({size}), got {column.shape}")
        with np.errstate(invalid="ignore"):
            broken = (
                (self.speed_rpm <= 0)
                | (self.accel_s <= 0)
                | (self.decel_s <= 0)
                | (self.constant_s < 0)
                | (self.pause_s < 0)
                | (self.torque_nm < 0)
                | (self.inertia_kgm2 < 0)
            )
        for name in _TRAPEZOID_FIELDS:
            broken |= ~np.isfinite(getattr(self, name))
        if broken.any():
            self._refuse(int(np.argmax(broken)))
        require_time_constant(self.thermal_time_constant_s)

    def _refuse(self, row: int, actuator_inertia: float | None = None) -> None:
        """Raise the scalar flowchart's error for ``row`` (the cycle's, or its torques' with
        ``actuator_inertia``), its field named with the row (``speed_rpm.17``)."""
        figures = {name: float(getattr(self, name)[row]) for name in _TRAPEZOID_FIELDS}
        try:
            app = Application(
                pattern=SpeedPattern(**{k: v for k, v in figures.items() if k in _PATTERN_FIELDS}),
                load=Load(torque_nm=figures["torque_nm"], inertia_kgm2=figures["inertia_kgm2"]),
            )
            profile = app.profile
            if actuator_inertia is not None:
                profile.torques(actuator_inertia)
        except InvalidInputError as exc:
            raise exc.moved(f"{exc.field}.{row}") from None
        raise AssertionError(f"row {row} breaks no rule of the scalar flowchart")

    @property
    def size(self) -> int:
        return self.speed_rpm.size


_PATTERN_FIELDS = frozenset(_TRAPEZOID_FIELDS[:5])


def _columns_cases(columns: TrapezoidColumns) -> _Cases:
    """The cases of ``columns`` as the flowchart's rows: the arrays :func:`_cases` builds
    for the same trapezoids, without an application per case."""
    pieces = trapezoid_piece_arrays(
        **{name: np.asarray(getattr(columns, name), dtype=np.float64) for name in _TRAPEZOID_FIELDS}
    )
    figures = cycle_figures(pieces)
    finite = np.isfinite(figures.mean_speed_rpm)
    for floor in (figures.accel_floor_nm, figures.decel_floor_nm, figures.rms_floor_nm):
        finite &= np.isfinite(floor)
    if not finite.all():  # finite inputs whose products overflow (profile_from's check)
        columns._refuse(int(np.argmin(finite)))
    tau = columns.thermal_time_constant_s
    n = columns.size
    return _Cases(
        pieces=pieces,
        figures=figures,
        load_inertia=np.asarray(columns.inertia_kgm2, dtype=np.float64),
        high_dynamics=np.asarray(columns.high_dynamics, dtype=np.bool_),
        output_load=np.full((n, len(_OUTPUT_LOAD_FIELDS)), math.nan),
        thermal_time_constant=np.full(n, DEFAULT_THERMAL_TIME_CONSTANT_S if tau is None else tau),
        thermal_assumed=np.full(n, tau is None, dtype=np.bool_),
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class RankedTable:
    """Each case's best actuators as a long table: a row per candidate, the cases' rows
    in order and each case's candidates best first. Torques, values and limits are NaN
    where a single selection gives None."""

    cycle_time_s: FloatArray
    """t_0 per case [s]."""
    mean_speed_rpm: FloatArray
    """n_av per case (Eq. 514.3) [rpm]."""
    duty_cycle_percent: FloatArray
    """ED per case (Eq. 514.4) [%]."""
    case: IndexArray
    """Per candidate, its case (a row of the columns ranked)."""
    actuator: IndexArray
    """Per candidate, its actuator (an index into the catalogue ranked against)."""
    verdicts: CodeArray
    """Per candidate, its verdict code (:data:`VERDICT_BY_CODE`)."""
    accel_torque_nm: FloatArray
    constant_torque_nm: FloatArray
    decel_torque_nm: FloatArray
    rms_torque_nm: FloatArray
    checks: CheckTable | None = None
    """The candidates' checks, where asked for."""


@dataclass(frozen=True, slots=True, kw_only=True)
class CheckTable:
    """Each candidate's checks as arrays, check × candidate (a rule × a row of
    :class:`RankedTable`), NaN where a single selection's check gives None."""

    rules: tuple[Rule, ...]
    """The checks, in the order of the first axis."""
    statuses: CodeArray
    """Status codes (:data:`STATUS_BY_CODE`)."""
    values: FloatArray
    limits: FloatArray
    approximate: BoolArray
    first_missing: CodeArray
    """The index into the rule's requirements of what the catalogue lacks (for no data,
    or a fail whatever that value is); −1: nothing."""


def rank_columns(
    actuators: Sequence[Actuator],
    columns: TrapezoidColumns,
    *,
    top: int = 3,
    checks: bool = False,
    rules: Sequence[Rule] = RULES,
    arrays: CatalogueArrays | None = None,
) -> RankedTable:
    """The best ``top`` actuators of every case of ``columns``, as :func:`select_batch`
    ranks and details them, as arrays: the candidates' verdicts and torques and, with
    ``checks``, each check's status, value, limit, approximation and missing value.
    No Python object per case or candidate: for bulk sizing.

    Equal, cell for cell, to :func:`select_batch` of the same cases as applications (the
    tests compare them with ``==``).
    """
    _check_arguments(columns.size, top, None)
    cases = _columns_cases(columns)
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    parts = [
        _table_rows(ranked)
        for ranked in _ranked_blocks(
            actuators, cases, top=top, models=None, rules=rules, detail=checks, arrays=cat
        )
    ]
    case, actuator, verdicts, accel, constant, decel, rms, *detail = (
        np.concatenate(column, axis=-1) for column in zip(*parts, strict=True)
    )
    finite = np.isfinite(accel) & np.isfinite(decel) & np.isfinite(rms)
    inertia = cat.inertia[actuator]
    finite |= np.isnan(inertia)  # no J_A: no torques (NaN), as a single selection's None
    if not finite.all():  # a torque overflowed: the scalar's error names the input
        bad = int(np.argmin(finite))
        columns._refuse(int(case[bad]), float(inertia[bad]))
    figures = cases.figures
    return RankedTable(
        cycle_time_s=figures.cycle_s,
        mean_speed_rpm=figures.mean_speed_rpm,
        duty_cycle_percent=figures.duty_cycle_percent,
        case=case,
        actuator=actuator,
        verdicts=verdicts,
        accel_torque_nm=accel,
        constant_torque_nm=constant,
        decel_torque_nm=decel,
        rms_torque_nm=rms,
        checks=CheckTable(rules=tuple(rules), **dict(zip(_CHECK_TABLE, detail, strict=True)))
        if detail
        else None,
    )


_CHECK_TABLE = ("statuses", "values", "limits", "approximate", "first_missing")


def _table_rows(ranked: _RankedBlock) -> tuple[Any, ...]:
    """A ranked block's kept cells as :class:`RankedTable`'s columns, candidate by
    candidate: case, actuator, verdict, the four torques and, where the block has them,
    the checks' statuses, values, limits, approximations and missing requirements."""
    block, order = ranked.block, ranked.order
    shape = block.accel_torque.shape
    rows = np.broadcast_to(np.arange(order.shape[0])[:, np.newaxis], order.shape)[ranked.kept]
    cols = order[ranked.kept]

    def cells(array: Any) -> Any:
        return np.broadcast_to(array, shape)[rows, cols]

    out = [
        rows + ranked.start,
        cols,
        ranked.verdicts[rows, cols],
        cells(block.accel_torque),
        cells(block.constant_torque),
        cells(block.decel_torque),
        cells(block.rms_torque),
    ]
    if block.details is not None:
        out += [
            np.stack([cells(c) for c in block.statuses]),
            np.stack([cells(d.values) for d in block.details]),
            np.stack([cells(d.limits) for d in block.details]),
            np.stack([cells(d.approximate) for d in block.details]),
            np.stack([cells(d.first_missing) for d in block.details]),
        ]
    return tuple(out)


def select_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    top: int = 3,
    models: Sequence[Collection[str] | None] | None = None,
    rules: Sequence[Rule] | None = None,
) -> list[Selection]:
    """The best ``top`` candidates of every load case, ranked as :func:`select` ranks them.

    Equal to ``select(actuators, app)`` with its candidates cut to ``top``, case by case
    (and to ``select`` over the actuators named in ``models[i]``, where given): the
    arrays rank and detail the chosen few (:func:`_detail`).

    Parameters
    ----------
    actuators
        The catalogue.
    apps
        The load cases.
    top
        Candidates kept per case, ≥ 1.
    models
        Per case, the model names it may use (None: the whole catalogue); names not in
        ``actuators`` are ignored. None: every case uses the whole catalogue.
    rules
        The checks (:data:`~actuator_selection.core.checks.RULES`: the chapter's), for the
        arrays and for the candidates alike.
    """
    _check_arguments(len(apps), top, models)
    rules = _rules_of(apps, rules)
    selections = []
    ranked_blocks = _ranked_blocks(
        actuators, _cases(apps), top=top, models=models, rules=rules, detail=True
    )
    for ranked in ranked_blocks:
        order, kept, figures, holding = (
            ranked.order,
            ranked.kept,
            ranked.cases.figures,
            ranked.cases.pieces.holding,
        )
        rows = np.broadcast_to(np.arange(order.shape[0])[:, np.newaxis], order.shape)[kept]
        cases = apps[ranked.start : ranked.start + order.shape[0]]
        profiles = [
            profile_from(_CycleOf(app), app.axis_load, row_figures, row_holding)
            for app, row_figures, row_holding in zip(
                cases, figure_rows(figures), holding.tolist(), strict=True
            )
        ]
        detailed = iter(_detail(actuators, rules, ranked, rows, order[kept], profiles))
        for profile, count in zip(profiles, kept.sum(axis=1).tolist(), strict=True):
            selections.append(
                Selection(
                    mean_speed_rpm=profile.mean_speed_rpm,
                    duty_cycle_percent=profile.duty_cycle_percent,
                    cycle_time_s=profile.cycle_s,
                    candidates=tuple(itertools.islice(detailed, count)),
                    profile=profile,
                )
            )
    return selections


def _detail(
    actuators: Sequence[Actuator],
    rules: Sequence[Rule],
    ranked: _RankedBlock,
    rows: IndexArray,
    columns: IndexArray,
    profiles: Sequence[Profile],
) -> list[Candidate]:
    """The candidates of the cells (``rows``, ``columns``) of a block evaluated with
    ``detail``: their torques, and each rule's check in words
    (:meth:`~actuator_selection.core.checks.Rule.report`) from the decisions, values and
    limits of the arrays and the operands of the cell, as floats. Equal to
    :func:`~actuator_selection.core.selection.evaluate` of the cell (the tests compare
    them with ``==``); the checks are built, and their words written, when first read."""
    block = ranked.block
    assert block.details is not None
    assert block.operands is not None
    shape = block.accel_torque.shape

    def cells(array: Any) -> list[Any]:
        picked: list[Any] = np.broadcast_to(array, shape)[rows, columns].tolist()
        return picked

    codes = [np.broadcast_to(c, shape)[rows, columns] for c in block.statuses]
    not_passing: list[list[int]] = [[] for _ in range(rows.size)]
    failing, cells_failing = np.nonzero(np.array(codes).reshape(len(codes), rows.size) != _PASS)
    for k, cell in zip(failing.tolist(), cells_failing.tolist(), strict=True):
        not_passing[cell].append(k)  # rule by rule: each cell's in the rules' order
    decided = _Decided(
        rules,
        [
            (
                rule_codes.tolist(),
                cells(d.values),
                cells(d.limits),
                cells(d.approximate),
                cells(d.first_missing),
            )
            for rule_codes, d in zip(codes, block.details, strict=True)
        ],
        not_passing,
        [cells(operand) for operand in block.operands],
    )
    torques = zip(
        cells(block.accel_torque),
        cells(block.constant_torque),
        cells(block.decel_torque),
        cells(block.rms_torque),
        strict=True,
    )
    verdicts = cells(ranked.verdicts)
    out = []
    for cell, (row, column, verdict, cell_torques) in enumerate(
        zip(rows.tolist(), columns.tolist(), verdicts, torques, strict=True)
    ):
        actuator = actuators[column]
        out.append(
            Candidate(
                actuator=actuator,
                verdict=VERDICT_BY_CODE[verdict],
                torques=_cycle_torques(actuator, profiles[row], *cell_torques),
                checks=_DecidedChecks(decided, cell),  # type: ignore[arg-type]
            )
        )
    return out


class _CycleOf(Deferred):
    """A case's motion (:attr:`~actuator_selection.core.selection.Application.cycle`), built
    when its profile's motion or pieces are first read, once for both."""

    __slots__ = ("_app", "_motion")

    def __init__(self, app: Application) -> None:
        self._app = app
        self._motion: Motion | None = None

    def resolve(self) -> Motion:
        if self._motion is None:
            self._motion = self._app.cycle
        return self._motion


Column = tuple[list[int], list[float], list[float], list[bool], list[int]]
"""One rule's decisions for the cells detailed: status codes, values, limits,
approximations and first missing requirements (−1: none)."""


@dataclass(frozen=True, slots=True, eq=False)
class _Decided:
    """The rules' decisions for the cells of a block that are detailed."""

    rules: Sequence[Rule]
    columns: list[Column]
    not_passing: list[list[int]]
    """Per cell, the indexes of the rules that do not pass, in order."""
    operands: list[list[Any]]
    """Each of :class:`Operands`' fields, cell by cell, as floats (or truths)."""

    def operands_of(self, cell: int) -> Operands:
        """What the rules computed from for ``cell``: needed only to word a check, so
        built only for a candidate whose checks or reasons are read."""
        return Operands._make([field[cell] for field in self.operands])

    def check(self, k: int, q: Operands, cell: int) -> Check:
        """Rule ``k``'s check of ``cell`` (its operands ``q``), with its words: a batch
        candidate's checks are built only to be listed in words (``include_checks``)."""
        codes, values, limits, approximate, missing = self.columns[k]
        first = missing[cell]
        return self.rules[k].report(
            q,
            STATUS_BY_CODE[codes[cell]],
            values[cell],
            limits[cell],
            approximate[cell],
            None if first < 0 else first,
        )

    def reasons(self, q: Operands, cell: int) -> list[str]:
        """The words of the rules that do not pass for ``cell`` (its operands ``q``)."""
        out = []
        for k in self.not_passing[cell]:
            codes, values, limits, _, missing = self.columns[k]
            first = missing[cell]
            out.append(
                self.rules[k].words(
                    q,
                    STATUS_BY_CODE[codes[cell]],
                    values[cell],
                    limits[cell],
                    None if first < 0 else first,
                )
            )
        return out


class _DecidedChecks(DeferredChecks):
    """One candidate's checks as the arrays decided them, each built by the rule's
    :meth:`~actuator_selection.core.checks.Rule.report` when first read."""

    __slots__ = ("_cell", "_decided")

    def __init__(self, decided: _Decided, cell: int) -> None:
        self._decided, self._cell = decided, cell

    def resolve(self) -> tuple[Check, ...]:
        d, cell = self._decided, self._cell
        q = d.operands_of(cell)
        return tuple([d.check(k, q, cell) for k in range(len(d.rules))])

    def reasons(self) -> list[str]:
        d, cell = self._decided, self._cell
        if not d.not_passing[cell]:
            return []
        return d.reasons(d.operands_of(cell), cell)


def _cycle_torques(
    actuator: Actuator,
    profile: Profile,
    accel: float,
    constant: float,
    decel: float,
    rms: float,
) -> CycleTorques | None:
    """:meth:`~actuator_selection.core.motion.Profile.torques` from the arrays' values:
    None without J_A; where a finite input overflowed a torque, the profile's own
    computation raises the error that names the input."""
    if actuator.inertia_kgm2 is None:
        return None
    if not (math.isfinite(accel) and math.isfinite(decel) and math.isfinite(rms)):
        return profile.torques(actuator.inertia_kgm2)
    return CycleTorques(
        accel_torque_nm=accel,
        constant_torque_nm=None if constant != constant else constant,
        decel_torque_nm=decel,
        rms_torque_nm=rms,
    )
