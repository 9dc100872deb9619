"""The motion profile contract: the upload's query and the answer (docs/profiles.md)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from actuator_selection.schemas.common import ResponseModel, StrictModel
from actuator_selection.schemas.selections import SegmentsCycleIn
from actuator_selection.sizing.sampled import DEFAULT_TOLERANCE

UnitText = str | None


def _unit(role: str, example: str) -> UnitText:
    return Field(
        default=None,
        max_length=40,
        description=f"unit of the {role} column where its heading gives none (pint's "
        f"spelling, e.g. `{example}`)",
    )


class ProfileQuery(StrictModel):
    """How to read a profile file whose headings lack units, and how closely to fit it."""

    time_unit: str = Field(
        default="s", min_length=1, max_length=40, description="unit of the time column"
    )
    position_unit: UnitText = _unit("position", "deg")
    velocity_unit: UnitText = _unit("velocity", "rpm")
    acceleration_unit: UnitText = _unit("acceleration", "rad/s^2")
    load_unit: UnitText = _unit("load (torque or force)", "N*m")
    tolerance_percent: float = Field(
        default=DEFAULT_TOLERANCE * 100,
        gt=0,
        le=10,
        description="deviation allowed between samples and segments, in % of the peak "
        "speed (and of the peak load)",
    )


class ProfileFiguresOut(ResponseModel):
    """Figures of a cycle that do not depend on the actuator, in the profile's units."""

    cycle_time_s: float = Field(description="t_0 [s]")
    mean_speed: float = Field(description="n_av = ∫|v| dt / t_0 (Eq. 514.3)")
    duty_cycle_percent: float = Field(description="ED (Eq. 514.4) [%]")
    peak_speed: float = Field(description="max |v|")
    peak_accel: float = Field(description="max |dv/dt| [speed unit/s]")
    rms_load: float | None = Field(description="RMS of the process load; null without one")
    peak_load: float | None = Field(description="max |load|; null without one")


class ProfileFiguresPair(ResponseModel):
    samples: ProfileFiguresOut = Field(description="of the samples (linear between them)")
    segments: ProfileFiguresOut = Field(description="of the segments the flowchart sizes")


class ProfileFitOut(ResponseModel):
    tolerance_percent: float
    exact: bool = Field(description="the segments lie within the tolerance of every sample")
    speed_deviation: float = Field(description="largest |v_sample − v_segments|")
    load_deviation: float | None = Field(description="largest |L_sample − L_segment|")


class ProfilePreviewOut(ResponseModel):
    time_s: list[float]
    speed: list[float]


class ProfileNoteOut(ResponseModel):
    code: str
    msg: str
    params: dict[str, float | str]


class ProfileOut(ResponseModel):
    """A stored profile: the cycle it sizes (`cycle: {"profile_id": id}` in a selection)."""

    id: str
    created_at: str
    kind: Literal["rotary", "linear"] = Field(
        description="rotary: speeds in rpm and loads in Nm at the actuator output (the "
        "chapter's loads and `rotary`); linear: mm/s and N (the linear mechanisms)"
    )
    speed_unit: str
    load_unit: str
    samples: int = Field(description="rows of samples read")
    columns: dict[str, str] = Field(description="each column read and its heading")
    ignored_columns: list[str]
    from_positions: bool = Field(description="the speeds are the positions' derivative")
    cycle: SegmentsCycleIn = Field(description="the segments, as POST /selections takes them")
    figures: ProfileFiguresPair
    fit: ProfileFitOut
    preview: ProfilePreviewOut = Field(
        description="at most 2000 samples' speeds for the cycle chart"
    )
    notes: list[ProfileNoteOut]
