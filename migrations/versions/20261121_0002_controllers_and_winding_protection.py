"""controllers and winding protection

Revision ID: 0002
Revises: 0001
Create Date: 2026-11-21
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0002"
down_revision: str | None = "0001"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    op.create_table(
        "controllers",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("source_row", sa.Integer(), nullable=False),
        sa.Column("manufacturer", sa.String(length=80), nullable=False),
        sa.Column("type", sa.String(length=80), nullable=False),
        sa.Column("variant", sa.String(length=40), nullable=True),
        sa.Column("cha_chm", sa.String(length=8), nullable=True),
        sa.Column("fha_c", sa.String(length=8), nullable=True),
        sa.Column("ffa_fpa", sa.String(length=8), nullable=True),
        sa.Column("lynxdrive", sa.String(length=8), nullable=True),
        sa.Column("torkdrive", sa.String(length=8), nullable=True),
        sa.Column("fha_mini", sa.String(length=8), nullable=True),
        sa.Column("bus_24vdc", sa.String(length=8), nullable=True),
        sa.Column("bus_320vdc", sa.String(length=8), nullable=True),
        sa.Column("bus_560vdc", sa.String(length=8), nullable=True),
        sa.Column("sensor_ptc", sa.String(length=8), nullable=True),
        sa.Column("sensor_kty84_130", sa.String(length=8), nullable=True),
        sa.Column("feedback_resolver_2pole", sa.String(length=8), nullable=True),
        sa.Column("feedback_sincos", sa.String(length=8), nullable=True),
        sa.Column("feedback_hiperface", sa.String(length=8), nullable=True),
        sa.Column("feedback_endat", sa.String(length=8), nullable=True),
        sa.Column("feedback_ttl", sa.String(length=8), nullable=True),
        sa.Column("correction", sa.Text(), nullable=True),
        sa.Column("source", sa.Text(), nullable=False),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_controllers")),
        sa.UniqueConstraint("source_row", name=op.f("uq_controllers_source_row")),
    )
    op.create_table(
        "dc_bus_classes",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("bus_class", sa.String(length=10), nullable=False),
        sa.Column("label", sa.String(length=40), nullable=False),
        sa.Column("nominal_dc_voltage_v", sa.Float(), nullable=False),
        sa.Column("derivation", sa.Text(), nullable=True),
        sa.Column("source", sa.Text(), nullable=False),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_dc_bus_classes")),
        sa.UniqueConstraint("bus_class", name=op.f("uq_dc_bus_classes_bus_class")),
    )
    op.create_table(
        "sensor_characteristic_points",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("sensor", sa.String(length=20), nullable=False),
        sa.Column("temperature_c", sa.Float(), nullable=False),
        sa.Column("resistance_ohm", sa.Float(), nullable=False),
        sa.Column("source", sa.Text(), nullable=False),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_sensor_characteristic_points")),
        sa.UniqueConstraint(
            "sensor", "temperature_c", name=op.f("uq_sensor_characteristic_points_sensor")
        ),
    )
    op.create_table(
        "temperature_sensor_fittings",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("family_id", sa.Integer(), nullable=False),
        sa.Column("variant", sa.String(length=40), nullable=True),
        sa.Column("sensor", sa.String(length=20), nullable=False),
        sa.Column("designation", sa.String(length=60), nullable=True),
        sa.Column("sensor_count", sa.Integer(), nullable=False),
        sa.Column("nominal_response_temperature_c", sa.Float(), nullable=True),
        sa.Column("note", sa.Text(), nullable=True),
        sa.Column("source", sa.Text(), nullable=False),
        sa.ForeignKeyConstraint(
            ["family_id"],
            ["actuator_families.id"],
            name=op.f("fk_temperature_sensor_fittings_family_id_actuator_families"),
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_temperature_sensor_fittings")),
        sa.UniqueConstraint(
            "family_id", "variant", "sensor", name=op.f("uq_temperature_sensor_fittings_family_id")
        ),
    )
    with op.batch_alter_table("temperature_sensor_fittings", schema=None) as batch_op:
        batch_op.create_index(
            batch_op.f("ix_temperature_sensor_fittings_family_id"), ["family_id"], unique=False
        )

    op.create_table(
        "actuator_interfaces",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("actuator_id", sa.Integer(), nullable=False),
        sa.Column("dc_bus_classes", sa.String(length=40), nullable=True),
        sa.Column("temperature_sensors", sa.String(length=40), nullable=True),
        sa.Column("feedback_systems", sa.String(length=80), nullable=True),
        sa.Column("derivation", sa.Text(), nullable=True),
        sa.Column("source", sa.Text(), nullable=False),
        sa.ForeignKeyConstraint(
            ["actuator_id"],
            ["actuators.id"],
            name=op.f("fk_actuator_interfaces_actuator_id_actuators"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_actuator_interfaces")),
        sa.UniqueConstraint("actuator_id", name=op.f("uq_actuator_interfaces_actuator_id")),
    )


def downgrade() -> None:
    op.drop_table("actuator_interfaces")
    with op.batch_alter_table("temperature_sensor_fittings", schema=None) as batch_op:
        batch_op.drop_index(batch_op.f("ix_temperature_sensor_fittings_family_id"))

    op.drop_table("temperature_sensor_fittings")
    op.drop_table("sensor_characteristic_points")
    op.drop_table("dc_bus_classes")
    op.drop_table("controllers")
