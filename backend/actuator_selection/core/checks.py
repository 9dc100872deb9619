"""The flowchart's checks as one table of rules (chapter p. 514–517).

Both flowcharts read :data:`RULES`: the scalar one
(:func:`~actuator_selection.core.selection.evaluate`) runs each rule on Python floats
for one actuator, the vectorised one (:mod:`actuator_selection.core.batch`) on numpy
arrays of load cases × actuators. A rule's formulas are written once for both: each
receives the :class:`Operands` — floats, or arrays that broadcast (cases as a column,
actuators as a row) — and an :class:`Ops` namespace with the few operations that
Python's operators do not cover (:data:`FLOAT_OPS` here, numpy's in the batch). A
catalogue value that is not published is NaN in the operands, never None, so the same
arithmetic runs on both; a rule's :attr:`Rule.requires` decides ``no_data`` before any
NaN is compared. Combine truth values with ``&`` and ``|``, never ``and``/``or``/``not``
(they do not work element-wise); negate with ``xp.not_``.

The rules, in the manufacturer's order (value ≤ limit passes):

1. ``max_speed``: n_2 ≤ n_max (Table 515.1);
2. ``inertia_ratio``: J_L ≤ 3·J_A (Table 515.1, footnote 1: recommended for highly
   dynamic applications, so a failure there and a warning otherwise);
3. ``peak_torque``: T_1 ≤ T_max (Eq. 514.1);
4. ``decel_torque``: |T_3| ≤ T_max (Eq. 514.1);
5. ``continuous_duty``: T_rms ≤ the continuous torque at n_av: the zone's edge (Fig. 517.1;
   Eq. 514.2, 514.3); where no zone is published, approximately T_0 − k_T·K_INL·n_av
   (Eq. 522.2, 522.3), else T_0;
6. ``thermal_peak``: T_rms stands only for a cycle short against the winding's thermal
   time constant: the peak of the winding's heating over the repeating cycle (the
   first-order model of Fig. 520.1), as a torque, against the same limit;
7. ``continuous_speed``: the speed side of the operating point: n_th, the speed the
   winding's heating follows by the same model (n_av for a short cycle), ≤ the zone's
   last, the allowable continuous or the rated speed.

Each check compares one quantity, and reports it with its own value, limit and unit.

**Adding a check is adding one rule** (its formulas and its message) to
:data:`RULES`; the scalar and the vectorised flowchart, the verdicts and the ranking
follow. Here n_av ≤ n_max (Eq. 514.3) as a further check, given to both flowcharts with
the chapter's worked example (Table 516.1, FHA-25C-50-L of Table 516.3):

>>> from actuator_selection.core.actuators import Actuator
>>> from actuator_selection.core.batch import evaluate_batch
>>> from actuator_selection.core.cycle import Load, SpeedPattern
>>> from actuator_selection.core.selection import Application, evaluate
>>> mean_speed = Rule(
...     name="mean_speed", reference="Eq. 514.3", unit="rpm",
...     value=lambda q, xp: q.mean_speed_rpm,
...     limit=lambda q, xp: q.max_speed_rpm,
...     requires=(published("max_speed_rpm", "maximum output speed n_max"),),
...     message=lambda q, status, value, limit: f"n_av = {value:.4g} rpm, n_max = {limit:.4g} rpm")
>>> app = Application(
...     pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1),
...     load=Load(torque_nm=5, inertia_kgm2=1.3))
>>> fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50,
...                max_torque_nm=151, max_speed_rpm=90, inertia_kgm2=0.86)
>>> rules = (*RULES, mean_speed)
>>> check = evaluate(fha, app, rules=rules).checks[-1]
>>> check.name, check.status.value, check.message
('mean_speed', 'pass', 'n_av = 6.154 rpm, n_max = 90 rpm')
>>> evaluate_batch([fha], [app], rules=rules).status(0, 0, "mean_speed").value
'pass'
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any, NamedTuple

from actuator_selection.core import bearing, electrical
from actuator_selection.core.check_messages import Phrase, phrase
from actuator_selection.core.deferred import Deferred, defer_field
from actuator_selection.core.messages import N_
from actuator_selection.core.units import RAD_PER_S_PER_RPM

INERTIA_RATIO_LIMIT = 3.0
"""J_L ≤ 3·J_A, the pre-selection rule of Table 515.1."""


class Status(StrEnum):
    """Outcome of one check."""

    PASS = "pass"
    FAIL = "fail"
    WARN = "warn"
    NO_DATA = "no_data"


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
    """A check's message not written yet (:meth:`Rule.report` with ``defer``): the
    scalar flowchart's checks (:meth:`Rule.check`) are listed as numbers by a
    selection's answer, which never reads their words; a candidate's detail does.
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


class DeferredChecks(Deferred):
    """A candidate's checks decided (by the vectorised flowchart) but not built yet:
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
    (:mod:`actuator_selection.core.batch`).

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
    for each field; the scalar flowchart builds five checks for every actuator of every
    case (a batch: five for each of 30,000 candidates). tests/core/test_checks.py keeps
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


Real = Any
"""A float in the scalar flowchart; a float64 array in the vectorised one."""
Truth = Any
"""A bool in the scalar flowchart; a bool array in the vectorised one."""


class Operands(NamedTuple):
    """What the rules compute from: the load case, the cycle, the actuator.

    Floats for one case and one actuator in the scalar flowchart; in the vectorised
    one, case quantities are columns (cases × 1), catalogue values rows (actuators),
    cycle torques cases × actuators. Unpublished catalogue values are NaN.

    Immutable like the frozen dataclasses of the core, but a named tuple: the scalar
    flowchart builds one for every actuator of every case (one
    :func:`~actuator_selection.core.selection.evaluate` takes about 15 µs), and a
    frozen dataclass of 15 fields takes about 2 µs to build, a named tuple built
    positionally about 0.4 µs.
    """

    speed_rpm: Real
    """Load speed n_2 [rpm] (Table 516.1): the highest |speed| of the cycle."""
    load_inertia_kgm2: Real
    """Load moment of inertia J_L [kgm²]."""
    high_dynamics: Truth
    """Whether the application is highly dynamic (Table 515.1, footnote 1)."""
    mean_speed_rpm: Real
    """Average output speed n_av [rpm] (Eq. 514.3)."""
    accel_torque_nm: Real
    """Acceleration torque T_1 [Nm] (Eq. 514.1); NaN without J_A."""
    decel_torque_nm: Real
    """Deceleration torque T_3 [Nm] (Eq. 514.1), negative while braking; NaN without J_A."""
    rms_torque_nm: Real
    """RMS torque T_rms [Nm] (Eq. 514.2); NaN without J_A."""
    max_torque_nm: Real
    """Repeated peak torque T_max [Nm]."""
    max_speed_rpm: Real
    """Maximum output speed n_max [rpm]."""
    inertia_kgm2: Real
    """Actuator moment of inertia J_A at the output [kgm²]."""
    stall_torque_nm: Real
    """Continuous stall torque T_0 [Nm]."""
    continuous_torque_nm: Real
    """Allowable continuous torque, where a catalogue gives that instead of T_0 [Nm]."""
    has_zone: Truth
    """Whether a continuous-duty zone is published (Fig. 517.1)."""
    zone_torque_nm: Real
    """The zone's edge at n_av [Nm]; NaN without a zone or beyond its last speed."""
    zone_max_speed_rpm: Real
    """The highest speed the zone covers [rpm]; NaN without a zone."""
    accel_torque_floor_nm: Real
    """The least T_1 over every J_A ≥ 0 [Nm] (:class:`~actuator_selection.core.cycle.
    TorqueFloors`): what fails without J_A."""
    decel_torque_floor_nm: Real
    """The least |T_3| over every J_A ≥ 0 [Nm]."""
    rms_torque_floor_nm: Real
    """The least T_rms over every J_A ≥ 0 [Nm]."""
    continuous_speed_rpm: Real
    """Allowable continuous output speed [rpm] (FHA-C); NaN where not published."""
    rated_speed_rpm: Real
    """Rated output speed [rpm] (CHA: rated motor speed / i); NaN where not published."""
    load_torque_nm: Real
    """The torque held at standstill [Nm]: |T_G| + T_F of the axis (for the chapter's load,
    T_L, taken as acting at standstill for the brake)."""
    brake_holding_torque_nm: Real
    """The holding brake's holding torque at the output [Nm]; NaN where not published."""
    decel_s: Real
    """Deceleration time t_3 [s] (Table 516.1), for the energy braking returns."""
    gear_ratio: Real
    """Gear ratio i [-]."""
    torque_constant_nm_per_a: Real
    """Torque constant at the output k_T [Nm/A] (CHA k_Tout); NaN where not published."""
    max_current_a: Real
    """Maximum current I_max [A]; NaN where not published."""
    no_load_starting_current_a: Real
    """No-load starting current I_NLS [A] (Eq. 522.2); NaN where not published."""
    no_load_current_constant_a_per_rpm: Real
    """No-load running current constant K_INL at 30 °C [A/rpm] (Eq. 522.2); NaN where not
    published (the cold value: the larger, so the safe side)."""
    motor_voltage_constant_v_per_krpm: Real
    """Motor voltage constant K_E [V_rms line-to-line per 1000 rpm] (CHA k_EM)."""
    resistance_line_ohm: Real
    """Winding resistance line-to-line R [Ω]."""
    inductance_line_h: Real
    """Winding inductance line-to-line L [H]."""
    pole_pairs: Real
    """The motor's number of pole pairs p; NaN where not published."""
    dc_bus_voltage_v: Real
    """The highest nominal DC bus voltage the actuator runs on (its Table 521.1 bus
    classes) [V]; NaN where no bus class is published."""
    radial_force_n: Real
    """External radial force F_r on the output flange [N]; NaN without an output load."""
    axial_force_n: Real
    """External axial force F_a [N]; NaN without an output load."""
    radial_lever_m: Real
    """L_r [m]: where F_r acts, from the output flange."""
    axial_lever_m: Real
    """L_a [m]: the distance of F_a from the axis."""
    load_factor: Real
    """f_w of the bearing life formula [-]."""
    static_safety_min: Real
    """The least static safety factor f_s the application needs [-]."""
    required_life_h: Real
    """The bearing life L_10 the application needs [h]; NaN where not asked."""
    swing_deg: Real
    """The cycle's swing [°] (:func:`~actuator_selection.core.bearing.swing_deg`); NaN
    without an output load (the output bearing is not checked)."""
    bearing_pitch_diameter_m: Real
    """Output bearing pitch circle diameter d_p [m]; NaN where not published."""
    bearing_offset_m: Real
    """Output bearing offset R [m]; NaN where not published."""
    bearing_dynamic_load_rating_n: Real
    """Output bearing basic dynamic load rating C [N]; NaN where not published."""
    bearing_static_load_rating_n: Real
    """Output bearing basic static load rating C_0 [N]; NaN where not published."""
    bearing_life_exponent: Real
    """Life exponent B of the output bearing's type: 3 for a ball, 10/3 for a roller
    bearing (:func:`~actuator_selection.core.bearing.life_exponent`); NaN where the type is
    not published."""
    bearing_moment_load_nm: Real
    """Allowable moment load on the output bearing [Nm] (FHA-C, FHA-C mini)."""
    bearing_dynamic_tilting_moment_nm: Real
    """Allowable dynamic tilting moment M_dyn(max) [Nm] (CHA)."""
    cycle_s: Real
    """Cycle time t_0 [s] (Table 516.1: t_1 + t_2 + t_3 + t_p)."""
    thermal_time_constant_s: Real
    """The winding's thermal time constant τ_th [s]: the catalogue's, else the
    application's, else :data:`~actuator_selection.core.thermal.
    DEFAULT_THERMAL_TIME_CONSTANT_S`."""
    thermal_time_constant_assumed: Truth
    """Whether τ_th is that assumed default (neither catalogue nor application gives one)."""
    thermal_torque_nm: Real
    """The peak of the winding's heating over the repeating cycle as a torque, √max x [Nm]
    (:meth:`~actuator_selection.core.motion.Profile.thermal_torque_nm`); NaN without J_A."""
    thermal_speed_rpm: Real
    """n_th: the speed the winding's speed-dependent heating follows, at its peak over the
    repeating cycle, never below n_av [rpm] (:meth:`~actuator_selection.core.motion.
    Profile.thermal_speed_rpm`, with τ_th as for :attr:`thermal_torque_nm`)."""
    no_load_torque_slope_nm_per_rpm: Real
    """k_T·K_INL [Nm/rpm]: the torque that the speed-dependent no-load current K_INL·n of
    Eq. 522.2 takes from the continuous stall current, per rpm (Eq. 522.3); K_INL at
    80 °C where published (the warm actuator of continuous duty), else at 30 °C; NaN
    where k_T or K_INL is not published (:func:`no_load_torque_slope`)."""


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
"""The operations on Python floats, for the scalar flowchart."""

Formula = Callable[[Operands, Ops], Any]
"""A rule's formula: a :data:`Real` or a :data:`Truth`, from the operands."""
Message = Callable[[Operands, Status, Any, Any], str]
"""A rule's message from (operands, status, value, limit); floats, the limit NaN where
there is none. Called on floats only: by :meth:`Rule.report`, for one actuator and one
case (the vectorised flowchart's candidates are reported one by one)."""


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

    The status: ``no_data`` where a requirement is missing (the first one names what is
    missing); else ``pass`` where ``value ≤ limit`` (and ``within``, if given, holds);
    else ``fail`` where ``binding`` holds (always, if not given), ``warn`` elsewhere. A
    limit that is NaN though nothing is missing (beyond a zone's last speed) fails.

    Each formula is called as ``f(q, xp)`` with the :class:`Operands` ``q`` and the
    :class:`Ops` ``xp``, on floats and on arrays alike; it must give the same IEEE result
    on both (the same operations in the same order) and must not raise on NaN operands
    (Python raises on a division by zero where numpy gives ±inf: keep divisors nonzero).
    The scalar flowchart computes ``value`` even where data is missing, and reports it
    unless it is NaN.
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
    within: Formula | None = None
    """A further condition for passing, or None."""
    binding: Formula | None = None
    """Where an exceeded limit fails (elsewhere it warns); None: it always fails."""
    approximate: Formula | None = None
    """Where the limit is a simplified stand-in (reported with the check); None: never."""
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
        vectorised flowchart for the candidates whose checks a batch lists.

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

    def words(
        self, q: Operands, status: Status, value: float, limit: float, missing: int | None
    ) -> str:
        """The message of the check :meth:`report` gives for the same arguments, without
        building the check: a batch words only the checks that do not pass (a
        candidate's reasons), and building each check first cost a third of that."""
        if status is Status.NO_DATA:
            assert missing is not None
            return self._no_data[missing][2]
        message = self.message(q, status, value, limit)
        # A failure at the least value for every J_A (lower_bound) names its missing J_A.
        return message if missing is None else _floor_message(message)

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


def _outcome(status: Status) -> str:
    """The message variant of ``status`` for a rule that only passes or fails."""
    return "pass" if status is Status.PASS else "fail"


# --- 1. max_speed: n_2 ≤ n_max (Table 515.1) ------------------------------------------------


def _max_speed_message(q: Operands, status: Status, n_2: float, n_max: float) -> str:
    return phrase(f"max_speed.{_outcome(status)}", value=n_2, limit=n_max)


MAX_SPEED = Rule(
    name="max_speed",
    reference="Table 515.1",
    unit="rpm",
    value=lambda q, xp: q.speed_rpm,
    limit=lambda q, xp: q.max_speed_rpm,
    requires=(published("max_speed_rpm", N_("maximum output speed n_max")),),
    message=_max_speed_message,
)
"""n_2 ≤ n_max (Table 515.1)."""


# --- 2. inertia_ratio: J_L ≤ 3·J_A (Table 515.1, footnote 1) --------------------------------


def _inertia_ratio_message(q: Operands, status: Status, j_l: float, limit: float) -> str:
    return phrase(f"inertia_ratio.{status.value}", value=j_l, limit=limit)


INERTIA_RATIO = Rule(
    name="inertia_ratio",
    reference="Table 515.1",
    unit="kgm²",
    value=lambda q, xp: q.load_inertia_kgm2,
    limit=lambda q, xp: INERTIA_RATIO_LIMIT * q.inertia_kgm2,
    requires=(published("inertia_kgm2", N_("moment of inertia J_A")),),
    binding=lambda q, xp: q.high_dynamics,
    message=_inertia_ratio_message,
)
"""J_L ≤ 3·J_A (Table 515.1); binding for highly dynamic applications only, a warning else."""


# --- 3., 4. peak_torque, decel_torque: T_1, |T_3| ≤ T_max (Eq. 514.1) -----------------------


def _torque_message(rule: str) -> Message:
    def message(q: Operands, status: Status, torque: float, t_max: float) -> str:
        return phrase(f"{rule}.{_outcome(status)}", value=torque, limit=t_max)

    return message


_TORQUE_REQUIRES = (
    published("inertia_kgm2", N_("moment of inertia J_A")),  # T_1, T_3 need it
    published("max_torque_nm", N_("maximum torque T_max")),
)

PEAK_TORQUE = Rule(
    name="peak_torque",
    reference="Eq. 514.1",
    unit="Nm",
    value=lambda q, xp: abs(q.accel_torque_nm),
    limit=lambda q, xp: q.max_torque_nm,
    requires=_TORQUE_REQUIRES,
    message=_torque_message("peak_torque"),
    lower_bound=lambda q, xp: q.accel_torque_floor_nm,
)
"""|T_1| ≤ T_max (Eq. 514.1); T_1 is positive in the chapter's cycle, negative where a
cycle's largest accelerating torque drives the other way."""

DECEL_TORQUE = Rule(
    name="decel_torque",
    reference="Eq. 514.1",
    unit="Nm",
    value=lambda q, xp: abs(q.decel_torque_nm),
    limit=lambda q, xp: q.max_torque_nm,
    requires=_TORQUE_REQUIRES,
    message=_torque_message("decel_torque"),
    lower_bound=lambda q, xp: q.decel_torque_floor_nm,
)
"""|T_3| ≤ T_max (Eq. 514.1): braking loads the gear as much as accelerating."""


# --- 5. continuous_duty: (n_av, T_rms) in the zone (Fig. 517.1; Eq. 514.2, 514.3) -----------


def _continuous_limit(q: Operands, xp: Ops) -> Real:
    """The continuous torque at n_av: the zone's edge; without a zone, the current-based
    edge T_0 − k_T·K_INL·n_av (at least 0) where k_T and K_INL are published, else T_0,
    else the allowable continuous torque (a rectangle)."""
    rectangle = xp.where(xp.isnan(q.stall_torque_nm), q.continuous_torque_nm, q.stall_torque_nm)
    falling = q.stall_torque_nm - q.no_load_torque_slope_nm_per_rpm * q.mean_speed_rpm
    falling = xp.where(falling > 0.0, falling, 0.0)
    current = xp.not_(xp.isnan(q.no_load_torque_slope_nm_per_rpm) | xp.isnan(q.stall_torque_nm))
    return xp.where(q.has_zone, q.zone_torque_nm, xp.where(current, falling, rectangle))


def _continuous_message(q: Operands, status: Status, t_rms: float, limit: float) -> str:
    outcome = _outcome(status)
    n_av = q.mean_speed_rpm
    if q.has_zone:
        if math.isnan(limit):
            return phrase(
                "continuous_duty.beyond_zone",
                value=t_rms,
                mean_speed_rpm=n_av,
                zone_max_speed_rpm=q.zone_max_speed_rpm,
            )
        return phrase(f"continuous_duty.{outcome}", value=t_rms, limit=limit, mean_speed_rpm=n_av)
    slope = q.no_load_torque_slope_nm_per_rpm
    if not (math.isnan(slope) or math.isnan(q.stall_torque_nm)):
        return phrase(
            f"continuous_duty.current_{outcome}",
            value=t_rms,
            limit=limit,
            mean_speed_rpm=n_av,
            stall_torque_nm=q.stall_torque_nm,
            slope_nm_per_rpm=slope,
        )
    what = (
        N_("allowable continuous torque")
        if math.isnan(q.stall_torque_nm)
        else N_("continuous stall torque T_0")
    )
    return phrase(
        f"continuous_duty.rectangle_{outcome}",
        value=t_rms,
        limit=limit,
        mean_speed_rpm=n_av,
        what=what,
    )


_CONTINUOUS_LIMIT_DATA = Requirement(
    any_of=("stall_torque_nm", "continuous_torque_nm"),
    unless="has_zone",
    what=N_("continuous-duty zone or continuous torque"),
)
"""The continuous limit's data, for the checks that compare with it (``_continuous_limit``)."""

CONTINUOUS_DUTY = Rule(
    name="continuous_duty",
    reference="Fig. 517.1; Eq. 522.2, 522.3",
    unit="Nm",
    value=lambda q, xp: q.rms_torque_nm,
    limit=_continuous_limit,
    requires=(
        published("inertia_kgm2", N_("moment of inertia J_A (T_rms needs it)")),
        _CONTINUOUS_LIMIT_DATA,
    ),
    approximate=lambda q, xp: xp.not_(q.has_zone),
    message=_continuous_message,
    lower_bound=lambda q, xp: q.rms_torque_floor_nm,
)
"""T_rms against the continuous torque at n_av (Fig. 517.1; Eq. 514.2, 514.3): the torque
side of the operating point (n_av, T_rms); its speed side is :data:`CONTINUOUS_SPEED`.
Each check reports the one quantity it compares, so a failure names what binds (issue
"A verdict an application engineer signs", item 5: a speed failure here had reported
T_rms = 39.79 Nm against 55 Nm, a passing torque).

With a published zone the limit is the zone's edge at n_av (NaN beyond its last speed:
the check fails, and :data:`CONTINUOUS_SPEED` names the speed). Without one, the
continuous torque falls with speed as the winding current does (issue item 6): Eq. 522.3
with the winding at its continuous stall current I_0 gives T(n) = k_T·(I_0 − I_NLS −
K_INL·n), the no-load current I_NLR = I_NLS + K_INL·n of Eq. 522.2 taking its share of
I_0. At standstill k_T·(I_0 − I_NLS) reproduces the published T_0 of the CHA-20A…58A
rows within ±6.5 % (tests/core/test_continuous.py); the edge is anchored at the
published T_0, T_c(n) = T_0 − k_T·K_INL·n, so that the catalogue's own stall point
stands and the current sets the slope (K_INL at 80 °C, the warm actuator of continuous
duty, where published: :func:`~actuator_selection.core.electrical.
no_load_torque_slope_nm_per_rpm`). CHA-25A-50 at 53 Nm and 68 rpm: 55 − 26·0.002·68 =
51.5 Nm < 53 Nm, a failure (the winding would carry 53/26 + 0.19 + 0.002·68 = 2.36 A
against I_0 = 2.3 A). Where k_T or K_INL is not published (FHA-C), T_0 or the allowable
continuous torque stands as a rectangle. Both are stand-ins for a zone, so the check is
approximate without one.
"""


# --- 5b. continuous_speed: the speed the winding's heating follows ≤ the continuous speed ----


def _speed_limit(q: Operands, xp: Ops) -> Real:
    """The zone's last speed; without a zone, the allowable continuous speed, else the rated
    speed, never n_max (a peak)."""
    published_speed = xp.where(
        xp.isnan(q.continuous_speed_rpm), q.rated_speed_rpm, q.continuous_speed_rpm
    )
    return xp.where(q.has_zone, q.zone_max_speed_rpm, published_speed)


def _speed_message(q: Operands, status: Status, n_th: float, limit: float) -> str:
    if q.has_zone:
        what = N_("continuous-duty zone's last speed")
    elif not math.isnan(q.continuous_speed_rpm):
        what = N_("allowable continuous speed")
    else:
        what = N_("rated speed")
    model = phrase(
        "continuous_speed.model",
        tau_s=q.thermal_time_constant_s,
        assumed=_ASSUMED if q.thermal_time_constant_assumed else None,
    )
    return phrase(
        f"continuous_speed.{_outcome(status)}",
        value=n_th,
        limit=limit,
        mean_speed_rpm=q.mean_speed_rpm,
        speed_what=what,
        model=model,
    )


_ASSUMED = phrase("thermal_peak.assumed")
"""The clause "assumed" of the thermal model (no params: one for every message)."""

CONTINUOUS_SPEED = Rule(
    name="continuous_speed",
    reference="Eq. 514.3; Fig. 520.1 (model)",
    unit="rpm",
    value=lambda q, xp: q.thermal_speed_rpm,
    limit=_speed_limit,
    requires=(
        Requirement(
            any_of=("continuous_speed_rpm", "rated_speed_rpm"),
            unless="has_zone",
            what=N_("continuous-duty zone or allowable continuous or rated speed"),
        ),
    ),
    approximate=lambda q, xp: q.thermal_time_constant_assumed,
    message=_speed_message,
)
"""n_th ≤ the continuous speed: the speed side of the operating point (issue "A verdict an
application engineer signs", items 3 and 5).

The chapter checks the cycle's mean speed n_av (Eq. 514.3), which stands only for a
cycle short against the winding's thermal time constant τ_th: CHA-25A-50 running at
105 rpm (1.5 × its rated 70 rpm) for 30 minutes, then pausing an hour, has n_av =
35 rpm, yet the winding heats for half an hour as at 105 rpm. n_th follows |n| through
the repeating cycle with the first-order model of :data:`THERMAL_PEAK`
(:meth:`~actuator_selection.core.motion.Profile.thermal_speed_rpm`): n_av for a short
cycle, a segment's own speed where the segment is long against τ_th; a run at k times
the limit from standstill crosses it after τ_th·ln(k/(k − 1)), 1.1·τ_th at k = 1.5.
The example peaks at 100 rpm with the assumed τ_th = 600 s and fails.

The limit: the zone's last speed; without a zone the allowable continuous speed
(FHA-C), else the rated speed (CHA), never n_max, a peak. τ_th as in
:data:`THERMAL_PEAK`: the catalogue's, else the application's, else an assumed 600 s,
short, so strict (:data:`~actuator_selection.core.thermal.
DEFAULT_THERMAL_TIME_CONSTANT_S`), and then the check is approximate.
"""

# --- 6. thermal_peak: the cycle's heating peak ≤ the continuous limit (Fig. 520.1 model) ------


def _on_current(q: Operands, xp: Ops) -> Truth:
    """Where the heating follows the winding current (no zone; T_0, k_T and K_INL
    published): the thermal value counts k_T·K_INL·|n| beside the torque
    (:meth:`~actuator_selection.core.motion.Profile.thermal_torque_nm`)."""
    return xp.not_(
        q.has_zone | xp.isnan(q.no_load_torque_slope_nm_per_rpm) | xp.isnan(q.stall_torque_nm)
    )


def _heating_limit(q: Operands, xp: Ops) -> Real:
    """T_0 where the heating follows the winding current (its value carries the no-load
    current's share, so the edge at standstill bounds it), else the continuous limit at
    n_av (``_continuous_limit``)."""
    return xp.where(_on_current(q, xp), q.stall_torque_nm, _continuous_limit(q, xp))


def _thermal_message(q: Operands, status: Status, peak: float, limit: float) -> str:
    tau, t_0 = q.thermal_time_constant_s, q.cycle_s
    ratio = t_0 / tau
    model = phrase(
        "thermal_peak.model",
        tau_s=tau,
        assumed=_ASSUMED if q.thermal_time_constant_assumed else None,
        cycle_s=t_0,
        ratio=ratio,
        regime=phrase(
            "thermal_peak.short" if ratio <= 0.1 else "thermal_peak.long",
            rms_torque_nm=q.rms_torque_nm,
        ),
    )
    if math.isnan(limit):
        return phrase(
            "thermal_peak.beyond_zone",
            value=peak,
            mean_speed_rpm=q.mean_speed_rpm,
            zone_max_speed_rpm=q.zone_max_speed_rpm,
            model=model,
        )
    if _on_current(q, FLOAT_OPS):
        return phrase(
            f"thermal_peak.current_{_outcome(status)}",
            value=peak,
            limit=limit,
            slope_nm_per_rpm=q.no_load_torque_slope_nm_per_rpm,
            model=model,
        )
    return phrase(f"thermal_peak.{_outcome(status)}", value=peak, limit=limit, model=model)


THERMAL_PEAK = Rule(
    name="thermal_peak",
    reference="Fig. 520.1 (model); Eq. 514.2",
    unit="Nm",
    value=lambda q, xp: q.thermal_torque_nm,
    limit=_heating_limit,
    requires=(
        published("inertia_kgm2", N_("moment of inertia J_A (the cycle's torques need it)")),
        _CONTINUOUS_LIMIT_DATA,
    ),
    approximate=lambda q, xp: q.thermal_time_constant_assumed | xp.not_(q.has_zone),
    message=_thermal_message,
    # The peak of a periodic x is at least its mean, T_rms²: T_rms's least over J_A ≥ 0
    # bounds the peak from below.
    lower_bound=lambda q, xp: q.rms_torque_floor_nm,
)
"""T_rms stands only for a cycle short against the winding's thermal time constant
(issue "The checks a sizing engineer signs", item 3): CHA-25A-50 carrying 80 Nm
(1.45·T_0 = 1.45·55 Nm) for an hour and then pausing for ten hours has T_rms =
80·√(1/11) = 24 Nm and passes ``continuous_duty``, though the winding passes its
continuous limit within that hour (Fig. 520.1's model: after τ_th·ln(k²/(k² − 1)),
0.65·τ_th at k = 1.45).

The check follows the winding's temperature through the repeating cycle with the
first-order model that stands in for Fig. 520.1 (losses ∝ T², time constant τ_th, the
continuous limit T_c reached in steady state at T_c): its peak, as a torque
(:meth:`~actuator_selection.core.motion.Profile.thermal_torque_nm`), against the same
continuous limit as ``continuous_duty`` (the zone's edge at n_av, else T_0 or the
allowable continuous torque). For a cycle short against τ_th the peak tends to T_rms
(the chapter's check, Eq. 514.2); a segment long against τ_th counts with its own
torque, and a step from cold to k·T_c crosses the limit after τ_th·ln(k²/(k² − 1)),
the overload duration of Fig. 520.1's model (:func:`~actuator_selection.core.thermal.
overload_duration_s`).

Where k_T and K_INL are published and no zone is (the CHA), the heating follows the
winding current, not the torque alone (issue "A verdict an application engineer signs",
item 6): I = T/k_T + I_NLS + K_INL·|n| (Eq. 522.2, 522.3) counts, as the torque it stands
for, k_T·(I − I_NLS) = T + k_T·K_INL·|n| while moving and T at standstill, against T_0,
which that torque reaches at standstill with I = I_0 (``_heating_limit``): at constant T
and n the current-based edge T ≤ T_0 − k_T·K_INL·n of ``continuous_duty``. The losses are
taken ∝ (I − I_NLS)², not I²: the same limit in steady state, a stand-in for a cycle
(approximate, as without a zone). Elsewhere torque stands for current (T = k_T·I; the
no-load current and the speed-dependent iron losses left out, as T_rms leaves them
out). τ_th is the
catalogue's where published, else the application's, else an assumed default
(:data:`~actuator_selection.core.thermal.DEFAULT_THERMAL_TIME_CONSTANT_S`, reported as
approximate); the limit is approximate without a zone, as in ``continuous_duty``.
"""

# --- brake_holding: T_L ≤ the brake's holding torque (catalogue brake data) -----------------


def _brake_message(q: Operands, status: Status, t_l: float, holding: float) -> str:
    return phrase(f"brake_holding.{_outcome(status)}", value=t_l, limit=holding)


BRAKE_HOLDING = Rule(
    name="brake_holding",
    reference="catalogue brake data (holding torque)",
    unit="Nm",
    value=lambda q, xp: q.load_torque_nm,
    limit=lambda q, xp: q.brake_holding_torque_nm,
    requires=(published("brake_holding_torque_nm", N_("brake holding torque")),),
    message=_brake_message,
)
"""T_L ≤ the holding torque of the actuator's brake (CHA tables; FHA-C manual §4-2), for
an actuator fitted with one (``Application.brake``). The chapter's T_L opposes motion
and needs no holding at standstill when it is friction; taken as acting at standstill it
covers a load that does (a weight, a spring, a process force), so the check is on the
safe side."""

# --- drive_current: peak motor current ≤ I_max (Eq. 522.2, 522.3 reversed) --------------------


def _no_load_current(q: Operands, xp: Ops) -> Real:
    """I_NLR = I_NLS + K_INL(30 °C)·n_2 (Eq. 522.2) at the load speed, the largest over the
    cycle; 0 where the catalogue gives neither (the check is then approximate)."""
    unknown = xp.isnan(q.no_load_starting_current_a) | xp.isnan(
        q.no_load_current_constant_a_per_rpm
    )
    running = q.no_load_starting_current_a + q.no_load_current_constant_a_per_rpm * q.speed_rpm
    return xp.where(unknown, 0.0, running)


def _larger(a: Real, b: Real, xp: Ops) -> Real:
    return xp.where(b > a, b, a)


def _peak_current(q: Operands, xp: Ops) -> Real:
    """I = max(T_1, |T_3|)/k_T + I_NLR (Eq. 522.3 solved for I, Eq. 522.2)."""
    torque = _larger(q.accel_torque_nm, abs(q.decel_torque_nm), xp)
    return torque / q.torque_constant_nm_per_a + _no_load_current(q, xp)


def _peak_current_floor(q: Operands, xp: Ops) -> Real:
    """The least peak current over every J_A ≥ 0: from the least T_1 and |T_3|."""
    torque = _larger(q.accel_torque_floor_nm, q.decel_torque_floor_nm, xp)
    return torque / q.torque_constant_nm_per_a + _no_load_current(q, xp)


def regenerative_energy_j(*, decel_torque_nm: float, speed_rpm: float, decel_s: float) -> float:
    """Mechanical energy braking returns per cycle [J]: −T_3·(2π/60)·n_2·t_3/2 where T_3 < 0.

    The output torque T_3 is constant while the speed falls linearly from n_2 to 0 in
    t_3 (Table 516.1), so the energy is the torque times the angle turned. It is what
    flows back into the actuator; the gear's and winding's losses take part of it
    before it reaches the DC bus, so it bounds what a braking resistor or the bus
    capacitors must take. The chapter's worked example (T_3 = −85.48 Nm, 40 rpm, 0.1 s):

    >>> round(regenerative_energy_j(decel_torque_nm=-85.48, speed_rpm=40, decel_s=0.1), 2)
    17.9
    """
    if decel_torque_nm >= 0:
        return 0.0
    return -decel_torque_nm * (speed_rpm * RAD_PER_S_PER_RPM) * decel_s / 2.0


def _rms_current_bound(q: Operands) -> float:
    """An upper bound of the rms current: T_rms/k_T + the largest I_NLR (Minkowski)."""
    return float(q.rms_torque_nm / q.torque_constant_nm_per_a + _no_load_current(q, FLOAT_OPS))


def _current_message(q: Operands, status: Status, current: float, i_max: float) -> str:
    if math.isnan(q.no_load_starting_current_a) or math.isnan(q.no_load_current_constant_a_per_rpm):
        no_load = phrase("drive_current.no_load_unknown")
    else:
        no_load = phrase(
            "drive_current.no_load", no_load_current_a=float(_no_load_current(q, FLOAT_OPS))
        )
    rms = None
    if not math.isnan(q.rms_torque_nm):
        rms = phrase("drive_current.rms", rms_current_a=_rms_current_bound(q))
    braking = None
    if not math.isnan(q.decel_torque_nm):
        energy = regenerative_energy_j(
            decel_torque_nm=q.decel_torque_nm, speed_rpm=q.speed_rpm, decel_s=q.decel_s
        )
        braking = phrase("drive_current.braking", energy_j=energy)
    return phrase(
        f"drive_current.{_outcome(status)}",
        value=current,
        limit=i_max,
        no_load=no_load,
        rms=rms,
        braking=braking,
    )


DRIVE_CURRENT = Rule(
    name="drive_current",
    reference="Eq. 522.2, Eq. 522.3",
    unit="A",
    value=_peak_current,
    limit=lambda q, xp: q.max_current_a,
    requires=(
        published("inertia_kgm2", N_("moment of inertia J_A (T_1 and T_3 need it)")),
        published("torque_constant_nm_per_a", N_("torque constant k_T")),
        published("max_current_a", N_("maximum current I_max")),
    ),
    approximate=lambda q, xp: (
        xp.isnan(q.no_load_starting_current_a) | xp.isnan(q.no_load_current_constant_a_per_rpm)
    ),
    message=_current_message,
    lower_bound=_peak_current_floor,
)
"""Peak motor current I = max(T_1, |T_3|)/k_T + I_NLR ≤ I_max (Eq. 522.3 solved for the
current, I_NLR by Eq. 522.2 at n_2 with K_INL at 30 °C, the larger cold value).

Adding I_NLR while braking is on the safe side (the no-load losses help to brake).
Where the catalogue gives no no-load current (FHA-C) it is left out and the check is
approximate. The message reports an upper bound of the rms current and the energy
braking returns per cycle (:func:`regenerative_energy_j`)."""


# --- drive_voltage: U with ωL·I in quadrature ≤ the bus's output voltage (Eq. 521.2) ---------

SQRT2 = math.sqrt(2.0)
"""U_DC/√2: the largest sinusoidal line-to-line rms voltage of a bus with space-vector
modulation (:func:`~actuator_selection.core.electrical.max_output_voltage_v`)."""


def _resistive_sum(q: Operands) -> Real:
    """Eq. 521.2 as printed: U_OUT = n·i·K_E + I_MAX·R (line-to-line rms)."""
    return electrical.in_phase_voltage_v(
        output_speed_rpm=q.speed_rpm,
        gear_ratio=q.gear_ratio,
        motor_voltage_constant_v_per_krpm=q.motor_voltage_constant_v_per_krpm,
        max_current_a=q.max_current_a,
        resistance_line_ohm=q.resistance_line_ohm,
    )


def _inductive_drop(q: Operands) -> Real:
    """ω·L·I_MAX with ω = 2π·p·n·i/60, the electrical angular frequency [V]."""
    return electrical.inductive_voltage_v(
        output_speed_rpm=q.speed_rpm,
        gear_ratio=q.gear_ratio,
        pole_pairs=q.pole_pairs,
        inductance_line_h=q.inductance_line_h,
        max_current_a=q.max_current_a,
    )


def _drive_voltage(q: Operands, xp: Ops) -> Real:
    """U = √((n·i·K_E + I·R)² + (ω·L·I)²): Eq. 521.2 with the inductive drop in quadrature
    (:func:`~actuator_selection.core.electrical.needed_voltage_v`, the one formula)."""
    return electrical.needed_voltage_v(_resistive_sum(q), _inductive_drop(q), xp.sqrt)


def _voltage_message(q: Operands, status: Status, volts: float, available: float) -> str:
    return phrase(
        f"drive_voltage.{_outcome(status)}",
        value=volts,
        limit=available,
        speed_rpm=q.speed_rpm,
        dc_bus_voltage_v=q.dc_bus_voltage_v,
        printed_v=float(_resistive_sum(q)),
    )


DRIVE_VOLTAGE = Rule(
    name="drive_voltage",
    reference="Eq. 521.2 with ωL·I in quadrature",
    unit="V",
    value=_drive_voltage,
    limit=lambda q, xp: q.dc_bus_voltage_v / SQRT2,
    requires=(
        published("motor_voltage_constant_v_per_krpm", N_("motor voltage constant K_E (V_rms)")),
        published("max_current_a", N_("maximum current I_max")),
        published("resistance_line_ohm", N_("line-to-line resistance R")),
        published("inductance_line_h", N_("line-to-line inductance L")),
        published("pole_pairs", N_("number of pole pairs p")),
        published(
            "dc_bus_voltage_v",
            N_("controller listed for the actuator (Table 521.1) on a DC bus class it runs on"),
        ),
    ),
    message=_voltage_message,
)
"""The controller's output voltage at the load speed n_2 and I_max: Eq. 521.2 with the
inductive drop ω·L·I in quadrature, U = √((n·i·K_E + I·R)² + (ω·L·I)²), all line-to-line
rms, ω = 2π·p·n·i/60 the electrical angular frequency, against U_DC/√2 of the highest
DC bus class the actuator shares with a controller Table 521.1 lists for it (the
catalogue snapshot derives ``dc_bus_voltage_v`` so): it fails exactly when every listed
controller's own voltage check fails (:mod:`actuator_selection.core.drive`, the same
formula, :func:`~actuator_selection.core.electrical.needed_voltage_v`). The resistive
drop stays in phase with the back-EMF and uses R and L line-to-line, as the chapter
does: on the safe side (between two terminals of a star winding the drops are 2/√3 of
their line-to-line share). Eq. 521.2
as printed is reported beside it. Only the CHA-style constants (motor K_E in V_rms
line-to-line, R and L line-to-line, pole pairs) are published; elsewhere no data."""


# --- output bearing: tilting moment, static safety, L_10 life (CHA §4.3; FHA-C ch. 2) -------


def _moment(q: Operands) -> Real:
    return bearing.tilting_moment_nm(
        radial_force_n=q.radial_force_n,
        axial_force_n=q.axial_force_n,
        radial_lever_m=q.radial_lever_m,
        axial_lever_m=q.axial_lever_m,
        offset_m=q.bearing_offset_m,
    )


def _moment_limit(q: Operands, xp: Ops) -> Real:
    """The allowable moment load (FHA-C, FHA-C mini), else the CHA's M_dyn(max)."""
    return xp.where(
        xp.isnan(q.bearing_moment_load_nm),
        q.bearing_dynamic_tilting_moment_nm,
        q.bearing_moment_load_nm,
    )


def _moment_message(q: Operands, status: Status, moment: float, limit: float) -> str:
    what = (
        N_("the allowable dynamic tilting moment M_dyn")
        if math.isnan(q.bearing_moment_load_nm)
        else N_("the allowable moment load")
    )
    return phrase(
        f"bearing_moment.{_outcome(status)}",
        value=moment,
        limit=limit,
        what=what,
        offset_mm=q.bearing_offset_m * 1000,
    )


BEARING_MOMENT = Rule(
    name="bearing_moment",
    reference="CHA §4.3; FHA-C manual ch. 2, formula (1)",
    unit="Nm",
    value=lambda q, xp: _moment(q),
    limit=_moment_limit,
    requires=(
        published("bearing_offset_m", N_("output bearing offset R")),
        Requirement(
            any_of=("bearing_moment_load_nm", "bearing_dynamic_tilting_moment_nm"),
            what=N_("allowable tilting moment of the output bearing"),
        ),
    ),
    message=_moment_message,
)
"""M = F_r·(L_r + R) + F_a·L_a ≤ the allowable moment (FHA-C "permissible moment
capacity"; CHA M_dyn(max), the moving bearing's limit, stricter than the static M_0,
which the static safety factor covers)."""


def _static_load(q: Operands) -> Real:
    return bearing.static_equivalent_load_n(
        radial_force_n=q.radial_force_n,
        axial_force_n=q.axial_force_n,
        moment_nm=_moment(q),
        pitch_diameter_m=q.bearing_pitch_diameter_m,
    )


def _static_message(q: Operands, status: Status, needed: float, c_0: float) -> str:
    p_0 = _static_load(q)
    f_s = c_0 / p_0 if p_0 > 0 else math.inf
    return phrase(
        f"bearing_static_safety.{_outcome(status)}",
        value=needed,
        limit=c_0,
        p_0_n=float(p_0),
        f_s=float(f_s),
        f_s_min=q.static_safety_min,
    )


BEARING_STATIC = Rule(
    name="bearing_static_safety",
    reference="CHA §4.3; FHA-C manual ch. 2, formulas (9), (10)",
    unit="N",
    value=lambda q, xp: q.static_safety_min * _static_load(q),
    limit=lambda q, xp: q.bearing_static_load_rating_n,
    requires=(
        published("bearing_pitch_diameter_m", N_("output bearing pitch circle diameter d_p")),
        published("bearing_offset_m", N_("output bearing offset R")),
        published("bearing_static_load_rating_n", N_("output bearing static load rating C_0")),
    ),
    message=_static_message,
)
"""f_s = C_0/P_0 ≥ f_s,min, checked as f_s,min·P_0 ≤ C_0 [N] (no division by a load that
may be 0): the static capacity the application needs against the one it has."""


def _dynamic_load(q: Operands, xp: Ops) -> Real:
    return bearing.dynamic_equivalent_load_n(
        radial_force_n=q.radial_force_n,
        axial_force_n=q.axial_force_n,
        moment_nm=_moment(q),
        pitch_diameter_m=q.bearing_pitch_diameter_m,
        xp=xp,
    )


def _life_factor(q: Operands, xp: Ops) -> Real:
    """(L_h·60·n_av/10⁶)^(1/B) with B of the bearing's type (3 ball, 10/3 roller); where
    the type is not published, the larger of the two, the safe side. Both powers depend
    on the case alone (``xp.pow`` runs on case columns); the type picks one per actuator."""
    life, speed = q.required_life_h, q.mean_speed_rpm
    roller = bearing.life_revolutions_factor(
        required_life_h=life,
        mean_speed_rpm=speed,
        xp=xp,
        exponent_inverse=bearing.LIFE_EXPONENT_INVERSE,
    )
    ball = bearing.life_revolutions_factor(
        required_life_h=life,
        mean_speed_rpm=speed,
        xp=xp,
        exponent_inverse=bearing.BALL_LIFE_EXPONENT_INVERSE,
    )
    exponent = q.bearing_life_exponent
    by_type = xp.where(exponent == bearing.BALL_LIFE_EXPONENT, ball, roller)
    return xp.where(xp.isnan(exponent), _larger(ball, roller, xp), by_type)


def _required_rating(q: Operands, xp: Ops) -> Real:
    """C_req = f_w·P_c·(L_h·60·n_av/10⁶)^(1/B): formula (7) solved for C."""
    return q.load_factor * _dynamic_load(q, xp) * _life_factor(q, xp)


def _life_message(q: Operands, status: Status, needed: float, c: float) -> str:
    p_c = _dynamic_load(q, FLOAT_OPS)
    exponent = q.bearing_life_exponent

    def life(b: float) -> float:
        return bearing.l10_life_h(
            dynamic_load_rating_n=c,
            load_factor=q.load_factor,
            equivalent_load_n=p_c,
            mean_speed_rpm=q.mean_speed_rpm,
            exponent=b,
        )

    if math.isnan(exponent):
        life_h = min(life(bearing.BALL_LIFE_EXPONENT), life(bearing.LIFE_EXPONENT))
        kind = "unknown"
    else:
        life_h = life(exponent)
        kind = "ball" if exponent == bearing.BALL_LIFE_EXPONENT else "roller"
    return phrase(
        f"bearing_life.{_outcome(status)}",
        value=needed,
        limit=c,
        life_h=float(life_h),
        mean_speed_rpm=q.mean_speed_rpm,
        required_life_h=q.required_life_h,
        p_c_n=float(p_c),
        load_factor=q.load_factor,
        bearing=phrase(f"bearing_life.{kind}"),
    )


BEARING_LIFE = Rule(
    name="bearing_life",
    reference="CHA §4.3, Table 69.3, Table 70.4; FHA-C manual ch. 2, formulas (5)–(7); ISO 281",
    unit="N",
    value=_required_rating,
    limit=lambda q, xp: q.bearing_dynamic_load_rating_n,
    requires=(
        published("bearing_pitch_diameter_m", N_("output bearing pitch circle diameter d_p")),
        published("bearing_offset_m", N_("output bearing offset R")),
        published("bearing_dynamic_load_rating_n", N_("output bearing dynamic load rating C")),
    ),
    approximate=lambda q, xp: xp.isnan(q.bearing_life_exponent),
    message=_life_message,
)
"""L_10 at the cycle's mean speed n_av ≥ the required life, checked as the dynamic load
rating that life needs, f_w·P_c·(L_h·60·n_av/10⁶)^(1/B), against C [N]; the message
gives L_10 in hours. B is the bearing type's life exponent (ISO 281: 3 for ball, 10/3 for
roller bearings; CHA manual 1018854 12/2015, p. 69, Table 69.3): 3 for the four-point
contact ball bearings of the CHA-14A, -17A and -20A, 10/3 for the cross roller bearings.
Where the catalogue gives no type, the stricter of the two (the larger C needed), and
the check is approximate (issue 28, item 4)."""

# --- output bearing: fretting under oscillating motion (CHA manual, p. 69) ------------------


def _fretting_message(q: Operands, status: Status, needed: float, swing: float) -> str:
    if not swing > 0.0:
        return phrase("bearing_fretting.still")
    kind = "pass" if status is Status.PASS else "warn"  # it never fails (never binding)
    return phrase(f"bearing_fretting.{kind}", value=needed, limit=swing)


BEARING_FRETTING = Rule(
    name="bearing_fretting",
    reference="CHA manual 1018854 12/2015, p. 69",
    unit="°",
    value=lambda q, xp: xp.where(q.swing_deg > 0.0, bearing.FRETTING_SWING_DEG, 0.0),
    limit=lambda q, xp: q.swing_deg,
    requires=(),
    binding=lambda q, xp: q.swing_deg < 0.0,  # never: a warning, the verdict stands
    message=_fretting_message,
)
"""The cycle's swing (:func:`~actuator_selection.core.bearing.swing_deg`) of at least
:data:`~actuator_selection.core.bearing.FRETTING_SWING_DEG` = 5°, checked as 5° ≤ the
swing; a smaller swing warns (the CHA manual warns of fretting under oscillating motion
below 5°, issue 28 item 4) and never fails: the manual gives no life for it. A cycle that
does not move passes (value 0). The swing is the range of the output's angle over the
cycle, so one small move repeated in one direction warns as well: on the safe side, as
the chapter's cycle does not say whether it returns."""

BEARING_RULES: tuple[Rule, ...] = (BEARING_MOMENT, BEARING_STATIC, BEARING_FRETTING)
"""The output bearing's checks where an output load is given (``Application.output_load``);
:data:`BEARING_LIFE` joins them where a required life is given."""

RULES: tuple[Rule, ...] = (
    MAX_SPEED,
    INERTIA_RATIO,
    PEAK_TORQUE,
    DECEL_TORQUE,
    CONTINUOUS_DUTY,
    THERMAL_PEAK,
    CONTINUOUS_SPEED,
    DRIVE_VOLTAGE,
)
"""The flowchart's checks in the manufacturer's order (chapter p. 514–517), then whether
T_rms stands for the cycle's length (:data:`THERMAL_PEAK`, Fig. 520.1's model), then the
continuous speed by the same model (:data:`CONTINUOUS_SPEED`), then whether a controller
listed for the actuator (Table 521.1) delivers the voltage the axis needs
(:data:`DRIVE_VOLTAGE`): an actuator that no listed controller can drive at n_2 is not
suitable, whether or not the drive is sized (issue 28, item 1). Where the catalogue lacks
the winding's constants (K_E in V_rms, L, p) or lists no controller on a bus class the
actuator runs on, that check lacks data and the verdict is unconfirmed."""

DRIVE_RULES: tuple[Rule, ...] = (DRIVE_CURRENT,)
"""The drive's further check, where asked for (``Application.drive``): peak current
(Eq. 522.2, 522.3), with the energy braking returns. The output voltage
(:data:`DRIVE_VOLTAGE`) is in :data:`RULES`, checked for every selection."""

BRAKE_RULES: tuple[Rule, ...] = (*RULES, BRAKE_HOLDING)
"""The checks of an actuator fitted with its holding brake: the flowchart's, then the
brake's (:data:`BRAKE_HOLDING`)."""
