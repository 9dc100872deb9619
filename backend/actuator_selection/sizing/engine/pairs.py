"""The engine on given (case, actuator) pairs, not on their product: case ``rows[p]`` on
actuator ``columns[p]``, for searches that ask each actuator about a value of its own
(the ratio study's bisection, :mod:`actuator_selection.sizing.ratio`).

The pairs run through the one block (:func:`~actuator_selection.sizing.engine.block.
evaluate_block`) as a column: the cases taken pair by pair (P rows), the catalogue's
values taken pair by pair as a column (P × 1), so that every array of the block is P × 1
and each cell is one pair. What the block reads per actuator beside the operands goes in
with the case: the actuator's τ_th where it publishes one (as the block's heating picks
it), and the zone's edge at the case's n_av (:class:`~actuator_selection.sizing.engine.
cases.ZoneTable`). Each cell is the same arithmetic as in the product, so a pair's
numbers equal its cell of :func:`~actuator_selection.sizing.engine.evaluate_batch` bit for
bit (``tests/sizing/test_ratio_search.py``: ``test_pairs_equal_their_cells_of_the_product``).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence

import numpy as np

from actuator_selection.sizing.checks import Rule
from actuator_selection.sizing.engine.arrays import IndexArray
from actuator_selection.sizing.engine.block import Block, evaluate_block
from actuator_selection.sizing.engine.cases import Cases, ZoneTable
from actuator_selection.sizing.engine.catalogue import CatalogueArrays, Lacking
from actuator_selection.sizing.engine.codes import summarised


def paired_catalogue(cat: CatalogueArrays, columns: IndexArray) -> CatalogueArrays:
    """The catalogue's values of actuator ``columns[p]`` for each pair, as a column (P × 1);
    τ_th left out (:func:`paired_cases` carries it), the zone's edge one column."""
    col = np.newaxis
    taken = {name: values.take(columns)[:, col] for name, values in cat.operands.items()}
    has_zone = bool(np.asarray(taken["has_zone"]).any())
    return CatalogueArrays(
        operands=taken,
        # one NaN: the block's heating takes each pair's τ_th from its case
        thermal_time_constant=np.full(1, math.nan),
        heating_slope=cat.heating_slope.take(columns)[:, col],
        zone_columns=np.zeros(1 if has_zone else 0, dtype=np.intp),
        rank_position=cat.rank_position[columns],
        model_rank=cat.model_rank[columns],
    )


def catalogue_part(cat: CatalogueArrays, columns: IndexArray) -> CatalogueArrays:
    """The actuators ``columns`` (ascending) of ``cat`` as a catalogue of their own, a row
    as the whole one: the product of cases × part of the catalogue (the ratio study's grid
    on the actuators that can be listed). Where the whole catalogue lacks data is taken
    from its, for each rule set it has evaluated."""
    return CatalogueArrays(
        operands={name: values.take(columns) for name, values in cat.operands.items()},
        thermal_time_constant=cat.thermal_time_constant.take(columns),
        heating_slope=cat.heating_slope.take(columns),
        zone_columns=np.flatnonzero(cat.operands["has_zone"].take(columns)),
        rank_position=cat.rank_position.take(columns),
        model_rank=cat.model_rank.take(columns),
        lacking={
            rules: _lacking_of(rules, lack, columns, (len(rules), 1, -1))
            for rules, lack in cat.lacking.items()
        },
    )


def _lacking_of(
    rules: tuple[Rule, ...], lack: Lacking, columns: IndexArray, shape: tuple[int, ...]
) -> Lacking:
    """The whole catalogue's ``lack`` (rules × 1 × actuators) of the actuators
    ``columns``, as ``shape``."""
    return summarised(
        rules,
        lack.first_missing.take(columns, axis=2).reshape(shape),
        lack.others_missing.take(columns, axis=2).reshape(shape),
    )


def paired_cases(
    cases: Cases, rows: IndexArray, cat: CatalogueArrays, columns: IndexArray
) -> Cases:
    """Case ``rows[p]`` for each pair, with actuator ``columns[p]``'s τ_th where the
    catalogue publishes one (then not assumed), as the block's heating takes it."""
    taken = cases.take(rows)
    published = cat.thermal_time_constant[columns]
    own = np.isnan(published)
    return dataclasses.replace(
        taken,
        thermal_time_constant=np.where(own, taken.thermal_time_constant, published),
        thermal_assumed=taken.thermal_assumed & own,
    )


def evaluate_pairs(
    cat: CatalogueArrays,
    zones: ZoneTable,
    cases: Cases,
    rows: IndexArray,
    columns: IndexArray,
    rules: Sequence[Rule],
    *,
    detail: bool = True,
    overload: bool = True,
) -> Block:
    """The flowchart for case ``rows[p]`` on actuator ``columns[p]``, pair by pair: a
    :class:`~actuator_selection.sizing.engine.block.Block` of P × 1 cells.

    ``cat`` and ``zones`` are the whole catalogue's (``catalogue_arrays``,
    ``zone_table`` of the same actuators), ``cases`` the distinct cases; ``detail`` and
    ``overload`` as :func:`~actuator_selection.sizing.engine.block.evaluate_block`'s."""
    rows, columns = np.asarray(rows, dtype=np.intp), np.asarray(columns, dtype=np.intp)
    paired = paired_catalogue(cat, columns)
    key = tuple(rules)
    lack = cat.lacking.get(key)
    if lack is not None:  # the whole catalogue's (rules × 1 × actuators), pair by pair
        paired.lacking[key] = _lacking_of(key, lack, columns, (len(rules), -1, 1))
    pairs = paired_cases(cases, rows, cat, columns)
    edges = zones.edges(columns, pairs.mean_speed)[:, np.newaxis]
    zone = edges if paired.zone_columns.size else np.empty((rows.size, 0))
    return evaluate_block(paired, pairs, zone, rules, detail=detail, overload=overload)
