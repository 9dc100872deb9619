"""Sensors, limits and overload duration (Tables 518.1, 519.2, Fig. 518.2, 519.1, 520.1).

Reference values come from the KTY 84-130 manufacturer's table, the DIN 44081
points, Table 519.2, and the first-order thermal model worked by hand.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.errors import InvalidInputError, OutOfRangeError
from actuator_selection.sizing.thermal import (
    DIN_44081,
    KtyCharacteristic,
    PtcZone,
    SensorFitting,
    TemperatureLimits,
    ThermalState,
    classify_kty_reading,
    classify_ptc,
    classify_ptc_reading,
    classify_sensor_reading,
    classify_temperature,
    finite_overload_duration_s,
    overload_curve,
    overload_duration_s,
)

SEED = Path(__file__).parents[2] / "seed_data"


def _rows(name: str) -> list[dict[str, str]]:
    with (SEED / name).open(encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def _kty() -> KtyCharacteristic:
    return KtyCharacteristic.from_points(
        (float(r["temperature_c"]), float(r["resistance_ohm"])) for r in _rows("kty84_130.csv")
    )


def _limits(family: str) -> TemperatureLimits:
    (row,) = [r for r in _rows("families.csv") if r["name"] == family]
    return TemperatureLimits(
        warning_temperature_c=float(row["warning_temperature_c"]),
        shutdown_temperature_c=float(row["shutdown_temperature_c"]),
        temperature_tolerance_percent=float(row["temperature_tolerance_percent"]),
        warning_resistance_ohm=float(row["warning_resistance_ohm"]),
        shutdown_resistance_ohm=float(row["shutdown_resistance_ohm"]),
        resistance_tolerance_percent=float(row["resistance_tolerance_percent"]),
    )


def _fittings(family: str) -> list[SensorFitting]:
    return [
        SensorFitting(
            family=r["family"],
            variant=r["variant"] or None,
            sensor=TemperatureSensor(r["sensor"]),
            sensor_count=int(r["sensor_count"]),
            nominal_response_temperature_c=(
                float(r["nominal_response_temperature_c"])
                if r["nominal_response_temperature_c"]
                else None
            ),
            designation=r["designation"] or None,
        )
        for r in _rows("temperature_sensors.csv")
        if r["family"] == family
    ]


# --------------------------------------------------------------------------- seed data


def test_every_seed_row_has_a_source() -> None:
    for name in ("kty84_130.csv", "families.csv", "temperature_sensors.csv"):
        rows = _rows(name)
        assert rows, name
        assert all(r["source"].strip() for r in rows), name


def test_kty_table_covers_minus_40_to_300_c_in_10_k_steps() -> None:
    kty = _kty()
    assert kty.temperatures_c == tuple(float(t) for t in range(-40, 301, 10))
    assert len(kty.resistances_ohm) == 35
    # Datasheet anchor points: −40 °C 359 Ω, R100 = 1000 Ω, 300 °C 2624 Ω.
    assert kty.resistances_ohm[0] == 359
    assert kty.resistance_ohm(100) == 1000
    assert kty.resistances_ohm[-1] == 2624


def test_table_518_1_sensors() -> None:
    by_variant = {(f.variant, f.sensor): f for f in _fittings("FHA-C")}
    fha_l = by_variant[("L", TemperatureSensor.PTC)]
    assert fha_l.nominal_response_temperature_c == 145
    assert ("H", TemperatureSensor.KTY84_130) in by_variant
    (tork_ptc,) = [f for f in _fittings("TorkDrive") if f.sensor is TemperatureSensor.PTC]
    assert (tork_ptc.sensor_count, tork_ptc.nominal_response_temperature_c) == (3, 130)
    (tork_kty,) = [f for f in _fittings("TorkDrive") if f.sensor is TemperatureSensor.KTY84_130]
    assert tork_kty.sensor_count == 2
    cha_ptc = {
        f.variant: f.nominal_response_temperature_c for f in _fittings("CHA") if f.sensor == "ptc"
    }
    assert cha_ptc == {"sizes 20-58": 145, "sizes 14-17": 120}
    ffa_l = [f for f in _fittings("FFA/FPA") if f.variant == "L"]
    assert ffa_l[0].nominal_response_temperature_c == 140
    assert _fittings("FHA-C mini") == []  # not in Table 518.1: no data, no row


# --------------------------------------------------------------------------- KTY


def test_kty_table_points_both_ways() -> None:
    kty = _kty()
    for t, r in zip(kty.temperatures_c, kty.resistances_ohm, strict=True):
        assert kty.resistance_ohm(t) == r
        assert kty.temperature_c(r) == t


def test_kty_interpolation_by_hand() -> None:
    kty = _kty()
    # Midpoint of 80 °C (882 Ω) and 90 °C (940 Ω): (882 + 940)/2 = 911 Ω at 85 °C.
    assert kty.resistance_ohm(85) == pytest.approx(911.0, abs=1e-9)
    assert kty.temperature_c(911) == pytest.approx(85.0, abs=1e-9)
    # 1100 Ω between 110 °C (1062 Ω) and 120 °C (1127 Ω): 110 + 10·38/65 = 115.846 °C.
    assert kty.temperature_c(1100) == pytest.approx(115.846, abs=1e-3)
    # The datasheet gives 603 Ω at 25 °C; the line 20 °C 581 Ω → 30 °C 626 Ω gives 603.5 Ω.
    assert kty.resistance_ohm(25) == pytest.approx(603, abs=1)


def test_kty_round_trip() -> None:
    kty = _kty()
    for tenth in range(-400, 3001, 37):
        t = tenth / 10
        assert kty.temperature_c(kty.resistance_ohm(t)) == pytest.approx(t, abs=1e-9)


@pytest.mark.parametrize("temperature_c", [-40.1, 300.1, -273.0, 1000.0])
def test_kty_temperature_outside_table_is_refused(temperature_c: float) -> None:
    with pytest.raises(OutOfRangeError, match="not extrapolated") as err:
        _kty().resistance_ohm(temperature_c)
    assert err.value.field == "temperature_c"


@pytest.mark.parametrize("resistance_ohm", [358.9, 2624.1, 0.0, 1e6])
def test_kty_resistance_outside_table_is_refused(resistance_ohm: float) -> None:
    with pytest.raises(OutOfRangeError) as err:
        _kty().temperature_c(resistance_ohm)
    assert err.value.field == "resistance_ohm"


def test_kty_table_must_rise() -> None:
    with pytest.raises(InvalidInputError, match="rise strictly"):
        KtyCharacteristic(temperatures_c=(0, 10, 20), resistances_ohm=(500, 600, 590))
    with pytest.raises(InvalidInputError, match="one resistance per"):
        KtyCharacteristic(temperatures_c=(0, 10), resistances_ohm=(500,))


# --------------------------------------------------------------------------- limits


@pytest.mark.parametrize("family", ["FHA-C", "CHA", "FFA/FPA", "CHM", "LynxDrive", "TorkDrive"])
def test_table_519_2_resistances_are_kty_values_at_the_limits(family: str) -> None:
    kty, lim = _kty(), _limits(family)
    tol = lim.resistance_tolerance_percent / 100
    for t, r in (
        (lim.warning_temperature_c, lim.warning_resistance_ohm),
        (lim.shutdown_temperature_c, lim.shutdown_resistance_ohm),
    ):
        assert kty.resistance_ohm(t) == pytest.approx(r, rel=tol)


def test_table_519_2_values() -> None:
    fha, ffa = _limits("FHA-C"), _limits("FFA/FPA")
    assert (fha.warning_temperature_c, fha.shutdown_temperature_c) == (80, 90)
    assert (fha.warning_resistance_ohm, fha.shutdown_resistance_ohm) == (882, 940)
    assert (ffa.warning_temperature_c, ffa.shutdown_temperature_c) == (120, 140)
    assert (ffa.warning_resistance_ohm, ffa.shutdown_resistance_ohm) == (1127, 1262)
    assert (fha.temperature_tolerance_percent, fha.resistance_tolerance_percent) == (5, 3)


def test_kty_940_ohm_on_fha_c_is_shutdown_at_90_c() -> None:
    a = classify_kty_reading(resistance_ohm=940, characteristic=_kty(), limits=_limits("FHA-C"))
    assert a.temperature_c == pytest.approx(90.0, abs=1e-9)
    assert a.state is ThermalState.SHUTDOWN
    assert a.sensor is TemperatureSensor.KTY84_130
    assert a.reference == "Table 519.2"


@pytest.mark.parametrize(
    ("family", "resistance_ohm", "state"),
    [
        ("FHA-C", 881.9, ThermalState.NORMAL),
        ("FHA-C", 882, ThermalState.WARNING),  # 80 °C: the warning limit is reached
        ("FHA-C", 939.9, ThermalState.WARNING),
        ("FHA-C", 1000, ThermalState.SHUTDOWN),
        ("CHM", 1126, ThermalState.NORMAL),
        ("CHM", 1127, ThermalState.WARNING),  # 120 °C
        ("TorkDrive", 1262, ThermalState.SHUTDOWN),  # 140 °C
        ("TorkDrive", 1200, ThermalState.WARNING),  # 130 + 10·6/68 = 130.9 °C
    ],
)
def test_kty_states_for_both_family_groups(
    family: str, resistance_ohm: float, state: ThermalState
) -> None:
    a = classify_kty_reading(
        resistance_ohm=resistance_ohm, characteristic=_kty(), limits=_limits(family)
    )
    assert a.state is state


def test_tolerance_band_flags_the_next_limit() -> None:
    fha = _limits("FHA-C")
    # Warning 80 °C − 5 % = 76 °C; shutdown 90 °C − 5 % = 85.5 °C.
    assert classify_temperature(temperature_c=75.9, limits=fha).near_limit is None
    near = classify_temperature(temperature_c=76.0, limits=fha)
    assert (near.state, near.near_limit) == (ThermalState.NORMAL, ThermalState.WARNING)
    assert classify_temperature(temperature_c=85.4, limits=fha).near_limit is None
    near = classify_temperature(temperature_c=85.5, limits=fha)
    assert (near.state, near.near_limit) == (ThermalState.WARNING, ThermalState.SHUTDOWN)
    assert classify_temperature(temperature_c=95, limits=fha).near_limit is None


def test_limits_must_be_ordered() -> None:
    with pytest.raises(InvalidInputError) as err:
        TemperatureLimits(
            warning_temperature_c=90,
            shutdown_temperature_c=80,
            temperature_tolerance_percent=5,
            warning_resistance_ohm=882,
            shutdown_resistance_ohm=940,
            resistance_tolerance_percent=3,
        )
    assert err.value.field == "warning_temperature_c"


# --------------------------------------------------------------------------- PTC


def test_din_44081_points() -> None:
    assert (DIN_44081.below_offset_k, DIN_44081.below_max_resistance_ohm) == (-5, 550)
    assert (DIN_44081.above_offset_k, DIN_44081.above_min_resistance_ohm) == (5, 1330)
    assert (DIN_44081.far_above_offset_k, DIN_44081.far_above_min_resistance_ohm) == (15, 4000)


@pytest.mark.parametrize(
    ("resistance_ohm", "zone", "above_c", "below_c"),
    [
        (100, PtcZone.BELOW, None, 150),
        (550, PtcZone.BELOW, None, 150),  # the DIN point itself is still "below"
        (551, PtcZone.AROUND, 140, 150),
        (1329, PtcZone.AROUND, 140, 150),
        (1330, PtcZone.ABOVE, 140, 160),  # at or above T_NAT + 5 K
        (3999, PtcZone.ABOVE, 140, 160),
        (4000, PtcZone.FAR_ABOVE, 140, None),
        (1e6, PtcZone.FAR_ABOVE, 140, None),
    ],
)
def test_single_ptc_zones_at_t_nat_145(
    resistance_ohm: float, zone: PtcZone, above_c: float | None, below_c: float | None
) -> None:
    r = classify_ptc(resistance_ohm=resistance_ohm, nominal_response_temperature_c=145)
    assert r.zone is zone
    assert (r.known_above_c, r.known_below_c) == (above_c, below_c)


@pytest.mark.parametrize(
    ("resistance_ohm", "zone"),
    [
        (1650, PtcZone.BELOW),  # 3 × 550
        (1651, PtcZone.AROUND),
        (3989, PtcZone.AROUND),  # 3 × 1330 = 3990
        (3990, PtcZone.ABOVE),
        (11999, PtcZone.ABOVE),
        (12000, PtcZone.FAR_ABOVE),  # 3 × 4000
    ],
)
def test_triplet_multiplies_the_din_points_by_three(resistance_ohm: float, zone: PtcZone) -> None:
    r = classify_ptc(
        resistance_ohm=resistance_ohm, nominal_response_temperature_c=130, sensor_count=3
    )
    assert r.zone is zone
    assert r.resistance_per_sensor_ohm == pytest.approx(resistance_ohm / 3)


@pytest.mark.parametrize(
    ("resistance_ohm", "state"),
    [(400, ThermalState.NORMAL), (900, ThermalState.WARNING), (1500, ThermalState.SHUTDOWN)],
)
def test_ptc_states_never_give_a_temperature(resistance_ohm: float, state: ThermalState) -> None:
    a = classify_ptc_reading(resistance_ohm=resistance_ohm, nominal_response_temperature_c=145)
    assert a.state is state
    assert a.temperature_c is None
    assert a.ptc is not None


@pytest.mark.parametrize("resistance_ohm", [0.0, -10.0, math.nan])
def test_ptc_reading_must_be_positive(resistance_ohm: float) -> None:
    with pytest.raises(InvalidInputError) as err:
        classify_ptc(resistance_ohm=resistance_ohm, nominal_response_temperature_c=145)
    assert err.value.field == "resistance_ohm"


def test_torkdrive_readings_via_its_fittings() -> None:
    fittings = {f.sensor: f for f in _fittings("TorkDrive")}
    ptc = classify_sensor_reading(
        resistance_ohm=3 * 800,
        fitting=fittings[TemperatureSensor.PTC],
        limits=_limits("TorkDrive"),
        kty=_kty(),
    )
    assert ptc.state is ThermalState.WARNING
    assert ptc.ptc is not None
    assert (ptc.ptc.known_above_c, ptc.ptc.known_below_c) == (125, 135)
    kty = classify_sensor_reading(
        resistance_ohm=1262,  # one of the two KTY: not multiplied
        fitting=fittings[TemperatureSensor.KTY84_130],
        limits=_limits("TorkDrive"),
        kty=_kty(),
    )
    assert kty.state is ThermalState.SHUTDOWN
    assert kty.temperature_c == pytest.approx(140)


def test_kty_fitting_needs_limits() -> None:
    (kty_fitting,) = [f for f in _fittings("FHA-C") if f.sensor is TemperatureSensor.KTY84_130]
    with pytest.raises(InvalidInputError) as err:
        classify_sensor_reading(resistance_ohm=900, fitting=kty_fitting, limits=None, kty=_kty())
    assert err.value.field == "family"


def test_ptc_fitting_needs_t_nat() -> None:
    with pytest.raises(InvalidInputError) as err:
        SensorFitting(family="X", sensor=TemperatureSensor.PTC)
    assert err.value.field == "nominal_response_temperature_c"


# --------------------------------------------------------------------------- overload


def test_overload_example_k2_tau600() -> None:
    # 600 s · ln(4/3) = 600 · 0.2876821 = 172.609 s
    assert overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600) == pytest.approx(
        172.609, abs=1e-3
    )


def test_preload_shortens_the_overload() -> None:
    cold = overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600)
    # p = 0.5: 600 · ln((4 − 0.25)/3) = 600 · ln 1.25 = 133.886 s
    warm = overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600, preload_factor=0.5)
    assert warm == pytest.approx(133.886, abs=1e-3)
    assert cold is not None
    assert warm is not None
    assert warm < cold
    # p = 1: the winding already sits at its limit.
    assert overload_duration_s(
        overload_factor=2.0, thermal_time_constant_s=600, preload_factor=1.0
    ) == pytest.approx(0.0, abs=1e-12)


def test_preload_above_stall_current_is_refused() -> None:
    with pytest.raises(InvalidInputError) as err:
        overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600, preload_factor=1.01)
    assert err.value.field == "preload_factor"


@pytest.mark.parametrize("k", [0.0, 0.5, 0.999, 1.0])
def test_no_shutdown_at_or_below_stall_current(k: float) -> None:
    assert overload_duration_s(overload_factor=k, thermal_time_constant_s=600) is None
    with pytest.raises(InvalidInputError) as err:
        finite_overload_duration_s(overload_factor=k, thermal_time_constant_s=600)
    assert err.value.field == "overload_factor"


def test_duration_grows_without_bound_as_k_approaches_one() -> None:
    # k = 1.0001: k² − 1 = 2.0001e-4, ln(1.00020001/2.0001e-4) = ln 5000.75 = 8.5173
    t = finite_overload_duration_s(overload_factor=1.0001, thermal_time_constant_s=600)
    assert t == pytest.approx(600 * 8.5173, rel=1e-4)
    durations = [
        finite_overload_duration_s(overload_factor=1 + 10.0**-e, thermal_time_constant_s=600)
        for e in range(1, 8)
    ]
    assert durations == sorted(durations)


def test_large_overload_approaches_tau_over_k_squared() -> None:
    # ln(k²/(k² − 1)) ≈ 1/(k² − 1) for large k: k = 10 → 600/99 = 6.06 s.
    t = finite_overload_duration_s(overload_factor=10, thermal_time_constant_s=600)
    assert t == pytest.approx(600 / 99, rel=1e-2)


def test_formula_agrees_with_the_heat_equation() -> None:
    """dθ/dt = (k² − θ)/τ from θ = p², integrated until θ = 1 (θ in units of the limit)."""
    tau, k, p = 600.0, 1.5, 0.6
    theta, t, dt = p * p, 0.0, 0.01
    while theta < 1.0:
        # exact step of the linear ODE, so only the stopping time is discretised
        theta = k * k + (theta - k * k) * math.exp(-dt / tau)
        t += dt
    expected = finite_overload_duration_s(
        overload_factor=k, thermal_time_constant_s=tau, preload_factor=p
    )
    assert t == pytest.approx(expected, abs=dt)


def test_overload_above_i_max_is_out_of_range() -> None:
    with pytest.raises(OutOfRangeError) as err:
        overload_duration_s(
            overload_factor=2.0, thermal_time_constant_s=600, max_overload_factor=1.74
        )
    assert err.value.field == "overload_factor"


def test_thermal_time_constant_must_be_positive() -> None:
    with pytest.raises(InvalidInputError) as err:
        overload_duration_s(overload_factor=2.0, thermal_time_constant_s=0)
    assert err.value.field == "thermal_time_constant_s"


def test_overload_curve_for_cha_25a_50() -> None:
    k_max = 4.0 / 2.3  # I_max / I_0 of the CHA-25A-50
    curve = overload_curve(thermal_time_constant_s=600, max_overload_factor=k_max, points=10)
    assert len(curve) == 10
    assert curve[0].overload_factor == pytest.approx(1 + (k_max - 1) / 10)
    assert curve[-1].overload_factor == pytest.approx(k_max)
    assert all(p.overload_factor > 1 for p in curve)
    durations = [p.duration_s for p in curve]
    assert durations == sorted(durations, reverse=True)
    assert curve[-1].duration_s == pytest.approx(600 * math.log(k_max**2 / (k_max**2 - 1)))


def test_overload_curve_needs_overload() -> None:
    with pytest.raises(InvalidInputError) as err:
        overload_curve(thermal_time_constant_s=600, max_overload_factor=1.0)
    assert err.value.field == "max_overload_factor"
