"""The checks, one family to a file, each rule with its words.

A rule is found where it is defined: every :class:`~actuator_selection.sizing.checks.rule.
Rule` at the top level of a family's module is a check (:data:`ALL_RULES`), with no list
to add it to. The order of a candidate's checks follows from where the rules stand: the
rules every case runs (``when`` None) first, then those a case asks for; within each, by
family (:data:`FAMILIES`), then in the order the family's file defines them. The answers
list the checks in that order, so a new rule goes below its family's others.
"""

from __future__ import annotations

import importlib
from functools import cache
from typing import TYPE_CHECKING, Final

from actuator_selection.sizing.checks.rule import Rule

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

FAMILIES: Final = ("motion", "thermal", "brake", "gear", "stiffness", "drive", "bearing")
"""The families' modules in the order of their checks (the chapter's flowchart first:
motion, thermal; then the brake's, the gear's, the stiffness', the drive's current, the
output bearing's). A new family is a new module here."""


def _discovered() -> tuple[Rule, ...]:
    found: dict[int, Rule] = {}
    for family in FAMILIES:
        module = importlib.import_module(f"{__name__}.{family}")
        for value in vars(module).values():
            if isinstance(value, Rule):
                found.setdefault(id(value), value)
    # Stable: the rules every case runs first, each group in family and file order.
    return tuple(sorted(found.values(), key=lambda rule: rule.when is not None))


ALL_RULES: Final = _discovered()
"""Every check, in the order a candidate lists them."""

RULES: Final = tuple(rule for rule in ALL_RULES if rule.when is None)
"""The checks of every load case: the flowchart's in the manufacturer's order (chapter
p. 514–517), then whether T_rms stands for the cycle's length (``THERMAL_PEAK``,
Fig. 520.1's model), then the continuous speed by the same model (``CONTINUOUS_SPEED``),
then whether a controller listed for the actuator (Table 521.1) delivers the voltage the
axis needs (``DRIVE_VOLTAGE``): an actuator that no listed controller can drive at n_2 is
not suitable, whether or not the drive is sized (issue 28, item 1). Where the catalogue
lacks the winding's constants (K_E in V_rms, L, p) or lists no controller on a bus class
the actuator runs on, that check lacks data and the verdict is unconfirmed."""

CONDITIONS: Final = tuple(dict.fromkeys(r.when for r in ALL_RULES if r.when is not None))
"""Each distinct ``when`` of the rules, once."""


def rules_for(app: Application) -> tuple[Rule, ...]:
    """The checks ``app`` runs: those of :data:`ALL_RULES` whose ``when`` holds for it, in
    their order; one tuple per combination, so that cases group by their rules cheaply."""
    return _rule_set(tuple([asked(app) for asked in CONDITIONS]))


@cache
def _rule_set(asked: tuple[bool, ...]) -> tuple[Rule, ...]:
    met = {when for when, yes in zip(CONDITIONS, asked, strict=True) if yes}
    return tuple(rule for rule in ALL_RULES if rule.when is None or rule.when in met)
