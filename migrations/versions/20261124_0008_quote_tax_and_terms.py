"""quotes: VAT rate and amount, gross total, payment and delivery terms, seller block

All nullable: quotes made before stated no VAT and no terms, and still render (net
only, with the seller as configured now).

Revision ID: 0008
Revises: 0007
Create Date: 2026-11-24
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op
from sqlalchemy.dialects import postgresql

revision: str = "0008"
down_revision: str | None = "0007"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

JSON_DOCUMENT = sa.JSON().with_variant(postgresql.JSONB(), "postgresql")


def upgrade() -> None:
    with op.batch_alter_table("quotes") as batch_op:
        batch_op.add_column(sa.Column("vat_percent", sa.Numeric(precision=5, scale=2)))
        batch_op.add_column(sa.Column("vat_amount", sa.Numeric(precision=14, scale=2)))
        batch_op.add_column(sa.Column("gross_total", sa.Numeric(precision=14, scale=2)))
        batch_op.add_column(sa.Column("payment_terms", sa.Text()))
        batch_op.add_column(sa.Column("delivery_terms", sa.Text()))
        batch_op.add_column(sa.Column("seller", JSON_DOCUMENT))
        batch_op.create_check_constraint(
            op.f("ck_quotes_vat"), "vat_percent >= 0 AND vat_percent <= 100"
        )


def downgrade() -> None:
    with op.batch_alter_table("quotes") as batch_op:
        batch_op.drop_constraint(op.f("ck_quotes_vat"), type_="check")
        for name in (
            "seller",
            "delivery_terms",
            "payment_terms",
            "gross_total",
            "vat_amount",
            "vat_percent",
        ):
            batch_op.drop_column(name)
