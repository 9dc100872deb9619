"""The winding's temperature sensors: KTY 84-130 and PTC characteristics, a PTC reading's
zone (Table 518.1, Fig. 518.2, 519.1).
"""

from __future__ import annotations

import math
from bisect import bisect_left
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from enum import StrEnum
from itertools import pairwise

from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.errors import InvalidInputError, OutOfRangeError

# --------------------------------------------------------------------------- sensors


@dataclass(frozen=True, slots=True, kw_only=True)
class SensorFitting:
    """The temperature sensor of one actuator family or variant (Table 518.1).

    Parameters
    ----------
    family
        Actuator family as the catalogue names it, e.g. ``"FHA-C"``.
    variant
        Variant the row applies to (e.g. ``"L"``, ``"H"``), None for the whole family.
    sensor
        PTC or KTY 84-130.
    sensor_count
        Number of sensors [-], ≥ 1. For a PTC they form a series string (DIN 44082
        triplet: three sensors, three times the resistance); KTY sensors are read
        one at a time.
    nominal_response_temperature_c
        T_NAT of a PTC [°C]; None for a KTY.
    designation
        Type designation as printed, e.g. ``"PTC 116-K13-145 °C"``.
    """

    family: str
    variant: str | None = None
    sensor: TemperatureSensor
    sensor_count: int = 1
    nominal_response_temperature_c: float | None = None
    designation: str | None = None

    def __post_init__(self) -> None:
        if self.sensor_count < 1:
            raise InvalidInputError("sensor_count", "must be ≥ 1: a fitted sensor exists")
        if self.sensor is TemperatureSensor.PTC:
            if self.nominal_response_temperature_c is None:
                raise InvalidInputError(
                    "nominal_response_temperature_c",
                    "is required for a PTC: its reading means something only relative to T_NAT",
                )
            _require_finite("nominal_response_temperature_c", self.nominal_response_temperature_c)
        elif self.nominal_response_temperature_c is not None:
            raise InvalidInputError(
                "nominal_response_temperature_c",
                "applies to a PTC only: a KTY 84-130 has no response temperature",
            )


def _require_finite(field: str, value: float) -> None:
    if not math.isfinite(value):
        raise InvalidInputError(field, f"must be a finite number, got {value!r}")


def _interpolate(xs: Sequence[float], ys: Sequence[float], x: float) -> float:
    """Linear interpolation in a table whose ``xs`` rise strictly; ``x`` inside the table."""
    i = bisect_left(xs, x)
    if xs[i] == x:
        return float(ys[i])
    x0, x1, y0, y1 = xs[i - 1], xs[i], ys[i - 1], ys[i]
    return y0 + (x - x0) * (y1 - y0) / (x1 - x0)


@dataclass(frozen=True, slots=True, kw_only=True)
class KtyCharacteristic:
    """Resistance/temperature table of the KTY 84-130 (Fig. 519.1), interpolated linearly.

    Temperatures and resistances both rise strictly, so the table reads both
    ways. Outside the table an :class:`OutOfRangeError` is raised: the
    manufacturer's table is not extrapolated.

    Parameters
    ----------
    temperatures_c
        Table temperatures [°C], strictly rising.
    resistances_ohm
        Resistance at each temperature [Ω], strictly rising.

    >>> kty = KtyCharacteristic(temperatures_c=(80, 90), resistances_ohm=(882, 940))
    >>> kty.resistance_ohm(85)
    911.0
    >>> kty.temperature_c(911)
    85.0
    """

    temperatures_c: tuple[float, ...]
    resistances_ohm: tuple[float, ...]

    def __post_init__(self) -> None:
        object.__setattr__(self, "temperatures_c", tuple(float(t) for t in self.temperatures_c))
        object.__setattr__(self, "resistances_ohm", tuple(float(r) for r in self.resistances_ohm))
        if len(self.temperatures_c) != len(self.resistances_ohm):
            raise InvalidInputError("resistances_ohm", "needs one resistance per table temperature")
        if len(self.temperatures_c) < 2:
            raise InvalidInputError("temperatures_c", "needs at least two table points")
        for name, values in (
            ("temperatures_c", self.temperatures_c),
            ("resistances_ohm", self.resistances_ohm),
        ):
            for v in values:
                _require_finite(name, v)
            if any(b <= a for a, b in pairwise(values)):
                raise InvalidInputError(
                    name, "must rise strictly: the table is read in both directions"
                )
        if self.resistances_ohm[0] <= 0:
            raise InvalidInputError("resistances_ohm", "must be > 0 Ω")

    @classmethod
    def from_points(cls, points: Iterable[tuple[float, float]]) -> KtyCharacteristic:
        """Build the table from (temperature [°C], resistance [Ω]) pairs in any order."""
        ordered = sorted(points)
        return cls(
            temperatures_c=tuple(t for t, _ in ordered),
            resistances_ohm=tuple(r for _, r in ordered),
        )

    def resistance_ohm(self, temperature_c: float) -> float:
        """Sensor resistance [Ω] at ``temperature_c`` [°C] (Fig. 519.1)."""
        _require_finite("temperature_c", temperature_c)
        lo, hi = self.temperatures_c[0], self.temperatures_c[-1]
        if not lo <= temperature_c <= hi:
            raise OutOfRangeError(
                "temperature_c",
                f"{temperature_c:g} °C is outside the KTY 84-130 table ({lo:g}…{hi:g} °C): "
                "the manufacturer's table is not extrapolated",
            )
        return _interpolate(self.temperatures_c, self.resistances_ohm, temperature_c)

    def temperature_c(self, resistance_ohm: float) -> float:
        """Sensor temperature [°C] at ``resistance_ohm`` [Ω] (Fig. 519.1, read backwards)."""
        _require_finite("resistance_ohm", resistance_ohm)
        lo, hi = self.resistances_ohm[0], self.resistances_ohm[-1]
        if not lo <= resistance_ohm <= hi:
            raise OutOfRangeError(
                "resistance_ohm",
                f"{resistance_ohm:g} Ω is outside the KTY 84-130 table ({lo:g}…{hi:g} Ω, "
                f"{self.temperatures_c[0]:g}…{self.temperatures_c[-1]:g} °C): the "
                "manufacturer's table is not extrapolated (an open or shorted sensor reads "
                "outside it)",
            )
        return _interpolate(self.resistances_ohm, self.temperatures_c, resistance_ohm)


@dataclass(frozen=True, slots=True, kw_only=True)
class PtcCharacteristic:
    """Characteristic points of one PTC thermistor around T_NAT (DIN 44081, Fig. 518.2).

    A conforming sensor has at most ``below_max_resistance_ohm`` at
    T_NAT + ``below_offset_k``, at least ``above_min_resistance_ohm`` at
    T_NAT + ``above_offset_k`` and at least ``far_above_min_resistance_ohm`` at
    T_NAT + ``far_above_offset_k``. Offsets in kelvin, resistances in Ω per sensor.
    """

    below_offset_k: float
    below_max_resistance_ohm: float
    above_offset_k: float
    above_min_resistance_ohm: float
    far_above_offset_k: float
    far_above_min_resistance_ohm: float

    def __post_init__(self) -> None:
        if not self.below_offset_k < self.above_offset_k < self.far_above_offset_k:
            raise InvalidInputError("ptc_characteristic", "offsets must rise: below < above")
        if not (
            0
            < self.below_max_resistance_ohm
            < self.above_min_resistance_ohm
            < self.far_above_min_resistance_ohm
        ):
            raise InvalidInputError(
                "ptc_characteristic", "resistances must rise with temperature: 0 < R1 < R2 < R3"
            )


DIN_44081 = PtcCharacteristic(
    below_offset_k=-5.0,
    below_max_resistance_ohm=550.0,
    above_offset_k=5.0,
    above_min_resistance_ohm=1330.0,
    far_above_offset_k=15.0,
    far_above_min_resistance_ohm=4000.0,
)
"""DIN 44081 points of one PTC: R ≤ 550 Ω at T_NAT − 5 K, R ≥ 1330 Ω at T_NAT + 5 K,
R ≥ 4000 Ω at T_NAT + 15 K (standard cited in public-catalogue-data.md; measuring
voltage ≤ 7.5 V). A DIN 44082 triplet is three such sensors in series."""


class PtcZone(StrEnum):
    """Where a PTC reading lies relative to T_NAT (DIN 44081 points; see :func:`classify_ptc`)."""

    BELOW = "below"
    AROUND = "around"
    ABOVE = "above"
    FAR_ABOVE = "far_above"


@dataclass(frozen=True, slots=True, kw_only=True)
class PtcReading:
    """What a PTC resistance tells, and no more.

    ``zone`` is the usual reading of the DIN 44081 points; ``known_above_c`` and
    ``known_below_c`` are the bounds of the winding temperature [°C] that follow
    for every conforming sensor (None where the points give no bound). A PTC
    never yields a temperature.
    """

    zone: PtcZone
    resistance_ohm: float
    resistance_per_sensor_ohm: float
    nominal_response_temperature_c: float
    known_above_c: float | None
    known_below_c: float | None
    message: str


def classify_ptc(
    *,
    resistance_ohm: float,
    nominal_response_temperature_c: float,
    sensor_count: int = 1,
    characteristic: PtcCharacteristic = DIN_44081,
) -> PtcReading:
    """Classify a PTC resistance against T_NAT with the DIN 44081 points (Fig. 518.2).

    With n sensors in series the string resistance is divided by n (all sensors
    in the same winding at the same temperature; one hot phase among cold ones
    is diluted, so a triplet reading is an average, not the hottest point).
    Per sensor, with R1 = 550 Ω, R2 = 1330 Ω, R3 = 4000 Ω:

    - ``below``, R ≤ R1: read as below T_NAT − 5 K; certain: T < T_NAT + 5 K;
    - ``around``, R1 < R < R2: within T_NAT ± 5 K; certain: T_NAT − 5 K < T < T_NAT + 5 K;
    - ``above``, R2 ≤ R < R3: read as at or above T_NAT + 5 K;
      certain: T_NAT − 5 K < T < T_NAT + 15 K;
    - ``far_above``, R ≥ R3: read as at or above T_NAT + 15 K; certain: T > T_NAT − 5 K.

    The certain bounds follow from the characteristic, which rises monotonically
    above its minimum-resistance temperature: a sensor at or below T_NAT − 5 K
    reads ≤ R1, one at or above T_NAT + 5 K reads ≥ R2, one at or above
    T_NAT + 15 K reads ≥ R3; the contrapositives bound the temperature.

    Parameters
    ----------
    resistance_ohm
        Measured resistance of the sensor string [Ω], > 0.
    nominal_response_temperature_c
        T_NAT [°C] (Table 518.1).
    sensor_count
        Sensors in series [-] (3 for a DIN 44082 triplet, TorkDrive).
    characteristic
        DIN 44081 points of one sensor.

    >>> r = classify_ptc(resistance_ohm=3 * 800, nominal_response_temperature_c=130,
    ...                  sensor_count=3)
    >>> r.zone.value, r.known_above_c, r.known_below_c
    ('around', 125.0, 135.0)
    """
    _require_finite("resistance_ohm", resistance_ohm)
    _require_finite("nominal_response_temperature_c", nominal_response_temperature_c)
    if resistance_ohm <= 0:
        raise InvalidInputError(
            "resistance_ohm", "must be > 0 Ω: a reading of 0 Ω is a short circuit, not a PTC"
        )
    if sensor_count < 1:
        raise InvalidInputError("sensor_count", "must be ≥ 1: sensors in the series string")
    c = characteristic
    t_nat = nominal_response_temperature_c
    per_sensor = resistance_ohm / sensor_count
    t_low = t_nat + c.below_offset_k
    t_high = t_nat + c.above_offset_k
    t_far = t_nat + c.far_above_offset_k
    string = f"{resistance_ohm:g} Ω" + (
        f" ({per_sensor:g} Ω per sensor, {sensor_count} in series)" if sensor_count > 1 else ""
    )
    zone: PtcZone
    known_above: float | None
    known_below: float | None
    if per_sensor <= c.below_max_resistance_ohm:
        zone, known_above, known_below = PtcZone.BELOW, None, t_high
        text = (
            f"PTC {string} ≤ {c.below_max_resistance_ohm:g} Ω: not responded, below "
            f"T_NAT − {-c.below_offset_k:g} K = {t_low:g} °C (certainly below {t_high:g} °C)"
        )
    elif per_sensor < c.above_min_resistance_ohm:
        zone, known_above, known_below = PtcZone.AROUND, t_low, t_high
        text = (
            f"PTC {string} between {c.below_max_resistance_ohm:g} and "
            f"{c.above_min_resistance_ohm:g} Ω: in the response band T_NAT ± "
            f"{c.above_offset_k:g} K ({t_low:g}…{t_high:g} °C)"
        )
    elif per_sensor < c.far_above_min_resistance_ohm:
        zone, known_above, known_below = PtcZone.ABOVE, t_low, t_far
        text = (
            f"PTC {string} ≥ {c.above_min_resistance_ohm:g} Ω: responded, at or above "
            f"T_NAT + {c.above_offset_k:g} K = {t_high:g} °C (certainly above {t_low:g} °C)"
        )
    else:
        zone, known_above, known_below = PtcZone.FAR_ABOVE, t_low, None
        text = (
            f"PTC {string} ≥ {c.far_above_min_resistance_ohm:g} Ω: responded, at or above "
            f"T_NAT + {c.far_above_offset_k:g} K = {t_far:g} °C (certainly above {t_low:g} °C)"
        )
    return PtcReading(
        zone=zone,
        resistance_ohm=resistance_ohm,
        resistance_per_sensor_ohm=per_sensor,
        nominal_response_temperature_c=t_nat,
        known_above_c=known_above,
        known_below_c=known_below,
        message=text,
    )
