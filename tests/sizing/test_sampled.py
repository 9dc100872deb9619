"""Samples to segments (sizing/sampled.py): exact where ramps fit, reversals through 0,
loads as segment means, noise capped at the segment bound with its deviation stated."""

from __future__ import annotations

import numpy as np
import pytest

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.motion import Motion, Segment
from actuator_selection.sizing.sampled import fit_segments, sample_figures, speeds_from_positions


def test_a_reversal_becomes_two_segments_through_standstill() -> None:
    t = np.array([0.0, 1.0, 2.0, 3.0])
    v = np.array([0.0, 10.0, -10.0, 0.0])
    cycle = fit_segments(t, v, None)
    ends = [round(e, 9) for _, e, _ in cycle.segments]
    assert ends == [10.0, 0.0, -10.0, 0.0]
    assert [round(d, 9) for d, _, _ in cycle.segments] == [1.0, 0.5, 0.5, 1.0]
    # the flowchart takes them: no segment changes sign
    start = cycle.start_speed
    segments = []
    for d, e, p in cycle.segments:
        segments.append(Segment(duration_s=d, start_rpm=start, end_rpm=e, process_torque_nm=p))
        start = e
    Motion(segments=tuple(segments), load=AxisLoad(inertia_kgm2=1.0, friction_torque_nm=0.0))
    # n_av of a sign change: two triangles of 0.5 s at 10 rpm each side, and the ramps
    assert cycle.samples.mean_speed == pytest.approx((5 + 2.5 + 2.5 + 5) / 3)


def test_loads_are_the_time_weighted_means_of_their_segments() -> None:
    t = np.linspace(0.0, 2.0, 201)
    v = np.interp(t, [0.0, 0.5, 1.5, 2.0], [0.0, 20.0, 20.0, 0.0])
    load = np.where(t < 1.0, 4.0, 8.0)
    cycle = fit_segments(t, v, load, tolerance=0.01)
    # the step between two samples is a segment of its own, at the mean of its ends
    assert {round(p, 6) for _, _, p in cycle.segments} == {4.0, 6.0, 8.0}
    assert cycle.load_deviation == pytest.approx(2.0)
    assert not cycle.exact
    assert cycle.fitted.rms_load == pytest.approx(cycle.samples.rms_load, rel=0.01)


def test_noise_is_capped_at_the_segment_bound_and_says_how_far() -> None:
    rng = np.random.default_rng(3)
    t = np.linspace(0.0, 10.0, 10_001)
    v = 30 * np.sin(np.pi * t / 10) + rng.normal(0, 0.3, t.size)
    v[0] = v[-1] = 0.0
    cycle = fit_segments(t, v, None, max_segments=50)
    assert len(cycle.segments) <= 50
    assert not cycle.exact
    assert 0 < cycle.deviation < 3
    assert cycle.fitted.mean_speed == pytest.approx(cycle.samples.mean_speed, rel=0.02)


def test_an_open_cycle_is_refused() -> None:
    with pytest.raises(InvalidInputError) as caught:
        fit_segments(np.array([0.0, 1.0, 2.0]), np.array([0.0, 5.0, 5.0]), None)
    assert caught.value.code == "profile_not_closed"


def test_positions_of_a_ramp_give_its_speeds_exactly() -> None:
    t = np.linspace(0.0, 1.0, 11)
    x = 0.5 * 3.0 * t * t
    assert speeds_from_positions(t, x) == pytest.approx(3.0 * t, abs=1e-12)


def test_figures_of_the_chapters_cycle() -> None:
    t = np.array([0.0, 0.1, 0.2, 0.3, 1.3])
    v = np.array([0.0, 40.0, 40.0, 0.0, 0.0])
    f = sample_figures(t, v, None)
    assert f.mean_speed == pytest.approx(40 * 0.2 / 1.3)  # Eq. 514.3
    assert f.duty_cycle_percent == pytest.approx(0.3 / 1.3 * 100)  # Eq. 514.4
