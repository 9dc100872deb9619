"""The ratio study's contract (issue 31 part 1): a load case with one free transmission
value, and per actuator the values for which every check passes."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import ConfigDict, Field, model_validator

from actuator_selection.schemas.common import ResponseModel, StrictModel
from actuator_selection.schemas.selections import SelectionRequest

Variable = Literal[
    "ratio",
    "lead_mm",
    "pulley_diameter_mm",
    "pinion_diameter_mm",
    "drum_diameter_mm",
    "roller_diameter_mm",
]

DEFAULT_RANGE: dict[str, tuple[float, float]] = {
    "ratio": (1.0, 20.0),
    "lead_mm": (5.0, 50.0),
    "pulley_diameter_mm": (20.0, 200.0),
    "pinion_diameter_mm": (20.0, 200.0),
    "drum_diameter_mm": (20.0, 200.0),
    "roller_diameter_mm": (20.0, 200.0),
}
"""The range searched where the request gives none."""

UNITS: dict[str, str] = {"ratio": "-"} | {k: "mm" for k in DEFAULT_RANGE if k != "ratio"}

MAX_VALUE = 10_000.0
"""The largest bound of any free value (a ratio of 10 000:1, a 10 m diameter)."""


class RatioStudyIn(StrictModel):
    """The free transmission value and where to look for it."""

    variable: Variable = Field(
        description="ratio: an external gear ratio i between the actuator and the load (in "
        "series with any transmission the mechanism has); otherwise the mechanism's own "
        "lead or diameter [mm], which the load must have"
    )
    min: float | None = Field(
        default=None, gt=0, le=MAX_VALUE, description="lower end; omitted: 1, 5 mm or 20 mm"
    )
    max: float | None = Field(
        default=None, gt=0, le=MAX_VALUE, description="upper end; omitted: 20, 50 mm or 200 mm"
    )
    series: list[float] | None = Field(
        default=None,
        min_length=1,
        max_length=200,
        description="a standard series (e.g. the leads 2, 4, 5, 10, 16, 20, 25, 32, 40, 50 "
        "mm): only these values are checked",
    )
    transmission_inertia_kgm2: float = Field(
        default=0.0, ge=0, le=1e6, description="J_tr of the external ratio, actuator side"
    )
    transmission_efficiency: float = Field(
        default=1.0, ge=0.01, le=1, description="η_tr of the external ratio"
    )
    curves: int = Field(
        default=5, ge=0, le=20, description="how many of the best actuators carry their curve"
    )

    @model_validator(mode="after")
    def _ordered(self) -> RatioStudyIn:
        low, high = self.bounds
        if not low < high:
            raise ValueError("min must be below max")
        return self

    @property
    def bounds(self) -> tuple[float, float]:
        low, high = DEFAULT_RANGE[self.variable]
        return (low if self.min is None else self.min, high if self.max is None else self.max)


class RatioStudyRequest(SelectionRequest):
    """A load case and its free transmission value (``models`` restricts the catalogue)."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "load": {
                        "type": "ball_screw_incline",
                        "mass_kg": 25.0,
                        "lead_mm": 10.0,
                        "friction_coefficient": 0.1,
                        "efficiency": 0.9,
                        "incline_deg": 90,
                        "speed": 300,
                    },
                    "cycle": {"accel_s": 0.1, "constant_s": 0.3, "decel_s": 0.1, "pause_s": 0.5},
                    "ratio_study": {"variable": "lead_mm", "min": 1, "max": 50},
                }
            ]
        }
    )

    ratio_study: RatioStudyIn


class IntervalOut(ResponseModel):
    """A range of the free value in which no check fails."""

    low: float
    high: float
    low_binding: list[str] = Field(
        description="the checks failing just below `low` (empty: the range's end)"
    )
    high_binding: list[str] = Field(
        description="the checks failing just above `high` (empty: the range's end)"
    )


class CurveOut(ResponseModel):
    """The binding utilisation (max value/limit over the checks) at each grid value."""

    values: list[float]
    utilisation: list[float | None]


class RatioActuatorOut(ResponseModel):
    model: str
    intervals: list[IntervalOut]
    best: float | None = Field(description="the value of least binding utilisation that fits")
    best_utilisation: float | None
    best_binding: str | None = Field(description="the check of the largest utilisation there")
    verdict: Literal["suitable", "unconfirmed", "unsuitable"] | None = Field(
        description="the flowchart's verdict at `best`"
    )
    curve: CurveOut | None = Field(description="for the best actuators only")


class RatioStudyOut(ResponseModel):
    """Per actuator, where the free value makes every check pass; those that fit somewhere
    first, by their best utilisation."""

    catalogue_version: int
    variable: Variable
    unit: str
    min: float
    max: float
    series: list[float] | None
    total_actuators: int = Field(description="the actuators studied")
    fitting_actuators: int = Field(
        description="those that fit at some value of the range (or the series)"
    )
    actuators: list[RatioActuatorOut] = Field(
        description="the ranking's first `top` (query): those with a best value first, by "
        "their best utilisation, then by model"
    )
    figure: dict[str, Any] | None = Field(
        default=None,
        description="with `figure=true`: the chart as a plotly figure (`data` and `layout`, "
        "JSON) in the document's language: the utilisation against the free value of the "
        "actuators with a curve, their feasible intervals shaded",
    )
