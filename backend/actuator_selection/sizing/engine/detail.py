"""A candidate's detail: the engine's decisions for chosen cells, as
:class:`~actuator_selection.sizing.candidates.Candidate` objects whose checks are each
rule's :meth:`~actuator_selection.sizing.checks.Rule.report` of the arrays' decision, value
and limit, built, with their words, when first read."""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any, cast

import numpy as np
import numpy.typing as npt

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.candidates import Candidate
from actuator_selection.sizing.checks import Brief, Check, DeferredChecks, Operands, Rule
from actuator_selection.sizing.deferred import Deferred
from actuator_selection.sizing.engine.arrays import (
    PASS,
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BoolArray,
    CodeArray,
    FloatArray,
    IndexArray,
)
from actuator_selection.sizing.engine.block import Block
from actuator_selection.sizing.motion import CycleTorques, Motion, Profile


def decide_cells(
    rules: Sequence[Rule], block: Block, rows: IndexArray, columns: IndexArray
) -> DecidedCells:
    """The rules' decisions for the cells (``rows``, ``columns``) of a block evaluated
    with ``detail``, and the operands they were decided from."""
    checks = block.checks
    assert checks is not None
    assert block.operands is not None
    shape = block.accel_torque.shape
    codes = block.statuses[:, rows, columns]  # rules × cells
    not_passing: list[list[int]] = [[] for _ in range(rows.size)]
    failing, cells_failing = np.nonzero(codes > PASS)
    for k, cell in zip(failing.tolist(), cells_failing.tolist(), strict=True):
        not_passing[cell].append(k)  # rule by rule: each cell's in the rules' order
    return DecidedCells(
        rules,
        RuleColumns(
            statuses=codes,
            values=checks.values[:, rows, columns],
            limits=checks.limits[:, rows, columns],
            approximate=checks.approximate[:, rows, columns],
            first_missing=checks.first_missing[:, rows, columns],
        ),
        not_passing,
        block.operands,
        lambda array: _picked(array, shape, rows, columns),
        lambda array: _picked_array(array, shape, rows, columns),
    )


def cell_torques(
    block: Block, rows: IndexArray, columns: IndexArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """The torques T_1, T_2, T_3 and T_rms of the cells (``rows``, ``columns``) of a
    block, each an array over the cells."""
    shape = block.accel_torque.shape
    return (
        _picked_array(block.accel_torque, shape, rows, columns),
        _picked_array(block.constant_torque, shape, rows, columns),
        _picked_array(block.decel_torque, shape, rows, columns),
        _picked_array(block.rms_torque, shape, rows, columns),
    )


def detail_cells(
    actuators: Sequence[Actuator],
    rules: Sequence[Rule],
    block: Block,
    verdicts: CodeArray,
    rows: IndexArray,
    columns: IndexArray,
    profiles: Sequence[Profile],
) -> list[Candidate]:
    """The candidates of the cells (``rows``, ``columns``) of a block evaluated with
    ``detail``: their torques, and each rule's check in words
    (:meth:`~actuator_selection.sizing.checks.Rule.report`) from the decisions, values and
    limits of the arrays and the operands of the cell, as floats. Equal to
    :func:`~actuator_selection.sizing.selection.evaluate` of the cell (the tests compare
    them with ``==``); the checks are built, and their words written, when first read."""
    shape = block.accel_torque.shape
    return candidates_of(
        actuators,
        decide_cells(rules, block, rows, columns),
        _picked_array(verdicts, shape, rows, columns),
        cell_torques(block, rows, columns),
        rows,
        columns,
        profiles,
    )


def candidates_of(
    actuators: Sequence[Actuator],
    decided: DecidedCells,
    verdicts: CodeArray,
    torques: tuple[FloatArray, FloatArray, FloatArray, FloatArray],
    rows: IndexArray,
    columns: IndexArray,
    profiles: Sequence[Profile],
) -> list[Candidate]:
    """The candidates of cells decided (:func:`decide_cells`), their verdict codes and
    torques (:func:`cell_torques`) each an array over the cells, ``profiles`` by row."""
    out = []
    for cell, (row, column, verdict, torques_of_cell) in enumerate(
        zip(
            rows.tolist(),
            columns.tolist(),
            verdicts.tolist(),
            zip(*(t.tolist() for t in torques), strict=True),
            strict=True,
        )
    ):
        actuator = actuators[column]
        out.append(
            Candidate(
                actuator=actuator,
                verdict=VERDICT_BY_CODE[verdict],
                torques=_cycle_torques(actuator, profiles[row], *torques_of_cell),
                checks=_DecidedChecks(decided, cell),  # type: ignore[arg-type]
            )
        )
    return out


class CycleOf(Deferred):
    """A case's motion (:attr:`~actuator_selection.sizing.selection.Application.cycle`), built
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


def _picked_array(
    array: Any, shape: tuple[int, ...], rows: IndexArray, columns: IndexArray
) -> npt.NDArray[Any]:
    """The cells (``rows``, ``columns``) of ``array`` broadcast to ``shape`` (cases ×
    actuators), as an array over the cells: a column of cases, a row of actuators and a
    scalar are indexed as they are, without broadcasting them first."""
    a = np.asarray(array)
    picked: npt.NDArray[Any]
    if a.size == 1:  # a scalar, or one cell (a 1 × 1 view's arrays): the same everywhere
        picked = np.full(rows.size, a.reshape(()), dtype=a.dtype)
    elif a.ndim == 2 and a.shape[1] == 1:  # a column of cases
        picked = a[rows, 0]
    elif a.ndim == 1 and a.shape[0] == shape[1]:  # a row of actuators
        picked = a[columns]
    elif a.shape == shape:
        picked = a[rows, columns]
    else:
        picked = np.broadcast_to(a, shape)[rows, columns]
    return picked


def _picked(array: Any, shape: tuple[int, ...], rows: IndexArray, columns: IndexArray) -> list[Any]:
    """The cells (``rows``, ``columns``) of ``array`` broadcast to ``shape`` (cases ×
    actuators), as Python values: a column of cases, a row of actuators and a scalar
    are indexed as they are, without broadcasting them first."""
    a = np.asarray(array)
    if a.size == 1:  # a scalar, or one cell (a 1 × 1 view's arrays): the same everywhere
        picked: list[Any] = [a.item()] * rows.size
    elif a.ndim == 2 and a.shape[1] == 1:  # a column of cases
        picked = a[rows, 0].tolist()
    elif a.ndim == 1 and a.shape[0] == shape[1]:  # a row of actuators
        picked = a[columns].tolist()
    elif a.shape == shape:
        picked = a[rows, columns].tolist()
    else:
        picked = np.broadcast_to(a, shape)[rows, columns].tolist()
    return picked


@dataclass(frozen=True, slots=True, eq=False)
class RuleColumns:
    """The rules' decisions for the cells detailed, each array rules × cells: what
    :meth:`~actuator_selection.sizing.checks.Rule.report` reports of each cell's checks."""

    statuses: CodeArray
    """Status codes (:data:`STATUS_BY_CODE`)."""
    values: FloatArray
    """The value checked; NaN where unknown (the check reports None)."""
    limits: FloatArray
    """The limit; NaN where there is none (no data, or beyond a zone's last speed)."""
    approximate: BoolArray
    first_missing: CodeArray
    """Index into the rule's requirements of the first one missing; −1 where none is."""


class DecidedCells:
    """The rules' decisions for the cells of a block that are detailed (:attr:`columns`),
    and the operands they were decided from, cell by cell (:meth:`operands_of`) or as
    arrays over the cells (:meth:`operand_columns`)."""

    __slots__ = (
        "_cell_arrays",
        "_cells",
        "_lists",
        "_operands",
        "_source",
        "columns",
        "not_passing",
        "rules",
    )

    def __init__(
        self,
        rules: Sequence[Rule],
        columns: RuleColumns,
        not_passing: list[list[int]],
        source: Operands,
        cells: Callable[[Any], list[Any]],
        cell_arrays: Callable[[Any], npt.NDArray[Any]],
    ) -> None:
        self.rules, self.columns, self.not_passing = rules, columns, not_passing
        self._source, self._cells, self._cell_arrays = source, cells, cell_arrays
        self._operands: list[list[Any]] | None = None
        self._lists: list[Column] | None = None

    def operand_columns(self) -> Operands:
        """Each of :class:`Operands`' fields as an array over the cells detailed, cut
        from the block's arrays when first read (a rule's message reads a few of them)."""
        return cast(Operands, _CutOperands(self._source, self._cell_arrays))

    def operands_of(self, cell: int) -> Operands:
        """What the rules computed from for ``cell``: needed only to word a check, so
        built only for a candidate whose checks or reasons are read (each of
        :class:`Operands`' fields for every cell detailed, as floats, on the first)."""
        if self._operands is None:
            self._operands = [self._cells(operand) for operand in self._source]
        return Operands._make([field[cell] for field in self._operands])

    def _columns(self) -> list[Column]:
        """:attr:`columns` rule by rule as Python values, for the checks built one by one."""
        if self._lists is None:
            c = self.columns
            self._lists = list(
                zip(
                    c.statuses.tolist(),
                    c.values.tolist(),
                    c.limits.tolist(),
                    c.approximate.tolist(),
                    c.first_missing.tolist(),
                    strict=True,
                )
            )
        return self._lists

    def check(self, k: int, q: Operands, cell: int) -> Check:
        """Rule ``k``'s check of ``cell`` (its operands ``q``), with its words: a batch
        candidate's checks are built only to be listed in words (``include_checks``)."""
        codes, values, limits, approximate, missing = self._columns()[k]
        first = missing[cell]
        return self.rules[k].report(
            q,
            STATUS_BY_CODE[codes[cell]],
            values[cell],
            limits[cell],
            approximate[cell],
            None if first < 0 else first,
        )

    def briefs(self, q: Operands, cell: int) -> list[tuple[Rule, Brief]]:
        """Every rule's check of ``cell``, the rule beside its :data:`~actuator_selection.
        sizing.checks.Brief` (:meth:`~actuator_selection.sizing.checks.Rule.brief`)."""
        out = []
        for rule, (codes, values, limits, approximate, missing) in zip(
            self.rules, self._columns(), strict=True
        ):
            first = missing[cell]
            brief = rule.brief(
                q,
                STATUS_BY_CODE[codes[cell]],
                values[cell],
                limits[cell],
                approximate[cell],
                None if first < 0 else first,
            )
            out.append((rule, brief))
        return out

    def reasons(self, q: Operands, cell: int) -> list[str]:
        """The words of the rules that do not pass for ``cell`` (its operands ``q``)."""
        out = []
        columns = self._columns()
        for k in self.not_passing[cell]:
            codes, values, limits, _, missing = columns[k]
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
    :meth:`~actuator_selection.sizing.checks.Rule.report` when first read."""

    __slots__ = ("_cell", "_decided")

    def __init__(self, decided: DecidedCells, cell: int) -> None:
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

    def briefs(self) -> list[tuple[Rule, Brief]]:
        d, cell = self._decided, self._cell
        return d.briefs(d.operands_of(cell), cell)

    def open_names(self) -> list[str]:
        rules = self._decided.rules
        return [rules[k].name for k in self._decided.not_passing[self._cell]]

    def decided(self) -> tuple[DecidedCells, int]:
        return self._decided, self._cell


def _cycle_torques(
    actuator: Actuator,
    profile: Profile,
    accel: float,
    constant: float,
    decel: float,
    rms: float,
) -> CycleTorques | None:
    """:meth:`~actuator_selection.sizing.motion.Profile.torques` from the arrays' values:
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


class _CutOperands:
    """:class:`Operands` over the cells detailed, read by name (as a rule's terms read
    them): each field cut by ``cut`` from ``source``'s when first read, then kept."""

    def __init__(self, source: Operands, cut: Callable[[Any], npt.NDArray[Any]]) -> None:
        self._source, self._cut = source, cut

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):  # not an operand: no such attribute
            raise AttributeError(name)
        found = self.__dict__[name] = self._cut(getattr(self._source, name))
        return found
