"""The rules' operands come from two homes (docs/decisions/0027): the registry's published
values and the worked-out ones typed in ``sizing/checks/operands.py``; the rules are found
in their family's file, in the answers' order."""

from __future__ import annotations

import ast
import inspect
import pkgutil

from actuator_selection.catalogue.fields import OPERAND_FIELDS
from actuator_selection.sizing.checks import ALL_RULES, FAMILIES, RULES, Operands, rules
from actuator_selection.sizing.checks.operands import PUBLISHED, Computed
from actuator_selection.sizing.engine.catalogue import CATALOGUE_OPERANDS

ANSWER_ORDER = (
    "max_speed",
    "inertia_ratio",
    "peak_torque",
    "decel_torque",
    "continuous_duty",
    "thermal_peak",
    "continuous_speed",
    "drive_voltage",
    "brake_holding",
    "brake_emergency_stops",
    "gear_average_torque",
    "gear_repeated_peak",
    "gear_input_speed",
    "gear_momentary_peak",
    "gear_life",
    "natural_frequency",
    "drive_current",
    "bearing_moment",
    "bearing_static_safety",
    "bearing_radial_force",
    "bearing_axial_force",
    "bearing_fretting",
    "bearing_life",
)
"""Every check in the order the answers (stored ones too) list them."""


def test_every_published_operand_is_a_field_and_declared_once() -> None:
    assert tuple(f.operand_name for f in OPERAND_FIELDS) == PUBLISHED
    assert Operands._fields == (*Computed._fields, *PUBLISHED)
    assert len(set(Operands._fields)) == len(Operands._fields), "an operand named twice"
    assert set(CATALOGUE_OPERANDS) <= set(Operands._fields)


def _names_read(source: str) -> set[str]:
    """The attributes a module reads of ``q`` (a rule's operands) and the operands its
    requirements name (``published("…")``, ``Requirement(any_of=…)``)."""
    names: set[str] = set()
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Attribute) and isinstance(node.value, ast.Name):
            if node.value.id == "q":
                names.add(node.attr)
        elif isinstance(node, ast.Call) and getattr(node.func, "id", None) == "published":
            first = node.args[0]
            if isinstance(first, ast.Constant) and isinstance(first.value, str):
                names.add(first.value)
    return names


def test_the_rules_read_operands_only() -> None:
    """mypy sees a published value as ``Any`` (``Operands.__getattr__``): a misspelt one
    fails here, before any rule runs."""
    fields = set(Operands._fields) | {"_replace"}
    for family in FAMILIES:
        module = __import__(f"{rules.__name__}.{family}", fromlist=["_"])
        unknown = _names_read(inspect.getsource(module)) - fields
        assert not unknown, f"{family}: not an operand: {sorted(unknown)}"
    for rule in ALL_RULES:
        for need in rule.requires:
            assert set(need.any_of) <= set(PUBLISHED) | set(CATALOGUE_OPERANDS), rule.name


def test_rules_are_found_in_their_families_in_the_answers_order() -> None:
    assert tuple(r.name for r in ALL_RULES) == ANSWER_ORDER
    assert tuple(r for r in ALL_RULES if r.when is None) == RULES
    assert len({r.name for r in ALL_RULES}) == len(ALL_RULES)
    modules = {m.name for m in pkgutil.iter_modules(rules.__path__)}
    assert modules == set(FAMILIES), "a family's module not in FAMILIES"
