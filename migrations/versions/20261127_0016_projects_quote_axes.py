"""quotes of machine projects: a line per axis (issue 31)

A quote rests on a stored selection or, now, on a stored machine project
(``quotes.project_id``; ``selection_id`` becomes nullable, one of the two is set); its
lines name the axis they belong to (``quote_items.axis``), and the quote keeps a copy of
each axis's engineering as quoted (``quotes.axes``: actuator, verdict, controller).

Revision ID: 0016
Revises: 0015
Create Date: 2026-11-27
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op
from sqlalchemy.dialects.postgresql import JSONB

revision: str = "0016"
down_revision: str | None = "0015"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None


def upgrade() -> None:
    with op.batch_alter_table("quotes") as batch_op:
        batch_op.alter_column("selection_id", existing_type=sa.String(36), nullable=True)
        batch_op.add_column(sa.Column("project_id", sa.String(36), nullable=True))
        batch_op.add_column(
            sa.Column("axes", sa.JSON().with_variant(JSONB(), "postgresql"), nullable=True)
        )
        batch_op.create_foreign_key(
            batch_op.f("fk_quotes_project_id_projects"), "projects", ["project_id"], ["id"]
        )
        batch_op.create_index(batch_op.f("ix_quotes_project_id"), ["project_id"], unique=False)
        batch_op.create_check_constraint(
            batch_op.f("ck_quotes_source"), "(selection_id IS NULL) <> (project_id IS NULL)"
        )
    with op.batch_alter_table("quote_items") as batch_op:
        batch_op.add_column(sa.Column("axis", sa.String(80), nullable=True))


def downgrade() -> None:
    with op.batch_alter_table("quote_items") as batch_op:
        batch_op.drop_column("axis")
    op.execute("DELETE FROM quotes WHERE project_id IS NOT NULL")
    with op.batch_alter_table("quotes") as batch_op:
        batch_op.drop_constraint(batch_op.f("ck_quotes_source"), type_="check")
        batch_op.drop_index(batch_op.f("ix_quotes_project_id"))
        batch_op.drop_constraint(batch_op.f("fk_quotes_project_id_projects"), type_="foreignkey")
        batch_op.drop_column("axes")
        batch_op.drop_column("project_id")
        batch_op.alter_column("selection_id", existing_type=sa.String(36), nullable=False)
