"""selections.ranking_zstd: an answer lists the ranking's first candidates, the rest beside it

Version 3 of the stored answer (``services.presenters.selection.ANSWER_VERSION``): the
answer lists the ranking's first ``top`` candidates (100 unless the request asked for
another number) with ``total_candidates``, ``verdict_counts`` and ``next_cursor``; the
rest of the ranking is stored in the new column ``ranking_zstd`` (zstd-compressed JSON)
and read page by page (GET /selections/{id}/candidates?cursor=…).

This migration rewrites each version-2 answer (every candidate listed) to version 3: the
first 100 candidates stay in the answer (those a version-2 answer gave drive options),
the rest go to ``ranking_zstd`` as they were (``{"start": 100, "rows": [...]}``, which
the reader takes beside the columns it writes itself), and the counts and the cursor are
added. Every figure stays as it was. The downgrade puts the rest back into the answer.

The code is this migration's own (a migration must not change when the application
does); ``tests/db/test_answer_upgrade.py`` runs it on answers as the old code wrote them.

Revision ID: 0018
Revises: 0017
Create Date: 2026-11-27
"""

from __future__ import annotations

import base64
import gzip
import json
import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import sqlalchemy as sa
import zstandard
from alembic import op

revision: str = "0018"
down_revision: str | None = "0017"
branch_labels: str | Sequence[str] | None = None
depends_on: str | Sequence[str] | None = None

JSON = dict[str, Any]

TOP = 100
"""Candidates a version-3 answer lists by default (``presenters.selection.DEFAULT_TOP``)."""

_SELECTIONS = sa.table(
    "selections",
    sa.column("id", sa.String),
    sa.column("answer_gzip", sa.LargeBinary),
    sa.column("answer_version", sa.Integer),
    sa.column("ranking_zstd", sa.LargeBinary),
)

_CHUNK = 200
"""Rows read and rewritten at a time."""

_VERDICTS = ("suitable", "unconfirmed", "unsuitable")


def upgrade() -> None:
    op.add_column("selections", sa.Column("ranking_zstd", sa.LargeBinary(), nullable=True))
    _rewrite(2, 3, _lean)


def downgrade() -> None:
    _rewrite(3, 2, _whole)
    op.drop_column("selections", "ranking_zstd")


def _rewrite(before: int, after: int, change: Any) -> None:
    """Each stored answer of version ``before`` through ``change`` to version ``after``."""
    connection = op.get_bind()
    table = _SELECTIONS
    ids = (
        connection.execute(
            sa.select(table.c.id).where(table.c.answer_version == before).order_by(table.c.id)
        )
        .scalars()
        .all()
    )
    for start in range(0, len(ids), _CHUNK):
        rows = connection.execute(
            sa.select(table.c.id, table.c.answer_gzip, table.c.ranking_zstd).where(
                table.c.id.in_(ids[start : start + _CHUNK])
            )
        ).all()
        for row in rows:
            answer = json.loads(gzip.decompress(row.answer_gzip))
            rest = None if row.ranking_zstd is None else _unpacked(row.ranking_zstd)
            changed = change(row.id, answer, rest)
            if changed is None:  # in the shape already: only the version is recorded
                connection.execute(
                    table.update().where(table.c.id == row.id).values(answer_version=after)
                )
                continue
            answer, rest = changed
            connection.execute(
                table.update()
                .where(table.c.id == row.id)
                .values(
                    answer_gzip=gzip.compress(_dumped(answer), compresslevel=1, mtime=0),
                    answer_version=after,
                    ranking_zstd=None if rest is None else _packed(rest),
                )
            )


def _dumped(data: Any) -> bytes:
    return json.dumps(data, ensure_ascii=False, separators=(",", ":")).encode()


def _packed(data: JSON) -> bytes:
    return zstandard.ZstdCompressor(level=1).compress(_dumped(data))


def _unpacked(stored: bytes) -> JSON:
    """A stored rest of a ranking: JSON (``rows``), or columns (``RNK1``: a JSON header,
    then the arrays' bytes, as ``ranking_rest`` writes them as of this revision)."""
    raw = zstandard.ZstdDecompressor().decompress(stored)
    if not raw.startswith(b"RNK1"):
        data: JSON = json.loads(raw)
        return data
    size = int.from_bytes(raw[4:8], "little")
    header: JSON = json.loads(raw[8 : 8 + size])
    offset = 8 + size
    for name, dtype, shape in header["arrays"]:
        array = np.frombuffer(raw, dtype=dtype, count=int(np.prod(shape)), offset=offset)
        offset += array.nbytes
        header[name] = array.reshape(shape).tolist()  # NaN stays NaN: None below
    return header


def _cursor(selection_id: str, place: int) -> str:
    """``services.selections.cursor`` as of this revision."""
    return base64.urlsafe_b64encode(f"{place}:{selection_id}".encode()).rstrip(b"=").decode()


def _lean(selection_id: str, answer: JSON, rest: JSON | None) -> tuple[JSON, JSON | None] | None:
    """A version-2 answer as version 3, and the rest of its ranking to store (or None);
    None for an answer written in version 3's shape already (by the code of this
    revision into a database not yet upgraded), left byte for byte."""
    if "total_candidates" in answer:
        return None
    candidates = answer["candidates"]
    counts = dict.fromkeys(_VERDICTS, 0)
    for c in candidates:
        counts[c["verdict"]] += 1
    out: JSON = {}
    for key, value in answer.items():
        if key == "candidates":
            out["candidates"] = candidates[:TOP]
            out["total_candidates"] = len(candidates)
            out["verdict_counts"] = counts
            out["next_cursor"] = _cursor(selection_id, TOP) if len(candidates) > TOP else None
        else:
            out[key] = value
    return out, ({"start": TOP, "rows": candidates[TOP:]} if len(candidates) > TOP else None)


def _whole(selection_id: str, answer: JSON, rest: JSON | None) -> tuple[JSON, JSON | None]:
    """A version-3 answer as version 2: every candidate listed."""
    listed = answer["candidates"] + ([] if rest is None else _rows(rest))
    out = {k: v for k, v in answer.items() if k not in _ADDED}
    out["candidates"] = listed
    return out, None


_ADDED = ("total_candidates", "verdict_counts", "next_cursor")


def _rows(rest: JSON) -> list[JSON]:
    """The candidates of a stored rest of a ranking, as ``ranked_candidates`` reads them
    (as of this revision)."""
    if "rows" in rest:
        rows: list[JSON] = rest["rows"]
        return rows
    names, what, statuses = rest["checks"], rest["missing_what"], rest["statuses"]
    out = []
    for j, model in enumerate(rest["model"]):
        checks = []
        for k, name in enumerate(names):
            check: JSON = {
                "name": name,
                "status": statuses[rest["status"][j][k]],
                "value": _number(rest["value"][j][k]),
                "limit": _number(rest["limit"][j][k]),
            }
            if rest["approximate"][j][k]:
                check["approximate"] = True
            if rest["missing"][j][k] >= 0:
                check["missing"] = what[k][rest["missing"][j][k]]
            checks.append(check)
        torques = [_number(column[j]) for column in rest["torques"]]
        out.append(
            {
                "model": model,
                "family": rest["family"][j],
                "gear_ratio": rest["gear_ratio"][j],
                "verdict": rest["verdict"][j],
                "accel_torque_nm": torques[0],
                "constant_torque_nm": torques[1],
                "decel_torque_nm": torques[2],
                "rms_torque_nm": torques[3],
                "checks": checks,
                "controllers_excluded": rest["controllers_excluded"][j],
                "drive_options": None,
            }
        )
    return out


def _number(value: Any) -> Any:
    """A stored float as the answer writes it: NaN (unknown) as None."""
    return None if isinstance(value, float) and math.isnan(value) else value
