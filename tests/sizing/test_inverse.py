"""The inverse solve's edges: no limit in range, the range's end reached, and the bound
agreeing with the flowchart on both sides."""

from __future__ import annotations

import dataclasses

from tests import worked_example

from actuator_selection.sizing.inverse import (
    MAX_LOAD_INERTIA_KGM2,
    largest_load_inertia,
    shortest_accel,
    shortest_pause,
)
from actuator_selection.sizing.selection import Verdict, evaluate

FHA = worked_example.FHA_25C_50_L
EXAMPLE = worked_example.APPLICATION


def test_a_check_that_no_pause_relieves_gives_no_limit() -> None:
    slow = dataclasses.replace(FHA, max_speed_rpm=30)  # n_2 = 40 rpm > n_max at any t_p
    limit = shortest_pause(slow, EXAMPLE)
    assert limit.value is None
    assert limit.limiting_checks == ("max_speed",)
    assert limit.verdict is Verdict.UNSUITABLE


def test_the_end_of_the_range_is_said_as_such() -> None:
    huge = dataclasses.replace(FHA, inertia_kgm2=1e7, max_torque_nm=1e12)
    limit = largest_load_inertia(huge, dataclasses.replace(EXAMPLE, high_dynamics=False))
    assert limit.value == MAX_LOAD_INERTIA_KGM2
    assert limit.limiting_checks == ()


def test_the_shortest_ramp_is_where_peak_torque_starts_to_fail() -> None:
    limit = shortest_accel(FHA, EXAMPLE)
    assert limit.value is not None
    assert EXAMPLE.pattern is not None

    def at(t: float) -> set[str]:
        pattern = dataclasses.replace(worked_example.PATTERN, accel_s=t)
        app = dataclasses.replace(EXAMPLE, pattern=pattern)
        return {c.name for c in evaluate(FHA, app).checks if c.status.value == "fail"}

    assert at(limit.value) == set()
    assert at(limit.value * (1 - 1e-6)) == {"peak_torque"}
