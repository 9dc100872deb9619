"""What an actuator is fitted with, as its catalogue names it.

The kinds a catalogue value names, one enum per part: the output bearing's type (the
CHA output bearing table, ``output_bearing_type``) and the winding's temperature
sensor (Table 518.1, the sensor columns of Table 521.1). What the sizing makes of
them lives with the sizing (the life exponent in :mod:`actuator_selection.sizing.bearing`).
"""

from __future__ import annotations

from enum import StrEnum


class BearingType(StrEnum):
    """The type of an actuator's output bearing, as its catalogue names it: it sets the life
    exponent B (:func:`~actuator_selection.sizing.bearing.life_exponent`)."""

    CROSS_ROLLER = "cross_roller"
    """A cross roller bearing (CHA-25A and larger; FHA-C): B = 10/3."""
    FOUR_POINT_CONTACT_BALL = "four_point_contact_ball"
    """A four-point contact ball bearing (CHA-14A, -17A, -20A; type "F" in the CHA output
    bearing table): B = 3."""


class TemperatureSensor(StrEnum):
    """Sensor types of Table 518.1 (the temperature sensor columns of Table 521.1)."""

    PTC = "ptc"
    KTY84_130 = "kty84_130"
