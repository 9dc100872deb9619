"""Unit conversions, each named once so that no equation hides a factor.

The catalogue speaks rpm at the output shaft; SI angular speed appears only
inside the equations that need it.
"""

from __future__ import annotations

import math

RAD_PER_S_PER_RPM = 2.0 * math.pi / 60.0
"""One revolution per minute in rad/s: the factor 2π/60 of Eq. 514.1."""


def rpm_to_rad_per_s(speed_rpm: float) -> float:
    """Angular speed [rad/s] of a speed given in revolutions per minute [rpm].

    >>> round(rpm_to_rad_per_s(60.0), 6)
    6.283185
    """
    return speed_rpm * RAD_PER_S_PER_RPM


def per_krpm_to_per_rpm(value_per_krpm: float) -> float:
    """A constant given per 1000 rpm (e.g. K_E in V/1000 rpm) expressed per rpm.

    >>> per_krpm_to_per_rpm(37.0)
    0.037
    """
    return value_per_krpm / 1000.0
