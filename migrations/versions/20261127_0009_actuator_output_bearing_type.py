"""actuators: the output bearing's type

Nullable text, ``cross_roller`` or ``four_point_contact_ball``: it sets the exponent of
the bearing life formula, 10/3 for a roller and 3 for a ball bearing (ISO 281; Harmonic
Drive AG, Engineering Data AC Servo Actuators CHA, 1018854 12/2015, p. 69, Table 69.3).
The CHA-14A, -17A and -20A carry four-point contact ball bearings (same document, 8/2018
V03, output bearing Table 55.1, type column "F"), the larger CHA cross roller bearings.

Revision ID: 0009
Revises: 0008
Create Date: 2026-11-27
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0009"
down_revision: str | None = "0008"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.add_column(sa.Column("output_bearing_type", sa.String(40), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.drop_column("output_bearing_type")
