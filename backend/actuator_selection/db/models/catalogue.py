"""The actuator catalogue: families, actuators and their continuous-duty zones.

Columns carry their unit in the name and are nullable wherever a public source
may not publish the value; every row keeps its ``source``.
"""

from __future__ import annotations

from datetime import datetime
from typing import TYPE_CHECKING, Any

from sqlalchemy import (
    DateTime,
    Float,
    ForeignKey,
    Integer,
    String,
    Text,
    UniqueConstraint,
    null,
)
from sqlalchemy.orm import Mapped, MappedColumn, mapped_column, relationship
from sqlalchemy.types import TypeEngine

from actuator_selection.catalogue.fields import (
    ACTUATOR_FIELDS,
    FAMILY_LENGTH,
    MODEL_LENGTH,
    CatalogueField,
    Kind,
)
from actuator_selection.db.models.base import Base


class ActuatorFamilyRow(Base):
    """A product family, its temperature sensor (Table 518.1) and limits (Table 519.2)."""

    __tablename__ = "actuator_families"

    id: Mapped[int] = mapped_column(primary_key=True)
    name: Mapped[str] = mapped_column(String(FAMILY_LENGTH), unique=True)
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
    """One catalogue actuator (one size and gear ratio), values at the output shaft.

    Besides its key, its family and its retirement, a column per catalogue value of
    :data:`~actuator_selection.catalogue.fields.ACTUATOR_FIELDS`, added below the class.
    """

    __tablename__ = "actuators"

    id: Mapped[int] = mapped_column(primary_key=True)
    model: Mapped[str] = mapped_column(String(MODEL_LENGTH), unique=True)
    family_id: Mapped[int] = mapped_column(ForeignKey("actuator_families.id"), index=True)
    retired_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True))
    """Set when the actuator is withdrawn: it leaves listings and selections, stays for quotes."""
    changed_version: Mapped[int | None] = mapped_column(
        Integer, index=True, default=None, onupdate=null()
    )
    """The catalogue version that last changed the actuator, its zone or its interface, so
    a process reads only the actuators changed since the version it holds. NULL while the
    change's transaction has not raised the version yet: every insert and update of the
    row sets it (``onupdate``), a change of the zone or interface sets it explicitly
    (:func:`~actuator_selection.db.repositories.mark_changed`), and raising the version
    stamps every NULL with the new one (``CatalogueVersionRepository.bump``)."""

    family: Mapped[ActuatorFamilyRow] = relationship(back_populates="actuators")
    zone_points: Mapped[list[ZonePointRow]] = relationship(
        back_populates="actuator",
        order_by="ZonePointRow.speed_rpm",
        cascade="all, delete-orphan",
    )

    if TYPE_CHECKING:

        def __getattr__(self, name: str) -> Any:
            """A catalogue value: its column is generated from its declaration."""


def value_column(field: CatalogueField) -> MappedColumn[Any]:
    """The column of a catalogue value: a float or a text as wide as its rule allows,
    NULL where the value may be missing ("no data")."""
    if field.kind is Kind.NUMBER:
        type_: TypeEngine[Any] = Float()
    elif field.max_length is not None:
        type_ = String(field.max_length)
    else:
        type_ = Text()
    return mapped_column(type_, nullable=not field.required)


# The key (model) and the family (a foreign key) are declared in the class.
for _field in ACTUATOR_FIELDS:
    if _field.name not in {"model", "family"}:
        # Declarative adds a column assigned to a mapped class to its table and mapper.
        setattr(ActuatorRow, _field.name, value_column(_field))


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
