"""actuators: the catalogue version that last changed each (issue 32, reload incrementally)

A process holding the catalogue at version v reads only the actuators stamped after v.
Rows stored before this revision are stamped 0 (older than any version a process holds).

Revision ID: 0017
Revises: 0016
Create Date: 2026-11-27
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0017"
down_revision: str | None = "0016"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.add_column(sa.Column("changed_version", sa.Integer(), nullable=True))
        batch_op.create_index("ix_actuators_changed_version", ["changed_version"])
    op.execute("UPDATE actuators SET changed_version = 0")


def downgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.drop_index("ix_actuators_changed_version")
        batch_op.drop_column("changed_version")
