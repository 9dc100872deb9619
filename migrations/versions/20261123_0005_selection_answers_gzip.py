"""selections.answer_gzip: the answer as sent, gzip-compressed, instead of a JSON column

A whole-catalogue answer was ~1.1 MB of jsonb a row; the lean answer is ~55 kB of
JSON, ~7 kB compressed, and GET /selections/{id} sends the stored bytes as they are.
Rows stored before are compressed from their JSON.

Revision ID: 0005
Revises: 0004
Create Date: 2026-11-23
"""

from __future__ import annotations

import gzip
import json
from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op
from sqlalchemy.dialects.postgresql import JSONB

revision: str = "0005"
down_revision: str | None = "0004"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_JSON = sa.JSON().with_variant(JSONB(), "postgresql")


_SELECTIONS = sa.table(
    "selections",
    sa.column("id", sa.String),
    sa.column("response", _JSON),
    sa.column("answer_gzip", sa.LargeBinary),
)


def upgrade() -> None:
    with op.batch_alter_table("selections") as batch_op:
        batch_op.add_column(sa.Column("answer_gzip", sa.LargeBinary(), nullable=True))
    connection = op.get_bind()
    old = _SELECTIONS
    for row in connection.execute(sa.select(old.c.id, old.c.response)).all():
        data = json.dumps(row.response, ensure_ascii=False, separators=(",", ":")).encode()
        connection.execute(
            old.update().where(old.c.id == row.id).values(answer_gzip=gzip.compress(data, mtime=0))
        )
    with op.batch_alter_table("selections") as batch_op:
        batch_op.alter_column("answer_gzip", existing_type=sa.LargeBinary(), nullable=False)
        batch_op.drop_column("response")


def downgrade() -> None:
    with op.batch_alter_table("selections") as batch_op:
        batch_op.add_column(sa.Column("response", _JSON, nullable=True))
    connection = op.get_bind()
    new = _SELECTIONS
    for row in connection.execute(sa.select(new.c.id, new.c.answer_gzip)).all():
        connection.execute(
            new.update()
            .where(new.c.id == row.id)
            .values(response=json.loads(gzip.decompress(row.answer_gzip)))
        )
    with op.batch_alter_table("selections") as batch_op:
        batch_op.alter_column("response", existing_type=_JSON, nullable=False)
        batch_op.drop_column("answer_gzip")
