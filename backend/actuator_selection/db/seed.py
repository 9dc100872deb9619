"""Loading the whole catalogue idempotently and atomically.

The catalogue is the files of
:data:`~actuator_selection.catalogue.files.CATALOGUE_SPECS`: families, actuators and
their zones (this module), and Table 521.1's controllers, sensor data, bus
classes and actuator interfaces (:mod:`actuator_selection.db.seed_controllers`).
Every file is validated before anything is written; one bad cell loads nothing
and the error names file, line and column. Loading the same files again changes
nothing: rows are matched by their natural key (family name, actuator model,
controller row, ...) and updated only where a value differs. The catalogue
version rises once per load that changed anything.

Two modes share one code path and one rulebook (the ``CsvSpec`` of each file,
:mod:`actuator_selection.catalogue.files`):

- **seed** (:func:`load_seed`, the ``seed`` command): adds and updates, never
  retires, so seeding again keeps what an administrator added or retired;
- **import** (:func:`apply_catalogue` with ``replace=True``, the admin API): the
  files are the whole catalogue, so an actuator or controller missing from them
  is retired (soft delete) and other rows missing from them are removed.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass, replace
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, cast

from sqlalchemy import Table, delete, insert, select
from sqlalchemy.orm import Session

from actuator_selection.catalogue.changes import CatalogueChanges, FileChanges
from actuator_selection.catalogue.csvio import (
    CatalogueFileError,
    CsvSpec,
    Problem,
    Record,
    parse,
    parse_rows,
    read,
)
from actuator_selection.catalogue.files import (
    ACTUATORS,
    CATALOGUE_SPECS,
    FAMILIES,
    JSON_KEYS,
    ZONE_POINTS,
)
from actuator_selection.db.changes import batches, retire_at, sync_rows
from actuator_selection.db.models import ActuatorFamilyRow, ActuatorRow, ZonePointRow
from actuator_selection.db.repositories import CatalogueVersionRepository, mark_changed
from actuator_selection.db.seed_controllers import apply_protection, protection_problems


@dataclass(frozen=True, slots=True)
class SeedReport:
    """What a seed run wrote."""

    inserted: int
    updated: int
    unchanged: int

    def __str__(self) -> str:
        return f"inserted {self.inserted}, updated {self.updated}, unchanged {self.unchanged}"


@dataclass(frozen=True, slots=True)
class CatalogueFiles:
    """The validated rows of a whole catalogue, by file name (every file of CATALOGUE_SPECS)."""

    rows: Mapping[str, list[Record]]

    def __getitem__(self, spec: CsvSpec) -> list[Record]:
        return self.rows[spec.file]


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


def _cross_check(files: CatalogueFiles) -> list[Problem]:
    """Problems that need more than one file: unknown families and models, bad zones, ..."""
    problems: list[Problem] = []
    family_names = {r.values["name"] for r in files[FAMILIES]}
    models = {r.values["model"] for r in files[ACTUATORS]}
    for r in files[ACTUATORS]:
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
    for r in files[ZONE_POINTS]:
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
    problems.extend(protection_problems(files.rows, families=family_names, models=models))
    return problems


def _checked(rows: dict[str, list[Record]], problems: list[Problem]) -> CatalogueFiles:
    files = CatalogueFiles(rows)
    if not problems:
        problems = _cross_check(files)
    if problems:
        raise CatalogueFileError(problems)
    return files


def read_catalogue(directory: Path) -> CatalogueFiles:
    """Validate the catalogue files in ``directory``; :class:`CatalogueFileError` lists problems."""
    rows: dict[str, list[Record]] = {}
    problems: list[Problem] = []
    for spec in CATALOGUE_SPECS:
        rows[spec.file], found = read(spec, directory)
        problems.extend(found)
    return _checked(rows, problems)


def parse_catalogue(texts: Mapping[str, str | Iterable[str] | None]) -> CatalogueFiles:
    """Validate the catalogue files given as text, or streams of their lines, by file name
    (None: the file is missing); each is read row by row (:func:`~.csvio.parse`)."""
    rows: dict[str, list[Record]] = {}
    problems: list[Problem] = []
    for spec in CATALOGUE_SPECS:
        text = texts.get(spec.file)
        if text is None:
            problems.append(Problem(file=spec.file, line=0, column=None, message="file missing"))
            rows[spec.file] = []
            continue
        rows[spec.file], found = parse(spec, text)
        problems.extend(found)
    problems.extend(
        Problem(
            file=name,
            line=0,
            column=None,
            message=f"unknown file (expected: {', '.join(spec.file for spec in CATALOGUE_SPECS)})",
        )
        for name in texts
        if name not in JSON_KEYS
    )
    return _checked(rows, problems)


def catalogue_from_json(body: Mapping[str, object]) -> CatalogueFiles:
    """Validate a catalogue given as ``{"families": [...], "actuators": [...], ...}`` (one
    array per file, keyed by its stem, of objects keyed by the CSV column names); problems
    name the array and its index.
    """
    rows: dict[str, list[Record]] = {}
    problems: list[Problem] = []
    for spec in CATALOGUE_SPECS:
        key = JSON_KEYS[spec.file]
        given = body.get(key)
        if not isinstance(given, list) or not all(isinstance(r, dict) for r in given):
            problems.append(
                Problem(file=key, line=0, column=None, message="must be an array of objects")
            )
            rows[spec.file] = []
            continue
        rows[spec.file], found = parse_rows(spec, given)
        problems.extend(replace(p, file=key) for p in found)
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
    try:
        return _checked(rows, problems)
    except CatalogueFileError as exc:
        raise CatalogueFileError(
            [replace(p, file=JSON_KEYS.get(p.file, p.file)) for p in exc.problems]
        ) from None


def apply_catalogue(
    session: Session, files: CatalogueFiles, *, replace: bool, now: datetime | None = None
) -> CatalogueChanges:
    """Upsert validated catalogue files (the caller commits); raises the version once on change.

    With ``replace`` the files are the whole catalogue: actuators and
    controllers they lack are retired (and those they hold are brought back);
    zones, sensor data, bus classes and interfaces they lack are removed (see
    :func:`~actuator_selection.db.seed_controllers.apply_protection`). Without
    it, nothing is retired, brought back or removed.
    """
    now = now or datetime.now(UTC)
    changes = CatalogueChanges()

    sync_rows(
        session,
        ActuatorFamilyRow,
        ("name",),
        [dict(r.values) for r in files[FAMILIES]],
        changes.files[FAMILIES.file],
    )
    family_ids = {f.name: f.id for f in session.scalars(select(ActuatorFamilyRow))}

    def actuator(values: dict[str, Any]) -> dict[str, Any]:
        values["family_id"] = family_ids[values.pop("family")]
        if replace:
            values["retired_at"] = None
        return values

    sync_rows(
        session,
        ActuatorRow,
        ("model",),
        (actuator(dict(r.values)) for r in files[ACTUATORS]),
        changes.files[ACTUATORS.file],
        withdraw=retire_at(now) if replace else None,
    )
    _apply_zones(session, files, changes.files[ZONE_POINTS.file], replace=replace)
    apply_protection(
        session,
        files.rows,
        changes.files,
        replace=replace,
        now=now,
        listed_models=[r.values["model"] for r in files[ACTUATORS]],
    )
    if changes.changed:
        CatalogueVersionRepository(session).bump()
    return changes


def _apply_zones(
    session: Session, files: CatalogueFiles, zon: FileChanges, *, replace: bool
) -> None:
    """Replace the zone of every actuator the zone file names (with ``replace``: that the
    actuator file lists, so a listed actuator without points loses its zone)."""
    wanted: dict[str, list[tuple[float, float, str]]] = {}
    for r in files[ZONE_POINTS]:
        v = r.values
        wanted.setdefault(v["actuator_model"], []).append(
            (v["speed_rpm"], v["torque_nm"], v["source"])
        )
    if replace:
        for r in files[ACTUATORS]:
            wanted.setdefault(r.values["model"], [])
    # Plain rows and batched statements, no ORM object per actuator or point (64,000
    # actuators import in one request).
    points = cast(Table, ZonePointRow.__table__)
    ids = dict(session.execute(select(ActuatorRow.model, ActuatorRow.id)).all())
    have: dict[int, list[tuple[float, float, str]]] = {}
    for actuator_id, speed, torque, source in session.execute(
        select(points.c.actuator_id, points.c.speed_rpm, points.c.torque_nm, points.c.source)
    ):
        have.setdefault(actuator_id, []).append((speed, torque, source))
    emptied: list[int] = []
    inserts: list[dict[str, Any]] = []
    changed: list[int] = []
    for model, given in wanted.items():
        actuator_id = ids[model]
        old = sorted(have.get(actuator_id, []))
        new = sorted(given)
        if old == new:
            zon.unchanged += len(new)
            continue
        changed.append(actuator_id)
        if old:
            emptied.append(actuator_id)
        inserts.extend(
            {"actuator_id": actuator_id, "speed_rpm": s, "torque_nm": t, "source": src}
            for s, t, src in new
        )
        if not new:
            zon.retired += len(old)
        elif old:
            zon.updated += len(new)
        else:
            zon.inserted += len(new)
    # Delete before insert: the (actuator, speed) unique constraint.
    for batch in batches(emptied):
        session.execute(delete(points).where(points.c.actuator_id.in_(batch)))
    for batch in batches(inserts):
        session.execute(insert(points), batch)
    mark_changed(session, changed)
    session.flush()


def load_seed(session: Session, directory: Path) -> SeedReport:
    """Validate every file in ``directory``, then upsert them (the caller commits).

    Never retires or removes anything: seeding again keeps what was added or
    retired since.

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
