"""The load kinds and their fields as a page shows them, derived from the request models.

A selection's ``load`` is one of the models of :data:`~schemas.selections.LoadIn` (the
chapter's direct load, ball screw and rotary table, and the mechanisms of
``schemas/mechanisms.py``). Each model declares its fields once: name, bounds, default,
unit (an :class:`~schemas.quantities.InUnit` marker, else the unit its name ends in), and
how a page shows it (``shown(symbol, label key)`` in its ``json_schema_extra``). This
module reads them back into one plain answer, served as ``GET /api/v1/mechanisms``
(``api/mechanisms.py``) and written into the page's ``frontend/pages/engineer/
mechanism-spec.js`` (``make mechanisms``; a test keeps that file equal to
:func:`mechanism_spec`). The page builds the load kind's choices and fieldsets from it.

Run as ``python -m actuator_selection.schemas.mechanism_spec PATH`` to write the module.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Annotated, Any, Literal, get_args, get_origin

from pydantic import BaseModel, Field

from actuator_selection.schemas.common import ResponseModel
from actuator_selection.schemas.mechanisms import TransmissionIn, _MechanismIn
from actuator_selection.schemas.quantities import LINEAR_SPEED_MM_PER_S, InUnit
from actuator_selection.schemas.selections import LoadIn

NOT_FIELDS = frozenset({"type", "speed", "speed_rpm", "transmission"})
"""Members of a load model that are not its own fields: the union tag, the trapezoid's
speed (one field of the form for every kind) and the transmission (its own fieldset)."""

UNIT_SUFFIXES = (
    ("_kgm2", "kgm²"),
    ("_kg", "kg"),
    ("_mm", "mm"),
    ("_m", "m"),
    ("_nm", "Nm"),
    ("_n", "N"),
    ("_deg", "°"),
    ("_rpm", "rpm"),
)
"""The unit of a plain-number field by the end of its name (the API's naming rule);
any other field is a ratio or coefficient, shown as "–"."""

EQUATIONS = {"ball_screw": "load.ball_screw.eq", "rotary_table": "load.rotary_table.eq"}
"""The message key of the chapter's equation and figure for its two resolved loads."""


class FieldSpec(ResponseModel):
    """One input of a load kind."""

    name: str = Field(description="the request field under `load` (or `load.transmission`)")
    symbol: str = Field(description="as the chapter prints it; `_` starts the subscript")
    label: str = Field(description="message key of the field's words (the page's catalogue)")
    unit: str = Field(description="the unit of a number in this field, as the API writes it")
    units: bool = Field(description="whether text with a unit ('0.5 in') is accepted too")
    required: bool
    default: float | None = Field(description="the value an omitted field takes; null: none")
    minimum: float | None = None
    maximum: float | None = None
    exclusive_minimum: bool = Field(default=False, description="the minimum itself is refused")


class MechanismSpec(ResponseModel):
    """One kind of `load`: its `type`, words and fields."""

    type: str
    label: str = Field(description="message key of the kind's name")
    hint: str | None = Field(description="message key of a line on its units, if any")
    equation: str | None = Field(description="message key of the chapter's equation, if any")
    speed_field: Literal["speed_rpm", "speed"] = Field(
        description="the trapezoid's load speed: n_2 in rpm, or `speed` (mm/s or rpm)"
    )
    linear: bool = Field(description="a linear axis: speed in mm/s, process loads in N")
    transmission: bool = Field(description="whether it takes `load.transmission`")
    fields: list[FieldSpec]


class MechanismsOut(ResponseModel):
    """Every kind of `load` a selection takes, in the order a page offers them."""

    kinds: list[MechanismSpec]
    transmission: list[FieldSpec] = Field(description="the fields of `load.transmission`")


def _in_unit(annotation: Any) -> InUnit | None:
    """The :class:`InUnit` marker inside ``annotation`` (through ``| None``), if any."""
    if get_origin(annotation) is Annotated:
        marker = next((m for m in annotation.__metadata__ if isinstance(m, InUnit)), None)
        return marker or _in_unit(get_args(annotation)[0])
    for arg in get_args(annotation):
        if (marker := _in_unit(arg)) is not None:
            return marker
    return None


def _unit_of(name: str) -> str:
    return next((unit for suffix, unit in UNIT_SUFFIXES if name.endswith(suffix)), "–")


def _number_schema(prop: dict[str, Any]) -> dict[str, Any]:
    """The number branch of a property's JSON schema (a quantity is number | text)."""
    if prop.get("type") == "number":
        return prop
    return next((p for p in prop.get("anyOf", []) if p.get("type") == "number"), {})


def _fields(model: type[BaseModel]) -> list[FieldSpec]:
    props = model.model_json_schema()["properties"]
    out = []
    for name, info in model.model_fields.items():
        if name in NOT_FIELDS:
            continue
        prop = props[name]
        number = _number_schema(prop)
        marker = _in_unit(info.annotation) or next(
            (m for m in info.metadata if isinstance(m, InUnit)), None
        )
        low = number.get("exclusiveMinimum", number.get("minimum"))
        default = None if info.is_required() else info.default
        out.append(
            FieldSpec(
                name=name,
                symbol=prop["x-symbol"],
                label=prop["x-label"],
                unit=marker.kind.label if marker else _unit_of(name),
                units=marker is not None,
                required=info.is_required(),
                default=default,
                minimum=low,
                maximum=number.get("maximum"),
                exclusive_minimum="exclusiveMinimum" in number,
            )
        )
    return out


def _models() -> list[type[BaseModel]]:
    """The models of the load union, in its order."""
    union = get_args(LoadIn)[0]
    return [get_args(member)[0] for member in get_args(union)]


def _kind(model: type[BaseModel]) -> MechanismSpec:
    kind = get_args(model.model_fields["type"].annotation)[0]
    mechanism = issubclass(model, _MechanismIn)
    speed = model.model_fields.get("speed")
    linear = speed is not None and (marker := _in_unit(speed.annotation)) is not None
    linear = linear and marker is not None and marker.kind is LINEAR_SPEED_MM_PER_S
    return MechanismSpec(
        type=kind,
        label=f"load.{kind}",
        hint=f"mech.{kind}.hint" if mechanism else None,
        equation=EQUATIONS.get(kind),
        speed_field="speed" if mechanism else "speed_rpm",
        linear=linear,
        transmission="transmission" in model.model_fields,
        fields=_fields(model),
    )


def mechanism_spec() -> MechanismsOut:
    """Every load kind with its fields, from the request models."""
    return MechanismsOut(kinds=[_kind(m) for m in _models()], transmission=_fields(TransmissionIn))


MODULE_HEAD = """\
// GENERATED from the request models by `make mechanisms`
// (backend/actuator_selection/schemas/mechanism_spec.py; the same answer as
// GET /api/v1/mechanisms). Do not edit: tests/api/test_mechanism_spec.py fails when stale.

/**
 * @typedef {object} FieldSpec
 * @property {string} name
 * @property {string} symbol
 * @property {string} label
 * @property {string} unit
 * @property {boolean} units
 * @property {boolean} required
 * @property {number | null} default
 * @property {number | null} minimum
 * @property {number | null} maximum
 * @property {boolean} exclusive_minimum
 *
 * @typedef {object} MechanismSpec
 * @property {string} type
 * @property {string} label
 * @property {string | null} hint
 * @property {string | null} equation
 * @property {"speed_rpm" | "speed"} speed_field
 * @property {boolean} linear
 * @property {boolean} transmission
 * @property {FieldSpec[]} fields
 *
 * @typedef {object} MechanismsSpec
 * @property {MechanismSpec[]} kinds
 * @property {FieldSpec[]} transmission
 */

/** @type {MechanismsSpec} */
export const SPEC = """


def module_text() -> str:
    """The page's ES module holding :func:`mechanism_spec` as a constant."""
    body = json.dumps(mechanism_spec().model_dump(mode="json"), ensure_ascii=False, indent=2)
    return f"{MODULE_HEAD}{body};\n"


if __name__ == "__main__":  # pragma: no cover - `make mechanisms`
    Path(sys.argv[1]).write_text(module_text(), encoding="utf-8")
