"""The motion cycle of a selection request: the chapter's trapezoid, segments, or a sampled
profile.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Discriminator, Field, Tag

from actuator_selection.errors import DomainError, InvalidInputError
from actuator_selection.schemas.common import (
    MAX_SPEED_RPM,
    MAX_TIME_S,
    MAX_TORQUE_NM,
    MIN_RAMP_S,
    StrictModel,
)
from actuator_selection.schemas.selections.loads import _renamed
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.motion import MAX_SEGMENTS, Motion, Segment, trapezoid


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
