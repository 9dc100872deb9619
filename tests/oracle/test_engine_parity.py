"""The vectorised flowchart equals the scalar one exactly: numbers, statuses, verdicts, ranking.

Every comparison is ``==``: the batch path promises the same IEEE results as
``sizing/cycle.py`` and ``sizing/selection.py``, not results within a tolerance.
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
from tests.oracle.flowchart import evaluate, select

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.check_messages import jsonable_params, renderer
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.bearing import OutputLoad
from actuator_selection.sizing.checks import RULES, Requirement, Rule, published, rules_for
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import (
    CHECK_NAMES,
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    case_verdicts,
    evaluate_batch,
    evaluate_cases,
    rank_batch,
    select_batch,
)
from actuator_selection.sizing.engine.cases import cases_of
from actuator_selection.sizing.motion import Motion, Segment, piece_arrays
from actuator_selection.sizing.selection import (
    Application,
    Candidate,
    Selection,
    Status,
    Verdict,
    ranking_key,
)

EXAMPLE = worked_example.APPLICATION
FHA = worked_example.FHA_25C_50_L


# --- the oracle -------------------------------------------------------------------------


def assert_matches_scalar(
    actuators: Sequence[Actuator], apps: Sequence[Application], rules: Sequence[Rule] = RULES
) -> None:
    """Every array cell of evaluate_batch equals the scalar flowchart, bit for bit."""
    ev = evaluate_batch(actuators, apps, rules=rules)
    assert ev.statuses.shape == (len(apps), len(actuators), len(rules))
    for i, app in enumerate(apps):
        assert ev.mean_speed_rpm[i] == app.profile.mean_speed_rpm
        scalar = select([], app)
        assert ev.duty_cycle_percent[i] == scalar.duty_cycle_percent
        assert ev.cycle_time_s[i] == scalar.cycle_time_s
        for j, actuator in enumerate(actuators):
            c = evaluate(actuator, app, rules=rules)
            where = f"case {i} {app}, actuator {actuator}"
            assert [ev.status(i, j, k.name) for k in c.checks] == [k.status for k in c.checks], (
                where
            )
            assert ev.verdict(i, j) is c.verdict, where
            for k, check in enumerate(c.checks):
                value = ev.values[i, j, k]
                limit = ev.limits[i, j, k]
                assert (None if math.isnan(value) else value) == check.value, where
                assert (None if math.isnan(limit) else limit) == check.limit, where
                assert ev.approximate[i, j, k] == check.approximate, where
                assert ev.missing(i, j, check.name) == check.missing, where
            if c.torques is None:
                assert math.isnan(ev.accel_torque_nm[i, j])
                assert math.isnan(ev.rms_torque_nm[i, j])
            else:
                assert ev.accel_torque_nm[i, j] == c.torques.accel_torque_nm, where
                constant = ev.constant_torque_nm[i, j]
                assert (None if math.isnan(constant) else constant) == (
                    c.torques.constant_torque_nm
                ), where
                assert ev.decel_torque_nm[i, j] == c.torques.decel_torque_nm, where
                assert ev.rms_torque_nm[i, j] == c.torques.rms_torque_nm, where


def truncated(selection: Selection, top: int) -> Selection:
    return dataclasses.replace(selection, candidates=selection.candidates[:top])


def assert_selects_like_scalar(
    actuators: Sequence[Actuator],
    apps: Sequence[Application],
    top: int,
    rules: Sequence[Rule] = RULES,
) -> None:
    """select_batch equals select() cut to ``top``, case by case (dataclass ==, exact floats)."""
    batch = select_batch(actuators, apps, top=top, rules=rules)
    ranks = rank_batch(actuators, apps, top=top, rules=rules)
    assert len(batch) == len(ranks) == len(apps)
    for app, got, columns in zip(apps, batch, ranks, strict=True):
        expected = truncated(select(actuators, app, rules=rules), top)
        # before ==, which builds every check: the reasons from the checks not passing alone
        assert [c.reasons for c in got.candidates] == [c.reasons for c in expected.candidates]
        assert got == expected
        # == holds for 1 and True: a flag must be a bool, or the JSON says 1
        assert all(type(k.approximate) is bool for c in got.candidates for k in c.checks)
        # == compares the English words, numbers rounded: every param to the last bit too
        assert _in_full(got) == _in_full(expected)
        assert [actuators[j] for j in columns] == [c.actuator for c in expected.candidates]


_FULL = renderer(translate=str, number=lambda value, spec: repr(value))
"""A message with every number written in full (repr), as no language writes it."""


def _in_full(selection: Selection) -> list[list[tuple[str, dict[str, object] | None]]]:
    """Each check's message with its numbers in full, and its params as the API sends them."""
    return [
        [(_FULL(k.message), jsonable_params(k.message)) for k in c.checks]
        for c in selection.candidates
    ]


# --- generators ---------------------------------------------------------------------------


def random_zone(rng: random.Random) -> ContinuousDutyZone:
    speeds = [0.0, *sorted(rng.sample(range(1, 400), rng.randint(1, 5)))]
    torque = rng.uniform(5, 500)
    points = []
    for s in speeds:
        points.append(ZonePoint(speed_rpm=float(s), torque_nm=torque))
        torque = max(0.0, torque - rng.uniform(0, torque / 2))
    return ContinuousDutyZone(points=tuple(points))


def random_actuator(rng: random.Random, k: int) -> Actuator:
    def maybe(value: float, missing: float = 0.12) -> float | None:
        return None if rng.random() < missing else value

    continuous_kind = rng.choice(["stall", "continuous", "both", "neither", "zone", "zone"])
    stall = rng.uniform(1, 800) if continuous_kind in ("stall", "both", "zone") else None
    return Actuator(
        model=f"SYN-{rng.randint(0, 40):02d}-{k}",  # shared prefixes: names break ties
        family="SYN",
        gear_ratio=rng.choice([30.0, 50.0, 100.0, 160.0]),
        # A few T_max values only: ties go to J_A, then to the model name.
        max_torque_nm=maybe(rng.choice([50.0, 100.0, rng.uniform(5, 2000)])),
        max_speed_rpm=maybe(rng.uniform(10, 300)),
        inertia_kgm2=maybe(rng.choice([0.5, rng.uniform(0.001, 10)]), missing=0.2),
        stall_torque_nm=stall,
        continuous_torque_nm=(
            rng.uniform(1, 800) if continuous_kind in ("continuous", "both") else None
        ),
        zone=random_zone(rng) if continuous_kind == "zone" else None,
        continuous_speed_rpm=maybe(rng.uniform(5, 300), missing=0.4),
        rated_speed_rpm=maybe(rng.uniform(5, 300), missing=0.4),
        # The winding's constants and the best listed controller's bus (drive_voltage).
        motor_voltage_constant_v_per_krpm=maybe(rng.uniform(1, 25), missing=0.05),
        max_current_a=maybe(rng.uniform(1, 20), missing=0.05),
        resistance_line_ohm=maybe(rng.uniform(0.3, 6), missing=0.05),
        inductance_line_mh=maybe(rng.uniform(0.3, 12), missing=0.05),
        pole_pairs=maybe(rng.choice([5.0, 6.0]), missing=0.05),
        dc_bus_voltage_v=maybe(rng.choice([24.0, 320.0, 560.0, 560.0]), missing=0.05),
    )


def random_case(rng: random.Random, actuators: Sequence[Actuator]) -> Application:
    other = rng.choice(actuators)
    speed = rng.uniform(1, 300)
    if other.max_speed_rpm is not None and rng.random() < 0.2:
        speed = other.max_speed_rpm  # n_2 exactly n_max
    inertia = rng.choice([0.0, rng.uniform(0, 30), rng.uniform(0, 1)])
    if other.inertia_kgm2 is not None and rng.random() < 0.2:
        inertia = 3.0 * other.inertia_kgm2  # J_L exactly 3·J_A
    return Application(
        pattern=SpeedPattern(
            speed_rpm=speed,
            accel_s=rng.uniform(1e-3, 1),
            constant_s=rng.choice([0.0, rng.uniform(0, 2)]),
            decel_s=rng.uniform(1e-3, 1),
            pause_s=rng.choice([0.0, rng.uniform(0, 5)]),
        ),
        load=Load(torque_nm=rng.choice([0.0, rng.uniform(0, 200)]), inertia_kgm2=inertia),
        high_dynamics=rng.random() < 0.6,
    )


def random_motion_case(rng: random.Random) -> Application:
    """A cycle of segments: moves both ways, S-curves, dwells, a weight, losses, process
    torques; between 1 and 6 moves, so that a batch pads short cycles."""
    segments: list[Segment] = []
    for _ in range(rng.randint(1, 6)):
        speed = rng.choice([-1.0, 1.0]) * rng.uniform(1, 200)
        jerk = rng.choice([0.0, 1.0, rng.uniform(0, 1)])
        force = rng.choice([0.0, rng.uniform(-50, 50)])
        segments += [
            Segment(duration_s=rng.uniform(1e-3, 1), start_rpm=0.0, end_rpm=speed, jerk_share=jerk),
            Segment(
                duration_s=rng.choice([0.0, rng.uniform(0, 2)]),
                start_rpm=speed,
                end_rpm=speed,
                process_torque_nm=force,
            ),
            Segment(duration_s=rng.uniform(1e-3, 1), start_rpm=speed, end_rpm=0.0, jerk_share=jerk),
            Segment(duration_s=rng.choice([0.0, rng.uniform(0, 3)]), start_rpm=0.0, end_rpm=0.0),
        ]
    load = AxisLoad(
        inertia_kgm2=rng.choice([0.0, rng.uniform(0, 30)]),
        friction_torque_nm=rng.choice([0.0, rng.uniform(0, 50)]),
        gravity_torque_nm=rng.choice([0.0, rng.uniform(-80, 80)]),
        efficiency=rng.choice([1.0, rng.uniform(0.5, 1)]),
    )
    return Application(
        motion=Motion(segments=tuple(segments), load=load), high_dynamics=rng.random() < 0.6
    )


def rounding_trap(edge: float) -> float:
    """A torque a > edge for which a + (edge − a) rounds below ``edge``.

    A zone point of torque a before a point of torque ``edge`` at n_av: the limit at
    n_av is ``edge`` only if the interpolation picks the same segment as bisect_right.
    """
    for k in range(1, 5000):
        a = edge * (2 + k / 97)
        if a + (edge - a) < edge:
            return a
    return 2 * edge


def boundary_actuators(apps: Sequence[Application]) -> list[Actuator]:
    """Actuators whose limits equal a case's own figures: every ``≤`` is decided at equality."""
    out = []
    for k, app in enumerate(apps):
        t = app.profile.torques(0.7)
        n_av = app.profile.mean_speed_rpm
        exact = Actuator(
            model=f"EDGE-{k}",
            family="EDGE",
            gear_ratio=50.0,
            max_torque_nm=abs(t.accel_torque_nm),
            max_speed_rpm=app.profile.peak_speed_rpm,
            inertia_kgm2=0.7,
            stall_torque_nm=t.rms_torque_nm,
            rated_speed_rpm=n_av,  # n_av at the rated speed exactly
        )
        ends_at_n_av = dataclasses.replace(
            exact,
            model=f"EDGE-Z-{k}",
            max_torque_nm=abs(t.decel_torque_nm),
            zone=ContinuousDutyZone(
                points=(
                    ZonePoint(speed_rpm=0.0, torque_nm=rounding_trap(t.rms_torque_nm)),
                    ZonePoint(speed_rpm=n_av, torque_nm=t.rms_torque_nm),
                )
            ),
        )
        corner_at_n_av = dataclasses.replace(
            ends_at_n_av,
            model=f"EDGE-C-{k}",
            zone=ContinuousDutyZone(
                points=(
                    ZonePoint(speed_rpm=0.0, torque_nm=rounding_trap(t.rms_torque_nm)),
                    ZonePoint(speed_rpm=n_av, torque_nm=t.rms_torque_nm),
                    ZonePoint(speed_rpm=2 * n_av, torque_nm=0.0),
                )
            ),
        )
        just_short = dataclasses.replace(
            ends_at_n_av,
            model=f"EDGE-S-{k}",
            zone=ContinuousDutyZone(
                points=(
                    ZonePoint(speed_rpm=0.0, torque_nm=1e4),
                    ZonePoint(speed_rpm=math.nextafter(n_av, 0.0), torque_nm=1e4),
                )
            ),
        )
        out += [exact, ends_at_n_av, corner_at_n_av, just_short]
    return out


# --- equality with the scalar flowchart -----------------------------------------------------


@pytest.mark.parametrize("seed", range(6))
def test_seeded_random_catalogues_match_scalar_exactly(seed: int) -> None:
    rng = random.Random(seed)
    actuators = [random_actuator(rng, k) for k in range(40)]
    apps = [random_case(rng, actuators) for _ in range(150)]
    actuators += boundary_actuators(apps[:10])
    assert_matches_scalar(actuators, apps)
    assert_selects_like_scalar(actuators, apps, top=3)


def test_boundaries_are_met_at_equality() -> None:
    """The limits built from a case's own numbers pass there: the arrays equal the scalar."""
    rng = random.Random(99)
    apps = [random_case(rng, [FHA]) for _ in range(20)]
    actuators = boundary_actuators(apps)
    ev = evaluate_batch(actuators, apps)
    for k in range(len(apps)):
        exact, ends, corner, short = (4 * k + m for m in range(4))
        assert ev.status(k, exact, "max_speed") is Status.PASS
        assert ev.status(k, exact, "peak_torque") is Status.PASS
        assert ev.status(k, exact, "continuous_duty") is Status.PASS
        assert ev.status(k, ends, "decel_torque") is Status.PASS
        assert ev.status(k, ends, "continuous_duty") is Status.PASS
        assert ev.status(k, corner, "continuous_duty") is Status.PASS
        assert ev.status(k, short, "continuous_duty") is Status.FAIL
    assert_matches_scalar(actuators, apps)


# Two checks the chapter does not have, made up to exercise the table: each is one Rule,
# and both flowcharts, the verdicts and the ranking take it up.
RMS_TO_PEAK = Rule(
    name="rms_to_peak",
    reference="Eq. 514.2",
    unit="Nm",
    value=lambda q, xp: 2.0 * q.rms_torque_nm,
    limit=lambda q, xp: xp.where(q.has_zone, q.zone_torque_nm, q.max_torque_nm),
    requires=(
        published("inertia_kgm2", "moment of inertia J_A"),
        Requirement(any_of=("max_torque_nm",), unless="has_zone", what="maximum torque T_max"),
    ),
    binding=lambda q, xp: xp.not_(q.high_dynamics),
    # a premise of a case (J_L > 0) or of an actuator (T_max > 100 Nm): not_applicable else
    applies=lambda q, xp: (q.load_inertia_kgm2 > 0.0) | (q.max_torque_nm > 100.0),
    message=lambda q, status, value, limit: f"2·T_rms = {value:.4g} Nm, limit {limit:.4g} Nm",
)
MEAN_SPEED = Rule(
    name="mean_speed",
    reference="Eq. 514.3",
    unit="rpm",
    value=lambda q, xp: q.mean_speed_rpm,
    limit=lambda q, xp: 0.5 * q.max_speed_rpm,
    requires=(published("max_speed_rpm", "maximum output speed n_max"),),
    within=lambda q, xp: q.load_inertia_kgm2 <= 10.0,
    message=lambda q, status, value, limit: f"n_av = {value:.4g} rpm",
)


@pytest.mark.parametrize("seed", range(2))
def test_an_added_rule_runs_in_both_flowcharts(seed: int) -> None:
    rng = random.Random(100 + seed)
    actuators = [random_actuator(rng, k) for k in range(30)]
    apps = [random_case(rng, actuators) for _ in range(80)]
    actuators += boundary_actuators(apps[:10])
    rules = (*RULES, RMS_TO_PEAK, MEAN_SPEED)
    assert_matches_scalar(actuators, apps, rules)
    assert_selects_like_scalar(actuators, apps, 3, rules)
    ev = evaluate_batch(actuators, apps, rules=rules)
    assert ev.check_names == (*CHECK_NAMES, "rms_to_peak", "mean_speed")
    seen = {ev.status(i, j, "rms_to_peak") for i in range(len(apps)) for j in range(len(actuators))}
    assert seen == set(Status)  # pass, fail, warn (not binding), no data, not applicable
    # The new checks change verdicts and so the ranking: the comparison above is not vacuous.
    assert (ev.verdicts != evaluate_batch(actuators, apps).verdicts).any()


@pytest.mark.parametrize("seed", range(3))
def test_segment_cycles_match_scalar_exactly(seed: int) -> None:
    """Cycles of segments, mixed with trapezoids of fewer pieces (padded), decide as the
    scalar flowchart does, cell for cell; a brake adds its check to both."""
    rng = random.Random(300 + seed)
    actuators = [random_actuator(rng, k) for k in range(25)]
    apps = [random_motion_case(rng) for _ in range(40)] + [
        random_case(rng, actuators) for _ in range(10)
    ]
    actuators += boundary_actuators(apps[:8])
    assert_matches_scalar(actuators, apps)
    assert_selects_like_scalar(actuators, apps, 3)
    braked = [dataclasses.replace(a, brake=True) for a in apps]
    assert_matches_scalar(actuators, braked, rules_for(braked[0]))
    ev = evaluate_batch(actuators, apps)
    # Not vacuous: motions give negative peaks, regenerating brakes and every verdict.
    assert (ev.accel_torque_nm < 0).any()
    assert set(ev.verdicts.ravel().tolist()) == {0, 1, 2}


def test_edge_cases_named_in_the_issue() -> None:
    zone = ContinuousDutyZone(
        points=(ZonePoint(speed_rpm=0, torque_nm=40), ZonePoint(speed_rpm=90, torque_nm=30))
    )
    actuators = [
        FHA,
        dataclasses.replace(FHA, model="NO-JA", inertia_kgm2=None),
        dataclasses.replace(FHA, model="ZONE", zone=zone),
        dataclasses.replace(
            FHA, model="T0", stall_torque_nm=36, rated_speed_rpm=70, **worked_example.DRIVEN
        ),
        dataclasses.replace(
            FHA,
            model="TC",
            continuous_torque_nm=40,
            continuous_speed_rpm=35,
            **worked_example.DRIVEN,
        ),
        dataclasses.replace(
            FHA,
            model="TC-NO-NMAX",
            continuous_torque_nm=40,
            max_speed_rpm=None,
            continuous_speed_rpm=35,
        ),
        dataclasses.replace(
            FHA, model="NO-TMAX", max_torque_nm=None, stall_torque_nm=36, rated_speed_rpm=70
        ),
        # ties T0 on T_max and J_A
        dataclasses.replace(
            FHA, model="TIE-A", stall_torque_nm=36, rated_speed_rpm=70, **worked_example.DRIVEN
        ),
        dataclasses.replace(FHA, model="T0-NO-SPEED", stall_torque_nm=36),
        Actuator(model="BARE", family="F", gear_ratio=50),
    ]
    at_ratio = dataclasses.replace(EXAMPLE, load=Load(torque_nm=5, inertia_kgm2=3 * 0.86))
    at_speed = dataclasses.replace(
        EXAMPLE, pattern=dataclasses.replace(worked_example.PATTERN, speed_rpm=90)
    )
    heavy = dataclasses.replace(EXAMPLE, load=Load(torque_nm=5, inertia_kgm2=2.6))
    apps = [
        EXAMPLE,
        at_ratio,
        at_speed,
        heavy,
        dataclasses.replace(heavy, high_dynamics=False),
    ]
    assert_matches_scalar(actuators, apps)
    for top in (1, 3, len(actuators), len(actuators) + 5):
        assert_selects_like_scalar(actuators, apps, top=top)
    ev = evaluate_batch(actuators, apps)
    assert ev.status(1, 0, "inertia_ratio") is Status.PASS  # J_L = 3·J_A exactly
    assert ev.status(2, 0, "max_speed") is Status.PASS  # n_2 = n_max exactly
    assert ev.status(3, 0, "inertia_ratio") is Status.FAIL
    assert ev.status(4, 0, "inertia_ratio") is Status.WARN
    assert ev.status(0, 1, "peak_torque") is Status.NO_DATA
    assert ev.verdict(0, 3) is Verdict.SUITABLE
    # T_0 without a speed: the torque is checked, the speed lacks data
    assert ev.status(0, 8, "continuous_duty") is Status.PASS
    assert ev.status(0, 8, "continuous_speed") is Status.NO_DATA
    ranked = [c.actuator.model for c in select_batch(actuators, [EXAMPLE], top=9)[0].candidates]
    assert ranked[:3] == ["T0", "TC", "TIE-A"]  # equal T_max and J_A: the name decides


finite = st.floats(allow_nan=False, allow_infinity=False)
optional_value = st.none() | st.floats(min_value=1e-3, max_value=3000) | st.sampled_from([50.0])


@st.composite
def zones(draw: st.DrawFn) -> ContinuousDutyZone:
    speeds = draw(
        st.lists(st.floats(min_value=1e-3, max_value=500), min_size=1, max_size=4, unique=True)
    )
    torques = draw(
        st.lists(
            st.floats(min_value=0, max_value=1000),
            min_size=len(speeds) + 1,
            max_size=len(speeds) + 1,
        )
    )
    points = zip([0.0, *sorted(speeds)], torques, strict=True)
    return ContinuousDutyZone(points=tuple(ZonePoint(speed_rpm=s, torque_nm=t) for s, t in points))


@st.composite
def catalogues(draw: st.DrawFn) -> list[Actuator]:
    n = draw(st.integers(min_value=0, max_value=7))
    return [
        Actuator(
            model=draw(st.sampled_from(["A", "B", "C"])) + str(k),
            family="H",
            gear_ratio=50.0,
            max_torque_nm=draw(optional_value),
            max_speed_rpm=draw(optional_value),
            inertia_kgm2=draw(st.none() | st.floats(min_value=0, max_value=20)),
            stall_torque_nm=draw(optional_value),
            continuous_torque_nm=draw(optional_value),
            zone=draw(st.none() | zones()),
            continuous_speed_rpm=draw(optional_value),
            rated_speed_rpm=draw(optional_value),
        )
        for k in range(n)
    ]


applications = st.builds(
    Application,
    pattern=st.builds(
        SpeedPattern,
        speed_rpm=st.floats(min_value=1e-3, max_value=1e5),
        accel_s=st.floats(min_value=1e-4, max_value=100),
        constant_s=st.floats(min_value=0, max_value=100),
        decel_s=st.floats(min_value=1e-4, max_value=100),
        pause_s=st.floats(min_value=0, max_value=100),
    ),
    load=st.builds(
        Load,
        torque_nm=st.floats(min_value=0, max_value=1e6),
        inertia_kgm2=st.floats(min_value=0, max_value=1e6),
    ),
    high_dynamics=st.booleans(),
)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    actuators=catalogues(),
    apps=st.lists(applications, min_size=0, max_size=6),
    top=st.integers(min_value=1, max_value=9),
)
def test_hypothesis_batch_equals_scalar(
    actuators: list[Actuator], apps: list[Application], top: int
) -> None:
    assert_matches_scalar(actuators, apps)
    assert_selects_like_scalar(actuators, apps, top=top)


# --- ranking and restriction ----------------------------------------------------------------


def test_verdict_codes_follow_ranking_key() -> None:
    def rank(v: Verdict) -> int:
        return ranking_key(Candidate(actuator=FHA, verdict=v, torques=None, checks=()))[0]

    assert [rank(v) for v in VERDICT_BY_CODE] == [0, 1, 2]
    assert set(STATUS_BY_CODE) == set(Status)


def test_models_restrict_each_case() -> None:
    rng = random.Random(3)
    actuators = [random_actuator(rng, k) for k in range(20)]
    apps = [random_case(rng, actuators) for _ in range(30)]
    names = [a.model for a in actuators]
    models: list[list[str] | None] = [
        None if i % 3 == 0 else [*rng.sample(names, rng.randint(1, 6)), "NOT-IN-CATALOGUE"]
        for i in range(len(apps))
    ]
    batch = select_batch(actuators, apps, top=4, models=models)
    for app, allowed, got in zip(apps, models, batch, strict=True):
        subset = actuators if allowed is None else [a for a in actuators if a.model in allowed]
        assert got == truncated(select(subset, app), 4)


def test_equal_keys_keep_catalogue_order_like_a_stable_sort() -> None:
    """Two entries of one model (equal ranking keys): select() keeps their input order."""
    twins = [
        dataclasses.replace(
            FHA,
            model="TWIN",
            gear_ratio=ratio,
            stall_torque_nm=36,
            rated_speed_rpm=70,
            **worked_example.DRIVEN,
        )
        for ratio in (50.0, 100.0, 30.0)
    ]
    for actuators in (twins, twins[::-1], [FHA, *twins]):
        assert_selects_like_scalar(actuators, [EXAMPLE], top=len(actuators))
        (got,) = select_batch(actuators, [EXAMPLE], top=2)
        assert [c.actuator for c in got.candidates] == [a for a in actuators if a.model == "TWIN"][
            :2
        ]


def test_empty_inputs() -> None:
    assert select_batch([FHA], []) == []
    (empty,) = select_batch([], [EXAMPLE])
    assert empty == select([], EXAMPLE)
    assert evaluate_batch([], [EXAMPLE]).statuses.shape == (1, 0, len(CHECK_NAMES))


def test_bad_arguments_are_domain_errors() -> None:
    with pytest.raises(InvalidInputError, match="top"):
        select_batch([FHA], [EXAMPLE], top=0)
    with pytest.raises(InvalidInputError, match="models"):
        select_batch([FHA], [EXAMPLE], models=[None, None])


def test_many_cases_span_several_blocks() -> None:
    """More cells than one block holds: the blocks join in order."""
    rng = random.Random(11)
    actuators = [random_actuator(rng, k) for k in range(7)]
    apps = [random_case(rng, actuators) for _ in range(12_000)]
    batch = select_batch(actuators, apps, top=2)
    for i in range(0, len(apps), 997):
        assert batch[i] == truncated(select(actuators, apps[i]), 2)


def test_large_blocks_equal_one_case_blocks() -> None:
    """A block of more cells than are heated as one array (``block._STACKED_CELLS``),
    whose pieces are taken fewer than 16 at a time (a block of ~65,000 cells), and cycles
    of many pieces: every cell as the one-case blocks give it, which the tests above hold
    to the scalar flowchart."""
    rng = random.Random(5)
    actuators = [random_actuator(rng, k) for k in range(70)]
    apps = [random_case(rng, actuators) for _ in range(900)]
    apps += [random_motion_case(rng) for _ in range(100)]
    rng.shuffle(apps)
    whole = evaluate_batch(actuators, apps)
    for i in range(0, len(apps), 19):
        one = evaluate_batch(actuators, [apps[i]])
        for field in (
            "accel_torque_nm",
            "constant_torque_nm",
            "decel_torque_nm",
            "rms_torque_nm",
            "statuses",
            "verdicts",
            "values",
            "limits",
            "approximate",
            "first_missing",
            "worst_overload",
        ):
            np.testing.assert_array_equal(
                getattr(whole, field)[i], getattr(one, field)[0], err_msg=f"case {i} {field}"
            )


def test_floors_without_j_a_match_the_scalar_flowchart() -> None:
    """Actuators without J_A against loads whose floors fail and pass: every cell equal."""
    base = worked_example.FHA_25C_50_L
    actuators = [
        dataclasses.replace(base, model=f"NJ-{t}", inertia_kgm2=None, max_torque_nm=t,
                            stall_torque_nm=s)
        for t, s in ((20.0, 5.0), (50.0, 30.0), (200.0, None), (1000.0, 400.0))
    ]  # fmt: skip
    actuators = [dataclasses.replace(a, rated_speed_rpm=60.0) for a in actuators]
    rng = random.Random(17)
    apps = [
        Application(
            pattern=SpeedPattern(
                speed_rpm=rng.uniform(5, 80),
                accel_s=rng.uniform(0.02, 0.5),
                constant_s=rng.uniform(0, 1),
                decel_s=rng.uniform(0.02, 0.5),
                pause_s=rng.uniform(0, 2),
            ),
            load=Load(torque_nm=rng.uniform(0, 300), inertia_kgm2=rng.uniform(0, 3)),
        )
        for _ in range(300)
    ]
    statuses = evaluate_batch(actuators, apps).statuses
    assert (statuses == STATUS_BY_CODE.index(Status.FAIL)).any()  # floors do fail here
    assert_matches_scalar(actuators, apps)
    assert_selects_like_scalar(actuators, apps, top=3)


def test_brake_checks_match_the_scalar_flowchart() -> None:
    """Cases with a brake: the brake's check in both flowcharts, equal cell by cell; cases
    with and without a brake are not mixed in one run."""
    rng = random.Random(23)
    actuators = [
        dataclasses.replace(random_actuator(rng, k), brake_holding_torque_nm=h)
        for k, h in enumerate([None, 10.0, 50.0, 200.0, None, 80.0, 5.0, 400.0])
    ]
    apps = [dataclasses.replace(random_case(rng, actuators), brake=True) for _ in range(120)]
    assert evaluate_batch(actuators, apps).check_names[-1] == "brake_holding"
    assert_matches_scalar(actuators, apps, rules=rules_for(apps[0]))
    assert_selects_like_scalar(actuators, apps, top=3, rules=rules_for(apps[0]))
    mixed = [apps[0], dataclasses.replace(apps[1], brake=False)]
    with pytest.raises(InvalidInputError):
        select_batch(actuators, mixed)


def test_trapezoid_columns_equal_the_pieces_of_their_segments() -> None:
    """The batch's column-built trapezoids are the pieces of the chapter's four segments,
    array for array, bit for bit."""
    rng = random.Random(7)
    apps = [random_case(rng, [FHA]) for _ in range(200)]
    fast = cases_of(apps).pieces
    slow = piece_arrays([a.cycle for a in apps])
    for f in dataclasses.fields(fast):
        assert np.array_equal(getattr(fast, f.name), getattr(slow, f.name)), f.name


@pytest.mark.parametrize("seed", range(3))
def test_case_verdicts_are_the_candidates_verdicts(seed: int) -> None:
    """The inverse solve's probes decide on :func:`case_verdicts` (status codes alone):
    each actuator's verdict per case equals its detailed candidate's and the oracle's."""
    rng = random.Random(seed)
    actuators = [random_actuator(rng, k) for k in range(12)]
    apps = [random_case(rng, actuators) for _ in range(40)]
    for actuator in actuators:
        candidates = evaluate_cases(actuator, apps)
        expected = [c.verdict for c in candidates]
        assert case_verdicts(actuator, apps) == expected
        assert expected == [evaluate(actuator, app).verdict for app in apps]


def with_gear_stiffness_brake(rng: random.Random, actuator: Actuator) -> Actuator:
    """TEST VALUES, MADE UP (not catalogue data): gear ratings, stiffness and brake limits,
    some missing, so that pass, fail and no data all occur."""

    def maybe(low: float, high: float) -> float | None:
        return None if rng.random() < 0.15 else rng.uniform(low, high)

    t1 = maybe(1, 100)
    return dataclasses.replace(
        actuator,
        brake_holding_torque_nm=maybe(1, 400),
        limit_torque_t1_nm=t1,
        limit_torque_t2_nm=None if t1 is None else 3.5 * t1,
        torsional_stiffness_k1_nm_per_rad=maybe(1e3, 1e5),
        torsional_stiffness_k2_nm_per_rad=maybe(1e3, 1e5),
        torsional_stiffness_k3_nm_per_rad=maybe(1e3, 1e5),
        brake_emergency_stop_count=rng.choice([None, 200.0]),
        brake_closing_time_s=rng.choice([None, 0.07]),
        gear_average_torque_limit_nm=maybe(5, 500),
        gear_repeated_peak_torque_nm=maybe(5, 800),
        gear_momentary_peak_torque_nm=maybe(5, 1500),
        gear_momentary_peak_count=maybe(100, 1e5),
        gear_average_input_speed_limit_rpm=maybe(500, 4000),
        gear_rated_torque_nm=maybe(5, 300),
        gear_rated_life_h=rng.choice([None, 7000.0, 10000.0]),
        gear_life_basis=rng.choice([None, "L10", "L50"]),
        output_bearing_pitch_diameter_m=maybe(0.03, 0.2),
        output_bearing_offset_m=maybe(0.0, 0.03),
        output_bearing_dynamic_load_rating_n=maybe(5e3, 1e5),
        output_bearing_static_load_rating_n=maybe(5e3, 1e5),
        output_bearing_radial_load_n=maybe(1e3, 2e4),
        output_bearing_axial_load_n=maybe(1e3, 4e4),
        output_bearing_moment_load_nm=maybe(50, 1000),
        output_bearing_type=rng.choice([None, "cross_roller", "four_point_contact_ball"]),
    )


@pytest.mark.parametrize("motion", [False, True])
def test_gear_stiffness_and_brake_checks_match_the_scalar_flowchart(motion: bool) -> None:
    """Issue 28, items 7–9: the gear's, the stiffness' and the brake's checks in both
    flowcharts, equal cell by cell, on trapezoids and on cycles of segments (S-curves,
    both directions: T_av's sum piece by piece)."""
    rng = random.Random(29 + motion)
    actuators = [with_gear_stiffness_brake(rng, random_actuator(rng, k)) for k in range(12)]
    base = [random_motion_case(rng) if motion else random_case(rng, actuators) for _ in range(60)]
    apps = [
        dataclasses.replace(
            app,
            brake=True,
            gear=True,
            gear_required_life_h=20000.0,
            momentary_torque_nm=300.0,
            momentary_count=500.0,
            min_natural_frequency_hz=15.0,
            brake_safety_factor=1.5,
            emergency_stops=150.0,
            output_load=OutputLoad(
                radial_force_n=rng.uniform(0, 1.5e4),
                axial_force_n=rng.uniform(-3e4, 3e4),
                radial_lever_m=rng.uniform(0, 0.1),
                axial_lever_m=rng.uniform(0, 0.05),
                required_life_h=20000.0,
            ),
        )
        for app in base
    ]
    rules = rules_for(apps[0])
    names = [r.name for r in rules]
    for name in (
        "gear_average_torque",
        "gear_life",
        "natural_frequency",
        "brake_emergency_stops",
        "bearing_radial_force",
        "bearing_axial_force",
    ):
        assert name in names
    assert_matches_scalar(actuators, apps, rules=rules)
    assert_selects_like_scalar(actuators, apps, top=3, rules=rules)
    statuses = evaluate_batch(actuators, apps, rules=rules).statuses
    for status in (Status.PASS, Status.FAIL, Status.NO_DATA):
        assert (statuses == STATUS_BY_CODE.index(status)).any()
