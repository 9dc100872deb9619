"""Shared pieces of the API contract: strict models and the stated physical bounds.

Bounds reject magnitudes that no servo-actuator application has, so that absurd
input gets a clear 422 instead of overflowing a calculation. They are generous:
the largest catalogue actuator delivers under 2 kNm at under 300 rpm.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import replace
from enum import Enum
from types import UnionType
from typing import Annotated, Any, ClassVar, Literal, Union, get_args, get_origin

from pydantic import BaseModel, ConfigDict, ValidationInfo, field_validator
from pydantic.config import JsonDict

from actuator_selection.text import text_problem

MAX_SPEED_RPM = 100_000.0
"""n_2 bound [rpm]: ten times the fastest servo motor shaft."""
MAX_TORQUE_NM = 1_000_000.0
"""Torque bound [Nm]: 500 times the largest catalogue actuator's peak torque."""
MAX_INERTIA_KGM2 = 1_000_000.0
"""Inertia bound [kgm²]: a 100 t ring of 4.5 m radius."""
MIN_RAMP_S = 1e-4
"""Shortest t_1, t_3 [s]: 0.1 ms, below a servo controller's current-loop cycle times 2."""
MAX_TIME_S = 86_400.0
"""Longest single phase of a cycle [s]: one day."""
MAX_MASS_KG = 1_000_000.0
"""Moved mass bound [kg]: 1000 t."""
MAX_LENGTH_M = 100.0
"""Bound for leads, diameters and radii [m]."""
MIN_LENGTH_M = 1e-6
"""Smallest screw lead or table diameter [m]: 1 µm, a hundred times below the finest
precision screw lead (~0.1 mm). Without it a lead of 5e-324 m passes "> 0" and its
T_L = μ·m·P·g/(2π·η) underflows to exactly 0, a load that silently vanishes."""
MIN_EFFICIENCY = 0.01
"""Smallest screw efficiency η [-]: 1 %. A ball screw runs at η ≈ 0.9, even a
self-locking trapezoidal lead screw at η ≈ 0.2–0.4; η divides Eq. 515.4, and a value
like 1e-300 drives T_L (and T_rms) past the largest float. With η ≥ 0.01 and the other
bounds here, T_L ≤ 1.6·10¹¹ Nm and every result of the cycle stays finite."""
MAX_FRICTION_COEFFICIENT = 10.0
"""μ bound [-]: dry rubber on rubber stays below 2."""


def shown(symbol: str, label: str) -> JsonDict:
    """How a page shows a request field (``json_schema_extra``): its symbol as the chapter
    prints it (``"J_S"``, subscript after ``_``) and the message key of its label
    (``"load.screw_inertia"``). ``schemas/mechanism_spec.py`` reads both from the models,
    so that the page's mechanism fields are declared here once (``GET /mechanisms``)."""
    return {"x-symbol": symbol, "x-label": label}


def text_rule_broken(value: object, *, line_breaks: bool = False) -> str | None:
    """The text rule (``text.text_problem``) broken by ``value``: text, or lists and
    objects of it (keys too); None when every text in it is clean."""
    if isinstance(value, str):
        return text_problem(value, line_breaks=line_breaks)
    if isinstance(value, list | tuple):
        items: Iterable[object] = value
    elif isinstance(value, dict):
        items = (x for pair in value.items() for x in pair)
    else:
        return None
    for item in items:
        if (rule := text_rule_broken(item, line_breaks=line_breaks)) is not None:
            return rule
    return None


class StrictModel(BaseModel):
    """Unknown fields are errors (a typo must not silently drop a value); no NaN or ±∞;
    text obeys the one text rule (``text.text_problem``): no U+0000 (PostgreSQL cannot
    store it), no control characters or bidirectional overrides, and line breaks and tabs
    only in the fields named in ``line_break_fields`` (e.g. an address).

    JSON types are strict: ``true`` is not 1 rpm, ``"yes"`` or ``1`` is not a boolean,
    ``"40"`` is not a number and ``40`` is not text. A JSON integer is still a number
    (``"speed_rpm": 40``). Fields the API documents as strings of another type opt out
    one by one and check their own input: decimals (``schemas.quotes.DecimalIn``),
    dates (``valid_until``), enumerations given by name (``sensor``).
    """

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=True, strict=True)

    line_break_fields: ClassVar[frozenset[str]] = frozenset()
    """Text fields that may hold line breaks and tabs (multi-line text)."""

    # After each field's own validation, so a nested model has already named its field.
    @field_validator("*", mode="after", check_fields=False)
    @classmethod
    def _text_rule(cls, value: Any, info: ValidationInfo) -> Any:
        if info.field_name not in _text_fields(cls):
            return value  # a number, a flag, a nested model (checked on its own)
        multi_line = info.field_name in cls.line_break_fields
        if (rule := text_rule_broken(value, line_breaks=multi_line)) is not None:
            raise ValueError(rule)
        return value

    @classmethod
    def __pydantic_init_subclass__(cls, **kwargs: Any) -> None:
        super().__pydantic_init_subclass__(**kwargs)
        _text_rule_on_text_fields(cls)


def _text_rule_on_text_fields(model: type[StrictModel]) -> None:
    """The text rule (``StrictModel._text_rule``) validating only ``model``'s text fields
    (:func:`_text_fields`), not every field: its schema rebuilt with the rule's fields
    named. A batch of 10,000 cases has ~10⁵ numbers, for each of which the rule was a
    Python call (~0.1 s of the request). A model not complete yet keeps the rule on every
    field (it skips the others itself)."""
    if not model.__pydantic_complete__:
        return
    validators = model.__pydantic_decorators__.field_validators
    rule = validators["_text_rule"]
    fields = tuple(sorted(_text_fields(model)))
    if rule.info.fields == fields:
        return
    validators["_text_rule"] = replace(rule, info=replace(rule.info, fields=fields))
    model.model_rebuild(force=True)


_TEXT_FIELDS: dict[type[BaseModel], frozenset[str]] = {}


def _text_fields(model: type[BaseModel]) -> frozenset[str]:
    """The fields of ``model`` whose values may hold text (computed once per model): the
    text rule is only run on them. A batch of 10,000 cases has ~10⁵ numbers, for which it
    cost a Python call each (1.3 s of the request)."""
    found = _TEXT_FIELDS.get(model)
    if found is None:
        found = _TEXT_FIELDS[model] = frozenset(
            name for name, field in model.model_fields.items() if _may_hold_text(field.annotation)
        )
    return found


_NO_TEXT: frozenset[object] = frozenset({float, int, bool, type(None)})


def _may_hold_text(annotation: object) -> bool:
    """False where every value of ``annotation`` is a number, a flag, None, a literal or
    enumeration of ours, a strict model (which runs the text rule on its own fields), or
    a container of such only; True for anything else (text, containers that may hold
    it, any other type: checked)."""
    if annotation in _NO_TEXT:
        return False
    if isinstance(annotation, type) and issubclass(annotation, StrictModel | Enum):
        return False
    origin = get_origin(annotation)
    if origin is Literal:
        return False
    if origin is Annotated:
        return _may_hold_text(get_args(annotation)[0])
    if origin is Union or origin is UnionType:
        return any(_may_hold_text(a) for a in get_args(annotation))
    if origin in _CONTAINERS and get_args(annotation):
        # a list of load cases holds no text of its own: each case checks its fields
        return any(_may_hold_text(a) for a in get_args(annotation) if a is not Ellipsis)
    return True


_CONTAINERS: frozenset[object] = frozenset({list, tuple, set, frozenset, dict})
"""Containers whose items' types say whether they may hold text (a dict's keys too)."""


class ResponseModel(BaseModel):
    """Base of response bodies."""

    model_config = ConfigDict(frozen=True)
