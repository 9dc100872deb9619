"""The holding brake's checks (catalogue brake data), for an actuator fitted with one:
its holding torque against the static load with a safety factor, and, where the
application names how many emergency stops it expects, their count against the brake's
allowable number with how far the load drops while the brake closes (issue 28, item 9)."""

from __future__ import annotations

import math
from typing import Final

from actuator_selection.core.check_messages import check_words, phrase
from actuator_selection.core.checks.rule import Operands, Rule, Status, outcome, published
from actuator_selection.core.messages import N_

DEFAULT_BRAKE_SAFETY_FACTOR: Final = 1.0
"""S of :data:`BRAKE_HOLDING` where the application sets none: 1, the catalogue's holding
torque as published. No public manufacturer document read for the catalogue's actuators
(CHA 1018854 12/2015 brake tables; FHA-C manual §4-2) names a safety factor for holding;
the application sets its own (docs/decisions/0024-gear-checks-when-asked.md)."""

WORDS: Final = {
    # brake_holding
    "brake_holding.pass": N_(
        "load torque at standstill T_L = {value:.4g} Nm ≤ the brake's holding torque = "
        "{limit:.4g} Nm"
    ),
    "brake_holding.fail": N_(
        "load torque at standstill T_L = {value:.4g} Nm exceeds the brake's holding torque = "
        "{limit:.4g} Nm"
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


BRAKE_HOLDING = Rule(
    name="brake_holding",
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


def drop_angle_rad(q: Operands) -> float:
    """How far the output turns while the brake closes (floats, one cell's words):
    θ = ½·α·t_c², α = T_L/(J_L + J_A) — the held load T_L accelerating the load and the
    actuator's inertia from rest, the motor without torque and nothing else braking
    (friction counted in T_L as driving: on the safe side) [rad]; NaN without t_c or J_A."""
    inertia = q.load_inertia_kgm2 + q.inertia_kgm2
    if not inertia > 0:
        return math.nan
    closing = q.brake_closing_time_s
    return float(0.5 * (q.load_torque_nm / inertia) * closing * closing)


def _emergency_message(q: Operands, status: Status, value: float, limit: float) -> str:
    angle = drop_angle_rad(q)
    if math.isnan(angle):
        drop = phrase("brake_drop_no_data")
    else:
        drop = phrase(
            "brake_drop", closing=q.brake_closing_time_s * 1000.0, angle=math.degrees(angle)
        )
    return phrase(f"brake_emergency_stops.{outcome(status)}", value=value, limit=limit, drop=drop)


BRAKE_EMERGENCY_STOPS = Rule(
    name="brake_emergency_stops",
    reference="CHA 1018854 12/2015 Table 36.3, Table 38.3, Table 40.3",
    unit="",
    value=lambda q, xp: q.emergency_stops,
    limit=lambda q, xp: q.brake_emergency_stop_count,
    requires=(published("brake_emergency_stop_count", N_("allowable number of emergency stops")),),
    message=_emergency_message,
)
"""The emergency stops the application expects over the life ≤ the brake's allowable
number (CHA-25A, -32A, -40A: 200), with the drop while the brake closes in its words."""
