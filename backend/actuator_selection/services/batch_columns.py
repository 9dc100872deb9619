"""Batch selection as columns (``POST /selections/batch/columns``): the engine's table
(``sizing.engine.rank_columns``) written as it is, each array at once, for clients that
read arrays (dataframes, ERP loaders); the per-case form is ``services/batch.py``."""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from typing import Any

import numpy as np

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.schemas.batch_columns import BatchColumnsRequest
from actuator_selection.schemas.checks import Localize
from actuator_selection.schemas.selections import RANKING_RULE
from actuator_selection.services.batch import Drives, too_many_candidates
from actuator_selection.services.catalogue import CatalogueSnapshot, DriveContext
from actuator_selection.services.errors import UseCaseError, entry
from actuator_selection.services.presenters.selection import dump_json
from actuator_selection.sizing.engine import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    CheckTable,
    RankedTable,
    TrapezoidColumns,
    rank_columns,
)

_COLUMNS = ("torque_nm", "inertia_kgm2", "accel_s", "constant_s", "decel_s", "pause_s")
"""The columns that must be as long as ``speed_rpm``."""


def check_columns(body: BatchColumnsRequest) -> None:
    """Refuse columns of unequal lengths, or more candidates than a batch answers (422)."""
    n = len(body.speed_rpm)
    lengths = {name: len(getattr(body, name)) for name in _COLUMNS}
    if isinstance(body.high_dynamics, list):
        lengths["high_dynamics"] = len(body.high_dynamics)
    if body.case_id is not None:
        lengths["case_id"] = len(body.case_id)
    errors = [
        entry(["body", name], "length_mismatch", "length_mismatch", cases=n, length=length)
        for name, length in lengths.items()
        if length != n
    ]
    errors += too_many_candidates(n, body.top)
    if errors:
        raise UseCaseError(errors)


def size_columns(
    body: BatchColumnsRequest, *, catalogue: CatalogueSnapshot, localize: Localize
) -> Iterator[bytes]:
    """The answer to ``body`` (within :func:`check_columns`) as JSON, piece by piece: the
    engine's table (``sizing.engine.rank_columns``) written as it is, each
    array at once as a JSON array, with words only in each model's controller note.

    The table is computed before this returns, so that an error in it is still an error
    answer; its JSON is then written while it is sent (:func:`_json_pieces`), so the
    document is never held whole (20,000 cases with checks: 23 MB). The request's
    columns are let go once they are arrays (``body``'s lists are empty afterwards).
    """
    n = len(body.speed_rpm)
    names = ("speed_rpm", *_COLUMNS)
    columns = TrapezoidColumns(
        **{name: np.array(getattr(body, name), dtype=np.float64) for name in names},
        high_dynamics=np.broadcast_to(np.array(body.high_dynamics, dtype=np.bool_), (n,)),
        thermal_time_constant_s=body.thermal_time_constant_s,
    )
    for name in names:
        getattr(body, name).clear()
    actuators = tuple(catalogue.actuators_of(body.models))
    table = rank_columns(
        actuators,
        columns,
        top=body.top,
        checks=body.include_checks,
        arrays=catalogue.arrays(actuators),
    )
    models = np.array([a.model for a in actuators], dtype=object)
    answer = {
        "catalogue_version": catalogue.version,
        "ranking": RANKING_RULE,
        "cases": {
            "case_id": body.case_id,
            "cycle_time_s": table.cycle_time_s,
            "mean_speed_rpm": table.mean_speed_rpm,
            "duty_cycle_percent": table.duty_cycle_percent,
        },
        "candidates": {
            "case": table.case,
            "model": models[table.actuator].tolist(),
            "verdict": _VERDICT_NAMES[table.verdicts].tolist(),
            "accel_torque_nm": table.accel_torque_nm,
            "constant_torque_nm": table.constant_torque_nm,
            "decel_torque_nm": table.decel_torque_nm,
            "rms_torque_nm": table.rms_torque_nm,
        },
        "checks": None if table.checks is None else _check_columns(table.checks),
        "models": _model_columns(
            table, columns, actuators, Drives(DriveContext(catalogue), localize)
        ),
    }
    return _coalesced(_json_pieces(answer), STREAM_BYTES)


STREAM_BYTES = 1 << 18
"""Bytes of a table's JSON sent per piece (at least; an array is written whole)."""


def _json_pieces(value: Any) -> Iterator[bytes]:
    """``value`` as JSON (:func:`dump_json`'s), an object's members and a list of objects'
    items one at a time, any other value whole: joined, the pieces are ``dump_json(value)``."""
    if isinstance(value, dict) and value:
        opening = b"{"
        for key, member in value.items():
            yield opening + dump_json(key) + b":"
            yield from _json_pieces(member)
            opening = b","
        yield b"}"
    elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
        opening = b"["
        for item in value:
            yield opening
            yield from _json_pieces(item)
            opening = b","
        yield b"]"
    else:
        yield dump_json(value)


def _coalesced(pieces: Iterator[bytes], size: int) -> Iterator[bytes]:
    """``pieces`` joined into pieces of at least ``size`` bytes (the last one shorter)."""
    buffer = bytearray()
    for piece in pieces:
        buffer += piece
        if len(buffer) >= size:
            yield bytes(buffer)
            buffer.clear()
    if buffer:
        yield bytes(buffer)


_VERDICT_NAMES = np.array([v.value for v in VERDICT_BY_CODE], dtype=object)
_STATUS_NAMES = np.array([s.value for s in STATUS_BY_CODE], dtype=object)


def _check_columns(table: CheckTable) -> list[dict[str, Any]]:
    """``checks``: each rule's column of the table, as a single selection's check briefs
    give them (NaN is null: no value, or no limit)."""
    out = []
    for k, rule in enumerate(table.rules):
        # first_missing + 1 indexes (nothing, what the first requirement needs, …)
        what = np.array([None, *(need.what for need in rule.requires)], dtype=object)
        out.append(
            {
                "name": rule.name,
                "reference": rule.reference,
                "unit": rule.unit,
                "status": _STATUS_NAMES[table.statuses[k]].tolist(),
                "value": table.values[k],
                "limit": table.limits[k],
                "approximate": table.approximate[k],
                "missing": what[table.first_missing[k] + 1].tolist(),
            }
        )
    return out


def _model_columns(
    table: RankedTable,
    columns: TrapezoidColumns,
    actuators: Sequence[Actuator],
    drives: Drives,
) -> dict[str, list[Any]]:
    """``models``: each actuator the candidates name, in catalogue order, with what the
    per-case batch repeats on every candidate of it."""
    named, first = np.unique(table.actuator, return_index=True)
    speeds = columns.speed_rpm[table.case[first]].tolist()
    rows = [
        (actuators[j], drives.summary(actuators[j], speed))
        for j, speed in zip(named.tolist(), speeds, strict=True)
    ]
    return {
        "model": [a.model for a, _ in rows],
        "family": [a.family for a, _ in rows],
        "gear_ratio": [float(a.gear_ratio) for a, _ in rows],
        **{key: [summary[key] for _, summary in rows] for key in _SUMMARY_KEYS},
    }


_SUMMARY_KEYS = (
    "controllers_excluded",
    "controllers_note",
    "controllers_note_code",
    "controllers_note_params",
)
