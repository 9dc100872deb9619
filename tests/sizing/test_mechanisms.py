"""Mechanisms at the actuator output against energy and power balances (issue "Real axes").

Expected values are computed here from the physics (work against gravity, kinetic energy,
power through an efficiency), not copied from the module's results.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import (
    STANDARD_GRAVITY_M_PER_S2,
    BallScrew,
    RotaryTable,
    ball_screw_load,
    rotary_table_load,
)
from actuator_selection.sizing.mechanisms import (
    BeltDrive,
    Conveyor,
    Hoist,
    InclinedBallScrew,
    RackPinion,
    Transmission,
    belt_axis,
    chapter_ball_screw_axis,
    conveyor_axis,
    hoist_axis,
    inclined_ball_screw_axis,
    rack_pinion_axis,
    rotary_table_axis,
    with_transmission,
)

G = STANDARD_GRAVITY_M_PER_S2
REL = 1e-12  # the same physics in another order: only rounding differs


def _rpm(omega_rad_per_s: float) -> float:
    return omega_rad_per_s * 60 / (2 * math.pi)


# --- the chapter's mechanisms: exactly sizing/loads.py -------------------------------------


@pytest.mark.parametrize(
    ("mass", "lead", "mu", "eta", "js"),
    [(100, 0.01, 0.1, 0.9, 0.001), (250, 0.02, 0.05, 0.9, 0.004), (0, 0.005, 0.0, 1.0, 0.0)],
)
def test_chapter_ball_screw_is_eq_515_4_exactly(
    mass: float, lead: float, mu: float, eta: float, js: float
) -> None:
    screw = BallScrew(
        mass_kg=mass, lead_m=lead, friction_coefficient=mu, efficiency=eta, screw_inertia_kgm2=js
    )
    load = ball_screw_load(screw)
    axis = chapter_ball_screw_axis(screw)
    assert axis.inertia_kgm2 == load.inertia_kgm2
    assert axis.friction_torque_nm == load.torque_nm
    assert axis.gravity_torque_nm == 0
    assert axis.efficiency == 1  # Eq. 515.4 divided T_F by η already
    assert (axis.speed_unit, axis.force_unit) == ("mm/s", "N")
    # 1 mm/s on a lead P [m] is 1e-3/P rev/s = 60e-3/P rpm.
    assert axis.speed_rpm_per_unit == pytest.approx(60e-3 / lead, rel=REL)


def test_rotary_table_is_eq_515_6_exactly() -> None:
    table = RotaryTable(
        mass_kg=80, diameter_m=0.6, friction_coefficient=0.03, friction_radius_m=0.2
    )
    load = rotary_table_load(table)
    axis = rotary_table_axis(table)
    assert (axis.inertia_kgm2, axis.friction_torque_nm) == (load.inertia_kgm2, load.torque_nm)
    assert (axis.speed_rpm_per_unit, axis.torque_nm_per_force_unit) == (1, 1)
    assert (axis.speed_unit, axis.force_unit, axis.efficiency) == ("rpm", "Nm", 1)


# --- gravity from the work done against it ------------------------------------------------


def _gravity_torque_by_work(lifted_kg: float, lowered_kg: float, *, rise_m_per_rad: float) -> float:
    """T_G = dE_pot/dφ: one radian of the shaft lifts one mass and lowers the other."""
    return (lifted_kg - lowered_kg) * G * rise_m_per_rad


@pytest.mark.parametrize("counterweight", [0.0, 3.0, 5.0, 8.0])
def test_vertical_belt_axis_with_and_without_counterweight(counterweight: float) -> None:
    mass, diameter = 5.0, 0.05
    axis = belt_axis(
        BeltDrive(
            mass_kg=mass,
            pulley_diameter_m=diameter,
            friction_coefficient=0.3,
            efficiency=0.9,
            incline_deg=90,
            belt_mass_kg=0.4,
            counterweight_kg=counterweight,
        )
    )
    # One radian of the pulley moves the carriage up by D/2, the counterweight down by as much.
    expected = _gravity_torque_by_work(mass, counterweight, rise_m_per_rad=diameter / 2)
    assert axis.gravity_torque_nm == pytest.approx(expected, rel=REL)
    assert (axis.gravity_torque_nm > 0) == (counterweight < mass)  # overhauling past balance
    assert axis.friction_torque_nm == 0  # a vertical guide carries no weight
    # Every mass moves at v = ω·D/2: J = Σm·(D/2)², the counterweight's too.
    assert axis.inertia_kgm2 == pytest.approx((mass + 0.4 + counterweight) * 0.025**2, rel=REL)


def test_vertical_hoist_with_and_without_counterweight() -> None:
    bare = hoist_axis(Hoist(load_mass_kg=100, drum_diameter_m=0.2, efficiency=0.9))
    balanced = hoist_axis(
        Hoist(load_mass_kg=100, drum_diameter_m=0.2, efficiency=0.9, counterweight_kg=100)
    )
    assert bare.gravity_torque_nm == pytest.approx(
        _gravity_torque_by_work(100, 0, rise_m_per_rad=0.1)
    )
    assert balanced.gravity_torque_nm == 0
    # The counterweight takes the weight away and doubles the inertia.
    assert balanced.inertia_kgm2 == pytest.approx(2 * bare.inertia_kgm2, rel=REL)


@pytest.mark.parametrize("incline", [-90.0, -30.0, 0.0, 15.0, 45.0, 90.0])
def test_inclined_screw_gravity_and_friction_from_the_incline(incline: float) -> None:
    mass, lead, mu = 40.0, 0.02, 0.1
    axis = inclined_ball_screw_axis(
        InclinedBallScrew(
            mass_kg=mass, lead_m=lead, friction_coefficient=mu, efficiency=0.9, incline_deg=incline
        )
    )
    theta = math.radians(incline)
    rise_per_rad = lead / (2 * math.pi) * math.sin(theta)  # height gained per shaft radian
    assert axis.gravity_torque_nm == pytest.approx(mass * G * rise_per_rad, rel=1e-9, abs=1e-15)
    normal_force = mass * G * math.cos(theta)
    assert axis.friction_torque_nm == pytest.approx(
        mu * normal_force * lead / (2 * math.pi), rel=1e-9, abs=1e-15
    )
    assert axis.efficiency == 0.9  # by power flow, not folded into T_F as Eq. 515.4 does


def test_horizontal_inclined_screw_differs_from_eq_515_4_by_eta_only() -> None:
    kwargs = {"mass_kg": 100.0, "lead_m": 0.01, "friction_coefficient": 0.1, "efficiency": 0.8}
    chapter = chapter_ball_screw_axis(BallScrew(**kwargs, screw_inertia_kgm2=0.001))
    ours = inclined_ball_screw_axis(InclinedBallScrew(**kwargs, screw_inertia_kgm2=0.001))
    assert ours.inertia_kgm2 == pytest.approx(chapter.inertia_kgm2, rel=REL)
    assert ours.friction_torque_nm / ours.efficiency == pytest.approx(
        chapter.friction_torque_nm, rel=REL
    )
    assert ours.gravity_torque_nm == 0


def test_inclined_conveyor_lifts_the_load_not_the_belt() -> None:
    conveyor = Conveyor(
        load_mass_kg=30,
        belt_mass_kg=10,
        roller_diameter_m=0.1,
        friction_coefficient=0.2,
        efficiency=0.9,
        incline_deg=20,
    )
    axis = conveyor_axis(conveyor)
    theta = math.radians(20)
    assert axis.gravity_torque_nm == pytest.approx(30 * G * math.sin(theta) * 0.05, rel=1e-12)
    # The carrying strand (half the belt) lies on the bed with the load.
    assert axis.friction_torque_nm == pytest.approx(
        0.2 * (30 + 5) * G * math.cos(theta) * 0.05, rel=1e-12
    )


# --- inertia from the kinetic energy, through a ratio ------------------------------------


def test_belt_inertia_through_a_ratio_is_its_kinetic_energy() -> None:
    """½·J_L·ω_out² = ½·J_tr·ω_out² + ½·J_D·ω² + ½·J_I·ω_I² + ½·(m + m_B)·v²."""
    belt = BeltDrive(
        mass_kg=6.0,
        pulley_diameter_m=0.064,
        friction_coefficient=0.05,
        efficiency=0.92,
        belt_mass_kg=0.8,
        pulley_inertia_kgm2=2.1e-4,
        idler_inertia_kgm2=1.3e-4,
        idler_diameter_m=0.048,
    )
    ratio, j_tr = 3.5, 4e-5
    axis = with_transmission(belt_axis(belt), Transmission(ratio=ratio, inertia_kgm2=j_tr))
    omega_out = 120.0
    omega = omega_out / ratio
    v = omega * 0.064 / 2
    omega_idler = v / (0.048 / 2)
    energy = 0.5 * (
        j_tr * omega_out**2 + 2.1e-4 * omega**2 + 1.3e-4 * omega_idler**2 + (6.0 + 0.8) * v**2
    )
    assert axis.inertia_kgm2 == pytest.approx(2 * energy / omega_out**2, rel=REL)
    # 1 mm/s of the carriage: ω = 1e-3/r, times i at the output.
    assert axis.speed_rpm_per_unit == pytest.approx(_rpm(1e-3 / 0.032) * ratio, rel=REL)


@settings(max_examples=200, deadline=None)
@given(
    mass=st.floats(0, 5000, allow_subnormal=False),
    diameter=st.floats(0.005, 1.0, allow_subnormal=False),
    j_pinion=st.floats(0, 1.0, allow_subnormal=False),
    ratio=st.floats(0.05, 200, allow_subnormal=False),
    j_tr=st.floats(0, 1.0, allow_subnormal=False),
    omega_out=st.floats(0.1, 1000, allow_subnormal=False),
)
def test_rack_inertia_through_a_ratio_is_its_kinetic_energy(
    mass: float, diameter: float, j_pinion: float, ratio: float, j_tr: float, omega_out: float
) -> None:
    rack = RackPinion(
        mass_kg=mass,
        pinion_diameter_m=diameter,
        friction_coefficient=0.1,
        efficiency=0.95,
        pinion_inertia_kgm2=j_pinion,
    )
    axis = with_transmission(rack_pinion_axis(rack), Transmission(ratio=ratio, inertia_kgm2=j_tr))
    omega = omega_out / ratio
    v = omega * diameter / 2
    energy = 0.5 * (j_tr * omega_out**2 + j_pinion * omega**2 + mass * v**2)
    assert axis.inertia_kgm2 == pytest.approx(2 * energy / omega_out**2, rel=1e-9)
    # The force factor from P = F·v = T·ω_out at 1 N.
    assert axis.torque_nm_per_force_unit == pytest.approx(v / omega_out, rel=1e-9)


def test_transmissions_in_series_are_one_transmission() -> None:
    hoist = hoist_axis(
        Hoist(load_mass_kg=50, drum_diameter_m=0.15, efficiency=0.9, drum_inertia_kgm2=0.02)
    )
    first, second = Transmission(ratio=4, efficiency=0.97), Transmission(ratio=2.5, efficiency=0.9)
    both = with_transmission(with_transmission(hoist, first), second)
    one = with_transmission(hoist, Transmission(ratio=10, efficiency=0.97 * 0.9))
    for name in ("inertia_kgm2", "gravity_torque_nm", "speed_rpm_per_unit", "efficiency"):
        assert getattr(both, name) == pytest.approx(getattr(one, name), rel=REL), name


# --- efficiency by the direction of power flow ---------------------------------------------


def _actuator_torque(axis: AxisLoad, *, direction: int) -> float:
    """The torque at constant speed as sizing/axis.py's docstring defines it (no process force)."""
    load = axis.gravity_torque_nm + direction * axis.friction_torque_nm
    return load / axis.efficiency if load * direction > 0 else load * axis.efficiency


@pytest.mark.parametrize("direction", [1, -1])
def test_lifting_and_lowering_power_through_both_efficiencies(direction: int) -> None:
    """Lifting, the actuator gives m·g·v/(η_tr·η); lowering, it holds back m·g·v·η_tr·η."""
    mass, diameter, eta, eta_tr, ratio = 80.0, 0.12, 0.9, 0.95, 7.0
    axis = with_transmission(
        hoist_axis(Hoist(load_mass_kg=mass, drum_diameter_m=diameter, efficiency=eta)),
        Transmission(ratio=ratio, efficiency=eta_tr),
    )
    v = 0.5  # m/s of the load, up for direction +1
    omega_out = ratio * v / (diameter / 2)
    shaft_power = _actuator_torque(axis, direction=direction) * direction * omega_out
    lifting_power = mass * G * v * direction
    expected = lifting_power / (eta * eta_tr) if direction > 0 else lifting_power * eta * eta_tr
    assert shaft_power == pytest.approx(expected, rel=REL)


def test_counterweight_heavier_than_the_load_overhauls_while_lifting() -> None:
    axis = belt_axis(
        BeltDrive(
            mass_kg=2,
            pulley_diameter_m=0.04,
            friction_coefficient=0,
            efficiency=0.8,
            incline_deg=90,
            counterweight_kg=3,
        )
    )
    assert axis.gravity_torque_nm < 0
    # Lifting the 2 kg load the 3 kg counterweight drives the actuator back: ×η, not /η.
    assert _actuator_torque(axis, direction=1) == pytest.approx(-1 * G * 0.02 * 0.8, rel=REL)


# --- inputs outside the physics are named ---------------------------------------------------


_VALID: dict[type, dict[str, float]] = {
    BeltDrive: {
        "mass_kg": 1,
        "pulley_diameter_m": 0.05,
        "friction_coefficient": 0,
        "efficiency": 1,
    },
    RackPinion: {
        "mass_kg": 1,
        "pinion_diameter_m": 0.05,
        "friction_coefficient": 0,
        "efficiency": 1,
    },
    Conveyor: {
        "load_mass_kg": 1,
        "belt_mass_kg": 1,
        "roller_diameter_m": 0.1,
        "friction_coefficient": 0,
        "efficiency": 1,
    },
    Hoist: {"load_mass_kg": 1, "drum_diameter_m": 0.1, "efficiency": 1},
    InclinedBallScrew: {"mass_kg": 1, "lead_m": 0.01, "friction_coefficient": 0, "efficiency": 1},
    Transmission: {"ratio": 2},
}


@pytest.mark.parametrize(
    ("kind", "field", "value"),
    [
        (BeltDrive, "mass_kg", -1),
        (BeltDrive, "pulley_diameter_m", 0),
        (BeltDrive, "efficiency", 1.01),
        (BeltDrive, "incline_deg", 91),
        (BeltDrive, "idler_diameter_m", 0),
        (RackPinion, "friction_coefficient", math.nan),
        (RackPinion, "pinion_diameter_m", -0.01),
        (Conveyor, "belt_mass_kg", -0.1),
        (Conveyor, "tail_roller_diameter_m", math.inf),
        (Hoist, "efficiency", 0),
        (Hoist, "counterweight_kg", -2),
        (InclinedBallScrew, "incline_deg", -math.inf),
        (InclinedBallScrew, "incline_deg", -90.5),
        (InclinedBallScrew, "friction_force_n", -1),
        (Transmission, "ratio", 0),
        (Transmission, "efficiency", 1.5),
        (Transmission, "inertia_kgm2", -1e-6),
    ],
)
def test_bad_inputs_name_their_field(kind: type, field: str, value: float) -> None:
    kind(**_VALID[kind])  # the valid inputs pass
    with pytest.raises(InvalidInputError) as caught:
        kind(**{**_VALID[kind], field: value})
    assert caught.value.field == field


def test_results_beyond_any_float_name_the_input() -> None:
    huge = BeltDrive(mass_kg=1, pulley_diameter_m=1e200, friction_coefficient=0, efficiency=1)
    with pytest.raises(InvalidInputError) as caught:
        belt_axis(huge)
    assert caught.value.field == "pulley_diameter_m"
    tiny = Hoist(load_mass_kg=1, drum_diameter_m=1e-320, efficiency=1)
    with pytest.raises(InvalidInputError) as caught:
        hoist_axis(tiny)
    assert caught.value.field == "drum_diameter_m"
    screw = chapter_ball_screw_axis(
        BallScrew(mass_kg=1, lead_m=0.01, friction_coefficient=0.1, efficiency=1)
    )
    for ratio in (1e-200, 1e-170, 1e300):
        with pytest.raises(InvalidInputError) as caught:
            with_transmission(screw, Transmission(ratio=ratio))
        assert caught.value.field == "ratio"
