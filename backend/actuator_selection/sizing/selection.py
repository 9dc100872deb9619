"""The selection flowchart for one actuator, and the ranking of many (chapter p. 514–517).

For each actuator the flowchart runs the checks of :data:`~actuator_selection.sizing.checks.RULES`,
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
rules live in :mod:`actuator_selection.sizing.checks`, one family to a file. One engine
runs them (:mod:`actuator_selection.sizing.engine`, arrays of cases × actuators): a
selection is its 1 × N view (:func:`select`), one actuator's candidate its 1 × 1 view
(:func:`evaluate`). The load case is :class:`~actuator_selection.sizing.application.
Application`; the outcome :class:`~actuator_selection.sizing.candidates.Candidate`.

Worked example (Table 516.1, FHA-25C-50-L of Table 516.3, no zone published here):

>>> from actuator_selection.catalogue.actuators import Actuator
>>> from actuator_selection.sizing.cycle import Load, SpeedPattern
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

from actuator_selection.sizing.application import Application, require_time_constant
from actuator_selection.sizing.candidates import (
    VALUE_OF,
    Candidate,
    Selection,
    Verdict,
    ranking_key,
    size_key,
)
from actuator_selection.sizing.checks import INERTIA_RATIO_LIMIT, Check, Status
from actuator_selection.sizing.engine import evaluate, evaluate_each, select

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
    "ranking_key",
    "require_time_constant",
    "select",
    "size_key",
]
