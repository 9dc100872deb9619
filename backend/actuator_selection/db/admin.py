"""Catalogue writes for administrators: actuators, their zones, whole-catalogue import/export.

Every write is validated by the rules of the seed files (``db/seed.py``'s
``CsvSpec``s through :func:`~actuator_selection.db.csvio.check_values`), so the
API and the seed loader cannot disagree on what a valid actuator is. Every
change raises the catalogue version; repositories flush, the request commits.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from datetime import datetime
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session, selectinload

from actuator_selection.db.csvio import CatalogueFileError, Problem, check_values
from actuator_selection.db.models import ActuatorFamilyRow, ActuatorRow, ZonePointRow
from actuator_selection.db.repositories import CatalogueVersionRepository
from actuator_selection.db.seed import (
    ACTUATORS,
    FAMILIES,
    ZONE_POINTS,
    CatalogueChanges,
    CatalogueFiles,
    apply_catalogue,
    zone_problems,
)


@dataclass(frozen=True, slots=True, kw_only=True)
class ActuatorState:
    """Whether a model exists and whether it is retired."""

    model: str
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
        stored["retired_at"] = None
        row = self._session.scalar(select(ActuatorRow).where(ActuatorRow.model == stored["model"]))
        changed = row is None
        if row is None:
            row = ActuatorRow()
            self._session.add(row)
        for name, value in stored.items():
            if getattr(row, name) != value:
                setattr(row, name, value)
                changed = True
        self._session.flush()
        if changed:
            CatalogueVersionRepository(self._session).bump()
        return changed

    def retire(self, model: str, *, now: datetime) -> bool:
        """Retire an active actuator (soft delete); False when it already was retired."""
        row = self._session.scalar(select(ActuatorRow).where(ActuatorRow.model == model))
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
        CatalogueVersionRepository(self._session).bump()
        return True

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
        """The active catalogue as stored values per file (retired actuators left out)."""
        families = self._session.scalars(select(ActuatorFamilyRow).order_by(ActuatorFamilyRow.name))
        actuators = list(
            self._session.scalars(
                select(ActuatorRow)
                .options(selectinload(ActuatorRow.family), selectinload(ActuatorRow.zone_points))
                .where(ActuatorRow.retired_at.is_(None))
                .order_by(ActuatorRow.model)
            )
        )
        return {
            FAMILIES.file: [
                {c.attribute: getattr(f, c.attribute) for c in FAMILIES.columns} for f in families
            ],
            ACTUATORS.file: [
                {
                    c.attribute: a.family.name if c.name == "family" else getattr(a, c.attribute)
                    for c in ACTUATORS.columns
                }
                for a in actuators
            ],
            ZONE_POINTS.file: [
                {
                    "actuator_model": a.model,
                    "speed_rpm": p.speed_rpm,
                    "torque_nm": p.torque_nm,
                    "source": p.source,
                }
                for a in actuators
                for p in a.zone_points
            ],
        }
