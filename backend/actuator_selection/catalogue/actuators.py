"""What the core knows of one catalogue actuator.

:class:`Actuator` is generated from the field registry
(:data:`~actuator_selection.catalogue.fields.ENGINE_FIELDS`): one attribute per
value the engine's checks read, named and typed as declared there, plus the values
derived from other files (:data:`~actuator_selection.catalogue.fields.
DERIVED_ACTUATOR_ATTRIBUTES`). Adding a catalogue value is its declaration; this module
does not change. Every value that a public source does not give is ``None``; the
calculations that need it say "no data" instead of guessing.
"""

from __future__ import annotations

import dataclasses
from typing import TYPE_CHECKING, Any, ClassVar

from actuator_selection.catalogue.fields import ENGINE_FIELDS, CatalogueField, Kind
from actuator_selection.catalogue.zones import ContinuousDutyZone

_DOC = """A servo actuator as the catalogue publishes it, values at the output shaft.

Its attributes are the registry's ``engine=True`` fields (name, unit and meaning in
:mod:`actuator_selection.catalogue.fields`), keyword-only, ``None`` where not
published except the required ones (``model``, ``family``, ``gear_ratio``); a text value
is also read by :meth:`text` (``a.text("output_bearing_type")``), typed. And:

zone
    Continuous-duty zone of the speed/torque diagram, where published.
dc_bus_voltage_v
    The highest nominal DC bus voltage among the Table 521.1 bus classes the actuator
    runs on [V]; derived from its interface by the catalogue snapshot, None where no
    bus class is published.
"""


def _attribute(field: CatalogueField) -> tuple[str, Any, Any]:
    """One declared value as a dataclass field: (name, type, default)."""
    kind: Any = float if field.kind is Kind.NUMBER else str
    if field.required:
        return (field.name, kind, dataclasses.field())
    return (field.name, kind | None, dataclasses.field(default=None))


def _text(self: Any, name: str) -> str | None:
    """A text value by its field name (``output_bearing_type``); None where not published."""
    value = getattr(self, name)
    assert value is None or isinstance(value, str), name
    return value


if TYPE_CHECKING:  # what mypy sees: the required values typed, a number by its name

    class Actuator:
        """A servo actuator as the catalogue publishes it (generated: see below)."""

        __dataclass_fields__: ClassVar[dict[str, dataclasses.Field[Any]]]
        model: str
        family: str
        gear_ratio: float
        zone: ContinuousDutyZone | None
        dc_bus_voltage_v: float | None

        def __init__(
            self,
            *,
            model: str,
            family: str,
            gear_ratio: float,
            zone: ContinuousDutyZone | None = None,
            dc_bus_voltage_v: float | None = None,
            **values: float | str | None,
        ) -> None: ...

        def __getattr__(self, name: str) -> float | None:
            """A number by its field name (``a.max_torque_nm``); None where not published."""

        def text(self, name: str) -> str | None:
            """A text value by its field name (``output_bearing_type``)."""

else:
    Actuator = dataclasses.make_dataclass(
        "Actuator",
        [
            *(_attribute(f) for f in ENGINE_FIELDS),
            ("zone", ContinuousDutyZone | None, dataclasses.field(default=None)),
            ("dc_bus_voltage_v", float | None, dataclasses.field(default=None)),
        ],
        namespace={"__doc__": _DOC, "__module__": __name__, "text": _text},
        frozen=True,
        slots=True,
        kw_only=True,
    )
