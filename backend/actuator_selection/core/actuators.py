"""What the core knows of one catalogue actuator.

Every field that a public source does not give is ``None``; the calculations
that need it say "no data" instead of guessing.
"""

from __future__ import annotations

from dataclasses import dataclass

from actuator_selection.core.zones import ContinuousDutyZone


@dataclass(frozen=True, slots=True, kw_only=True)
class Actuator:
    """A servo actuator as the catalogue publishes it, values at the output shaft.

    Parameters
    ----------
    model
        Catalogue model, e.g. ``"CHA-25A-50"``.
    family
        Product family, e.g. ``"CHA"``.
    gear_ratio
        Harmonic Drive gear ratio i [-].
    max_torque_nm
        Repeated peak torque T_max [Nm].
    max_speed_rpm
        Maximum output speed n_max [rpm].
    inertia_kgm2
        Moment of inertia J_A at the output [kgm²].
    stall_torque_nm
        Continuous stall torque T_0 [Nm].
    continuous_torque_nm
        Allowable continuous torque where the catalogue gives that instead of T_0 [Nm].
    zone
        Continuous-duty zone of the speed/torque diagram, where published.
    continuous_speed_rpm
        Allowable continuous output speed [rpm] (FHA-C, FHA-C mini), where published.
    rated_speed_rpm
        Rated output speed [rpm]; for the CHA the rated motor speed n_N divided by i
        (derived; the catalogue row's ``derivation`` says so).
    brake_holding_torque_nm
        Holding torque of the motor brake referred to the output, T_Br [Nm].
    output_bearing_pitch_diameter_m, output_bearing_offset_m
        Output bearing pitch circle diameter d_p and offset R [m] (CHA).
    output_bearing_dynamic_load_rating_n, output_bearing_static_load_rating_n
        Output bearing dynamic and static load ratings C and C_0 [N] (CHA).
    output_bearing_dynamic_tilting_moment_nm, output_bearing_static_tilting_moment_nm
        Allowable dynamic and static tilting moments M_dyn(max) and M_0(max) [Nm] (CHA).
    output_bearing_radial_load_n, output_bearing_axial_load_n
        Allowable radial and axial load on the output bearing [N] (FHA-C).
    output_bearing_moment_load_nm
        Allowable moment load on the output bearing [Nm] (FHA-C, FHA-C mini).
    output_bearing_moment_stiffness_nm_per_rad
        Moment stiffness of the output bearing [Nm/rad] (FHA-C, FHA-C mini).
    output_bearing_type
        The output bearing's type (:class:`~actuator_selection.core.bearing.BearingType`
        value: ``cross_roller`` or ``four_point_contact_ball``), which sets the life
        exponent; None where not published.
    inductance_line_mh
        Winding inductance line-to-line L [mH] (CHA).
    pole_pairs
        The motor's number of pole pairs p (CHA tables).
    dc_bus_voltage_v
        The highest nominal DC bus voltage among the Table 521.1 bus classes the actuator
        runs on [V]; derived from its interface by the catalogue snapshot, None where no
        bus class is published.
    """

    model: str
    family: str
    gear_ratio: float
    max_torque_nm: float | None = None
    max_speed_rpm: float | None = None
    inertia_kgm2: float | None = None
    stall_torque_nm: float | None = None
    continuous_torque_nm: float | None = None
    max_current_a: float | None = None
    stall_current_a: float | None = None
    torque_constant_nm_per_a: float | None = None
    motor_voltage_constant_v_per_krpm: float | None = None
    output_voltage_constant_v_per_rpm: float | None = None
    resistance_line_ohm: float | None = None
    resistance_phase_ohm: float | None = None
    no_load_starting_current_a: float | None = None
    no_load_current_constant_30c_a_per_rpm: float | None = None
    no_load_current_constant_80c_a_per_rpm: float | None = None
    thermal_time_constant_s: float | None = None
    zone: ContinuousDutyZone | None = None
    continuous_speed_rpm: float | None = None
    rated_speed_rpm: float | None = None
    brake_holding_torque_nm: float | None = None
    output_bearing_pitch_diameter_m: float | None = None
    output_bearing_offset_m: float | None = None
    output_bearing_dynamic_load_rating_n: float | None = None
    output_bearing_static_load_rating_n: float | None = None
    output_bearing_dynamic_tilting_moment_nm: float | None = None
    output_bearing_static_tilting_moment_nm: float | None = None
    output_bearing_radial_load_n: float | None = None
    output_bearing_axial_load_n: float | None = None
    output_bearing_moment_load_nm: float | None = None
    output_bearing_moment_stiffness_nm_per_rad: float | None = None
    output_bearing_type: str | None = None
    inductance_line_mh: float | None = None
    pole_pairs: float | None = None
    dc_bus_voltage_v: float | None = None
