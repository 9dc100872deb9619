"""The engine: the flowchart for every load case × actuator, as arrays, block by block.

:func:`evaluate_batch` keeps every array; :func:`rank_batch` ranks; :func:`select_batch`
ranks and details the best of each case (:mod:`~actuator_selection.sizing.engine.detail`).
One selection is the engine's 1 × N view (:func:`select`), one actuator's candidate its
1 × 1 view (:func:`evaluate`): the same arrays, the same rules, whatever the size.

Worked example (Table 516.1 against the FHA-25C-50-L of Table 516.3), two cases:

>>> from actuator_selection.catalogue.actuators import Actuator
>>> from actuator_selection.sizing.cycle import Load, SpeedPattern
>>> fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50,
...                max_torque_nm=151, max_speed_rpm=90, inertia_kgm2=0.86)
>>> pattern = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1)
>>> apps = [Application(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=1.3)),
...         Application(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=3.0))]
>>> ev = evaluate_batch([fha], apps)
>>> [round(t, 2) for t in ev.accel_torque_nm[:, 0].tolist()]
[95.48, 166.69]
>>> [ev.verdict(i, 0).value for i in range(2)]
['unconfirmed', 'unsuitable']
>>> [s.candidates[0].verdict.value for s in select_batch([fha], apps, top=1)]
['unconfirmed', 'unsuitable']
"""

from __future__ import annotations

import itertools
from collections.abc import Collection, Iterator, Sequence
from dataclasses import dataclass
from dataclasses import field as dataclasses_field
from typing import Any

import numpy as np
import numpy.typing as npt

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.candidates import Candidate, Selection, Verdict
from actuator_selection.sizing.checks import RULES, Rule, Status, rules_for
from actuator_selection.sizing.engine.arrays import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BoolArray,
    CodeArray,
    FloatArray,
    IndexArray,
)
from actuator_selection.sizing.engine.block import CHECK_NAMES, Block, blocks, evaluate_block
from actuator_selection.sizing.engine.cases import (
    Cases,
    cases_of,
    zone_limit_float,
    zone_limits,
)
from actuator_selection.sizing.engine.catalogue import CatalogueArrays, catalogue_arrays
from actuator_selection.sizing.engine.detail import (
    CycleOf,
    DecidedCells,
    candidates_of,
    cell_torques,
    decide_cells,
    detail_cells,
)
from actuator_selection.sizing.engine.one_case import OneCase
from actuator_selection.sizing.motion import CycleFigures, figure_rows, profile_from


@dataclass(frozen=True, slots=True, eq=False, kw_only=True)
class BatchEvaluation:
    """The flowchart for every case (rows) × actuator (columns), as arrays.

    Torques are NaN where the actuator has no J_A (a candidate's ``torques`` is None).
    Every number equals, bit for bit, what the plain-float oracle of the tests gives.
    """

    mean_speed_rpm: FloatArray
    """n_av per case (Eq. 514.3) [rpm]."""
    duty_cycle_percent: FloatArray
    """ED per case (Eq. 514.4) [%]."""
    cycle_time_s: FloatArray
    """t_0 per case [s]."""
    accel_torque_nm: FloatArray
    """T_1 per case × actuator (Eq. 514.1) [Nm]."""
    constant_torque_nm: FloatArray
    """T_2 per case × actuator [Nm]; NaN where the cycle never runs at constant speed."""
    decel_torque_nm: FloatArray
    """T_3 per case × actuator [Nm]."""
    rms_torque_nm: FloatArray
    """T_rms per case × actuator (Eq. 514.2) [Nm]."""
    statuses: CodeArray
    """Status codes (:data:`STATUS_BY_CODE`), case × actuator × check (:attr:`check_names`)."""
    verdicts: CodeArray
    """Verdict codes (:data:`VERDICT_BY_CODE`), case × actuator."""
    values: FloatArray
    """Each check's value, case × actuator × check; NaN where unknown."""
    limits: FloatArray
    """Each check's limit, case × actuator × check; NaN where it has none."""
    approximate: BoolArray
    """Where a check's limit is a simplified stand-in, case × actuator × check."""
    first_missing: CodeArray
    """Per case × actuator × check, the index of the first requirement of the rule that
    the catalogue does not meet (its ``what`` in :attr:`missing_what`); −1: none."""
    worst_overload: FloatArray
    """Per case × actuator, the largest overload of its checks
    (:attr:`~actuator_selection.sizing.selection.Candidate.worst_overload`)."""
    missing_what: tuple[tuple[str, ...], ...] = ()
    """Per check, its requirements' ``what`` (:class:`~actuator_selection.sizing.checks.
    Requirement`), in order."""
    check_names: tuple[str, ...] = CHECK_NAMES
    """The checks (the rules' names) along the last axis of :attr:`statuses`."""
    rank_position: npt.NDArray[np.int32] = dataclasses_field(
        default_factory=lambda: np.empty(0, dtype=np.int32)
    )
    """Each actuator's place in the static order (T_max, J_A, model) that breaks ties."""

    def status(self, case: int, actuator: int, check: str) -> Status:
        """The status of one check of one case and actuator."""
        return STATUS_BY_CODE[int(self.statuses[case, actuator, self.check_names.index(check)])]

    def missing(self, case: int, actuator: int, check: str) -> str | None:
        """What the catalogue lacks for one check (``Check.missing``), or None."""
        k = self.check_names.index(check)
        index = int(self.first_missing[case, actuator, k])
        return None if index < 0 else self.missing_what[k][index]

    def verdict(self, case: int, actuator: int) -> Verdict:
        """The verdict of one case and actuator."""
        return VERDICT_BY_CODE[int(self.verdicts[case, actuator])]

    def ranking(self, case: int) -> list[int]:
        """The actuators of one case, best first
        (:func:`~actuator_selection.sizing.selection.ranking_key`: verdict, worst overload,
        then T_max, J_A and model)."""
        order = np.lexsort((self.rank_position, self.worst_overload[case], self.verdicts[case]))
        ranked: list[int] = order.tolist()
        return ranked


def evaluate_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> BatchEvaluation:
    """Run the flowchart for every case × actuator and keep every array.

    Parameters
    ----------
    actuators
        The catalogue, columns in this order.
    apps
        The load cases, rows in this order.
    rules
        The checks (:data:`~actuator_selection.sizing.checks.RULES`: the chapter's).
    arrays
        ``catalogue_arrays(actuators)``, where the caller keeps it.

    Memory grows with cases × actuators (about 40 bytes a cell); for ranking alone
    use :func:`select_batch`, which keeps only the best of each case.
    """
    rules = rules_of(apps, rules)
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    if len(apps) == 1 and len(actuators) == 1:  # one cell (a one-model selection's)
        one = OneCase.of(apps[0])  # on floats: no arrays for its case
        zone = zone_limit_float(actuators[0], one.floats.mean_speed_rpm)
        block = evaluate_block(cat, one, zone, rules, detail=True)
        return _evaluation(block, one.figures, rules, cat)
    cases = cases_of(apps)
    limits_of_zones = zone_limits(actuators, cat.zone_columns, cases.mean_speed)
    shape = (len(apps), len(actuators))
    ranges = blocks(actuators, apps)
    if len(ranges) == 1:  # one block (a selection's): its arrays as they are
        return _evaluation(
            evaluate_block(cat, cases, limits_of_zones, rules, detail=True),
            cases.figures,
            rules,
            cat,
        )
    accel, constant, decel, rms = (np.empty(shape) for _ in range(4))
    checks = (*shape, len(rules))
    statuses = np.empty(checks, dtype=np.int8)
    values, limits = np.empty(checks), np.empty(checks)
    approximate = np.empty(checks, dtype=np.bool_)
    first_missing = np.empty(checks, dtype=np.int8)
    verdicts = np.empty(shape, dtype=np.int8)
    worst_overload = np.empty(shape)
    for start, stop in ranges:
        rows = cases.rows(start, stop)
        block = evaluate_block(cat, rows, limits_of_zones[start:stop], rules, detail=True)
        reported = block.checks
        assert reported is not None
        accel[start:stop] = block.accel_torque
        constant[start:stop] = block.constant_torque
        decel[start:stop] = block.decel_torque
        rms[start:stop] = block.rms_torque
        _put_checks(statuses[start:stop], block.statuses)
        _put_checks(values[start:stop], reported.values)
        _put_checks(limits[start:stop], reported.limits)
        _put_checks(approximate[start:stop], reported.approximate)
        _put_checks(first_missing[start:stop], reported.first_missing)
        verdicts[start:stop] = block.verdicts()
        worst_overload[start:stop] = block.overload
    return _assembled(
        cases.figures,
        rules,
        cat,
        accel_torque_nm=accel,
        constant_torque_nm=constant,
        decel_torque_nm=decel,
        rms_torque_nm=rms,
        statuses=statuses,
        verdicts=verdicts,
        values=values,
        limits=limits,
        approximate=approximate,
        first_missing=first_missing,
        worst_overload=worst_overload,
    )


def _evaluation(
    block: Block, figures: CycleFigures, rules: Sequence[Rule], cat: CatalogueArrays
) -> BatchEvaluation:
    """The :class:`BatchEvaluation` of one block of every case: the block's arrays, its
    rules' axis moved last (a copy each), not copied into arrays of the whole batch."""
    reported = block.checks
    assert reported is not None

    def checks_last(rules_first: npt.NDArray[Any]) -> npt.NDArray[Any]:
        if rules_first.shape[1:] == (1, 1):  # one cell: the same order in memory, as it is
            return rules_first.reshape(1, 1, -1)
        return np.ascontiguousarray(rules_first.transpose(1, 2, 0))

    return _assembled(
        figures,
        rules,
        cat,
        accel_torque_nm=block.accel_torque,
        constant_torque_nm=block.constant_torque,
        decel_torque_nm=block.decel_torque,
        rms_torque_nm=block.rms_torque,
        statuses=checks_last(block.statuses),
        verdicts=block.verdicts(),
        values=checks_last(reported.values),
        limits=checks_last(reported.limits),
        approximate=checks_last(reported.approximate),
        first_missing=checks_last(reported.first_missing),
        worst_overload=block.overload,
    )


def _assembled(
    figures: CycleFigures, rules: Sequence[Rule], cat: CatalogueArrays, **cells: npt.NDArray[Any]
) -> BatchEvaluation:
    """The :class:`BatchEvaluation` of the cases of ``figures`` from its arrays of cells by
    name."""
    key = tuple(rules)
    names = _NAMES.get(key)
    if names is None:  # per rule set, once (a selection's rules are one of a few sets)
        if len(_NAMES) > 64:  # rule sets made by the caller: keep it bounded
            _NAMES.clear()
        names = _NAMES[key] = (
            tuple(tuple(need.what for need in rule.requires) for rule in rules),
            tuple(rule.name for rule in rules),
        )
    return BatchEvaluation(
        mean_speed_rpm=figures.mean_speed_rpm,
        duty_cycle_percent=figures.duty_cycle_percent,
        cycle_time_s=figures.cycle_s,
        missing_what=names[0],
        check_names=names[1],
        rank_position=cat.rank_position,
        **cells,
    )


_NAMES: dict[tuple[Rule, ...], tuple[tuple[tuple[str, ...], ...], tuple[str, ...]]] = {}
"""Per rule set, :attr:`BatchEvaluation.missing_what` and :attr:`~BatchEvaluation.
check_names`."""


def _put_checks(cells: npt.NDArray[Any], rules: npt.NDArray[Any]) -> None:
    """A block's rules × cases × actuators into ``cells``, cases × actuators × checks (a
    contiguous part of the evaluation's array), as one copy of a transposed table."""
    count = rules.shape[0]
    if count:
        cells.reshape(-1, count)[...] = rules.reshape(count, -1).T


def _allowed_columns(
    actuators: Sequence[Actuator], models: Sequence[Collection[str] | None]
) -> list[BoolArray | None]:
    """Per case, the columns its ``models`` list allows (None: every one)."""
    column_of: dict[str, list[int]] = {}
    for j, a in enumerate(actuators):
        column_of.setdefault(a.model, []).append(j)
    masks: dict[frozenset[str], BoolArray] = {}
    allowed: list[BoolArray | None] = []
    for names in models:
        if names is None:
            allowed.append(None)
            continue
        key = frozenset(names)
        if key not in masks:
            mask = np.zeros(len(actuators), dtype=np.bool_)
            mask[[j for name in key for j in column_of.get(name, ())]] = True
            masks[key] = mask
        allowed.append(masks[key])
    return allowed


@dataclass(frozen=True, slots=True, eq=False)
class RankedBlock:
    """A block of cases ranked: its cases (from row ``start``), the flowchart's arrays, and
    each row's best ``top`` columns with where they are kept (False past the actuators a
    case's ``models`` allows)."""

    start: int
    cases: Cases
    block: Block
    verdicts: CodeArray
    """The block's verdict codes (:data:`VERDICT_BY_CODE`), beyond them where a case's
    ``models`` leave an actuator out."""
    order: IndexArray
    kept: BoolArray


def ranked_blocks(
    actuators: Sequence[Actuator],
    cases: Cases,
    *,
    top: int,
    models: Sequence[Collection[str] | None] | None,
    rules: Sequence[Rule],
    detail: bool,
    arrays: CatalogueArrays | None = None,
) -> Iterator[RankedBlock]:
    """The cases ranked block by block (:func:`~actuator_selection.sizing.selection.
    ranking_key`); ``detail``: with each check's values for the candidates' detail. The
    arguments as :func:`select_batch` has checked them, ``rules`` resolved."""
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    limits_of_zones = zone_limits(actuators, cat.zone_columns, cases.mean_speed)
    allowed = _allowed_columns(actuators, models) if models is not None else None
    excluded = np.int8(len(VERDICT_BY_CODE))  # a verdict code beyond every verdict
    keep = min(top, len(actuators))
    by_position = np.argsort(cat.rank_position)  # the actuators in the static order
    for start, stop in blocks(actuators, range(cases.size)):
        rows = cases.rows(start, stop)
        block = evaluate_block(cat, rows, limits_of_zones[start:stop], rules, detail=detail)
        # ranking_key: verdict, the worst overload (0 unless unsuitable), then the
        # actuator's place in the static order (T_max, J_A, model).
        verdicts = block.verdicts()
        if allowed is not None:
            for row, mask in enumerate(allowed[start:stop]):
                if mask is not None:
                    verdicts[row, ~mask] = excluded
        order = _best(verdicts, block.overload, cat.rank_position, by_position, keep)
        kept = np.take_along_axis(verdicts, order, axis=1) < excluded
        yield RankedBlock(
            start=start, cases=rows, block=block, verdicts=verdicts, order=order, kept=kept
        )


_PICKED_UP_TO = 8
"""Up to this many candidates a case, :func:`_best` picks them one by one."""
_TAKEN = np.iinfo(np.int64).max
_UNSUITABLE = np.int8(VERDICT_BY_CODE.index(Verdict.UNSUITABLE))


def _best(
    verdicts: CodeArray,
    overload: FloatArray,
    position: npt.NDArray[np.int32],
    by_position: IndexArray,
    keep: int,
) -> IndexArray:
    """Each row's first ``keep`` columns by verdict, worst overload, then ``position``
    (``by_position`` its argsort): ``np.lexsort((position, overload, verdicts))[:, :keep]``.

    Where few are kept, picked one by one instead: a key per cell in the static order,
    its verdict code, an unsuitable one's overload by its bits (a float ≥ 1 or ∞: its
    bits order as it does, above every code), a code beyond the verdicts last (in the
    static order, where lexsort orders them by overload too: every caller drops them);
    the first smallest (``argmin``) is the first by position. A 1,024 × 64 block, 3 kept: 0.4 ms
    against 1.5 ms. Only there an overload is 0 but where a check fails (then ≥ 1), so an
    overload of NaN (∞/∞) is sorted as it is."""
    if keep > _PICKED_UP_TO or np.isnan(overload).any():
        position_ = np.broadcast_to(position, verdicts.shape)
        return np.lexsort((position_, overload, verdicts), axis=-1)[:, :keep]
    codes = verdicts.take(by_position, axis=1)
    key = codes.astype(np.int64)
    np.copyto(key, _TAKEN - 1, where=codes > _UNSUITABLE)  # left out by a case's models
    bits = np.broadcast_to(overload, verdicts.shape).take(by_position, axis=1)
    np.copyto(key, bits.view(np.int64), where=codes == _UNSUITABLE)
    rows = np.arange(key.shape[0])
    picked = np.empty((key.shape[0], keep), dtype=np.intp)
    for k in range(keep):
        at = key.argmin(axis=1)
        picked[:, k] = at
        key[rows, at] = _TAKEN
    best: IndexArray = by_position[picked]
    return best


def rules_of(apps: Sequence[Application], rules: Sequence[Rule] | None) -> Sequence[Rule]:
    """``rules``, or the rules the cases need
    (:func:`~actuator_selection.sizing.checks.rules_for`), one set for all."""
    if rules is not None:
        return rules
    needed = {rules_for(app) for app in apps}
    if len(needed) > 1:
        raise InvalidInputError(
            "brake",
            "cases with different checks (with and without a brake or an output load) "
            "need separate runs",
        )
    return needed.pop() if needed else RULES


def check_arguments(cases: int, top: int, models: Sequence[Collection[str] | None] | None) -> None:
    if top < 1:
        raise InvalidInputError("top", "must be ≥ 1: the number of candidates kept per case")
    if models is not None and len(models) != cases:
        raise InvalidInputError("models", "needs one entry (or None) per load case")


def rank_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    top: int = 3,
    models: Sequence[Collection[str] | None] | None = None,
    rules: Sequence[Rule] | None = None,
) -> list[list[int]]:
    """Per case, the indexes into ``actuators`` of its best ``top``, best first.

    The ranking of :func:`select` (:func:`~actuator_selection.sizing.selection.ranking_key`)
    without building the candidates; arguments as for :func:`select_batch`.
    """
    check_arguments(len(apps), top, models)
    rules = rules_of(apps, rules)
    chosen: list[list[int]] = []
    for ranked in ranked_blocks(
        actuators, cases_of(apps), top=top, models=models, rules=rules, detail=False
    ):
        chosen.extend(
            [j for j, k in zip(row, row_kept, strict=True) if k]
            for row, row_kept in zip(ranked.order.tolist(), ranked.kept.tolist(), strict=True)
        )
    return chosen


@dataclass(frozen=True, slots=True, eq=False)
class RankedCells:
    """A block of cases ranked (from case ``start``) and its best cells detailed: the
    cases' figures, and for each case's candidates in order (``counts`` of them a case)
    the actuator, verdict code, torques and the rules' decisions, as arrays over the
    cells: what :func:`select_batch` builds its selections from."""

    start: int
    figures: CycleFigures
    holding: FloatArray
    counts: list[int]
    rows: IndexArray
    columns: IndexArray
    verdicts: CodeArray
    torques: tuple[FloatArray, FloatArray, FloatArray, FloatArray]
    """T_1, T_2, T_3 and T_rms of each cell (NaN: T_2 without a constant piece)."""
    decided: DecidedCells
    block: Block
    block_verdicts: CodeArray


def ranked_cells(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    top: int = 3,
    models: Sequence[Collection[str] | None] | None = None,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> Iterator[RankedCells]:
    """The best ``top`` cells of every load case block by block, as :func:`select_batch`
    takes them (its arguments), before any object per case or candidate is built."""
    check_arguments(len(apps), top, models)
    rules = rules_of(apps, rules)
    for ranked in ranked_blocks(
        actuators,
        cases_of(apps),
        top=top,
        models=models,
        rules=rules,
        detail=True,
        arrays=arrays,
    ):
        order, kept = ranked.order, ranked.kept
        rows = np.broadcast_to(np.arange(order.shape[0])[:, np.newaxis], order.shape)[kept]
        columns = order[kept]
        yield RankedCells(
            start=ranked.start,
            figures=ranked.cases.figures,
            holding=ranked.cases.pieces.holding,
            counts=kept.sum(axis=1).tolist(),
            rows=rows,
            columns=columns,
            verdicts=ranked.verdicts[rows, columns],
            torques=cell_torques(ranked.block, rows, columns),
            decided=decide_cells(rules, ranked.block, rows, columns),
            block=ranked.block,
            block_verdicts=ranked.verdicts,
        )


def select_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    *,
    top: int = 3,
    models: Sequence[Collection[str] | None] | None = None,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> list[Selection]:
    """The best ``top`` candidates of every load case, ranked as :func:`select` ranks them.

    Equal to ``select(actuators, app)`` with its candidates cut to ``top``, case by case
    (and to ``select`` over the actuators named in ``models[i]``, where given): the
    arrays rank and detail the chosen few (:func:`_detail`).

    Parameters
    ----------
    actuators
        The catalogue.
    apps
        The load cases.
    top
        Candidates kept per case, ≥ 1.
    models
        Per case, the model names it may use (None: the whole catalogue); names not in
        ``actuators`` are ignored. None: every case uses the whole catalogue.
    rules
        The checks (:data:`~actuator_selection.sizing.checks.RULES`: the chapter's), for the
        arrays and for the candidates alike.
    """
    selections = []
    for ranked in ranked_cells(actuators, apps, top=top, models=models, rules=rules, arrays=arrays):
        cases = apps[ranked.start : ranked.start + len(ranked.counts)]
        profiles = [
            profile_from(CycleOf(app), app.axis_load, row_figures, row_holding)
            for app, row_figures, row_holding in zip(
                cases, figure_rows(ranked.figures), ranked.holding.tolist(), strict=True
            )
        ]
        detailed = iter(
            candidates_of(
                actuators,
                ranked.decided,
                ranked.verdicts,
                ranked.torques,
                ranked.rows,
                ranked.columns,
                profiles,
            )
        )
        for profile, count in zip(profiles, ranked.counts, strict=True):
            selections.append(
                Selection(
                    mean_speed_rpm=profile.mean_speed_rpm,
                    duty_cycle_percent=profile.duty_cycle_percent,
                    cycle_time_s=profile.cycle_s,
                    candidates=tuple(itertools.islice(detailed, count)),
                    profile=profile,
                )
            )
    return selections


def evaluate_each(
    actuators: Sequence[Actuator],
    app: Application,
    *,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> list[Candidate]:
    """The candidate of each of ``actuators`` for ``app``, in their order: the engine's
    1 × N view, each candidate detailed from the arrays (``rules``: by default
    :func:`~actuator_selection.sizing.checks.rules_for`)."""
    rules = rules_of([app], rules)
    if not actuators:
        return []
    app.profile  # noqa: B018 - computed first: the engine takes the profile's figures
    cat = catalogue_arrays(actuators) if arrays is None else arrays
    cases = cases_of([app])
    block = evaluate_block(
        cat,
        cases,
        zone_limits(actuators, cat.zone_columns, cases.mean_speed),
        rules,
        detail=True,
    )
    columns = np.arange(len(actuators), dtype=np.intp)
    return detail_cells(
        actuators,
        rules,
        block,
        block.verdicts(),
        np.zeros_like(columns),
        columns,
        [app.profile],
    )


def evaluate(
    actuator: Actuator,
    app: Application,
    *,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> Candidate:
    """The candidate of one actuator for ``app``: the engine's 1 × 1 view."""
    (candidate,) = evaluate_each((actuator,), app, rules=rules, arrays=arrays)
    return candidate


def select(
    actuators: Sequence[Actuator],
    app: Application,
    *,
    rules: Sequence[Rule] | None = None,
) -> Selection:
    """Every actuator's candidate for ``app``, ranked
    (:func:`~actuator_selection.sizing.candidates.ranking_key`): the engine's 1 × N view."""
    if not actuators:
        profile = app.profile
        return Selection(
            mean_speed_rpm=profile.mean_speed_rpm,
            duty_cycle_percent=profile.duty_cycle_percent,
            cycle_time_s=profile.cycle_s,
            candidates=(),
            profile=profile,
        )
    app.profile  # noqa: B018 - computed first: the engine takes the profile's figures
    (selection,) = select_batch(actuators, [app], top=len(actuators), rules=rules)
    return selection


def evaluate_cases(
    actuator: Actuator,
    apps: Sequence[Application],
    *,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> list[Candidate]:
    """The candidate of one actuator for each of ``apps``: the engine's M × 1 view (the
    inverse solve's probes, a batch of them at once)."""
    if not apps:
        return []
    chosen = select_batch((actuator,), apps, top=1, rules=rules, arrays=arrays)
    return [selection.candidates[0] for selection in chosen]


def case_verdicts(
    actuator: Actuator,
    apps: Sequence[Application],
    *,
    rules: Sequence[Rule] | None = None,
    arrays: CatalogueArrays | None = None,
) -> list[Verdict | None]:
    """The verdict of one actuator for each of ``apps``: :func:`evaluate_cases`'
    verdicts from the status codes alone, no candidate built and no check worded (the
    inverse solve's probes, which decide on the verdict). None where a finite input
    overflowed a torque: the candidate (:func:`evaluate_cases`) names the input."""
    if not apps:
        return []
    rules = rules_of(apps, rules)
    cat = catalogue_arrays((actuator,)) if arrays is None else arrays
    cases = cases_of(apps)
    limits_of_zones = zone_limits((actuator,), cat.zone_columns, cases.mean_speed)
    known = actuator.inertia_kgm2 is not None
    out: list[Verdict | None] = []
    for start, stop in blocks((actuator,), apps):
        block = evaluate_block(
            cat, cases.rows(start, stop), limits_of_zones[start:stop], rules, detail=False
        )
        finite = (
            np.isfinite(block.accel_torque[:, 0])
            & np.isfinite(block.decel_torque[:, 0])
            & np.isfinite(block.rms_torque[:, 0])
        )
        out.extend(
            VERDICT_BY_CODE[code] if ok or not known else None
            for code, ok in zip(block.verdicts()[:, 0].tolist(), finite.tolist(), strict=True)
        )
    return out
