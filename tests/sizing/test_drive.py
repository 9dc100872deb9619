"""Drive options: Table 521.1 matching joined with the output-voltage check of Eq. 521.2."""

from __future__ import annotations

import math

import pytest

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.controllers import (
    ActuatorInterface,
    BusClass,
    Controller,
    FeedbackSystem,
    ProductFamily,
    SupportLevel,
)
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.sizing.compatibility import MatchVerdict, match_controllers
from actuator_selection.sizing.drive import (
    DriveOptions,
    drive_options,
    shared_voltage_check,
    shared_voltage_checks,
    voltage_check,
)
from actuator_selection.sizing.electrical import DcBusClass
from actuator_selection.sizing.selection import Status

TESTED = SupportLevel.TESTED
BUSES = (
    DcBusClass(bus_class=BusClass.V24, nominal_voltage_v=24),
    DcBusClass(bus_class=BusClass.V320, nominal_voltage_v=320),
    DcBusClass(bus_class=BusClass.V560, nominal_voltage_v=560),
)
# CHA-25A-50 as in the starter catalogue (n_max, K_E, I_max, R and L line-to-line, p).
CHA = Actuator(
    model="CHA-25A-50",
    family="CHA",
    gear_ratio=50,
    max_speed_rpm=112,
    motor_voltage_constant_v_per_krpm=37,
    max_current_a=4.0,
    resistance_line_ohm=3.7,
    inductance_line_mh=6.0,
    pole_pairs=6,
)
CHA_INTERFACE = ActuatorInterface(
    family=ProductFamily.CHA_CHM,
    bus_classes=frozenset({BusClass.V320, BusClass.V560}),
    temperature_sensors=frozenset({TemperatureSensor.KTY84_130}),
    feedback_systems=frozenset({FeedbackSystem.RESOLVER_2POLE}),
)


def _controller(row: int, *buses: BusClass) -> Controller:
    return Controller(
        manufacturer="Test",
        type=f"row {row}",
        source_row=row,
        families={ProductFamily.CHA_CHM: TESTED},
        bus_classes=dict.fromkeys(buses, TESTED),
        temperature_sensors={TemperatureSensor.KTY84_130: TESTED},
        feedback_systems={FeedbackSystem.RESOLVER_2POLE: TESTED},
    )


CONTROLLERS = (
    _controller(1, BusClass.V560),
    _controller(2, BusClass.V320),
    _controller(3, BusClass.V320, BusClass.V560),
    _controller(4, BusClass.V560),
    _controller(5, BusClass.V320, BusClass.V560),
    _controller(6, BusClass.V320),
    _controller(7, BusClass.V24),  # excluded: the CHA runs on 320 or 560 V only
)


def _options(actuator: Actuator, interface: ActuatorInterface) -> DriveOptions:
    return drive_options(
        actuator=actuator,
        interface=interface,
        matching=match_controllers(actuator=interface, controllers=CONTROLLERS),
        buses=BUSES,
        speed_rpm=40.0,
    )


def test_options_are_the_matching_less_the_excluded_each_with_its_voltage_check() -> None:
    matching = match_controllers(actuator=CHA_INTERFACE, controllers=CONTROLLERS)
    drive = _options(CHA, CHA_INTERFACE)
    assert [o.match for o in drive.options] == [
        m for m in matching.matches if m.verdict is not MatchVerdict.EXCLUDED
    ]
    assert [o.match.controller.source_row for o in drive.options] == [1, 2, 3, 4, 5, 6]
    assert drive.excluded == 1
    for option in drive.options:
        assert option.voltage == voltage_check(
            actuator=CHA,
            interface=CHA_INTERFACE,
            controller=option.match.controller,
            buses=BUSES,
            speed_rpm=40.0,
        )


def test_controllers_sharing_the_same_bus_classes_share_one_check() -> None:
    by_row = {
        o.match.controller.source_row: o.voltage for o in _options(CHA, CHA_INTERFACE).options
    }
    assert by_row[1] is by_row[4]  # 560 V
    assert by_row[2] is by_row[6]  # 320 V
    assert by_row[3] is by_row[5]  # both: the 560 V bus is the better one
    assert by_row[1] == by_row[3]
    # Eq. 521.2 at n_2 = 40 rpm: 2000 rpm × 37 V/1000 rpm + 4.0 A × 3.7 Ω = 88.8 V, with
    # ω·L·I = 2π·6·2000/60 s⁻¹ × 6.0 mH × 4.0 A = 30.16 V in quadrature, against
    # 560/√2 = 396.0 V and 320/√2 = 226.3 V (space vector modulation).
    inductive = 2 * math.pi * 6 * 2000 / 60 * 6.0e-3 * 4.0
    assert by_row[1].value == by_row[2].value == pytest.approx(math.hypot(88.8, inductive))
    assert by_row[1].limit == pytest.approx(395.98, abs=0.01)
    assert by_row[2].limit == pytest.approx(226.27, abs=0.01)
    assert by_row[1].reference == "Eq. 521.2 with ωL·I in quadrature (560vdc bus)"
    assert by_row[2].status is Status.PASS


def test_without_motor_constants_every_option_says_no_data() -> None:
    fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50, max_speed_rpm=90)
    checks = {o.voltage for o in _options(fha, CHA_INTERFACE).options}
    assert len(checks) == 1
    (check,) = checks
    assert check.status is Status.NO_DATA
    assert "K_E" in check.message


def test_unknown_bus_classes_leave_the_voltage_unchecked() -> None:
    interface = ActuatorInterface(
        family=ProductFamily.CHA_CHM,
        temperature_sensors=frozenset({TemperatureSensor.KTY84_130}),
        feedback_systems=frozenset({FeedbackSystem.RESOLVER_2POLE}),
    )
    drive = _options(CHA, interface)
    assert drive.excluded == 0  # nothing excludes the 24 V controller without the CHA's bus
    assert {o.voltage.message for o in drive.options} == {
        "no data: the actuator's DC bus class is not published"
    }


@pytest.mark.parametrize("words", [True, False])
@pytest.mark.parametrize(
    "actuator",
    [CHA, Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50, max_speed_rpm=90)],
)
def test_the_checks_of_several_bus_groups_are_each_groups_check(
    words: bool, actuator: Actuator
) -> None:
    """A candidate's drive options check U_OUT once for all its bus groups: the same
    checks, in the same order, as one group at a time (an empty group: no shared bus)."""
    groups = [BUSES[1:2], BUSES[1:], (), BUSES[2:], BUSES[:1]]
    checks = shared_voltage_checks(
        actuator=actuator, interface=CHA_INTERFACE, shared=groups, speed_rpm=60.0, words=words
    )
    assert checks == [
        shared_voltage_check(
            actuator=actuator, interface=CHA_INTERFACE, shared=g, speed_rpm=60.0, words=words
        )
        for g in groups
    ]
    assert len({c.status for c in checks}) > 1 or actuator is not CHA
