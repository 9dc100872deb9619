"""Winding protection: temperature sensors, their limits, and overload duration (p. 518–520).

Table 518.1 names the temperature sensor built into each actuator family: a
KTY 84-130 (an analogue thermometer, Fig. 519.1) or a PTC thermistor (a switch
around its nominal response temperature T_NAT, Fig. 518.2). Table 519.2 fixes
the warning and shutdown limits per family. Where no sensor can protect the
winding, the controller must, and Fig. 520.1 gives the time to shutdown at an
overload; its values are not published, so :func:`overload_duration_s` uses the
first-order thermal model of the winding instead.

The sensor table, the limits and T_NAT are catalogue data passed in by the
caller; only the DIN 44081 characteristic points are kept here, as a cited
standard (:data:`DIN_44081`).

Worked example (KTY 84-130 table, Table 519.2 column FHA/CHA): 940 Ω is 90 °C,
the shutdown limit.

>>> kty = KtyCharacteristic(temperatures_c=(80, 90, 100), resistances_ohm=(882, 940, 1000))
>>> fha = TemperatureLimits(warning_temperature_c=80, shutdown_temperature_c=90,
...                         temperature_tolerance_percent=5, warning_resistance_ohm=882,
...                         shutdown_resistance_ohm=940, resistance_tolerance_percent=3)
>>> a = classify_kty_reading(resistance_ohm=940, characteristic=kty, limits=fha)
>>> a.temperature_c, a.state.value
(90.0, 'shutdown')
>>> round(overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600), 1)
172.6
"""

from __future__ import annotations

from actuator_selection.sizing.thermal.limits import (
    TemperatureLimits,
    ThermalAssessment,
    ThermalState,
    classify_kty_reading,
    classify_ptc_reading,
    classify_sensor_reading,
    classify_temperature,
)
from actuator_selection.sizing.thermal.overload import (
    DEFAULT_THERMAL_TIME_CONSTANT_S,
    OverloadPoint,
    finite_overload_duration_s,
    overload_curve,
    overload_duration_s,
)
from actuator_selection.sizing.thermal.sensors import (
    DIN_44081,
    KtyCharacteristic,
    PtcCharacteristic,
    PtcReading,
    PtcZone,
    SensorFitting,
    classify_ptc,
)

__all__ = [
    "DEFAULT_THERMAL_TIME_CONSTANT_S",
    "DIN_44081",
    "KtyCharacteristic",
    "OverloadPoint",
    "PtcCharacteristic",
    "PtcReading",
    "PtcZone",
    "SensorFitting",
    "TemperatureLimits",
    "ThermalAssessment",
    "ThermalState",
    "classify_kty_reading",
    "classify_ptc",
    "classify_ptc_reading",
    "classify_sensor_reading",
    "classify_temperature",
    "finite_overload_duration_s",
    "overload_curve",
    "overload_duration_s",
]
