"""Cycles of segments against first principles: quadrature of T(t)² and |n(t)|, S-curves
in closed form, a vertical lift with and without counterweight, losses by power flow, and
the chapter's trapezoid equal to its four segments."""

from __future__ import annotations

import math
import random
from dataclasses import fields

import numpy as np
import pytest
from tests import worked_example
from tests.oracle.test_engine_parity import random_motion_case

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.cycle import (
    Load,
    SpeedPattern,
    cycle_torques,
    duty_cycle_percent,
    mean_speed_rpm,
)
from actuator_selection.sizing.motion import (
    Motion,
    Profile,
    Segment,
    cycle_figures,
    figures_of,
    heating_gain,
    heating_gain_array,
    piece_arrays,
    profile_of,
    trapezoid,
    trapezoid_piece_arrays,
)
from actuator_selection.sizing.selection import Application

G = 9.81
OMEGA = 2 * math.pi / 60  # rad/s per rpm


def quadrature(motion: Motion, j_a: float, steps: int = 20_000) -> tuple[float, float]:
    """T_rms and n_av by the midpoint rule over each segment's own time, from the physics:
    n(t) and α(t) of a constant or S-curve ramp, T = T_G + s·T_F + T_P + (J_A + J_L)·α
    (η = 1), standstill torque T_G + T_P."""
    load = motion.load
    energy = travel = total = 0.0
    for seg in motion.segments:
        t = seg.duration_s
        total += t
        if t == 0:
            continue
        dn = seg.end_rpm - seg.start_rpm
        tj = seg.jerk_share * t / 2
        peak = dn * OMEGA / (t - tj) if dn else 0.0
        for k in range(steps):
            tau = (k + 0.5) * t / steps
            if tj > 0 and tau < tj:
                alpha = peak * tau / tj
            elif tj > 0 and tau > t - tj:
                alpha = peak * (t - tau) / tj
            else:
                alpha = peak
            # speed: integrate α from the start (closed form of the three phases)
            if tj == 0:
                n = seg.start_rpm + dn * tau / t
            elif tau < tj:
                n = seg.start_rpm + peak * tau * tau / (2 * tj) / OMEGA
            elif tau <= t - tj:
                n = seg.start_rpm + (peak * tj / 2 + peak * (tau - tj)) / OMEGA
            else:
                rest = t - tau
                n = seg.end_rpm - peak * rest * rest / (2 * tj) / OMEGA
            s = (n > 0) - (n < 0) if n else seg.direction
            torque = (
                load.gravity_torque_nm
                + s * load.friction_torque_nm
                + seg.process_torque_nm
                + (j_a + load.inertia_kgm2) * alpha
            )
            energy += torque * torque * t / steps
            travel += abs(n) * t / steps
    return math.sqrt(energy / total), travel / total


def test_trapezoid_is_the_chapters_cycle_operation_for_operation() -> None:
    p, load = worked_example.PATTERN, worked_example.LOAD
    profile = worked_example.APPLICATION.profile
    assert profile.mean_speed_rpm == mean_speed_rpm(p)
    assert profile.duty_cycle_percent == duty_cycle_percent(p)
    assert profile.cycle_s == p.cycle_s
    t = profile.torques(0.86)
    assert t == cycle_torques(pattern=p, load=load, actuator_inertia_kgm2=0.86)
    # and against the chapter's printed values (Table 516.1 / 516.3)
    assert (round(t.accel_torque_nm, 2), round(t.decel_torque_nm, 2)) == (95.48, -85.48)
    assert round(t.rms_torque_nm, 2) == 35.57


def test_trapezoid_shorthand_equals_its_segments_written_out() -> None:
    axis = AxisLoad(inertia_kgm2=1.3, friction_torque_nm=5)
    written = Motion(
        segments=(
            Segment(duration_s=0.1, start_rpm=0, end_rpm=40),
            Segment(duration_s=0.1, start_rpm=40, end_rpm=40),
            Segment(duration_s=0.1, start_rpm=40, end_rpm=0),
            Segment(duration_s=1.0, start_rpm=0, end_rpm=0),
        ),
        load=axis,
    )
    shorthand = trapezoid(
        speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0, load=axis
    )
    assert written == shorthand
    a, b = profile_of(written), profile_of(shorthand)
    assert a.torques(0.86) == b.torques(0.86)
    assert a.torques(0.86) == worked_example.APPLICATION.profile.torques(0.86)


@pytest.mark.parametrize("jerk", [0.0, 0.3, 1.0])
def test_rms_and_mean_speed_equal_quadrature_for_a_two_way_cycle(jerk: float) -> None:
    """Out, dwell, back past the start, home: reversals, S-curves, a weight, friction and
    a process torque, against the midpoint rule on the physics."""
    motion = Motion(
        segments=(
            Segment(duration_s=0.2, start_rpm=0, end_rpm=60, jerk_share=jerk),
            Segment(duration_s=0.3, start_rpm=60, end_rpm=60, process_torque_nm=12),
            Segment(duration_s=0.25, start_rpm=60, end_rpm=0, jerk_share=jerk),
            Segment(duration_s=0.1, start_rpm=0, end_rpm=0),
            Segment(duration_s=0.15, start_rpm=0, end_rpm=-45, jerk_share=jerk),
            Segment(duration_s=0.15, start_rpm=-45, end_rpm=0, jerk_share=jerk),
            Segment(duration_s=0.5, start_rpm=0, end_rpm=0),
        ),
        load=AxisLoad(inertia_kgm2=0.8, friction_torque_nm=3, gravity_torque_nm=7.5),
    )
    profile = profile_of(motion)
    rms, n_av = quadrature(motion, j_a=0.4)
    assert profile.torques(0.4).rms_torque_nm == pytest.approx(rms, rel=1e-6)
    assert profile.mean_speed_rpm == pytest.approx(n_av, rel=1e-6)
    assert profile.peak_speed_rpm == 60
    assert profile.duty_cycle_percent == pytest.approx((0.2 + 0.3 + 0.25 + 0.3) / 1.65 * 100)


def test_pure_s_curve_rms_in_closed_form() -> None:
    """α rises linearly to α_p = 2Δω/t and falls back: ∫α² dt = α_p²·t/3, so a cycle of
    an S-curve up and one down (J, no load torque) has T_rms = J·α_p/√3; its mean speed
    is that of the straight ramps (n/2), the S-curve being symmetric."""
    n, t, j = 90.0, 0.4, 2.5
    motion = Motion(
        segments=(
            Segment(duration_s=t, start_rpm=0, end_rpm=n, jerk_share=1.0),
            Segment(duration_s=t, start_rpm=n, end_rpm=0, jerk_share=1.0),
        ),
        load=AxisLoad(inertia_kgm2=j, friction_torque_nm=0),
    )
    profile = profile_of(motion)
    alpha_p = 2 * n * OMEGA / t
    torques = profile.torques(0.0)
    assert torques.rms_torque_nm == pytest.approx(j * alpha_p / math.sqrt(3), rel=1e-12)
    assert torques.accel_torque_nm == pytest.approx(j * alpha_p, rel=1e-12)
    assert torques.decel_torque_nm == pytest.approx(-j * alpha_p, rel=1e-12)
    assert profile.mean_speed_rpm == pytest.approx(n / 2, rel=1e-12)
    assert torques.constant_torque_nm is None  # never at constant speed


def lift(mass: float, counter: float, radius: float, eta: float = 1.0) -> AxisLoad:
    """A drum of radius r lifting m against a counterweight m_c (first principles)."""
    return AxisLoad(
        inertia_kgm2=(mass + counter) * radius**2,
        friction_torque_nm=0.0,
        gravity_torque_nm=(mass - counter) * G * radius,
        efficiency=eta,
    )


def lift_cycle(load: AxisLoad) -> Motion:
    return Motion(
        segments=(
            Segment(duration_s=0.5, start_rpm=0, end_rpm=30),
            Segment(duration_s=1.0, start_rpm=30, end_rpm=30),
            Segment(duration_s=0.5, start_rpm=30, end_rpm=0),
            Segment(duration_s=1.0, start_rpm=0, end_rpm=0),
            Segment(duration_s=0.5, start_rpm=0, end_rpm=-30),
            Segment(duration_s=1.0, start_rpm=-30, end_rpm=-30),
            Segment(duration_s=0.5, start_rpm=-30, end_rpm=0),
            Segment(duration_s=1.0, start_rpm=0, end_rpm=0),
        ),
        load=load,
    )


def test_vertical_lift_holds_its_weight_and_a_counterweight_relieves_it() -> None:
    m, r, alpha = 100.0, 0.1, 30 * OMEGA / 0.5
    bare = profile_of(lift_cycle(lift(m, 0.0, r)))
    weight = m * G * r  # 98.1 Nm held at standstill and at constant speed
    t = bare.torques(0.0)
    assert t.accel_torque_nm == pytest.approx(weight + m * r * r * alpha)  # lifting off
    assert t.constant_torque_nm == pytest.approx(weight)  # both runs hold the weight
    assert bare.holding_torque_nm == pytest.approx(weight)
    rms, _ = quadrature(lift_cycle(lift(m, 0.0, r)), 0.0)
    assert t.rms_torque_nm == pytest.approx(rms, rel=1e-6)
    balanced = profile_of(lift_cycle(lift(m, 80.0, r))).torques(0.0)
    assert balanced.constant_torque_nm == pytest.approx(20 * G * r)
    assert balanced.rms_torque_nm < t.rms_torque_nm / 3


def test_losses_follow_the_power_flow() -> None:
    """Lifting, the actuator gives T_G/η; lowering, the weight drives and it gives T_G·η."""
    eta = 0.8
    profile = profile_of(lift_cycle(lift(100.0, 0.0, 0.1, eta)))
    weight = 100.0 * G * 0.1
    runs = {
        round(st.torques_nm[0], 9)
        for st in profile.segment_torques(0.0)
        if st.segment in (1, 5)  # the two runs at constant speed
    }
    assert runs == {round(weight / eta, 9), round(weight * eta, 9)}


def test_friction_reverses_with_the_motion() -> None:
    motion = Motion(
        segments=(
            Segment(duration_s=0.1, start_rpm=0, end_rpm=-20),
            Segment(duration_s=0.2, start_rpm=-20, end_rpm=-20),
            Segment(duration_s=0.1, start_rpm=-20, end_rpm=0),
        ),
        load=AxisLoad(inertia_kgm2=0.0, friction_torque_nm=4.0),
    )
    t = profile_of(motion).torques(0.0)
    assert t.constant_torque_nm == -4.0
    assert t.accel_torque_nm == -4.0


@pytest.mark.parametrize(
    ("segments", "field"),
    [
        ((Segment(duration_s=1, start_rpm=0, end_rpm=10),), "segments"),  # does not close
        (
            (
                Segment(duration_s=1, start_rpm=0, end_rpm=10),
                Segment(duration_s=1, start_rpm=5, end_rpm=0),
            ),
            "segments.1.start_rpm",
        ),
        ((Segment(duration_s=0, start_rpm=0, end_rpm=0),), "segments"),  # lasts 0 s
        (
            (
                Segment(duration_s=1, start_rpm=0, end_rpm=10),
                Segment(duration_s=1, start_rpm=10, end_rpm=10),
                Segment(duration_s=1, start_rpm=10, end_rpm=0),
                Segment(duration_s=1, start_rpm=-0.0, end_rpm=-5),
                Segment(duration_s=1, start_rpm=-4, end_rpm=0),
            ),
            "segments.4.start_rpm",  # the first jump named, not the last
        ),
    ],
)
def test_a_cycle_that_cannot_repeat_is_refused(segments: tuple[Segment, ...], field: str) -> None:
    with pytest.raises(InvalidInputError) as caught:
        Motion(segments=segments, load=AxisLoad(inertia_kgm2=1, friction_torque_nm=0))
    assert caught.value.field == field


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"duration_s": 0, "start_rpm": 0, "end_rpm": 10}, "duration_s"),
        ({"duration_s": 1, "start_rpm": 10, "end_rpm": -10}, "end_rpm"),
        ({"duration_s": 1, "start_rpm": 0, "end_rpm": 10, "jerk_share": 1.5}, "jerk_share"),
        ({"duration_s": -1, "start_rpm": 0, "end_rpm": 0}, "duration_s"),
        ({"duration_s": math.inf, "start_rpm": 0, "end_rpm": 0}, "duration_s"),
        ({"duration_s": 1, "start_rpm": 0, "end_rpm": -math.inf}, "end_rpm"),
        ({"duration_s": 1, "start_rpm": math.nan, "end_rpm": math.nan}, "start_rpm"),
        ({"duration_s": 1, "start_rpm": 0, "end_rpm": 0, "jerk_share": math.nan}, "jerk_share"),
        (
            {"duration_s": 1, "start_rpm": 0, "end_rpm": 0, "process_torque_nm": math.inf},
            "process_torque_nm",
        ),
    ],
)
def test_an_impossible_segment_names_its_field(kwargs: dict[str, float], field: str) -> None:
    with pytest.raises(InvalidInputError) as caught:
        Segment(**kwargs)
    assert caught.value.field == field


def test_an_application_is_a_motion_or_the_shorthand_not_both() -> None:
    with pytest.raises(InvalidInputError):
        Application()
    with pytest.raises(InvalidInputError):
        Application(
            pattern=worked_example.PATTERN,
            load=worked_example.LOAD,
            motion=worked_example.APPLICATION.cycle,
        )


def test_figures_of_known_profiles_are_the_computed_figures_bit_for_bit() -> None:
    """A single selection hands its profile's figures to the vectorised flowchart instead of
    computing them again: they must be the very floats ``cycle_figures`` gives."""
    motions = [
        trapezoid(
            speed_rpm=speed,
            accel_s=0.1 * k,
            constant_s=0.07 * k,
            decel_s=0.13,
            pause_s=0.9 / k,
            load=AxisLoad(inertia_kgm2=1.3 / k, friction_torque_nm=5 * k, gravity_torque_nm=k),
        )
        for k, speed in enumerate((40.0, 17.3, 123.45, 3.0), start=1)
    ]
    computed = cycle_figures(piece_arrays(motions))
    known = figures_of([profile_of(m) for m in motions])
    for name in (f.name for f in fields(computed)):
        assert getattr(known, name).tobytes() == getattr(computed, name).tobytes(), name


def _bits(value: object) -> tuple[str, bytes]:
    """A figure's type and its bits: 0.0 and −0.0, 40 and 40.0 told apart."""
    return type(value).__name__, np.float64(value).tobytes()  # type: ignore[arg-type]


@pytest.mark.parametrize("seed", range(3))
def test_the_shorthand_profile_is_that_of_its_four_segments_bit_for_bit(seed: int) -> None:
    """An application of the chapter's shorthand computes its profile from the pattern's
    columns (``trapezoid_profile``) without a piece object: the very figures, types and
    signs of zero that ``profile_of`` sums over the four segments' pieces, and the same
    pieces once read."""
    rng = random.Random(40 + seed)
    for k in range(200):
        speed = rng.choice([40, 3.0, rng.uniform(0.01, 5000.0), 1e150])
        times = [rng.choice([1, 0.1, rng.uniform(1e-3, 10.0)]) for _ in range(2)]
        app = Application(
            pattern=SpeedPattern(
                speed_rpm=speed,
                accel_s=times[0],
                constant_s=rng.choice([0.0, 0, rng.uniform(0.0, 5.0)]),
                decel_s=times[1],
                pause_s=rng.choice([0.0, 2, rng.uniform(0.0, 5.0)]),
            ),
            load=Load(
                torque_nm=rng.choice([-0.0, 0.0, 5, rng.uniform(0.0, 500.0)]),
                inertia_kgm2=rng.choice([0.0, 1, rng.uniform(0.0, 50.0)]),
            ),
        )
        expected: Profile | str
        try:
            expected = profile_of(app.cycle)
        except InvalidInputError as e:
            expected = str(e)  # a load and cycle beyond floating point: the same 422
        if isinstance(expected, str):
            with pytest.raises(InvalidInputError) as raised:
                app.profile  # noqa: B018 - computed when read
            assert str(raised.value) == expected, k
            continue
        got = app.profile
        for f in fields(got):
            if f.name not in ("motion", "load", "pieces"):
                assert _bits(getattr(got, f.name)) == _bits(getattr(expected, f.name)), (k, f)
        assert got.motion == expected.motion
        assert got.load == expected.load
        assert got.pieces == expected.pieces
        assert [_bits(p.static_nm) for p in got.pieces] == [
            _bits(p.static_nm) for p in expected.pieces
        ]


def test_one_trapezoid_as_columns_is_its_row_of_many_bit_for_bit() -> None:
    """A single case's trapezoid pieces are built on Python floats: the very arrays that
    the same case gets as one row of many, overflows to ±∞ and zeros' signs included."""
    rng = random.Random(11)
    names = ("speed_rpm", "accel_s", "constant_s", "decel_s", "pause_s", "torque_nm")
    rows = [
        [
            rng.choice([40.0, 1e300, rng.uniform(0.01, 5000.0)]),
            rng.choice([0.1, 1e-300, rng.uniform(1e-3, 10.0)]),
            rng.choice([0.0, rng.uniform(0.0, 5.0)]),
            rng.choice([0.1, 1e-300, 0.0, rng.uniform(1e-3, 10.0)]),
            rng.choice([0.0, rng.uniform(0.0, 5.0)]),
            rng.choice([-0.0, 0.0, 5.0, rng.uniform(0.0, 500.0)]),
            rng.choice([0.0, 1.3, math.nan, rng.uniform(0.0, 50.0)]),
        ]
        for _ in range(300)
    ]
    table = np.array(rows, dtype=np.float64)

    def columns(at: slice) -> dict[str, np.ndarray]:
        out = {name: table[at, k] for k, name in enumerate(names)}
        return {**out, "inertia_kgm2": table[at, 6]}

    many = trapezoid_piece_arrays(**columns(slice(None)))
    for i in range(len(rows)):
        one = trapezoid_piece_arrays(**columns(slice(i, i + 1)))
        for f in fields(one):
            expected = getattr(many, f.name)[i : i + 1]
            assert getattr(one, f.name).tobytes() == expected.tobytes(), (i, f.name)


@pytest.mark.parametrize("seed", range(4))
def test_one_profile_sums_on_floats_what_many_sum_on_arrays(seed: int) -> None:
    """``profile_of`` sums one cycle's figures on Python floats, ``cycle_figures`` many
    cycles' on numpy arrays (short cycles padded): the same floats, to the bit, for cycles
    of segments with S-curves, reversals, weights, losses and process torques."""
    rng = random.Random(700 + seed)
    motions = [random_motion_case(rng).cycle for _ in range(30)]
    arrays = cycle_figures(piece_arrays(motions))
    for i, motion in enumerate(motions):
        profile = profile_of(motion)
        for name in (f.name for f in fields(arrays)):
            expected = getattr(arrays, name)[i]
            assert np.float64(getattr(profile, name)).tobytes() == expected.tobytes(), (i, name)


def test_heating_gains_on_arrays_are_heating_gain_bit_for_bit() -> None:
    """The engine's gains of a block (``heating_gain_array``) are the floats' own, to the
    last bit, for ordinary and extreme durations and time constants alike."""
    rng = random.Random(5)
    specials = [0.0, 5e-324, 1e-300, 1e-8, 0.1, 1.0, 600.0, 1e300, math.inf]
    durations = [*specials, *(10 ** rng.uniform(-6, 5) for _ in range(500))]
    taus = [
        5e-324,
        1e-300,
        0.5,
        600.0,
        3600.0,
        1e300,
        *(10 ** rng.uniform(-2, 4) for _ in range(9)),
    ]
    table = np.array([[t, tau] for t in durations for tau in taus])
    with np.errstate(all="ignore"):  # as the engine calls it: t/τ overflows to ∞ here
        gains = heating_gain_array(table[:, :1], table[:, 1:]).ravel()
    expected = np.array([heating_gain(t, tau) for t, tau in table.tolist()])
    assert gains.view(np.uint64).tolist() == expected.view(np.uint64).tolist()
