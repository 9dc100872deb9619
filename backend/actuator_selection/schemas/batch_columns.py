"""The bulk batch contract: load cases of the chapter's shorthand as columns, answered
as columns (POST /selections/batch/columns).

A planning run that sizes thousands of axes holds them as a table: one column per
figure of Table 516.1. Sent as such, a request is a few JSON arrays of numbers, and
its answer a table of candidates (a row per candidate, each row naming its case)
that a dataframe reads as it comes, with no words written per candidate and each
model's drive-option summary listed once. The fields keep the names and meanings of
the per-case batch (``schemas/batch.py``); what it has beyond the shorthand (load
mechanisms, segment cycles, a brake, an output load, ``models`` per case, storing)
stays there.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import ConfigDict, Field

from actuator_selection.schemas.batch import MAX_BATCH_CASES, MAX_TOP, CaseId
from actuator_selection.schemas.checks import CheckStatus
from actuator_selection.schemas.common import (
    MAX_INERTIA_KGM2,
    MAX_SPEED_RPM,
    MAX_TIME_S,
    MAX_TORQUE_NM,
    MIN_RAMP_S,
    ResponseModel,
    StrictModel,
)
from actuator_selection.schemas.selections import RANKING_RULE, ModelName

_Speed = Annotated[float, Field(gt=0, le=MAX_SPEED_RPM)]
_Ramp = Annotated[float, Field(ge=MIN_RAMP_S, le=MAX_TIME_S)]
_Duration = Annotated[float, Field(ge=0, le=MAX_TIME_S)]
_Torque = Annotated[float, Field(ge=0, le=MAX_TORQUE_NM)]
_Inertia = Annotated[float, Field(ge=0, le=MAX_INERTIA_KGM2)]


def _column(what: str) -> Any:
    return Field(
        min_length=1,
        max_length=MAX_BATCH_CASES,
        description=f"{what}, one value per load case; every column as long as `speed_rpm` "
        f"(at most {MAX_BATCH_CASES} cases)",
    )


COLUMNS_EXAMPLE: dict[str, Any] = {
    "speed_rpm": [40, 60],
    "torque_nm": [5, 12],
    "inertia_kgm2": [1.3, 0.4],
    "accel_s": [0.1, 0.2],
    "constant_s": [0.1, 0.5],
    "decel_s": [0.1, 0.2],
    "pause_s": [1.0, 0.5],
    "top": 3,
    "include_checks": False,
}
"""The chapter's worked example (Table 516.1) and a second case."""


class BatchColumnsRequest(StrictModel):
    """Load cases of the chapter's shorthand (T_L, J_L and the t_1…t_p cycle at n_2, at the
    actuator output) as columns: case i is the i-th value of every column."""

    model_config = ConfigDict(json_schema_extra={"examples": [COLUMNS_EXAMPLE]})

    speed_rpm: list[_Speed] = _column("n_2, load speed at the output [rpm], > 0")
    torque_nm: list[_Torque] = _column("T_L, load torque opposing the motion [Nm], ≥ 0")
    inertia_kgm2: list[_Inertia] = _column("J_L, load moment of inertia [kgm²], ≥ 0")
    accel_s: list[_Ramp] = _column("t_1, acceleration time [s], > 0")
    constant_s: list[_Duration] = _column("t_2, time at speed n_2 [s]")
    decel_s: list[_Ramp] = _column("t_3, deceleration time [s], > 0")
    pause_s: list[_Duration] = _column("t_p, standstill [s]")
    high_dynamics: bool | list[bool] = Field(
        default=True,
        description="J_L ≤ 3·J_A is binding (fail) when true, a warning otherwise: one value "
        "for every case, or one per case",
    )
    models: list[ModelName] | None = Field(
        default=None,
        min_length=1,
        max_length=1000,
        description="the actuators every case may use; null = the whole catalogue",
    )
    thermal_time_constant_s: float | None = Field(
        default=None,
        gt=0,
        le=MAX_TIME_S,
        description="the winding's thermal time constant τ_th [s] where the catalogue gives "
        "none, for every case (check `thermal_peak`); omitted: 600 s, assumed",
    )
    top: int = Field(
        default=3,
        ge=1,
        le=MAX_TOP,
        description="best candidates answered per case; cases × top ≤ 60,000",
    )
    include_checks: bool = Field(
        default=True, description="false leaves `checks` out (null): verdicts and torques only"
    )
    case_id: list[CaseId] | None = Field(
        default=None,
        max_length=MAX_BATCH_CASES,
        description="the client's own id of each case (an order position, say), as long as "
        "`speed_rpm`; answered as `cases.case_id`",
    )


class CaseColumns(ResponseModel):
    """Each case's cycle figures, in the order of the cases sent."""

    case_id: list[str] | None = Field(description="the `case_id` column as sent, else null")
    cycle_time_s: list[float] = Field(description="t_0 = t_1 + t_2 + t_3 + t_p [s]")
    mean_speed_rpm: list[float] = Field(description="n_av (Eq. 514.3) [rpm]")
    duty_cycle_percent: list[float] = Field(description="ED (Eq. 514.4) [%]")


class CandidateColumns(ResponseModel):
    """The candidates as a table, a row per candidate: the cases in order, each case's best
    `top` best first (fewer where the catalogue has fewer actuators)."""

    case: list[int] = Field(description="the candidate's case: its index in the columns sent")
    model: list[str] = Field(description="the actuator (its family and drive in `models`)")
    verdict: list[Literal["suitable", "unconfirmed", "unsuitable"]]
    accel_torque_nm: list[float | None] = Field(description="T_1 (Eq. 514.1) [Nm]")
    constant_torque_nm: list[float | None] = Field(description="T_2 = T_L [Nm]")
    decel_torque_nm: list[float | None] = Field(description="T_3, usually negative [Nm]")
    rms_torque_nm: list[float | None] = Field(description="T_rms (Eq. 514.2) [Nm]")


class CheckColumns(ResponseModel):
    """One check of every candidate, row for row with `candidates` (a single selection's
    `checks` entry of that name, as columns)."""

    name: str
    reference: str = Field(description="the chapter's equation, table or figure")
    unit: str = Field(description="unit of the check's value and limit")
    status: list[CheckStatus]
    value: list[float | None]
    limit: list[float | None]
    approximate: list[bool] = Field(
        description="true where a simplified limit stood in for the zone"
    )
    missing: list[str | None] = Field(
        description="the catalogue value that is missing: for no_data, what the check needs; "
        "for a fail, the value is its least over every value of what is missing; else null"
    )


class ModelColumns(ResponseModel):
    """What a candidate's model is, once per model answered: the per-case batch gives
    the same fields on every candidate."""

    model: list[str]
    family: list[str]
    gear_ratio: list[float]
    controllers_excluded: list[int] = Field(description="how many controllers Table 521.1 excludes")
    controllers_note: list[str] = Field(description="what the controller list rests on")
    controllers_note_code: list[str | None] = Field(description="stable code of the note")
    controllers_note_params: list[dict[str, Any] | None] = Field(
        description="the values the note names"
    )


class BatchColumnsOut(ResponseModel):
    """The best candidates of every case, as tables."""

    catalogue_version: int = Field(description="version of the catalogue the batch used")
    ranking: str = Field(default=RANKING_RULE, description="how candidates are ordered")
    cases: CaseColumns
    candidates: CandidateColumns
    checks: list[CheckColumns] | None = Field(
        description="each check of the flowchart, in its order; null unless include_checks"
    )
    models: ModelColumns = Field(description="the models the candidates name, each once")
