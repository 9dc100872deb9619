"""The selection flowchart for one actuator, and the ranking of many (chapter p. 514–517).

For each actuator the flowchart checks, in the manufacturer's order:

1. ``max_speed``: n_2 ≤ n_max (Table 515.1);
2. ``inertia_ratio``: J_L ≤ 3·J_A (Table 515.1, footnote 1: recommended for highly
   dynamic applications, so a failure there and a warning otherwise);
3. ``peak_torque``: T_1 ≤ T_max (Eq. 514.1);
4. ``decel_torque``: |T_3| ≤ T_max (Eq. 514.1);
5. ``continuous_duty``: (n_av, T_rms) inside the continuous-duty zone (Fig. 517.1).

A check never passes without data: a missing catalogue value gives ``no_data``.

Worked example (Table 516.1, FHA-25C-50-L of Table 516.3, no zone published here):

>>> app = Application(
...     pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1),
...     load=Load(torque_nm=5, inertia_kgm2=1.3))
>>> fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50,
...                max_torque_nm=151, max_speed_rpm=90, inertia_kgm2=0.86)
>>> c = evaluate(fha, app)
>>> [(k.name, k.status.value) for k in c.checks]  # doctest: +NORMALIZE_WHITESPACE
[('max_speed', 'pass'), ('inertia_ratio', 'pass'), ('peak_torque', 'pass'),
 ('decel_torque', 'pass'), ('continuous_duty', 'no_data')]
>>> c.verdict.value
'unconfirmed'
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from enum import StrEnum

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.cycle import (
    CycleTorques,
    Load,
    SpeedPattern,
    cycle_torques,
    duty_cycle_percent,
    mean_speed_rpm,
)

INERTIA_RATIO_LIMIT = 3.0
"""J_L ≤ 3·J_A, the pre-selection rule of Table 515.1."""


class Status(StrEnum):
    """Outcome of one check."""

    PASS = "pass"
    FAIL = "fail"
    WARN = "warn"
    NO_DATA = "no_data"


class Verdict(StrEnum):
    """Outcome for one actuator: suitable only when every check has data and none fails."""

    SUITABLE = "suitable"
    UNCONFIRMED = "unconfirmed"
    UNSUITABLE = "unsuitable"


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

    @property
    def margin_percent(self) -> float | None:
        """Headroom (limit − value)/limit [%]; negative when the limit is exceeded."""
        if self.value is None or self.limit is None or self.limit <= 0:
            return None
        return (self.limit - self.value) / self.limit * 100.0


@dataclass(frozen=True, slots=True, kw_only=True)
class Application:
    """The load case: speed pattern, load at the output, and how dynamic it is."""

    pattern: SpeedPattern
    load: Load
    high_dynamics: bool = True


@dataclass(frozen=True, slots=True, kw_only=True)
class Candidate:
    """The flowchart's result for one actuator."""

    actuator: Actuator
    verdict: Verdict
    torques: CycleTorques | None
    checks: tuple[Check, ...]

    @property
    def reasons(self) -> tuple[str, ...]:
        """Messages of the checks that fail, lack data or warn, in flowchart order."""
        return tuple(c.message for c in self.checks if c.status is not Status.PASS)


@dataclass(frozen=True, slots=True, kw_only=True)
class Selection:
    """The flowchart over many actuators, ranked (see :func:`rank`)."""

    mean_speed_rpm: float
    duty_cycle_percent: float
    cycle_time_s: float
    candidates: tuple[Candidate, ...]


def _fmt(x: float) -> str:
    return f"{x:.4g}"


def _no_data(name: str, unit: str, reference: str, missing: str, value: float | None) -> Check:
    return Check(
        name=name,
        status=Status.NO_DATA,
        value=value,
        limit=None,
        unit=unit,
        reference=reference,
        message=f"no data: the catalogue gives no {missing} for this actuator",
    )


def check_max_speed(actuator: Actuator, app: Application) -> Check:
    """n_2 ≤ n_max (Table 515.1)."""
    n_2 = app.pattern.speed_rpm
    ref = "Table 515.1"
    if actuator.max_speed_rpm is None:
        return _no_data("max_speed", "rpm", ref, "maximum output speed n_max", n_2)
    ok = n_2 <= actuator.max_speed_rpm
    relation = "≤" if ok else "exceeds"
    return Check(
        name="max_speed",
        status=Status.PASS if ok else Status.FAIL,
        value=n_2,
        limit=actuator.max_speed_rpm,
        unit="rpm",
        reference=ref,
        message=f"load speed n_2 = {_fmt(n_2)} rpm {relation} n_max = "
        f"{_fmt(actuator.max_speed_rpm)} rpm",
    )


def check_inertia_ratio(actuator: Actuator, app: Application) -> Check:
    """J_L ≤ 3·J_A (Table 515.1); binding for highly dynamic applications only."""
    j_l = app.load.inertia_kgm2
    ref = "Table 515.1"
    if actuator.inertia_kgm2 is None:
        return _no_data("inertia_ratio", "kgm²", ref, "moment of inertia J_A", j_l)
    limit = INERTIA_RATIO_LIMIT * actuator.inertia_kgm2
    if j_l <= limit:
        status = Status.PASS
        message = f"load inertia J_L = {_fmt(j_l)} kgm² ≤ 3·J_A = {_fmt(limit)} kgm²"
    else:
        status = Status.FAIL if app.high_dynamics else Status.WARN
        consequence = (
            "the limit is binding for a highly dynamic application"
            if app.high_dynamics
            else "recommended for highly dynamic applications only"
        )
        message = f"load inertia J_L = {_fmt(j_l)} kgm² exceeds 3·J_A = {_fmt(limit)} kgm²: " + (
            consequence
        )
    return Check(
        name="inertia_ratio",
        status=status,
        value=j_l,
        limit=limit,
        unit="kgm²",
        reference=ref,
        message=message,
    )


def _torque_check(
    name: str, label: str, value: float | None, actuator: Actuator, missing: str
) -> Check:
    ref = "Eq. 514.1"
    if value is None:
        return _no_data(name, "Nm", ref, missing, None)
    if actuator.max_torque_nm is None:
        return _no_data(name, "Nm", ref, "maximum torque T_max", value)
    ok = value <= actuator.max_torque_nm
    relation = "≤" if ok else "exceeds"
    return Check(
        name=name,
        status=Status.PASS if ok else Status.FAIL,
        value=value,
        limit=actuator.max_torque_nm,
        unit="Nm",
        reference=ref,
        message=f"{label} = {_fmt(value)} Nm {relation} T_max = {_fmt(actuator.max_torque_nm)} Nm",
    )


def check_peak_torque(actuator: Actuator, torques: CycleTorques | None) -> Check:
    """T_1 ≤ T_max (Eq. 514.1)."""
    value = torques.accel_torque_nm if torques else None
    return _torque_check(
        "peak_torque", "acceleration torque T_1", value, actuator, "moment of inertia J_A"
    )


def check_decel_torque(actuator: Actuator, torques: CycleTorques | None) -> Check:
    """|T_3| ≤ T_max (Eq. 514.1): braking loads the gear as much as accelerating."""
    value = abs(torques.decel_torque_nm) if torques else None
    return _torque_check(
        "decel_torque", "deceleration torque |T_3|", value, actuator, "moment of inertia J_A"
    )


def check_continuous_duty(actuator: Actuator, torques: CycleTorques | None, n_av: float) -> Check:
    """(n_av, T_rms) inside the continuous-duty zone (Fig. 517.1; Eq. 514.2, 514.3).

    With a published zone the torque limit is the zone's edge at n_av. Without
    one, the continuous stall torque T_0 (or the catalogue's allowable continuous
    torque) and n_max bound a rectangle that is reported as approximate: the
    real edge falls with speed, so the rectangle may be optimistic at high n_av.
    """
    ref = "Fig. 517.1"
    name = "continuous_duty"
    if torques is None:
        return _no_data(name, "Nm", ref, "moment of inertia J_A (T_rms needs it)", None)
    t_rms = torques.rms_torque_nm
    point = f"(n_av = {_fmt(n_av)} rpm, T_rms = {_fmt(t_rms)} Nm)"
    if actuator.zone is not None:
        limit = actuator.zone.torque_limit_nm(n_av)
        if limit is None:
            return Check(
                name=name,
                status=Status.FAIL,
                value=t_rms,
                limit=None,
                unit="Nm",
                reference=ref,
                message=f"operating point {point} lies beyond the continuous-duty zone, "
                f"which ends at {_fmt(actuator.zone.max_speed_rpm)} rpm",
            )
        ok = t_rms <= limit
        return Check(
            name=name,
            status=Status.PASS if ok else Status.FAIL,
            value=t_rms,
            limit=limit,
            unit="Nm",
            reference=ref,
            message=f"operating point {point} lies {'inside' if ok else 'above'} the "
            f"continuous-duty zone (limit {_fmt(limit)} Nm at n_av)",
        )
    if actuator.stall_torque_nm is not None:
        limit, what = actuator.stall_torque_nm, "continuous stall torque T_0"
    elif actuator.continuous_torque_nm is not None:
        limit, what = actuator.continuous_torque_nm, "allowable continuous torque"
    else:
        return _no_data(name, "Nm", ref, "continuous-duty zone or continuous torque", t_rms)
    if actuator.max_speed_rpm is None:
        return _no_data(name, "Nm", ref, "maximum output speed n_max", t_rms)
    ok = t_rms <= limit and n_av <= actuator.max_speed_rpm
    return Check(
        name=name,
        status=Status.PASS if ok else Status.FAIL,
        value=t_rms,
        limit=limit,
        unit="Nm",
        reference=ref,
        approximate=True,
        message=f"approximate: operating point {point} {'within' if ok else 'outside'} "
        f"{what} = {_fmt(limit)} Nm and n_max = {_fmt(actuator.max_speed_rpm)} rpm "
        "(no continuous-duty zone published)",
    )


def _verdict(checks: Iterable[Check]) -> Verdict:
    statuses = {c.status for c in checks}
    if Status.FAIL in statuses:
        return Verdict.UNSUITABLE
    if Status.NO_DATA in statuses:
        return Verdict.UNCONFIRMED
    return Verdict.SUITABLE


def evaluate(actuator: Actuator, app: Application) -> Candidate:
    """Run the flowchart's checks for one actuator."""
    torques = (
        cycle_torques(
            pattern=app.pattern, load=app.load, actuator_inertia_kgm2=actuator.inertia_kgm2
        )
        if actuator.inertia_kgm2 is not None
        else None
    )
    checks = (
        check_max_speed(actuator, app),
        check_inertia_ratio(actuator, app),
        check_peak_torque(actuator, torques),
        check_decel_torque(actuator, torques),
        check_continuous_duty(actuator, torques, mean_speed_rpm(app.pattern)),
    )
    return Candidate(actuator=actuator, verdict=_verdict(checks), torques=torques, checks=checks)


_VERDICT_ORDER = {Verdict.SUITABLE: 0, Verdict.UNCONFIRMED: 1, Verdict.UNSUITABLE: 2}


def ranking_key(candidate: Candidate) -> tuple[int, float, float, str]:
    """Sort key: verdict (suitable, unconfirmed, unsuitable), then the smallest actuator.

    "Smallest" is the lowest peak torque T_max, then the lowest inertia J_A: the
    least actuator that does the job comes first. Unknown values sort last, and
    the model name breaks ties so that the order is total and repeatable.
    """
    a = candidate.actuator
    inf = float("inf")
    return (
        _VERDICT_ORDER[candidate.verdict],
        a.max_torque_nm if a.max_torque_nm is not None else inf,
        a.inertia_kgm2 if a.inertia_kgm2 is not None else inf,
        a.model,
    )


def select(actuators: Iterable[Actuator], app: Application) -> Selection:
    """Run the flowchart for every actuator and rank the candidates (:func:`ranking_key`)."""
    candidates = sorted((evaluate(a, app) for a in actuators), key=ranking_key)
    return Selection(
        mean_speed_rpm=mean_speed_rpm(app.pattern),
        duty_cycle_percent=duty_cycle_percent(app.pattern),
        cycle_time_s=app.pattern.cycle_s,
        candidates=tuple(candidates),
    )
