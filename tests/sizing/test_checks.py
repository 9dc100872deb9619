"""The rules (sizing/checks/): one definition of each check, run by the engine and the oracle."""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np
import pytest
from tests import worked_example
from tests.oracle.flowchart import ORDER, operands

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.sizing import checks, selection
from actuator_selection.sizing.checks import FLOAT_OPS, RULES, Check, Operands, Requirement, Status
from actuator_selection.sizing.checks.rule import _new_check
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.engine import ARRAY_OPS, CHECK_NAMES
from actuator_selection.sizing.motion import CycleTorques
from actuator_selection.sizing.selection import Application, evaluate

EXAMPLE = worked_example.APPLICATION
FHA = worked_example.FHA_25C_50_L


def zone(*points: tuple[float, float]) -> ContinuousDutyZone:
    return ContinuousDutyZone(points=tuple(ZonePoint(speed_rpm=s, torque_nm=t) for s, t in points))


def test_the_table_holds_the_chapters_five_checks_in_flowchart_order() -> None:
    """The chapter's five, then whether T_rms stands for the cycle's length, then whether
    a listed controller delivers the voltage (issue 28, item 1)."""
    assert [(r.name, r.reference, r.unit) for r in RULES] == [
        ("max_speed", "Table 515.1", "rpm"),
        ("inertia_ratio", "Table 515.1", "kgm²"),
        ("peak_torque", "Eq. 514.1", "Nm"),
        ("decel_torque", "Eq. 514.1", "Nm"),
        ("continuous_duty", "Fig. 517.1; Eq. 522.2, 522.3", "Nm"),
        ("thermal_peak", "Fig. 520.1 (model); Eq. 514.2", "Nm"),
        ("continuous_speed", "Eq. 514.3; Fig. 520.1 (model)", "rpm"),
        ("drive_voltage", "Eq. 521.2 with ωL·I in quadrature", "V"),
    ]
    assert tuple(r.name for r in RULES) == CHECK_NAMES


def test_names_that_moved_stay_importable_from_selection() -> None:
    assert selection.Check is checks.Check
    assert selection.Status is checks.Status
    assert selection.INERTIA_RATIO_LIMIT == checks.INERTIA_RATIO_LIMIT == 3.0


def test_the_rules_fast_check_constructor_builds_a_check() -> None:
    """Rule.check builds checks without the generated __init__: they must be the same."""
    args: dict[str, Any] = {
        "name": "n",
        "status": Status.WARN,
        "value": 1.5,
        "limit": None,
        "unit": "Nm",
        "reference": "Eq. 514.1",
        "message": "m",
        "approximate": True,
        "missing": "x",
    }
    assert list(args) == [f.name for f in dataclasses.fields(Check)]  # every field, in order
    fast = _new_check(*args.values())
    assert type(fast) is Check
    assert fast == Check(**args)
    assert repr(fast) == repr(Check(**args))
    assert dataclasses.asdict(fast) == args
    with pytest.raises(dataclasses.FrozenInstanceError):
        fast.value = 2.0  # type: ignore[misc]
    assert evaluate(FHA, EXAMPLE).checks[0] == Check(
        name="max_speed",
        status=Status.PASS,
        value=40,
        limit=90,
        unit="rpm",
        reference="Table 515.1",
        message="load speed n_2 = 40 rpm ≤ n_max = 90 rpm",
    )


def test_deferred_words_are_written_once_when_read() -> None:
    """Rule.report with defer (the batch's candidates) is the same check as without: the
    message is written on first read and then kept; ==, hash and repr read it too."""
    q = operands(FHA, EXAMPLE, EXAMPLE.profile.torques(FHA.inertia_kgm2 or 0.0), EXAMPLE.profile)
    for plain in RULES:
        written: list[str] = []

        def counted(*args: Any, words: Any = plain.message, log: list[str] = written) -> str:
            log.append(words(*args))
            return log[-1]

        rule = dataclasses.replace(plain, message=counted)
        eager = plain.check(q)
        status, value = eager.status, rule.value(q, FLOAT_OPS)
        missing = None
        if eager.missing is not None:  # no data: the index of what is missing
            missing = [need.what for need in rule.requires].index(eager.missing)
        args = (q, status, value, rule.limit(q, FLOAT_OPS), eager.approximate, missing)
        deferred = rule.report(*args, defer=True)
        assert written == [], rule.name  # nothing written yet
        assert deferred == eager, rule.name
        assert hash(deferred) == hash(eager)
        assert repr(deferred) == repr(eager)
        assert deferred.message is deferred.message  # written once, then kept
        assert dataclasses.asdict(deferred) == dataclasses.asdict(eager)
        # a no-data message is one constant per requirement: nothing to write
        assert len(written) == (status is not Status.NO_DATA), rule.name
    with pytest.raises(dataclasses.FrozenInstanceError):
        deferred.message = "changed"  # type: ignore[misc]


def test_operands_name_each_value() -> None:
    """operands() builds the named tuple positionally: each value lands in its field."""
    actuator = Actuator(
        model="M",
        family="F",
        gear_ratio=50,
        max_torque_nm=11,
        max_speed_rpm=12,
        inertia_kgm2=13,
        stall_torque_nm=14,
        continuous_torque_nm=15,
        zone=zone((0, 40), (100, 30)),
        continuous_speed_rpm=16,
        rated_speed_rpm=17,
        brake_holding_torque_nm=18,
    )
    app = Application(
        pattern=SpeedPattern(speed_rpm=21, accel_s=1, constant_s=1, decel_s=1, pause_s=1),
        load=Load(torque_nm=5, inertia_kgm2=22),
        high_dynamics=False,
    )
    torques = CycleTorques(
        accel_torque_nm=31, constant_torque_nm=5, decel_torque_nm=-33, rms_torque_nm=34
    )
    profile = dataclasses.replace(
        app.profile,
        mean_speed_rpm=50.0,
        accel_floor_nm=41,
        decel_floor_nm=42,
        rms_floor_nm=43,
    )
    q = operands(actuator, app, torques, profile)
    # The drive's and the output bearing's operands: tests/sizing/test_drive_current.py.
    named = q._asdict()
    assert {k: named[k] for k in ORDER[: ORDER.index("decel_s")]} == {
        "speed_rpm": 21,
        "load_inertia_kgm2": 22,
        "high_dynamics": False,
        "mean_speed_rpm": 50.0,
        "accel_torque_nm": 31,
        "decel_torque_nm": -33,
        "rms_torque_nm": 34,
        "max_torque_nm": 11,
        "max_speed_rpm": 12,
        "inertia_kgm2": 13,
        "stall_torque_nm": 14,
        "continuous_torque_nm": 15,
        "has_zone": True,
        "zone_torque_nm": 35.0,
        "zone_max_speed_rpm": 100,
        "accel_torque_floor_nm": 41,
        "decel_torque_floor_nm": 42,
        "rms_torque_floor_nm": 43,
        "continuous_speed_rpm": 16,
        "rated_speed_rpm": 17,
        "load_torque_nm": 5,
        "brake_holding_torque_nm": 18,
    }
    bare = operands(Actuator(model="B", family="F", gear_ratio=50), app, None, profile)
    first_new = ORDER.index("decel_s")  # later ones: test_drive_current.py
    values = bare._asdict()
    unpublished = [
        name for name in ORDER[:first_new] if isinstance(v := values[name], float) and math.isnan(v)
    ]
    assert unpublished == [
        "accel_torque_nm",
        "decel_torque_nm",
        "rms_torque_nm",
        "max_torque_nm",
        "max_speed_rpm",
        "inertia_kgm2",
        "stall_torque_nm",
        "continuous_torque_nm",
        "zone_torque_nm",
        "zone_max_speed_rpm",
        "continuous_speed_rpm",
        "rated_speed_rpm",
        "brake_holding_torque_nm",
    ]
    assert bare.has_zone is False
    beyond = operands(actuator, app, torques, dataclasses.replace(profile, mean_speed_rpm=101.0))
    assert math.isnan(beyond.zone_torque_nm)


def worked_operands(**changes: float | bool) -> Operands:
    actuator = dataclasses.replace(FHA, stall_torque_nm=36)
    torques = evaluate(actuator, EXAMPLE).torques
    profile = dataclasses.replace(EXAMPLE.profile, mean_speed_rpm=8 / 1.3)
    return operands(actuator, EXAMPLE, torques, profile)._replace(**changes)


@pytest.mark.parametrize(
    "unpublished",
    [
        (),
        ("max_speed_rpm",),
        ("inertia_kgm2",),
        ("max_torque_nm",),
        ("stall_torque_nm",),
        ("stall_torque_nm", "continuous_torque_nm"),
        ("stall_torque_nm", "continuous_torque_nm", "max_speed_rpm"),
    ],
)
@pytest.mark.parametrize("has_zone", [False, True])
def test_requirements_decide_no_data_alike_on_floats_and_arrays(
    unpublished: tuple[str, ...], has_zone: bool
) -> None:
    """Rule.check's short cut for floats, Requirement.missing on floats and on arrays."""
    q = worked_operands(has_zone=has_zone, **dict.fromkeys(unpublished, math.nan))
    arrays = Operands(*(np.array([v]) for v in q))
    for rule in RULES:
        no_data = rule.check(q).status is Status.NO_DATA
        assert no_data == any(need.missing(q, FLOAT_OPS) for need in rule.requires), rule.name
        masks = [need.missing(arrays, ARRAY_OPS) for need in rule.requires]
        assert no_data == bool(np.any(masks)), rule.name


def test_a_requirement_is_met_by_any_of_its_values_or_its_exemption() -> None:
    need = Requirement(
        any_of=("stall_torque_nm", "continuous_torque_nm"), unless="has_zone", what="x"
    )
    nan = math.nan
    assert not need.missing(
        worked_operands(stall_torque_nm=nan, continuous_torque_nm=40), FLOAT_OPS
    )
    assert need.missing(worked_operands(stall_torque_nm=nan, continuous_torque_nm=nan), FLOAT_OPS)
    assert not need.missing(
        worked_operands(stall_torque_nm=nan, continuous_torque_nm=nan, has_zone=True), FLOAT_OPS
    )


WORKED_PASSES = (
    ("pass", "load speed n_2 = 40 rpm ≤ n_max = 90 rpm", False),
    ("pass", "load inertia J_L = 1.3 kgm² ≤ 3·J_A = 2.58 kgm²", False),
    ("pass", "acceleration torque T_1 = 95.48 Nm ≤ T_max = 151 Nm", False),
    ("pass", "deceleration torque |T_3| = 85.48 Nm ≤ T_max = 151 Nm", False),
)
"""The worked example's first four checks on FHA-25C-50-L (Table 516.1/516.3): T_1 95.48 Nm,
|T_3| 85.48 Nm, as the chapter gives them."""

STALL_PASS = (
    "pass",
    "approximate: operating point (n_av = 6.154 rpm, T_rms = 35.57 Nm) within continuous "
    "stall torque T_0 = 36 Nm (no continuous-duty zone published: the limit is taken as "
    "constant with speed; the speed is checked on its own)",
    True,
)
"""The continuous check of the worked example on a CHA-like FHA-25C-50-L: T_0 = 36 Nm
and a rated output speed of 70 rpm (CHA-25A-50: 3500 rpm / 50)."""

# Every message the flowchart writes, pinned: generated with the hand-written checks
# that the rule table replaced; continuous_duty's rectangle words since its speed moved to
# continuous_speed (issue "A verdict an application engineer signs", item 5).
MESSAGES = {
    "example": (
        *WORKED_PASSES,
        (
            "no_data",
            "no data: the catalogue gives no continuous-duty zone or continuous torque for this "
            "actuator",
            False,
        ),
    ),
    "fast": (
        ("fail", "load speed n_2 = 91 rpm exceeds n_max = 90 rpm", False),
        ("pass", "load inertia J_L = 1.3 kgm² ≤ 3·J_A = 2.58 kgm²", False),
        ("fail", "acceleration torque T_1 = 210.8 Nm exceeds T_max = 151 Nm", False),
        ("fail", "deceleration torque |T_3| = 200.8 Nm exceeds T_max = 151 Nm", False),
        (
            "no_data",
            "no data: the catalogue gives no continuous-duty zone or continuous torque for this "
            "actuator",
            False,
        ),
    ),
    "heavy": (
        ("pass", "load speed n_2 = 40 rpm ≤ n_max = 90 rpm", False),
        (
            "fail",
            "load inertia J_L = 2.6 kgm² exceeds 3·J_A = 2.58 kgm²: the limit is binding for a "
            "highly dynamic application",
            False,
        ),
        ("pass", "acceleration torque T_1 = 149.9 Nm ≤ T_max = 151 Nm", False),
        ("pass", "deceleration torque |T_3| = 139.9 Nm ≤ T_max = 151 Nm", False),
        (
            "no_data",
            "no data: the catalogue gives no continuous-duty zone or continuous torque for this "
            "actuator",
            False,
        ),
    ),
    "heavy_relaxed": (
        ("pass", "load speed n_2 = 40 rpm ≤ n_max = 90 rpm", False),
        (
            "warn",
            "load inertia J_L = 2.6 kgm² exceeds 3·J_A = 2.58 kgm²: recommended for highly "
            "dynamic applications only",
            False,
        ),
        ("pass", "acceleration torque T_1 = 149.9 Nm ≤ T_max = 151 Nm", False),
        ("pass", "deceleration torque |T_3| = 139.9 Nm ≤ T_max = 151 Nm", False),
        (
            "no_data",
            "no data: the catalogue gives no continuous-duty zone or continuous torque for this "
            "actuator",
            False,
        ),
    ),
    "small": (
        ("pass", "load speed n_2 = 40 rpm ≤ n_max = 90 rpm", False),
        ("pass", "load inertia J_L = 1.3 kgm² ≤ 3·J_A = 2.58 kgm²", False),
        ("fail", "acceleration torque T_1 = 95.48 Nm exceeds T_max = 50 Nm", False),
        ("fail", "deceleration torque |T_3| = 85.48 Nm exceeds T_max = 50 Nm", False),
        (
            "no_data",
            "no data: the catalogue gives no continuous-duty zone or continuous torque for this "
            "actuator",
            False,
        ),
    ),
    "bare": (
        (
            "no_data",
            "no data: the catalogue gives no maximum output speed n_max for this actuator",
            False,
        ),
        (
            "no_data",
            "no data: the catalogue gives no moment of inertia J_A for this actuator",
            False,
        ),
        (
            "no_data",
            "no data: the catalogue gives no moment of inertia J_A for this actuator",
            False,
        ),
        (
            "no_data",
            "no data: the catalogue gives no moment of inertia J_A for this actuator",
            False,
        ),
        (
            "no_data",
            "no data: the catalogue gives no moment of inertia J_A (T_rms needs it) for this "
            "actuator",
            False,
        ),
    ),
    "no_tmax": (
        ("pass", "load speed n_2 = 40 rpm ≤ n_max = 90 rpm", False),
        ("pass", "load inertia J_L = 1.3 kgm² ≤ 3·J_A = 2.58 kgm²", False),
        (
            "no_data",
            "no data: the catalogue gives no maximum torque T_max for this actuator",
            False,
        ),
        (
            "no_data",
            "no data: the catalogue gives no maximum torque T_max for this actuator",
            False,
        ),
        STALL_PASS,
    ),
    "no_nmax": (
        (
            "no_data",
            "no data: the catalogue gives no maximum output speed n_max for this actuator",
            False,
        ),
        ("pass", "load inertia J_L = 1.3 kgm² ≤ 3·J_A = 2.58 kgm²", False),
        ("pass", "acceleration torque T_1 = 95.48 Nm ≤ T_max = 151 Nm", False),
        ("pass", "deceleration torque |T_3| = 85.48 Nm ≤ T_max = 151 Nm", False),
        STALL_PASS,  # the continuous check needs no n_max, a peak speed
    ),
    "no_speed": (*WORKED_PASSES, STALL_PASS),  # the speed lacks data: continuous_speed
    "above_rated": (*WORKED_PASSES, STALL_PASS),  # the speed fails: continuous_speed
    "zone_inside": (
        *WORKED_PASSES,
        (
            "pass",
            "operating point (n_av = 6.154 rpm, T_rms = 35.57 Nm) lies inside the continuous-duty "
            "zone (limit 39.32 Nm at n_av)",
            False,
        ),
    ),
    "zone_above": (
        *WORKED_PASSES,
        (
            "fail",
            "operating point (n_av = 6.154 rpm, T_rms = 35.57 Nm) lies above the continuous-duty "
            "zone (limit 34.66 Nm at n_av)",
            False,
        ),
    ),
    "zone_beyond": (
        *WORKED_PASSES,
        (
            "fail",
            "operating point (n_av = 6.154 rpm, T_rms = 35.57 Nm) lies beyond the continuous-duty "
            "zone, which ends at 5 rpm",
            False,
        ),
    ),
    "stall_pass": (*WORKED_PASSES, STALL_PASS),
    "stall_fail": (
        *WORKED_PASSES,
        (
            "fail",
            "approximate: operating point (n_av = 6.154 rpm, T_rms = 35.57 Nm) exceeds continuous "
            "stall torque T_0 = 35 Nm (no continuous-duty zone published: the limit is taken as "
            "constant with speed; the speed is checked on its own)",
            True,
        ),
    ),
    "allowable": (
        *WORKED_PASSES,
        (
            "pass",
            "approximate: operating point (n_av = 6.154 rpm, T_rms = 35.57 Nm) within allowable "
            "continuous torque = 40 Nm (no continuous-duty zone published: the limit is taken as "
            "constant with speed; the speed is checked on its own)",
            True,
        ),
    ),
}


def _heating(status: str, against: str) -> tuple[str, str, bool]:
    """The thermal_peak check of the worked example's cycle (t_0 = 1.3 s) with the assumed
    τ_th = 600 s: the heating peaks at 35.58 Nm, just above T_rms = 35.57 Nm (by hand,
    linearised: x swings about its mean T_rms² = 1265.2 Nm² by Σ(m_k − T_rms²)·t_k/τ_th and
    peaks 1.03 Nm² above it, at the end of braking)."""
    return (
        status,
        f"winding heating over the repeating cycle peaks at 35.58 Nm as a torque{against} "
        "(first-order thermal model, τ_th = 600 s assumed: not published for this actuator; "
        "cycle t_0 = 1.3 s = 0.00217·τ_th, short against τ_th: T_rms = 35.57 Nm governs)",
        True,
    )


NO_CONTINUOUS = (
    "no_data",
    "no data: the catalogue gives no continuous-duty zone or continuous torque for this actuator",
    False,
)
HEATING = {
    "example": NO_CONTINUOUS,
    "fast": NO_CONTINUOUS,
    "heavy": NO_CONTINUOUS,
    "heavy_relaxed": NO_CONTINUOUS,
    "small": NO_CONTINUOUS,
    "bare": (
        "no_data",
        "no data: the catalogue gives no moment of inertia J_A (the cycle's torques need it) "
        "for this actuator",
        False,
    ),
    "no_tmax": _heating("pass", " ≤ the continuous limit 36 Nm"),
    "no_nmax": _heating("pass", " ≤ the continuous limit 36 Nm"),
    "no_speed": _heating("pass", " ≤ the continuous limit 36 Nm"),
    "above_rated": _heating("pass", " ≤ the continuous limit 36 Nm"),
    "zone_inside": _heating("pass", " ≤ the continuous limit 39.32 Nm"),
    "zone_above": _heating("fail", " exceeds the continuous limit 34.66 Nm"),
    "zone_beyond": _heating(
        "fail", ", with n_av = 6.154 rpm beyond the continuous-duty zone, which ends at 5 rpm"
    ),
    "stall_pass": _heating("pass", " ≤ the continuous limit 36 Nm"),
    "stall_fail": _heating("fail", " exceeds the continuous limit 35 Nm"),
    "allowable": _heating("pass", " ≤ the continuous limit 40 Nm"),
}
"""The sixth check's message in each scenario (``thermal_peak``): where ``continuous_duty``
has its data, the heating peak of this short cycle against the same limit."""


def _speed(status: str, against: str) -> tuple[str, str, bool]:
    """The continuous_speed check of the worked example's cycle with the assumed τ_th =
    600 s: n_th peaks at 6.159 rpm, just above n_av = 6.154 rpm (the ripple of |n| about its
    mean over a 1.3 s cycle, 40 rpm·0.2 s·1.1 s/1.3 s/600 s ≈ 0.01 rpm)."""
    return (
        status,
        "speed the winding's heating follows n_th = 6.159 rpm (cycle mean n_av = 6.154 rpm; "
        "first-order thermal model, τ_th = 600 s assumed: not published for this actuator; a "
        f"segment long against τ_th counts with its own speed, whatever n_av){against}",
        True,
    )


NO_SPEED = (
    "no_data",
    "no data: the catalogue gives no continuous-duty zone or allowable continuous or rated "
    "speed for this actuator",
    False,
)
SPEED = {
    **dict.fromkeys(
        ("example", "fast", "heavy", "heavy_relaxed", "small", "bare", "no_speed"), NO_SPEED
    ),
    "no_tmax": _speed("pass", " ≤ the rated speed 70 rpm"),
    "no_nmax": _speed("pass", " ≤ the rated speed 70 rpm"),
    "above_rated": _speed(
        "fail", " exceeds the rated speed 5 rpm: continuous operation above it is not allowed"
    ),
    "zone_inside": _speed("pass", " ≤ the continuous-duty zone's last speed 90 rpm"),
    "zone_above": _speed("pass", " ≤ the continuous-duty zone's last speed 90 rpm"),
    "zone_beyond": _speed(
        "fail",
        " exceeds the continuous-duty zone's last speed 5 rpm: continuous operation above it "
        "is not allowed",
    ),
    "stall_pass": _speed("pass", " ≤ the rated speed 70 rpm"),
    "stall_fail": _speed("pass", " ≤ the rated speed 70 rpm"),
    "allowable": _speed("pass", " ≤ the allowable continuous speed 35 rpm"),
}
"""The seventh check's message in each scenario (``continuous_speed``)."""


@pytest.mark.parametrize("scenario", MESSAGES)
def test_every_branch_writes_the_same_message(scenario: str) -> None:
    heavy = dataclasses.replace(EXAMPLE, load=Load(torque_nm=5, inertia_kgm2=2.6))
    fast = dataclasses.replace(
        EXAMPLE, pattern=dataclasses.replace(worked_example.PATTERN, speed_rpm=91)
    )
    cha_like = dataclasses.replace(FHA, stall_torque_nm=36, rated_speed_rpm=70)
    actuator, app = {
        "example": (FHA, EXAMPLE),
        "fast": (FHA, fast),
        "heavy": (FHA, heavy),
        "heavy_relaxed": (FHA, dataclasses.replace(heavy, high_dynamics=False)),
        "small": (dataclasses.replace(FHA, max_torque_nm=50), EXAMPLE),
        "bare": (Actuator(model="X", family="F", gear_ratio=50), EXAMPLE),
        "no_tmax": (dataclasses.replace(cha_like, max_torque_nm=None), EXAMPLE),
        "no_nmax": (dataclasses.replace(cha_like, max_speed_rpm=None), EXAMPLE),
        "no_speed": (dataclasses.replace(FHA, stall_torque_nm=36), EXAMPLE),
        "above_rated": (dataclasses.replace(cha_like, rated_speed_rpm=5), EXAMPLE),
        "zone_inside": (dataclasses.replace(FHA, zone=zone((0, 40), (90, 30))), EXAMPLE),
        "zone_above": (dataclasses.replace(FHA, zone=zone((0, 35), (90, 30))), EXAMPLE),
        "zone_beyond": (dataclasses.replace(FHA, zone=zone((0, 80), (5, 80))), EXAMPLE),
        "stall_pass": (cha_like, EXAMPLE),
        "stall_fail": (dataclasses.replace(cha_like, stall_torque_nm=35), EXAMPLE),
        "allowable": (
            dataclasses.replace(FHA, continuous_torque_nm=40, continuous_speed_rpm=35),
            EXAMPLE,
        ),
    }[scenario]
    *flowchart, drive = evaluate(actuator, app).checks
    got = tuple((k.status.value, k.message, k.approximate) for k in flowchart)
    assert got == (*MESSAGES[scenario], HEATING[scenario], SPEED[scenario])
    # None of these gives the winding's constants: the drive's voltage is not confirmed.
    assert (drive.name, drive.status.value) == ("drive_voltage", "no_data")
