"""Catalogue management: zone writes and what an import changed.

Actuators are written as JSON objects keyed by the columns of ``actuators.csv``
(units in the names, e.g. ``max_torque_nm``); they are validated by the seed
files' own rules, not by a second schema, so their body is a free-form object here.
"""

from __future__ import annotations

from typing import Any

from pydantic import Field

from actuator_selection.db.seed import ACTUATORS, CatalogueChanges
from actuator_selection.schemas.common import ResponseModel, StrictModel
from actuator_selection.schemas.prices import ChangesOut


def actuator_json_schema() -> dict[str, Any]:
    """OpenAPI schema of an actuator write, derived from the ``actuators.csv`` columns."""
    properties: dict[str, Any] = {}
    for column in ACTUATORS.columns:
        kind = "number" if column.numeric else "string"
        properties[column.name] = {
            "type": kind if column.required else [kind, "null"],
            "description": f"as the column {column.name} of actuators.csv"
            + (f"; must be {column.rule.value}" if column.numeric else ""),
        }
    return {
        "type": "object",
        "properties": properties,
        "required": [c.name for c in ACTUATORS.columns if c.required],
        "additionalProperties": False,
    }


class ZonePointIn(StrictModel):
    """A corner of the continuous-duty zone's upper edge; checked by zone_points.csv's rules."""

    speed_rpm: Any = Field(description="n [rpm], ≥ 0")
    torque_nm: Any = Field(description="T [Nm], ≥ 0")


class ZoneIn(StrictModel):
    """A whole zone edge (Fig. 517.1): at least two points, one of them at 0 rpm."""

    points: list[ZonePointIn] = Field(max_length=1000)
    source: Any = Field(description="where the zone was read from (required)")


class CatalogueImportOut(ResponseModel):
    """What a catalogue import changed (``dry_run``: would change; nothing was written)."""

    dry_run: bool
    catalogue_version: int = Field(description="the version after the import (unchanged if dry)")
    files: dict[str, ChangesOut] = Field(
        description="per file; `retired`: actuators withdrawn (actuators.csv) or zone points "
        "removed (zone_points.csv)"
    )

    @classmethod
    def build(cls, changes: CatalogueChanges, *, dry_run: bool, version: int) -> CatalogueImportOut:
        """The response body of an import."""
        return cls(
            dry_run=dry_run,
            catalogue_version=version,
            files={name: ChangesOut.from_changes(c) for name, c in changes.files.items()},
        )
