"""The flowchart for columns of load cases (``rank_columns``) equals ``select_batch``.

Every comparison is ``==`` on the numbers (NaN in the table where a candidate has None):
the bulk path ranks and details with the same arrays as the per-case batch, which
the tests of ``test_batch.py`` hold to the scalar flowchart bit for bit.
"""

from __future__ import annotations

import dataclasses
import math
import random
from collections.abc import Sequence

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from tests import worked_example
from tests.oracle.test_engine_parity import (
    applications,
    boundary_actuators,
    catalogues,
    random_actuator,
    random_case,
)

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.checks import BRAKE_HOLDING, RULES, Rule
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    TrapezoidColumns,
    rank_columns,
    select_batch,
)
from actuator_selection.sizing.selection import Application


def columns_of(apps: Sequence[Application], tau: float | None = None) -> TrapezoidColumns:
    """The chapter's shorthand cases as columns."""
    patterns = [a.pattern for a in apps if a.pattern is not None]
    loads = [a.load for a in apps if a.load is not None]
    assert len(patterns) == len(loads) == len(apps), "the chapter's shorthand only"

    def column(values: list[float]) -> np.ndarray:
        return np.array(values, dtype=np.float64)

    return TrapezoidColumns(
        speed_rpm=column([p.speed_rpm for p in patterns]),
        accel_s=column([p.accel_s for p in patterns]),
        constant_s=column([p.constant_s for p in patterns]),
        decel_s=column([p.decel_s for p in patterns]),
        pause_s=column([p.pause_s for p in patterns]),
        torque_nm=column([x.torque_nm for x in loads]),
        inertia_kgm2=column([x.inertia_kgm2 for x in loads]),
        high_dynamics=np.array([a.high_dynamics for a in apps], dtype=np.bool_),
        thermal_time_constant_s=tau,
    )


def _or_none(x: float) -> float | None:
    return None if math.isnan(x) else x


def assert_table_like_select_batch(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    top: int,
    *,
    tau: float | None = None,
    rules: Sequence[Rule] = RULES,
) -> None:
    """rank_columns equals select_batch row for row: case, actuator, verdict, torques, and
    each check's status, value, limit, approximation and missing value."""
    cases = [dataclasses.replace(a, thermal_time_constant_s=tau) for a in apps]
    expected = select_batch(actuators, cases, top=top, rules=rules)
    table = rank_columns(actuators, columns_of(apps, tau), top=top, checks=True, rules=rules)
    bare = rank_columns(actuators, columns_of(apps, tau), top=top, rules=rules)
    assert bare.checks is None
    assert table.checks is not None
    assert table.checks.rules == tuple(rules)
    for name in ("case", "actuator", "verdicts"):
        assert np.array_equal(getattr(bare, name), getattr(table, name)), name

    assert table.cycle_time_s.tolist() == [s.cycle_time_s for s in expected]
    assert table.mean_speed_rpm.tolist() == [s.mean_speed_rpm for s in expected]
    assert table.duty_cycle_percent.tolist() == [s.duty_cycle_percent for s in expected]
    rows = [(i, c) for i, s in enumerate(expected) for c in s.candidates]
    assert table.case.tolist() == [i for i, _ in rows]
    assert [actuators[j] for j in table.actuator.tolist()] == [c.actuator for _, c in rows]
    assert [VERDICT_BY_CODE[v] for v in table.verdicts.tolist()] == [c.verdict for _, c in rows]
    for name in ("accel_torque_nm", "constant_torque_nm", "decel_torque_nm", "rms_torque_nm"):
        got = [_or_none(x) for x in getattr(table, name).tolist()]
        assert got == [getattr(c.torques, name) if c.torques else None for _, c in rows], name
        assert got == [_or_none(x) for x in getattr(bare, name).tolist()], name
    checks = table.checks
    for k, rule in enumerate(rules):
        scalar = [c.checks[k] for _, c in rows]
        assert {c.name for c in scalar} <= {rule.name}
        assert [STATUS_BY_CODE[s] for s in checks.statuses[k].tolist()] == [
            c.status for c in scalar
        ]
        assert [_or_none(x) for x in checks.values[k].tolist()] == [c.value for c in scalar]
        assert [_or_none(x) for x in checks.limits[k].tolist()] == [c.limit for c in scalar]
        assert checks.approximate[k].tolist() == [c.approximate for c in scalar]
        needs = [need.what for need in rule.requires]
        missing = [None if m < 0 else needs[m] for m in checks.first_missing[k].tolist()]
        assert missing == [c.missing for c in scalar]


@pytest.mark.parametrize("seed", range(4))
def test_seeded_random_catalogues_equal_select_batch(seed: int) -> None:
    rng = random.Random(seed)
    actuators = [random_actuator(rng, k) for k in range(40)]
    apps = [random_case(rng, actuators) for _ in range(150)]
    actuators += boundary_actuators(apps[:10])
    assert_table_like_select_batch(actuators, apps, top=3)
    assert_table_like_select_batch(actuators, apps, top=7, tau=45.0)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    actuators=catalogues(),
    apps=st.lists(applications, min_size=1, max_size=6),
    top=st.integers(min_value=1, max_value=9),
)
def test_hypothesis_columns_equal_select_batch(
    actuators: list[Actuator], apps: list[Application], top: int
) -> None:
    assert_table_like_select_batch(actuators, apps, top)


def test_the_worked_example_and_the_brake_rules() -> None:
    """Table 516.1 against the FHA-25C-50-L (Table 516.3): T_1 95.48 Nm, and the brake's
    check where the rules are the braked actuator's."""
    fha = dataclasses.replace(worked_example.FHA_25C_50_L, brake_holding_torque_nm=4.0)
    table = rank_columns([fha], columns_of([worked_example.APPLICATION]), top=1)
    assert round(table.accel_torque_nm[0], 2) == 95.48
    braked = [dataclasses.replace(worked_example.APPLICATION, brake=True)]
    assert_table_like_select_batch([fha], braked, top=1, rules=(*RULES, BRAKE_HOLDING))


def test_an_empty_catalogue_gives_figures_and_no_candidates() -> None:
    apps = [worked_example.APPLICATION] * 2
    assert_table_like_select_batch([], apps, top=3)
    assert rank_columns([], columns_of(apps), checks=True).case.size == 0


def test_many_cases_span_several_blocks() -> None:
    rng = random.Random(11)
    actuators = [random_actuator(rng, k) for k in range(7)]
    apps = [random_case(rng, actuators) for _ in range(12_000)]
    table = rank_columns(actuators, columns_of(apps), top=2)
    assert table.case.tolist() == [i for i in range(len(apps)) for _ in range(2)]
    sample = apps[::997]
    expected = select_batch(actuators, sample, top=2)
    rows = table.actuator.reshape(len(apps), 2)[::997]
    assert [[actuators[j] for j in r] for r in rows.tolist()] == [
        [c.actuator for c in s.candidates] for s in expected
    ]


# --- what the columns refuse ------------------------------------------------------------


def _columns(**changed: list[float]) -> TrapezoidColumns:
    base = columns_of([worked_example.APPLICATION] * 3)
    return dataclasses.replace(base, **{k: np.array(v) for k, v in changed.items()})  # type: ignore[arg-type]


@pytest.mark.parametrize(
    ("field", "values", "row"),
    [
        ("speed_rpm", [40.0, 40.0, 0.0], 2),
        ("accel_s", [0.1, -0.1, 0.1], 1),
        ("decel_s", [0.0, 0.1, 0.1], 0),
        ("constant_s", [0.1, 0.1, -1.0], 2),
        ("pause_s", [1.0, math.inf, 1.0], 1),
        ("torque_nm", [5.0, math.nan, -5.0], 1),
        ("inertia_kgm2", [1.3, 1.3, -2.0], 2),
    ],
)
def test_a_row_is_refused_with_the_scalar_error(field: str, values: list[float], row: int) -> None:
    """The scalar classes' own error, its field named with the first row that breaks one."""
    if field in ("torque_nm", "inertia_kgm2"):
        with pytest.raises(InvalidInputError) as scalar:
            Load(**{"torque_nm": 5.0, "inertia_kgm2": 1.3, field: values[row]})
    else:
        pattern = {"speed_rpm": 40.0, "accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1}
        with pytest.raises(InvalidInputError) as scalar:
            SpeedPattern(**{**pattern, "pause_s": 1.0, field: values[row]})
    with pytest.raises(InvalidInputError) as columns:
        _columns(**{field: values})
    assert columns.value.field == f"{field}.{row}"
    assert columns.value.code == scalar.value.code
    assert columns.value.message == scalar.value.message


def test_an_overflow_is_refused_as_the_scalar_flowchart_refuses_it() -> None:
    huge = _columns(speed_rpm=[40.0, 1e300, 40.0], accel_s=[0.1, 1e-300, 0.1])
    app = Application(
        pattern=SpeedPattern(speed_rpm=1e300, accel_s=1e-300, constant_s=0.1, decel_s=0.1,
                             pause_s=1.0),
        load=Load(torque_nm=5.0, inertia_kgm2=1.3),
    )  # fmt: skip
    with pytest.raises(InvalidInputError) as scalar:
        select_batch([worked_example.FHA_25C_50_L], [app])
    with pytest.raises(InvalidInputError) as columns:
        rank_columns([worked_example.FHA_25C_50_L], huge)
    assert columns.value.field == f"{scalar.value.field}.1"
    assert columns.value.code == scalar.value.code == "result_overflow"


def test_columns_of_other_lengths_and_bad_arguments_are_refused() -> None:
    with pytest.raises(ValueError, match="pause_s"):
        _columns(pause_s=[1.0, 1.0])
    with pytest.raises(InvalidInputError, match="at least one"):
        dataclasses.replace(_columns(), **{n: np.array([]) for n in _COLUMN_NAMES})  # type: ignore[arg-type]
    with pytest.raises(InvalidInputError, match="thermal_time_constant_s"):
        dataclasses.replace(_columns(), thermal_time_constant_s=0.0)
    with pytest.raises(InvalidInputError, match="top"):
        rank_columns([worked_example.FHA_25C_50_L], _columns(), top=0)


_COLUMN_NAMES = [
    f.name for f in dataclasses.fields(TrapezoidColumns) if f.name != "thermal_time_constant_s"
]
"""The columns: every field but the one τ_th."""
