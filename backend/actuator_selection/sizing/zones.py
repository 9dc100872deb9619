"""The continuous-duty zone's edge at a speed (Fig. 517.1).

The catalogue publishes the zone's upper edge as its corner points
(:class:`~actuator_selection.catalogue.zones.ContinuousDutyZone`); an operating point
(n_av, T_rms) below the edge may run indefinitely. Between two points the edge is
linearly interpolated; beyond the last point's speed the zone ends. The engine's checks
compute the same edge on arrays (:func:`~actuator_selection.sizing.engine.cases.zone_limits`).
"""

from __future__ import annotations

from bisect import bisect_right

from actuator_selection.catalogue.zones import ContinuousDutyZone


def torque_limit_nm(zone: ContinuousDutyZone, speed_rpm: float) -> float | None:
    """Continuous torque ``zone`` allows at ``speed_rpm``; None outside its speed range.

    >>> from actuator_selection.catalogue.zones import ZonePoint
    >>> zone = ContinuousDutyZone(points=(ZonePoint(speed_rpm=0, torque_nm=60),
    ...                                   ZonePoint(speed_rpm=100, torque_nm=40)))
    >>> torque_limit_nm(zone, 50)
    50.0
    >>> torque_limit_nm(zone, 101) is None
    True
    """
    if speed_rpm < 0 or speed_rpm > zone.max_speed_rpm:
        return None
    speeds = [p.speed_rpm for p in zone.points]
    i = bisect_right(speeds, speed_rpm)
    if i >= len(zone.points):
        return zone.points[-1].torque_nm
    a, b = zone.points[i - 1], zone.points[i]
    share = (speed_rpm - a.speed_rpm) / (b.speed_rpm - a.speed_rpm)
    return a.torque_nm + share * (b.torque_nm - a.torque_nm)
