"""Catalogue resources: actuators and their families."""

from __future__ import annotations

from pydantic import Field

from actuator_selection.core.catalogue import ActuatorRecord, FamilyRecord
from actuator_selection.core.electrical import OUTPUT_TURNS_OPPOSITE_TO_MOTOR
from actuator_selection.schemas.common import ResponseModel


class ZonePointOut(ResponseModel):
    """A corner of the continuous-duty zone's upper edge."""

    speed_rpm: float
    torque_nm: float


class ActuatorOut(ResponseModel):
    """A catalogue actuator; ``null`` where no public source gives the value."""

    model: str
    family: str
    gear_ratio: float
    max_torque_nm: float | None = Field(description="T_max, repeated peak torque [Nm]")
    max_speed_rpm: float | None = Field(description="n_max, maximum output speed [rpm]")
    inertia_kgm2: float | None = Field(description="J_A, moment of inertia at the output [kgm²]")
    stall_torque_nm: float | None = Field(description="T_0, continuous stall torque [Nm]")
    continuous_torque_nm: float | None = Field(description="allowable continuous torque [Nm]")
    max_current_a: float | None = Field(description="I_max [A_rms]")
    stall_current_a: float | None = Field(description="I_0, continuous stall current [A_rms]")
    continuous_current_a: float | None = Field(description="allowable continuous current [A]")
    torque_constant_nm_per_a: float | None = Field(description="k_T at the output [Nm/A]")
    motor_torque_constant_nm_per_a: float | None = Field(description="k_TM of the motor [Nm/A]")
    motor_voltage_constant_v_per_krpm: float | None = Field(
        description="K_E of the motor, line-to-line [V per 1000 rpm motor speed]"
    )
    output_voltage_constant_v_per_rpm: float | None = Field(
        description="k_E referred to the output [V per output rpm]"
    )
    resistance_line_ohm: float | None = Field(description="winding resistance, line-to-line [Ω]")
    resistance_phase_ohm: float | None = Field(description="winding resistance per phase [Ω]")
    inductance_line_mh: float | None
    inductance_phase_mh: float | None
    no_load_starting_current_a: float | None = Field(description="I_NLS (Eq. 522.2) [A]")
    no_load_current_constant_30c_a_per_rpm: float | None = Field(
        description="K_INL at 30 °C (Eq. 522.2) [A/rpm]"
    )
    no_load_current_constant_80c_a_per_rpm: float | None = Field(
        description="K_INL at 80 °C [A/rpm]"
    )
    thermal_time_constant_s: float | None
    mass_kg: float | None
    max_dc_bus_voltage_v: float | None
    supply_voltage: str | None
    feedback: str | None
    continuous_duty_zone: list[ZonePointOut] | None = Field(
        description="upper edge of the continuous-duty zone, where published"
    )
    continuous_duty_zone_source: str | None
    output_turns_opposite_to_motor: bool = Field(
        default=OUTPUT_TURNS_OPPOSITE_TO_MOTOR,
        description="the integrated Harmonic Drive gear reverses the direction: the output "
        "turns counter-clockwise when the motor shaft turns clockwise (chapter, Direction of "
        "Rotation)",
    )
    continuous_speed_rpm: float | None = Field(
        description="allowable continuous output speed [rpm]"
    )
    rated_speed_rpm: float | None = Field(
        description="rated output speed [rpm] (CHA: derived, rated motor speed / i; see derivation)"
    )
    brake_holding_torque_nm: float | None = Field(
        description="T_Br, holding torque of the motor brake at the output [Nm]"
    )
    output_bearing_pitch_diameter_m: float | None = Field(
        description="d_p, pitch circle diameter of the output bearing [m]"
    )
    output_bearing_offset_m: float | None = Field(description="R, output bearing offset [m]")
    output_bearing_dynamic_load_rating_n: float | None = Field(
        description="C, dynamic load rating of the output bearing [N]"
    )
    output_bearing_static_load_rating_n: float | None = Field(
        description="C_0, static load rating of the output bearing [N]"
    )
    output_bearing_dynamic_tilting_moment_nm: float | None = Field(
        description="M_dyn(max), allowable dynamic tilting moment [Nm]"
    )
    output_bearing_static_tilting_moment_nm: float | None = Field(
        description="M_0(max), allowable static tilting moment [Nm]"
    )
    output_bearing_radial_load_n: float | None = Field(
        description="allowable radial load on the output bearing [N]"
    )
    output_bearing_axial_load_n: float | None = Field(
        description="allowable axial load on the output bearing [N]"
    )
    output_bearing_moment_load_nm: float | None = Field(
        description="allowable moment load on the output bearing [Nm]"
    )
    output_bearing_moment_stiffness_nm_per_rad: float | None = Field(
        description="moment stiffness of the output bearing [Nm/rad]"
    )
    pole_pairs: float | None = Field(description="the motor's number of pole pairs p")
    output_bearing_type: str | None = Field(
        description="the output bearing's type, `cross_roller` or `four_point_contact_ball`: "
        "it sets the life exponent (10/3 or 3)"
    )
    notes: str | None
    derivation: str | None = Field(description="how the row's derived values were obtained")
    source: str = Field(
        description="the manufacturer's documents the values come from: publisher, title, "
        "document number, edition, page or table"
    )
    read_at: str | None = Field(
        description="where values were read or checked: public copies of the cited documents "
        "(mirror websites), kept beside the citation, never in its place"
    )

    @classmethod
    def from_record(cls, record: ActuatorRecord) -> ActuatorOut:
        """The response body of one catalogue record."""
        a = record.actuator
        return cls(
            model=a.model,
            family=a.family,
            gear_ratio=a.gear_ratio,
            max_torque_nm=a.max_torque_nm,
            max_speed_rpm=a.max_speed_rpm,
            inertia_kgm2=a.inertia_kgm2,
            stall_torque_nm=a.stall_torque_nm,
            continuous_torque_nm=a.continuous_torque_nm,
            max_current_a=a.max_current_a,
            stall_current_a=a.stall_current_a,
            continuous_current_a=record.continuous_current_a,
            torque_constant_nm_per_a=a.torque_constant_nm_per_a,
            motor_torque_constant_nm_per_a=record.motor_torque_constant_nm_per_a,
            motor_voltage_constant_v_per_krpm=a.motor_voltage_constant_v_per_krpm,
            output_voltage_constant_v_per_rpm=a.output_voltage_constant_v_per_rpm,
            resistance_line_ohm=a.resistance_line_ohm,
            resistance_phase_ohm=a.resistance_phase_ohm,
            inductance_line_mh=record.inductance_line_mh,
            inductance_phase_mh=record.inductance_phase_mh,
            no_load_starting_current_a=a.no_load_starting_current_a,
            no_load_current_constant_30c_a_per_rpm=a.no_load_current_constant_30c_a_per_rpm,
            no_load_current_constant_80c_a_per_rpm=a.no_load_current_constant_80c_a_per_rpm,
            thermal_time_constant_s=a.thermal_time_constant_s,
            mass_kg=record.mass_kg,
            max_dc_bus_voltage_v=record.max_dc_bus_voltage_v,
            supply_voltage=record.supply_voltage,
            feedback=record.feedback,
            continuous_duty_zone=(
                [ZonePointOut(speed_rpm=p.speed_rpm, torque_nm=p.torque_nm) for p in a.zone.points]
                if a.zone
                else None
            ),
            continuous_duty_zone_source=record.zone_source,
            continuous_speed_rpm=a.continuous_speed_rpm,
            rated_speed_rpm=a.rated_speed_rpm,
            brake_holding_torque_nm=a.brake_holding_torque_nm,
            output_bearing_pitch_diameter_m=a.output_bearing_pitch_diameter_m,
            output_bearing_offset_m=a.output_bearing_offset_m,
            output_bearing_dynamic_load_rating_n=a.output_bearing_dynamic_load_rating_n,
            output_bearing_static_load_rating_n=a.output_bearing_static_load_rating_n,
            output_bearing_dynamic_tilting_moment_nm=a.output_bearing_dynamic_tilting_moment_nm,
            output_bearing_static_tilting_moment_nm=a.output_bearing_static_tilting_moment_nm,
            output_bearing_radial_load_n=a.output_bearing_radial_load_n,
            output_bearing_axial_load_n=a.output_bearing_axial_load_n,
            output_bearing_moment_load_nm=a.output_bearing_moment_load_nm,
            output_bearing_moment_stiffness_nm_per_rad=a.output_bearing_moment_stiffness_nm_per_rad,
            pole_pairs=a.pole_pairs,
            output_bearing_type=a.output_bearing_type,
            notes=record.notes,
            derivation=record.derivation,
            source=record.source,
            read_at=record.read_at,
        )


class ActuatorPageOut(ResponseModel):
    """A page of catalogue actuators, ordered by model."""

    actuators: list[ActuatorOut]
    next_cursor: str | None = Field(
        description="give as `cursor` for the next page; null: this is the last page"
    )


class FamilyOut(ResponseModel):
    """A product family with its temperature sensor (Table 518.1) and limits (Table 519.2)."""

    name: str
    description: str | None
    temperature_sensors: str | None
    warning_temperature_c: float | None
    shutdown_temperature_c: float | None
    temperature_tolerance_percent: float | None
    warning_resistance_ohm: float | None
    shutdown_resistance_ohm: float | None
    resistance_tolerance_percent: float | None
    source: str

    @classmethod
    def from_record(cls, record: FamilyRecord) -> FamilyOut:
        """The response body of one family."""
        return cls.model_validate(record, from_attributes=True)
