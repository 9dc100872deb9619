"""A batch's cases and candidates without words written as rows of pieces, joined once.

Each case of a slice is a row of byte strings, in the order of its JSON text: the
literal text between members (the same in every row) and each member's JSON (a list
over the rows). A candidate's members sit in its case's row, its checks' JSON among
them, so that the slice's text is one ``b"".join`` of every piece: each byte is copied
into the answer once. Filling a template per candidate and then one per case, and
joining the cases, copied the checks' bytes (most of the 110 MB answer of 10,000 cases)
three times more (:func:`case_rows` of :func:`candidate_columns`).
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Sequence

import numpy as np
import numpy.typing as npt

from actuator_selection.services.presenters.selection import (
    LOAD_KEYS,
    LOAD_TEMPLATE,
    dump_json,
    json_items,
    load_columns,
)
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.axis import AxisLoad

Column = bytes | list[bytes]
"""A piece of every row: the same literal text (bytes), or each row's own (a list)."""


def candidate_columns(
    actuators: list[bytes],
    verdicts: list[bytes],
    torques: Sequence[list[bytes]],
    reason_checks: list[bytes],
    checks: list[bytes] | None,
    controllers: list[bytes] | None,
    summaries: list[bytes],
    reasons: list[bytes] | None = None,
) -> list[Column]:
    """Each cell's batch candidate (``batch_candidate_body`` of
    ``services/presenters/batch.py`` as ``dump_json`` writes it) as columns over the
    cells, from each member's JSON over the cells: ``actuators`` the actuator's members
    (``"model":…,"family":…,"gear_ratio":…``), ``verdicts`` and ``torques`` (T_1, T_2,
    T_3, T_rms) its values, ``reason_checks`` the list, ``checks`` the list
    (``coded_checks_json``; None: not asked for), ``controllers`` the list (None: not
    asked for), ``summaries`` the members of the controllers' summary each after a
    comma, and ``reasons`` the list of words (None: without words, as
    ``coded_candidate_body`` has it; with words ``reason_checks`` comes last, as
    ``candidate_body`` and then ``batch_candidate_body`` put it)."""
    accel, constant, decel, rms = torques
    columns: list[Column] = [
        b"{",
        actuators,
        b',"verdict":',
        verdicts,
        b',"accel_torque_nm":',
        accel,
        b',"constant_torque_nm":',
        constant,
        b',"decel_torque_nm":',
        decel,
        b',"rms_torque_nm":',
        rms,
    ]
    columns += (
        [b',"reason_checks":', reason_checks] if reasons is None else [b',"reasons":', reasons]
    )
    if checks is not None:
        columns += [b',"checks":', checks]
    if controllers is not None:
        columns += [b',"controllers":', controllers]
    columns.append(summaries)
    if reasons is not None:
        columns += [b',"reason_checks":', reason_checks]
    columns.append(b"}")
    return columns


_LOAD_TEXT = LOAD_TEMPLATE.split(b"%b")
"""A case's ``load`` between its members' values (``LOAD_TEMPLATE``'s literal text)."""


def case_rows(
    ids: list[bytes],
    case_ids: list[bytes],
    loads: Sequence[list[bytes]],
    figures: Sequence[list[bytes]],
    candidates: list[Column],
    counts: Sequence[int],
) -> list[Column]:
    """Each case's entry of ``results`` as columns over the cases, each case after a
    comma: the text ``case_body`` of ``services/presenters/batch.py`` has ``dump_json``
    write, from its members' JSON: ``loads`` the members of its ``load``
    (``load_columns``), ``figures`` the cycle times, mean speeds and duty cycles,
    ``candidates`` every case's candidates in turn as :func:`candidate_columns` over the
    cells (``counts`` of them a case)."""
    columns: list[Column] = [b',{"id":', ids, b',"case_id":', case_ids, b',"load":']
    for text, member in zip(_LOAD_TEXT, loads, strict=False):
        columns += [text, member]
    columns += [
        _LOAD_TEXT[-1] + b',"cycle_time_s":',
        figures[0],
        b',"mean_speed_rpm":',
        figures[1],
        b',"duty_cycle_percent":',
        figures[2],
        b',"candidates":[',
    ]
    if counts and min(counts) == max(counts):  # as many in every case: their columns in turn
        n = counts[0]
        for k in range(n):
            if k:
                columns.append(b",")
            columns += [c if isinstance(c, bytes) else c[k::n] for c in candidates]
    else:
        written = [b"".join(row) for row in rows(candidates, sum(counts))]
        ends = itertools.accumulate(counts)
        columns.append(
            [b",".join(written[end - n : end]) for end, n in zip(ends, counts, strict=True)]
        )
    columns.append(b"]}")
    return columns


def json_texts(values: Sequence[object]) -> list[bytes]:
    """Each of ``values`` as ``dump_json`` writes it (a case's ``id`` or ``case_id``),
    None as one shared ``null``, the rest copied out of orjson's text: orjson's own small
    answers, kept, cost several times a copy (10,000 cases' ids and case ids in slices of
    200: 7 ms against 0.3 ms; kept 10,000 at once, 2.5 µs each against 0.2 µs)."""
    return [_NULL if value is None else bytes(memoryview(dump_json(value))) for value in values]


_NULL = dump_json(None)


def case_loads(apps: Sequence[Application], peaks: npt.NDArray[np.float64]) -> list[list[bytes]]:
    """``load_columns`` of the cases' axis loads at their peak speeds ``peaks`` (each
    member of their ``load`` as JSON over the cases); where every case is the chapter's
    shorthand, read from its load as ``Application.axis_load`` makes it (T_L the friction,
    J_L, no weight, η 1) without an axis load per case."""
    loads = [app.load for app in apps if app.motion is None and app.load is not None]
    if len(loads) < len(apps):
        return load_columns([app.axis_load for app in apps], peaks)
    n = len(apps)
    return [
        json_items(peaks),
        _numbers([x.torque_nm for x in loads]),
        _numbers([x.inertia_kgm2 for x in loads]),
        _NO_WEIGHT * n,
        _NO_LOSS * n,
    ]


def _numbers(figures: list[float]) -> list[bytes]:
    """Each figure as JSON, as ``load_columns`` writes it."""
    if all(type(x) is float for x in figures):
        return json_items(np.array(figures, dtype=np.float64))
    return [dump_json(x) for x in figures]


_SHORTHAND_AXIS = AxisLoad(inertia_kgm2=0.0, friction_torque_nm=0.0)
assert LOAD_KEYS == ("speed_rpm", "torque_nm", "inertia_kgm2", "gravity_torque_nm", "efficiency")
_NO_WEIGHT = _numbers([_SHORTHAND_AXIS.gravity_torque_nm])
_NO_LOSS = _numbers([_SHORTHAND_AXIS.efficiency])
"""A shorthand's axis load's weight (0) and efficiency (1) as JSON, one item."""


def rows(columns: Sequence[Column], n: int) -> Iterator[tuple[bytes, ...]]:
    """Each of the ``n`` rows' pieces, in order."""
    every = [itertools.repeat(c, n) if isinstance(c, bytes) else c for c in columns]
    return zip(*every, strict=True)


def pieces(columns: Sequence[Column], n: int) -> list[bytes]:
    """Every piece of the ``n`` rows, row by row: joined, their text (literal text next
    to literal text joined already)."""
    merged: list[Column] = []
    for c in columns:
        if isinstance(c, bytes) and merged and isinstance(merged[-1], bytes):
            merged[-1] += c
        else:
            merged.append(c)
    return list(itertools.chain.from_iterable(rows(merged, n)))
