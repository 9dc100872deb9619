"""The drive's checks: the peak motor current (Eq. 522.2, 522.3) and the controller's
output voltage at the load speed (Eq. 521.2 with the inductive drop)."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Final

from actuator_selection.phrases.check_messages import check_words, phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing import electrical
from actuator_selection.sizing.checks.rule import (
    FLOAT_OPS,
    Operands,
    Ops,
    Real,
    Rule,
    Status,
    compared,
    larger,
    outcome,
    published,
)
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

WORDS: Final = {
    # drive_current
    "drive_current.pass": N_(
        "peak motor current I = max(T_1, |T_3|)/k_T + I_NLR = {value:.4g} A ≤ I_max = "
        "{limit:.4g} A{no_load}{rms}{braking}"
    ),
    "drive_current.fail": N_(
        "peak motor current I = max(T_1, |T_3|)/k_T + I_NLR = {value:.4g} A exceeds I_max = "
        "{limit:.4g} A{no_load}{rms}{braking}"
    ),
    "drive_current.no_load_unknown": N_(
        " (approximate: the catalogue gives no no-load current, left out)"
    ),
    "drive_current.no_load": N_(" (I_NLR = {no_load_current_a:.3g} A at n_2, K_INL at 30 °C)"),
    "drive_current.rms": N_("; rms current ≤ {rms_current_a:.4g} A"),
    "drive_current.braking": N_("; braking returns up to {energy_j:.4g} J per cycle to the drive"),
    # drive_voltage
    "drive_voltage.pass": N_(
        "U = √((n·i·K_E + I_max·R)² + (ω·L·I_max)²) = {value:.4g} V_rms at n_2 = "
        "{speed_rpm:.4g} rpm ≤ {limit:.4g} V_rms from a {dc_bus_voltage_v:g} V DC bus "
        "(space-vector modulation); Eq. 521.2 as printed (no inductive drop) gives "
        "{printed_v:.4g} V_rms"
    ),
    "drive_voltage.fail": N_(
        "U = √((n·i·K_E + I_max·R)² + (ω·L·I_max)²) = {value:.4g} V_rms at n_2 = "
        "{speed_rpm:.4g} rpm exceeds {limit:.4g} V_rms from a {dc_bus_voltage_v:g} V DC bus "
        "(space-vector modulation); Eq. 521.2 as printed (no inductive drop) gives "
        "{printed_v:.4g} V_rms"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)


# --- drive_current: peak motor current ≤ I_max (Eq. 522.2, 522.3 reversed) --------------------


def _no_load_current(q: Operands, xp: Ops) -> Real:
    """I_NLR = I_NLS + K_INL(30 °C)·n_2 (Eq. 522.2) at the load speed, the largest over the
    cycle; 0 where the catalogue gives neither (the check is then approximate)."""
    unknown = xp.isnan(q.no_load_starting_current_a) | xp.isnan(
        q.no_load_current_constant_a_per_rpm
    )
    running = q.no_load_starting_current_a + q.no_load_current_constant_a_per_rpm * q.speed_rpm
    return xp.where(unknown, 0.0, running)


def _peak_current(q: Operands, xp: Ops) -> Real:
    """I = max(T_1, |T_3|)/k_T + I_NLR (Eq. 522.3 solved for I, Eq. 522.2)."""
    torque = larger(q.accel_torque_nm, abs(q.decel_torque_nm), xp)
    return torque / q.torque_constant_nm_per_a + _no_load_current(q, xp)


def _peak_current_floor(q: Operands, xp: Ops) -> Real:
    """The least peak current over every J_A ≥ 0: from the least T_1 and |T_3|."""
    torque = larger(q.accel_torque_floor_nm, q.decel_torque_floor_nm, xp)
    return torque / q.torque_constant_nm_per_a + _no_load_current(q, xp)


def regenerative_energy_j(*, decel_torque_nm: float, speed_rpm: float, decel_s: float) -> float:
    """Mechanical energy braking returns per cycle [J]: −T_3·(2π/60)·n_2·t_3/2 where T_3 < 0.

    The output torque T_3 is constant while the speed falls linearly from n_2 to 0 in
    t_3 (Table 516.1), so the energy is the torque times the angle turned. It is what
    flows back into the actuator; the gear's and winding's losses take part of it
    before it reaches the DC bus, so it bounds what a braking resistor or the bus
    capacitors must take. The chapter's worked example (T_3 = −85.48 Nm, 40 rpm, 0.1 s):

    >>> round(regenerative_energy_j(decel_torque_nm=-85.48, speed_rpm=40, decel_s=0.1), 2)
    17.9
    """
    if decel_torque_nm >= 0:
        return 0.0
    return -decel_torque_nm * (speed_rpm * RAD_PER_S_PER_RPM) * decel_s / 2.0


def _rms_current_bound(q: Operands) -> float:
    """An upper bound of the rms current: T_rms/k_T + the largest I_NLR (Minkowski)."""
    return float(q.rms_torque_nm / q.torque_constant_nm_per_a + _no_load_current(q, FLOAT_OPS))


def _current_message(q: Operands, status: Status, current: float, i_max: float) -> str:
    if math.isnan(q.no_load_starting_current_a) or math.isnan(q.no_load_current_constant_a_per_rpm):
        no_load = phrase("drive_current.no_load_unknown")
    else:
        no_load = phrase(
            "drive_current.no_load", no_load_current_a=float(_no_load_current(q, FLOAT_OPS))
        )
    rms = None
    if not math.isnan(q.rms_torque_nm):
        rms = phrase("drive_current.rms", rms_current_a=_rms_current_bound(q))
    braking = None
    if not math.isnan(q.decel_torque_nm):
        energy = regenerative_energy_j(
            decel_torque_nm=q.decel_torque_nm, speed_rpm=q.speed_rpm, decel_s=q.decel_s
        )
        braking = phrase("drive_current.braking", energy_j=energy)
    return phrase(
        f"drive_current.{outcome(status)}",
        value=current,
        limit=i_max,
        no_load=no_load,
        rms=rms,
        braking=braking,
    )


def drive_asked(app: Application) -> bool:
    """Whether the drive's current is sized (the voltage is checked either way)."""
    return app.drive


DRIVE_CURRENT = Rule(
    name="drive_current",
    when=drive_asked,
    reference="Eq. 522.2, Eq. 522.3",
    unit="A",
    value=_peak_current,
    limit=lambda q, xp: q.max_current_a,
    requires=(
        published("inertia_kgm2", N_("moment of inertia J_A (T_1 and T_3 need it)")),
        published("torque_constant_nm_per_a", N_("torque constant k_T")),
        published("max_current_a", N_("maximum current I_max")),
    ),
    approximate=lambda q, xp: (
        xp.isnan(q.no_load_starting_current_a) | xp.isnan(q.no_load_current_constant_a_per_rpm)
    ),
    message=_current_message,
    lower_bound=_peak_current_floor,
)
"""Peak motor current I = max(T_1, |T_3|)/k_T + I_NLR ≤ I_max (Eq. 522.3 solved for the
current, I_NLR by Eq. 522.2 at n_2 with K_INL at 30 °C, the larger cold value).

Adding I_NLR while braking is on the safe side (the no-load losses help to brake).
Where the catalogue gives no no-load current (FHA-C) it is left out and the check is
approximate. The message reports an upper bound of the rms current and the energy
braking returns per cycle (:func:`regenerative_energy_j`)."""


# --- drive_voltage: U with ωL·I in quadrature ≤ the bus's output voltage (Eq. 521.2) ---------

SQRT2 = math.sqrt(2.0)
"""U_DC/√2: the largest sinusoidal line-to-line rms voltage of a bus with space-vector
modulation (:func:`~actuator_selection.sizing.electrical.max_output_voltage_v`)."""


def _resistive_sum(q: Operands) -> Real:
    """Eq. 521.2 as printed: U_OUT = n·i·K_E + I_MAX·R (line-to-line rms)."""
    return electrical.in_phase_voltage_v(
        output_speed_rpm=q.speed_rpm,
        gear_ratio=q.gear_ratio,
        motor_voltage_constant_v_per_krpm=q.motor_voltage_constant_v_per_krpm,
        max_current_a=q.max_current_a,
        resistance_line_ohm=q.resistance_line_ohm,
    )


def _inductive_drop(q: Operands) -> Real:
    """ω·L·I_MAX with ω = 2π·p·n·i/60, the electrical angular frequency [V]."""
    return electrical.inductive_voltage_v(
        output_speed_rpm=q.speed_rpm,
        gear_ratio=q.gear_ratio,
        pole_pairs=q.pole_pairs,
        inductance_line_h=q.inductance_line_h,
        max_current_a=q.max_current_a,
    )


def _drive_voltage(q: Operands, xp: Ops) -> Real:
    """U = √((n·i·K_E + I·R)² + (ω·L·I)²): Eq. 521.2 with the inductive drop in quadrature
    (:func:`~actuator_selection.sizing.electrical.needed_voltage_v`, the one formula)."""
    return electrical.needed_voltage_v(_resistive_sum(q), _inductive_drop(q), xp.sqrt)


DRIVE_VOLTAGE = Rule(
    name="drive_voltage",
    reference="Eq. 521.2 with ωL·I in quadrature",
    unit="V",
    value=_drive_voltage,
    limit=lambda q, xp: q.dc_bus_voltage_v / SQRT2,
    requires=(
        published("motor_voltage_constant_v_per_krpm", N_("motor voltage constant K_E (V_rms)")),
        published("max_current_a", N_("maximum current I_max")),
        published("resistance_line_ohm", N_("line-to-line resistance R")),
        published("inductance_line_h", N_("line-to-line inductance L")),
        published("pole_pairs", N_("number of pole pairs p")),
        published(
            "dc_bus_voltage_v",
            N_("controller listed for the actuator (Table 521.1) on a DC bus class it runs on"),
        ),
    ),
    message=compared(
        "drive_voltage",
        ("speed_rpm", lambda q, xp, value, limit: q.speed_rpm),
        ("dc_bus_voltage_v", lambda q, xp, value, limit: q.dc_bus_voltage_v),
        ("printed_v", lambda q, xp, value, limit: _resistive_sum(q)),
    ),
)
"""The controller's output voltage at the load speed n_2 and I_max: Eq. 521.2 with the
inductive drop ω·L·I in quadrature, U = √((n·i·K_E + I·R)² + (ω·L·I)²), all line-to-line
rms, ω = 2π·p·n·i/60 the electrical angular frequency, against U_DC/√2 of the highest
DC bus class the actuator shares with a controller Table 521.1 lists for it (the
catalogue snapshot derives ``dc_bus_voltage_v`` so): it fails exactly when every listed
controller's own voltage check fails (:mod:`actuator_selection.sizing.drive`, the same
formula, :func:`~actuator_selection.sizing.electrical.needed_voltage_v`). The resistive
drop stays in phase with the back-EMF and uses R and L line-to-line, as the chapter
does: on the safe side (between two terminals of a star winding the drops are 2/√3 of
their line-to-line share). Eq. 521.2
as printed is reported beside it. Only the CHA-style constants (motor K_E in V_rms
line-to-line, R and L line-to-line, pole pairs) are published; elsewhere no data."""
