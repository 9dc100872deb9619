"""The strain wave gear's own limits (issue 28, item 7), where asked for
(``Application.gear``; docs/decisions/0024-gear-checks-when-asked.md).

The conventions and equations are Harmonic Drive AG's component catalogues' (*CSD-2A
Component Sets Engineering Data*, 1019659 11/2014, §4.1.1 Torque Based Dimensioning,
p. 18; L_n in Table 20.1):

- average output torque T_av = (Σ|n_i|·t_i·|T_i|³ / Σ|n_i|·t_i)^(1/3), each piece of the
  cycle weighted by its mean |n| times its time (a held pause weighs zero, a ramp counts
  at n/2), |T_i| the larger magnitude at the piece's ends (exact for the chapter's
  trapezoid, on the safe side for an S-curve): ≤ the limit for average torque T_A;
- the cycle's peak torque max(|T_1|, |T_3|) ≤ the limit for repeated peak torque T_R;
- a momentary peak (collision, emergency stop) ≤ T_M, and its count ≤ the allowed N_M;
- average input speed n_in,av = i·n_av (n_av of Eq. 514.3, the pause included) ≤ the
  allowable average input speed;
- wave generator life L = L_n·(T_N/T_av)³·(n_N/n_in,av), n_N = 2000 rpm, ≥ the required
  life; L is of the basis of L_n (L_50 in the component catalogues; L_10 ≈ L_50/5).

The ratings are catalogue fields that an administrator imports with their source; none is
published for the starter catalogue's actuators, so there these checks say no data.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Final

from actuator_selection.phrases.check_messages import check_words, phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.checks.operands import Operands, Real
from actuator_selection.sizing.checks.rule import (
    FLOAT_OPS,
    Ops,
    Rule,
    Status,
    larger,
    outcome,
    published,
)

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

RATED_INPUT_SPEED_RPM: Final = 2000.0
"""n_N: the input speed at which T_N and L_n are rated (CSD-2A 1019659 11/2014, p. 18)."""

LIFE_BASES: Final = {"L10": 10.0, "L50": 50.0}
"""The catalogue's text of the L_n basis → the operand (percent of units failed)."""

WORDS: Final = {
    "gear_average_torque.pass": N_(
        "average output torque T_av = {value:.4g} Nm ≤ the gear's limit for average torque "
        "T_A = {limit:.4g} Nm"
    ),
    "gear_average_torque.fail": N_(
        "average output torque T_av = {value:.4g} Nm exceeds the gear's limit for average "
        "torque T_A = {limit:.4g} Nm"
    ),
    "gear_repeated_peak.pass": N_(
        "peak torque of the cycle {value:.4g} Nm ≤ the gear's limit for repeated peak torque "
        "T_R = {limit:.4g} Nm"
    ),
    "gear_repeated_peak.fail": N_(
        "peak torque of the cycle {value:.4g} Nm exceeds the gear's limit for repeated peak "
        "torque T_R = {limit:.4g} Nm"
    ),
    "gear_momentary_peak.pass": N_(
        "momentary peak torque {value:.4g} Nm ≤ T_M = {limit:.4g} Nm, {count:.4g} times ≤ "
        "the {allowed:.4g} allowed"
    ),
    "gear_momentary_peak.fail": N_(
        "momentary peak torque {value:.4g} Nm against T_M = {limit:.4g} Nm, {count:.4g} "
        "times against the {allowed:.4g} allowed: exceeded"
    ),
    "gear_input_speed.pass": N_(
        "average input speed n_in,av = i·n_av = {value:.4g} rpm ≤ the gear's allowable "
        "average input speed {limit:.4g} rpm"
    ),
    "gear_input_speed.fail": N_(
        "average input speed n_in,av = i·n_av = {value:.4g} rpm exceeds the gear's "
        "allowable average input speed {limit:.4g} rpm"
    ),
    "gear_life.pass": N_(
        "wave generator life L_{basis:.0f} = {life:.4g} h ≥ the required {required:.4g} h "
        "(the required life needs L_n ≥ {value:.4g} h, the gear has {limit:.4g} h)"
    ),
    "gear_life.fail": N_(
        "wave generator life L_{basis:.0f} = {life:.4g} h is short of the required "
        "{required:.4g} h (the required life needs L_n ≥ {value:.4g} h, the gear has "
        "{limit:.4g} h)"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)

_INERTIA = published("inertia_kgm2", N_("moment of inertia J_A"))
"""The cycle's torques need J_A."""


def life_basis(text: str | None) -> float | None:
    """The operand of the catalogue's L_n basis (``"L10"`` → 10, ``"L50"`` → 50)."""
    return None if text is None else LIFE_BASES[text]


def average_torque_nm(q: Operands, xp: Ops) -> Real:
    """T_av = (Σ|n_i|·t_i·|T_i|³ / Σ|n_i|·t_i)^(1/3) [Nm] (CSD-2A, p. 18)."""
    return xp.pow(q.gear_torque_cube_nm3, 1.0 / 3.0)


def input_speed_rpm(q: Operands, xp: Ops) -> Real:
    """n_in,av = i·n_av [rpm], the pause included (CSD-2A, p. 18)."""
    return q.gear_ratio * q.mean_speed_rpm


def needed_rated_life_h(q: Operands, xp: Ops) -> Real:
    """The L_n that gives the required life L at this cycle: L = L_n·(T_N/T_av)³·(n_N/n_in,av)
    solved for L_n, L_req·(T_av³/T_N³)·(n_in,av/n_N) [h] (no division by a T_av or a speed
    that may be 0: a cycle that does not move needs none)."""
    t_n = q.gear_rated_torque_nm
    return (
        q.gear_required_life_h
        * (q.gear_torque_cube_nm3 / (t_n * t_n * t_n))
        * (input_speed_rpm(q, xp) / RATED_INPUT_SPEED_RPM)
    )


def life_h(q: Operands) -> float:
    """L = L_n·(T_N/T_av)³·(n_N/n_in,av) [h] for one cell (floats); inf where the cycle
    loads or turns the gear not at all."""
    load = q.gear_torque_cube_nm3 * input_speed_rpm(q, FLOAT_OPS)
    if not load > 0:
        return math.inf
    t_n = q.gear_rated_torque_nm
    return float(q.gear_rated_life_h * t_n * t_n * t_n * RATED_INPUT_SPEED_RPM / load)


def _simple(name: str):  # type: ignore[no-untyped-def]
    def message(q: Operands, status: Status, value: float, limit: float) -> str:
        return phrase(f"{name}.{outcome(status)}", value=value, limit=limit)

    return message


def gear_asked(app: Application) -> bool:
    """Whether the gear's own limits are checked (docs/decisions/0024)."""
    return app.gear


def momentary_asked(app: Application) -> bool:
    """Whether a momentary peak is checked against the gear's T_M."""
    return app.gear and app.momentary_torque_nm is not None


def gear_life_asked(app: Application) -> bool:
    """Whether the wave generator's life is checked."""
    return app.gear and app.gear_required_life_h is not None


GEAR_AVERAGE_TORQUE = Rule(
    name="gear_average_torque",
    when=gear_asked,
    reference="CSD-2A 1019659 11/2014 §4.1.1, p. 18",
    unit="Nm",
    value=average_torque_nm,
    limit=lambda q, xp: q.gear_average_torque_limit_nm,
    requires=(
        published("gear_average_torque_limit_nm", N_("limit for average torque of the gear")),
        _INERTIA,
    ),
    message=_simple("gear_average_torque"),
)
"""T_av ≤ T_A."""

GEAR_REPEATED_PEAK = Rule(
    name="gear_repeated_peak",
    when=gear_asked,
    reference="CSD-2A 1019659 11/2014 §4.1.1, p. 18",
    unit="Nm",
    value=lambda q, xp: larger(abs(q.accel_torque_nm), abs(q.decel_torque_nm), xp),
    limit=lambda q, xp: q.gear_repeated_peak_torque_nm,
    requires=(
        published("gear_repeated_peak_torque_nm", N_("limit for repeated peak torque of the gear")),
        _INERTIA,
    ),
    message=_simple("gear_repeated_peak"),
)
"""max(|T_1|, |T_3|) ≤ T_R."""


def _momentary_message(q: Operands, status: Status, value: float, limit: float) -> str:
    return phrase(
        f"gear_momentary_peak.{outcome(status)}",
        value=value,
        limit=limit,
        count=q.momentary_count,
        allowed=q.gear_momentary_peak_count,
    )


GEAR_INPUT_SPEED = Rule(
    name="gear_input_speed",
    when=gear_asked,
    reference="CSD-2A 1019659 11/2014 §4.1.1, p. 18",
    unit="rpm",
    value=input_speed_rpm,
    limit=lambda q, xp: q.gear_average_input_speed_limit_rpm,
    requires=(
        published(
            "gear_average_input_speed_limit_rpm", N_("allowable average input speed of the gear")
        ),
    ),
    message=_simple("gear_input_speed"),
)
"""i·n_av ≤ the allowable average input speed."""


GEAR_MOMENTARY_PEAK = Rule(
    name="gear_momentary_peak",
    when=momentary_asked,
    reference="CSD-2A 1019659 11/2014 §4.1.1, p. 18",
    unit="Nm",
    value=lambda q, xp: q.momentary_torque_nm,
    limit=lambda q, xp: q.gear_momentary_peak_torque_nm,
    within=lambda q, xp: q.momentary_count <= q.gear_momentary_peak_count,
    requires=(
        published(
            "gear_momentary_peak_torque_nm", N_("limit for momentary peak torque of the gear")
        ),
        published(
            "gear_momentary_peak_count", N_("allowable number of momentary peaks of the gear")
        ),
    ),
    message=_momentary_message,
)
"""The momentary peak the application names ≤ T_M, as often as N_M allows at most."""


def _life_message(q: Operands, status: Status, value: float, limit: float) -> str:
    return phrase(
        f"gear_life.{outcome(status)}",
        value=value,
        limit=limit,
        life=life_h(q),
        required=q.gear_required_life_h,
        basis=q.gear_life_basis,
    )


GEAR_LIFE = Rule(
    name="gear_life",
    when=gear_life_asked,
    reference="CSD-2A 1019659 11/2014 §4.1.1, p. 18; Table 20.1",
    unit="h",
    value=needed_rated_life_h,
    limit=lambda q, xp: q.gear_rated_life_h,
    requires=(
        published("gear_rated_life_h", N_("nominal life L_n of the wave generator")),
        published("gear_rated_torque_nm", N_("rated torque T_N of the gear")),
        published("gear_life_basis", N_("basis of the gear's nominal life (L_10 or L_50)")),
        _INERTIA,
    ),
    message=_life_message,
)
"""L = L_n·(T_N/T_av)³·(n_N/n_in,av) ≥ L_req, checked as the L_n the required life needs
≤ the gear's L_n [h]; L is of L_n's basis (L_10 or L_50), which the message names."""

AVERAGE_TORQUE_RULES: Final = frozenset({"gear_average_torque", "gear_life"})
"""The checks that read T_av: the engine sums Σ|n_i|·t_i·|T_i|³ only for a rule set with one."""
