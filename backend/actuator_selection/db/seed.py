"""Loading the catalogue (families, actuators, zones) idempotently and atomically.

Every file is validated before anything is written; one bad cell loads nothing
and the error names file, line and column. Loading the same files again changes
nothing: rows are matched by their natural key (family name, actuator model) and
updated only where a value differs.

Two modes share one code path and one rulebook (the ``CsvSpec`` below):

- **seed** (:func:`load_seed`, the ``seed`` command): adds and updates, never
  retires, so seeding again keeps what an administrator added or retired;
- **import** (:func:`apply_catalogue` with ``replace=True``, the admin API): the
  files are the whole catalogue, so an actuator missing from them is retired
  (soft delete) and a zone missing from them is removed.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from datetime import UTC, datetime
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
    parse,
    parse_rows,
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
        Column(name="name", required=True, max_length=40),
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
        Column(name="model", required=True, max_length=60),
        Column(name="family", required=True, max_length=40),
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
        Column(name="supply_voltage", max_length=40),
        Column(name="feedback", max_length=80),
        Column(name="notes"),
        Column(name="source", required=True),
    ),
)

ZONE_POINTS = CsvSpec(
    file="zone_points.csv",
    key=("actuator_model", "speed_rpm"),
    columns=(
        Column(name="actuator_model", required=True, max_length=60),
        Column(name="speed_rpm", numeric=True, required=True, rule=_N),
        Column(name="torque_nm", numeric=True, required=True, rule=_N),
        Column(name="source", required=True),
    ),
)


CATALOGUE_SPECS = (FAMILIES, ACTUATORS, ZONE_POINTS)
"""The files of a whole catalogue, in loading order."""


@dataclass(frozen=True, slots=True)
class SeedReport:
    """What a seed run wrote."""

    inserted: int
    updated: int
    unchanged: int

    def __str__(self) -> str:
        return f"inserted {self.inserted}, updated {self.updated}, unchanged {self.unchanged}"


@dataclass(slots=True)
class FileChanges:
    """What loading one file did (or, in a dry run, would do) to the stored rows.

    ``retired``: actuators withdrawn (soft delete) for ``actuators.csv``; zone
    points removed for ``zone_points.csv``.
    """

    inserted: int = 0
    updated: int = 0
    unchanged: int = 0
    retired: int = 0

    def count(self, *, is_new: bool, changed: bool, n: int = 1) -> None:
        """Count ``n`` rows as inserted, updated or unchanged."""
        if is_new:
            self.inserted += n
        elif changed:
            self.updated += n
        else:
            self.unchanged += n


@dataclass(slots=True)
class CatalogueChanges:
    """What a catalogue load changed, per file."""

    files: dict[str, FileChanges] = field(
        default_factory=lambda: {spec.file: FileChanges() for spec in CATALOGUE_SPECS}
    )

    @property
    def changed(self) -> bool:
        """True when anything was inserted, updated or retired."""
        return any(c.inserted or c.updated or c.retired for c in self.files.values())


@dataclass(frozen=True, slots=True, kw_only=True)
class CatalogueFiles:
    """The validated rows of a whole catalogue."""

    families: list[Record]
    actuators: list[Record]
    zone_points: list[Record]


def zone_problems(
    model: str, points: Sequence[tuple[float, int]], *, file: str = ZONE_POINTS.file
) -> list[Problem]:
    """Problems of one actuator's zone, given as (speed_rpm, line) pairs.

    The zone's edge needs at least two points, one of them at 0 rpm (the
    continuous stall torque, Fig. 517.1), and distinct speeds.
    """
    problems: list[Problem] = []
    first_line = min(line for _, line in points) if points else 0
    seen: dict[float, int] = {}
    for speed, line in points:
        if speed in seen:
            problems.append(
                Problem(
                    file=file,
                    line=line,
                    column="speed_rpm",
                    message=f"duplicates line {seen[speed]} ({model}, {speed:g} rpm)",
                )
            )
        seen.setdefault(speed, line)
    if len(points) < 2 or 0 not in seen:
        problems.append(
            Problem(
                file=file,
                line=first_line,
                column="speed_rpm",
                message=f"the zone of {model} needs at least two points, one of them at 0 rpm",
            )
        )
    return problems


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
    per_model: dict[str, list[tuple[float, int]]] = {}
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
        per_model.setdefault(model, []).append((r.values["speed_rpm"], r.line))
    for model, points in per_model.items():
        # Duplicates were already reported by the file's key check.
        problems.extend(p for p in zone_problems(model, points) if "duplicates" not in p.message)
    return problems


def _checked(files: CatalogueFiles, problems: list[Problem]) -> CatalogueFiles:
    if not problems:
        problems = _cross_check(files.families, files.actuators, files.zone_points)
    if problems:
        raise CatalogueFileError(problems)
    return files


def read_catalogue(directory: Path) -> CatalogueFiles:
    """Validate the catalogue files in ``directory``; :class:`CatalogueFileError` lists problems."""
    families, p1 = read(FAMILIES, directory)
    actuators, p2 = read(ACTUATORS, directory)
    zones, p3 = read(ZONE_POINTS, directory)
    files = CatalogueFiles(families=families, actuators=actuators, zone_points=zones)
    return _checked(files, p1 + p2 + p3)


def parse_catalogue(texts: Mapping[str, str | None]) -> CatalogueFiles:
    """Validate the catalogue files given as text by file name (None: the file is missing)."""
    problems: list[Problem] = []
    parsed: list[list[Record]] = []
    for spec in CATALOGUE_SPECS:
        text = texts.get(spec.file)
        if text is None:
            problems.append(Problem(file=spec.file, line=0, column=None, message="file missing"))
            parsed.append([])
            continue
        records, file_problems = parse(spec, text)
        parsed.append(records)
        problems.extend(file_problems)
    for name in texts:
        if name not in {spec.file for spec in CATALOGUE_SPECS}:
            problems.append(
                Problem(
                    file=name,
                    line=0,
                    column=None,
                    message="unknown file (expected: "
                    f"{', '.join(spec.file for spec in CATALOGUE_SPECS)})",
                )
            )
    families, actuators, zones = parsed
    files = CatalogueFiles(families=families, actuators=actuators, zone_points=zones)
    return _checked(files, problems)


JSON_KEYS = {
    FAMILIES.file: "families",
    ACTUATORS.file: "actuators",
    ZONE_POINTS.file: "zone_points",
}
"""The key of each file's rows in the JSON form of a catalogue."""


def catalogue_from_json(body: Mapping[str, object]) -> CatalogueFiles:
    """Validate a catalogue given as ``{"families": [...], "actuators": [...], "zone_points":
    [...]}`` of objects keyed by the CSV column names; problems name the array and its index.
    """
    problems: list[Problem] = []
    parsed: list[list[Record]] = []
    for spec in CATALOGUE_SPECS:
        key = JSON_KEYS[spec.file]
        rows = body.get(key)
        if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
            problems.append(
                Problem(file=key, line=0, column=None, message="must be an array of objects")
            )
            parsed.append([])
            continue
        records, row_problems = parse_rows(spec, rows)
        parsed.append(records)
        problems.extend(replace(p, file=key) for p in row_problems)
    problems.extend(
        Problem(
            file=name,
            line=0,
            column=None,
            message=f"unknown key (expected: {', '.join(JSON_KEYS.values())})",
        )
        for name in body
        if name not in JSON_KEYS.values()
    )
    families, actuators, zones = parsed
    files = CatalogueFiles(families=families, actuators=actuators, zone_points=zones)
    try:
        return _checked(files, problems)
    except CatalogueFileError as exc:
        raise CatalogueFileError(
            [replace(p, file=JSON_KEYS.get(p.file, p.file)) for p in exc.problems]
        ) from None


def _apply(row: Any, values: dict[str, Any]) -> bool:
    """Set ``values`` on ``row``; True when anything changed."""
    changed = False
    for name, value in values.items():
        if getattr(row, name) != value:
            setattr(row, name, value)
            changed = True
    return changed


def apply_catalogue(
    session: Session, files: CatalogueFiles, *, replace: bool, now: datetime | None = None
) -> CatalogueChanges:
    """Upsert validated catalogue files (the caller commits); raises the version on change.

    With ``replace`` the files are the whole catalogue: actuators they lack are
    retired (and those they hold are brought back), zones they lack are removed.
    Without it, nothing is retired or brought back and absent zones stay.
    """
    now = now or datetime.now(UTC)
    changes = CatalogueChanges()
    fam, act, zon = (changes.files[spec.file] for spec in CATALOGUE_SPECS)

    family_rows = {f.name: f for f in session.scalars(select(ActuatorFamilyRow))}
    for r in files.families:
        family = family_rows.get(r.values["name"])
        is_new = family is None
        if family is None:
            family = ActuatorFamilyRow()
            session.add(family)
            family_rows[r.values["name"]] = family
        fam.count(is_new=is_new, changed=_apply(family, r.values))
    session.flush()

    actuator_rows = {a.model: a for a in session.scalars(select(ActuatorRow))}
    for r in files.actuators:
        values = dict(r.values)
        values["family_id"] = family_rows[values.pop("family")].id
        if replace:
            values["retired_at"] = None
        actuator = actuator_rows.get(values["model"])
        is_new = actuator is None
        if actuator is None:
            actuator = ActuatorRow()
            session.add(actuator)
            actuator_rows[values["model"]] = actuator
        act.count(is_new=is_new, changed=_apply(actuator, values))
    if replace:
        listed = {r.values["model"] for r in files.actuators}
        for model, actuator in actuator_rows.items():
            if model not in listed and actuator.retired_at is None:
                actuator.retired_at = now
                act.retired += 1
    session.flush()

    wanted: dict[str, list[tuple[float, float, str]]] = {}
    for r in files.zone_points:
        v = r.values
        wanted.setdefault(v["actuator_model"], []).append(
            (v["speed_rpm"], v["torque_nm"], v["source"])
        )
    if replace:
        for r in files.actuators:
            wanted.setdefault(r.values["model"], [])
    for model, points in wanted.items():
        actuator = actuator_rows[model]
        have = sorted((p.speed_rpm, p.torque_nm, p.source) for p in actuator.zone_points)
        if have == sorted(points):
            zon.unchanged += len(points)
            continue
        # Delete before insert: the unit of work would insert first and trip the
        # (actuator, speed) unique constraint.
        actuator.zone_points.clear()
        session.flush()
        actuator.zone_points.extend(
            ZonePointRow(speed_rpm=s, torque_nm=t, source=src) for s, t, src in sorted(points)
        )
        if not points:
            zon.retired += len(have)
        elif have:
            zon.updated += len(points)
        else:
            zon.inserted += len(points)
    session.flush()
    if changes.changed:
        CatalogueVersionRepository(session).bump()
    return changes


def load_seed(session: Session, directory: Path) -> SeedReport:
    """Validate every file in ``directory``, then upsert them (the caller commits).

    Never retires an actuator: seeding again keeps what was added or retired since.

    Raises
    ------
    CatalogueFileError
        Listing every bad header, row and cell; nothing has been written then.
    """
    changes = apply_catalogue(session, read_catalogue(directory), replace=False)
    files = changes.files.values()
    return SeedReport(
        inserted=sum(c.inserted for c in files),
        updated=sum(c.updated for c in files),
        unchanged=sum(c.unchanged for c in files),
    )
