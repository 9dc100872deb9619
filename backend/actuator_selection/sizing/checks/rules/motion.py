"""The motion checks: speed, inertia ratio, peak torques (chapter p. 514–515).

1. ``max_speed``: n_2 ≤ n_max (Table 515.1);
2. ``inertia_ratio``: J_L ≤ 3·J_A (Table 515.1, footnote 1: recommended for highly
   dynamic applications, so a failure there and a warning otherwise);
3. ``peak_torque``: |T_1| ≤ T_max (Eq. 514.1);
4. ``decel_torque``: |T_3| ≤ T_max (Eq. 514.1).
"""

from __future__ import annotations

from typing import Final

from actuator_selection.phrases.check_messages import check_words
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.checks.rule import Rule, compared, published

INERTIA_RATIO_LIMIT = 3.0
"""J_L ≤ 3·J_A, the pre-selection rule of Table 515.1."""


WORDS: Final = {
    # 1. max_speed
    "max_speed.pass": N_("load speed n_2 = {value:.4g} rpm ≤ n_max = {limit:.4g} rpm"),
    "max_speed.fail": N_("load speed n_2 = {value:.4g} rpm exceeds n_max = {limit:.4g} rpm"),
    # 2. inertia_ratio
    "inertia_ratio.pass": N_("load inertia J_L = {value:.4g} kgm² ≤ 3·J_A = {limit:.4g} kgm²"),
    "inertia_ratio.fail": N_(
        "load inertia J_L = {value:.4g} kgm² exceeds 3·J_A = {limit:.4g} kgm²: the limit is "
        "binding for a highly dynamic application"
    ),
    "inertia_ratio.warn": N_(
        "load inertia J_L = {value:.4g} kgm² exceeds 3·J_A = {limit:.4g} kgm²: recommended "
        "for highly dynamic applications only"
    ),
    # 3., 4. peak_torque, decel_torque
    "peak_torque.pass": N_("acceleration torque T_1 = {value:.4g} Nm ≤ T_max = {limit:.4g} Nm"),
    "peak_torque.fail": N_(
        "acceleration torque T_1 = {value:.4g} Nm exceeds T_max = {limit:.4g} Nm"
    ),
    "decel_torque.pass": N_("deceleration torque |T_3| = {value:.4g} Nm ≤ T_max = {limit:.4g} Nm"),
    "decel_torque.fail": N_(
        "deceleration torque |T_3| = {value:.4g} Nm exceeds T_max = {limit:.4g} Nm"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)


# --- 1. max_speed: n_2 ≤ n_max (Table 515.1) ------------------------------------------------


MAX_SPEED = Rule(
    name="max_speed",
    reference="Table 515.1",
    unit="rpm",
    value=lambda q, xp: q.speed_rpm,
    limit=lambda q, xp: q.max_speed_rpm,
    requires=(published("max_speed_rpm", N_("maximum output speed n_max")),),
    message=compared("max_speed"),
)
"""n_2 ≤ n_max (Table 515.1)."""


# --- 2. inertia_ratio: J_L ≤ 3·J_A (Table 515.1, footnote 1) --------------------------------


INERTIA_RATIO = Rule(
    name="inertia_ratio",
    reference="Table 515.1",
    unit="kgm²",
    value=lambda q, xp: q.load_inertia_kgm2,
    limit=lambda q, xp: INERTIA_RATIO_LIMIT * q.inertia_kgm2,
    requires=(published("inertia_kgm2", N_("moment of inertia J_A")),),
    binding=lambda q, xp: q.high_dynamics,
    message=compared("inertia_ratio", by_status=True),
)
"""J_L ≤ 3·J_A (Table 515.1); binding for highly dynamic applications only, a warning else."""


# --- 3., 4. peak_torque, decel_torque: T_1, |T_3| ≤ T_max (Eq. 514.1) -----------------------


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
    message=compared("peak_torque"),
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
    message=compared("decel_torque"),
    lower_bound=lambda q, xp: q.decel_torque_floor_nm,
)
"""|T_3| ≤ T_max (Eq. 514.1): braking loads the gear as much as accelerating."""
