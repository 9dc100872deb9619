"""The columns input format: load cases of the chapter's shorthand as columns
(:class:`TrapezoidColumns`), ranked into a long table of candidates
(:func:`rank_columns`, :class:`RankedTable`), no Python object per case or candidate."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.application import Application, require_time_constant
from actuator_selection.sizing.checks import RULES, Rule
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine.arrays import BoolArray, CodeArray, FloatArray, IndexArray
from actuator_selection.sizing.engine.cases import OUTPUT_LOAD_FIELDS, Cases, default_requests
from actuator_selection.sizing.engine.catalogue import CatalogueArrays, catalogue_arrays
from actuator_selection.sizing.engine.evaluation import RankedBlock, check_arguments, ranked_blocks
from actuator_selection.sizing.motion import cycle_figures, trapezoid_piece_arrays
from actuator_selection.sizing.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S

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
    J_L), as :class:`~actuator_selection.sizing.cycle.SpeedPattern` and
    :class:`~actuator_selection.sizing.cycle.Load` take them, for :func:`rank_columns`.

    A row those classes refuse is refused here with their error, its field named with
    the row (``speed_rpm.17``): the rules are theirs, checked for the whole column at
    once and worded by the single-case classes for the first row that breaks one.
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
        """Raise the single case's error for ``row`` (the cycle's, or its torques' with
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
        raise AssertionError(f"row {row} breaks no rule of a single case")

    @property
    def size(self) -> int:
        return self.speed_rpm.size


_PATTERN_FIELDS = frozenset(_TRAPEZOID_FIELDS[:5])


def columns_cases(columns: TrapezoidColumns) -> Cases:
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
    return Cases(
        pieces=pieces,
        figures=figures,
        load_inertia=np.asarray(columns.inertia_kgm2, dtype=np.float64),
        high_dynamics=np.asarray(columns.high_dynamics, dtype=np.bool_),
        output_load=np.full((n, len(OUTPUT_LOAD_FIELDS)), math.nan),
        thermal_time_constant=np.full(n, DEFAULT_THERMAL_TIME_CONSTANT_S if tau is None else tau),
        thermal_assumed=np.full(n, tau is None, dtype=np.bool_),
        requests=default_requests(n),
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
    check_arguments(columns.size, top, None)
    cases = columns_cases(columns)
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    parts = [
        _table_rows(ranked)
        for ranked in ranked_blocks(
            actuators, cases, top=top, models=None, rules=rules, detail=checks, arrays=cat
        )
    ]
    case, actuator, verdicts, accel, constant, decel, rms, *detail = (
        np.concatenate(column, axis=-1) for column in zip(*parts, strict=True)
    )
    finite = np.isfinite(accel) & np.isfinite(decel) & np.isfinite(rms)
    inertia = cat.inertia[actuator]
    finite |= np.isnan(inertia)  # no J_A: no torques (NaN), as a single selection's None
    if not finite.all():  # a torque overflowed: the single case's error names the input
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


def _table_rows(ranked: RankedBlock) -> tuple[Any, ...]:
    """A ranked block's kept cells as :class:`RankedTable`'s columns, candidate by
    candidate: case, actuator, verdict, the four torques and, where the block has them,
    the checks' statuses, values, limits, approximations and missing requirements."""
    block, order = ranked.block, ranked.order
    shape = block.accel_torque.shape
    rows = np.broadcast_to(np.arange(order.shape[0])[:, np.newaxis], order.shape)[ranked.kept]
    cols = order[ranked.kept]
    flat = rows * shape[1] + cols  # each cell's place in a block's array, flattened

    def cells(array: Any) -> Any:
        if array.shape == shape and array.flags.c_contiguous:  # one take of the places
            return array.reshape(-1).take(flat)
        return np.broadcast_to(array, shape)[rows, cols]

    out = [
        rows + ranked.start,
        cols,
        cells(ranked.verdicts),
        cells(block.accel_torque),
        cells(block.constant_torque),
        cells(block.decel_torque),
        cells(block.rms_torque),
    ]
    checks = block.checks
    if checks is not None:  # rules × cells, in C order (the answer's writer, orjson,
        # takes C order only): each rule's cells by one take of their flat places, where
        # a[:, rows, cols] laid them out cells-first and a copy put them in order
        out += [
            a.reshape(a.shape[0], -1).take(flat, axis=1)
            if a.shape[1:] == shape
            else np.ascontiguousarray(a[:, rows, cols])
            for a in (
                block.statuses,
                checks.values,
                checks.limits,
                checks.approximate,
                checks.first_missing,
            )
        ]
    return tuple(out)
