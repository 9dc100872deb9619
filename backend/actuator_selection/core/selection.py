"""The selection flowchart for one actuator, and the ranking of many (chapter p. 514–517).

For each actuator the flowchart runs the checks of :data:`~actuator_selection.core.checks.RULES`,
in the manufacturer's order:

1. ``max_speed``: n_2 ≤ n_max (Table 515.1);
2. ``inertia_ratio``: J_L ≤ 3·J_A (Table 515.1, footnote 1: recommended for highly
   dynamic applications, so a failure there and a warning otherwise);
3. ``peak_torque``: T_1 ≤ T_max (Eq. 514.1);
4. ``decel_torque``: |T_3| ≤ T_max (Eq. 514.1);
5. ``continuous_duty``: T_rms against the continuous torque at n_av: the zone's edge
   (Fig. 517.1), else the current-based edge (Eq. 522.2, 522.3) or T_0;
6. ``thermal_peak``: whether T_rms stands for the cycle's length: the peak of the
   winding's heating over the repeating cycle against the same limit (the first-order
   thermal model of Fig. 520.1);
7. ``continuous_speed``: the speed the winding's heating follows (n_av for a short
   cycle, a long segment's own speed) against the continuous or rated speed;
8. ``drive_voltage``: whether a controller listed for the actuator (Table 521.1)
   delivers the voltage the axis needs at n_2 (Eq. 521.2 with the inductive drop).

A check never passes without data: a missing catalogue value gives ``no_data``. The
rules live in :mod:`actuator_selection.core.checks`, one table that the vectorised
flowchart (:mod:`actuator_selection.core.batch`) reads as well.

Worked example (Table 516.1, FHA-25C-50-L of Table 516.3, no zone published here):

>>> app = Application(
...     pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1),
...     load=Load(torque_nm=5, inertia_kgm2=1.3))
>>> fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50,
...                max_torque_nm=151, max_speed_rpm=90, inertia_kgm2=0.86)
>>> c = evaluate(fha, app)
>>> [(k.name, k.status.value) for k in c.checks]  # doctest: +NORMALIZE_WHITESPACE
[('max_speed', 'pass'), ('inertia_ratio', 'pass'), ('peak_torque', 'pass'),
 ('decel_torque', 'pass'), ('continuous_duty', 'no_data'), ('thermal_peak', 'no_data'),
 ('continuous_speed', 'no_data'), ('drive_voltage', 'no_data')]
>>> c.verdict.value
'unconfirmed'
>>> c.checks[2].message
'acceleration torque T_1 = 95.48 Nm ≤ T_max = 151 Nm'
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from functools import lru_cache
from typing import Any

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.axis import AxisLoad
from actuator_selection.core.bearing import OutputLoad, life_exponent, swing_deg
from actuator_selection.core.checks import (
    BEARING_LIFE,
    BEARING_RULES,
    BRAKE_RULES,
    DRIVE_RULES,
    INERTIA_RATIO_LIMIT,
    RULES,
    Check,
    DeferredChecks,
    Operands,
    Rule,
    Status,
)
from actuator_selection.core.cycle import Load, SpeedPattern
from actuator_selection.core.deferred import defer_field
from actuator_selection.core.electrical import no_load_torque_slope_nm_per_rpm
from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.motion import CycleTorques, Motion, Profile, profile_of, trapezoid
from actuator_selection.core.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S

__all__ = [
    "INERTIA_RATIO_LIMIT",
    "VALUE_OF",
    "Application",
    "Candidate",
    "Check",
    "Selection",
    "Status",
    "Verdict",
    "evaluate",
    "evaluate_each",
    "operands",
    "ranking_key",
    "select",
]
"""Check, Status and INERTIA_RATIO_LIMIT live in :mod:`~actuator_selection.core.checks`
and stay importable from here."""


class Verdict(StrEnum):
    """Outcome for one actuator: suitable only when every check has data and none fails."""

    SUITABLE = "suitable"
    UNCONFIRMED = "unconfirmed"
    UNSUITABLE = "unsuitable"


VALUE_OF: dict[Status | Verdict, str] = {e: e.value for e in (*Status, *Verdict)}
"""Each status's and verdict's value, for answers written as plain data: a dict lookup
is several times cheaper than an enum's ``.value``."""


def require_time_constant(tau: float | None) -> None:
    """Refuse a thermal time constant τ_th (:attr:`Application.thermal_time_constant_s`)
    that is not a finite number > 0."""
    if tau is not None and not (math.isfinite(tau) and tau > 0):
        raise InvalidInputError(
            "thermal_time_constant_s",
            f"must be a finite number > 0: τ_th divides the time in the thermal model, got {tau!r}",
        )


@dataclass(frozen=True, slots=True, kw_only=True)
class Application:
    """The load case: the motion (a cycle of segments driving an axis load, or the
    chapter's trapezoid ``pattern`` with its ``load`` as a shorthand), and how dynamic it is.

    Give either ``motion`` or both ``pattern`` and ``load``; :attr:`cycle` is the motion
    either way (:func:`~actuator_selection.core.motion.trapezoid` for the shorthand).
    """

    pattern: SpeedPattern | None = None
    load: Load | None = None
    motion: Motion | None = None
    high_dynamics: bool = True
    brake: bool = False
    """Whether the actuator is fitted with its holding brake (checked by
    :data:`~actuator_selection.core.checks.BRAKE_HOLDING`)."""
    _profile: list[Profile] = field(
        default_factory=list, init=False, repr=False, compare=False, hash=False
    )
    """The cycle's :class:`~actuator_selection.core.motion.Profile`, once computed."""

    def __post_init__(self) -> None:
        if self.motion is None and (self.pattern is None or self.load is None):
            raise InvalidInputError("cycle", "needs a motion, or a speed pattern and a load")
        if self.motion is not None and (self.pattern is not None or self.load is not None):
            raise InvalidInputError(
                "cycle", "give segments or the t_1…t_p pattern with its load, not both"
            )
        require_time_constant(self.thermal_time_constant_s)

    @property
    def cycle(self) -> Motion:
        """The motion: :attr:`motion`, or the chapter's trapezoid of the shorthand."""
        if self.motion is not None:
            return self.motion
        assert self.pattern is not None
        p = self.pattern
        return trapezoid(
            speed_rpm=p.speed_rpm,
            accel_s=p.accel_s,
            constant_s=p.constant_s,
            decel_s=p.decel_s,
            pause_s=p.pause_s,
            load=self.axis_load,
        )

    @property
    def axis_load(self) -> AxisLoad:
        """The motion's axis load, without building the motion: for the shorthand, the
        load's T_L as friction (acting against the motion) and its J_L."""
        if self.motion is not None:
            return self.motion.load
        assert self.load is not None
        return AxisLoad(inertia_kgm2=self.load.inertia_kgm2, friction_torque_nm=self.load.torque_nm)

    @property
    def profile(self) -> Profile:
        """The cycle prepared for the flowchart (computed once)."""
        if not self._profile:
            self._profile.append(profile_of(self.cycle))
        return self._profile[0]

    @property
    def known_profile(self) -> Profile | None:
        """:attr:`profile` if it has been computed, else None (nothing is computed)."""
        return self._profile[0] if self._profile else None

    drive: bool = False
    """Whether the drive's current is sized too
    (:data:`~actuator_selection.core.checks.DRIVE_RULES`); the output voltage is checked
    either way (:data:`~actuator_selection.core.checks.DRIVE_VOLTAGE`)."""
    output_load: OutputLoad | None = None
    """An external load on the output flange, or None: the output bearing is not checked
    (:data:`~actuator_selection.core.checks.BEARING_RULES`)."""
    thermal_time_constant_s: float | None = None
    """The winding's thermal time constant τ_th [s] for the heating check
    (:data:`~actuator_selection.core.checks.THERMAL_PEAK`) where the catalogue gives
    none; None: :data:`~actuator_selection.core.thermal.DEFAULT_THERMAL_TIME_CONSTANT_S`,
    an assumption (the check then says approximate)."""

    @property
    def rules(self) -> tuple[Rule, ...]:
        """The checks this application needs: the flowchart's, the brake's if fitted, the
        output bearing's if an output load is given (its life if a life is required)."""
        load = self.output_load
        return _rule_set(
            self.brake,
            self.drive,
            load is not None,
            load is not None and load.required_life_h is not None,
        )


@lru_cache(maxsize=16)
def _rule_set(brake: bool, drive: bool, bearing: bool, life: bool) -> tuple[Rule, ...]:
    """One tuple per combination, so that cases group by their rules cheaply."""
    rules = BRAKE_RULES if brake else RULES
    if drive:
        rules = (*rules, *DRIVE_RULES)
    if bearing:
        rules = (*rules, *BEARING_RULES)
    if life:
        rules = (*rules, BEARING_LIFE)
    return rules


@dataclass(frozen=True, slots=True, kw_only=True)
class Candidate:
    """The flowchart's result for one actuator."""

    actuator: Actuator
    verdict: Verdict
    torques: CycleTorques | None
    checks: tuple[Check, ...]

    @property
    def reasons(self) -> tuple[str, ...]:
        """Messages of the checks that fail, lack data or warn, in flowchart order, each
        once (``continuous_duty`` and ``thermal_peak`` lack the same catalogue value)."""
        held = _CHECKS.__get__(self, Candidate)
        if isinstance(held, DeferredChecks):  # a batch's candidate, checks unread: these alone
            return tuple(dict.fromkeys(held.reasons()))
        return tuple(dict.fromkeys(c.message for c in self.checks if c.status is not Status.PASS))

    @property
    def worst_overload(self) -> float:
        """The largest :attr:`~actuator_selection.core.checks.Check.overload` of its
        checks: 0 unless a check failed, else how far the worst one is over its limit."""
        return max((c.overload for c in self.checks), default=0.0)


_CHECKS: Any = defer_field(Candidate, "checks")
"""A candidate's checks may be :class:`~actuator_selection.core.checks.DeferredChecks`
(the vectorised flowchart's), built when first read."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Selection:
    """The flowchart over many actuators, ranked (see :func:`rank`)."""

    mean_speed_rpm: float
    duty_cycle_percent: float
    cycle_time_s: float
    candidates: tuple[Candidate, ...]
    profile: Profile
    """The cycle as the flowchart saw it (peak speed, load, pieces)."""


def _verdict(checks: Iterable[Check]) -> Verdict:
    statuses = {c.status for c in checks}
    if Status.FAIL in statuses:
        return Verdict.UNSUITABLE
    if Status.NO_DATA in statuses:
        return Verdict.UNCONFIRMED
    return Verdict.SUITABLE


def operands(
    actuator: Actuator,
    app: Application,
    torques: CycleTorques | None,
    profile: Profile,
    heating: dict[float, Heating] | None = None,
) -> Operands:
    """The floats the rules compute from, NaN for what the catalogue does not publish.

    Parameters
    ----------
    actuator
        The catalogue entry.
    app
        The load case.
    torques
        T_1, T_2, T_3, T_rms (Eq. 514.1, 514.2) [Nm]; None without J_A.
    profile
        The cycle's figures: n_av (Eq. 514.3), peak speed, the least T_1, |T_3|, T_rms
        over every J_A ≥ 0, the torque held at standstill.
    heating
        The cycle's heating per τ_th (:data:`Heating`), filled as computed: pass the same
        dict for every actuator of one case.
    """
    nan = math.nan
    zone = actuator.zone
    n_av = profile.mean_speed_rpm
    zone_torque = None if zone is None else zone.torque_limit_nm(n_av)
    # Positional, in the order of the fields (a test checks each): a third of the time
    # that keywords take, for every actuator of every case.
    return Operands(
        profile.peak_speed_rpm,
        profile.load.inertia_kgm2,
        app.high_dynamics,
        n_av,
        nan if torques is None else torques.accel_torque_nm,
        nan if torques is None else torques.decel_torque_nm,
        nan if torques is None else torques.rms_torque_nm,
        nan if actuator.max_torque_nm is None else actuator.max_torque_nm,
        nan if actuator.max_speed_rpm is None else actuator.max_speed_rpm,
        nan if actuator.inertia_kgm2 is None else actuator.inertia_kgm2,
        nan if actuator.stall_torque_nm is None else actuator.stall_torque_nm,
        nan if actuator.continuous_torque_nm is None else actuator.continuous_torque_nm,
        zone is not None,
        nan if zone_torque is None else zone_torque,
        nan if zone is None else zone.max_speed_rpm,
        profile.accel_floor_nm,
        profile.decel_floor_nm,
        profile.rms_floor_nm,
        nan if actuator.continuous_speed_rpm is None else actuator.continuous_speed_rpm,
        nan if actuator.rated_speed_rpm is None else actuator.rated_speed_rpm,
        profile.holding_torque_nm,
        nan if actuator.brake_holding_torque_nm is None else actuator.brake_holding_torque_nm,
        *_drive_and_bearing(actuator, app, profile),
        *_thermal(actuator, app, torques, profile, {} if heating is None else heating),
    )


Heating = tuple[tuple[tuple[float, ...], float], float]
"""A cycle's heating gains (:meth:`~actuator_selection.core.motion.Profile.heating_gains`)
and its n_th (:meth:`~actuator_selection.core.motion.Profile.thermal_speed_rpm`) for one
τ_th: the same for every actuator without a published τ_th, so computed once per τ_th."""


def _thermal(
    actuator: Actuator,
    app: Application,
    torques: CycleTorques | None,
    profile: Profile,
    heating: dict[float, Heating],
) -> tuple[float, ...]:
    """The operands after the output bearing's: t_0, τ_th (the catalogue's, else the
    application's, else the assumed default), whether τ_th is that assumption, the peak
    of the cycle's heating as a torque (NaN without J_A) and as a speed, and k_T·K_INL."""
    tau = actuator.thermal_time_constant_s
    assumed = False
    if tau is None:
        tau = app.thermal_time_constant_s
        if tau is None:
            tau, assumed = DEFAULT_THERMAL_TIME_CONSTANT_S, True
    known = heating.get(tau)
    if known is None:
        gains = profile.heating_gains(tau)
        known = heating[tau] = (gains, profile.thermal_speed_rpm(*gains))
    gains, speed = known
    slope = no_load_torque_slope_nm_per_rpm(
        torque_constant_nm_per_a=actuator.torque_constant_nm_per_a,
        constant_30c_a_per_rpm=actuator.no_load_current_constant_30c_a_per_rpm,
        constant_80c_a_per_rpm=actuator.no_load_current_constant_80c_a_per_rpm,
    )
    if torques is None or actuator.inertia_kgm2 is None:
        peak = math.nan
    else:
        # On the winding current where the current-based edge stands (no zone, T_0).
        on_current = actuator.zone is None and actuator.stall_torque_nm is not None
        peak = profile.thermal_torque_nm(
            actuator.inertia_kgm2, *gains, slope if on_current else None
        )
    return (
        profile.cycle_s,
        tau,
        assumed,
        peak,
        speed,
        _value(slope),
    )


def _where(condition: bool, if_true: float, if_false: float) -> float:
    return if_true if condition else if_false


def _value(value: float | None) -> float:
    return math.nan if value is None else value


def _drive_and_bearing(actuator: Actuator, app: Application, profile: Profile) -> tuple[float, ...]:
    """The operands after ``brake_holding_torque_nm``: the drive's and the output bearing's
    catalogue values and the output load, in the order of :class:`Operands`."""
    a, nan = actuator, math.nan
    k_inl = a.no_load_current_constant_30c_a_per_rpm
    inductance = a.inductance_line_mh
    load = app.output_load
    if load is None:
        forces: tuple[float, ...] = (nan,) * 8
    else:
        forces = (
            load.radial_force_n,
            load.axial_force_n,
            load.radial_lever_m,
            load.axial_lever_m,
            load.load_factor,
            load.static_safety_min,
            _value(load.required_life_h),
            swing_deg(
                (
                    (p.duration_s, p.start_rpm, p.end_rpm, p.accel_start, p.accel_end)
                    for p in profile.pieces
                ),
                _where,
            ),
        )
    return (
        profile.braking_s,
        a.gear_ratio,
        _value(a.torque_constant_nm_per_a),
        _value(a.max_current_a),
        _value(a.no_load_starting_current_a),
        _value(k_inl),
        _value(a.motor_voltage_constant_v_per_krpm),
        _value(a.resistance_line_ohm),
        nan if inductance is None else inductance / 1000.0,
        _value(a.pole_pairs),
        _value(a.dc_bus_voltage_v),
        *forces,
        _value(a.output_bearing_pitch_diameter_m),
        _value(a.output_bearing_offset_m),
        _value(a.output_bearing_dynamic_load_rating_n),
        _value(a.output_bearing_static_load_rating_n),
        life_exponent(a.output_bearing_type),
        _value(a.output_bearing_moment_load_nm),
        _value(a.output_bearing_dynamic_tilting_moment_nm),
    )


def evaluate(
    actuator: Actuator, app: Application, *, rules: Sequence[Rule] | None = None
) -> Candidate:
    """Run the flowchart's checks (``rules``, by default :attr:`Application.rules`: the
    chapter's, and the brake's where fitted) for one actuator."""
    (candidate,) = evaluate_each((actuator,), app, rules=rules)
    return candidate


def evaluate_each(
    actuators: Iterable[Actuator],
    app: Application,
    *,
    rules: Sequence[Rule] | None = None,
) -> list[Candidate]:
    """:func:`evaluate` for each of ``actuators`` in turn, the cycle prepared once."""
    if rules is None:
        rules = app.rules
    profile = app.profile
    heating: dict[float, Heating] = {}  # per τ_th, for every actuator
    candidates = []
    for actuator in actuators:
        torques = (
            profile.torques(actuator.inertia_kgm2) if actuator.inertia_kgm2 is not None else None
        )
        q = operands(actuator, app, torques, profile, heating)
        checks = tuple([rule.check(q) for rule in rules])
        candidates.append(
            Candidate(actuator=actuator, verdict=_verdict(checks), torques=torques, checks=checks)
        )
    return candidates


_VERDICT_ORDER = {Verdict.SUITABLE: 0, Verdict.UNCONFIRMED: 1, Verdict.UNSUITABLE: 2}


def ranking_key(candidate: Candidate) -> tuple[int, float, float, float, str]:
    """Sort key: verdict (suitable, unconfirmed, unsuitable), then, among the unsuitable,
    the nearest miss (the smallest :attr:`Candidate.worst_overload`), then the smallest
    actuator (:func:`size_key`). When nothing fits, the actuator that misses least comes
    first, not the smallest one, which misses most."""
    return (
        _VERDICT_ORDER[candidate.verdict],
        candidate.worst_overload,
        *size_key(candidate.actuator),
    )


def size_key(a: Actuator) -> tuple[float, float, str]:
    """The smallest actuator first: the lowest peak torque T_max, then the lowest inertia
    J_A, so that the least actuator that does the job comes first. Unknown values sort
    last, and the model name breaks ties so that the order is total and repeatable."""
    inf = float("inf")
    return (
        a.max_torque_nm if a.max_torque_nm is not None else inf,
        a.inertia_kgm2 if a.inertia_kgm2 is not None else inf,
        a.model,
    )


def select(
    actuators: Iterable[Actuator], app: Application, *, rules: Sequence[Rule] | None = None
) -> Selection:
    """Run the flowchart for every actuator and rank the candidates (:func:`ranking_key`)."""
    candidates = sorted(evaluate_each(actuators, app, rules=rules), key=ranking_key)
    profile = app.profile
    return Selection(
        mean_speed_rpm=profile.mean_speed_rpm,
        duty_cycle_percent=profile.duty_cycle_percent,
        cycle_time_s=profile.cycle_s,
        candidates=tuple(candidates),
        profile=profile,
    )
