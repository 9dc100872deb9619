"""Controller output voltage (Eq. 521.2 with the inductive drop), output torque from
current (Eq. 522.2, 522.3) and the direction of rotation (chapter, "Direction of Rotation").

Worked example, CHA-25A-50 at its maximum output speed of 112 rpm (CHA catalogue:
K_E = 37 V/1000 rpm motor-side, I_max = 4.0 A, R = 3.7 Ω, L = 6.0 mH line-to-line, p = 6):
Eq. 521.2 as printed gives 207.2 V + 14.8 V = 222.0 V; the inductive drop ω·L·I_max =
2π·6·5600/60 rad/s · 6.0 mH · 4.0 A = 84.4 V in quadrature raises it to 237.5 V.

>>> u = controller_output_voltage(output_speed_rpm=112, gear_ratio=50,
...     motor_voltage_constant_v_per_krpm=37, max_current_a=4.0, resistance_line_ohm=3.7,
...     inductance_line_h=6.0e-3, pole_pairs=6)
>>> u.motor_speed_rpm, round(u.back_emf_v, 1), round(u.resistive_v, 1), round(u.printed_v, 1)
(-5600.0, 207.2, 14.8, 222.0)
>>> round(u.inductive_v, 1), round(u.total_v, 1)
(84.4, 237.5)

and its output torque at 2.0 A, 50 rpm, 30 °C (k_Tout = 26.0 Nm/A, I_NLS = 0.19 A,
K_INL(30 °C) = 6·10⁻³ A/rpm):

>>> t = output_torque_from_current(current_a=2.0, output_speed_rpm=50,
...     torque_constant_nm_per_a=26.0, no_load_starting_current_a=0.19,
...     no_load_current_constant_30c_a_per_rpm=6e-3)
>>> round(t.no_load_running_current_a, 2), round(t.output_torque_nm, 2)
(0.49, 39.26)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from enum import StrEnum
from typing import Any, Final

from actuator_selection.catalogue.controllers import BusClass
from actuator_selection.errors import InvalidInputError, MissingDataError, OutOfRangeError
from actuator_selection.phrases.check_messages import phrase
from actuator_selection.phrases.messages import N_, Text
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM, per_krpm_to_per_rpm


def _finite(field: str, value: float) -> None:
    if not math.isfinite(value):
        raise InvalidInputError(field, f"must be a finite number, got {value!r}")


def _positive(field: str, value: float, rule: str) -> None:
    _finite(field, value)
    if value <= 0:
        raise InvalidInputError(field, f"must be > 0: {rule}")


def _non_negative(field: str, value: float, rule: str) -> None:
    _finite(field, value)
    if value < 0:
        raise InvalidInputError(field, f"must be ≥ 0: {rule}")


# --------------------------------------------------------------------------- direction

OUTPUT_TURNS_OPPOSITE_TO_MOTOR = True
"""The Harmonic Drive gear reverses the direction: motor shaft clockwise, output
counter-clockwise (chapter, "Direction of Rotation")."""


def motor_speed_rpm(*, output_speed_rpm: float, gear_ratio: float) -> float:
    """Signed motor shaft speed [rpm] for a signed output speed (chapter, Direction of Rotation).

    n_motor = −i·n_out: both speeds are signed in the same sense (e.g. positive =
    counter-clockwise seen from the output flange); the minus sign is the
    reversal by the Harmonic Drive gear (:data:`OUTPUT_TURNS_OPPOSITE_TO_MOTOR`).

    >>> motor_speed_rpm(output_speed_rpm=112, gear_ratio=50)
    -5600.0
    """
    _finite("output_speed_rpm", output_speed_rpm)
    _positive("gear_ratio", gear_ratio, "the gear ratio i multiplies the output speed")
    sign = -1.0 if OUTPUT_TURNS_OPPOSITE_TO_MOTOR else 1.0
    return sign * gear_ratio * output_speed_rpm + 0.0  # + 0.0: standstill is 0.0, not -0.0


def output_speed_rpm(*, motor_speed_rpm: float, gear_ratio: float) -> float:
    """Signed output speed [rpm] for a signed motor speed: n_out = −n_motor/i.

    >>> output_speed_rpm(motor_speed_rpm=-5600, gear_ratio=50)
    112.0
    """
    _finite("motor_speed_rpm", motor_speed_rpm)
    _positive("gear_ratio", gear_ratio, "the gear ratio i divides the motor speed")
    sign = -1.0 if OUTPUT_TURNS_OPPOSITE_TO_MOTOR else 1.0
    return sign * motor_speed_rpm / gear_ratio + 0.0  # + 0.0: standstill is 0.0, not -0.0


# --------------------------------------------------------------------------- Eq. 521.2


def line_resistance_from_phase_ohm(resistance_phase_ohm: float) -> float:
    """Line-to-line resistance [Ω] of a star-connected winding from its phase resistance.

    Derived, not catalogue data: between two terminals of a star winding two
    phases are in series, R_LL = 2·R_ph. The FHA-C catalogue gives R per phase;
    Eq. 521.2 with the CHA catalogue uses R line-to-line.

    >>> line_resistance_from_phase_ohm(2.6)
    5.2
    """
    _positive("resistance_phase_ohm", resistance_phase_ohm, "a winding resistance")
    return 2.0 * resistance_phase_ohm


def output_voltage_constant_v_per_rpm(
    *, motor_voltage_constant_v_per_krpm: float, gear_ratio: float
) -> float:
    """Voltage constant per output rpm [V/rpm] from the motor's K_E per 1000 rpm.

    k_E,out = i·K_E/1000, the form the FHA-C catalogue prints.

    >>> round(output_voltage_constant_v_per_rpm(motor_voltage_constant_v_per_krpm=37,
    ...                                         gear_ratio=50), 6)
    1.85
    """
    _positive("gear_ratio", gear_ratio, "the gear ratio i")
    _positive("motor_voltage_constant_v_per_krpm", motor_voltage_constant_v_per_krpm, "K_E")
    return gear_ratio * per_krpm_to_per_rpm(motor_voltage_constant_v_per_krpm)


def in_phase_voltage_v(
    *,
    output_speed_rpm: Any,
    gear_ratio: Any,
    motor_voltage_constant_v_per_krpm: Any,
    max_current_a: Any,
    resistance_line_ohm: Any,
) -> Any:
    """Eq. 521.2 as printed, U = |n_OUT|·i·K_E/1000 + I_MAX·R [V_rms line-to-line].

    Written once for floats and for numpy arrays (the flowchart's rule
    :data:`~actuator_selection.sizing.checks.DRIVE_VOLTAGE` runs it on both); no input
    checks here, the callers validate. The back-EMF and the resistive drop are added in
    phase, the chapter's conservative sum.

    >>> in_phase_voltage_v(output_speed_rpm=-112, gear_ratio=50,
    ...     motor_voltage_constant_v_per_krpm=37, max_current_a=4.0, resistance_line_ohm=3.7)
    222.0
    """
    motor_rpm = abs(output_speed_rpm) * gear_ratio
    return motor_rpm * (motor_voltage_constant_v_per_krpm / 1000.0) + (
        max_current_a * resistance_line_ohm
    )


def inductive_voltage_v(
    *,
    output_speed_rpm: Any,
    gear_ratio: Any,
    pole_pairs: Any,
    inductance_line_h: Any,
    max_current_a: Any,
) -> Any:
    """The inductive drop ω·L·I_MAX [V], ω = 2π·p·|n_OUT|·i/60 the electrical angular
    frequency of the motor (p pole pairs, L line-to-line). Floats or arrays.

    >>> round(inductive_voltage_v(output_speed_rpm=60, gear_ratio=50, pole_pairs=6,
    ...     inductance_line_h=9e-3, max_current_a=14.4), 2)
    244.29
    """
    omega = abs(output_speed_rpm) * gear_ratio * RAD_PER_S_PER_RPM * pole_pairs
    return omega * inductance_line_h * max_current_a


def needed_voltage_v(in_phase_v: Any, inductive_v: Any, sqrt: Any = math.sqrt) -> Any:
    """U = √(U_in-phase² + (ω·L·I)²): Eq. 521.2 extended by the inductive drop, which
    leads the current by 90° and so adds in quadrature to the in-phase terms (the
    phasor diagram of a PM synchronous motor driven with the current in phase with the
    back-EMF, i_d = 0). The one formula for the voltage a controller must deliver: the
    selection's ``drive_voltage`` check, each controller's voltage check
    (:mod:`actuator_selection.sizing.drive`) and the controller-voltage tool use it.
    ``sqrt`` is ``math.sqrt`` for floats, ``numpy.sqrt`` for arrays (both correctly
    rounded, so equal bit for bit).

    CHA-58A-50 at 60 rpm (349.56 V in phase, 244.29 V inductive):

    >>> round(needed_voltage_v(349.56, 244.2948, math.sqrt), 1)
    426.5
    """
    return sqrt(in_phase_v * in_phase_v + inductive_v * inductive_v)


@dataclass(frozen=True, slots=True, kw_only=True)
class OutputVoltage:
    """The terms of Eq. 521.2 with the inductive drop [V, rpm].

    ``motor_speed_rpm`` is signed (negative: the motor turns opposite to the
    output, :func:`motor_speed_rpm`); the voltages use its magnitude n_OUT·i.
    ``printed_v`` is Eq. 521.2 as printed (back-EMF + resistive drop), ``total_v``
    the voltage needed with the inductive drop in quadrature (:func:`needed_voltage_v`).
    """

    output_speed_rpm: float
    motor_speed_rpm: float
    back_emf_v: float
    resistive_v: float
    inductive_v: float
    printed_v: float
    total_v: float
    reference: str = "Eq. 521.2 with ωL·I in quadrature"


def _check_winding(
    max_current_a: float, resistance_line_ohm: float, inductance_line_h: float, pole_pairs: float
) -> None:
    _non_negative("max_current_a", max_current_a, "I_MAX is a current magnitude (A rms)")
    _positive("resistance_line_ohm", resistance_line_ohm, "the armature resistance R")
    _non_negative("inductance_line_h", inductance_line_h, "the winding inductance L")
    _positive("pole_pairs", pole_pairs, "the motor's pole pairs p set the electrical frequency")


def controller_output_voltage(
    *,
    output_speed_rpm: float,
    gear_ratio: float,
    motor_voltage_constant_v_per_krpm: float,
    max_current_a: float,
    resistance_line_ohm: float,
    inductance_line_h: float,
    pole_pairs: float,
) -> OutputVoltage:
    """The controller output voltage a motor needs at n_OUT and I_MAX (Eq. 521.2 with
    the inductive drop), motor-side K_E.

    U = √((n_OUT·i·K_E + I_MAX·R)² + (ω·L·I_MAX)²), ω = 2π·p·n_OUT·i/60, K_E per 1000 rpm
    of motor speed (:func:`in_phase_voltage_v`, :func:`inductive_voltage_v`,
    :func:`needed_voltage_v`).

    The chapter labels U_OUT [V_DC], but the CHA's K_E is V_rms line-to-line
    per 1000 rpm and I_MAX is A_rms, so U_OUT is an rms line-to-line voltage;
    compare it with what a bus delivers through :func:`check_output_voltage`.
    Eq. 521.2 as printed adds the resistive drop arithmetically and leaves out the
    inductive drop, which at the CHA's speeds is of the order of the back-EMF
    (CHA-58A-50 at 60 rpm: 244 V against 315 V); it is reported as ``printed_v``.

    Parameters
    ----------
    output_speed_rpm
        n_OUT [rpm], signed; the voltage needs its magnitude.
    gear_ratio
        i [-], > 0.
    motor_voltage_constant_v_per_krpm
        K_E [V_rms line-to-line per 1000 rpm of motor speed], > 0 (CHA: k_EM).
    max_current_a
        I_MAX [A_rms], ≥ 0.
    resistance_line_ohm
        R [Ω] line-to-line, > 0 (a phase value converts with
        :func:`line_resistance_from_phase_ohm`).
    inductance_line_h
        L [H] line-to-line, ≥ 0 (0 gives Eq. 521.2 as printed).
    pole_pairs
        p [-], > 0.

    >>> round(controller_output_voltage(output_speed_rpm=60, gear_ratio=50,
    ...     motor_voltage_constant_v_per_krpm=105, max_current_a=14.4,
    ...     resistance_line_ohm=2.4, inductance_line_h=9e-3, pole_pairs=6).total_v, 1)
    426.5
    """
    _finite("output_speed_rpm", output_speed_rpm)
    _positive("gear_ratio", gear_ratio, "the gear ratio i multiplies the output speed")
    _positive(
        "motor_voltage_constant_v_per_krpm",
        motor_voltage_constant_v_per_krpm,
        "K_E is the back-EMF per 1000 rpm of motor speed",
    )
    _check_winding(max_current_a, resistance_line_ohm, inductance_line_h, pole_pairs)
    printed = in_phase_voltage_v(
        output_speed_rpm=output_speed_rpm,
        gear_ratio=gear_ratio,
        motor_voltage_constant_v_per_krpm=motor_voltage_constant_v_per_krpm,
        max_current_a=max_current_a,
        resistance_line_ohm=resistance_line_ohm,
    )
    inductive = inductive_voltage_v(
        output_speed_rpm=output_speed_rpm,
        gear_ratio=gear_ratio,
        pole_pairs=pole_pairs,
        inductance_line_h=inductance_line_h,
        max_current_a=max_current_a,
    )
    motor_rpm = abs(output_speed_rpm) * gear_ratio
    return OutputVoltage(
        output_speed_rpm=output_speed_rpm,
        motor_speed_rpm=motor_speed_rpm(output_speed_rpm=output_speed_rpm, gear_ratio=gear_ratio),
        back_emf_v=motor_rpm * per_krpm_to_per_rpm(motor_voltage_constant_v_per_krpm),
        resistive_v=max_current_a * resistance_line_ohm,
        inductive_v=float(inductive),
        printed_v=float(printed),
        total_v=float(needed_voltage_v(printed, inductive)),
    )


def controller_output_voltage_from_output_constant(
    *,
    output_speed_rpm: float,
    gear_ratio: float,
    output_voltage_constant_v_per_rpm: float,
    max_current_a: float,
    resistance_line_ohm: float,
    inductance_line_h: float,
    pole_pairs: float,
) -> OutputVoltage:
    """:func:`controller_output_voltage` with a voltage constant per output rpm (FHA-C
    catalogue form), k_E,out = i·K_E/1000 [V/rpm].

    The FHA-C catalogue gives R per phase: pass
    ``line_resistance_from_phase_ohm(R_phase)`` so that phase and line values
    are never mixed silently. The constant must be in the same convention as
    the bus comparison (rms line-to-line); check the catalogue before use.

    >>> u = controller_output_voltage_from_output_constant(output_speed_rpm=90, gear_ratio=50,
    ...     output_voltage_constant_v_per_rpm=2.5, max_current_a=7.3,
    ...     resistance_line_ohm=line_resistance_from_phase_ohm(2.6), inductance_line_h=0.0,
    ...     pole_pairs=6)
    >>> round(u.back_emf_v, 1), round(u.resistive_v, 2), round(u.total_v, 2)
    (225.0, 37.96, 262.96)
    """
    _positive("gear_ratio", gear_ratio, "the gear ratio i")
    _positive(
        "output_voltage_constant_v_per_rpm",
        output_voltage_constant_v_per_rpm,
        "k_E,out is the back-EMF per output rpm",
    )
    return controller_output_voltage(
        output_speed_rpm=output_speed_rpm,
        gear_ratio=gear_ratio,
        motor_voltage_constant_v_per_krpm=output_voltage_constant_v_per_rpm / gear_ratio * 1000.0,
        max_current_a=max_current_a,
        resistance_line_ohm=resistance_line_ohm,
        inductance_line_h=inductance_line_h,
        pole_pairs=pole_pairs,
    )


class Modulation(StrEnum):
    """How the controller's inverter turns its DC bus into three-phase voltage."""

    SPACE_VECTOR = "space_vector"
    """Space-vector PWM (or sine PWM with third-harmonic injection): U_LL,rms ≤ U_DC/√2."""
    SINE_TRIANGLE = "sine_triangle"
    """Sine-triangle PWM without over-modulation: U_LL,rms ≤ √3·U_DC/(2√2) ≈ 0.612·U_DC."""


MODULATION_WORDS: Final[Mapping[Modulation, Text]] = {
    Modulation.SPACE_VECTOR: N_("space_vector"),
    Modulation.SINE_TRIANGLE: N_("sine_triangle"),
}
"""A modulation as the voltage check names it (its value in English, words in German)."""


def max_output_voltage_v(*, dc_bus_voltage_v: float, modulation: Modulation) -> float:
    """Largest sinusoidal line-to-line rms voltage [V_rms] a three-phase inverter delivers.

    In the linear range of the modulation, from a DC bus U_DC:

    - sine-triangle PWM: phase peak U_DC/2, so U_LL,rms = √3·U_DC/(2·√2) ≈ 0.612·U_DC
      (Mohan, Undeland, Robbins, *Power Electronics*, 3rd ed., 2003, sect. 8-6-1,
      V_LL1 = 0.612·m_a·V_d for m_a ≤ 1);
    - space-vector PWM: line-to-line peak U_DC, so U_LL,rms = U_DC/√2 ≈ 0.707·U_DC,
      2/√3 of the sine-triangle limit (Holmes, Lipo, *Pulse Width Modulation for
      Power Converters*, 2003, ch. 3 and 5).

    Switch and dead-time drops of a real controller are not included.

    >>> round(max_output_voltage_v(dc_bus_voltage_v=320, modulation=Modulation.SPACE_VECTOR), 1)
    226.3
    >>> round(max_output_voltage_v(dc_bus_voltage_v=320, modulation=Modulation.SINE_TRIANGLE), 1)
    196.0
    """
    _positive("dc_bus_voltage_v", dc_bus_voltage_v, "the DC bus voltage feeds the inverter")
    if modulation is Modulation.SPACE_VECTOR:
        return dc_bus_voltage_v / math.sqrt(2.0)
    return dc_bus_voltage_v * math.sqrt(3.0) / (2.0 * math.sqrt(2.0))


@dataclass(frozen=True, slots=True, kw_only=True)
class DcBusClass:
    """A DC bus voltage class of Table 521.1 with its nominal voltage [V] (catalogue data)."""

    bus_class: BusClass
    nominal_voltage_v: float

    def __post_init__(self) -> None:
        _positive("nominal_dc_voltage_v", self.nominal_voltage_v, "a DC bus voltage")


@dataclass(frozen=True, slots=True, kw_only=True)
class OutputVoltageCheck:
    """U_OUT (Eq. 521.2) against the output voltage a DC bus class delivers [V_rms]."""

    bus_class: BusClass
    dc_bus_voltage_v: float
    modulation: Modulation
    available_voltage_v: float
    required_voltage_v: float
    sufficient: bool
    margin_percent: float
    reference: str
    message: str


def check_output_voltage(
    *, required_voltage_v: float, bus: DcBusClass, modulation: Modulation = Modulation.SPACE_VECTOR
) -> OutputVoltageCheck:
    """Does a DC bus class deliver U_OUT of Eq. 521.2? (Table 521.1 bus classes).

    Like with like: U_OUT is V_rms line-to-line (K_E of the CHA is V_rms
    line-to-line per 1000 rpm), and :func:`max_output_voltage_v` turns the bus
    voltage into the largest V_rms line-to-line the inverter delivers. Sufficient
    when U_OUT ≤ available; margin = (available − U_OUT)/available.

    >>> c = check_output_voltage(required_voltage_v=222.0,
    ...     bus=DcBusClass(bus_class=BusClass.V320, nominal_voltage_v=320))
    >>> c.sufficient, round(c.available_voltage_v, 1), round(c.margin_percent, 1)
    (True, 226.3, 1.9)
    """
    _non_negative("required_voltage_v", required_voltage_v, "U_OUT of Eq. 521.2")
    available = max_output_voltage_v(dc_bus_voltage_v=bus.nominal_voltage_v, modulation=modulation)
    ok = required_voltage_v <= available
    margin = (available - required_voltage_v) / available * 100.0
    return OutputVoltageCheck(
        bus_class=bus.bus_class,
        dc_bus_voltage_v=bus.nominal_voltage_v,
        modulation=modulation,
        available_voltage_v=available,
        required_voltage_v=required_voltage_v,
        sufficient=ok,
        margin_percent=margin,
        reference="Eq. 521.2, Table 521.1",
        message=phrase(
            "output_voltage.pass" if ok else "output_voltage.fail",
            required_voltage_v=required_voltage_v,
            available_voltage_v=available,
            dc_bus_voltage_v=bus.nominal_voltage_v,
            modulation=MODULATION_WORDS[modulation],
        ),
    )


def check_output_voltage_all(
    *,
    required_voltage_v: float,
    buses: Iterable[DcBusClass],
    modulation: Modulation = Modulation.SPACE_VECTOR,
) -> tuple[OutputVoltageCheck, ...]:
    """:func:`check_output_voltage` for every bus class, lowest voltage first."""
    return tuple(
        check_output_voltage(required_voltage_v=required_voltage_v, bus=b, modulation=modulation)
        for b in sorted(buses, key=lambda b: b.nominal_voltage_v)
    )


# --------------------------------------------------------------------------- Eq. 522.2/3

K_INL_LOW_TEMPERATURE_C = 30.0
"""Temperature of the first published no-load current constant, K_INL(30 °C) (Eq. 522.2)."""
K_INL_HIGH_TEMPERATURE_C = 80.0
"""Temperature of the second published constant, K_INL(80 °C) (CHA catalogue)."""


def no_load_current_constant_a_per_rpm(
    *,
    temperature_c: float,
    constant_30c_a_per_rpm: float,
    constant_80c_a_per_rpm: float | None,
    extrapolate: bool = False,
) -> float:
    """K_INL [A/rpm] at ``temperature_c`` between the catalogue's 30 °C and 80 °C values.

    The catalogue gives K_INL at 30 °C (Eq. 522.2) and 80 °C; in between it is
    interpolated linearly in temperature (an assumption: two points give no
    curvature). Outside 30…80 °C an :class:`OutOfRangeError` unless
    ``extrapolate`` is set; then the same line is extended (never below 0).

    >>> no_load_current_constant_a_per_rpm(temperature_c=55, constant_30c_a_per_rpm=6e-3,
    ...                                    constant_80c_a_per_rpm=2e-3)
    0.004
    """
    _finite("temperature_c", temperature_c)
    _non_negative("no_load_current_constant_30c_a_per_rpm", constant_30c_a_per_rpm, "K_INL")
    if temperature_c == K_INL_LOW_TEMPERATURE_C:
        return constant_30c_a_per_rpm
    if constant_80c_a_per_rpm is None:
        raise MissingDataError(
            "no_load_current_constant_80c_a_per_rpm",
            f"no data: K_INL is published only at {K_INL_LOW_TEMPERATURE_C:g} °C for this "
            f"actuator, so the torque at {temperature_c:g} °C cannot be computed",
        )
    _non_negative("no_load_current_constant_80c_a_per_rpm", constant_80c_a_per_rpm, "K_INL")
    lo, hi = K_INL_LOW_TEMPERATURE_C, K_INL_HIGH_TEMPERATURE_C
    if not extrapolate and not lo <= temperature_c <= hi:
        raise OutOfRangeError(
            "temperature_c",
            f"{temperature_c:g} °C is outside {lo:g}…{hi:g} °C, where K_INL is published; "
            "set extrapolate to extend the line",
        )
    share = (temperature_c - lo) / (hi - lo)
    value = constant_30c_a_per_rpm + share * (constant_80c_a_per_rpm - constant_30c_a_per_rpm)
    return max(value, 0.0)


def no_load_torque_slope_nm_per_rpm(
    *,
    torque_constant_nm_per_a: float | None,
    constant_30c_a_per_rpm: float | None,
    constant_80c_a_per_rpm: float | None,
) -> float | None:
    """k_T·K_INL [Nm/rpm]: the output torque that the speed-dependent part of the no-load
    current, K_INL·n (Eq. 522.2), takes from a given winding current at each rpm (Eq. 522.3,
    T_out = k_T·(I − I_NLS − K_INL·n)); None where k_T or K_INL is not published.

    For the continuous-duty edge at speed (``_continuous_limit`` of
    ``sizing/checks/rules/thermal.py``):
    continuous duty is the warm steady state, so K_INL at 80 °C where published (the
    actuator at operating temperature; the 30 °C value is the cold start's), else at 30 °C,
    the larger, on the safe side. CHA-25A-50 (k_T = 26 Nm/A, K_INL(80 °C) = 2·10⁻³ A/rpm):

    >>> round(no_load_torque_slope_nm_per_rpm(torque_constant_nm_per_a=26.0,
    ...     constant_30c_a_per_rpm=6e-3, constant_80c_a_per_rpm=2e-3), 6)
    0.052
    """
    k_inl = constant_80c_a_per_rpm if constant_80c_a_per_rpm is not None else constant_30c_a_per_rpm
    if torque_constant_nm_per_a is None or k_inl is None:
        return None
    return torque_constant_nm_per_a * k_inl


@dataclass(frozen=True, slots=True, kw_only=True)
class OutputTorque:
    """The terms of Eq. 522.2 and 522.3.

    ``output_torque_nm`` is K_T·(I − I_NLR) as computed, not clamped: when the
    measured current is below the no-load running current it is negative and
    ``below_no_load_current`` is set (see :func:`output_torque_from_current`).
    """

    no_load_current_constant_a_per_rpm: float
    no_load_running_current_a: float
    torque_producing_current_a: float
    output_torque_nm: float
    below_no_load_current: bool
    extrapolated: bool
    reference: str
    message: str


def output_torque_from_current(
    *,
    current_a: float,
    output_speed_rpm: float,
    torque_constant_nm_per_a: float,
    no_load_starting_current_a: float,
    no_load_current_constant_30c_a_per_rpm: float,
    no_load_current_constant_80c_a_per_rpm: float | None = None,
    temperature_c: float = K_INL_LOW_TEMPERATURE_C,
    extrapolate: bool = False,
) -> OutputTorque:
    """Output torque from the measured current (Eq. 522.2, 522.3).

    I_NLR = I_NLS + K_INL·|n_out|                (Eq. 522.2)
    T_out = K_T·(I − I_NLR)                      (Eq. 522.3)

    K_INL at ``temperature_c`` comes from :func:`no_load_current_constant_a_per_rpm`.

    When I < I_NLR the equation gives a negative torque. That is reported as
    computed with ``below_no_load_current`` set, not clamped to 0 and not
    refused: a current below the no-load current means that the load drives
    the actuator (overhauling, braking) or that the actuator is warmer than
    assumed (K_INL falls with temperature); the current alone cannot tell which.

    Parameters
    ----------
    current_a
        Measured current I, fundamental wave [A_rms], ≥ 0.
    output_speed_rpm
        n_out [rpm], signed; the no-load current depends on its magnitude.
    torque_constant_nm_per_a
        K_T at the output [Nm/A], > 0.
    no_load_starting_current_a
        I_NLS [A], ≥ 0.
    no_load_current_constant_30c_a_per_rpm
        K_INL(30 °C) [A/rpm] (catalogue value in 10⁻³ A/rpm divided by 1000).
    no_load_current_constant_80c_a_per_rpm
        K_INL(80 °C) [A/rpm]; needed for any temperature other than 30 °C.
    temperature_c
        Actuator temperature [°C]; 30…80 °C unless ``extrapolate``.
    extrapolate
        Extend the K_INL line outside 30…80 °C instead of refusing.

    >>> t = output_torque_from_current(current_a=0.3, output_speed_rpm=50,
    ...     torque_constant_nm_per_a=26.0, no_load_starting_current_a=0.19,
    ...     no_load_current_constant_30c_a_per_rpm=6e-3)
    >>> round(t.output_torque_nm, 2), t.below_no_load_current
    (-4.94, True)
    """
    _non_negative(
        "current_a", current_a, "the measured current is an rms magnitude (fundamental wave)"
    )
    _finite("output_speed_rpm", output_speed_rpm)
    _positive("torque_constant_nm_per_a", torque_constant_nm_per_a, "K_T multiplies Eq. 522.3")
    _non_negative("no_load_starting_current_a", no_load_starting_current_a, "I_NLS")
    k_inl = no_load_current_constant_a_per_rpm(
        temperature_c=temperature_c,
        constant_30c_a_per_rpm=no_load_current_constant_30c_a_per_rpm,
        constant_80c_a_per_rpm=no_load_current_constant_80c_a_per_rpm,
        extrapolate=extrapolate,
    )
    extrapolated = not K_INL_LOW_TEMPERATURE_C <= temperature_c <= K_INL_HIGH_TEMPERATURE_C
    i_nlr = no_load_starting_current_a + k_inl * abs(output_speed_rpm)
    producing = current_a - i_nlr
    torque = torque_constant_nm_per_a * producing
    below = producing < 0
    message = (
        f"I_NLR = {i_nlr:.4g} A at {abs(output_speed_rpm):g} rpm and {temperature_c:g} °C; "
        f"T_out = {torque_constant_nm_per_a:g} Nm/A · ({current_a:g} − {i_nlr:.4g}) A = "
        f"{torque:.4g} Nm"
    )
    if below:
        message += (
            "; the measured current is below the no-load running current: the load drives "
            "the actuator or the actuator is warmer than assumed (not clamped)"
        )
    if extrapolated:
        message += (
            f"; K_INL extrapolated outside {K_INL_LOW_TEMPERATURE_C:g}…"
            f"{K_INL_HIGH_TEMPERATURE_C:g} °C"
        )
    return OutputTorque(
        no_load_current_constant_a_per_rpm=k_inl,
        no_load_running_current_a=i_nlr,
        torque_producing_current_a=producing,
        output_torque_nm=torque,
        below_no_load_current=below,
        extrapolated=extrapolated,
        reference="Eq. 522.2, Eq. 522.3",
        message=message,
    )
