"""Reads of the controller catalogue and the winding-protection data, as core types."""

from __future__ import annotations

from typing import TypeVar

from sqlalchemy import select
from sqlalchemy.orm import Session

from actuator_selection.catalogue.controllers import (
    MARK_COLUMNS,
    ActuatorInterface,
    BusClass,
    FeedbackSystem,
    controller_from_record,
    product_family,
)
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.catalogue.records import ControllerRecord, InterfaceRecord
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorInterfaceRow,
    ActuatorRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
)
from actuator_selection.errors import NotFoundError
from actuator_selection.sizing.electrical import DcBusClass
from actuator_selection.sizing.thermal import KtyCharacteristic, SensorFitting, TemperatureLimits

_Option = TypeVar("_Option", BusClass, TemperatureSensor, FeedbackSystem)


def _options(text: str | None, kind: type[_Option]) -> frozenset[_Option] | None:
    return frozenset(kind(o) for o in text.split()) if text and text.strip() else None


def _controller_record(row: ControllerRow) -> ControllerRecord:
    return ControllerRecord(
        controller=controller_from_record(
            {
                "source_row": row.source_row,
                "manufacturer": row.manufacturer,
                "type": row.type,
                "variant": row.variant,
                "correction": row.correction,
                **{column: getattr(row, column) for _, _, column in MARK_COLUMNS},
            }
        ),
        source=row.source,
    )


class ProtectionRepository:
    """Controllers (Table 521.1), sensors (Tables 518.1, 519.2), bus classes, interfaces."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def controllers(self) -> list[ControllerRecord]:
        """Every active row of the compatibility matrix (Table 521.1 and later rows) in order."""
        rows = self._session.scalars(
            select(ControllerRow)
            .where(ControllerRow.retired_at.is_(None))
            .order_by(ControllerRow.source_row)
        )
        return [_controller_record(r) for r in rows]

    def controller(self, source_row: int) -> ControllerRecord | None:
        """One active row of the compatibility matrix; None when unknown or retired."""
        row = self._session.scalar(
            select(ControllerRow).where(
                ControllerRow.source_row == source_row, ControllerRow.retired_at.is_(None)
            )
        )
        return None if row is None else _controller_record(row)

    def interfaces(
        self, models: list[str] | None = None, *, since: int | None = None
    ) -> dict[str, InterfaceRecord]:
        """Matching data by actuator model (every listed model, with None where unknown);
        with ``since``, of the actuators changed after that catalogue version only."""
        table = ActuatorInterfaceRow
        stmt = (
            select(
                ActuatorRow.model,
                ActuatorFamilyRow.name,
                table.id,
                table.dc_bus_classes,
                table.temperature_sensors,
                table.feedback_systems,
                table.derivation,
                table.source,
            )
            .join(ActuatorFamilyRow, ActuatorRow.family_id == ActuatorFamilyRow.id)
            .outerjoin(table, table.actuator_id == ActuatorRow.id)
        )
        if models is not None:
            stmt = stmt.where(ActuatorRow.model.in_(models))
        if since is not None:
            stmt = stmt.where(ActuatorRow.changed_version > since)
        # A catalogue has a handful of distinct interfaces: each is built once (64,000
        # actuators are read after every catalogue change).
        built: dict[tuple[str, str | None, str | None, str | None, bool], ActuatorInterface] = {}
        out: dict[str, InterfaceRecord] = {}
        for (
            model,
            family,
            row_id,
            buses,
            sensors,
            feedback,
            derivation,
            source,
        ) in self._session.connection().execute(stmt).all():
            known = row_id is not None
            key = (family, buses, sensors, feedback, known)
            interface = built.get(key)
            if interface is None:
                try:
                    product = product_family(family)
                except NotFoundError:
                    product = None
                interface = built.setdefault(
                    key,
                    ActuatorInterface(
                        family=product,
                        bus_classes=_options(buses, BusClass) if known else None,
                        temperature_sensors=_options(sensors, TemperatureSensor) if known else None,
                        feedback_systems=_options(feedback, FeedbackSystem) if known else None,
                    ),
                )
            out[model] = InterfaceRecord(interface=interface, derivation=derivation, source=source)
        return out

    def bus_classes(self) -> list[DcBusClass]:
        """The DC bus classes with their nominal voltages."""
        rows = self._session.scalars(
            select(DcBusClassRow).order_by(DcBusClassRow.nominal_dc_voltage_v)
        )
        return [
            DcBusClass(bus_class=BusClass(r.bus_class), nominal_voltage_v=r.nominal_dc_voltage_v)
            for r in rows
        ]

    def kty(self) -> KtyCharacteristic:
        """The KTY 84-130 characteristic."""
        rows = self._session.scalars(
            select(SensorPointRow)
            .where(SensorPointRow.sensor == TemperatureSensor.KTY84_130.value)
            .order_by(SensorPointRow.temperature_c)
        )
        return KtyCharacteristic.from_points((r.temperature_c, r.resistance_ohm) for r in rows)

    def fittings(self, family: str) -> list[SensorFitting]:
        """Sensors fitted to ``family`` (Table 518.1), empty when the table lists none."""
        rows = self._session.scalars(
            select(SensorFittingRow)
            .join(ActuatorFamilyRow, SensorFittingRow.family_id == ActuatorFamilyRow.id)
            .where(ActuatorFamilyRow.name == family)
            .order_by(SensorFittingRow.id)
        )
        return [
            SensorFitting(
                family=family,
                variant=r.variant,
                sensor=TemperatureSensor(r.sensor),
                sensor_count=r.sensor_count,
                nominal_response_temperature_c=r.nominal_response_temperature_c,
                designation=r.designation,
            )
            for r in rows
        ]

    def limits(self, family: str) -> TemperatureLimits | None:
        """Warning and shutdown limits of ``family`` (Table 519.2); None when unpublished.

        Raises
        ------
        NotFoundError
            For a family the catalogue does not know.
        """
        row = self._session.scalars(
            select(ActuatorFamilyRow).where(ActuatorFamilyRow.name == family)
        ).one_or_none()
        if row is None:
            raise NotFoundError("family", f"unknown family {family!r}")
        w_t, s_t, t_tol = (
            row.warning_temperature_c,
            row.shutdown_temperature_c,
            row.temperature_tolerance_percent,
        )
        w_r, s_r, r_tol = (
            row.warning_resistance_ohm,
            row.shutdown_resistance_ohm,
            row.resistance_tolerance_percent,
        )
        if (
            w_t is None
            or s_t is None
            or t_tol is None
            or w_r is None
            or s_r is None
            or r_tol is None
        ):
            return None
        return TemperatureLimits(
            warning_temperature_c=w_t,
            shutdown_temperature_c=s_t,
            temperature_tolerance_percent=t_tol,
            warning_resistance_ohm=w_r,
            shutdown_resistance_ohm=s_r,
            resistance_tolerance_percent=r_tol,
        )
