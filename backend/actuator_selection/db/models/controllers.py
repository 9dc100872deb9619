"""Servo controllers (Table 521.1), temperature sensors (Tables 518.1, 519.2), bus classes.

Table 521.1 is kept as printed: one row per source row, its 16 mark columns
(``tested`` = ●, ``possible`` = ○, NULL = empty cell), and a ``correction``
column that records every change against the source. Rows an administrator
adds continue the numbering; a retired row (soft delete) leaves the matching.
"""

from __future__ import annotations

from datetime import datetime

from sqlalchemy import DateTime, Float, ForeignKey, Integer, String, Text, UniqueConstraint
from sqlalchemy.orm import Mapped, mapped_column

from actuator_selection.db.models.base import Base

Mark = String(8)


class ControllerRow(Base):
    """One row of Table 521.1."""

    __tablename__ = "controllers"

    id: Mapped[int] = mapped_column(primary_key=True)
    source_row: Mapped[int] = mapped_column(Integer, unique=True)
    manufacturer: Mapped[str] = mapped_column(String(80))
    type: Mapped[str] = mapped_column(String(80))
    variant: Mapped[str | None] = mapped_column(String(40))
    cha_chm: Mapped[str | None] = mapped_column(Mark)
    fha_c: Mapped[str | None] = mapped_column(Mark)
    ffa_fpa: Mapped[str | None] = mapped_column(Mark)
    lynxdrive: Mapped[str | None] = mapped_column(Mark)
    torkdrive: Mapped[str | None] = mapped_column(Mark)
    fha_mini: Mapped[str | None] = mapped_column(Mark)
    bus_24vdc: Mapped[str | None] = mapped_column(Mark)
    bus_320vdc: Mapped[str | None] = mapped_column(Mark)
    bus_560vdc: Mapped[str | None] = mapped_column(Mark)
    sensor_ptc: Mapped[str | None] = mapped_column(Mark)
    sensor_kty84_130: Mapped[str | None] = mapped_column(Mark)
    feedback_resolver_2pole: Mapped[str | None] = mapped_column(Mark)
    feedback_sincos: Mapped[str | None] = mapped_column(Mark)
    feedback_hiperface: Mapped[str | None] = mapped_column(Mark)
    feedback_endat: Mapped[str | None] = mapped_column(Mark)
    feedback_ttl: Mapped[str | None] = mapped_column(Mark)
    correction: Mapped[str | None] = mapped_column(Text)
    source: Mapped[str] = mapped_column(Text)
    retired_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True))


class SensorFittingRow(Base):
    """A temperature sensor fitted to a family or variant (Table 518.1)."""

    __tablename__ = "temperature_sensor_fittings"
    __table_args__ = (UniqueConstraint("family_id", "variant", "sensor"),)

    id: Mapped[int] = mapped_column(primary_key=True)
    family_id: Mapped[int] = mapped_column(ForeignKey("actuator_families.id"), index=True)
    variant: Mapped[str | None] = mapped_column(String(40))
    sensor: Mapped[str] = mapped_column(String(20))
    designation: Mapped[str | None] = mapped_column(String(60))
    sensor_count: Mapped[int] = mapped_column(Integer)
    nominal_response_temperature_c: Mapped[float | None] = mapped_column(Float)
    note: Mapped[str | None] = mapped_column(Text)
    source: Mapped[str] = mapped_column(Text)


class SensorPointRow(Base):
    """A point of a sensor's resistance characteristic (KTY 84-130 datasheet table)."""

    __tablename__ = "sensor_characteristic_points"
    __table_args__ = (UniqueConstraint("sensor", "temperature_c"),)

    id: Mapped[int] = mapped_column(primary_key=True)
    sensor: Mapped[str] = mapped_column(String(20))
    temperature_c: Mapped[float] = mapped_column(Float)
    resistance_ohm: Mapped[float] = mapped_column(Float)
    source: Mapped[str] = mapped_column(Text)


class DcBusClassRow(Base):
    """A DC bus voltage class of Table 521.1 with its nominal voltage."""

    __tablename__ = "dc_bus_classes"

    id: Mapped[int] = mapped_column(primary_key=True)
    bus_class: Mapped[str] = mapped_column(String(10), unique=True)
    label: Mapped[str] = mapped_column(String(40))
    nominal_dc_voltage_v: Mapped[float] = mapped_column(Float)
    derivation: Mapped[str | None] = mapped_column(Text)
    source: Mapped[str] = mapped_column(Text)


class ActuatorInterfaceRow(Base):
    """What controller matching needs of an actuator; NULL where no source says it."""

    __tablename__ = "actuator_interfaces"

    id: Mapped[int] = mapped_column(primary_key=True)
    actuator_id: Mapped[int] = mapped_column(
        ForeignKey("actuators.id", ondelete="CASCADE"), unique=True
    )
    dc_bus_classes: Mapped[str | None] = mapped_column(String(40))
    temperature_sensors: Mapped[str | None] = mapped_column(String(40))
    feedback_systems: Mapped[str | None] = mapped_column(String(80))
    derivation: Mapped[str | None] = mapped_column(Text)
    source: Mapped[str] = mapped_column(Text)
