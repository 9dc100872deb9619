"""Mechanisms as a request gives them (issue "Real axes"): belt, rack and pinion, conveyor,
lift, an inclined or vertical ball screw, a rotary load, each with an optional
transmission ratio between the actuator output and the mechanism.

Lengths are in millimetres, linear speeds in mm/s, masses in kg, inertias in kgm², angles
in degrees and forces in N as numbers; any of them may also be text with a unit
(``"0.5 in"``, ``"12 in/s"``, ``"22 lb"``, ``"3 lb*in^2"``; ``schemas.quantities``).
:meth:`~_MechanismIn.to_axis` converts to SI once and resolves the mechanism in the core
(``sizing.mechanisms``); a core error names the request's field under the path given.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal, get_args

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
from actuator_selection.schemas.quantities import (
    ANGLE_DEG,
    FORCE_N,
    INERTIA_KGM2,
    LENGTH_MM,
    LINEAR_SPEED_MM_PER_S,
    MASS_KG,
    ROTARY_SPEED_RPM,
    TORQUE_NM,
    InUnit,
)
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.mechanisms import (
    MAX_INCLINE_DEG,
    MM_PER_M,
    BeltDrive,
    Conveyor,
    Hoist,
    InclinedBallScrew,
    RackPinion,
    Transmission,
    belt_axis,
    conveyor_axis,
    hoist_axis,
    inclined_ball_screw_axis,
    mm_to_m,
    rack_pinion_axis,
    with_transmission,
)

MIN_LENGTH_MM = MIN_LENGTH_M * MM_PER_M
"""Smallest lead or diameter [mm]: ``MIN_LENGTH_M`` (1 µm) in mm."""
MAX_LENGTH_MM = MAX_LENGTH_M * MM_PER_M
"""Largest lead or diameter [mm]: ``MAX_LENGTH_M`` (100 m) in mm."""
MAX_LINEAR_SPEED_MM_PER_S = 100_000.0
"""Load speed bound of a linear axis [mm/s]: 100 m/s, ten times the fastest linear motor
or belt axis."""
MAX_FORCE_N = 10_000_000.0
"""Force bound [N]: the weight of ``MAX_MASS_KG`` (1000 t) and then some."""
MIN_RATIO = 0.001
"""Smallest transmission ratio i [-]: a 1:1000 step-up."""
MAX_RATIO = 10_000.0
"""Largest transmission ratio i [-]: 10 000:1, beyond any reduction put ahead of an actuator
whose Harmonic Drive gear already reduces 30–160:1."""

Mass = Annotated[float, Field(ge=0, le=MAX_MASS_KG), InUnit(MASS_KG)]
Length = Annotated[float, Field(ge=MIN_LENGTH_MM, le=MAX_LENGTH_MM), InUnit(LENGTH_MM)]
Inertia = Annotated[float, Field(ge=0, le=MAX_INERTIA_KGM2), InUnit(INERTIA_KGM2)]
Incline = Annotated[float, Field(ge=-MAX_INCLINE_DEG, le=MAX_INCLINE_DEG), InUnit(ANGLE_DEG)]
FrictionForce = Annotated[float, Field(ge=0, le=MAX_FORCE_N), InUnit(FORCE_N)]
LinearSpeed = Annotated[
    float, Field(gt=0, le=MAX_LINEAR_SPEED_MM_PER_S), InUnit(LINEAR_SPEED_MM_PER_S)
]
RotarySpeed = Annotated[float, Field(gt=0, le=MAX_SPEED_RPM), InUnit(ROTARY_SPEED_RPM)]
Friction = Annotated[
    float, Field(ge=0, le=MAX_FRICTION_COEFFICIENT, description="coefficient of friction μ [-]")
]
Efficiency = Annotated[float, Field(ge=MIN_EFFICIENCY, le=1, description="η [-], 0.01 ≤ η ≤ 1")]

_LINEAR_SPEED = (
    "load speed v for the trapezoid shorthand [mm/s] (n_2 = v × the axis's rpm per mm/s); "
    "omit it where a segment cycle gives the speeds"
)


def _request_field(core_field: str) -> str:
    """The request's name of a core input: lengths come in mm (``lead_m`` → ``lead_mm``)."""
    return f"{core_field}m" if core_field.endswith("_m") else core_field


def _renamed(exc: DomainError, prefix: str) -> DomainError:
    """``exc`` naming the request's field under ``prefix`` (``lead_m`` → ``load.lead_mm``)."""
    return exc.moved(f"{prefix}.{_request_field(exc.field)}")


class TransmissionIn(StrictModel):
    """A gearbox or belt reduction between the actuator output and the mechanism."""

    ratio: float = Field(
        ge=MIN_RATIO,
        le=MAX_RATIO,
        description="i [-]: actuator output speed over mechanism shaft speed (i > 1 reduces)",
        json_schema_extra=shown("i", "mech.tr.ratio"),
    )
    inertia_kgm2: Inertia = Field(
        default=0.0,
        description="J_tr, its moment of inertia at the actuator side [kgm²]",
        json_schema_extra=shown("J_tr", "mech.tr.inertia"),
    )
    efficiency: Efficiency = Field(
        default=1.0, description="η_tr [-]", json_schema_extra=shown("η_tr", "mech.tr.efficiency")
    )

    def to_core(self) -> Transmission:
        """The transmission as the core sees it."""
        return Transmission(
            ratio=self.ratio, inertia_kgm2=self.inertia_kgm2, efficiency=self.efficiency
        )


class _MechanismIn(StrictModel):
    """A mechanism as sent; :meth:`to_axis` resolves it at the actuator output."""

    transmission: TransmissionIn | None = Field(
        default=None, description="a ratio between the actuator output and the mechanism"
    )

    def to_axis(self, *, at: str = "load") -> AxisLoad:
        """The mechanism at the actuator output, through its transmission if it has one.

        A core error names its field as the request has it, under ``at`` (the mechanism's
        place in the request body), e.g. ``load.pulley_diameter_mm`` or
        ``load.transmission.ratio``.
        """
        try:
            axis = self._axis()
        except DomainError as exc:
            raise _renamed(exc, at) from None
        if self.transmission is None:
            return axis
        try:
            return with_transmission(axis, self.transmission.to_core())
        except DomainError as exc:
            raise _renamed(exc, f"{at}.transmission") from None

    def _axis(self) -> AxisLoad:
        raise NotImplementedError


class BallScrewInclineIn(_MechanismIn):
    """A ball screw at any incline, vertical included (``sizing.mechanisms``: r = P/2π)."""

    type: Literal["ball_screw_incline"]
    speed: LinearSpeed | None = Field(default=None, description=_LINEAR_SPEED)
    mass_kg: Mass = Field(
        description="moved mass m [kg]", json_schema_extra=shown("m", "mech.mass")
    )
    lead_mm: Length = Field(
        description="screw lead P [mm per revolution]", json_schema_extra=shown("P", "load.lead")
    )
    friction_coefficient: Friction = Field(json_schema_extra=shown("μ", "load.friction"))
    efficiency: Efficiency = Field(
        description="screw efficiency η [-], by power flow",
        json_schema_extra=shown("η", "load.efficiency"),
    )
    incline_deg: Incline = Field(
        default=0.0,
        description="θ [°]: 0 horizontal, 90 vertical (positive motion lifts)",
        json_schema_extra=shown("θ", "mech.incline"),
    )
    screw_inertia_kgm2: Inertia = Field(
        default=0.0, description="J_S [kgm²]", json_schema_extra=shown("J_S", "load.screw_inertia")
    )
    counterweight_kg: Mass = Field(
        default=0.0,
        description="m_c [kg], on a rope over a pulley",
        json_schema_extra=shown("m_c", "mech.counterweight"),
    )
    friction_force_n: FrictionForce = Field(
        default=0.0,
        description="friction force independent of the weight [N]",
        json_schema_extra=shown("F_R", "mech.friction_force"),
    )

    def screw(self) -> InclinedBallScrew:
        """The screw as the core sees it (its lead in m)."""
        return InclinedBallScrew(
            mass_kg=self.mass_kg,
            lead_m=mm_to_m(self.lead_mm),
            friction_coefficient=self.friction_coefficient,
            efficiency=self.efficiency,
            incline_deg=self.incline_deg,
            screw_inertia_kgm2=self.screw_inertia_kgm2,
            counterweight_kg=self.counterweight_kg,
            friction_force_n=self.friction_force_n,
        )

    def _axis(self) -> AxisLoad:
        return inclined_ball_screw_axis(self.screw())


class BeltIn(_MechanismIn):
    """A linear axis on a timing belt, e.g. a vertical pick-and-place axis (θ = 90°)."""

    type: Literal["belt"]
    speed: LinearSpeed | None = Field(default=None, description=_LINEAR_SPEED)
    mass_kg: Mass = Field(
        description="moved mass m (carriage and payload) [kg]",
        json_schema_extra=shown("m", "mech.mass"),
    )
    pulley_diameter_mm: Length = Field(
        description="pitch diameter D of the drive pulley [mm]",
        json_schema_extra=shown("D", "mech.pulley_diameter"),
    )
    friction_coefficient: Friction = Field(json_schema_extra=shown("μ", "load.friction"))
    efficiency: Efficiency = Field(
        description="belt drive efficiency η [-], by power flow",
        json_schema_extra=shown("η", "load.efficiency"),
    )
    incline_deg: Incline = Field(
        default=0.0,
        description="θ [°]: 0 horizontal, 90 vertical (positive motion lifts)",
        json_schema_extra=shown("θ", "mech.incline"),
    )
    belt_mass_kg: Mass = Field(
        default=0.0,
        description="m_B, the whole belt [kg]",
        json_schema_extra=shown("m_B", "mech.belt_mass"),
    )
    pulley_inertia_kgm2: Inertia = Field(
        default=0.0,
        description="J_D, drive pulley [kgm²]",
        json_schema_extra=shown("J_D", "mech.pulley_inertia"),
    )
    idler_inertia_kgm2: Inertia = Field(
        default=0.0,
        description="J_I, idler pulley [kgm²]",
        json_schema_extra=shown("J_I", "mech.idler_inertia"),
    )
    idler_diameter_mm: Length | None = Field(
        default=None,
        description="D_I [mm]; omitted: the drive pulley's",
        json_schema_extra=shown("D_I", "mech.idler_diameter"),
    )
    counterweight_kg: Mass = Field(
        default=0.0,
        description="m_c [kg], on a rope over a pulley",
        json_schema_extra=shown("m_c", "mech.counterweight"),
    )
    friction_force_n: FrictionForce = Field(
        default=0.0,
        description="friction force independent of the weight [N]",
        json_schema_extra=shown("F_R", "mech.friction_force"),
    )

    def belt(self) -> BeltDrive:
        """The belt drive as the core sees it (its lengths in m)."""
        return BeltDrive(
            mass_kg=self.mass_kg,
            pulley_diameter_m=mm_to_m(self.pulley_diameter_mm),
            friction_coefficient=self.friction_coefficient,
            efficiency=self.efficiency,
            incline_deg=self.incline_deg,
            belt_mass_kg=self.belt_mass_kg,
            pulley_inertia_kgm2=self.pulley_inertia_kgm2,
            idler_inertia_kgm2=self.idler_inertia_kgm2,
            idler_diameter_m=None
            if self.idler_diameter_mm is None
            else mm_to_m(self.idler_diameter_mm),
            counterweight_kg=self.counterweight_kg,
            friction_force_n=self.friction_force_n,
        )

    def _axis(self) -> AxisLoad:
        return belt_axis(self.belt())


class RackPinionIn(_MechanismIn):
    """A linear axis driven by a pinion on a rack."""

    type: Literal["rack_pinion"]
    speed: LinearSpeed | None = Field(default=None, description=_LINEAR_SPEED)
    mass_kg: Mass = Field(
        description="moved mass m [kg]", json_schema_extra=shown("m", "mech.mass")
    )
    pinion_diameter_mm: Length = Field(
        description="pitch diameter d of the pinion [mm]",
        json_schema_extra=shown("d", "mech.pinion_diameter"),
    )
    friction_coefficient: Friction = Field(json_schema_extra=shown("μ", "load.friction"))
    efficiency: Efficiency = Field(
        description="rack and pinion efficiency η [-], by power flow",
        json_schema_extra=shown("η", "load.efficiency"),
    )
    incline_deg: Incline = Field(
        default=0.0,
        description="θ [°]: 0 horizontal, 90 vertical (positive motion lifts)",
        json_schema_extra=shown("θ", "mech.incline"),
    )
    pinion_inertia_kgm2: Inertia = Field(
        default=0.0, description="J_P [kgm²]", json_schema_extra=shown("J_P", "mech.pinion_inertia")
    )
    counterweight_kg: Mass = Field(
        default=0.0,
        description="m_c [kg], on a rope over a pulley",
        json_schema_extra=shown("m_c", "mech.counterweight"),
    )
    friction_force_n: FrictionForce = Field(
        default=0.0,
        description="friction force independent of the weight [N]",
        json_schema_extra=shown("F_R", "mech.friction_force"),
    )

    def rack(self) -> RackPinion:
        """The rack and pinion as the core sees it (its diameter in m)."""
        return RackPinion(
            mass_kg=self.mass_kg,
            pinion_diameter_m=mm_to_m(self.pinion_diameter_mm),
            friction_coefficient=self.friction_coefficient,
            efficiency=self.efficiency,
            incline_deg=self.incline_deg,
            pinion_inertia_kgm2=self.pinion_inertia_kgm2,
            counterweight_kg=self.counterweight_kg,
            friction_force_n=self.friction_force_n,
        )

    def _axis(self) -> AxisLoad:
        return rack_pinion_axis(self.rack())


class ConveyorIn(_MechanismIn):
    """A belt conveyor between a drive roller and a tail roller."""

    type: Literal["conveyor"]
    speed: LinearSpeed | None = Field(default=None, description=_LINEAR_SPEED)
    load_mass_kg: Mass = Field(
        description="m_L, everything on the belt [kg]",
        json_schema_extra=shown("m", "mech.conveyor_load"),
    )
    belt_mass_kg: Mass = Field(
        description="m_B, the whole belt [kg]", json_schema_extra=shown("m_B", "mech.belt_mass")
    )
    roller_diameter_mm: Length = Field(
        description="D, drive roller [mm]", json_schema_extra=shown("D", "mech.roller_diameter")
    )
    friction_coefficient: Friction = Field(
        description="μ [-] between the carrying strand and its bed",
        json_schema_extra=shown("μ", "load.friction"),
    )
    efficiency: Efficiency = Field(
        description="η [-], by power flow", json_schema_extra=shown("η", "load.efficiency")
    )
    incline_deg: Incline = Field(
        default=0.0,
        description="θ [°] (the load is lifted for θ > 0)",
        json_schema_extra=shown("θ", "mech.incline"),
    )
    drive_roller_inertia_kgm2: Inertia = Field(
        default=0.0,
        description="J_D [kgm²]",
        json_schema_extra=shown("J_D", "mech.drive_roller_inertia"),
    )
    tail_roller_inertia_kgm2: Inertia = Field(
        default=0.0,
        description="J_T [kgm²]",
        json_schema_extra=shown("J_T", "mech.tail_roller_inertia"),
    )
    tail_roller_diameter_mm: Length | None = Field(
        default=None,
        description="D_T [mm]; omitted: the drive roller's",
        json_schema_extra=shown("D_T", "mech.tail_roller_diameter"),
    )
    friction_force_n: FrictionForce = Field(
        default=0.0,
        description="friction force independent of the weight [N]",
        json_schema_extra=shown("F_R", "mech.friction_force"),
    )

    def _axis(self) -> AxisLoad:
        return conveyor_axis(
            Conveyor(
                load_mass_kg=self.load_mass_kg,
                belt_mass_kg=self.belt_mass_kg,
                roller_diameter_m=mm_to_m(self.roller_diameter_mm),
                friction_coefficient=self.friction_coefficient,
                efficiency=self.efficiency,
                incline_deg=self.incline_deg,
                drive_roller_inertia_kgm2=self.drive_roller_inertia_kgm2,
                tail_roller_inertia_kgm2=self.tail_roller_inertia_kgm2,
                tail_roller_diameter_m=None
                if self.tail_roller_diameter_mm is None
                else mm_to_m(self.tail_roller_diameter_mm),
                friction_force_n=self.friction_force_n,
            )
        )


class LiftIn(_MechanismIn):
    """A lift or hoist: a load on a rope wound on a drum, perhaps with a counterweight."""

    type: Literal["lift"]
    speed: LinearSpeed | None = Field(default=None, description=_LINEAR_SPEED)
    load_mass_kg: Mass = Field(
        description="m, cage or hook and payload [kg]",
        json_schema_extra=shown("m", "mech.lift_mass"),
    )
    drum_diameter_mm: Length = Field(
        description="D at the rope's centre line [mm]",
        json_schema_extra=shown("D", "mech.drum_diameter"),
    )
    efficiency: Efficiency = Field(
        description="η [-], by power flow", json_schema_extra=shown("η", "load.efficiency")
    )
    counterweight_kg: Mass = Field(
        default=0.0, description="m_c [kg]", json_schema_extra=shown("m_c", "mech.counterweight")
    )
    drum_inertia_kgm2: Inertia = Field(
        default=0.0, description="J_D [kgm²]", json_schema_extra=shown("J_D", "mech.drum_inertia")
    )
    friction_force_n: FrictionForce = Field(
        default=0.0,
        description="friction force of the load's guides [N]",
        json_schema_extra=shown("F_R", "mech.friction_force"),
    )

    def _axis(self) -> AxisLoad:
        return hoist_axis(
            Hoist(
                load_mass_kg=self.load_mass_kg,
                drum_diameter_m=mm_to_m(self.drum_diameter_mm),
                efficiency=self.efficiency,
                counterweight_kg=self.counterweight_kg,
                drum_inertia_kgm2=self.drum_inertia_kgm2,
                friction_force_n=self.friction_force_n,
            )
        )


class RotaryIn(_MechanismIn):
    """A rotary load given by its inertia and torques at the mechanism shaft (e.g. an index
    table behind a gearbox)."""

    type: Literal["rotary"]
    speed: RotarySpeed | None = Field(
        default=None,
        description="load speed for the trapezoid shorthand [rpm]; omit it where a segment "
        "cycle gives the speeds",
    )
    inertia_kgm2: Inertia = Field(
        description="J, moment of inertia of the load [kgm²]",
        json_schema_extra=shown("J", "load.inertia"),
    )
    friction_torque_nm: Annotated[float, Field(ge=0, le=MAX_TORQUE_NM), InUnit(TORQUE_NM)] = Field(
        default=0.0,
        description="T_F, friction opposing the motion [Nm]",
        json_schema_extra=shown("T_F", "mech.friction_torque"),
    )
    gravity_torque_nm: Annotated[
        float, Field(ge=-MAX_TORQUE_NM, le=MAX_TORQUE_NM), InUnit(TORQUE_NM)
    ] = Field(
        default=0.0,
        description="T_G, a torque acting at standstill too (an unbalanced weight) [Nm]; "
        "positive opposes positive rotation",
        json_schema_extra=shown("T_G", "mech.gravity_torque"),
    )
    efficiency: Efficiency = Field(
        default=1.0,
        description="η [-], by power flow",
        json_schema_extra=shown("η", "load.efficiency"),
    )

    def _axis(self) -> AxisLoad:
        return AxisLoad(
            inertia_kgm2=self.inertia_kgm2,
            friction_torque_nm=self.friction_torque_nm,
            gravity_torque_nm=self.gravity_torque_nm,
            efficiency=self.efficiency,
        )


Mechanisms = (
    Annotated[BallScrewInclineIn, Tag("ball_screw_incline")]
    | Annotated[BeltIn, Tag("belt")]
    | Annotated[RackPinionIn, Tag("rack_pinion")]
    | Annotated[ConveyorIn, Tag("conveyor")]
    | Annotated[LiftIn, Tag("lift")]
    | Annotated[RotaryIn, Tag("rotary")]
)
"""Every mechanism, tagged by its ``type``: the one list of them (the request's load union
takes it whole, ``schemas/selections.py``)."""


def union_tags(union: Any) -> tuple[str, ...]:
    """The tags of a union of ``Annotated[Model, Tag(…)]`` members, in its order.

    >>> union_tags(Mechanisms)[:2]
    ('ball_screw_incline', 'belt')
    """
    return tuple(
        next(m.tag for m in member.__metadata__ if isinstance(m, Tag)) for member in get_args(union)
    )


MECHANISM_TYPES = union_tags(Mechanisms)
"""The ``type`` of each mechanism in :data:`MechanismIn`."""


def _mechanism_kind(value: Any) -> str | None:
    kind = value.get("type") if isinstance(value, dict) else getattr(value, "type", None)
    return kind if isinstance(kind, str) else None


MechanismIn = Annotated[
    Mechanisms,
    Discriminator(
        _mechanism_kind,
        custom_error_type="mechanism_type",
        custom_error_message="type must be one of "
        + ", ".join(f"'{kind}'" for kind in MECHANISM_TYPES),
    ),
]
"""A mechanism of any kind, told apart by its ``type``."""
