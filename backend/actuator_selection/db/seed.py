"""Loading the starter catalogue from ``seed_data/`` idempotently and atomically.

Every file is validated before anything is written; one bad cell loads nothing
and the error names file, line and column. Loading the same files again changes
nothing: rows are matched by their natural key (family name, actuator model) and
updated only where a value differs.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from actuator_selection.db.csvio import (
    CatalogueFileError,
    Column,
    CsvSpec,
    Problem,
    Record,
    Rule,
    read,
)
from actuator_selection.db.models import ActuatorFamilyRow, ActuatorRow, ZonePointRow
from actuator_selection.db.repositories import CatalogueVersionRepository

_P, _N = Rule.POSITIVE, Rule.NON_NEGATIVE
MILLI = 1e-3

FAMILIES = CsvSpec(
    file="families.csv",
    key=("name",),
    columns=(
        Column(name="name", required=True),
        Column(name="description"),
        Column(name="temperature_sensors"),
        Column(name="warning_temperature_c", numeric=True),
        Column(name="shutdown_temperature_c", numeric=True),
        Column(name="temperature_tolerance_percent", numeric=True, rule=_N),
        Column(name="warning_resistance_ohm", numeric=True, rule=_P),
        Column(name="shutdown_resistance_ohm", numeric=True, rule=_P),
        Column(name="resistance_tolerance_percent", numeric=True, rule=_N),
        Column(name="source", required=True),
    ),
)

ACTUATORS = CsvSpec(
    file="actuators.csv",
    key=("model",),
    columns=(
        Column(name="model", required=True),
        Column(name="family", required=True),
        Column(name="gear_ratio", numeric=True, required=True, rule=_P),
        Column(name="max_torque_nm", numeric=True, rule=_P),
        Column(name="max_speed_rpm", numeric=True, rule=_P),
        Column(name="inertia_kgm2", numeric=True, rule=_P),
        Column(name="stall_torque_nm", numeric=True, rule=_P),
        Column(name="continuous_torque_nm", numeric=True, rule=_P),
        Column(name="max_current_a", numeric=True, rule=_P),
        Column(name="stall_current_a", numeric=True, rule=_P),
        Column(name="continuous_current_a", numeric=True, rule=_P),
        Column(name="torque_constant_nm_per_a", numeric=True, rule=_P),
        Column(name="motor_torque_constant_nm_per_a", numeric=True, rule=_P),
        Column(name="motor_voltage_constant_v_per_krpm", numeric=True, rule=_P),
        Column(name="output_voltage_constant_v_per_rpm", numeric=True, rule=_P),
        Column(name="resistance_line_ohm", numeric=True, rule=_P),
        Column(name="resistance_phase_ohm", numeric=True, rule=_P),
        Column(name="inductance_line_mh", numeric=True, rule=_P),
        Column(name="inductance_phase_mh", numeric=True, rule=_P),
        Column(name="no_load_starting_current_a", numeric=True, rule=_N),
        Column(
            name="no_load_current_constant_30c_ma_per_rpm",
            numeric=True,
            rule=_N,
            scale=MILLI,
            target="no_load_current_constant_30c_a_per_rpm",
        ),
        Column(
            name="no_load_current_constant_80c_ma_per_rpm",
            numeric=True,
            rule=_N,
            scale=MILLI,
            target="no_load_current_constant_80c_a_per_rpm",
        ),
        Column(name="thermal_time_constant_s", numeric=True, rule=_P),
        Column(name="mass_kg", numeric=True, rule=_P),
        Column(name="max_dc_bus_voltage_v", numeric=True, rule=_P),
        Column(name="supply_voltage"),
        Column(name="feedback"),
        Column(name="notes"),
        Column(name="source", required=True),
    ),
)

ZONE_POINTS = CsvSpec(
    file="zone_points.csv",
    key=("actuator_model", "speed_rpm"),
    columns=(
        Column(name="actuator_model", required=True),
        Column(name="speed_rpm", numeric=True, required=True, rule=_N),
        Column(name="torque_nm", numeric=True, required=True, rule=_N),
        Column(name="source", required=True),
    ),
)


@dataclass(frozen=True, slots=True)
class SeedReport:
    """What a seed run wrote."""

    inserted: int
    updated: int
    unchanged: int

    def __str__(self) -> str:
        return f"inserted {self.inserted}, updated {self.updated}, unchanged {self.unchanged}"


def _cross_check(
    families: list[Record], actuators: list[Record], zones: list[Record]
) -> list[Problem]:
    """Problems that need more than one file: unknown families and models, bad zones."""
    problems: list[Problem] = []
    family_names = {r.values["name"] for r in families}
    models = {r.values["model"] for r in actuators}
    for r in actuators:
        if r.values["family"] not in family_names:
            problems.append(
                Problem(
                    file=ACTUATORS.file,
                    line=r.line,
                    column="family",
                    message=f"unknown family {r.values['family']!r} (known: "
                    f"{', '.join(sorted(family_names))})",
                )
            )
    starts: dict[str, bool] = {}
    counts: dict[str, int] = {}
    first_line: dict[str, int] = {}
    for r in zones:
        model = r.values["actuator_model"]
        if model not in models:
            problems.append(
                Problem(
                    file=ZONE_POINTS.file,
                    line=r.line,
                    column="actuator_model",
                    message=f"unknown actuator model {model!r}",
                )
            )
        counts[model] = counts.get(model, 0) + 1
        first_line.setdefault(model, r.line)
        starts[model] = starts.get(model, False) or r.values["speed_rpm"] == 0
    for model, count in counts.items():
        if count < 2 or not starts[model]:
            problems.append(
                Problem(
                    file=ZONE_POINTS.file,
                    line=first_line[model],
                    column="speed_rpm",
                    message=f"the zone of {model} needs at least two points, one of them at 0 rpm",
                )
            )
    return problems


def _apply(row: Any, values: dict[str, Any]) -> bool:
    """Set ``values`` on ``row``; True when anything changed."""
    changed = False
    for name, value in values.items():
        if getattr(row, name) != value:
            setattr(row, name, value)
            changed = True
    return changed


def load_seed(session: Session, directory: Path) -> SeedReport:
    """Validate every file in ``directory``, then upsert them (the caller commits).

    Raises
    ------
    CatalogueFileError
        Listing every bad header, row and cell; nothing has been written then.
    """
    families, p1 = read(FAMILIES, directory)
    actuators, p2 = read(ACTUATORS, directory)
    zones, p3 = read(ZONE_POINTS, directory)
    problems = p1 + p2 + p3
    if not problems:
        problems = _cross_check(families, actuators, zones)
    if problems:
        raise CatalogueFileError(problems)

    inserted = updated = unchanged = 0

    def count(is_new: bool, changed: bool) -> None:
        nonlocal inserted, updated, unchanged
        if is_new:
            inserted += 1
        elif changed:
            updated += 1
        else:
            unchanged += 1

    family_rows = {f.name: f for f in session.scalars(select(ActuatorFamilyRow))}
    for r in families:
        family = family_rows.get(r.values["name"])
        is_new = family is None
        if family is None:
            family = ActuatorFamilyRow()
            session.add(family)
            family_rows[r.values["name"]] = family
        count(is_new, _apply(family, r.values))
    session.flush()

    actuator_rows = {a.model: a for a in session.scalars(select(ActuatorRow))}
    for r in actuators:
        values = dict(r.values)
        values["family_id"] = family_rows[values.pop("family")].id
        actuator = actuator_rows.get(values["model"])
        is_new = actuator is None
        if actuator is None:
            actuator = ActuatorRow()
            session.add(actuator)
            actuator_rows[values["model"]] = actuator
        count(is_new, _apply(actuator, values))
    session.flush()

    wanted: dict[str, list[tuple[float, float, str]]] = {}
    for r in zones:
        v = r.values
        wanted.setdefault(v["actuator_model"], []).append(
            (v["speed_rpm"], v["torque_nm"], v["source"])
        )
    for model, points in wanted.items():
        actuator = actuator_rows[model]
        have = sorted((p.speed_rpm, p.torque_nm, p.source) for p in actuator.zone_points)
        if have == sorted(points):
            unchanged += len(points)
            continue
        # Delete before insert: the unit of work would insert first and trip the
        # (actuator, speed) unique constraint.
        actuator.zone_points.clear()
        session.flush()
        actuator.zone_points.extend(
            ZonePointRow(speed_rpm=s, torque_nm=t, source=src) for s, t, src in sorted(points)
        )
        if have:
            updated += len(points)
        else:
            inserted += len(points)
    session.flush()
    if inserted or updated:
        CatalogueVersionRepository(session).bump()
    return SeedReport(inserted=inserted, updated=updated, unchanged=unchanged)
