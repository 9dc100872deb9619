"""batch jobs: jobs, their chunks' cases and results; procrastinate's queue on PostgreSQL

A job's results are written once per chunk (primary key ``(job_id, chunk)``). On
PostgreSQL the chunks are tasks of procrastinate's queue, whose tables and functions are
its own schema (``procrastinate/sql/schema.sql`` of the version in requirements.lock),
applied here so that ``migrate`` sets up everything; a later procrastinate whose schema
changes gets a migration of ours applying its ``sql/migrations`` files. SQLite runs jobs
in the server process and needs no queue tables.

Revision ID: 0013
Revises: 0012
Create Date: 2026-11-27
"""

from __future__ import annotations

from collections.abc import Sequence

import sqlalchemy as sa
from alembic import op

revision: str = "0013"
down_revision: str | None = "0012"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

_DROP_PROCRASTINATE = r"""
DO $$
DECLARE r record;
BEGIN
    FOR r IN SELECT tablename FROM pg_tables
             WHERE schemaname = current_schema() AND tablename LIKE 'procrastinate\_%%' LOOP
        EXECUTE format('DROP TABLE IF EXISTS %%I CASCADE', r.tablename);
    END LOOP;
    FOR r IN SELECT p.oid::regprocedure AS f FROM pg_proc p
             JOIN pg_namespace n ON n.oid = p.pronamespace
             WHERE n.nspname = current_schema() AND p.proname LIKE 'procrastinate\_%%' LOOP
        EXECUTE 'DROP FUNCTION IF EXISTS ' || r.f || ' CASCADE';
    END LOOP;
    FOR r IN SELECT t.typname FROM pg_type t
             JOIN pg_namespace n ON n.oid = t.typnamespace
             WHERE n.nspname = current_schema() AND t.typname LIKE 'procrastinate\_%%'
               AND t.typtype IN ('e', 'c') LOOP
        EXECUTE format('DROP TYPE IF EXISTS %%I CASCADE', r.typname);
    END LOOP;
END $$;
"""
"""procrastinate's tables, functions and types (everything its schema names
``procrastinate_…``), as ``%`` reaches the driver doubled."""


def upgrade() -> None:
    op.create_table(
        "batch_jobs",
        sa.Column("id", sa.String(36), primary_key=True),
        sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
        sa.Column("started_at", sa.DateTime(timezone=True), nullable=True),
        sa.Column("finished_at", sa.DateTime(timezone=True), nullable=True),
        sa.Column("state", sa.String(16), nullable=False),
        sa.Column("options", sa.JSON(), nullable=False),
        sa.Column("catalogue_version", sa.Integer(), nullable=False),
        sa.Column("cases", sa.Integer(), nullable=False),
        sa.Column("chunks", sa.Integer(), nullable=False),
        sa.Column("error", sa.Text(), nullable=True),
    )
    for table, payload in (("batch_job_chunks", "input_zlib"), ("batch_job_results", None)):
        columns: list[sa.Column[object]] = [
            sa.Column(
                "job_id",
                sa.String(36),
                sa.ForeignKey("batch_jobs.id", ondelete="CASCADE"),
                primary_key=True,
            ),
            sa.Column("chunk", sa.Integer(), primary_key=True),
        ]
        if payload is not None:
            columns += [
                sa.Column("first_case", sa.Integer(), nullable=False),
                sa.Column("cases", sa.Integer(), nullable=False),
                sa.Column(payload, sa.LargeBinary(), nullable=False),
            ]
        else:
            columns += [
                sa.Column("cases", sa.Integer(), nullable=False),
                sa.Column("catalogue_version", sa.Integer(), nullable=False),
                sa.Column("worker", sa.String(200), nullable=False),
                sa.Column("created_at", sa.DateTime(timezone=True), nullable=False),
                sa.Column("lines_zlib", sa.LargeBinary(), nullable=False),
            ]
        op.create_table(table, *columns)
    if op.get_bind().dialect.name == "postgresql":
        from procrastinate.schema import SchemaManager

        # The driver's own execute: the schema's PL/pgSQL is not SQLAlchemy text.
        op.get_bind().exec_driver_sql(SchemaManager.get_schema().replace("%", "%%"))


def downgrade() -> None:
    if op.get_bind().dialect.name == "postgresql":
        op.get_bind().exec_driver_sql(_DROP_PROCRASTINATE)
    op.drop_table("batch_job_results")
    op.drop_table("batch_job_chunks")
    op.drop_table("batch_jobs")
