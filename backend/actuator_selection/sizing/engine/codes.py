"""The rules' status codes for a block, every rule at once.

Each rule computes its value, limit and conditions on the block's arrays with numpy's
operations (:data:`ARRAY_OPS`); this module writes them into one array per quantity, rules
× cases × actuators (:class:`RuleArrays`), and decides every rule's codes with one set of
comparisons and masks (:func:`status_codes`): no data where a requirement is missing,
else pass, fail or warn; not applicable where the premise does not hold; and the
overload that ranks what does not fit.

Why at once: a one-model selection is a block of one cell, where each numpy call costs
its fixed overhead whatever the size of its arrays. Deciding rule by rule took some ten
calls per rule (masks, ``where``, ``any``), a sixth of the selection's time; stacked,
the same decisions take a dozen calls for all the rules, and a block of thousands of
cells does the same element-wise work as before. Every comparison and every selected
value is the one :meth:`~actuator_selection.sizing.checks.Rule.check` makes, so the
codes, values and limits equal the plain-float oracle's bit for bit (``tests/oracle``).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from itertools import repeat
from typing import Any

import numpy as np

from actuator_selection.sizing.checks import FLOAT_OPS, Operands, Ops, Rule
from actuator_selection.sizing.engine.arrays import (
    FAIL,
    NO_DATA,
    NOT_APPLICABLE,
    PASS,
    WARN,
    BoolArray,
    CodeArray,
    FloatArray,
)
from actuator_selection.sizing.engine.catalogue import CatalogueArrays, Lacking
from actuator_selection.sizing.engine.formulas import float_maximum


def _python_pow(x: Any, exponent: float) -> Any:
    """``math.pow`` element by element: bit for bit what Python's floats compute
    (numpy's power differs in the last bit for some inputs). The rules raise only case
    quantities to a power, so the arrays are one column of cases."""
    base = np.asarray(x, dtype=np.float64)
    flat = base.ravel().tolist()
    powers = np.fromiter(map(math.pow, flat, repeat(exponent)), np.float64, len(flat))
    return powers.reshape(base.shape)


ARRAY_OPS = Ops(where=np.where, isnan=np.isnan, not_=np.logical_not, sqrt=np.sqrt, pow=_python_pow)
"""The rules' operations on numpy arrays (one cell's words use
:data:`~actuator_selection.sizing.checks.FLOAT_OPS`)."""


@dataclass(frozen=True, slots=True, eq=False)
class RuleDetail:
    """What :meth:`~actuator_selection.sizing.checks.Rule.check` reports for one rule, as
    arrays of the block's shape (cases × actuators): a rule's row of :class:`RuleArrays`."""

    values: FloatArray
    """The value checked; NaN where unknown (the check reports None)."""
    limits: FloatArray
    """The limit; NaN where there is none (no data, or beyond a zone's last speed)."""
    approximate: BoolArray
    first_missing: CodeArray
    """Index into the rule's requirements of the first one missing; −1 where none is."""


@dataclass(frozen=True, slots=True, eq=False)
class RuleArrays:
    """What the checks report for a block, every rule at once: each array rules × cases ×
    actuators, the rules in their order."""

    values: FloatArray
    """The value checked; NaN where unknown (the check reports None)."""
    limits: FloatArray
    """The limit; NaN where there is none (no data, or beyond a zone's last speed)."""
    approximate: BoolArray
    """Where the limit is a simplified stand-in."""
    first_missing: CodeArray
    """Index into the rule's requirements of the first one missing; −1 where none is."""

    def part(self, rules: slice) -> RuleArrays:
        """The rules ``rules`` of each array (views)."""
        return RuleArrays(
            self.values[rules],
            self.limits[rules],
            self.approximate[rules],
            self.first_missing[rules],
        )

    def __iter__(self) -> Iterator[RuleDetail]:
        """Rule by rule (:class:`RuleDetail`), in the rules' order."""
        for k in range(self.values.shape[0]):
            yield RuleDetail(
                self.values[k], self.limits[k], self.approximate[k], self.first_missing[k]
            )


def lacking(rules: Sequence[Rule], q: Operands, cat: CatalogueArrays) -> Lacking:
    """Where the catalogue misses the requirements of ``rules``
    (:class:`~actuator_selection.sizing.engine.catalogue.Lacking`).

    A requirement names catalogue values only (:class:`~actuator_selection.sizing.checks.
    Requirement`), so this is a fact about the actuators, computed once per catalogue and
    rule set and kept with the catalogue's arrays (:attr:`CatalogueArrays.lacking`): six
    rules' requirements were a fifth of a whole-catalogue selection's engine."""
    key = tuple(rules)
    found = cat.lacking.get(key)
    if found is not None:
        return found
    n = cat.inertia.shape  # actuators; a column of pairs (engine.pairs)
    xp = ARRAY_OPS
    first_missing = np.full((len(rules), *n), -1, dtype=np.int8)
    others_missing = np.zeros((len(rules), *n), dtype=np.bool_)
    for r, rule in enumerate(rules):
        first, others = first_missing[r], others_missing[r]
        for k, need in enumerate(rule.requires):
            missing = need.missing(q, xp)
            assert np.shape(missing) == n, f"{rule.name}: a requirement names a case's value"
            first[(first < 0) & missing] = k
            if k:
                others |= missing
    # As the block's arrays: rules × 1 × actuators (rules × pairs × 1 for pairs).
    shape = (len(rules), *(1,) * (2 - len(n)), *n)
    found = cat.lacking[key] = summarised(
        rules, first_missing.reshape(shape), others_missing.reshape(shape)
    )
    return found


def summarised(
    rules: Sequence[Rule], first_missing: CodeArray, others_missing: BoolArray
) -> Lacking:
    """The :class:`~actuator_selection.sizing.engine.catalogue.Lacking` of ``rules`` from
    where each misses its first requirement and any other (rules × the block's cells)."""
    everywhere, floors = [], []
    for r, rule in enumerate(rules):
        first, others = first_missing[r], others_missing[r]
        # Where only the first requirement (J_A) is missing, a lower bound may fail.
        floor = rule.lower_bound is not None and bool(((first == 0) & ~others).any())
        if floor:
            floors.append(r)
        everywhere.append(bool((first >= 0).all()) and not floor)
    somewhere: list[bool] = np.asarray(
        (first_missing >= 0).reshape(len(rules), -1).any(axis=1)
    ).tolist()
    one = first_missing.size == len(rules)  # one actuator: its values rule by rule
    return Lacking(
        first_missing=first_missing,
        others_missing=others_missing,
        everywhere=tuple(everywhere),
        somewhere=tuple(somewhere),
        floors=tuple(floors),
        cell=(first_missing.ravel().tolist(), others_missing.ravel().tolist()) if one else ([], []),
    )


_CACHED_CELLS = 1 << 16
"""Cells (rules × cases × actuators) decided at a time (:func:`status_codes`), so that
the temporaries stay in the CPU cache, as a block's arrays do
(:data:`~actuator_selection.sizing.engine.block._BLOCK_CELLS`)."""


def status_codes(
    rules: Sequence[Rule],
    q: Operands,
    cat: CatalogueArrays,
    shape: tuple[int, int],
    *,
    detail: bool = False,
    overload: bool = True,
) -> tuple[CodeArray, FloatArray, RuleArrays | None]:
    """Every rule's codes for the block (:meth:`~actuator_selection.sizing.checks.Rule.check`
    on arrays), rules × cases × actuators; the largest overload of the rules per cell
    (:func:`~actuator_selection.sizing.checks.overload`); with ``detail``, each rule's
    value, limit, approximation and missing requirement as the check reports them.
    Without ``overload``, the overload is not computed (:data:`NO_OVERLOAD`: the ratio
    study's search never reads it).

    The rules are decided as many at a time as :data:`_CACHED_CELLS` holds: every rule of
    a small block at once (a one-model selection's: one set of numpy calls), one by one
    in a block of thousands of cells (on the whole block's rules at once, its
    temporaries left the cache and deciding took twice as long).

    Called with numpy's floating-point errors ignored: NaN where data is missing is
    masked here. A block of one cell is decided on floats (:func:`cell_codes`)."""
    lack = lacking(rules, q, cat)
    stacked = (len(rules), *shape)
    codes = np.empty(stacked, dtype=np.int8)
    out = None
    if detail:  # written rule by rule; without detail, only each part's are kept a while
        out = RuleArrays(
            values=np.empty(stacked),
            limits=np.empty(stacked),
            approximate=np.zeros(stacked, dtype=np.bool_),
            first_missing=np.empty(stacked, dtype=np.int8),
        )
        out.first_missing[...] = lack.first_missing
    worst: FloatArray | None = None
    step = max(1, _CACHED_CELLS // max(1, shape[0] * shape[1]))
    for start in range(0, len(rules), step):
        part = slice(start, start + step)
        reported = None if out is None else out.part(part)
        over = _decided(rules[part], start, q, lack, codes[part], reported, overload=overload)
        if over is not None:
            worst = over if worst is None else np.maximum(worst, over, out=worst)
    if not overload:
        return codes, NO_OVERLOAD, out
    return codes, np.zeros(shape) if worst is None else worst, out


def _decided(
    rules: Sequence[Rule],
    first: int,
    q: Operands,
    lack: Lacking,
    codes: CodeArray,
    out: RuleArrays | None,
    *,
    overload: bool = True,
) -> FloatArray | None:
    """:func:`status_codes` of ``rules`` at once, the rules ``first``, ``first + 1``, … of
    ``lack``'s: their codes written to ``codes``, what the checks report to ``out`` (None:
    not kept); returns their overload (None without ``overload``)."""
    xp = ARRAY_OPS
    stacked = codes.shape
    if out is None:
        values, limits = np.empty(stacked), np.empty(stacked)
    else:
        values, limits = out.values, out.limits
    # The optional formulas, stacked where a rule has one (a rule without: True, False).
    within = binding = applies = None
    for k, rule in enumerate(rules):
        if rule.applies is not None:
            if applies is None:
                applies = np.ones(stacked, dtype=np.bool_)
            applies[k] = rule.applies(q, xp)
        if lack.everywhere[first + k]:  # no data in any cell: only the value, as reported
            values[k] = math.nan if out is None else rule.value(q, xp)
            limits[k] = math.nan
            continue
        values[k] = rule.value(q, xp)
        limits[k] = rule.limit(q, xp)
        if rule.within is not None:
            if within is None:
                within = np.ones(stacked, dtype=np.bool_)
            within[k] = rule.within(q, xp)
        if rule.binding is not None:
            if binding is None:
                binding = np.ones(stacked, dtype=np.bool_)
            binding[k] = rule.binding(q, xp)
        if out is not None and rule.approximate is not None:
            out.approximate[k] = rule.approximate(q, xp)
    ok = values <= limits
    if within is not None:
        ok &= within
    decided = _picked(ok, PASS, FAIL if binding is None else _picked(binding, FAIL, WARN))
    part = slice(first, first + len(rules))
    missing: BoolArray | None = None
    # No data where a requirement is missing, unless the floor fails.
    if any(lack.somewhere[part]):
        missing = lack.first_missing[part] >= 0
        floors = [k - first for k in lack.floors if part.start <= k < part.stop]
        if floors:
            floor_fails = np.zeros(stacked, dtype=np.bool_)
            for k in floors:
                floor_fails[k] = _floor_fails(
                    rules[k], q, lack, first + k, values[k], limits[k], within, binding, k
                )
            missing = missing & ~floor_fails
            _put(decided, floor_fails, FAIL)
        _put(decided, missing, NO_DATA)
    if applies is not None:  # the premise does not hold: not applicable, whatever the data
        _put(decided, ~applies, NOT_APPLICABLE)
    codes[...] = decided
    worst = _overload(decided, values, limits) if overload else None
    if out is not None:  # as reported: no limit, no approximation where data is missing;
        if missing is not None:  # nothing (NaN, False, −1) where a check does not apply
            np.copyto(limits, math.nan, where=missing)
            np.copyto(out.approximate, False, where=missing)
        if applies is not None:
            not_applying = ~applies
            np.copyto(values, math.nan, where=not_applying)
            np.copyto(limits, math.nan, where=not_applying)
            np.copyto(out.approximate, False, where=not_applying)
            np.copyto(out.first_missing, -1, where=not_applying)
    return worst


def _picked(where: BoolArray, yes: np.int8, no: np.int8 | CodeArray) -> CodeArray:
    """``np.where(where, yes, no)`` for status codes, by int8 arithmetic (no + where·(yes −
    no)): numpy runs it as vector loops, where np.where of a scalar took its slow path
    (ten times the time over a block's rules × cases × actuators)."""
    picked = where.astype(np.int8)
    picked *= yes - no
    picked += no
    return picked


def _put(codes: CodeArray, where: BoolArray, code: np.int8) -> None:
    """``codes`` made ``code`` where ``where`` holds, in place: ``np.where(where, code,
    codes)`` by int8 arithmetic, as :func:`_picked`."""
    codes += where.view(np.int8) * (code - codes)


def cell_codes(
    rules: Sequence[Rule], q: Operands, lack: Lacking, *, detail: bool, overload: bool
) -> tuple[CodeArray, FloatArray, RuleArrays | None] | None:
    """:func:`status_codes` for a block of one cell, its operands ``q`` floats: each rule's
    formulas on Python floats (:data:`~actuator_selection.sizing.checks.FLOAT_OPS`, as the
    words of a check compute them), decided as :func:`_decided` decides each cell: every
    value as the arrays hold it (a truth as ``bool``, a number as ``float``), the same
    comparisons in the same order; the arrays of one cell built at the end. None where a
    formula raises on floats (a division by zero, the root of a negative number, where
    numpy gives ±∞ or NaN): the caller decides on arrays then.

    Why: a one-model selection is a block of one cell, where each numpy call costs its
    fixed overhead for one number, some five calls per rule."""
    xp = FLOAT_OPS
    first_missing, others_missing = lack.cell
    codes: list[int] = []
    values: list[float] = []
    limits: list[float] = []
    approximates: list[bool] = []
    reported_missing = list(first_missing)
    worst = 0.0
    try:
        for k, rule in enumerate(rules):
            applies = True if rule.applies is None else bool(rule.applies(q, xp))
            within = binding = True
            approximate = False
            if lack.everywhere[k]:  # no data: only the value, as reported
                value = float(rule.value(q, xp)) if detail else math.nan
                limit = math.nan
            else:
                value, limit = float(rule.value(q, xp)), float(rule.limit(q, xp))
                if rule.within is not None:
                    within = bool(rule.within(q, xp))
                if rule.binding is not None:
                    binding = bool(rule.binding(q, xp))
                if detail and rule.approximate is not None:
                    approximate = bool(rule.approximate(q, xp))
            code = PASS if value <= limit and within else FAIL if binding else WARN
            missing = first_missing[k] >= 0
            if k in lack.floors and first_missing[k] == 0 and not others_missing[k] and binding:
                floor = float(rule.lower_bound(q, xp))  # type: ignore[misc]
                if floor > limit or not within:  # fails on the least value over every J_A
                    value, missing, code = floor, False, FAIL
            if missing:
                code, limit, approximate = NO_DATA, math.nan, False
            if not applies:
                code, value, limit, approximate = NOT_APPLICABLE, math.nan, math.nan, False
                reported_missing[k] = -1
            if overload and code == FAIL:
                no_limit = limit != limit or limit <= 0 or value != value
                over = math.inf if no_limit else float_maximum(value / limit, 1.0)
                worst = float_maximum(worst, over)
            codes.append(int(code))
            values.append(value)
            limits.append(limit)
            approximates.append(approximate)
    except (ArithmeticError, ValueError):
        return None
    shape = (len(rules), 1, 1)
    statuses = np.array(codes, dtype=np.int8).reshape(shape)
    out = None
    if detail:
        out = RuleArrays(
            values=np.array(values).reshape(shape),
            limits=np.array(limits).reshape(shape),
            approximate=np.array(approximates, dtype=np.bool_).reshape(shape),
            first_missing=np.array(reported_missing, dtype=np.int8).reshape(shape),
        )
    if not overload:
        return statuses, NO_OVERLOAD, out
    return statuses, np.full((1, 1), worst), out


NO_OVERLOAD: FloatArray = np.zeros(())
"""The overload where it is not asked for (:func:`status_codes`' ``overload``): 0,
broadcasting to any cells."""


def _overload(codes: CodeArray, values: FloatArray, limits: FloatArray) -> FloatArray:
    """The largest :func:`~actuator_selection.sizing.checks.overload` of the rules per
    cell: value/limit, at least 1, where a rule fails; infinite where it has no limit."""
    failing = codes == FAIL
    if not failing.any():  # nothing fails: no overload (most cells of a selection)
        return np.zeros(codes.shape[1:])
    # A limit: above 0 (not NaN), and a value (not NaN); two passes where NaN, ≤ 0, NaN
    # took five
    has_limit = limits > 0.0
    has_limit &= values == values
    # np.where(no limit, ∞, max(v/l, 1)), then 0 where it does not fail, in place (np.where
    # of a scalar took its slow path)
    over = values / limits
    np.maximum(over, 1.0, out=over)
    np.copyto(over, math.inf, where=~has_limit)
    np.copyto(over, 0.0, where=~failing)
    if over.shape[0] == 1:  # one rule: its overloads, each ≥ 0 (or NaN) as max() keeps it
        only: FloatArray = over[0]
        return only
    overload: FloatArray = over.max(axis=0, initial=0.0)
    return overload


def _floor_fails(
    rule: Rule,
    q: Operands,
    lack: Lacking,
    index: int,
    values: FloatArray,
    limits: FloatArray,
    within: BoolArray | None,
    binding: BoolArray | None,
    k: int,
) -> BoolArray:
    """Where ``rule`` (``index`` in ``lack``, ``k`` in ``within`` and ``binding``) fails on
    its :attr:`~actuator_selection.sizing.checks.Rule.lower_bound` (``Rule.check``'s
    ``_floor_failure`` on arrays): only its first requirement (J_A) is missing and even
    the least value over every J_A fails; there ``values`` becomes that least value."""
    assert rule.lower_bound is not None
    floor = rule.lower_bound(q, ARRAY_OPS)
    fails: BoolArray = (
        (lack.first_missing[index] == 0)
        & ~lack.others_missing[index]
        & ((floor > limits) | (False if within is None else ~within[k]))
        & (True if binding is None else binding[k])
    )
    values[...] = np.where(fails, floor, values)
    return fails
