"""A selection request: the load, the cycle, the options, and the worked example."""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import ConfigDict, Field

from actuator_selection.errors import InvalidInputError
from actuator_selection.schemas.common import (
    MAX_TIME_S,
    StrictModel,
)
from actuator_selection.schemas.output_load import (
    DRIVE_FIELD,
    OUTPUT_LOAD_FIELD,
    OutputLoadIn,
    output_load_core,
)
from actuator_selection.schemas.selections.cycles import AnyCycleIn, CycleIn
from actuator_selection.schemas.selections.loads import LoadIn, _load_speed, _LoadIn
from actuator_selection.sizing.application import DEFAULT_BRAKE_SAFETY_FACTOR
from actuator_selection.sizing.cycle import SpeedPattern
from actuator_selection.sizing.selection import Application

ModelName = Annotated[str, Field(min_length=1, max_length=60)]


WORKED_EXAMPLE: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}
"""The chapter's worked example (Table 516.1): the example request of the API documents."""


class GearIn(StrictModel):
    """The strain wave gear's own limits are checked (issue 28, item 7): T_av, repeated
    peak torque, average input speed; with a momentary peak and with a required life."""

    required_life_h: float | None = Field(
        default=None,
        gt=0,
        le=1e7,
        description="wave generator life the application needs [h] (check `gear_life`)",
    )
    momentary_torque_nm: float | None = Field(
        default=None,
        gt=0,
        le=1e7,
        description="a momentary peak torque at the output, a collision or emergency stop "
        "[Nm] (check `gear_momentary_peak`); needs `momentary_count`",
    )
    momentary_count: float | None = Field(
        default=None, gt=0, le=1e12, description="how often that peak occurs over the life"
    )


class SelectionRequest(StrictModel):
    """A load case to size; ``models`` restricts the catalogue to those listed."""

    model_config = ConfigDict(json_schema_extra={"examples": [WORKED_EXAMPLE]})

    load: LoadIn
    cycle: AnyCycleIn
    high_dynamics: bool = Field(
        default=True, description="J_L ≤ 3·J_A is binding (fail) when true, a warning otherwise"
    )
    brake: bool = Field(
        default=False,
        description="the actuator is fitted with its holding brake: its holding torque is "
        "checked against T_L at standstill (check `brake_holding`)",
    )
    models: list[ModelName] | None = Field(default=None, min_length=1, max_length=1000)
    drive: bool = DRIVE_FIELD
    output_load: OutputLoadIn | None = OUTPUT_LOAD_FIELD
    thermal_time_constant_s: float | None = Field(
        default=None,
        gt=0,
        le=MAX_TIME_S,
        description="the winding's thermal time constant τ_th [s] where the catalogue gives "
        "none (check `thermal_peak`); omitted: 600 s, assumed, and the check says approximate",
    )

    gear: GearIn | None = Field(
        default=None,
        description="check the strain wave gear's own limits (checks `gear_average_torque`, "
        "`gear_repeated_peak`, `gear_input_speed`, and `gear_momentary_peak`, `gear_life` "
        "where asked); omitted: not checked (their ratings are catalogue values an "
        "administrator imports; where missing the checks say no data)",
    )
    min_natural_frequency_hz: float | None = Field(
        default=None,
        gt=0,
        le=1e6,
        description="the least natural frequency of the load on the gear's torsional "
        "stiffness, f_n = (1/2π)·√(K_1/J_L) [Hz] (check `natural_frequency`, which also "
        "reports the torsional deflection under T_L and under T_1)",
    )
    brake_safety_factor: float = Field(
        default=DEFAULT_BRAKE_SAFETY_FACTOR,
        ge=1,
        le=100,
        description="S of the brake's holding check S·T_L ≤ T_Br (check `brake_holding`); "
        "default 1, the holding torque as published: the user's choice, since no public "
        "manufacturer or standards document we read names a default (decision 0026)",
    )
    emergency_stops: float | None = Field(
        default=None,
        gt=0,
        le=1e12,
        description="emergency stops expected over the life, with a brake: against the "
        "brake's allowable number (check `brake_emergency_stops`, which also reports how "
        "far a falling load turns the output while the brake closes)",
    )

    def to_core(self) -> Application:
        """The application as the core sees it: the chapter's shorthand (T_L, J_L, the
        t_1…t_p pattern) where that is what was sent, else a motion of segments."""
        speed, speed_field = _load_speed(self.load)
        if self._plain():  # every option at its default: the core's defaults
            options: dict[str, Any] = {"high_dynamics": self.high_dynamics}
        else:
            options = self._options()
        load = self.load
        if isinstance(self.cycle, CycleIn) and isinstance(load, _LoadIn) and load.chapter_shorthand:
            if speed is None:
                raise InvalidInputError(speed_field, code="speed_required")
            pattern = SpeedPattern(
                speed_rpm=speed,
                accel_s=self.cycle.accel_s,
                constant_s=self.cycle.constant_s,
                decel_s=self.cycle.decel_s,
                pause_s=self.cycle.pause_s,
            )
            return Application(pattern=pattern, load=load.to_core(), **options)
        motion = self.cycle.to_motion(speed, load.to_axis(), speed_field)
        return Application(motion=motion, **options)

    def _plain(self) -> bool:
        """Whether every option but ``high_dynamics`` is at its default (a batch's case,
        mostly): :meth:`_options` then says nothing the core's defaults do not."""
        return (
            not self.brake
            and not self.drive
            and self.output_load is None
            and self.thermal_time_constant_s is None
            and self.gear is None
            and self.min_natural_frequency_hz is None
            and self.brake_safety_factor == DEFAULT_BRAKE_SAFETY_FACTOR
            and self.emergency_stops is None
        )

    def _options(self) -> dict[str, Any]:
        """The application's options beyond its motion, as the core names them."""
        return {
            "high_dynamics": self.high_dynamics,
            "brake": self.brake,
            "drive": self.drive,
            "output_load": output_load_core(self.output_load),
            "thermal_time_constant_s": self.thermal_time_constant_s,
            "gear": self.gear is not None,
            "gear_required_life_h": None if self.gear is None else self.gear.required_life_h,
            "momentary_torque_nm": None if self.gear is None else self.gear.momentary_torque_nm,
            "momentary_count": None if self.gear is None else self.gear.momentary_count,
            "min_natural_frequency_hz": self.min_natural_frequency_hz,
            "brake_safety_factor": self.brake_safety_factor,
            "emergency_stops": self.emergency_stops,
        }
