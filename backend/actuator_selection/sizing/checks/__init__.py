"""The flowchart's checks (chapter p. 514–517): the rule machinery, and the rules one
family to a file, each with its words.

- :mod:`~actuator_selection.sizing.checks.operands`: :class:`Operands`, what the rules
  compute from, one name per quantity;
- :mod:`~actuator_selection.sizing.checks.rule`: :class:`Check`, :class:`Rule`,
  :class:`Requirement`, :class:`Ops`;
- :mod:`~actuator_selection.sizing.checks.rules`: ``motion`` (speed, inertia, peak torques),
  ``thermal`` (continuous duty, heating, continuous speed), ``drive`` (current, voltage),
  ``bearing`` (output bearing), ``brake`` (holding brake, emergency stops), ``gear`` (the
  strain wave gear's own limits), ``stiffness`` (natural frequency, deflection).

The rules are found in their family's file (:data:`ALL_RULES`; a rule's ``when`` says which
load cases it checks, :func:`rules_for`); the engine (:mod:`actuator_selection.sizing.engine`)
runs them on arrays of load cases × actuators, in the order of a candidate's checks.

Each check compares one quantity, and reports it with its own value, limit and unit.

**Adding a check is adding one rule** (its formulas and its words) to the file of its
family; the engine, the verdicts and the ranking follow. Here
n_av ≤ n_max (Eq. 514.3) as a further check, with the chapter's worked example
(Table 516.1, FHA-25C-50-L of Table 516.3):

>>> from actuator_selection.catalogue.actuators import Actuator
>>> from actuator_selection.sizing.cycle import Load, SpeedPattern
>>> from actuator_selection.sizing.engine import evaluate_batch
>>> from actuator_selection.sizing.selection import Application, evaluate
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

from actuator_selection.sizing.checks.operands import Operands, Real, Truth
from actuator_selection.sizing.checks.rule import (
    FLOAT_OPS,
    Brief,
    Check,
    DeferredChecks,
    Formula,
    Message,
    Ops,
    Requirement,
    Rule,
    Status,
    margin_percent,
    overload,
    published,
    utilisation,
)
from actuator_selection.sizing.checks.rules import ALL_RULES, FAMILIES, RULES, rules_for
from actuator_selection.sizing.checks.rules.bearing import (
    BEARING_AXIAL_FORCE,
    BEARING_FRETTING,
    BEARING_LIFE,
    BEARING_MOMENT,
    BEARING_RADIAL_FORCE,
    BEARING_STATIC,
)
from actuator_selection.sizing.checks.rules.brake import BRAKE_EMERGENCY_STOPS, BRAKE_HOLDING
from actuator_selection.sizing.checks.rules.drive import (
    DRIVE_CURRENT,
    DRIVE_VOLTAGE,
    regenerative_energy_j,
)
from actuator_selection.sizing.checks.rules.gear import (
    GEAR_AVERAGE_TORQUE,
    GEAR_INPUT_SPEED,
    GEAR_LIFE,
    GEAR_MOMENTARY_PEAK,
    GEAR_REPEATED_PEAK,
)
from actuator_selection.sizing.checks.rules.motion import (
    DECEL_TORQUE,
    INERTIA_RATIO,
    INERTIA_RATIO_LIMIT,
    MAX_SPEED,
    PEAK_TORQUE,
)
from actuator_selection.sizing.checks.rules.stiffness import NATURAL_FREQUENCY
from actuator_selection.sizing.checks.rules.thermal import (
    CONTINUOUS_DUTY,
    CONTINUOUS_SPEED,
    THERMAL_PEAK,
)

__all__ = [
    "ALL_RULES",
    "BEARING_AXIAL_FORCE",
    "BEARING_FRETTING",
    "BEARING_LIFE",
    "BEARING_MOMENT",
    "BEARING_RADIAL_FORCE",
    "BEARING_STATIC",
    "BRAKE_EMERGENCY_STOPS",
    "BRAKE_HOLDING",
    "CONTINUOUS_DUTY",
    "CONTINUOUS_SPEED",
    "DECEL_TORQUE",
    "DRIVE_CURRENT",
    "DRIVE_VOLTAGE",
    "FAMILIES",
    "FLOAT_OPS",
    "GEAR_AVERAGE_TORQUE",
    "GEAR_INPUT_SPEED",
    "GEAR_LIFE",
    "GEAR_MOMENTARY_PEAK",
    "GEAR_REPEATED_PEAK",
    "INERTIA_RATIO",
    "INERTIA_RATIO_LIMIT",
    "MAX_SPEED",
    "NATURAL_FREQUENCY",
    "PEAK_TORQUE",
    "RULES",
    "THERMAL_PEAK",
    "Brief",
    "Check",
    "DeferredChecks",
    "Formula",
    "Message",
    "Operands",
    "Ops",
    "Real",
    "Requirement",
    "Rule",
    "Status",
    "Truth",
    "margin_percent",
    "overload",
    "published",
    "regenerative_energy_j",
    "rules_for",
    "utilisation",
]
