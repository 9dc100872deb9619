"""selections.answer_version: stored answers carry their shape's version, upgraded once

Stored answers came in two historical shapes, which the readers (quotes, reports, the
AAS export) tolerated side by side until now:

- version 0, the answer before the lean one (up to 2026-11-23, commit 2cc9373): each
  candidate with its reasons, every check in words (unit, reference, message, margin)
  and its whole controller list (Table 521.1, each with its criteria and voltage check);
- version 1, the lean answer as first stored (2026-11-23) and the fields added to it
  one by one since: checks as numbers, ``check_rules`` and ``controllers`` once,
  drive options grouped; later the load's T_G and η, the cycle's ``segments``,
  ``brake``, ``drive``, ``output_load``, ``output_bearing`` (and its code), ``binding``.

This migration rewrites each such answer to version 2, today's ``SelectionOut`` with
every field present, and records the version; readers take version 2 only. The upgrade
keeps every figure (verdicts, torques, check values, limits, units, references, the
controllers and their voltage checks) and gives each added field what it meant when the
answer was made: T_G 0 and η 1 (the chapter's loads, Eq. 515.4/515.6), the chapter's
four segments of the t_1…t_p cycle, no brake, no drive sizing, no output load (bearing
not checked), no binding. A version-0 answer's words go: a check's words are written
from its numbers in the reader's language, as for every lean answer, a no-data check's
from what its words said it misses; its reasons and controllers note are the detail's
(GET …/candidates/{model}); an unsuitable candidate's controllers are left out
(``drive_options`` null), as the lean answer leaves them. So a version-0 answer becomes
the version-1 answer that the lean code (2cc9373) wrote for the same case. Answers of
version 2 are left byte for byte as they are.

The code is this migration's own (a migration must not change when the application
does); ``tests/db/test_answer_upgrade.py`` stores answers as the old code wrote them,
runs it and reads them back.

Revision ID: 0010
Revises: 0009
Create Date: 2026-11-27
"""

from __future__ import annotations

import gzip
import json
import re
from collections.abc import Sequence
from typing import Any

import sqlalchemy as sa
from alembic import op

revision: str = "0011"
down_revision: str | None = "0010"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

ANSWER_VERSION = 2
"""The version the answers are upgraded to (``services.presenters.selection``)."""

_SELECTIONS = sa.table(
    "selections",
    sa.column("id", sa.String),
    sa.column("answer_gzip", sa.LargeBinary),
    sa.column("answer_version", sa.Integer),
)

_CHUNK = 200
"""Rows read and rewritten at a time."""

JSON = dict[str, Any]

_NO_DATA = re.compile(r"no data: the catalogue gives no (.+) for this actuator")
"""A version-0 no-data check's words (``sizing/checks`` then): they name what it misses."""

_NOT_CHECKED = "not checked: no output_load given"
"""``output_bearing`` of an answer without an output load (``i18n/check_messages.py``)."""


def upgrade() -> None:
    # NOT NULL with a default from the start: on SQLite, making the column NOT NULL later
    # would copy the table, which the quotes' foreign key to it forbids.
    op.add_column(
        "selections",
        sa.Column("answer_version", sa.Integer(), nullable=False, server_default="0"),
    )
    connection = op.get_bind()
    table = _SELECTIONS
    ids = connection.execute(sa.select(table.c.id).order_by(table.c.id)).scalars().all()
    for start in range(0, len(ids), _CHUNK):
        rows = connection.execute(
            sa.select(table.c.id, table.c.answer_gzip).where(
                table.c.id.in_(ids[start : start + _CHUNK])
            )
        ).all()
        for row in rows:
            values: dict[str, Any] = {"answer_version": ANSWER_VERSION}
            answer = json.loads(gzip.decompress(row.answer_gzip))
            upgraded = upgraded_answer(answer)
            if upgraded != answer:
                text = json.dumps(upgraded, ensure_ascii=False, separators=(",", ":"))
                values["answer_gzip"] = gzip.compress(text.encode(), compresslevel=1, mtime=0)
            connection.execute(table.update().where(table.c.id == row.id).values(**values))
    if connection.dialect.name != "sqlite":  # SQLite cannot drop a default in place
        op.alter_column("selections", "answer_version", server_default=None)


def downgrade() -> None:
    # The answers stay upgraded: the readers before this revision read version 2 too.
    # (ALTER TABLE … DROP COLUMN in place: SQLite ≥ 3.35.)
    op.drop_column("selections", "answer_version")


def answer_version(answer: JSON) -> int:
    """The version of a stored answer's shape, by its fields."""
    if "check_rules" not in answer:
        return 0
    return 2 if all(field in answer for field in _ADDED_FIELDS) else 1


_ADDED_FIELDS = (
    "segments",
    "brake",
    "drive",
    "output_load",
    "output_bearing",
    "output_bearing_code",
    "binding",
)
"""Top-level fields the lean answer gained after it was first stored."""


def upgraded_answer(answer: JSON) -> JSON:
    """``answer`` in today's shape (version 2); an answer of version 2 as it is."""
    version = answer_version(answer)
    if version == 2 and {"gravity_torque_nm", "efficiency"} <= set(answer["load"]):
        return answer
    lean = _lean(answer) if version == 0 else answer
    load = {
        "speed_rpm": lean["load"]["speed_rpm"],
        "torque_nm": lean["load"]["torque_nm"],
        "inertia_kgm2": lean["load"]["inertia_kgm2"],
        "gravity_torque_nm": lean["load"].get("gravity_torque_nm", 0.0),
        "efficiency": lean["load"].get("efficiency", 1.0),
    }
    return {
        "id": lean["id"],
        "created_at": lean["created_at"],
        "catalogue_version": lean["catalogue_version"],
        "load": load,
        "segments": lean["segments"] if "segments" in lean else _segments(lean),
        "mechanism": lean.get("mechanism"),
        "cycle": lean["cycle"],
        "high_dynamics": lean["high_dynamics"],
        "brake": lean.get("brake", False),
        "drive": lean.get("drive", False),
        "output_load": lean.get("output_load"),
        "output_bearing": lean.get("output_bearing", _NOT_CHECKED),
        "output_bearing_code": lean.get("output_bearing_code", "output_bearing.not_checked"),
        "models": lean.get("models"),
        "cycle_time_s": lean["cycle_time_s"],
        "mean_speed_rpm": lean["mean_speed_rpm"],
        "duty_cycle_percent": lean["duty_cycle_percent"],
        "ranking": lean["ranking"],
        "check_rules": lean["check_rules"],
        "controllers": lean["controllers"],
        "candidates": lean["candidates"],
        "binding": lean.get("binding"),
    }


def _segments(answer: JSON) -> list[JSON]:
    """The chapter's cycle (Fig. 516.2) as the answer's four segments at the output: 0 →
    n_2 in t_1, n_2 for t_2, n_2 → 0 in t_3, standstill for t_p (``sizing/motion``)."""
    cycle, n_2 = answer["cycle"], answer["load"]["speed_rpm"]
    speeds = ((0.0, n_2), (n_2, n_2), (n_2, 0.0), (0.0, 0.0))
    durations = (cycle["accel_s"], cycle["constant_s"], cycle["decel_s"], cycle["pause_s"])
    out, clock = [], 0.0
    for duration, (start, end) in zip(durations, speeds, strict=True):
        out.append(
            {
                "start_s": clock,
                "duration_s": duration,
                "start_rpm": start,
                "end_rpm": end,
                "jerk_share": 0.0,
                "process_torque_nm": 0.0,
            }
        )
        clock += duration
    return out


def _lean(answer: JSON) -> JSON:
    """A version-0 answer as the lean answer (version 1) states it: checks as numbers with
    their unit and reference once, controllers once, each candidate's drive options
    grouped by level, missing criteria and voltage check."""
    rules: dict[str, JSON] = {}
    refs: dict[tuple[Any, ...], int] = {}
    candidates = []
    for c in answer["candidates"]:
        checks = []
        for check in c["checks"]:
            rules.setdefault(
                check["name"],
                {"name": check["name"], "reference": check["reference"], "unit": check["unit"]},
            )
            brief = {k: check[k] for k in ("name", "status", "value", "limit")}
            if check.get("approximate"):
                brief["approximate"] = True
            said = check["status"] == "no_data" and _NO_DATA.fullmatch(check.get("message", ""))
            if said:
                brief["missing"] = said.group(1)
            checks.append(brief)
        drive_options = None
        if c["verdict"] != "unsuitable":
            groups: dict[tuple[Any, ...], JSON] = {}
            for option in c.get("controllers", []):
                ref = (
                    option["manufacturer"],
                    option["type"],
                    option["variant"],
                    option["source_row"],
                )
                number = refs.setdefault(ref, len(refs))
                v = option["voltage"]
                voltage = {k: v[k] for k in ("status", "value", "limit", "reference")}
                key = (option["level"], tuple(option["missing"]), *voltage.values())
                group = groups.setdefault(
                    key,
                    {
                        "level": option["level"],
                        "missing": list(option["missing"]),
                        "voltage": voltage,
                        "controllers": [],
                    },
                )
                group["controllers"].append(number)
            drive_options = list(groups.values())
        candidates.append(
            {
                "model": c["model"],
                "family": c["family"],
                "gear_ratio": c["gear_ratio"],
                "verdict": c["verdict"],
                "accel_torque_nm": c["accel_torque_nm"],
                "constant_torque_nm": c["constant_torque_nm"],
                "decel_torque_nm": c["decel_torque_nm"],
                "rms_torque_nm": c["rms_torque_nm"],
                "checks": checks,
                "controllers_excluded": c["controllers_excluded"],
                "drive_options": drive_options,
            }
        )
    controllers = [
        {"manufacturer": m, "type": t, "variant": v, "source_row": r} for m, t, v, r in refs
    ]
    return {
        **{k: v for k, v in answer.items() if k != "candidates"},
        "check_rules": list(rules.values()),
        "controllers": controllers,
        "candidates": candidates,
    }
