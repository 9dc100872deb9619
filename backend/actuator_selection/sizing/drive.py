"""From a chosen actuator to a working drive: compatible controllers and their voltage.

Joins the matching of Table 521.1 with the controller output voltage of
Eq. 521.2 with the inductive drop in quadrature (the one formula,
:func:`~actuator_selection.sizing.electrical.needed_voltage_v`, that the selection's
``drive_voltage`` check uses too). The voltage is checked for each actuator–controller
pair that has the data: the controller's bus classes that the actuator also runs on, the largest
output voltage among them, against U_OUT at the load speed n_2; U_OUT at n_max
is reported beside it, since a drive that cannot reach n_max still serves a
slower load.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.controllers import ActuatorInterface, Controller
from actuator_selection.phrases.check_messages import phrase
from actuator_selection.sizing.compatibility import (
    CompatibilityResult,
    ControllerMatch,
    MatchVerdict,
)
from actuator_selection.sizing.electrical import (
    DcBusClass,
    Modulation,
    OutputVoltageCheck,
    check_output_voltage,
    controller_output_voltage,
    max_output_voltage_v,
)
from actuator_selection.sizing.selection import Check, Status

VOLTAGE_REFERENCE = "Eq. 521.2 with ωL·I in quadrature"
MODULATION = Modulation.SPACE_VECTOR
"""The modulation :func:`check_output_voltage` assumes by default."""


@dataclass(frozen=True, slots=True, kw_only=True)
class DriveOption:
    """A controller that is not excluded for the actuator, with its voltage check."""

    match: ControllerMatch
    voltage: Check


@dataclass(frozen=True, slots=True, kw_only=True)
class DriveOptions:
    """The controllers for one actuator: usable ones best first, and how many are excluded."""

    options: tuple[DriveOption, ...]
    excluded: int


def _no_voltage_data(code: str, words: bool) -> Check:
    return Check(
        name="controller_voltage",
        status=Status.NO_DATA,
        value=None,
        limit=None,
        unit="V",
        reference=VOLTAGE_REFERENCE,
        message=phrase(f"controller_voltage.{code}") if words else "",
    )


def shared_bus_classes(
    *, interface: ActuatorInterface, controller: Controller, buses: Sequence[DcBusClass]
) -> tuple[DcBusClass, ...]:
    """The bus classes of ``buses`` (in their order) that both the actuator and the controller
    run on; empty when the actuator's bus class is not published."""
    if interface.bus_classes is None:
        return ()
    return tuple(
        b
        for b in buses
        if b.bus_class in interface.bus_classes and controller.level(b.bus_class) is not None
    )


def voltage_check(
    *,
    actuator: Actuator,
    interface: ActuatorInterface,
    controller: Controller,
    buses: Sequence[DcBusClass],
    speed_rpm: float,
) -> Check:
    """U_OUT (Eq. 521.2 with ωL·I) at ``speed_rpm`` against the best bus class the pair shares.

    Only the CHA-style constants (motor K_E in V_rms line-to-line per 1000 rpm,
    R and L line-to-line, pole pairs p) are used: for catalogues that give k_E per output
    rpm without saying whether it is rms or peak, comparing with an rms bus voltage would be
    a guess, so those pairs say "no data".
    """
    return shared_voltage_check(
        actuator=actuator,
        interface=interface,
        shared=shared_bus_classes(interface=interface, controller=controller, buses=buses),
        speed_rpm=speed_rpm,
    )


def shared_voltage_check(
    *,
    actuator: Actuator,
    interface: ActuatorInterface,
    shared: Sequence[DcBusClass],
    speed_rpm: float,
    words: bool = True,
) -> Check:
    """:func:`voltage_check` for a controller that shares the bus classes ``shared``.

    ``words=False`` leaves the message empty (U_OUT at n_max, which only the message
    reports, is not computed; a check without data says nothing either), for answers
    that list the numbers alone; status, value, limit and reference are the same either
    way.
    """
    (check,) = shared_voltage_checks(
        actuator=actuator, interface=interface, shared=(shared,), speed_rpm=speed_rpm, words=words
    )
    return check


def shared_voltage_checks(
    *,
    actuator: Actuator,
    interface: ActuatorInterface,
    shared: Sequence[Sequence[DcBusClass]],
    speed_rpm: float,
    words: bool = True,
) -> list[Check]:
    """:func:`shared_voltage_check` for each of ``shared``, in its order: U_OUT at n_2
    (and at n_max, for the words) computed once for the actuator, each check its bus
    classes' (a candidate's drive options list a handful of such groups)."""
    k_e = actuator.motor_voltage_constant_v_per_krpm
    i_max, r_line = actuator.max_current_a, actuator.resistance_line_ohm
    l_line, poles = actuator.inductance_line_mh, actuator.pole_pairs
    if k_e is None or i_max is None or r_line is None or l_line is None or poles is None:
        return [_no_voltage_data("no_constants", words)] * len(shared)
    if interface.bus_classes is None:
        return [_no_voltage_data("no_bus_class", words)] * len(shared)

    def required(speed: float) -> float:
        return controller_output_voltage(
            output_speed_rpm=speed,
            gear_ratio=actuator.gear_ratio,
            motor_voltage_constant_v_per_krpm=k_e,
            max_current_a=i_max,
            resistance_line_ohm=r_line,
            inductance_line_h=l_line / 1000.0,
            pole_pairs=poles,
        ).total_v

    u_load = u_max = None
    checks = []
    for classes in shared:
        if not classes:
            checks.append(_no_voltage_data("no_shared_bus", words))
            continue
        if u_load is None:
            u_load = required(speed_rpm)
        bus = _best_bus(tuple(classes))
        available = _available_v(bus)
        message = ""
        if words:
            best: OutputVoltageCheck = check_output_voltage(required_voltage_v=u_load, bus=bus)
            at_max_speed = None
            if actuator.max_speed_rpm is not None:
                if u_max is None:
                    u_max = required(actuator.max_speed_rpm)
                at_max_speed = phrase(
                    "controller_voltage.reaches"
                    if u_max <= available
                    else "controller_voltage.does_not_reach",
                    max_speed_rpm=actuator.max_speed_rpm,
                    max_speed_voltage_v=u_max,
                )
            message = phrase(
                "controller_voltage.at_speed",
                output=best.message,
                speed_rpm=speed_rpm,
                at_max_speed=at_max_speed,
            )
        checks.append(
            Check(
                name="controller_voltage",
                status=Status.PASS if u_load <= available else Status.FAIL,
                value=u_load,
                limit=available,
                unit="V",
                reference=f"{VOLTAGE_REFERENCE} ({bus.bus_class.value} bus)",
                message=message,
            )
        )
    return checks


@lru_cache(maxsize=64)
def _available_v(bus: DcBusClass) -> float:
    """The largest output voltage a bus class delivers (:func:`check_output_voltage`'s)."""
    return max_output_voltage_v(dc_bus_voltage_v=bus.nominal_voltage_v, modulation=MODULATION)


@lru_cache(maxsize=256)
def _best_bus(shared: tuple[DcBusClass, ...]) -> DcBusClass:
    """The bus class of ``shared`` that gives the largest output voltage (the first of
    equals, as ``max`` picks)."""
    return max(shared, key=_available_v)


def drive_options(
    *,
    actuator: Actuator,
    interface: ActuatorInterface,
    matching: CompatibilityResult,
    buses: Sequence[DcBusClass],
    speed_rpm: float,
) -> DriveOptions:
    """Controllers that ``matching`` does not exclude, tested first, each with its voltage check.

    Parameters
    ----------
    actuator
        The actuator whose U_OUT (Eq. 521.2) is checked.
    interface
        The actuator's matching data.
    matching
        ``match_controllers(actuator=interface, ...)`` (Table 521.1). It depends on the
        interface alone, so a caller sizing many actuators computes it once per distinct
        interface (a whole catalogue has a handful) and passes it to every actuator.
    buses
        The DC bus classes with their nominal voltages.
    speed_rpm
        n_2, the load speed [rpm].
    """
    usable = [m for m in matching.matches if m.verdict is not MatchVerdict.EXCLUDED]
    # The voltage check depends on the controller only through the bus classes it shares
    # with the actuator, so controllers sharing the same classes share one check.
    shared = [
        shared_bus_classes(interface=interface, controller=m.controller, buses=buses)
        for m in usable
    ]
    distinct = list(dict.fromkeys(shared))
    checks = dict(
        zip(
            distinct,
            shared_voltage_checks(
                actuator=actuator, interface=interface, shared=distinct, speed_rpm=speed_rpm
            ),
            strict=True,
        )
    )
    options = [DriveOption(match=m, voltage=checks[s]) for m, s in zip(usable, shared, strict=True)]
    return DriveOptions(options=tuple(options), excluded=len(matching.matches) - len(usable))
