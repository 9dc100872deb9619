"""The holding brake's checks (catalogue brake data), for an actuator fitted with one:
its holding torque against the static load with a safety factor, and, where the
application names how many emergency stops it expects, their count against the brake's
allowable number with how far the load drops while the brake closes (issue 28, item 9)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Final

from actuator_selection.phrases.check_messages import Phrase, check_words, phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.checks.rule import Operands, Rule, Status, outcome, published
from actuator_selection.sizing.loads import STANDARD_GRAVITY_M_PER_S2

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

WORDS: Final = {
    # brake_holding
    "brake_holding.pass": N_(
        "load torque at standstill T_L = {value:.4g} Nm ≤ the brake's holding torque = "
        "{limit:.4g} Nm (safety factor S = 1: no published document we read names a default "
        "for a holding brake; set brake_safety_factor from your own risk assessment)"
    ),
    "brake_holding.fail": N_(
        "load torque at standstill T_L = {value:.4g} Nm exceeds the brake's holding torque = "
        "{limit:.4g} Nm (safety factor S = 1: no published document we read names a default "
        "for a holding brake; set brake_safety_factor from your own risk assessment)"
    ),
    "brake_holding.pass_factor": N_(
        "S·T_L = {factor:.3g} × {torque:.4g} Nm = {value:.4g} Nm ≤ the brake's holding torque "
        "= {limit:.4g} Nm"
    ),
    "brake_holding.fail_factor": N_(
        "S·T_L = {factor:.3g} × {torque:.4g} Nm = {value:.4g} Nm exceeds the brake's holding "
        "torque = {limit:.4g} Nm"
    ),
    # brake_emergency_stops
    "brake_emergency_stops.pass": N_(
        "{value:.4g} emergency stops expected ≤ the {limit:.4g} the brake allows; {drop}"
    ),
    "brake_emergency_stops.fail": N_(
        "{value:.4g} emergency stops expected exceed the {limit:.4g} the brake allows; {drop}"
    ),
    "brake_drop": N_(
        "while the brake closes ({closing:.3g} ms) a load that falls turns the output by "
        "up to {angle:.3g}°"
    ),
    "brake_drop_linear": N_(
        "while the brake closes ({closing:.3g} ms) the load falls by up to {travel:.3g} mm "
        "(the output turns {angle:.3g}°; free fall would be {free_fall:.3g} mm)"
    ),
    "brake_drop_none": N_(
        "no weight acts on the axis (T_G = 0): the load does not fall while the brake closes"
    ),
    "brake_drop_no_data": N_(
        "the drop while the brake closes: no data (closing time or J_A not published)"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)


# --- brake_holding: T_L ≤ the brake's holding torque (catalogue brake data) -----------------


def _brake_message(q: Operands, status: Status, t_l: float, holding: float) -> str:
    if q.brake_safety_factor == 1.0:
        return phrase(f"brake_holding.{outcome(status)}", value=t_l, limit=holding)
    return phrase(
        f"brake_holding.{outcome(status)}_factor",
        value=t_l,
        limit=holding,
        factor=q.brake_safety_factor,
        torque=q.load_torque_nm,
    )


def braked(app: Application) -> bool:
    """Whether the actuator is fitted with its holding brake."""
    return app.brake


def emergency_stops_asked(app: Application) -> bool:
    """Whether the brake's emergency stops are checked."""
    return app.brake and app.emergency_stops is not None


BRAKE_HOLDING = Rule(
    name="brake_holding",
    when=braked,
    reference="catalogue brake data (holding torque)",
    unit="Nm",
    value=lambda q, xp: q.brake_safety_factor * q.load_torque_nm,
    limit=lambda q, xp: q.brake_holding_torque_nm,
    requires=(published("brake_holding_torque_nm", N_("brake holding torque")),),
    message=_brake_message,
)
"""T_L ≤ the holding torque of the actuator's brake (CHA tables; FHA-C manual §4-2), for
an actuator fitted with one (``Application.brake``). The chapter's T_L opposes motion
and needs no holding at standstill when it is friction; taken as acting at standstill it
covers a load that does (a weight, a spring, a process force), so the check is on the
safe side. The load is multiplied by the safety factor S the application sets (default 1:
no public manufacturer document read names one; docs/decisions/0024)."""


def drop_torque_nm(q: Operands) -> float:
    """The torque that turns the output while the brake closes (floats): the axis's |T_G|,
    or the chapter's T_L where the load is the shorthand (its nature unknown: taken as a
    weight, as :data:`BRAKE_HOLDING` does) [Nm]."""
    torque = q.drop_torque_nm
    return float(q.load_torque_nm if math.isnan(torque) else torque)


def drop_angle_rad(q: Operands) -> float:
    """How far the output turns while the brake closes (floats, one cell's words):
    θ = ½·α·t_c², α = T/(J_L + J_A) with T of :func:`drop_torque_nm` — the weight
    accelerating the load and the actuator's inertia from rest, the motor without torque,
    nothing else braking and no losses (the safe side) [rad]; NaN without t_c or J_A.

    On a linear axis of lever r (travel r·θ, J_L = J_rot + m·r², T = m_eff·g·r) this is
    s = ½·g·t_c²·m_eff·r²/(J_rot + m·r² + J_A): never more than free fall ½·g·t_c², equal
    to it where the falling mass is all the inertia (J_rot = J_A = 0, no counterweight)."""
    inertia = q.load_inertia_kgm2 + q.inertia_kgm2
    if not inertia > 0:
        return math.nan
    closing = q.brake_closing_time_s
    return float(0.5 * (drop_torque_nm(q) / inertia) * closing * closing)


def _drop_words(q: Operands) -> Phrase:
    """The drop while the brake closes, in words: the load's fall in mm on a linear axis
    (through the mechanism's travel per output radian), else the output's angle."""
    if drop_torque_nm(q) == 0.0:
        return phrase("brake_drop_none")
    angle = drop_angle_rad(q)
    if math.isnan(angle):
        return phrase("brake_drop_no_data")
    closing = q.brake_closing_time_s
    if math.isnan(q.travel_mm_per_rad):
        return phrase("brake_drop", closing=closing * 1000.0, angle=math.degrees(angle))
    return phrase(
        "brake_drop_linear",
        closing=closing * 1000.0,
        travel=angle * q.travel_mm_per_rad,
        angle=math.degrees(angle),
        free_fall=0.5 * STANDARD_GRAVITY_M_PER_S2 * closing * closing * 1000.0,
    )


def _emergency_message(q: Operands, status: Status, value: float, limit: float) -> str:
    return phrase(
        f"brake_emergency_stops.{outcome(status)}", value=value, limit=limit, drop=_drop_words(q)
    )


BRAKE_EMERGENCY_STOPS = Rule(
    name="brake_emergency_stops",
    when=emergency_stops_asked,
    reference="CHA 1018854 12/2015 Table 36.3, Table 38.3, Table 40.3",
    unit="",
    value=lambda q, xp: q.emergency_stops,
    limit=lambda q, xp: q.brake_emergency_stop_count,
    requires=(published("brake_emergency_stop_count", N_("allowable number of emergency stops")),),
    message=_emergency_message,
)
"""The emergency stops the application expects over the life ≤ the brake's allowable
number (CHA-25A, -32A, -40A: 200), with the drop while the brake closes in its words."""
