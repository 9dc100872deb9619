"""The holding brake's check (catalogue brake data), for an actuator fitted with one."""

from __future__ import annotations

from typing import Final

from actuator_selection.core.check_messages import check_words, phrase
from actuator_selection.core.checks.rule import Operands, Rule, Status, outcome, published
from actuator_selection.core.messages import N_

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
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)


# --- brake_holding: T_L ≤ the brake's holding torque (catalogue brake data) -----------------


def _brake_message(q: Operands, status: Status, t_l: float, holding: float) -> str:
    return phrase(f"brake_holding.{outcome(status)}", value=t_l, limit=holding)


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
