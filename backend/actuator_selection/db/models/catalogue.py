"""The actuator catalogue: families, actuators and their continuous-duty zones.

Columns carry their unit in the name and are nullable wherever a public source
may not publish the value; every row keeps its ``source``.
"""

from __future__ import annotations

from datetime import datetime

from sqlalchemy import DateTime, Float, ForeignKey, Integer, String, Text, UniqueConstraint
from sqlalchemy.orm import Mapped, mapped_column, relationship

from actuator_selection.db.models.base import Base


class ActuatorFamilyRow(Base):
    """A product family, its temperature sensor (Table 518.1) and limits (Table 519.2)."""

    __tablename__ = "actuator_families"

    id: Mapped[int] = mapped_column(primary_key=True)
    name: Mapped[str] = mapped_column(String(40), unique=True)
    description: Mapped[str | None] = mapped_column(Text)
    temperature_sensors: Mapped[str | None] = mapped_column(Text)
    warning_temperature_c: Mapped[float | None] = mapped_column(Float)
    shutdown_temperature_c: Mapped[float | None] = mapped_column(Float)
    temperature_tolerance_percent: Mapped[float | None] = mapped_column(Float)
    warning_resistance_ohm: Mapped[float | None] = mapped_column(Float)
    shutdown_resistance_ohm: Mapped[float | None] = mapped_column(Float)
    resistance_tolerance_percent: Mapped[float | None] = mapped_column(Float)
    source: Mapped[str] = mapped_column(Text)

    actuators: Mapped[list[ActuatorRow]] = relationship(back_populates="family")


class ActuatorRow(Base):
    """One catalogue actuator (one size and gear ratio), values at the output shaft."""

    __tablename__ = "actuators"

    id: Mapped[int] = mapped_column(primary_key=True)
    model: Mapped[str] = mapped_column(String(60), unique=True)
    family_id: Mapped[int] = mapped_column(ForeignKey("actuator_families.id"), index=True)
    gear_ratio: Mapped[float] = mapped_column(Float)
    max_torque_nm: Mapped[float | None] = mapped_column(Float)
    max_speed_rpm: Mapped[float | None] = mapped_column(Float)
    inertia_kgm2: Mapped[float | None] = mapped_column(Float)
    stall_torque_nm: Mapped[float | None] = mapped_column(Float)
    continuous_torque_nm: Mapped[float | None] = mapped_column(Float)
    max_current_a: Mapped[float | None] = mapped_column(Float)
    stall_current_a: Mapped[float | None] = mapped_column(Float)
    continuous_current_a: Mapped[float | None] = mapped_column(Float)
    torque_constant_nm_per_a: Mapped[float | None] = mapped_column(Float)
    motor_torque_constant_nm_per_a: Mapped[float | None] = mapped_column(Float)
    motor_voltage_constant_v_per_krpm: Mapped[float | None] = mapped_column(Float)
    output_voltage_constant_v_per_rpm: Mapped[float | None] = mapped_column(Float)
    resistance_line_ohm: Mapped[float | None] = mapped_column(Float)
    resistance_phase_ohm: Mapped[float | None] = mapped_column(Float)
    inductance_line_mh: Mapped[float | None] = mapped_column(Float)
    inductance_phase_mh: Mapped[float | None] = mapped_column(Float)
    no_load_starting_current_a: Mapped[float | None] = mapped_column(Float)
    no_load_current_constant_30c_a_per_rpm: Mapped[float | None] = mapped_column(Float)
    no_load_current_constant_80c_a_per_rpm: Mapped[float | None] = mapped_column(Float)
    thermal_time_constant_s: Mapped[float | None] = mapped_column(Float)
    mass_kg: Mapped[float | None] = mapped_column(Float)
    max_dc_bus_voltage_v: Mapped[float | None] = mapped_column(Float)
    supply_voltage: Mapped[str | None] = mapped_column(String(40))
    feedback: Mapped[str | None] = mapped_column(String(80))
    continuous_speed_rpm: Mapped[float | None] = mapped_column(Float)
    rated_speed_rpm: Mapped[float | None] = mapped_column(Float)
    brake_holding_torque_nm: Mapped[float | None] = mapped_column(Float)
    output_bearing_pitch_diameter_m: Mapped[float | None] = mapped_column(Float)
    output_bearing_offset_m: Mapped[float | None] = mapped_column(Float)
    output_bearing_dynamic_load_rating_n: Mapped[float | None] = mapped_column(Float)
    output_bearing_static_load_rating_n: Mapped[float | None] = mapped_column(Float)
    output_bearing_dynamic_tilting_moment_nm: Mapped[float | None] = mapped_column(Float)
    output_bearing_static_tilting_moment_nm: Mapped[float | None] = mapped_column(Float)
    output_bearing_radial_load_n: Mapped[float | None] = mapped_column(Float)
    output_bearing_axial_load_n: Mapped[float | None] = mapped_column(Float)
    output_bearing_moment_load_nm: Mapped[float | None] = mapped_column(Float)
    output_bearing_moment_stiffness_nm_per_rad: Mapped[float | None] = mapped_column(Float)
    pole_pairs: Mapped[float | None] = mapped_column(Float)
    output_bearing_type: Mapped[str | None] = mapped_column(String(40))
    notes: Mapped[str | None] = mapped_column(Text)
    derivation: Mapped[str | None] = mapped_column(Text)
    source: Mapped[str] = mapped_column(Text)
    """The manufacturer's documents the values come from (never a mirror website)."""
    read_at: Mapped[str | None] = mapped_column(Text)
    """Where a value was read or checked (a public copy of the document), beside ``source``."""
    retired_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True))
    """Set when the actuator is withdrawn: it leaves listings and selections, stays for quotes."""

    family: Mapped[ActuatorFamilyRow] = relationship(back_populates="actuators")
    zone_points: Mapped[list[ZonePointRow]] = relationship(
        back_populates="actuator",
        order_by="ZonePointRow.speed_rpm",
        cascade="all, delete-orphan",
    )


class ZonePointRow(Base):
    """A corner of the upper edge of an actuator's continuous-duty zone (Fig. 517.1)."""

    __tablename__ = "zone_points"
    __table_args__ = (UniqueConstraint("actuator_id", "speed_rpm"),)

    id: Mapped[int] = mapped_column(primary_key=True)
    actuator_id: Mapped[int] = mapped_column(ForeignKey("actuators.id", ondelete="CASCADE"))
    speed_rpm: Mapped[float] = mapped_column(Float)
    torque_nm: Mapped[float] = mapped_column(Float)
    source: Mapped[str] = mapped_column(Text)

    actuator: Mapped[ActuatorRow] = relationship(back_populates="zone_points")


class CatalogueStateRow(Base):
    """The catalogue's version: one row, its number raised by every change of the catalogue."""

    __tablename__ = "catalogue_state"

    id: Mapped[int] = mapped_column(primary_key=True)
    version: Mapped[int] = mapped_column(Integer)
    changed_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
