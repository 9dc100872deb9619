"""All SQL of the service. Repositories flush at most; the request's session commits.

They hand out core dataclasses, never ORM rows, so the engineering does not learn
where its numbers came from.
"""

from __future__ import annotations

import functools
from collections.abc import Collection, Sequence
from dataclasses import asdict, dataclass, fields
from datetime import UTC, datetime
from types import MappingProxyType
from typing import Any, cast

from sqlalchemy import Insert, Table, bindparam, func, insert, select, update
from sqlalchemy.orm import Session, selectinload

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.fields import ACTUATOR_FIELDS, ENGINE_FIELDS
from actuator_selection.catalogue.records import ActuatorRecord, FamilyRecord
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.db.changes import batches
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorRow,
    CatalogueStateRow,
    ProfileRow,
    SelectionRow,
    ZonePointRow,
)


@dataclass(frozen=True, slots=True, kw_only=True)
class ActuatorFilter:
    """Catalogue query: every given criterion must hold."""

    family: str | None = None
    min_max_torque_nm: float | None = None
    max_inertia_kgm2: float | None = None
    min_max_speed_rpm: float | None = None
    models: Sequence[str] | None = None
    max_max_torque_nm: float | None = None
    min_continuous_torque_nm: float | None = None
    gear_ratio: float | None = None
    after_model: str | None = None
    """Only models after this one (by name): the next page of a list."""
    limit: int | None = None
    """At most this many (the first by model name)."""


def _to_record(row: ActuatorRow) -> ActuatorRecord:
    """The record of a row: every declared value under its name, the engine's among them."""
    values: dict[str, Any] = {
        f.name: row.family.name if f.name == "family" else getattr(row, f.name)
        for f in ACTUATOR_FIELDS
    }
    zone = (
        ContinuousDutyZone(
            points=tuple(
                ZonePoint(speed_rpm=p.speed_rpm, torque_nm=p.torque_nm) for p in row.zone_points
            )
        )
        if row.zone_points
        else None
    )
    return ActuatorRecord(
        actuator=Actuator(zone=zone, **{f.name: values[f.name] for f in ENGINE_FIELDS}),
        values=MappingProxyType(values),
        zone_source="; ".join(sorted({p.source for p in row.zone_points})) or None,
    )


_VALUES = ActuatorRow.__table__.c
"""The catalogue values' columns, by name (generated from their declarations)."""


class CatalogueRepository:
    """Reads of the actuator catalogue."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def actuators(self, query: ActuatorFilter | None = None) -> list[ActuatorRecord]:
        """Actuators matching ``query``, ordered by model."""
        query = query or ActuatorFilter()
        stmt = (
            select(ActuatorRow)
            .join(ActuatorRow.family)
            .options(selectinload(ActuatorRow.zone_points), selectinload(ActuatorRow.family))
            .where(ActuatorRow.retired_at.is_(None))
            .order_by(ActuatorRow.model)
        )
        if query.family is not None:
            stmt = stmt.where(ActuatorFamilyRow.name == query.family)
        if query.min_max_torque_nm is not None:
            stmt = stmt.where(_VALUES.max_torque_nm >= query.min_max_torque_nm)
        if query.max_inertia_kgm2 is not None:
            stmt = stmt.where(_VALUES.inertia_kgm2 <= query.max_inertia_kgm2)
        if query.min_max_speed_rpm is not None:
            stmt = stmt.where(_VALUES.max_speed_rpm >= query.min_max_speed_rpm)
        if query.models is not None:
            stmt = stmt.where(ActuatorRow.model.in_(list(query.models)))
        if query.max_max_torque_nm is not None:
            stmt = stmt.where(_VALUES.max_torque_nm <= query.max_max_torque_nm)
        if query.min_continuous_torque_nm is not None:
            stmt = stmt.where(_VALUES.continuous_torque_nm >= query.min_continuous_torque_nm)
        if query.gear_ratio is not None:
            stmt = stmt.where(_VALUES.gear_ratio == query.gear_ratio)
        if query.after_model is not None:
            stmt = stmt.where(ActuatorRow.model > query.after_model)
        if query.limit is not None:
            stmt = stmt.limit(query.limit)
        return [_to_record(row) for row in self._session.scalars(stmt)]

    def engine_actuators(self, since: int | None = None) -> tuple[dict[str, Actuator], set[str]]:
        """The active actuators as the engine reads them (the fields marked ``engine``, the
        zone), by model, and the models retired: with ``since``, only the actuators
        changed after that catalogue version (``ActuatorRow.changed_version``), else every
        active one. Two plain queries (Core, no ORM rows).

        This is the catalogue snapshot's read (``services/catalogue.py``), done by each
        process after every catalogue change: a change of a few actuators reads those.
        """
        columns = [
            ActuatorFamilyRow.name if f.name == "family" else _VALUES[f.name] for f in ENGINE_FIELDS
        ]
        wanted = (
            ActuatorRow.retired_at.is_(None)
            if since is None
            else ActuatorRow.changed_version > since
        )
        zones: dict[str, list[ZonePoint]] = {}
        connection = self._session.connection()
        points = connection.execute(
            select(ActuatorRow.model, ZonePointRow.speed_rpm, ZonePointRow.torque_nm)
            .join(ZonePointRow, ZonePointRow.actuator_id == ActuatorRow.id)
            .where(wanted)
            .order_by(ActuatorRow.model, ZonePointRow.speed_rpm)
        ).all()  # fetchall: iterating a result fetches row by row, 3× slower here
        for model, speed, torque in points:
            zones.setdefault(model, []).append(ZonePoint(speed_rpm=speed, torque_nm=torque))
        names = [f.name for f in ENGINE_FIELDS]
        rows = connection.execute(
            select(ActuatorRow.retired_at.is_not(None), *columns)
            .join(ActuatorRow.family)
            .where(wanted)
            .order_by(ActuatorRow.model)
        ).all()
        active: dict[str, Actuator] = {}
        retired: set[str] = set()
        for gone, *values in rows:
            model = values[0]
            if gone:
                retired.add(model)
                continue
            its = zones.get(model)
            zone = None if its is None else ContinuousDutyZone(points=tuple(its))
            active[model] = Actuator(zone=zone, **dict(zip(names, values, strict=True)))
        return active, retired

    def actuator(self, model: str) -> ActuatorRecord | None:
        """One actuator by its model, or None."""
        found = self.actuators(ActuatorFilter(models=[model]))
        return found[0] if found else None

    def families(self) -> list[FamilyRecord]:
        """All product families, ordered by name."""
        rows = self._session.scalars(select(ActuatorFamilyRow).order_by(ActuatorFamilyRow.name))
        return [
            FamilyRecord(
                name=r.name,
                description=r.description,
                temperature_sensors=r.temperature_sensors,
                warning_temperature_c=r.warning_temperature_c,
                shutdown_temperature_c=r.shutdown_temperature_c,
                temperature_tolerance_percent=r.temperature_tolerance_percent,
                warning_resistance_ohm=r.warning_resistance_ohm,
                shutdown_resistance_ohm=r.shutdown_resistance_ohm,
                resistance_tolerance_percent=r.resistance_tolerance_percent,
                source=r.source,
            )
            for r in rows
        ]


class CatalogueVersionRepository:
    """The catalogue's version number: read by selections, raised by every catalogue change."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def current(self) -> int:
        """The version now; 0 for a catalogue that was never written."""
        version = self._session.scalar(select(CatalogueStateRow.version))
        return version or 0

    def pin(self) -> int:
        """The version, held until the transaction ends: call it before reading the catalogue.

        Every catalogue change raises the version (:meth:`bump`) in its own
        transaction. On PostgreSQL this read takes a share lock on the version's row:
        a change that has already raised the version is waited for, and its data is
        then read with it; a change that has not yet raised it cannot do so before
        this transaction ends, so the data read meanwhile is the version's own. So the
        rows read after ``pin()`` are exactly those of the version it returns, under
        READ COMMITTED. SQLite's transactions read one snapshot anyway (the lock
        clause is not rendered there).
        """
        version = self._session.scalar(select(CatalogueStateRow.version).with_for_update(read=True))
        return version or 0

    def bump(self) -> int:
        """Raise the version by one inside the caller's transaction; returns the new number.

        On PostgreSQL the UPDATE locks the row, so concurrent changes get distinct numbers.
        """
        now = datetime.now(UTC)
        updated = self._session.execute(
            update(CatalogueStateRow)
            .values(version=CatalogueStateRow.version + 1, changed_at=now)
            .returning(CatalogueStateRow.version)
        ).scalar()
        if updated is None:
            self._session.add(CatalogueStateRow(id=1, version=1, changed_at=now))
            self._session.flush()
            updated = 1
        # The actuators this transaction changed (ActuatorRow.changed_version NULL) now
        # carry the version that changed them.
        self._session.execute(
            update(ActuatorRow)
            .where(ActuatorRow.changed_version.is_(None))
            .values(changed_version=updated)
        )
        return updated


def mark_changed(session: Session, actuator_ids: Collection[int]) -> None:
    """Mark the actuators ``actuator_ids`` as changed by this transaction (their zone or
    interface, which lives in other tables): the transaction's ``bump`` stamps them, so
    every process reads them again. A change of an actuator's own row marks it by itself."""
    for batch in batches(list(actuator_ids)):
        session.execute(
            update(ActuatorRow).where(ActuatorRow.id.in_(batch)).values(changed_version=None)
        )


@dataclass(frozen=True, slots=True, kw_only=True)
class NewSelection:
    """A selection to store: its request, the catalogue version it was sized against and
    its answer as sent, gzip-compressed, and the version of the answer's shape."""

    id: str
    created_at: datetime
    catalogue_version: int
    request: dict[str, Any]
    answer_gzip: bytes
    answer_version: int
    ranking_zstd: bytes | None = None


_NEW_SELECTION_FIELDS = tuple(f.name for f in fields(NewSelection))


@functools.cache
def _insert_at_version() -> Insert:
    """:meth:`SelectionRepository.add_at_version`'s statement, built once, its values
    bound parameters. Built per request, with a literal per column and the request
    deep-copied into them, storing one selection took 2.5 ms on PostgreSQL; now 1.5 ms."""
    table = cast(Table, SelectionRow.__table__)
    version = func.coalesce(select(CatalogueStateRow.version).scalar_subquery(), 0)
    values = select(
        *(bindparam(name, type_=table.c[name].type) for name in _NEW_SELECTION_FIELDS)
    ).where(version == bindparam("at_version"))
    # RETURNING rather than rowcount, which psycopg leaves at -1 for INSERT … SELECT.
    return insert(table).from_select(list(_NEW_SELECTION_FIELDS), values).returning(table.c.id)


class SelectionRepository:
    """Stored selections: written once, read back unchanged."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def add(self, selection: NewSelection) -> None:
        """Store one selection."""
        self._session.add(SelectionRow(**asdict(selection)))
        self._session.flush()

    def add_at_version(self, selection: NewSelection) -> bool:
        """Store one selection if the catalogue is still at its ``catalogue_version``;
        False (nothing stored) when a change has raised the version since.

        One statement, ``INSERT … SELECT … WHERE version = :v``: the version check and
        the insert take a single round trip, so a selection sized against the in-memory
        catalogue is stored only with the version it was sized against. A Core statement,
        run on the session's connection in its transaction: the ORM's execution (and its
        flush, with no ORM object involved) cost a one-model request ~57,000 instructions.
        """
        values = {name: getattr(selection, name) for name in _NEW_SELECTION_FIELDS}
        values["at_version"] = selection.catalogue_version
        inserted = self._session.connection().execute(_insert_at_version(), values)
        return inserted.first() is not None

    def answer_gzip(self, id: str) -> bytes | None:
        """The stored answer of a selection (gzip-compressed JSON), or None."""
        return self._session.scalar(select(SelectionRow.answer_gzip).where(SelectionRow.id == id))

    def ranking(self, id: str) -> tuple[bytes, int, bytes | None] | None:
        """The stored answer of a selection (gzip-compressed JSON), the version of its
        shape and the rest of its ranking (zstd-compressed; None: the answer lists it
        whole), or None."""
        row = self._session.execute(
            select(
                SelectionRow.answer_gzip, SelectionRow.answer_version, SelectionRow.ranking_zstd
            ).where(SelectionRow.id == id)
        ).one_or_none()
        return None if row is None else (row.answer_gzip, row.answer_version, row.ranking_zstd)

    def request(self, id: str) -> tuple[dict[str, Any], int] | None:
        """The stored request of a selection and its catalogue version, or None."""
        row = self._session.execute(
            select(SelectionRow.request, SelectionRow.catalogue_version).where(
                SelectionRow.id == id
            )
        ).one_or_none()
        return None if row is None else (row.request, row.catalogue_version)


class ProfileRepository:
    """Stored motion profiles: written once, read back unchanged."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def add(self, id: str, created_at: datetime, kind: str, answer: dict[str, Any]) -> None:
        """Store one profile."""
        self._session.add(ProfileRow(id=id, created_at=created_at, kind=kind, answer=answer))
        self._session.flush()

    def answers(self, ids: Collection[str]) -> dict[str, dict[str, Any]]:
        """The stored answers of the profiles ``ids`` that exist, by id."""
        rows = self._session.execute(
            select(ProfileRow.id, ProfileRow.answer).where(ProfileRow.id.in_(list(ids)))
        )
        return {row.id: row.answer for row in rows}
