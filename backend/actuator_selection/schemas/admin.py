"""Catalogue management: zone writes and what an import changed.

Actuators and controllers are written as JSON objects keyed by the columns of
``actuators.csv`` and ``controllers.csv`` (units in the names, e.g.
``max_torque_nm``); they are validated by the seed files' own rules, not by a
second schema, so their body is a free-form object here, documented by a
schema derived from those rules.
"""

from __future__ import annotations

from typing import Any

from pydantic import ConfigDict, Field

from actuator_selection.catalogue.changes import CatalogueChanges
from actuator_selection.catalogue.csvio import WHOLE_NUMBER_MAX, CsvSpec, whole_number
from actuator_selection.catalogue.files import OPTION_COLUMNS, mark
from actuator_selection.schemas.common import ResponseModel, StrictModel
from actuator_selection.schemas.prices import ChangesOut


def write_json_schema(
    spec: CsvSpec, *, optional: tuple[str, ...] = (), without: tuple[str, ...] = ()
) -> dict[str, Any]:
    """OpenAPI schema of a row write, derived from the columns of ``spec``'s file.

    ``optional``: required columns the endpoint fills in when they are left out;
    ``without``: columns the path gives instead.
    """
    properties: dict[str, Any] = {}
    columns = [c for c in spec.columns if c.name not in without]
    for column in columns:
        described = f"as the column {column.name} of {spec.file}"
        if column.numeric:
            kind: dict[str, Any] = {"type": "number"}
            described += f"; must be {column.rule.value}"
        elif column.convert is whole_number:
            kind = {"type": "integer", "minimum": 1, "maximum": WHOLE_NUMBER_MAX}
        elif column.convert is mark:
            kind = {"enum": ["tested", "possible", "●", "○", ""]}
        elif column.name in OPTION_COLUMNS:
            text = {"type": "string", "description": "space-separated names"}
            kind = {"anyOf": [text, {"type": "array", "items": {"type": "string"}}]}
        else:
            kind = {"type": "string"}
            if column.max_length is not None:
                kind["maxLength"] = column.max_length
            if column.pattern is not None:
                kind["pattern"] = f"^{column.pattern.regex.pattern}$"
        nullable = not column.required or column.name in optional
        properties[column.name] = (
            {"anyOf": [kind, {"type": "null"}], "description": described}
            if nullable
            else {**kind, "description": described}
        )
    return {
        "type": "object",
        "properties": properties,
        "required": [c.name for c in columns if c.required and c.name not in optional],
        "additionalProperties": False,
    }


class ZonePointIn(StrictModel):
    """A corner of the continuous-duty zone's upper edge; checked by zone_points.csv's rules."""

    speed_rpm: Any = Field(description="n [rpm], ≥ 0")
    torque_nm: Any = Field(description="T [Nm], ≥ 0")


class ZoneIn(StrictModel):
    """A whole zone edge (Fig. 517.1): at least two points, one of them at 0 rpm."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "points": [
                        {"speed_rpm": 0, "torque_nm": 60},
                        {"speed_rpm": 90, "torque_nm": 40},
                    ],
                    "source": "read from Fig. 517.1",
                }
            ]
        }
    )

    # As the free-text source column of zone_points.csv, which it is stored in.
    line_break_fields = frozenset({"source"})

    points: list[ZonePointIn] = Field(max_length=1000)
    source: Any = Field(description="where the zone was read from (required)")


class CatalogueImportOut(ResponseModel):
    """What a catalogue import changed (``dry_run``: would change; nothing was written)."""

    dry_run: bool
    catalogue_version: int = Field(description="the version after the import (unchanged if dry)")
    files: dict[str, ChangesOut] = Field(
        description="per file; `retired`: actuators and controllers withdrawn (soft delete, "
        "actuators.csv and controllers.csv), other rows removed"
    )

    @classmethod
    def build(cls, changes: CatalogueChanges, *, dry_run: bool, version: int) -> CatalogueImportOut:
        """The response body of an import."""
        return cls(
            dry_run=dry_run,
            catalogue_version=version,
            files={name: ChangesOut.from_changes(c) for name, c in changes.files.items()},
        )
