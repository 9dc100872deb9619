"""Physical quantities at the edge: a number in the field's unit, or text with a unit.

A field annotated with a :class:`InUnit` marker takes

- a JSON number, read in the unit its name and description state (``"lead_mm": 10``),
  exactly as sent; or
- a string of a number and a unit (``"lead_mm": "0.5 in"``, ``"speed": "12 in/s"``,
  ``"mass_kg": "22 lb"``), converted to the field's unit by pint's unit registry.

The text must be a plain decimal number followed by a unit expression: unit names,
spaces, ``*``, ``·``, ``/``, parentheses and single-digit exponents (``m^2``, ``m**2``,
``m²``). Arithmetic (``3 m + 2 mm``, ``2**10 mm``) is not accepted: a request carries
values, not formulas, and pint would evaluate them (with Python integers, unbounded).
A unit of the wrong kind (``"3 kg"`` for a length), an unknown unit or malformed text is
a validation error (422) on that field whose message states the rule. Angles count as a
unit of their own: ``"2 rad/s"`` or ``"40 rpm"`` is a rotary speed, ``"1 Hz"`` or
``"1/s"`` is not (a revolution or a radian per second? the text does not say).

The converted value then meets the field's bounds in the field's unit; the message of a
bound broken by a converted value shows the value after conversion.

pint stays here, out of the domain (it imports the standard library and numpy only).
"""

from __future__ import annotations

import math
import re
import threading
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from pydantic import GetCoreSchemaHandler, GetJsonSchemaHandler, ValidationError
from pydantic.json_schema import JsonSchemaValue
from pydantic_core import CoreSchema, PydanticCustomError, core_schema

from actuator_selection.phrases.messages import N_, Text

if TYPE_CHECKING:
    import pint

QUANTITY_MESSAGES: dict[tuple[str, str], str] = {
    ("quantity_text", "too_long"): N_(
        "must be a number in {unit}, or text of a number and a unit of at most "
        "{max_length} characters, e.g. '{example}'"
    ),
    ("quantity_text", "not_quantity"): N_(
        "must be a number in {unit}, or text of a number and then a unit, e.g. '{example}' "
        "(no formulas; exponents of one digit): got '{text}'"
    ),
    ("quantity_unit", "unknown_unit"): N_(
        "must be a number in {unit}, or text with a known unit, e.g. '{example}': "
        "'{given_unit}' is not one ({reason})"
    ),
    ("quantity_unit", "wrong_kind"): N_(
        "must be {kind}, a number in {unit} or text like '{example}': '{given_unit}' is not "
        "a unit of {kind_words}{note}"
    ),
    ("finite_number", "overflow"): N_("Input should be a finite number: '{text}' in {unit}"),
}
"""The errors of quantity text by ``type`` and ``ctx["rule"]``: English templates over the
error's ``ctx`` (``i18n/localize.py`` renders them in the request's language)."""


def _error(type_: str, rule: str, kind: QuantityKind, **ctx: Any) -> PydanticCustomError:
    context = {
        "rule": rule,
        "unit": kind.label,
        "kind": kind.kind,
        "kind_words": kind_words(kind),
        "example": kind.example,
        **ctx,
    }
    return PydanticCustomError(type_, QUANTITY_MESSAGES[type_, rule], context)


MAX_QUANTITY_TEXT = 64
"""Longest text of a quantity [characters]: ``"1234.5678 kg*m^2"`` needs 16."""

_NAME_CHAR = r"(?:[^\W\d\u00b2\u00b3\u00b9\u2070-\u207f]|°)"
"""One character of a unit name: a letter (µ included) or °; no digits, no superscripts
(pint reads those as exponents)."""
_EXPONENT = r"(?:(?:\^|\*\*)-?[0-9]|[²³])"
"""One exponent of one digit, ``^2``, ``**-1`` or ``²``, allowed right after a name only:
``m^9^9^9`` or ``(m^9)^9`` would make pint raise integers to powers without end."""
_TEXT = re.compile(
    r"\s*(?P<number>[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?)"
    rf"\s*(?P<unit>(?:{_NAME_CHAR}{_EXPONENT}?|[·/*() ])+?)\s*"
)
"""A decimal number, then a unit expression of names, exponents and ``* · / ( )``.

Each repetition takes one name character (perhaps with its exponent) or one separator:
no quantifier nests in another, so a failed match backtracks over at most the ways to
split the spaces, quadratic in the (64-character) text. A name as a repeated group of
characters, ``(?:[a-z]+)+``, matched the same texts but tried every split of a run of
letters: ``"1 aaaaaaaaaaaaaaaaaaaaaa!"`` took seconds, one letter more twice as long."""

_ALIASES = ("@alias revolution = rev", "@alias pound = lbm")
"""Spellings engineers use that pint's default registry lacks (``rev/min``, ``lbm``)."""

_registry: pint.UnitRegistry[float] | None = None
_registry_lock = threading.Lock()


def _pint_error() -> type[Exception]:
    """pint's base error, from the module the registry loaded."""
    import pint

    return pint.PintError


def unit_registry() -> pint.UnitRegistry[float]:
    """The one unit registry, built on first use (pint reads its definitions in ~0.2 s and
    takes ~13 MB: a cost that requests with plain numbers never pay)."""
    global _registry
    with _registry_lock:
        if _registry is None:
            import pint

            registry: pint.UnitRegistry[float] = pint.UnitRegistry()
            for alias in _ALIASES:
                registry.define(alias)
            _registry = registry
        return _registry


@dataclass(frozen=True, slots=True)
class QuantityKind:
    """What a quantity field measures: its unit for numbers, and words for its messages.

    Parameters
    ----------
    unit
        The field's unit in pint's spelling (``"mm/s"``); numbers are read in it, text is
        converted to it.
    label
        The unit as the API writes it (``"kgm²"``).
    kind
        What it measures, for messages (``"a linear speed"``).
    example
        Text that converts, for messages and the JSON schema (``"12 in/s"``).
    note
        What else a message about a unit of the wrong kind should say.
    """

    unit: str
    label: str
    kind: str
    example: str
    note: str = Text("")


def to_unit(text: str, kind: QuantityKind) -> float:
    """The value of ``text`` (a number and a unit) in ``kind.unit``.

    Raises
    ------
    PydanticCustomError
        ``quantity_text`` for text that is not a number and a unit, ``quantity_unit`` for
        an unknown unit or one of another kind (its dimension, and for angles the angle,
        must match), ``finite_number`` for a number beyond any float.

    >>> to_unit("0.5 in", LENGTH_MM)
    12.7
    >>> round(to_unit("12 in/s", LINEAR_SPEED_MM_PER_S), 9)
    304.8
    >>> round(to_unit("2 rev/s", ROTARY_SPEED_RPM), 9)
    120.0
    """
    if len(text) > MAX_QUANTITY_TEXT:
        raise _error("quantity_text", "too_long", kind, max_length=MAX_QUANTITY_TEXT)
    match = _TEXT.fullmatch(text)
    if match is None:
        raise _error("quantity_text", "not_quantity", kind, text=text)
    number = float(match["number"])
    if not math.isfinite(number):
        raise PydanticCustomError("finite_number", "Input should be a finite number")
    registry = unit_registry()
    try:
        unit = registry.parse_units(match["unit"])
        given_base = registry.get_base_units(unit)[1]
    # pint's parser raises many kinds (UndefinedUnitError, AssertionError on "()",
    # tokenizer errors, ZeroDivisionError …); for text from a request each one means
    # "not a unit", never a server error.
    except Exception as exc:
        raise _error(
            "quantity_unit",
            "unknown_unit",
            kind,
            given_unit=match["unit"],
            reason=_pint_reason(exc),
        ) from None
    target = registry.parse_units(kind.unit)
    # Base units, not dimensions: pint counts the radian as dimensionless, so "1/s" has
    # the dimension of "rpm" while its base units (1/s against rad/s) tell them apart.
    if given_base != registry.get_base_units(target)[1]:
        raise _error("quantity_unit", "wrong_kind", kind, given_unit=match["unit"], note=kind.note)
    try:
        value = float(registry.Quantity(number, unit).to(target).magnitude)
    except (ArithmeticError, _pint_error()):  # a factor past the largest float
        value = math.inf
    if not math.isfinite(value):
        raise _error("finite_number", "overflow", kind, text=text)
    return value


def _pint_reason(exc: Exception) -> str:
    reason = str(exc).strip()
    return reason if reason and len(reason) <= 120 else "it cannot be read"


class InUnit:
    """Annotated marker for a ``float`` field in ``kind.unit`` that also takes text with a
    unit (module doc). Put the field's bounds before it, so that they check the value in
    the field's unit and show in its JSON schema:

    ``lead_mm: Annotated[float, Field(gt=0, le=100_000), InUnit(LENGTH_MM)]``
    """

    __slots__ = ("kind",)

    def __init__(self, kind: QuantityKind) -> None:
        self.kind = kind

    def __get_pydantic_core_schema__(
        self, source: Any, handler: GetCoreSchemaHandler
    ) -> CoreSchema:
        kind = self.kind

        def validate(value: Any, inner: Callable[[Any], Any]) -> Any:
            if not isinstance(value, str):
                return inner(value)  # numbers (and everything else) as the float schema says
            converted = to_unit(value, kind)
            try:
                return inner(converted)
            except ValidationError as exc:
                error = exc.errors(include_url=False)[0]
                # The bound's own ctx, and what was given: the message shows the conversion.
                context = {
                    **error.get("ctx", {}),
                    "unit": kind.label,
                    "given": value,
                    "converted": converted,
                }
                message = f"{error['msg']} ({kind.label}): {value!r} is {converted:g} {kind.label}"
                raise PydanticCustomError(
                    error["type"], message.replace("{", "{{").replace("}", "}}"), context
                ) from None

        return core_schema.no_info_wrap_validator_function(validate, handler(source))

    def __get_pydantic_json_schema__(
        self, schema: CoreSchema, handler: GetJsonSchemaHandler
    ) -> JsonSchemaValue:
        number = handler(schema)
        text = {
            "type": "string",
            "maxLength": MAX_QUANTITY_TEXT,
            "description": f"a number and a unit of {kind_words(self.kind)}",
            "examples": [self.kind.example],
        }
        return {"anyOf": [number, text]}

    def __repr__(self) -> str:
        return f"InUnit({self.kind.unit!r})"


def kind_words(kind: QuantityKind) -> str:
    """``kind.kind`` without its article, for a description ("a length" → "length")."""
    return Text(kind.kind.removeprefix("a ").removeprefix("an "))


KIND_WORDS = (
    N_("length"),
    N_("linear speed"),
    N_("rotary speed"),
    N_("mass"),
    N_("moment of inertia"),
    N_("angle"),
    N_("force"),
    N_("torque"),
    N_("time"),
    N_("rotary acceleration"),
    N_("linear acceleration"),
)
"""What the kinds measure, as :func:`kind_words` gives it: marked for the catalogs."""


LENGTH_MM = QuantityKind(unit="mm", label="mm", kind=N_("a length"), example="0.5 in")
LINEAR_SPEED_MM_PER_S = QuantityKind(
    unit="mm/s", label="mm/s", kind=N_("a linear speed"), example="12 in/s"
)
ROTARY_SPEED_RPM = QuantityKind(
    unit="rpm",
    label="rpm",
    kind=N_("a rotary speed"),
    example="2 rad/s",
    note=N_(
        " (an angle per time, e.g. rpm, rev/s, deg/s, rad/s; Hz and 1/s do not say whether "
        "they count revolutions or radians)"
    ),
)
MASS_KG = QuantityKind(unit="kg", label="kg", kind=N_("a mass"), example="22 lb")
INERTIA_KGM2 = QuantityKind(
    unit="kg*m^2", label="kgm²", kind=N_("a moment of inertia"), example="3 lb*in^2"
)
ANGLE_DEG = QuantityKind(
    unit="deg",
    label="°",
    kind=N_("an angle"),
    example="0.5 rad",
    note=N_(" (deg, rad, turn; a bare number in text or % is not an angle)"),
)
FORCE_N = QuantityKind(unit="N", label="N", kind=N_("a force"), example="20 lbf")
TORQUE_NM = QuantityKind(unit="N*m", label="Nm", kind=N_("a torque"), example="10 lbf*ft")
TIME_S = QuantityKind(unit="s", label="s", kind=N_("a time"), example="20 ms")
ROTARY_ACCEL_RPM_PER_S = QuantityKind(
    unit="rpm/s", label="rpm/s", kind=N_("a rotary acceleration"), example="2 rad/s^2"
)
LINEAR_ACCEL_MM_PER_S2 = QuantityKind(
    unit="mm/s^2", label="mm/s²", kind=N_("a linear acceleration"), example="2 m/s^2"
)
