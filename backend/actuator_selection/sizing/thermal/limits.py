"""The warning and shutdown limits per family and a sensor reading against them (Table 519.2)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum

from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.errors import InvalidInputError
from actuator_selection.sizing.thermal.sensors import (
    DIN_44081,
    KtyCharacteristic,
    PtcCharacteristic,
    PtcReading,
    PtcZone,
    SensorFitting,
    _require_finite,
    classify_ptc,
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
