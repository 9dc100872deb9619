"""The continuous-duty zone of an actuator's speed/torque diagram (Fig. 517.1), as published.

The catalogue draws the zone's upper edge as a curve from standstill to the
highest continuous speed; an operating point (n_av, T_rms) below that curve may
run indefinitely. The catalogue holds the edge as its corner points (``zone_points.csv``);
the edge between them, linearly interpolated, is the sizing's
(:func:`~actuator_selection.sizing.zones.torque_limit_nm`).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from actuator_selection.errors import InvalidInputError


@dataclass(frozen=True, slots=True, kw_only=True)
class ZonePoint:
    """One corner of the zone's upper edge: output speed [rpm] and torque [Nm]."""

    speed_rpm: float
    torque_nm: float


@dataclass(frozen=True, slots=True, kw_only=True)
class ContinuousDutyZone:
    """Upper edge of the continuous-duty zone, from standstill upwards in speed.

    The first point is at 0 rpm (the continuous stall torque), speeds rise
    strictly, torques are ≥ 0. Beyond the last point's speed the zone ends.

    >>> zone = ContinuousDutyZone(points=(ZonePoint(speed_rpm=0, torque_nm=60),
    ...                                   ZonePoint(speed_rpm=100, torque_nm=40)))
    >>> zone.max_speed_rpm
    100
    """

    points: tuple[ZonePoint, ...]

    def __post_init__(self) -> None:
        if len(self.points) < 2:
            raise InvalidInputError("zone", "needs at least two points")
        if self.points[0].speed_rpm != 0:
            raise InvalidInputError("zone", "must start at 0 rpm (the continuous stall torque)")
        for p in self.points:
            if not (math.isfinite(p.speed_rpm) and math.isfinite(p.torque_nm)):
                raise InvalidInputError("zone", "points must be finite numbers")
            if p.torque_nm < 0:
                raise InvalidInputError("zone", "torques must be ≥ 0")
        speeds = [p.speed_rpm for p in self.points]
        if any(b <= a for a, b in itertools.pairwise(speeds)):
            raise InvalidInputError("zone", "speeds must rise strictly from point to point")

    @property
    def max_speed_rpm(self) -> float:
        """The highest speed the zone covers [rpm]."""
        return self.points[-1].speed_rpm
