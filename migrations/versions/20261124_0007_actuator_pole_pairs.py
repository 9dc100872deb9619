"""actuators: the motor's number of pole pairs

Nullable: published in the CHA tables (Harmonic Drive AG, Engineering Data AC Servo
Actuators CHA, 1018854), not for the FHA-C and FHA-C mini. The drive's voltage check
(Eq. 521.2 with the inductive drop ω·L·I) needs it for the electrical frequency.

Revision ID: 0007
Revises: 0006
Create Date: 2026-11-24
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0007"
down_revision: str | None = "0006"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.add_column(sa.Column("pole_pairs", sa.Float(), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.drop_column("pole_pairs")
