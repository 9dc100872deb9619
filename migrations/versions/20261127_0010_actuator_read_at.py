"""actuators: where a row's values were read, beside their citation

Nullable text ``read_at``: the public copy (a mirror website) on which a value was read or
checked. ``source`` cites the manufacturer's document only (publisher, title, document
number, edition, page or table); documents and pages print ``source``, never ``read_at``.

Revision ID: 0010
Revises: 0009
Create Date: 2026-11-27
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0010"
down_revision: str | None = "0009"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.add_column(sa.Column("read_at", sa.Text(), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("actuators") as batch_op:
        batch_op.drop_column("read_at")
