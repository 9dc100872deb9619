"""A selection's answer: the candidates, their checks and figures, the binding check."""

from __future__ import annotations

from datetime import datetime
from typing import Any, Literal

from pydantic import Field

from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.checks import CheckOut, CheckStatus
from actuator_selection.schemas.common import (
    ResponseModel,
)
from actuator_selection.schemas.controllers import (
    DriveOptionOut,
)
from actuator_selection.schemas.output_load import (
    OutputLoadIn,
)
from actuator_selection.schemas.selections.cycles import AnyCycleIn


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
    status: CheckStatus
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


class VerdictCounts(ResponseModel):
    """How many candidates of a whole ranking have each verdict."""

    suitable: int
    unconfirmed: int
    unsuitable: int


class CandidatePageOut(ResponseModel):
    """A page of a stored selection's ranking (GET /selections/{id}/candidates)."""

    selection_id: str
    start: int = Field(description="the place of the first candidate in the ranking (0: the best)")
    total_candidates: int = Field(description="how many candidates the whole ranking holds")
    candidates: list[CandidateOut] = Field(
        description="best first; drive options are listed only for candidates that the "
        "selection's own answer lists (elsewhere null: the candidate's detail lists them)"
    )
    next_cursor: str | None = Field(description="reads on after this page; null: the last page")


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
    candidates: list[CandidateOut] = Field(
        description="the ranking's first candidates, best first: as many as `top` asked "
        "(POST /selections?top=, default 25), or all where fewer; the rest are read by "
        "`next_cursor` (GET /selections/{id}/candidates)"
    )
    total_candidates: int = Field(description="how many candidates the whole ranking holds")
    verdict_counts: VerdictCounts = Field(description="the whole ranking's candidates by verdict")
    next_cursor: str | None = Field(
        description="reads the ranking on after `candidates` (GET /selections/{id}/candidates"
        "?cursor=); null: `candidates` is the whole ranking"
    )
    binding: BindingOut | None = Field(
        default=None,
        description="what binds across the catalogue when every candidate is unsuitable; "
        "null otherwise (and in answers stored before it existed)",
    )
