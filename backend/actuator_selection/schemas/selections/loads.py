"""The load a selection request drives: the direct load, the chapter's ball screw and
rotary table, or a mechanism.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Discriminator, Field, Tag

from actuator_selection.errors import DomainError
from actuator_selection.schemas.common import (
    MAX_FRICTION_COEFFICIENT,
    MAX_INERTIA_KGM2,
    MAX_LENGTH_M,
    MAX_MASS_KG,
    MAX_SPEED_RPM,
    MAX_TORQUE_NM,
    MIN_EFFICIENCY,
    MIN_LENGTH_M,
    StrictModel,
    shown,
)
from actuator_selection.schemas.mechanisms import Mechanisms, _MechanismIn, union_tags
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.cycle import Load
from actuator_selection.sizing.loads import (
    BallScrew,
    RotaryTable,
    ball_screw_load,
    rotary_table_load,
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
        """The load at the output with its friction, weight and losses (``sizing/axis.py``)."""
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
