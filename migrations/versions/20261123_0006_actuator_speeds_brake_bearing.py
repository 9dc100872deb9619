"""actuators: allowable continuous and rated output speed, brake holding torque, output
bearing data and a derivation text

All nullable: an empty value is one no public source gives ("no data"). The values
come from the second audit of public copies (CHA Engineering Data 1018854, FHA-C and
FHA-C mini manuals); ``derivation`` says how a derived value was obtained.

Revision ID: 0006
Revises: 0005
Create Date: 2026-11-23
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0006"
down_revision: str | None = "0005"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_FLOATS = (
    "continuous_speed_rpm",
    "rated_speed_rpm",
    "brake_holding_torque_nm",
    "output_bearing_pitch_diameter_m",
    "output_bearing_offset_m",
    "output_bearing_dynamic_load_rating_n",
    "output_bearing_static_load_rating_n",
    "output_bearing_dynamic_tilting_moment_nm",
    "output_bearing_static_tilting_moment_nm",
    "output_bearing_radial_load_n",
    "output_bearing_axial_load_n",
    "output_bearing_moment_load_nm",
    "output_bearing_moment_stiffness_nm_per_rad",
)


def upgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        for name in _FLOATS:
            batch_op.add_column(sa.Column(name, sa.Float(), nullable=True))
        batch_op.add_column(sa.Column("derivation", sa.Text(), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.drop_column("derivation")
        for name in reversed(_FLOATS):
            batch_op.drop_column(name)
