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

import math
from bisect import bisect_left
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from enum import StrEnum
from itertools import pairwise

from actuator_selection.core.errors import InvalidInputError, OutOfRangeError

# --------------------------------------------------------------------------- sensors


class TemperatureSensor(StrEnum):
    """Sensor types of Table 518.1 (the temperature sensor columns of Table 521.1)."""

    PTC = "ptc"
    KTY84_130 = "kty84_130"


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


# --------------------------------------------------------------------------- limits


class ThermalState(StrEnum):
    """State of the winding against the limits of Table 519.2."""

    NORMAL = "normal"
    WARNING = "warning"
    SHUTDOWN = "shutdown"


@dataclass(frozen=True, slots=True, kw_only=True)
class TemperatureLimits:
    """Warning and shutdown limits of one family (Table 519.2).

    The resistances are those of the KTY 84-130 at the two temperatures; the
    tolerances are as printed (±5 % of the °C value, ±3 % of the resistance).

    Parameters
    ----------
    warning_temperature_c, shutdown_temperature_c
        Limits [°C], warning < shutdown.
    temperature_tolerance_percent
        Tolerance of the temperature limits [%], ≥ 0.
    warning_resistance_ohm, shutdown_resistance_ohm
        KTY 84-130 resistance at the limits [Ω], warning < shutdown.
    resistance_tolerance_percent
        Tolerance of the resistance limits [%], ≥ 0.
    """

    warning_temperature_c: float
    shutdown_temperature_c: float
    temperature_tolerance_percent: float
    warning_resistance_ohm: float
    shutdown_resistance_ohm: float
    resistance_tolerance_percent: float

    def __post_init__(self) -> None:
        for name in (
            "warning_temperature_c",
            "shutdown_temperature_c",
            "temperature_tolerance_percent",
            "warning_resistance_ohm",
            "shutdown_resistance_ohm",
            "resistance_tolerance_percent",
        ):
            _require_finite(name, getattr(self, name))
        if self.warning_temperature_c >= self.shutdown_temperature_c:
            raise InvalidInputError(
                "warning_temperature_c", "must be below the shutdown temperature (Table 519.2)"
            )
        if not 0 < self.warning_resistance_ohm < self.shutdown_resistance_ohm:
            raise InvalidInputError(
                "warning_resistance_ohm",
                "must be > 0 Ω and below the shutdown resistance (Table 519.2)",
            )
        if self.temperature_tolerance_percent < 0 or self.resistance_tolerance_percent < 0:
            raise InvalidInputError("temperature_tolerance_percent", "tolerances must be ≥ 0 %")

    def lower_edge_c(self, state: ThermalState) -> float:
        """Lowest temperature [°C] at which a controller within tolerance may enter ``state``."""
        limit = (
            self.warning_temperature_c
            if state is ThermalState.WARNING
            else self.shutdown_temperature_c
        )
        return limit * (1.0 - self.temperature_tolerance_percent / 100.0)


@dataclass(frozen=True, slots=True, kw_only=True)
class ThermalAssessment:
    """A winding temperature or sensor reading judged against Table 519.2.

    ``temperature_c`` is None for a PTC (it cannot know a temperature);
    ``near_limit`` names a higher state whose tolerance band already contains the
    reading (a controller set within tolerance may have entered it).
    """

    state: ThermalState
    sensor: TemperatureSensor | None
    resistance_ohm: float | None
    temperature_c: float | None
    ptc: PtcReading | None
    near_limit: ThermalState | None
    reference: str
    message: str


def classify_temperature(*, temperature_c: float, limits: TemperatureLimits) -> ThermalAssessment:
    """Normal, warning or shutdown for a winding temperature (Table 519.2).

    A limit that is reached counts: T ≥ shutdown → shutdown; T ≥ warning →
    warning; else normal. The tolerance (±5 %) does not move the state; it
    sets ``near_limit`` when the reading is within the band below the next limit.

    >>> fha = TemperatureLimits(warning_temperature_c=80, shutdown_temperature_c=90,
    ...                         temperature_tolerance_percent=5, warning_resistance_ohm=882,
    ...                         shutdown_resistance_ohm=940, resistance_tolerance_percent=3)
    >>> a = classify_temperature(temperature_c=86, limits=fha)
    >>> a.state.value, a.near_limit.value
    ('warning', 'shutdown')
    """
    _require_finite("temperature_c", temperature_c)
    return _assess_temperature(
        temperature_c=temperature_c,
        limits=limits,
        sensor=None,
        resistance_ohm=None,
        prefix=f"winding temperature {temperature_c:.4g} °C",
    )


def _assess_temperature(
    *,
    temperature_c: float,
    limits: TemperatureLimits,
    sensor: TemperatureSensor | None,
    resistance_ohm: float | None,
    prefix: str,
) -> ThermalAssessment:
    warn, stop = limits.warning_temperature_c, limits.shutdown_temperature_c
    if temperature_c >= stop:
        state = ThermalState.SHUTDOWN
        text = f"{prefix} ≥ shutdown limit {stop:g} °C"
    elif temperature_c >= warn:
        state = ThermalState.WARNING
        text = f"{prefix} ≥ warning limit {warn:g} °C, below shutdown {stop:g} °C"
    else:
        state = ThermalState.NORMAL
        text = f"{prefix} below warning limit {warn:g} °C"
    near: ThermalState | None = None
    for higher in (ThermalState.SHUTDOWN, ThermalState.WARNING):
        if _rank(higher) > _rank(state) and temperature_c >= limits.lower_edge_c(higher):
            near = higher
            break
    if near is not None:
        text += (
            f"; within the ±{limits.temperature_tolerance_percent:g} % tolerance of the "
            f"{near.value} limit"
        )
    return ThermalAssessment(
        state=state,
        sensor=sensor,
        resistance_ohm=resistance_ohm,
        temperature_c=temperature_c,
        ptc=None,
        near_limit=near,
        reference="Table 519.2",
        message=text,
    )


_STATE_RANK = {ThermalState.NORMAL: 0, ThermalState.WARNING: 1, ThermalState.SHUTDOWN: 2}


def _rank(state: ThermalState) -> int:
    return _STATE_RANK[state]


def classify_kty_reading(
    *, resistance_ohm: float, characteristic: KtyCharacteristic, limits: TemperatureLimits
) -> ThermalAssessment:
    """Temperature of a KTY 84-130 reading and its state against Table 519.2.

    The resistance of one sensor (a TorkDrive's two KTY are read one at a time)
    is converted with the manufacturer's table (Fig. 519.1) and classified with
    :func:`classify_temperature`. The resistance limits of Table 519.2 are the
    same table's values at the limit temperatures, so both views agree.

    >>> kty = KtyCharacteristic(temperatures_c=(80, 90, 100), resistances_ohm=(882, 940, 1000))
    >>> lim = TemperatureLimits(warning_temperature_c=80, shutdown_temperature_c=90,
    ...                         temperature_tolerance_percent=5, warning_resistance_ohm=882,
    ...                         shutdown_resistance_ohm=940, resistance_tolerance_percent=3)
    >>> a = classify_kty_reading(resistance_ohm=911, characteristic=kty, limits=lim)
    >>> a.temperature_c, a.state.value, a.near_limit
    (85.0, 'warning', None)
    """
    temperature = characteristic.temperature_c(resistance_ohm)
    return _assess_temperature(
        temperature_c=temperature,
        limits=limits,
        sensor=TemperatureSensor.KTY84_130,
        resistance_ohm=resistance_ohm,
        prefix=f"KTY 84-130 {resistance_ohm:g} Ω = {temperature:.4g} °C",
    )


_PTC_STATE = {
    PtcZone.BELOW: ThermalState.NORMAL,
    PtcZone.AROUND: ThermalState.WARNING,
    PtcZone.ABOVE: ThermalState.SHUTDOWN,
    PtcZone.FAR_ABOVE: ThermalState.SHUTDOWN,
}


def classify_ptc_reading(
    *,
    resistance_ohm: float,
    nominal_response_temperature_c: float,
    sensor_count: int = 1,
    characteristic: PtcCharacteristic = DIN_44081,
) -> ThermalAssessment:
    """State of the winding from a PTC reading (Table 518.1, Fig. 518.2).

    The temperature limits of Table 519.2 are KTY settings (their resistances are
    KTY values); a PTC knows only T_NAT, which is its shutdown point:

    - ``below`` → normal;
    - ``around`` (T_NAT ± 5 K) → warning: the reading cannot exclude T ≥ T_NAT
      and the protective relay may trip at any moment;
    - ``above`` / ``far_above`` → shutdown: at or above T_NAT.

    >>> a = classify_ptc_reading(resistance_ohm=1500, nominal_response_temperature_c=145)
    >>> a.state.value, a.temperature_c, a.ptc.zone.value
    ('shutdown', None, 'above')
    """
    reading = classify_ptc(
        resistance_ohm=resistance_ohm,
        nominal_response_temperature_c=nominal_response_temperature_c,
        sensor_count=sensor_count,
        characteristic=characteristic,
    )
    state = _PTC_STATE[reading.zone]
    t_nat = nominal_response_temperature_c
    consequence = {
        ThermalState.NORMAL: "normal",
        ThermalState.WARNING: f"warning: T ≥ T_NAT = {t_nat:g} °C cannot be excluded",
        ThermalState.SHUTDOWN: f"shutdown: T_NAT = {t_nat:g} °C reached",
    }[state]
    return ThermalAssessment(
        state=state,
        sensor=TemperatureSensor.PTC,
        resistance_ohm=resistance_ohm,
        temperature_c=None,
        ptc=reading,
        near_limit=ThermalState.SHUTDOWN if state is ThermalState.WARNING else None,
        reference="Table 518.1, Fig. 518.2 (DIN 44081)",
        message=f"{reading.message} → {consequence}",
    )


def classify_sensor_reading(
    *,
    resistance_ohm: float,
    fitting: SensorFitting,
    limits: TemperatureLimits | None,
    kty: KtyCharacteristic | None,
    ptc: PtcCharacteristic = DIN_44081,
) -> ThermalAssessment:
    """Classify a reading of the sensor a family carries (Table 518.1, 519.2).

    Dispatches on ``fitting.sensor``: a KTY needs the KTY table and the family's
    limits; a PTC needs only its T_NAT and count from ``fitting``.

    Raises
    ------
    InvalidInputError
        A KTY reading without the KTY table or without limits for the family.
    """
    t_nat = fitting.nominal_response_temperature_c
    if fitting.sensor is TemperatureSensor.PTC and t_nat is not None:  # SensorFitting: PTC has it
        return classify_ptc_reading(
            resistance_ohm=resistance_ohm,
            nominal_response_temperature_c=t_nat,
            sensor_count=fitting.sensor_count,
            characteristic=ptc,
        )
    if kty is None:
        raise InvalidInputError("kty", "a KTY 84-130 reading needs the sensor's table")
    if limits is None:
        raise InvalidInputError(
            "family", f"Table 519.2 gives no limits for {fitting.family}: a KTY needs them"
        )
    return classify_kty_reading(resistance_ohm=resistance_ohm, characteristic=kty, limits=limits)


# --------------------------------------------------------------------------- overload

DEFAULT_THERMAL_TIME_CONSTANT_S = 600.0
"""τ_th [s] assumed where neither the catalogue nor the request gives one: 10 min.

No public Harmonic Drive document we found publishes a winding thermal time constant
for the CHA, FHA-C or FHA-C mini (``shared/reference/public-catalogue-data.md``, "Not
published as numbers anywhere we found"), so this is an assumption, not catalogue data,
and a check that uses it says ``approximate``. Why 10 min:

- a smaller τ_th is the safe side: every time to shutdown τ_th·ln((k² − p²)/(k² − 1))
  is proportional to it, and the peak of the cycle's heating grows as τ_th shrinks
  (tests/core/test_thermal_validity.py checks both);
- it must still let the chapter's own rule stand where the manufacturer applies it: the
  continuous-duty diagram of the worked example is drawn for a duty cycle of one minute
  ("ED = 1 min.", Fig. 517.1; the reading of that note is unconfirmed), and T_rms over a
  cycle only stands for cycles short against τ_th; at τ_th = 10 × 1 min a one-minute
  cycle's heating peak lies within a few per cent of T_rms, at smaller τ_th it would not;
- the issue that asked for this check expects shutdown after 10–40 min at 1.45·T_0
  (τ_th ≈ 15–62 min in this model); a drive maker's generic I²t default for servomotors
  is 540 s (Beckhoff, object 32C8:01 "Motor thermal time constant"). 600 s is at the
  short end of these, so the check is strict rather than lenient.

Give the actuator's real τ_th (the catalogue column ``thermal_time_constant_s``, or
the request's ``thermal_time_constant_s``) where it is known.
"""


def _check_overload_inputs(
    overload_factor: float,
    thermal_time_constant_s: float,
    preload_factor: float,
    max_overload_factor: float | None,
) -> None:
    _require_finite("overload_factor", overload_factor)
    _require_finite("thermal_time_constant_s", thermal_time_constant_s)
    _require_finite("preload_factor", preload_factor)
    if overload_factor < 0:
        raise InvalidInputError("overload_factor", "must be ≥ 0: k = I/I_s is a ratio of currents")
    if thermal_time_constant_s <= 0:
        raise InvalidInputError(
            "thermal_time_constant_s", "must be > 0: τ_th divides the time in the thermal model"
        )
    if preload_factor < 0:
        raise InvalidInputError("preload_factor", "must be ≥ 0: p = I_prev/I_s")
    if preload_factor > 1:
        raise InvalidInputError(
            "preload_factor",
            "must be ≤ 1: a steady preload above the stall current I_s would hold the "
            "winding above its limit, which is no state to start an overload from",
        )
    if max_overload_factor is not None and overload_factor > max_overload_factor:
        raise OutOfRangeError(
            "overload_factor",
            f"k = {overload_factor:g} exceeds I_max/I_s = {max_overload_factor:g}: "
            "Fig. 520.1 holds for I ≤ I_max",
        )


def overload_duration_s(
    *,
    overload_factor: float,
    thermal_time_constant_s: float,
    preload_factor: float = 0.0,
    max_overload_factor: float | None = None,
) -> float | None:
    """Time until the winding reaches its limit at overload k = I/I_s [s] (Fig. 520.1).

    The figure's values are not published; the first-order thermal model of the
    winding (temperature rise ∝ I², limit reached at I_s in steady state) gives,
    from the steady state of a previous current p·I_s,

        t = τ_th · ln((k² − p²) / (k² − 1)),   k > 1, 0 ≤ p ≤ 1,

    and from cold (p = 0) t = τ_th · ln(k² / (k² − 1)). For k ≤ 1 the limit is
    never reached and None is returned. p = 1 means the winding is already at its
    limit: t = 0 for any k > 1. p > 1 is refused (see :class:`InvalidInputError`).

    Parameters
    ----------
    overload_factor
        k = I/I_s [-], ratio of the actual effective current to the continuous stall current.
    thermal_time_constant_s
        τ_th [s], the winding's thermal time constant.
    preload_factor
        p = I_prev/I_s [-] of the current the winding carried long enough to settle; 0 = cold.
    max_overload_factor
        I_max/I_s [-]; when given, k above it is an :class:`OutOfRangeError` (I ≤ I_max).

    >>> round(overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600), 1)
    172.6
    >>> overload_duration_s(overload_factor=1.0, thermal_time_constant_s=600) is None
    True
    """
    _check_overload_inputs(
        overload_factor, thermal_time_constant_s, preload_factor, max_overload_factor
    )
    if overload_factor <= 1.0:
        return None
    k2 = overload_factor * overload_factor
    p2 = preload_factor * preload_factor
    return thermal_time_constant_s * math.log((k2 - p2) / (k2 - 1.0))


def finite_overload_duration_s(
    *,
    overload_factor: float,
    thermal_time_constant_s: float,
    preload_factor: float = 0.0,
    max_overload_factor: float | None = None,
) -> float:
    """As :func:`overload_duration_s`, but k ≤ 1 is an :class:`InvalidInputError`.

    For callers that need a number: at k ≤ 1 there is no shutdown to time.

    >>> finite_overload_duration_s(overload_factor=0.8, thermal_time_constant_s=600)
    Traceback (most recent call last):
    ...
    actuator_selection.core.errors.InvalidInputError: overload_factor: must be > 1 for a \
duration: at k = 0.8 ≤ 1 the winding never reaches its limit (Fig. 520.1)
    """
    duration = overload_duration_s(
        overload_factor=overload_factor,
        thermal_time_constant_s=thermal_time_constant_s,
        preload_factor=preload_factor,
        max_overload_factor=max_overload_factor,
    )
    if duration is None:
        raise InvalidInputError(
            "overload_factor",
            f"must be > 1 for a duration: at k = {overload_factor:g} ≤ 1 the winding never "
            "reaches its limit (Fig. 520.1)",
        )
    return duration


@dataclass(frozen=True, slots=True, kw_only=True)
class OverloadPoint:
    """One point of the overload curve: k [-] and the time to shutdown [s]."""

    overload_factor: float
    duration_s: float


def overload_curve(
    *,
    thermal_time_constant_s: float,
    max_overload_factor: float,
    preload_factor: float = 0.0,
    points: int = 50,
) -> tuple[OverloadPoint, ...]:
    """The overload characteristic of Fig. 520.1 from the thermal model, for a chart.

    ``points`` equally spaced factors k_j = 1 + (k_max − 1)·j/points, j = 1…points:
    the curve starts just above 1 (where t grows without bound) and ends at
    k_max = I_max/I_s.

    >>> c = overload_curve(thermal_time_constant_s=600, max_overload_factor=3, points=4)
    >>> [(p.overload_factor, round(p.duration_s, 1)) for p in c]
    [(1.5, 352.7), (2.0, 172.6), (2.5, 104.6), (3.0, 70.7)]
    """
    _require_finite("max_overload_factor", max_overload_factor)
    if max_overload_factor <= 1:
        raise InvalidInputError(
            "max_overload_factor",
            "must be > 1: with I_max ≤ I_s there is no overload to draw",
        )
    if points < 1:
        raise InvalidInputError("points", "must be ≥ 1")
    curve = []
    for j in range(1, points + 1):
        k = 1.0 + (max_overload_factor - 1.0) * j / points
        curve.append(
            OverloadPoint(
                overload_factor=k,
                duration_s=finite_overload_duration_s(
                    overload_factor=k,
                    thermal_time_constant_s=thermal_time_constant_s,
                    preload_factor=preload_factor,
                ),
            )
        )
    return tuple(curve)
