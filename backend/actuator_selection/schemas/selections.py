"""The selection contract: what ERP systems and the web page send and receive.

Field names are part of the public API (issue "Selection engine end to end"); keep them.
"""

from __future__ import annotations

from datetime import datetime
from typing import Annotated, Any, Literal

from pydantic import ConfigDict, Discriminator, Field, Tag

from actuator_selection.core.axis import AxisLoad
from actuator_selection.core.cycle import Load, SpeedPattern
from actuator_selection.core.errors import DomainError, InvalidInputError
from actuator_selection.core.loads import BallScrew, RotaryTable, ball_screw_load, rotary_table_load
from actuator_selection.core.motion import MAX_SEGMENTS, Motion, Segment, trapezoid
from actuator_selection.core.selection import Application
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.checks import CheckOut
from actuator_selection.schemas.common import (
    MAX_FRICTION_COEFFICIENT,
    MAX_INERTIA_KGM2,
    MAX_LENGTH_M,
    MAX_MASS_KG,
    MAX_SPEED_RPM,
    MAX_TIME_S,
    MAX_TORQUE_NM,
    MIN_EFFICIENCY,
    MIN_LENGTH_M,
    MIN_RAMP_S,
    ResponseModel,
    StrictModel,
    shown,
)
from actuator_selection.schemas.controllers import (
    DriveOptionOut,
)
from actuator_selection.schemas.mechanisms import Mechanisms, _MechanismIn, union_tags
from actuator_selection.schemas.output_load import (
    DRIVE_FIELD,
    OUTPUT_LOAD_FIELD,
    OutputLoadIn,
    output_load_core,
)

SpeedRpm = Annotated[
    float,
    Field(
        gt=0,
        le=MAX_SPEED_RPM,
        description="n_2, load speed at the output [rpm]; with the t_1…t_p cycle only "
        "(segments give their own speeds)",
    ),
]
Mass = Annotated[float, Field(ge=0, le=MAX_MASS_KG, description="moved mass m [kg]")]
Friction = Annotated[
    float, Field(ge=0, le=MAX_FRICTION_COEFFICIENT, description="coefficient of friction μ [-]")
]
Inertia = Annotated[float, Field(ge=0, le=MAX_INERTIA_KGM2)]


def _renamed(exc: DomainError, prefix: str) -> DomainError:
    """``exc`` with its field under ``prefix`` (``efficiency`` → ``load.efficiency``), so that
    a core error names the field where the request body has it."""
    return exc.moved(f"{prefix}.{exc.field}")


class _LoadIn(StrictModel):
    """A load as sent; :meth:`to_core` resolves it to T_L and J_L at the output."""

    speed_rpm: SpeedRpm | None = None

    def to_core(self) -> Load:
        """The load as the core sees it; a core error names its field under ``load``."""
        try:
            return self._resolve()
        except DomainError as exc:
            raise _renamed(exc, "load") from None

    def to_axis(self) -> AxisLoad:
        """The load at the output with its friction, weight and losses (``core/axis.py``)."""
        load = self.to_core()
        return AxisLoad(inertia_kgm2=load.inertia_kgm2, friction_torque_nm=load.torque_nm)

    @property
    def chapter_shorthand(self) -> bool:
        """Whether the load is the chapter's T_L, J_L alone (no weight, no losses)."""
        return True

    def _resolve(self) -> Load:
        raise NotImplementedError


class DirectLoad(_LoadIn):
    """T_L and J_L given directly, at the actuator output."""

    type: Literal["direct"] = "direct"
    torque_nm: float = Field(
        ge=0,
        le=MAX_TORQUE_NM,
        description="T_L, load torque opposing the motion [Nm]",
        json_schema_extra=shown("T_L", "load.torque"),
    )
    inertia_kgm2: Inertia = Field(
        description="J_L, load moment of inertia [kgm²]",
        json_schema_extra=shown("J_L", "load.inertia"),
    )
    gravity_torque_nm: float = Field(
        default=0.0,
        ge=-MAX_TORQUE_NM,
        le=MAX_TORQUE_NM,
        description="T_G, a torque that acts at standstill too (a weight less its "
        "counterweight) [Nm], signed: positive opposes positive rotation; negative "
        "overhauls (drives the axis)",
        json_schema_extra=shown("T_G", "load.gravity"),
    )
    efficiency: float = Field(
        default=1.0,
        ge=MIN_EFFICIENCY,
        le=1,
        description="η between actuator and load: torques are divided by η where the "
        "actuator drives, multiplied where the load drives back",
        json_schema_extra=shown("η", "load.efficiency"),
    )

    def _resolve(self) -> Load:
        return Load(torque_nm=self.torque_nm, inertia_kgm2=self.inertia_kgm2)

    def to_axis(self) -> AxisLoad:
        return AxisLoad(
            inertia_kgm2=self.inertia_kgm2,
            friction_torque_nm=self.torque_nm,
            gravity_torque_nm=self.gravity_torque_nm,
            efficiency=self.efficiency,
        )

    @property
    def chapter_shorthand(self) -> bool:
        return self.gravity_torque_nm == 0 and self.efficiency == 1


class BallScrewLoad(_LoadIn):
    """Linear horizontal motion by a ball screw (Fig. 515.2, Eq. 515.4)."""

    type: Literal["ball_screw"]
    mass_kg: Mass = Field(json_schema_extra=shown("m", "load.mass"))
    lead_m: float = Field(
        ge=MIN_LENGTH_M,
        le=MAX_LENGTH_M,
        description="screw lead P [m/rev], ≥ 1 µm",
        json_schema_extra=shown("P", "load.lead"),
    )
    friction_coefficient: Friction = Field(json_schema_extra=shown("μ", "load.friction"))
    efficiency: float = Field(
        ge=MIN_EFFICIENCY,
        le=1,
        description="screw efficiency η [-], 0.01 ≤ η ≤ 1",
        json_schema_extra=shown("η", "load.efficiency"),
    )
    screw_inertia_kgm2: Inertia = Field(
        default=0.0,
        description="J_S, screw inertia [kgm²]",
        json_schema_extra=shown("J_S", "load.screw_inertia"),
    )

    def _resolve(self) -> Load:
        """T_L and J_L by Eq. 515.4."""
        return ball_screw_load(
            BallScrew(
                mass_kg=self.mass_kg,
                lead_m=self.lead_m,
                friction_coefficient=self.friction_coefficient,
                efficiency=self.efficiency,
                screw_inertia_kgm2=self.screw_inertia_kgm2,
            )
        )


class RotaryTableLoad(_LoadIn):
    """A rotary table, a uniform disc (Fig. 515.3/515.5, Eq. 515.6)."""

    type: Literal["rotary_table"]
    mass_kg: Mass = Field(json_schema_extra=shown("m", "load.mass"))
    diameter_m: float = Field(
        ge=MIN_LENGTH_M,
        le=MAX_LENGTH_M,
        description="table diameter D [m], ≥ 1 µm",
        json_schema_extra=shown("D", "load.diameter"),
    )
    friction_coefficient: Friction = Field(json_schema_extra=shown("μ", "load.friction"))
    friction_radius_m: float = Field(
        ge=0,
        le=MAX_LENGTH_M,
        description="radius r at which friction acts [m]",
        json_schema_extra=shown("r", "load.friction_radius"),
    )

    def _resolve(self) -> Load:
        """T_L and J_L by Eq. 515.6."""
        return rotary_table_load(
            RotaryTable(
                mass_kg=self.mass_kg,
                diameter_m=self.diameter_m,
                friction_coefficient=self.friction_coefficient,
                friction_radius_m=self.friction_radius_m,
            )
        )


def _load_kind(value: Any) -> str:
    kind = value.get("type", "direct") if isinstance(value, dict) else getattr(value, "type", None)
    return kind if isinstance(kind, str) else "direct"


_Loads = (
    Annotated[DirectLoad, Tag("direct")]
    | Annotated[BallScrewLoad, Tag("ball_screw")]
    | Annotated[RotaryTableLoad, Tag("rotary_table")]
    | Mechanisms
)
LOAD_TYPES = union_tags(_Loads)
"""The ``type`` of each load in :data:`LoadIn`: the chapter's three, then the mechanisms."""

LoadIn = Annotated[
    _Loads,
    Discriminator(
        _load_kind,
        custom_error_type="load_type",
        custom_error_message="type must be one of " + ", ".join(f"'{k}'" for k in LOAD_TYPES),
    ),
]
"""The chapter's loads (T_L and J_L, Eq. 515.4, 515.6; speeds in rpm at the output) and the
mechanisms of ``schemas/mechanisms.py`` (speeds in mm/s on linear axes, units at the edge)."""


def _load_speed(load: _LoadIn | _MechanismIn) -> tuple[float | None, str]:
    """The trapezoid's load speed as sent, and its field."""
    if isinstance(load, _LoadIn):
        return load.speed_rpm, "load.speed_rpm"
    return getattr(load, "speed", None), "load.speed"


class CycleIn(StrictModel):
    """The speed pattern of Fig. 516.2: the chapter's trapezoid, at the load speed n_2."""

    accel_s: float = Field(
        ge=MIN_RAMP_S, le=MAX_TIME_S, description="t_1, acceleration time [s], > 0"
    )
    constant_s: float = Field(ge=0, le=MAX_TIME_S, description="t_2, time at speed n_2 [s]")
    decel_s: float = Field(
        ge=MIN_RAMP_S, le=MAX_TIME_S, description="t_3, deceleration time [s], > 0"
    )
    pause_s: float = Field(ge=0, le=MAX_TIME_S, description="t_p, standstill [s]")

    def to_motion(self, speed: float | None, axis: AxisLoad, speed_field: str) -> Motion:
        """The trapezoid as segments at the output (``speed`` in the load's unit)."""
        if speed is None:
            raise InvalidInputError(speed_field, code="speed_required")
        return trapezoid(
            speed_rpm=speed * axis.speed_rpm_per_unit,
            accel_s=self.accel_s,
            constant_s=self.constant_s,
            decel_s=self.decel_s,
            pause_s=self.pause_s,
            load=axis,
        )


class SegmentIn(StrictModel):
    """One step of a cycle: to ``speed`` in ``duration_s`` (or at ``accel``), along a ramp
    or an S-curve, with a process load. Speeds and loads are in the load's units (rpm and
    Nm at the output for the chapter's loads)."""

    speed: float | None = Field(
        default=None,
        ge=-MAX_SPEED_RPM,
        le=MAX_SPEED_RPM,
        description="speed at the segment's end, signed (negative: the other way); omitted: "
        "the speed the segment starts at (a run at constant speed, or a dwell at 0)",
    )
    duration_s: float | None = Field(
        default=None,
        ge=0,
        le=MAX_TIME_S,
        description="duration [s]; give it or `accel`",
    )
    accel: float | None = Field(
        default=None,
        gt=0,
        le=1e9,
        description="acceleration (magnitude) in speed units per second, instead of "
        "`duration_s` for a change of speed",
    )
    jerk_share: float = Field(
        default=0.0,
        ge=0,
        le=1,
        description="share of the duration in which the acceleration ramps up and down: 0 "
        "constant acceleration, 1 a pure S-curve",
    )
    process_load: float = Field(
        default=0.0,
        ge=-MAX_TORQUE_NM,
        le=MAX_TORQUE_NM,
        description="external torque [Nm] (or force [N] on a linear axis) during the "
        "segment, signed: positive opposes positive motion",
    )


class SegmentsCycleIn(StrictModel):
    """A cycle of segments (issue "Real axes"); it repeats, so it must end at the speed it
    starts at. The CHA manual sums T_rms and n_av over n segments; so does the service."""

    start_speed: float = Field(
        default=0.0,
        ge=-MAX_SPEED_RPM,
        le=MAX_SPEED_RPM,
        description="speed at the cycle's start, in the load's unit",
    )
    segments: list[SegmentIn] = Field(min_length=1, max_length=MAX_SEGMENTS)

    def to_motion(self, speed: float | None, axis: AxisLoad, speed_field: str) -> Motion:
        """The segments at the output; a core error names the segment's field."""
        if speed is not None:
            raise InvalidInputError(speed_field, code="speed_with_segments")
        to_rpm, to_nm = axis.speed_rpm_per_unit, axis.torque_nm_per_force_unit
        segments = []
        start = self.start_speed
        for k, seg in enumerate(self.segments):
            where = f"cycle.segments.{k}"
            end = start if seg.speed is None else seg.speed
            if (seg.duration_s is None) == (seg.accel is None):
                raise InvalidInputError(f"{where}.duration_s", code="duration_or_accel")
            if seg.accel is not None:
                if end == start:
                    raise InvalidInputError(f"{where}.accel", code="accel_without_speed_change")
                duration = abs(end - start) / seg.accel
            else:
                assert seg.duration_s is not None
                duration = seg.duration_s
            try:
                segments.append(
                    Segment(
                        duration_s=duration,
                        start_rpm=start * to_rpm,
                        end_rpm=end * to_rpm,
                        jerk_share=seg.jerk_share,
                        process_torque_nm=seg.process_load * to_nm,
                    )
                )
            except DomainError as exc:
                field = {"end_rpm": "speed", "start_rpm": "speed"}.get(exc.field, exc.field)
                raise exc.moved(f"{where}.{field}") from None
            start = end
        try:
            return Motion(segments=tuple(segments), load=axis)
        except DomainError as exc:
            raise _renamed(exc, "cycle") from None


class ProfileCycleIn(StrictModel):
    """A measured profile uploaded before (``POST /profiles``), by its id: sized as the
    segments stored with it, which the stored selection then holds."""

    profile_id: str = Field(
        min_length=1, max_length=36, description="the id `POST /profiles` answered"
    )

    def to_motion(self, speed: float | None, axis: AxisLoad, speed_field: str) -> Motion:
        """Never reached: the service puts the stored segments in its place first."""
        raise InvalidInputError("cycle.profile_id", code="profile_not_resolved")


def _cycle_kind(value: Any) -> str:
    if isinstance(value, dict):
        if "profile_id" in value:
            return "profile"
        return "segments" if "segments" in value else "trapezoid"
    if isinstance(value, ProfileCycleIn):
        return "profile"
    return "segments" if isinstance(value, SegmentsCycleIn) else "trapezoid"


AnyCycleIn = Annotated[
    Annotated[CycleIn, Tag("trapezoid")]
    | Annotated[SegmentsCycleIn, Tag("segments")]
    | Annotated[ProfileCycleIn, Tag("profile")],
    Discriminator(
        _cycle_kind,
        custom_error_type="cycle_form",
        custom_error_message="cycle must be the t_1…t_p pattern, a list of segments or a "
        "profile's id",
    ),
]


ModelName = Annotated[str, Field(min_length=1, max_length=60)]


WORKED_EXAMPLE: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}
"""The chapter's worked example (Table 516.1): the example request of the API documents."""


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

    def to_core(self) -> Application:
        """The application as the core sees it: the chapter's shorthand (T_L, J_L, the
        t_1…t_p pattern) where that is what was sent, else a motion of segments."""
        speed, speed_field = _load_speed(self.load)
        options: dict[str, Any] = {
            "high_dynamics": self.high_dynamics,
            "brake": self.brake,
            "drive": self.drive,
            "output_load": output_load_core(self.output_load),
            "thermal_time_constant_s": self.thermal_time_constant_s,
        }
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


class ResolvedLoad(ResponseModel):
    """The load at the output after a mechanism's conversion (Eq. 515.4/515.6)."""

    speed_rpm: float = Field(description="n_2: the cycle's highest |speed| at the output [rpm]")
    torque_nm: float = Field(description="T_L: friction, opposing the motion [Nm]")
    inertia_kgm2: float = Field(description="J_L at the output [kgm²]")
    gravity_torque_nm: float = Field(description="T_G: acts at standstill too, signed [Nm]")
    efficiency: float = Field(description="η between actuator and load")


class CheckBrief(ResponseModel):
    """One check of a candidate in a selection's answer: its outcome and its numbers.

    Unit and reference are the rule's (``check_rules``); the margin is
    ``(limit − value)/limit · 100``; the message in words is in the candidate's detail
    (GET /selections/{id}/candidates/{model}).
    """

    name: str
    status: Literal["pass", "fail", "warn", "no_data"]
    value: float | None
    limit: float | None
    approximate: bool = Field(
        default=False,
        description="true when a simplified limit stood in for the zone; omitted when false",
    )
    missing: str | None = Field(
        default=None,
        description="the catalogue value that is missing: for no_data, what the check needs; "
        "for a fail, the value is its least over every value of what is missing (it fails "
        "whatever that value is); omitted otherwise",
    )


class CheckRuleOut(ResponseModel):
    """What a check compares, once per selection: its reference and unit."""

    name: str
    reference: str = Field(description="the chapter's equation, table or figure")
    unit: str = Field(description="unit of the check's value and limit")


class ControllerRef(ResponseModel):
    """A row of Table 521.1 that a candidate's drive options refer to by its index."""

    manufacturer: str
    type: str
    variant: str | None
    source_row: int | None


class VoltageBrief(ResponseModel):
    """The controller output-voltage check (Eq. 521.2) at n_2, for a group of controllers."""

    status: Literal["pass", "fail", "warn", "no_data"]
    value: float | None = Field(description="U_OUT needed at n_2 [V_rms]")
    limit: float | None = Field(description="U_OUT the best shared DC bus gives [V_rms]")
    reference: str = Field(description="Eq. 521.2 and the bus class compared with")


class DriveOptionGroup(ResponseModel):
    """Controllers not excluded for a candidate that match it alike and share one voltage check."""

    level: Literal["tested", "possible", "unconfirmed"] = Field(
        description="tested: every criterion of Table 521.1 practically tested; possible: "
        "some only theoretically; unconfirmed: nothing excludes them but the actuator lacks data"
    )
    missing: list[str] = Field(description="criteria the actuator has no data for")
    controllers: list[int] = Field(description="indexes into the selection's `controllers`")
    voltage: VoltageBrief


class CandidateFigures(ResponseModel):
    """What every form of a candidate states first: the actuator, its verdict, its torques."""

    model: str
    family: str
    gear_ratio: float
    verdict: Literal["suitable", "unconfirmed", "unsuitable"]
    accel_torque_nm: float | None = Field(description="T_1 (Eq. 514.1) [Nm]")
    constant_torque_nm: float | None = Field(description="T_2 = T_L [Nm]")
    decel_torque_nm: float | None = Field(description="T_3, usually negative [Nm]")
    rms_torque_nm: float | None = Field(description="T_rms (Eq. 514.2) [Nm]")


class CandidateOut(CandidateFigures):
    """The flowchart's result for one actuator, as the ranking lists it."""

    checks: list[CheckBrief]
    controllers_excluded: int = Field(description="how many controllers Table 521.1 excludes")
    drive_options: list[DriveOptionGroup] | None = Field(
        description="controllers of Table 521.1 not excluded for this actuator, best first, "
        "grouped by match and voltage check; null for an unsuitable candidate (its detail "
        "lists them)"
    )


class SegmentTorqueOut(ResponseModel):
    """The torque along one segment of the cycle, for the cycle chart: the torque at each
    end of its pieces (straight between them), at times from the cycle's start."""

    segment: int = Field(description="index of the segment (the trapezoid: t_1, t_2, t_3, t_p)")
    times_s: list[float]
    torques_nm: list[float]


class SegmentOut(ResponseModel):
    """One segment of the cycle at the actuator output."""

    start_s: float = Field(description="time from the cycle's start [s]")
    duration_s: float
    start_rpm: float = Field(description="output speed at the start, signed [rpm]")
    end_rpm: float = Field(description="output speed at the end, signed [rpm]")
    jerk_share: float
    process_torque_nm: float


class CandidateDetailOut(CandidateFigures):
    """One candidate of a stored selection in full: every check in words, every controller
    of Table 521.1 with its criteria and voltage check, and the actuator's catalogue data."""

    selection_id: str
    catalogue_version: int
    reasons: list[str] = Field(description="messages of the checks that did not pass")
    checks: list[CheckOut]
    controllers: list[DriveOptionOut] = Field(
        description="controllers of Table 521.1 not excluded for this actuator, best first, "
        "each with its output-voltage check (Eq. 521.2) at n_2"
    )
    controllers_excluded: int = Field(description="how many controllers Table 521.1 excludes")
    controllers_note: str = Field(
        description="what the controller list rests on, in the answer's language"
    )
    controllers_note_code: str | None = Field(
        default=None,
        description="stable code of `controllers_note` (`controllers_note.unconfirmed`, …)",
    )
    controllers_note_params: dict[str, Any] | None = Field(
        default=None,
        description="the values `controllers_note` names: `count`, `excluded`, `missing` "
        "(the criteria without data, in English words)",
    )
    actuator: ActuatorOut = Field(description="the catalogue entry, as GET /actuators/{model}")
    segment_torques: list[SegmentTorqueOut] = Field(
        default_factory=list,
        description="the torque along each segment with this actuator's J_A (empty without J_A)",
    )


RANKING_RULE = (
    "suitable first, then unconfirmed, then unsuitable; the unsuitable nearest miss first "
    "(smallest worst overload, the largest value/limit of its failed checks); then the "
    "smallest actuator first (lowest T_max, then lowest J_A, then model name)"
)


class BindingCheckOut(ResponseModel):
    """One check that fails for some candidates when none is suitable, and its nearest miss."""

    name: str = Field(description="the check, as a candidate's `checks` name it")
    failing: int = Field(description="how many candidates fail it")
    value: float | None = Field(description="the nearest miss's value (unit: `check_rules`)")
    limit: float | None = Field(
        description="the nearest miss's limit: of the failing candidates, the one with the "
        "smallest value/limit (for max_speed: the largest n_max)"
    )
    model: str = Field(description="the candidate with the nearest miss")


class BindingChangeOut(ResponseModel):
    """What the inverse solve says of a longer t_1 or pause for the nearest miss."""

    quantity: Literal["accel_s", "pause_s"]
    model: str = Field(description="the nearest miss: the first candidate")
    value: float | None = Field(
        description="the shortest t_1 or pause with which no check of `model` fails; null "
        "where none does (see `reason_code`, as POST /selections/limits words it)"
    )
    unit: str
    limiting_checks: list[str] = Field(
        description="the checks that fail just short of `value`, or at every value"
    )
    reason_code: str | None = Field(description="why `value` is null: a limit's reason_code")


class BindingTransmissionOut(ResponseModel):
    """Where the load's own lead or diameter makes an actuator fit (the ratio study,
    POST /selections/ratio-study, over the variable's default range widened 10× both ways)."""

    variable: str = Field(description="the load's field, e.g. lead_mm")
    unit: str
    model: str
    low: float = Field(description="the interval of the variable that holds `best`")
    high: float
    best: float = Field(description="the value of least binding utilisation")
    best_utilisation: float


class BindingOut(ResponseModel):
    """What binds across the catalogue when no candidate is suitable or unconfirmed."""

    candidates: int = Field(description="how many candidates were sized")
    checks: list[BindingCheckOut] = Field(
        description="each check that fails for some candidate, the most failed first"
    )
    changes: list[BindingChangeOut] = Field(
        description="a longer t_1 and a longer pause for the nearest miss (no pause where the "
        "cycle does not end at standstill)"
    )
    transmissions: list[BindingTransmissionOut] = Field(
        default_factory=list,
        description="the load's own lead or diameter: the best few actuators that fit at "
        "some value of it, with its interval and best value (empty: none, the load has no "
        "such value, or a batch's case: not searched there)",
    )


class SelectionOut(ResponseModel):
    """A stored selection: the load case, cycle figures and the ranked candidates."""

    id: str
    created_at: datetime
    catalogue_version: int = Field(description="version of the catalogue the selection used")
    load: ResolvedLoad
    mechanism: dict[str, Any] | None = Field(description="the mechanism as sent, if any")
    cycle: AnyCycleIn
    high_dynamics: bool
    brake: bool = Field(default=False, description="whether a holding brake is fitted")
    drive: bool = Field(default=False, description="whether the drive was sized too")
    output_load: OutputLoadIn | None = Field(default=None, description="as sent, if any")
    output_bearing: str = Field(
        default="",
        description="whether the output bearing was checked, in English (a stored answer is "
        "the same in every language): word it by `output_bearing_code`",
    )
    output_bearing_code: str | None = Field(
        default=None,
        description="the code of `output_bearing`: output_bearing.not_checked, "
        "output_bearing.no_life or output_bearing.checked",
    )
    models: list[str] | None = Field(
        default=None, description="the catalogue restriction as sent; null = whole catalogue"
    )
    segments: list[SegmentOut] = Field(
        default_factory=list,
        description="the cycle at the actuator output, segment by segment (the trapezoid: "
        "t_1, t_2, t_3, t_p)",
    )
    cycle_time_s: float = Field(
        description="t_0 = t_1 + t_2 + t_3 + t_p, the sum of the segments [s]"
    )
    mean_speed_rpm: float = Field(description="n_av (Eq. 514.3) [rpm]")
    duty_cycle_percent: float = Field(description="ED (Eq. 514.4) [%]")
    ranking: str = Field(default=RANKING_RULE, description="how candidates are ordered")
    check_rules: list[CheckRuleOut] = Field(
        description="reference and unit of each check the candidates list, in their order"
    )
    controllers: list[ControllerRef] = Field(
        description="the rows of Table 521.1 that the candidates' drive options refer to"
    )
    candidates: list[CandidateOut]
    binding: BindingOut | None = Field(
        default=None,
        description="what binds across the catalogue when every candidate is unsuitable; "
        "null otherwise (and in answers stored before it existed)",
    )
