"""The continuous-duty zone polyline."""

from __future__ import annotations

import pytest

from actuator_selection.catalogue.zones import ContinuousDutyZone, ZonePoint
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.zones import torque_limit_nm


def zone(*points: tuple[float, float]) -> ContinuousDutyZone:
    return ContinuousDutyZone(points=tuple(ZonePoint(speed_rpm=s, torque_nm=t) for s, t in points))


def test_interpolates_between_corners() -> None:
    z = zone((0, 100), (40, 80), (90, 20))
    assert torque_limit_nm(z, 0) == 100
    assert torque_limit_nm(z, 20) == pytest.approx(90)  # halfway from 100 to 80
    assert torque_limit_nm(z, 40) == 80
    assert torque_limit_nm(z, 65) == pytest.approx(50)  # halfway from 80 to 20
    assert torque_limit_nm(z, 90) == 20


def test_outside_speed_range_has_no_limit() -> None:
    z = zone((0, 100), (90, 20))
    assert torque_limit_nm(z, 90.0001) is None
    assert torque_limit_nm(z, -1) is None
    assert z.max_speed_rpm == 90


@pytest.mark.parametrize(
    "points",
    [
        ((0, 10),),
        ((5, 10), (10, 5)),
        ((0, 10), (10, 5), (10, 4)),
        ((0, 10), (10, -1)),
        ((0, 10), (20, 5), (15, 4)),
    ],
)
def test_rejects_malformed_zones(points: tuple[tuple[float, float], ...]) -> None:
    with pytest.raises(InvalidInputError):
        zone(*points)
