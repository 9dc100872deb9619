"""Machine projects: several axes, each a selection's load case, on one DC bus (issue 31).

An axis is a selection request (``SelectionRequest``: load, mechanism, cycle and options)
with its name, its start ``offset_s`` on the machine cycle and, optionally, its chosen
actuator ``model`` (else the best candidate of its selection). The bus is a class of
Table 521.1 with, where the engineer has them from the drives' data sheets, the bus
capacitance and the highest and the chopper's voltages: the catalogue holds none of
them, so without them the capacitor and the resistance say "no data".
"""

from __future__ import annotations

from datetime import datetime
from typing import Any, Literal

from pydantic import ConfigDict, Field, StrictInt

from actuator_selection.catalogue.controllers import BusClass
from actuator_selection.schemas.common import MAX_TIME_S, ResponseModel, StrictModel
from actuator_selection.schemas.selections import (
    CheckBrief,
    ModelName,
    SelectionRequest,
    VoltageBrief,
)

MAX_AXES = 16
"""Axes in one project: more than one DC bus of a machine usually feeds."""
MAX_BUS_VOLTAGE_V = 2000.0
"""Bound for the bus voltages given [V]: above every servo drive's DC bus."""
MAX_CAPACITANCE_UF = 1_000_000.0
"""Bound for the bus capacitance [µF]: 1 F."""

EXAMPLE_AXIS: dict[str, Any] = {
    "name": "X",
    "offset_s": 0.0,
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}


class AxisIn(SelectionRequest):
    """One axis: a selection request with its name, offset and chosen actuator."""

    model_config = ConfigDict(json_schema_extra={"examples": [EXAMPLE_AXIS]})

    name: str = Field(default="", max_length=80, description="the axis's name, e.g. Z")
    offset_s: float = Field(
        default=0.0,
        ge=0,
        le=MAX_TIME_S,
        description="when the axis's cycle starts on the machine cycle [s] (taken modulo t_0)",
    )
    model: ModelName | None = Field(
        default=None,
        description="the chosen actuator; omitted: the first candidate of the axis's "
        "selection that publishes J_A",
    )
    controller: StrictInt | None = Field(
        default=None,
        ge=1,
        le=1_000_000,
        description="the chosen servo controller: its row in Table 521.1 (`source_row`, one "
        "of the axis's `controllers` in the answer): one Table 521.1 does not exclude for the "
        "axis's actuator, with a mark for the project's DC bus class, else 422; omitted: none",
    )


class BusIn(StrictModel):
    """The shared DC bus."""

    bus_class: BusClass = Field(strict=False, description="the DC bus class of Table 521.1")
    capacitance_uf: float | None = Field(
        default=None,
        gt=0,
        le=MAX_CAPACITANCE_UF,
        description="the bus capacitance of all drives on the bus [µF], from their data "
        "sheets; omitted: the capacitor result says no data",
    )
    max_voltage_v: float | None = Field(
        default=None,
        gt=0,
        le=MAX_BUS_VOLTAGE_V,
        description="the highest bus voltage the drives allow before they brake or trip [V] "
        "(data sheet); omitted: no data",
    )
    chopper_voltage_v: float | None = Field(
        default=None,
        gt=0,
        le=MAX_BUS_VOLTAGE_V,
        description="the braking chopper's switching voltage U_ch [V] (data sheet); "
        "omitted: the resistance says no data",
    )


class ProjectRequest(StrictModel):
    """A machine project: its axes on one bus, synchronised with their offsets."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [{"name": "Cell 1", "bus": {"bus_class": "560vdc"}, "axes": [EXAMPLE_AXIS]}]
        }
    )

    name: str = Field(min_length=1, max_length=120)
    bus: BusIn
    axes: list[AxisIn] = Field(min_length=1, max_length=MAX_AXES)


class PowerOut(ResponseModel):
    """Figures of one electrical power over the machine cycle (sizing/bus.py)."""

    peak_w: float = Field(description="the largest power drawn [W]")
    least_w: float = Field(description="the least power [W], negative where it regenerates")
    mean_w: float = Field(description="∫P dt/t_0, the net mean [W]")
    mean_supply_w: float = Field(
        description="∫max(P, 0) dt/t_0: the supply's mean when regeneration is burnt [W]"
    )
    energy_in_j: float = Field(description="∫max(P, 0) dt per cycle [J]")
    regen_energy_j: float = Field(description="∫max(−P, 0) dt per cycle, fed back [J]")
    regen_peak_w: float = Field(description="the largest power fed back [W]")
    regen_pulse_energy_j: float = Field(description="the largest pulse fed back [J]")
    regen_pulses: int = Field(description="pulses of regeneration per cycle")
    std_w: float = Field(description="standard deviation of P at a random instant [W]")


class EnergiesOut(ResponseModel):
    """∫ over the cycle of each power of an axis [J]: electrical = mechanical + losses."""

    mechanical_j: float
    no_load_j: float
    copper_j: float
    electrical_j: float


class ControllerChoice(ResponseModel):
    """A controller of Table 521.1 an axis may take: not excluded for its actuator, with a
    mark for the project's DC bus class."""

    source_row: int
    name: str = Field(description="manufacturer, type and variant")
    level: Literal["tested", "possible", "unconfirmed"] = Field(
        description="the match of Table 521.1 for the actuator (unconfirmed: the actuator "
        "lacks data for a criterion)"
    )
    bus_mark: Literal["tested", "possible"] = Field(
        description="the controller's mark for the project's DC bus class (Table 521.1)"
    )


class AxisControllerOut(ControllerChoice):
    """The axis's chosen controller and its output voltage on the project's bus."""

    voltage: VoltageBrief = Field(
        description="U_OUT the actuator needs at the axis's peak speed (Eq. 521.2) against "
        "what the project's DC bus class gives"
    )


class AxisCheckOut(CheckBrief):
    """A check of the axis's actuator as its selection's answer lists it, with its rule's
    unit and reference (which a selection's answer lists once, in ``check_rules``)."""

    unit: str = Field(description="unit of the check's value and limit")
    reference: str = Field(description="the chapter's equation, table or figure")


class AxisOut(ResponseModel):
    """One axis sized: its actuator, its selection's figures and its power."""

    name: str
    offset_s: float
    model: str
    chosen: bool = Field(description="the engineer chose the model (else: best candidate)")
    verdict: str = Field(description="the actuator's verdict in the axis's selection")
    checks: list[AxisCheckOut] | None = Field(
        default=None,
        description="the checks that verdict rests on, as the axis's selection lists them for "
        "the actuator; null: a project stored before they were (size it again)",
    )
    gear_ratio: float
    accel_torque_nm: float | None
    decel_torque_nm: float | None
    rms_torque_nm: float | None
    copper_loss_published: bool = Field(
        description="k_T and R are published: the copper loss is in the power"
    )
    no_load_loss_published: bool = Field(
        description="k_T, I_NLS and K_INL are published: the no-load loss is in the power"
    )
    energies: EnergiesOut
    power: PowerOut
    controller: AxisControllerOut | None = Field(
        description="the chosen controller (`controller` of the request); null: none chosen"
    )
    controllers: list[ControllerChoice] = Field(
        description="the controllers the axis may take on the project's bus, best first"
    )


class CapacitorOut(ResponseModel):
    """E = ½·C·(U_max² − U_nom²) against the largest pulse; nulls: no data."""

    capacitance_uf: float | None
    nominal_voltage_v: float = Field(description="U_nom of the bus class (Table 521.1)")
    max_voltage_v: float | None
    energy_j: float | None
    absorbs_every_pulse: bool | None
    reference: str


class BrakingResistorOut(ResponseModel):
    """The braking resistor the regeneration needs."""

    needed: bool
    peak_power_w: float
    continuous_power_w: float
    pulse_energy_j: float
    chopper_voltage_v: float | None
    max_resistance_ohm: float | None = Field(description="R ≤ U_ch²/P_peak; null: no data")
    min_resistance_ohm: float | None = Field(
        default=None, description="the chopper's minimum resistance (drive data sheet): no data"
    )
    reference: str


class PhasingOut(ResponseModel):
    """The axes in random phase instead of synchronised."""

    worst_peak_w: float = Field(description="worst-case alignment: Σ of each axis's peak")
    worst_regen_peak_w: float = Field(description="worst-case alignment of the regeneration")
    mean_w: float
    std_w: float
    statistical_peak_w: float = Field(
        description="μ + 3σ of the bus power at a random instant, independent uniform "
        "phases, normal approximation: a statistical figure, not a bound"
    )
    statistical_regen_w: float
    method: str


class BusOut(ResponseModel):
    """The shared bus over the machine cycle."""

    bus_class: BusClass
    nominal_voltage_v: float
    controllers_bus_mark: Literal["tested", "possible"] | None = Field(
        description="the weakest mark of the chosen controllers for the bus class (Table "
        "521.1); null: no axis has a controller"
    )
    voltage_status: Literal["pass", "fail", "warn", "no_data"] | None = Field(
        description="the worst output-voltage check (Eq. 521.2) of the chosen controllers on "
        "the bus; null: no axis has a controller"
    )
    power: PowerOut
    capacitor: CapacitorOut
    braking_resistor: BrakingResistorOut
    random_phasing: PhasingOut


class CurveOut(ResponseModel):
    """Each axis's electrical power for a chart, at every stretch's ends and inside."""

    times_s: list[float]
    axes_w: list[list[float]]


class ProjectOut(ResponseModel):
    """A stored machine project and its sizing."""

    id: str
    created_at: datetime
    updated_at: datetime
    catalogue_version: int = Field(description="the catalogue version the sizing used")
    request: ProjectRequest
    cycle_time_s: float
    axes: list[AxisOut]
    bus: BusOut
    curve: CurveOut


class ProjectBrief(ResponseModel):
    """A project in a list."""

    id: str
    name: str
    created_at: datetime
    updated_at: datetime
    catalogue_version: int
    axes: int


class ProjectPageOut(ResponseModel):
    """A page of projects, oldest first."""

    projects: list[ProjectBrief]
    next_cursor: str | None = Field(
        description="give as `cursor` for the next page; null: this is the last page"
    )
