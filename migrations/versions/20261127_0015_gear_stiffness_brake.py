"""actuators: torsional stiffness, brake limits and the gear's own ratings (issue 28, 7–9)

Nullable numbers: T_1, T_2, K_1–K_3 (CHA manual 1018854 12/2015 §3.3.5 p. 50), the brake's
allowable emergency stops and closing time (CHA technical data brake), the strain wave
gear's ratings (limit for average, repeated and momentary peak torque, the count of
momentary peaks, allowable average input speed, T_N, L_n) and the text L_n basis.

Revision ID: 0015
Revises: 0014
Create Date: 2026-11-27
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0015"
down_revision: str | None = "0014"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

NUMBERS = (
    "limit_torque_t1_nm",
    "limit_torque_t2_nm",
    "torsional_stiffness_k1_nm_per_rad",
    "torsional_stiffness_k2_nm_per_rad",
    "torsional_stiffness_k3_nm_per_rad",
    "brake_emergency_stop_count",
    "brake_closing_time_s",
    "gear_average_torque_limit_nm",
    "gear_repeated_peak_torque_nm",
    "gear_momentary_peak_torque_nm",
    "gear_momentary_peak_count",
    "gear_average_input_speed_limit_rpm",
    "gear_rated_torque_nm",
    "gear_rated_life_h",
)


def upgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        for name in NUMBERS:
            batch_op.add_column(sa.Column(name, sa.Float(), nullable=True))
        batch_op.add_column(sa.Column("gear_life_basis", sa.String(10), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.drop_column("gear_life_basis")
        for name in reversed(NUMBERS):
            batch_op.drop_column(name)
