"""Catalogue writes for administrators: actuators, their zones, controllers, import/export.

Every write is validated by the rules of the seed files (the ``CsvSpec``s of
``catalogue/files.py`` through
:func:`~actuator_selection.catalogue.csvio.check_values`), so the API and the seed
loader cannot disagree on what a valid actuator or controller is. Every change
raises the catalogue version; repositories flush, the request commits.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import datetime
from typing import Any

from sqlalchemy import func, select
from sqlalchemy.orm import Session, selectinload

from actuator_selection.catalogue.changes import CatalogueChanges
from actuator_selection.catalogue.csvio import (
    CatalogueFileError,
    CsvSpec,
    Problem,
    Record,
    check_values,
)
from actuator_selection.catalogue.files import (
    ACTUATORS,
    BUS_CLASSES,
    CONTROLLERS,
    FAMILIES,
    INTERFACES,
    KTY_POINTS,
    SENSOR_FITTINGS,
    ZONE_POINTS,
)
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.db.changes import set_values
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorInterfaceRow,
    ActuatorRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
    ZonePointRow,
)
from actuator_selection.db.repositories import CatalogueVersionRepository, mark_changed
from actuator_selection.db.seed import CatalogueFiles, apply_catalogue, zone_problems
from actuator_selection.db.seed_controllers import controller_name_problems


@dataclass(frozen=True, slots=True, kw_only=True)
class ActuatorState:
    """Whether a model exists and whether it is retired."""

    model: str
    retired_at: datetime | None


@dataclass(frozen=True, slots=True, kw_only=True)
class ControllerState:
    """Whether a row of the compatibility matrix exists and whether it is retired."""

    source_row: int
    retired_at: datetime | None


@dataclass(frozen=True, slots=True, kw_only=True)
class ZonePointIn:
    """One validated corner of a zone's edge [rpm, Nm]."""

    speed_rpm: float
    torque_nm: float


class CatalogueAdminRepository:
    """Administrator's writes to the catalogue."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def state(self, model: str) -> ActuatorState | None:
        """The model's existence and retirement, or None when the catalogue never held it."""
        row = self._session.scalar(select(ActuatorRow).where(ActuatorRow.model == model))
        return ActuatorState(model=row.model, retired_at=row.retired_at) if row else None

    def validate_actuator(self, values: Mapping[str, object]) -> dict[str, Any]:
        """Stored values of an actuator given by its CSV column names, or
        :class:`CatalogueFileError` with the seed loader's problems (and an unknown family).
        """
        checked, problems = check_values(ACTUATORS, values)
        family = checked.get("family")
        if family is not None and not any(p.column == "family" for p in problems):
            known = set(self._session.scalars(select(ActuatorFamilyRow.name)))
            if family not in known:
                problems.append(
                    Problem(
                        file=ACTUATORS.file,
                        line=0,
                        column="family",
                        message=f"unknown family {family!r} (known: {', '.join(sorted(known))})",
                    )
                )
        if problems:
            raise CatalogueFileError(problems)
        return checked

    def save_actuator(self, values: Mapping[str, Any]) -> bool:
        """Insert or replace an actuator from validated ``values``; brings a retired one back.

        Returns True when anything changed (and the catalogue version was raised).
        """
        stored = dict(values)
        family = self._session.scalar(
            select(ActuatorFamilyRow).where(ActuatorFamilyRow.name == stored.pop("family"))
        )
        assert family is not None, "validate_actuator checks the family"
        stored["family_id"] = family.id
        return self._save(ActuatorRow, ActuatorRow.model == stored["model"], stored)

    def retire(self, model: str, *, now: datetime) -> bool:
        """Retire an active actuator (soft delete); False when it already was retired."""
        return self._retire(ActuatorRow, ActuatorRow.model == model, now)

    def controller_state(self, source_row: int) -> ControllerState | None:
        """The row's existence and retirement, or None when the matrix never held it."""
        row = self._session.scalar(
            select(ControllerRow).where(ControllerRow.source_row == source_row)
        )
        return (
            ControllerState(source_row=row.source_row, retired_at=row.retired_at) if row else None
        )

    def next_controller_row(self) -> int:
        """The first row number after every row the matrix holds or held."""
        return (self._session.scalar(select(func.max(ControllerRow.source_row))) or 0) + 1

    def validate_controller(self, values: Mapping[str, object]) -> dict[str, Any]:
        """Stored values of a controller given by its CSV column names, or
        :class:`CatalogueFileError` with the seed loader's problems (and a name that
        another active row already has).
        """
        checked, problems = check_values(CONTROLLERS, values)
        if not problems:
            others = {
                (r.manufacturer, r.type, r.variant): r.source_row
                for r in self._session.scalars(
                    select(ControllerRow).where(
                        ControllerRow.retired_at.is_(None),
                        ControllerRow.source_row != checked["source_row"],
                    )
                )
            }
            problems = controller_name_problems([Record(line=0, values=checked)], others=others)
        if problems:
            raise CatalogueFileError(problems)
        return checked

    def save_controller(self, values: Mapping[str, Any]) -> bool:
        """Insert or replace a row of the matrix from validated ``values``; brings a
        retired one back. True when anything changed (and the version was raised).
        """
        return self._save(ControllerRow, ControllerRow.source_row == values["source_row"], values)

    def retire_controller(self, source_row: int, *, now: datetime) -> bool:
        """Retire an active controller (soft delete); False when it already was retired."""
        return self._retire(ControllerRow, ControllerRow.source_row == source_row, now)

    def _save(self, model: type[Any], where: Any, values: Mapping[str, Any]) -> bool:
        row = self._session.scalar(select(model).where(where))
        changed = row is None
        if row is None:
            row = model()
            self._session.add(row)
        changed = set_values(row, {**values, "retired_at": None}) or changed
        self._session.flush()
        if changed:
            CatalogueVersionRepository(self._session).bump()
        return changed

    def _retire(self, model: type[Any], where: Any, now: datetime) -> bool:
        row = self._session.scalar(select(model).where(where))
        if row is None or row.retired_at is not None:
            return False
        row.retired_at = now
        self._session.flush()
        CatalogueVersionRepository(self._session).bump()
        return True

    @staticmethod
    def validate_zone(
        model: str, points: Sequence[Mapping[str, object]], source: object
    ) -> list[ZonePointIn]:
        """Zone points checked by the rules of ``zone_points.csv``; problems name the index."""
        problems: list[Problem] = []
        checked: list[tuple[float, float, int]] = []
        for index, point in enumerate(points):
            values, point_problems = check_values(
                ZONE_POINTS, {**point, "actuator_model": model, "source": source}, line=index
            )
            problems.extend(point_problems)
            if not point_problems:
                checked.append((values["speed_rpm"], values["torque_nm"], index))
        if not problems:
            problems = zone_problems(model, [(s, i) for s, _, i in checked])
        if problems:
            raise CatalogueFileError(problems)
        return [ZonePointIn(speed_rpm=s, torque_nm=t) for s, t, _ in sorted(checked)]

    def set_zone(self, model: str, points: Sequence[ZonePointIn], *, source: str | None) -> bool:
        """Replace the zone of ``model`` (no points: remove it); True when anything changed."""
        row = self._session.scalar(
            select(ActuatorRow)
            .options(selectinload(ActuatorRow.zone_points))
            .where(ActuatorRow.model == model)
        )
        assert row is not None, "the caller checks the model"
        have = sorted((p.speed_rpm, p.torque_nm, p.source) for p in row.zone_points)
        want = sorted((p.speed_rpm, p.torque_nm, source or "") for p in points)
        if have == want:
            return False
        # Delete before insert: the unit of work would insert first and trip the
        # (actuator, speed) unique constraint.
        row.zone_points.clear()
        self._session.flush()
        row.zone_points.extend(
            ZonePointRow(speed_rpm=s, torque_nm=t, source=src) for s, t, src in want
        )
        self._session.flush()
        mark_changed(self._session, [row.id])
        CatalogueVersionRepository(self._session).bump()
        return True

    @staticmethod
    def validate_interface(values: Mapping[str, object]) -> dict[str, Any]:
        """Stored values of an actuator's interface given by the columns of
        actuator_interfaces.csv, or :class:`CatalogueFileError` with the seed loader's problems.
        """
        checked, problems = check_values(INTERFACES, values)
        if problems:
            raise CatalogueFileError(problems)
        return checked

    def set_interface(self, model: str, values: Mapping[str, Any] | None) -> bool:
        """Replace (None: remove) the interface of ``model``; True when anything changed."""
        actuator_id = self._session.scalar(select(ActuatorRow.id).where(ActuatorRow.model == model))
        assert actuator_id is not None, "the caller checks the model"
        row = self._session.scalar(
            select(ActuatorInterfaceRow).where(ActuatorInterfaceRow.actuator_id == actuator_id)
        )
        if values is None:
            if row is None:
                return False
            self._session.delete(row)
            changed = True
        else:
            stored = {k: v for k, v in values.items() if k != "actuator_model"}
            changed = row is None
            if row is None:
                row = ActuatorInterfaceRow(actuator_id=actuator_id)
                self._session.add(row)
            changed = set_values(row, stored) or changed
        self._session.flush()
        if changed:
            mark_changed(self._session, [actuator_id])
            CatalogueVersionRepository(self._session).bump()
        return changed

    def import_catalogue(self, files: CatalogueFiles, *, dry_run: bool) -> CatalogueChanges:
        """Replace the catalogue by ``files`` (see ``apply_catalogue(replace=True)``).

        A dry run does the very same work inside a savepoint and rolls it back, so
        its report is exactly what a real import would do.
        """
        savepoint = self._session.begin_nested()
        try:
            changes = apply_catalogue(self._session, files, replace=True)
        except BaseException:
            savepoint.rollback()
            raise
        if dry_run:
            savepoint.rollback()
        else:
            savepoint.commit()
        return changes

    def export(self) -> dict[str, list[dict[str, Any]]]:
        """The active catalogue as stored values per file (retired actuators and
        controllers, and what belongs to retired actuators, left out)."""
        session = self._session
        families = session.scalars(select(ActuatorFamilyRow).order_by(ActuatorFamilyRow.name))
        actuators = list(
            session.scalars(
                select(ActuatorRow)
                .options(selectinload(ActuatorRow.family), selectinload(ActuatorRow.zone_points))
                .where(ActuatorRow.retired_at.is_(None))
                .order_by(ActuatorRow.model)
            )
        )
        controllers = session.scalars(
            select(ControllerRow)
            .where(ControllerRow.retired_at.is_(None))
            .order_by(ControllerRow.source_row)
        )
        fittings = session.execute(
            select(SensorFittingRow, ActuatorFamilyRow.name)
            .join(ActuatorFamilyRow, SensorFittingRow.family_id == ActuatorFamilyRow.id)
            .order_by(
                ActuatorFamilyRow.name,
                SensorFittingRow.variant.nulls_first(),
                SensorFittingRow.sensor,
            )
        )
        kty_points = session.scalars(
            select(SensorPointRow)
            .where(SensorPointRow.sensor == TemperatureSensor.KTY84_130.value)
            .order_by(SensorPointRow.temperature_c)
        )
        bus_classes = session.scalars(
            select(DcBusClassRow).order_by(DcBusClassRow.nominal_dc_voltage_v)
        )
        interfaces = session.execute(
            select(ActuatorInterfaceRow, ActuatorRow.model)
            .join(ActuatorRow, ActuatorInterfaceRow.actuator_id == ActuatorRow.id)
            .where(ActuatorRow.retired_at.is_(None))
            .order_by(ActuatorRow.model)
        )
        return {
            FAMILIES.file: [_values(FAMILIES, f) for f in families],
            ACTUATORS.file: [_values(ACTUATORS, a, family=a.family.name) for a in actuators],
            ZONE_POINTS.file: [
                _values(ZONE_POINTS, p, actuator_model=a.model)
                for a in actuators
                for p in a.zone_points
            ],
            CONTROLLERS.file: [_values(CONTROLLERS, c) for c in controllers],
            SENSOR_FITTINGS.file: [_values(SENSOR_FITTINGS, f, family=n) for f, n in fittings],
            KTY_POINTS.file: [_values(KTY_POINTS, p) for p in kty_points],
            BUS_CLASSES.file: [_values(BUS_CLASSES, b) for b in bus_classes],
            INTERFACES.file: [_values(INTERFACES, i, actuator_model=m) for i, m in interfaces],
        }


def _values(spec: CsvSpec, row: Any, **given: Any) -> dict[str, Any]:
    """A stored row as the values of ``spec``'s columns; ``given`` supplies the ones a row
    holds by reference (a family's or actuator's name instead of its id)."""
    return {
        c.attribute: given[c.name] if c.name in given else getattr(row, c.attribute)
        for c in spec.columns
    }
