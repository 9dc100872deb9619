"""The flowchart on plain floats, one actuator at a time: the test oracle of the engine.

The service runs one engine (:mod:`actuator_selection.sizing.engine`), on arrays, for one
actuator and for 64,000. This is the flowchart written out again on Python floats, as the
chapter reads (p. 514–517): for each actuator the torques of its cycle
(:meth:`~actuator_selection.sizing.motion.Profile.torques`), the operands by name, and each
rule's :meth:`~actuator_selection.sizing.checks.Rule.check`. The parity tests compare the
engine with it cell by cell, with ``==``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.fields import OPERAND_FIELDS
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.bearing import life_exponent, swing_deg
from actuator_selection.sizing.candidates import Candidate, Selection, Verdict, ranking_key
from actuator_selection.sizing.checks import Check, Operands, Rule, Status, rules_for
from actuator_selection.sizing.electrical import no_load_torque_slope_nm_per_rpm
from actuator_selection.sizing.motion import CycleTorques, Profile
from actuator_selection.sizing.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S
from actuator_selection.sizing.zones import torque_limit_nm


def _verdict(checks: Iterable[Check]) -> Verdict:
    statuses = {c.status for c in checks}
    if Status.FAIL in statuses:
        return Verdict.UNSUITABLE
    if Status.NO_DATA in statuses:
        return Verdict.UNCONFIRMED
    return Verdict.SUITABLE


def operands(
    actuator: Actuator,
    app: Application,
    torques: CycleTorques | None,
    profile: Profile,
    heating: dict[float, Heating] | None = None,
) -> Operands:
    """The floats the rules compute from, NaN for what the catalogue does not publish.

    Parameters
    ----------
    actuator
        The catalogue entry.
    app
        The load case.
    torques
        T_1, T_2, T_3, T_rms (Eq. 514.1, 514.2) [Nm]; None without J_A.
    profile
        The cycle's figures: n_av (Eq. 514.3), peak speed, the least T_1, |T_3|, T_rms
        over every J_A ≥ 0, the torque held at standstill.
    heating
        The cycle's heating per τ_th (:data:`Heating`), filled as computed: pass the same
        dict for every actuator of one case.
    """
    nan = math.nan
    zone = actuator.zone
    n_av = profile.mean_speed_rpm
    zone_torque = None if zone is None else torque_limit_nm(zone, n_av)
    # The oracle's own reading of the catalogue, independent of the engine's
    # (CATALOGUE_OPERANDS): in the oracle's order (ORDER), named by it.
    values = (
        profile.peak_speed_rpm,
        profile.load.inertia_kgm2,
        app.high_dynamics,
        n_av,
        nan if torques is None else torques.accel_torque_nm,
        nan if torques is None else torques.decel_torque_nm,
        nan if torques is None else torques.rms_torque_nm,
        nan if actuator.max_torque_nm is None else actuator.max_torque_nm,
        nan if actuator.max_speed_rpm is None else actuator.max_speed_rpm,
        nan if actuator.inertia_kgm2 is None else actuator.inertia_kgm2,
        nan if actuator.stall_torque_nm is None else actuator.stall_torque_nm,
        nan if actuator.continuous_torque_nm is None else actuator.continuous_torque_nm,
        zone is not None,
        nan if zone_torque is None else zone_torque,
        nan if zone is None else zone.max_speed_rpm,
        profile.accel_floor_nm,
        profile.decel_floor_nm,
        profile.rms_floor_nm,
        nan if actuator.continuous_speed_rpm is None else actuator.continuous_speed_rpm,
        nan if actuator.rated_speed_rpm is None else actuator.rated_speed_rpm,
        profile.holding_torque_nm,
        nan if actuator.brake_holding_torque_nm is None else actuator.brake_holding_torque_nm,
        *_drive_and_bearing(actuator, app, profile),
        *_thermal(actuator, app, torques, profile, {} if heating is None else heating),
        *_gear_stiffness_brake(actuator, app, profile),
    )
    # A published value the oracle does not read itself above is read as published.
    published = {
        name: _value(getattr(actuator, f.name))
        for f in OPERAND_FIELDS
        if (name := f.operand_name) is not None and name not in ORDER
    }
    return Operands(**dict(zip(ORDER, values, strict=True)), **published)


ORDER = (
    "speed_rpm",
    "load_inertia_kgm2",
    "high_dynamics",
    "mean_speed_rpm",
    "accel_torque_nm",
    "decel_torque_nm",
    "rms_torque_nm",
    "max_torque_nm",
    "max_speed_rpm",
    "inertia_kgm2",
    "stall_torque_nm",
    "continuous_torque_nm",
    "has_zone",
    "zone_torque_nm",
    "zone_max_speed_rpm",
    "accel_torque_floor_nm",
    "decel_torque_floor_nm",
    "rms_torque_floor_nm",
    "continuous_speed_rpm",
    "rated_speed_rpm",
    "load_torque_nm",
    "brake_holding_torque_nm",
    "decel_s",
    "gear_ratio",
    "torque_constant_nm_per_a",
    "max_current_a",
    "no_load_starting_current_a",
    "no_load_current_constant_a_per_rpm",
    "motor_voltage_constant_v_per_krpm",
    "resistance_line_ohm",
    "inductance_line_h",
    "pole_pairs",
    "dc_bus_voltage_v",
    "radial_force_n",
    "axial_force_n",
    "radial_lever_m",
    "axial_lever_m",
    "load_factor",
    "static_safety_min",
    "required_life_h",
    "swing_deg",
    "bearing_pitch_diameter_m",
    "bearing_offset_m",
    "bearing_dynamic_load_rating_n",
    "bearing_static_load_rating_n",
    "bearing_life_exponent",
    "bearing_moment_load_nm",
    "bearing_dynamic_tilting_moment_nm",
    "cycle_s",
    "thermal_time_constant_s",
    "thermal_time_constant_assumed",
    "thermal_torque_nm",
    "thermal_speed_rpm",
    "no_load_torque_slope_nm_per_rpm",
    "gear_torque_cube_nm3",
    "gear_required_life_h",
    "momentary_torque_nm",
    "momentary_count",
    "min_natural_frequency_hz",
    "brake_safety_factor",
    "emergency_stops",
    "drop_torque_nm",
    "travel_mm_per_rad",
    "limit_torque_t1_nm",
    "limit_torque_t2_nm",
    "stiffness_k1_nm_per_rad",
    "stiffness_k2_nm_per_rad",
    "stiffness_k3_nm_per_rad",
    "brake_emergency_stop_count",
    "brake_closing_time_s",
    "gear_average_torque_limit_nm",
    "gear_repeated_peak_torque_nm",
    "gear_momentary_peak_torque_nm",
    "gear_momentary_peak_count",
    "gear_average_input_speed_limit_rpm",
    "gear_rated_torque_nm",
    "gear_rated_life_h",
    "gear_life_basis",
    "bearing_radial_load_n",
    "bearing_axial_load_n",
)
"""The operands :func:`operands` reads itself, in its order (its helpers return theirs in
this order); a catalogue value declared since is read as published, from the registry."""


Heating = tuple[tuple[tuple[float, ...], float], float]
"""A cycle's heating gains (:meth:`~actuator_selection.sizing.motion.Profile.heating_gains`)
and its n_th (:meth:`~actuator_selection.sizing.motion.Profile.thermal_speed_rpm`) for one
τ_th: the same for every actuator without a published τ_th, so computed once per τ_th."""


def _thermal(
    actuator: Actuator,
    app: Application,
    torques: CycleTorques | None,
    profile: Profile,
    heating: dict[float, Heating],
) -> tuple[float, ...]:
    """The operands after the output bearing's: t_0, τ_th (the catalogue's, else the
    application's, else the assumed default), whether τ_th is that assumption, the peak
    of the cycle's heating as a torque (NaN without J_A) and as a speed, and k_T·K_INL."""
    tau = actuator.thermal_time_constant_s
    assumed = False
    if tau is None:
        tau = app.thermal_time_constant_s
        if tau is None:
            tau, assumed = DEFAULT_THERMAL_TIME_CONSTANT_S, True
    known = heating.get(tau)
    if known is None:
        gains = profile.heating_gains(tau)
        known = heating[tau] = (gains, profile.thermal_speed_rpm(*gains))
    gains, speed = known
    slope = no_load_torque_slope_nm_per_rpm(
        torque_constant_nm_per_a=actuator.torque_constant_nm_per_a,
        constant_30c_a_per_rpm=actuator.no_load_current_constant_30c_a_per_rpm,
        constant_80c_a_per_rpm=actuator.no_load_current_constant_80c_a_per_rpm,
    )
    if torques is None or actuator.inertia_kgm2 is None:
        peak = math.nan
    else:
        # On the winding current where the current-based edge stands (no zone, T_0).
        on_current = actuator.zone is None and actuator.stall_torque_nm is not None
        peak = profile.thermal_torque_nm(
            actuator.inertia_kgm2, *gains, slope if on_current else None
        )
    return (
        profile.cycle_s,
        tau,
        assumed,
        peak,
        speed,
        _value(slope),
    )


def _gear_stiffness_brake(
    actuator: Actuator, app: Application, profile: Profile
) -> tuple[float, ...]:
    """The operands after k_T·K_INL: the cube of the gear's T_av written out from the
    component catalogues' sum (CSD-2A 1019659 11/2014, p. 18), each piece at its mean |n|
    and the larger |T| of its ends, the request's further inputs, then the stiffness, brake
    and gear catalogue values."""
    a, nan = actuator, math.nan
    cube = weight = 0.0
    if a.inertia_kgm2 is None:
        t_cube = nan
    else:
        for p in profile.pieces:
            w = (abs(p.start_rpm) + abs(p.end_rpm)) / 2.0 * p.duration_s
            inertia = a.inertia_kgm2 + p.inertia_kgm2
            t0 = p.static_nm + inertia * p.accel_start
            t1 = p.static_nm + inertia * p.accel_end
            largest = max(abs(t0), abs(t1))
            cube = cube + w * (largest * largest * largest)
            weight = weight + w
        t_cube = cube / weight if weight > 0 else nan
    basis = {"L10": 10.0, "L50": 50.0}
    return (
        t_cube,
        _value(app.gear_required_life_h),
        _value(app.momentary_torque_nm),
        _value(app.momentary_count),
        _value(app.min_natural_frequency_hz),
        app.brake_safety_factor,
        _value(app.emergency_stops),
        # the brake's drop: the axis's weight |T_G| (the shorthand: NaN, its T_L), and the
        # travel per output radian of a linear axis, 60/(2π·k) with k rpm per mm/s
        nan if app.motion is None else abs(app.motion.load.gravity_torque_nm),
        nan
        if app.motion is None or app.motion.load.speed_unit != "mm/s"
        else 60.0 / (2.0 * math.pi * app.motion.load.speed_rpm_per_unit),
        _value(a.limit_torque_t1_nm),
        _value(a.limit_torque_t2_nm),
        _value(a.torsional_stiffness_k1_nm_per_rad),
        _value(a.torsional_stiffness_k2_nm_per_rad),
        _value(a.torsional_stiffness_k3_nm_per_rad),
        _value(a.brake_emergency_stop_count),
        _value(a.brake_closing_time_s),
        _value(a.gear_average_torque_limit_nm),
        _value(a.gear_repeated_peak_torque_nm),
        _value(a.gear_momentary_peak_torque_nm),
        _value(a.gear_momentary_peak_count),
        _value(a.gear_average_input_speed_limit_rpm),
        _value(a.gear_rated_torque_nm),
        _value(a.gear_rated_life_h),
        nan if (life := a.text("gear_life_basis")) is None else basis[life],
        _value(a.output_bearing_radial_load_n),
        _value(a.output_bearing_axial_load_n),
    )


def _where(condition: bool, if_true: float, if_false: float) -> float:
    return if_true if condition else if_false


def _value(value: float | None) -> float:
    return math.nan if value is None else value


def _drive_and_bearing(actuator: Actuator, app: Application, profile: Profile) -> tuple[float, ...]:
    """The operands after ``brake_holding_torque_nm``: the drive's and the output bearing's
    catalogue values and the output load, in the order of :class:`Operands`."""
    a, nan = actuator, math.nan
    k_inl = a.no_load_current_constant_30c_a_per_rpm
    inductance = a.inductance_line_mh
    load = app.output_load
    if load is None:
        forces: tuple[float, ...] = (nan,) * 8
    else:
        forces = (
            load.radial_force_n,
            load.axial_force_n,
            load.radial_lever_m,
            load.axial_lever_m,
            load.load_factor,
            load.static_safety_min,
            _value(load.required_life_h),
            swing_deg(
                (
                    (p.duration_s, p.start_rpm, p.end_rpm, p.accel_start, p.accel_end)
                    for p in profile.pieces
                ),
                _where,
            ),
        )
    return (
        profile.braking_s,
        a.gear_ratio,
        _value(a.torque_constant_nm_per_a),
        _value(a.max_current_a),
        _value(a.no_load_starting_current_a),
        _value(k_inl),
        _value(a.motor_voltage_constant_v_per_krpm),
        _value(a.resistance_line_ohm),
        nan if inductance is None else inductance / 1000.0,
        _value(a.pole_pairs),
        _value(a.dc_bus_voltage_v),
        *forces,
        _value(a.output_bearing_pitch_diameter_m),
        _value(a.output_bearing_offset_m),
        _value(a.output_bearing_dynamic_load_rating_n),
        _value(a.output_bearing_static_load_rating_n),
        life_exponent(a.text("output_bearing_type")),
        _value(a.output_bearing_moment_load_nm),
        _value(a.output_bearing_dynamic_tilting_moment_nm),
    )


def evaluate(
    actuator: Actuator, app: Application, *, rules: Sequence[Rule] | None = None
) -> Candidate:
    """Run the flowchart's checks (``rules``, by default :func:`rules_for`: the
    chapter's, and the brake's where fitted) for one actuator."""
    (candidate,) = evaluate_each((actuator,), app, rules=rules)
    return candidate


def evaluate_each(
    actuators: Iterable[Actuator],
    app: Application,
    *,
    rules: Sequence[Rule] | None = None,
) -> list[Candidate]:
    """:func:`evaluate` for each of ``actuators`` in turn, the cycle prepared once."""
    if rules is None:
        rules = rules_for(app)
    profile = app.profile
    heating: dict[float, Heating] = {}  # per τ_th, for every actuator
    candidates = []
    for actuator in actuators:
        torques = (
            profile.torques(actuator.inertia_kgm2) if actuator.inertia_kgm2 is not None else None
        )
        q = operands(actuator, app, torques, profile, heating)
        checks = tuple([rule.check(q) for rule in rules])
        candidates.append(
            Candidate(actuator=actuator, verdict=_verdict(checks), torques=torques, checks=checks)
        )
    return candidates


def select(
    actuators: Iterable[Actuator], app: Application, *, rules: Sequence[Rule] | None = None
) -> Selection:
    """Run the flowchart for every actuator and rank the candidates (:func:`ranking_key`)."""
    candidates = sorted(evaluate_each(actuators, app, rules=rules), key=ranking_key)
    profile = app.profile
    return Selection(
        mean_speed_rpm=profile.mean_speed_rpm,
        duty_cycle_percent=profile.duty_cycle_percent,
        cycle_time_s=profile.cycle_s,
        candidates=tuple(candidates),
        profile=profile,
    )
