"""Engineering tools: controller output voltage, sensor reading, overload duration, torque."""

from __future__ import annotations

from typing import Literal

from pydantic import ConfigDict, Field, field_validator

from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.schemas.common import MAX_SPEED_RPM, ResponseModel, StrictModel

MAX_VOLTAGE_CONSTANT = 10_000.0
"""K_E bound [V per 1000 rpm]: a hundred times the largest catalogue value."""
MAX_CURRENT_A = 10_000.0
MAX_RESISTANCE_OHM = 100_000.0
MAX_INDUCTANCE_MH = 100_000.0
MAX_POLE_PAIRS = 1_000.0
MAX_GEAR_RATIO = 10_000.0
MAX_TIME_CONSTANT_S = 1e6
MAX_OVERLOAD_FACTOR = 100.0
OUTPUT_DIRECTION = (
    "the output turns opposite to the motor shaft (chapter, Direction of Rotation): "
    "a positive output speed is a negative motor speed"
)

_SENSOR_NAMES = {
    "kty84-130": TemperatureSensor.KTY84_130,
    "kty 84-130": TemperatureSensor.KTY84_130,
    "kty84_130": TemperatureSensor.KTY84_130,
    "ptc": TemperatureSensor.PTC,
}


class ControllerVoltageRequest(StrictModel):
    """Eq. 521.2 with the inductive drop for a catalogue ``model`` or for explicit
    constants (these override)."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "output_speed_rpm": 40,
                    "gear_ratio": 50,
                    "voltage_constant_v_per_krpm": 25,
                    "max_current_a": 8.3,
                    "resistance_ohm": 1.2,
                    "inductance_mh": 3.0,
                    "pole_pairs": 6,
                }
            ]
        }
    )

    model: str | None = Field(default=None, max_length=60)
    output_speed_rpm: float = Field(ge=0, le=MAX_SPEED_RPM, description="n_OUT [rpm]")
    gear_ratio: float | None = Field(default=None, gt=0, le=MAX_GEAR_RATIO, description="i")
    voltage_constant_v_per_krpm: float | None = Field(
        default=None,
        gt=0,
        le=MAX_VOLTAGE_CONSTANT,
        description="K_E of the motor, V_rms line-to-line per 1000 rpm motor speed",
    )
    max_current_a: float | None = Field(default=None, ge=0, le=MAX_CURRENT_A, description="I_MAX")
    resistance_ohm: float | None = Field(
        default=None, gt=0, le=MAX_RESISTANCE_OHM, description="R, line-to-line [Ω]"
    )
    inductance_mh: float | None = Field(
        default=None,
        ge=0,
        le=MAX_INDUCTANCE_MH,
        description="L, line-to-line [mH]; 0 gives Eq. 521.2 as printed",
    )
    pole_pairs: float | None = Field(
        default=None, gt=0, le=MAX_POLE_PAIRS, description="p, the motor's pole pairs"
    )


class BusVoltageOut(ResponseModel):
    """What one DC bus class delivers against U_OUT."""

    bus_class: str
    dc_bus_voltage_v: float
    available_voltage_v: float
    sufficient: bool
    margin_percent: float
    message: str


class ControllerVoltageOut(ResponseModel):
    """U_OUT = √((n_OUT·i·K_E + I_MAX·R)² + (ω·L·I_MAX)²) (Eq. 521.2 with the inductive
    drop in quadrature, as the selection's drive_voltage check) and its terms."""

    voltage_v: float = Field(description="U_OUT, V_rms line-to-line, with ω·L·I_MAX")
    back_emf_v: float = Field(description="n_OUT·i·K_E")
    resistive_v: float = Field(description="I_MAX·R")
    inductive_v: float = Field(description="ω·L·I_MAX, ω = 2π·p·n_OUT·i/60")
    printed_v: float = Field(description="Eq. 521.2 as printed: n_OUT·i·K_E + I_MAX·R")
    output_speed_rpm: float
    motor_speed_rpm: float = Field(description="signed: negative = opposite to the output")
    direction: str = OUTPUT_DIRECTION
    gear_ratio: float
    voltage_constant_v_per_krpm: float
    max_current_a: float
    resistance_ohm: float
    inductance_mh: float
    pole_pairs: float
    bus_classes: list[BusVoltageOut] = Field(
        description="each DC bus class of Table 521.1, space-vector modulation: U_LL,rms = U_DC/√2"
    )
    reference: str = "Eq. 521.2 with ωL·I in quadrature"


class SensorTemperatureRequest(StrictModel):
    """A winding-sensor resistance, optionally judged against a family's limits."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [{"sensor": "kty84_130", "resistance_ohm": 1000, "family": "FHA-C"}]
        }
    )

    # Not strict: JSON gives the sensor's name as text, never an enum member.
    sensor: TemperatureSensor = Field(strict=False, description="'KTY84-130' or 'PTC'")
    resistance_ohm: float = Field(gt=0, le=1e6, description="measured resistance [Ω]")
    family: str | None = Field(default=None, max_length=40, description="e.g. FHA-C")
    nominal_response_temperature_c: float | None = Field(
        default=None, ge=-50, le=300, description="PTC only: T_NAT [°C], if not from the family"
    )
    sensor_count: int | None = Field(
        default=None, ge=1, le=10, description="PTC only: sensors in series (TorkDrive: 3)"
    )

    @field_validator("sensor", mode="before")
    @classmethod
    def _sensor_name(cls, value: object) -> object:
        if isinstance(value, str):
            return _SENSOR_NAMES.get(value.strip().lower(), value)
        return value


class PtcOut(ResponseModel):
    """What a PTC reading tells: a zone around T_NAT, never a temperature."""

    zone: str
    resistance_per_sensor_ohm: float
    nominal_response_temperature_c: float
    known_above_c: float | None
    known_below_c: float | None


class SensorTemperatureOut(ResponseModel):
    """The reading: temperature (KTY only), state against Table 519.2, explanation."""

    sensor: str
    resistance_ohm: float
    temperature_c: float | None = Field(description="KTY 84-130 only; a PTC cannot tell it")
    state: Literal["normal", "warning", "shutdown"] | None = Field(
        description="null when the family has no published limits"
    )
    near_limit: str | None
    ptc: PtcOut | None
    family: str | None
    message: str
    reference: str


class OverloadDurationRequest(StrictModel):
    """Time to shutdown at an overload (first-order thermal model standing in for Fig. 520.1)."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {"overload_factor": 2, "thermal_time_constant_s": 1200, "preload_factor": 0.5}
            ]
        }
    )

    overload_factor: float = Field(gt=0, le=MAX_OVERLOAD_FACTOR, description="k = I / I_s")
    thermal_time_constant_s: float | None = Field(
        default=None, gt=0, le=MAX_TIME_CONSTANT_S, description="τ_th [s]; else the catalogue's"
    )
    preload_factor: float = Field(
        default=0.0, ge=0, le=MAX_OVERLOAD_FACTOR, description="p = I_prev / I_s (0 from cold)"
    )
    model: str | None = Field(default=None, max_length=60)
    max_overload_factor: float | None = Field(
        default=None,
        gt=1,
        le=MAX_OVERLOAD_FACTOR,
        description="upper end of the curve; default I_max/I_0 of the model",
    )


class OverloadPointOut(ResponseModel):
    """One point of the overload curve."""

    overload_factor: float
    time_to_shutdown_s: float | None


class OverloadDurationOut(ResponseModel):
    """t = τ_th·ln((k² − p²)/(k² − 1))."""

    time_to_shutdown_s: float
    overload_factor: float
    preload_factor: float
    thermal_time_constant_s: float
    curve: list[OverloadPointOut] | None = Field(
        description="k from just above 1 to the maximum overload; null without a maximum"
    )
    model_note: str = (
        "Fig. 520.1's values are not published; this is the first-order thermal model of a "
        "winding, t = τ_th·ln((k² − p²)/(k² − 1))"
    )
    reference: str = "Fig. 520.1 (model)"


class OutputTorqueRequest(StrictModel):
    """Eq. 522.2/522.3 for a catalogue ``model`` or explicit constants (these override)."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "current_a": 3,
                    "speed_rpm": 40,
                    "temperature_c": 30,
                    "torque_constant_nm_per_a": 33,
                    "no_load_starting_current_a": 0.3,
                    "no_load_current_constant_30c_a_per_rpm": 0.002,
                }
            ]
        }
    )

    current_a: float = Field(ge=0, le=MAX_CURRENT_A, description="measured fundamental I [A]")
    speed_rpm: float = Field(
        ge=-MAX_SPEED_RPM, le=MAX_SPEED_RPM, description="actuator output speed n_out [rpm]"
    )
    temperature_c: float = Field(default=30.0, ge=-50, le=300, description="actuator temperature")
    extrapolate: bool = Field(default=False, description="allow temperatures outside 30…80 °C")
    model: str | None = Field(default=None, max_length=60)
    torque_constant_nm_per_a: float | None = Field(default=None, gt=0, le=1e6)
    no_load_starting_current_a: float | None = Field(default=None, ge=0, le=MAX_CURRENT_A)
    no_load_current_constant_30c_a_per_rpm: float | None = Field(default=None, ge=0, le=10)
    no_load_current_constant_80c_a_per_rpm: float | None = Field(default=None, ge=0, le=10)


class OutputTorqueOut(ResponseModel):
    """T_out = K_T·(I − I_NLR), I_NLR = I_NLS + K_INL·n_out."""

    torque_nm: float
    no_load_current_a: float = Field(description="I_NLR (Eq. 522.2)")
    no_load_current_constant_a_per_rpm: float = Field(description="K_INL at temperature_c")
    torque_producing_current_a: float
    below_no_load_current: bool
    extrapolated: bool
    motor_speed_rpm: float | None = Field(description="signed; null without a gear ratio")
    direction: str = OUTPUT_DIRECTION
    message: str
    reference: str
