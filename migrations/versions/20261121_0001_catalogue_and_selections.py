"""catalogue and selections

Revision ID: 0001
Revises:
Create Date: 2026-11-21
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op
from sqlalchemy.dialects import postgresql

revision: str = "0001"
down_revision: str | None = None
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    op.create_table(
        "actuator_families",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("name", sa.String(length=40), nullable=False),
        sa.Column("description", sa.Text(), nullable=True),
        sa.Column("temperature_sensors", sa.Text(), nullable=True),
        sa.Column("warning_temperature_c", sa.Float(), nullable=True),
        sa.Column("shutdown_temperature_c", sa.Float(), nullable=True),
        sa.Column("temperature_tolerance_percent", sa.Float(), nullable=True),
        sa.Column("warning_resistance_ohm", sa.Float(), nullable=True),
        sa.Column("shutdown_resistance_ohm", sa.Float(), nullable=True),
        sa.Column("resistance_tolerance_percent", sa.Float(), nullable=True),
        sa.Column("source", sa.Text(), nullable=False),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_actuator_families")),
        sa.UniqueConstraint("name", name=op.f("uq_actuator_families_name")),
    )
    op.create_table(
        "catalogue_state",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("version", sa.Integer(), nullable=False),
        sa.Column("changed_at", sa.DateTime(timezone=True), nullable=False),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_catalogue_state")),
    )
    op.create_table(
        "selections",
        sa.Column("id", sa.String(length=36), nullable=False),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("catalogue_version", sa.Integer(), nullable=False),
        sa.Column(
            "request", sa.JSON().with_variant(postgresql.JSONB(), "postgresql"), nullable=False
        ),
        sa.Column(
            "response", sa.JSON().with_variant(postgresql.JSONB(), "postgresql"), nullable=False
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_selections")),
    )
    op.create_table(
        "actuators",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("model", sa.String(length=60), nullable=False),
        sa.Column("family_id", sa.Integer(), nullable=False),
        sa.Column("gear_ratio", sa.Float(), nullable=False),
        sa.Column("max_torque_nm", sa.Float(), nullable=True),
        sa.Column("max_speed_rpm", sa.Float(), nullable=True),
        sa.Column("inertia_kgm2", sa.Float(), nullable=True),
        sa.Column("stall_torque_nm", sa.Float(), nullable=True),
        sa.Column("continuous_torque_nm", sa.Float(), nullable=True),
        sa.Column("max_current_a", sa.Float(), nullable=True),
        sa.Column("stall_current_a", sa.Float(), nullable=True),
        sa.Column("continuous_current_a", sa.Float(), nullable=True),
        sa.Column("torque_constant_nm_per_a", sa.Float(), nullable=True),
        sa.Column("motor_torque_constant_nm_per_a", sa.Float(), nullable=True),
        sa.Column("motor_voltage_constant_v_per_krpm", sa.Float(), nullable=True),
        sa.Column("output_voltage_constant_v_per_rpm", sa.Float(), nullable=True),
        sa.Column("resistance_line_ohm", sa.Float(), nullable=True),
        sa.Column("resistance_phase_ohm", sa.Float(), nullable=True),
        sa.Column("inductance_line_mh", sa.Float(), nullable=True),
        sa.Column("inductance_phase_mh", sa.Float(), nullable=True),
        sa.Column("no_load_starting_current_a", sa.Float(), nullable=True),
        sa.Column("no_load_current_constant_30c_a_per_rpm", sa.Float(), nullable=True),
        sa.Column("no_load_current_constant_80c_a_per_rpm", sa.Float(), nullable=True),
        sa.Column("thermal_time_constant_s", sa.Float(), nullable=True),
        sa.Column("mass_kg", sa.Float(), nullable=True),
        sa.Column("max_dc_bus_voltage_v", sa.Float(), nullable=True),
        sa.Column("supply_voltage", sa.String(length=40), nullable=True),
        sa.Column("feedback", sa.String(length=80), nullable=True),
        sa.Column("notes", sa.Text(), nullable=True),
        sa.Column("source", sa.Text(), nullable=False),
        sa.ForeignKeyConstraint(
            ["family_id"],
            ["actuator_families.id"],
            name=op.f("fk_actuators_family_id_actuator_families"),
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_actuators")),
        sa.UniqueConstraint("model", name=op.f("uq_actuators_model")),
    )
    with op.batch_alter_table("actuators", schema=None) as batch_op:
        batch_op.create_index(batch_op.f("ix_actuators_family_id"), ["family_id"], unique=False)

    op.create_table(
        "zone_points",
        sa.Column("id", sa.Integer(), nullable=False),
        sa.Column("actuator_id", sa.Integer(), nullable=False),
        sa.Column("speed_rpm", sa.Float(), nullable=False),
        sa.Column("torque_nm", sa.Float(), nullable=False),
        sa.Column("source", sa.Text(), nullable=False),
        sa.ForeignKeyConstraint(
            ["actuator_id"],
            ["actuators.id"],
            name=op.f("fk_zone_points_actuator_id_actuators"),
            ondelete="CASCADE",
        ),
        sa.PrimaryKeyConstraint("id", name=op.f("pk_zone_points")),
        sa.UniqueConstraint("actuator_id", "speed_rpm", name=op.f("uq_zone_points_actuator_id")),
    )


def downgrade() -> None:
    op.drop_table("zone_points")
    with op.batch_alter_table("actuators", schema=None) as batch_op:
        batch_op.drop_index(batch_op.f("ix_actuators_family_id"))

    op.drop_table("actuators")
    op.drop_table("selections")
    op.drop_table("catalogue_state")
    op.drop_table("actuator_families")
