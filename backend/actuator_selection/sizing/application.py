"""The load case of a selection: :class:`Application`, the motion with its load and what
else is checked (brake, drive, output bearing, τ_th)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Final

from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.bearing import OutputLoad
from actuator_selection.sizing.cycle import Load, SpeedPattern
from actuator_selection.sizing.motion import (
    Motion,
    Profile,
    profile_of,
    trapezoid,
    trapezoid_profile,
)


def require_time_constant(tau: float | None) -> None:
    """Refuse a thermal time constant τ_th (:attr:`Application.thermal_time_constant_s`)
    that is not a finite number > 0."""
    if tau is not None and not (math.isfinite(tau) and tau > 0):
        raise InvalidInputError(
            "thermal_time_constant_s",
            f"must be a finite number > 0: τ_th divides the time in the thermal model, got {tau!r}",
        )


DEFAULT_BRAKE_SAFETY_FACTOR: Final = 1.0
"""S of the brake's holding check (:data:`~actuator_selection.sizing.checks.BRAKE_HOLDING`)
where the application sets none: 1, the catalogue's holding torque as published, and the
answer says that S is the user's choice. No public document read names a default: the
manufacturer's brake tables give the holding torque, the allowable emergency stops and the
closing time (CHA 1018854 12/2015, e.g. Table 36.3;
FHA-C manual §4-2) but no factor, and a search of public standards notes and guidance on
gravity-loaded axes (DGUV/FB HM information on vertical axes, EN 60204-1, ISO 13849)
found no citable text stating one; a factor found in a secondary source only is not a
citation (docs/decisions/0026-brake-drop-and-holding-factor.md)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Application:
    """The load case: the motion (a cycle of segments driving an axis load, or the
    chapter's trapezoid ``pattern`` with its ``load`` as a shorthand), and how dynamic it is.

    Give either ``motion`` or both ``pattern`` and ``load``; :attr:`cycle` is the motion
    either way (:func:`~actuator_selection.sizing.motion.trapezoid` for the shorthand).
    """

    pattern: SpeedPattern | None = None
    load: Load | None = None
    motion: Motion | None = None
    high_dynamics: bool = True
    brake: bool = False
    """Whether the actuator is fitted with its holding brake (checked by
    :data:`~actuator_selection.sizing.checks.BRAKE_HOLDING`)."""
    _profile: list[Profile] = field(
        default_factory=list, init=False, repr=False, compare=False, hash=False
    )
    """The cycle's :class:`~actuator_selection.sizing.motion.Profile`, once computed."""

    def __post_init__(self) -> None:
        if (
            self.motion is None
            and self.pattern is not None
            and self.load is not None
            and self.thermal_time_constant_s is None
            and self.gear_required_life_h is None
            and self.momentary_torque_nm is None
            and self.momentary_count is None
            and self.min_natural_frequency_hz is None
            and self.emergency_stops is None
            and self.brake_safety_factor == DEFAULT_BRAKE_SAFETY_FACTOR
        ):
            return  # the shorthand with every option at its default: each rule below holds
        if self.motion is None and (self.pattern is None or self.load is None):
            raise InvalidInputError("cycle", "needs a motion, or a speed pattern and a load")
        if self.motion is not None and (self.pattern is not None or self.load is not None):
            raise InvalidInputError(
                "cycle", "give segments or the t_1…t_p pattern with its load, not both"
            )
        require_time_constant(self.thermal_time_constant_s)
        for name, value in (
            ("gear_required_life_h", self.gear_required_life_h),
            ("momentary_torque_nm", self.momentary_torque_nm),
            ("momentary_count", self.momentary_count),
            ("min_natural_frequency_hz", self.min_natural_frequency_hz),
            ("emergency_stops", self.emergency_stops),
        ):
            if value is not None and not (math.isfinite(value) and value > 0):
                raise InvalidInputError(name, f"must be a finite number > 0, got {value!r}")
        if not (math.isfinite(self.brake_safety_factor) and self.brake_safety_factor >= 1):
            raise InvalidInputError(
                "brake_safety_factor",
                f"must be a finite number ≥ 1, got {self.brake_safety_factor!r}",
            )
        if self.momentary_torque_nm is not None and self.momentary_count is None:
            raise InvalidInputError("momentary_count", "needed with momentary_torque_nm")

    @property
    def cycle(self) -> Motion:
        """The motion: :attr:`motion`, or the chapter's trapezoid of the shorthand."""
        if self.motion is not None:
            return self.motion
        assert self.pattern is not None
        p = self.pattern
        return trapezoid(
            speed_rpm=p.speed_rpm,
            accel_s=p.accel_s,
            constant_s=p.constant_s,
            decel_s=p.decel_s,
            pause_s=p.pause_s,
            load=self.axis_load,
        )

    @property
    def axis_load(self) -> AxisLoad:
        """The motion's axis load, without building the motion: for the shorthand, the
        load's T_L as friction (acting against the motion) and its J_L."""
        if self.motion is not None:
            return self.motion.load
        assert self.load is not None
        return AxisLoad(inertia_kgm2=self.load.inertia_kgm2, friction_torque_nm=self.load.torque_nm)

    @property
    def profile(self) -> Profile:
        """The cycle prepared for the flowchart (computed once; the chapter's shorthand
        without building its pieces, :func:`~actuator_selection.sizing.motion.
        trapezoid_profile`)."""
        if not self._profile:
            p = self.pattern
            self._profile.append(
                profile_of(self.cycle)
                if p is None
                else trapezoid_profile(
                    self.cycle,
                    speed_rpm=p.speed_rpm,
                    accel_s=p.accel_s,
                    constant_s=p.constant_s,
                    decel_s=p.decel_s,
                    pause_s=p.pause_s,
                )
            )
        return self._profile[0]

    @property
    def known_profile(self) -> Profile | None:
        """:attr:`profile` if it has been computed, else None (nothing is computed)."""
        return self._profile[0] if self._profile else None

    drive: bool = False
    """Whether the drive's current is sized too
    (:data:`~actuator_selection.sizing.checks.DRIVE_CURRENT`); the output voltage is checked
    either way (:data:`~actuator_selection.sizing.checks.DRIVE_VOLTAGE`)."""
    output_load: OutputLoad | None = None
    """An external load on the output flange, or None: the output bearing is not checked
    (the rules of :mod:`~actuator_selection.sizing.checks.rules.bearing`)."""
    gear: bool = False
    """Whether the strain wave gear's own limits are checked
    (the rules of :mod:`~actuator_selection.sizing.checks.rules.gear`; docs/decisions/0024)."""
    gear_required_life_h: float | None = None
    """The wave generator life the application needs [h]; None: not checked."""
    momentary_torque_nm: float | None = None
    """A momentary peak torque (collision, emergency stop) at the output [Nm]; None: not
    checked."""
    momentary_count: float | None = None
    """How often that momentary peak occurs over the life [-]."""
    min_natural_frequency_hz: float | None = None
    """The least natural frequency of the load on the gear's stiffness the application
    needs [Hz]; None: not checked (:data:`~actuator_selection.sizing.checks.NATURAL_FREQUENCY`)."""
    brake_safety_factor: float = DEFAULT_BRAKE_SAFETY_FACTOR
    """S of the brake's holding check, S·T_L ≤ T_Br (docs/decisions/0024)."""
    emergency_stops: float | None = None
    """Emergency stops expected over the life, against the brake's allowable count; None:
    not checked."""
    thermal_time_constant_s: float | None = None
    """The winding's thermal time constant τ_th [s] for the heating check
    (:data:`~actuator_selection.sizing.checks.THERMAL_PEAK`) where the catalogue gives
    none; None: :data:`~actuator_selection.sizing.thermal.DEFAULT_THERMAL_TIME_CONSTANT_S`,
    an assumption (the check then says approximate)."""

    @property
    def drop_torque_nm(self) -> float | None:
        """The torque that turns the output while the brake closes, the motor without
        torque [Nm]: a motion's |T_G| (a weight; friction, which holds back, and the
        losses of a load driving back counted zero: the safe side); None for the
        chapter's shorthand, whose T_L may be a weight (taken as one, as the holding check
        does: ``load_torque_nm``)."""
        if self.motion is None:
            return None
        return abs(self.motion.load.gravity_torque_nm)

    @property
    def travel_mm_per_rad(self) -> float | None:
        """The load's travel per radian of the output [mm/rad] for a linear axis
        (:attr:`~actuator_selection.sizing.axis.AxisLoad.travel_mm_per_rad`); None for a
        rotary load, or the chapter's shorthand (a rotary load)."""
        return None if self.motion is None else self.motion.load.travel_mm_per_rad
