"""The rule machinery: a check (:class:`Check`), its rule (:class:`Rule`), what a rule
needs of the catalogue (:class:`Requirement`) and the operations it computes with.

A rule's formulas are written once: each receives the :class:`~actuator_selection.sizing.
checks.operands.Operands` (arrays that broadcast: cases as a column, actuators as a row;
floats for one cell) and an :class:`Ops` namespace with the few operations Python's
operators do not cover. The engine (:mod:`actuator_selection.sizing.engine`) runs every rule
on its arrays and decides the status there; :meth:`Rule.report` then builds one cell's
:class:`Check` with its words from that decision. A catalogue value that is not published
is NaN, never None; a rule's :attr:`Rule.requires` decides ``no_data`` before any NaN is
compared. Combine truth values with ``&`` and ``|``, never ``and``/``or``/``not`` (they
do not work element-wise); negate with ``xp.not_``.

The rules themselves live one family to a file in :mod:`actuator_selection.sizing.checks.
rules`, each with its words beside it.
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum
from typing import TYPE_CHECKING, Any, Final

from actuator_selection.phrases.check_messages import Phrase, check_words, phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.checks.operands import Operands, Real, Truth
from actuator_selection.sizing.deferred import Deferred, defer_field

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

__all__ = [
    "FLOAT_OPS",
    "Brief",
    "Check",
    "DeferredChecks",
    "Formula",
    "Message",
    "Operands",
    "Ops",
    "Pick",
    "Real",
    "Requirement",
    "Rule",
    "Said",
    "Status",
    "Term",
    "Truth",
    "Variants",
    "compared",
    "given_limit",
    "given_value",
    "larger",
    "margin_percent",
    "outcome",
    "overload",
    "published",
    "said",
]

WORDS: Final = {
    "no_data": N_("no data: the catalogue gives no {what} for this actuator"),
    "fail_for_any_inertia": N_(
        "{message}, at its least for any J_A ≥ 0 (the catalogue gives no J_A for this actuator)"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)


class Status(StrEnum):
    """Outcome of one check.

    ``no_data``: the check applies, but a catalogue value it needs is not published (the
    verdict is "unconfirmed"). ``not_applicable``: the check's premise does not hold for
    this actuator or case (:attr:`Rule.applies`), so there is nothing to judge; it
    neither passes nor fails the verdict (docs/decisions/0025-not-applicable.md).
    """

    PASS = "pass"
    FAIL = "fail"
    WARN = "warn"
    NO_DATA = "no_data"
    NOT_APPLICABLE = "not_applicable"

    @property
    def open(self) -> bool:
        """Whether the check is one of a candidate's reasons: it fails, warns or lacks
        data (neither ``pass`` nor ``not_applicable``)."""
        return self in _OPEN


_OPEN: Final = frozenset((Status.FAIL, Status.WARN, Status.NO_DATA))


@dataclass(frozen=True, slots=True, kw_only=True)
class Check:
    """One step of the flowchart: ``value`` compared with ``limit`` (value ≤ limit passes)."""

    name: str
    status: Status
    value: float | None
    limit: float | None
    unit: str
    reference: str
    message: str
    approximate: bool = False
    missing: str | None = None
    """The catalogue value that is missing, in words: for ``no_data``, what the check
    needs; for a ``fail`` on a lower bound (:attr:`Rule.lower_bound`), what the value's
    least over every possible value stands in for (J_A). None otherwise."""

    @property
    def margin_percent(self) -> float | None:
        """Headroom (limit − value)/limit [%] (:func:`margin_percent`)."""
        return margin_percent(self.value, self.limit)

    @property
    def utilisation(self) -> float | None:
        """value/limit: how much of the limit the value uses (:func:`utilisation`)."""
        return utilisation(self.value, self.limit)

    @property
    def overload(self) -> float:
        """How far a failed check is over its limit (:func:`overload`); 0 unless failed."""
        return overload(self.status, self.value, self.limit)


def utilisation(value: float | None, limit: float | None) -> float | None:
    """value/limit: how much of the limit the value uses (> 1 when it is exceeded); None
    without both or where the limit is not positive."""
    if value is None or limit is None or limit <= 0:
        return None
    return value / limit


class _Words(Deferred):
    """A check's message not written yet (:meth:`Rule.report` with ``defer``): a check
    listed as numbers never has its words read; a candidate's detail reads them.
    """

    __slots__ = ("_limit", "_missing", "_q", "_rule", "_status", "_value")

    def __init__(
        self,
        rule: Rule,
        q: Operands,
        status: Status,
        value: float,
        limit: float,
        missing: int | None,
    ) -> None:
        self._rule, self._q, self._status = rule, q, status
        self._value, self._limit, self._missing = value, limit, missing

    def resolve(self) -> str:
        return self._rule.words(self._q, self._status, self._value, self._limit, self._missing)


defer_field(Check, "message")


Brief = tuple[Status, float | None, float | None, bool, str]
"""A check's status, value, limit, ``approximate`` and message, as its :class:`Check` has
them (:meth:`Rule.brief`); its name, unit and reference are its rule's."""


class DeferredChecks(Deferred):
    """A candidate's checks decided (by the engine) but not built yet:
    :meth:`resolve` builds them all, :meth:`reasons` words only those that do not pass
    (a candidate's ``reasons``) without building them."""

    __slots__ = ()

    def resolve(self) -> tuple[Check, ...]:
        """Every check, in the rules' order."""
        raise NotImplementedError

    def reasons(self) -> list[str]:
        """The messages of the checks that fail, warn or lack data, in the rules' order
        (:meth:`Rule.words`)."""
        raise NotImplementedError

    def briefs(self) -> list[tuple[Rule, Brief]]:
        """Every check as its rule and a :data:`Brief`, in the rules' order, without
        building it."""
        raise NotImplementedError

    def open_names(self) -> list[str]:
        """The names of the checks that fail, warn or lack data, in the rules' order,
        without building or wording them."""
        raise NotImplementedError

    def decided(self) -> tuple[Any, int]:
        """The engine's decisions of the cells detailed with these (a
        :class:`~actuator_selection.sizing.engine.detail.DecidedCells`), and which cell
        these are: a batch writes every cell's checks from its arrays at once."""
        raise NotImplementedError


def margin_percent(value: float | None, limit: float | None) -> float | None:
    """Headroom (limit − value)/limit [%]; negative when the limit is exceeded; None
    without a value or a positive limit.

    >>> margin_percent(40.0, 90.0) == (90.0 - 40.0) / 90.0 * 100.0
    True
    """
    if value is None or limit is None or limit <= 0:
        return None
    return (limit - value) / limit * 100.0


def overload(status: Status, value: float | None, limit: float | None) -> float:
    """How far a check is over its limit, for ranking actuators that do not fit.

    0 unless the check failed; else value/limit, at least 1 (a check that fails on a
    further condition, such as n_av beyond n_max in the continuous check, is at its
    limit at least), and infinite where there is no limit to compare with (beyond a
    zone's last speed). The vectorised ranking computes the same
    (:mod:`actuator_selection.sizing.engine`).

    >>> overload(Status.FAIL, 120.0, 100.0), overload(Status.PASS, 80.0, 100.0)
    (1.2, 0.0)
    """
    if status is not Status.FAIL:
        return 0.0
    if value is None or limit is None or limit <= 0:
        return math.inf
    return max(value / limit, 1.0)


_new_object = object.__new__
_set_field = object.__setattr__  # Check is frozen


def _new_check(
    name: str,
    status: Status,
    value: float | None,
    limit: float | None,
    unit: str,
    reference: str,
    message: str,
    approximate: bool,
    missing: str | None = None,
) -> Check:
    """``Check(name=…, …)`` at two thirds of the cost, for :meth:`Rule.check`.

    The generated frozen ``__init__`` takes keywords and looks up ``object.__setattr__``
    for each field; the engine's candidates build eight checks each
    (a batch: eight for each of 30,000 candidates). tests/sizing/test_checks.py keeps
    this equal to ``Check(...)``, field for field.
    """
    check: Check = _new_object(Check)
    _set_field(check, "name", name)
    _set_field(check, "status", status)
    _set_field(check, "value", value)
    _set_field(check, "limit", limit)
    _set_field(check, "unit", unit)
    _set_field(check, "reference", reference)
    _set_field(check, "message", message)
    _set_field(check, "approximate", approximate)
    _set_field(check, "missing", missing)
    return check


def _where(condition: bool, if_true: float, if_false: float) -> float:
    return if_true if condition else if_false


@dataclass(frozen=True, slots=True, kw_only=True)
class Ops:
    """The operations a rule needs beyond arithmetic, comparison, ``&``, ``|`` and ``abs``."""

    where: Callable[[Any, Any, Any], Any]
    """``where(condition, if_true, if_false)``, element-wise."""
    isnan: Callable[[Any], Any]
    """NaN test: an unpublished catalogue value."""
    not_: Callable[[Any], Any]
    """Logical negation (``~`` would turn a Python bool into −1 or −2)."""
    sqrt: Callable[[Any], Any]
    """Square root (correctly rounded in IEEE 754, so equal on floats and arrays)."""
    pow: Callable[[Any, float], Any]
    """``x`` to a float power, as Python's ``math.pow`` computes it: numpy's own power
    differs from the C library's in the last bit for some inputs, so the vectorised
    flowchart maps ``math.pow`` over its (case-only) arrays."""


FLOAT_OPS = Ops(where=_where, isnan=math.isnan, not_=operator.not_, sqrt=math.sqrt, pow=math.pow)
"""The operations on Python floats: one cell's words, and the tests' plain-float oracle."""

Formula = Callable[[Operands, Ops], Any]
"""A rule's formula: a :data:`Real` or a :data:`Truth`, from the operands."""
Message = Callable[[Operands, Status, Any, Any], str]
"""A rule's message from (operands, status, value, limit); floats, the limit NaN where
there is none. Called on floats only: by :meth:`Rule.report`, for one actuator and one
case (the engine's candidates are reported one by one)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Requirement:
    """Catalogue values a rule needs: without them its status is ``no_data``.

    Met where any one of :attr:`any_of` is published (not NaN), or where :attr:`unless`
    holds. "No data" is a fact about the catalogue entry, so a requirement names
    catalogue values only.
    """

    any_of: tuple[str, ...]
    """Names of catalogue values in :class:`Operands`; one of them suffices."""
    what: str
    """The value in words, for "the catalogue gives no … for this actuator"."""
    unless: str | None = None
    """Name of a truth in :class:`Operands` under which nothing is needed, or None."""

    def missing(self, q: Operands, xp: Ops) -> Truth:
        """Where the requirement is not met (:meth:`Rule.check` has a short cut for floats)."""
        lacking = xp.isnan(getattr(q, self.any_of[0]))
        for name in self.any_of[1:]:
            lacking = lacking & xp.isnan(getattr(q, name))
        if self.unless is not None:
            lacking = lacking & xp.not_(getattr(q, self.unless))
        return lacking


def published(operand: str, what: str) -> Requirement:
    """The requirement that the catalogue value ``operand`` of :class:`Operands` is not NaN.

    >>> published("max_speed_rpm", "maximum output speed n_max").any_of
    ('max_speed_rpm',)
    """
    return Requirement(any_of=(operand,), what=what)


@dataclass(frozen=True, slots=True, kw_only=True, eq=False)
class Rule:
    """One check of the flowchart: ``value ≤ limit`` passes, given its catalogue values.

    A rule is equal only to itself (``eq=False``): cases are grouped by their tuple of
    rules, and hashing every field of every rule per case cost a 10,000-case batch ~60 ms.

    The status: ``not_applicable`` where :attr:`applies` does not hold; else ``no_data``
    where a requirement is missing (the first one names what is
    missing); else ``pass`` where ``value ≤ limit`` (and ``within``, if given, holds);
    else ``fail`` where ``binding`` holds (always, if not given), ``warn`` elsewhere. A
    limit that is NaN though nothing is missing (beyond a zone's last speed) fails.

    Each formula is called as ``f(q, xp)`` with the :class:`Operands` ``q`` and the
    :class:`Ops` ``xp``, on floats and on arrays alike; it must give the same IEEE result
    on both (the same operations in the same order) and must not raise on NaN operands
    (Python raises on a division by zero where numpy gives ±inf: keep divisors nonzero).
    The engine computes ``value`` even where data is missing, and reports it unless it
    is NaN.
    """

    name: str
    """The check's name in the API."""
    reference: str
    """The chapter's equation, table or figure."""
    unit: str
    """Unit of value and limit."""
    value: Formula
    """The quantity checked [unit]."""
    limit: Formula
    """The bound it must not exceed [unit]."""
    requires: tuple[Requirement, ...]
    """Catalogue values without which the check says ``no_data``, in the order they are named."""
    message: Message
    """The check in words, for pass, fail and warn (``no_data`` has one message for all)."""
    when: Callable[[Application], bool] | None = None
    """Which load cases it checks (the brake's where one is fitted, the output bearing's
    where an output load is given, …); None: every one. The rules are found in their
    family's file (:data:`~actuator_selection.sizing.checks.rules.ALL_RULES`) and each case
    runs those whose ``when`` holds (:attr:`~actuator_selection.sizing.application.
    rules_for`): a rule sharing a condition with others names the same function."""
    within: Formula | None = None
    """A further condition for passing, or None."""
    binding: Formula | None = None
    """Where an exceeded limit fails (elsewhere it warns); None: it always fails."""
    approximate: Formula | None = None
    """Where the limit is a simplified stand-in (reported with the check); None: never."""
    applies: Formula | None = None
    """Where the check's premise holds (a :data:`Truth`); elsewhere its status is
    ``not_applicable``, decided before any data is needed, and :attr:`message` is called
    with that status for its words (value and limit NaN). None: it always applies."""
    lower_bound: Formula | None = None
    """The least value over every J_A ≥ 0, or None. Where the catalogue lacks only the
    rule's first requirement (J_A) and even this least value fails (it exceeds the limit,
    or ``within`` fails, which does not depend on J_A), the check fails rather than
    lacking data: it would fail for every J_A."""
    _no_data: tuple[tuple[str | None, tuple[str, ...], str, str], ...] = field(
        init=False, repr=False, compare=False
    )
    """:attr:`requires` as (unless, any_of, message, what) for :meth:`check`'s short cut."""

    def __post_init__(self) -> None:
        no_data = tuple(
            (
                need.unless,
                need.any_of,
                phrase("no_data", what=need.what),
                need.what,
            )
            for need in self.requires
        )
        object.__setattr__(self, "_no_data", no_data)

    def check(self, q: Operands) -> Check:
        """The check for one actuator and one load case (floats); its words are written
        when its message is first read (an answer that lists checks as numbers never
        reads them)."""
        xp = FLOAT_OPS
        if self.applies is not None and not self.applies(q, xp):
            return self.report(q, Status.NOT_APPLICABLE, math.nan, math.nan, False, None)
        value = self.value(q, xp)
        for index, (unless, any_of, _, _) in enumerate(self._no_data):
            if unless is not None and getattr(q, unless):
                continue
            for name in any_of:
                published_value = getattr(q, name)
                if published_value == published_value:  # not NaN
                    break
            else:
                if index == 0 and self.lower_bound is not None and self._others_met(q):
                    floor = self._floor_failure(q)
                    if floor is not None:
                        return floor
                return self.report(q, Status.NO_DATA, value, math.nan, False, index)
        limit = self.limit(q, xp)
        if value <= limit and (self.within is None or self.within(q, xp)):
            status = Status.PASS
        elif self.binding is None or self.binding(q, xp):
            status = Status.FAIL
        else:
            status = Status.WARN
        approximate = self.approximate is not None and self.approximate(q, xp)
        return self.report(q, status, value, limit, approximate, None, defer=True)

    def report(
        self,
        q: Operands,
        status: Status,
        value: float,
        limit: float,
        approximate: bool,
        missing: int | None,
        *,
        defer: bool = False,
    ) -> Check:
        """The check with its words (:meth:`words`), from a decision already taken: by
        :meth:`check` (with ``defer``: the words written when first read), or by the
        engine for the candidates whose checks it lists.

        ``value`` and ``limit`` as the rule computed them (NaN where unknown or beyond a
        zone's last speed); ``missing``: the index into :attr:`requires` of the first
        requirement not met, for ``no_data``, and for a ``fail`` on :attr:`lower_bound`
        (then 0, J_A, and ``value`` is the least value); else None.
        """
        if status is Status.NO_DATA:
            assert missing is not None
            _, _, no_data, what = self._no_data[missing]
            known = value if value == value else None  # NaN: T_1, T_3, T_rms without J_A
            return _new_check(
                self.name, status, known, None, self.unit, self.reference, no_data, False, what
            )
        if status is Status.NOT_APPLICABLE:
            said = self.message(q, status, math.nan, math.nan)
            return _new_check(self.name, status, None, None, self.unit, self.reference, said, False)
        # failed for every J_A: at its least, without J_A
        lacking = self._no_data[missing][3] if missing is not None else None
        message: Any = (
            _Words(self, q, status, value, limit, missing)
            if defer
            else self.words(q, status, value, limit, missing)
        )
        return _new_check(
            self.name,
            status,
            value if value == value else None,
            limit if limit == limit else None,  # NaN: beyond a zone's last speed
            self.unit,
            self.reference,
            message,
            approximate,
            lacking,
        )

    def brief(
        self,
        q: Operands,
        status: Status,
        value: float,
        limit: float,
        approximate: bool,
        missing: int | None,
    ) -> Brief:
        """What :meth:`report` gives for the same arguments as a :data:`Brief` (status,
        value, limit, approximate, message), without building the check: a batch lists
        240,000 checks as numbers and codes."""
        if status is Status.NO_DATA:
            assert missing is not None
            known = value if value == value else None  # NaN: T_1, T_3, T_rms without J_A
            return (status, known, None, False, self._no_data[missing][2])
        if status is Status.NOT_APPLICABLE:
            return (status, None, None, False, self.message(q, status, math.nan, math.nan))
        return (
            status,
            value if value == value else None,
            limit if limit == limit else None,
            approximate,
            self.words(q, status, value, limit, missing),
        )

    def words(
        self, q: Operands, status: Status, value: float, limit: float, missing: int | None
    ) -> str:
        """The message of the check :meth:`report` gives for the same arguments, without
        building the check: a batch words only the checks that do not pass (a
        candidate's reasons), and building each check first cost a third of that."""
        if status is Status.NO_DATA:
            assert missing is not None
            return self.no_data_message(missing)
        message = self.message(q, status, value, limit)
        # A failure at the least value for every J_A (lower_bound) names its missing J_A.
        return message if missing is None else _floor_message(message)

    def no_data_message(self, missing: int) -> str:
        """The message of ``no_data`` where the requirement ``missing`` (an index into
        :attr:`requires`) is the first one not met."""
        return self._no_data[missing][2]

    def _others_met(self, q: Operands) -> bool:
        """Whether every requirement but the first is met (floats)."""
        return not any(need.missing(q, FLOAT_OPS) for need in self.requires[1:])

    def _floor_failure(self, q: Operands) -> Check | None:
        """The check failed on :attr:`lower_bound`, or None where the bound passes; its
        ``missing`` names what the bound stands in for (the first requirement)."""
        assert self.lower_bound is not None
        xp = FLOAT_OPS
        floor, limit = self.lower_bound(q, xp), self.limit(q, xp)
        within = self.within is None or self.within(q, xp)
        if not (floor > limit or not within) or (
            self.binding is not None and not self.binding(q, xp)
        ):
            return None
        approximate = self.approximate is not None and self.approximate(q, xp)
        return self.report(q, Status.FAIL, floor, limit, approximate, 0, defer=True)


def _floor_message(message: str) -> str:
    """A failure at the least value over every J_A ≥ 0, in words."""
    if isinstance(message, Phrase):
        return phrase("fail_for_any_inertia", message=message)
    return f"{message}, at its least for any J_A ≥ 0 (the catalogue gives no J_A for this actuator)"


def outcome(status: Status) -> str:
    """The message variant of ``status`` for a rule that only passes or fails."""
    return "pass" if status is Status.PASS else "fail"


Term = Callable[[Operands, Ops, Any, Any], Any]
"""A message's param or condition, from the operands, the ops, and the check's value and
limit: a float for one cell, an array over many (as a rule's :data:`Formula`)."""


def given_value(q: Operands, xp: Ops, value: Any, limit: Any) -> Any:
    """The check's value, as a message's param."""
    return value


def given_limit(q: Operands, xp: Ops, value: Any, limit: Any) -> Any:
    """The check's limit, as a message's param."""
    return limit


@dataclass(frozen=True, slots=True)
class Said:
    """A rule's :data:`Message` (or a clause of one) declared rather than written out: its
    code and its params in their order. Being declared, the same message is also written
    for many cells at once from the engine's arrays (a batch's codes and params,
    ``services/presenters/batch.py``), its :data:`Term` params run on arrays as the rules'
    formulas do, with no call per check.

    ``code`` may name the check's ``{outcome}`` (:func:`outcome`: pass, fail) or its
    ``{status}`` (pass, fail, warn). A param is a :data:`Term`, a nested :class:`Said` (a
    clause), a :class:`Pick` between two, or a constant (words, a clause, None)."""

    code: str
    params: tuple[tuple[str, Any], ...] = ()
    codes: tuple[str, ...] = field(init=False, repr=False, compare=False)
    """``code`` for each status, in :class:`Status`' order."""

    def __post_init__(self) -> None:
        codes = tuple(self.code.format(outcome=outcome(s), status=s.value) for s in Status)
        object.__setattr__(self, "codes", codes)

    def __call__(self, q: Operands, status: Status, value: Any, limit: Any) -> str:
        params = {name: said(p, q, status, value, limit) for name, p in self.params}
        return Phrase(self.codes[_STATUS_INDEX[status]], params)  # phrase(), its dict built


_STATUS_INDEX: Final = {s: i for i, s in enumerate(Status)}


@dataclass(frozen=True, slots=True)
class Pick:
    """A param that is ``if_true`` where ``condition`` (a :data:`Term`) holds, else
    ``if_false`` (each a param of :class:`Said`)."""

    condition: Term
    if_true: Any
    if_false: Any


@dataclass(frozen=True, slots=True)
class Variants:
    """A rule's :data:`Message` that is the first of ``cases`` whose condition (a
    :data:`Term`; None: always) holds."""

    cases: tuple[tuple[Term | None, Said], ...]

    def __call__(self, q: Operands, status: Status, value: Any, limit: Any) -> str:
        for condition, message in self.cases:
            if condition is None or condition(q, FLOAT_OPS, value, limit):
                return message(q, status, value, limit)
        raise ValueError("no variant of the message holds")


def said(param: Any, q: Operands, status: Status, value: Any, limit: Any) -> Any:
    """A param of :class:`Said` for one cell."""
    if isinstance(param, Said):
        return param(q, status, value, limit)
    if isinstance(param, Pick):
        chosen = param.if_true if param.condition(q, FLOAT_OPS, value, limit) else param.if_false
        return said(chosen, q, status, value, limit)
    if callable(param):
        return param(q, FLOAT_OPS, value, limit)
    return param  # a constant: words, a clause or None


def compared(name: str, *extra: tuple[str, Any], by_status: bool = False) -> Said:
    """The message that says a check's value against its limit: the code
    ``{name}.{outcome}`` (or ``.{status}``), the params ``value``, ``limit``, then
    ``extra``."""
    code = f"{name}.{{status}}" if by_status else f"{name}.{{outcome}}"
    return Said(code, (("value", given_value), ("limit", given_limit), *extra))


def larger(a: Real, b: Real, xp: Ops) -> Real:
    """The larger of ``a`` and ``b``, element-wise (``b`` where it is larger)."""
    return xp.where(b > a, b, a)
