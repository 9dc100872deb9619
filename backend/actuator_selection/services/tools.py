"""Engineering tools of the chapter's second half (Fig. 520.1, Eq. 521.2–522.3, Table 519.2):
a value asked for on its own, from the request's numbers or an actuator's catalogue data."""

from __future__ import annotations

from sqlalchemy.orm import Session

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.repositories import CatalogueRepository
from actuator_selection.errors import InvalidInputError, MissingDataError, NotFoundError
from actuator_selection.schemas.tools import (
    BusVoltageOut,
    ControllerVoltageOut,
    ControllerVoltageRequest,
    OutputTorqueOut,
    OutputTorqueRequest,
    OverloadDurationOut,
    OverloadDurationRequest,
    OverloadPointOut,
    PtcOut,
    SensorTemperatureOut,
    SensorTemperatureRequest,
)
from actuator_selection.sizing.electrical import (
    check_output_voltage,
    controller_output_voltage,
    motor_speed_rpm,
    output_torque_from_current,
)
from actuator_selection.sizing.thermal import (
    classify_kty_reading,
    classify_ptc_reading,
    finite_overload_duration_s,
    overload_curve,
)


def _actuator(session: Session, model: str | None) -> Actuator | None:
    if model is None:
        return None
    record = CatalogueRepository(session).actuator(model)
    if record is None:
        raise NotFoundError("model", f"unknown actuator model {model!r}")
    return record.actuator


def _need(
    explicit: float | None, actuator: Actuator | None, attribute: str, field: str, what: str
) -> float:
    """The request's value, else the catalogue's; a clear 422 when neither has it."""
    if explicit is not None:
        return explicit
    if actuator is None:
        raise InvalidInputError(field, f"is required without a model ({what})")
    value: float | None = getattr(actuator, attribute)
    if value is None:
        raise MissingDataError(
            field,
            f"no data: the catalogue gives no {what} for {actuator.model}; give {field} explicitly",
        )
    return value


def controller_voltage(body: ControllerVoltageRequest, session: Session) -> ControllerVoltageOut:
    """Minimum controller output voltage U_OUT (Eq. 521.2 with ωL·I in quadrature, the
    formula of the selection's ``drive_voltage`` check) and what each bus class delivers."""
    a = _actuator(session, body.model)
    ratio = _need(body.gear_ratio, a, "gear_ratio", "gear_ratio", "gear ratio")
    k_e = _need(
        body.voltage_constant_v_per_krpm,
        a,
        "motor_voltage_constant_v_per_krpm",
        "voltage_constant_v_per_krpm",
        "motor voltage constant K_E per 1000 rpm",
    )
    i_max = _need(body.max_current_a, a, "max_current_a", "max_current_a", "maximum current I_max")
    r = _need(
        body.resistance_ohm,
        a,
        "resistance_line_ohm",
        "resistance_ohm",
        "line-to-line winding resistance R",
    )
    l_mh = _need(
        body.inductance_mh,
        a,
        "inductance_line_mh",
        "inductance_mh",
        "line-to-line winding inductance L",
    )
    poles = _need(body.pole_pairs, a, "pole_pairs", "pole_pairs", "number of pole pairs p")
    u = controller_output_voltage(
        output_speed_rpm=body.output_speed_rpm,
        gear_ratio=ratio,
        motor_voltage_constant_v_per_krpm=k_e,
        max_current_a=i_max,
        resistance_line_ohm=r,
        inductance_line_h=l_mh / 1000.0,
        pole_pairs=poles,
    )
    buses = [
        check_output_voltage(required_voltage_v=u.total_v, bus=b)
        for b in ProtectionRepository(session).bus_classes()
    ]
    return ControllerVoltageOut(
        voltage_v=u.total_v,
        back_emf_v=u.back_emf_v,
        resistive_v=u.resistive_v,
        inductive_v=u.inductive_v,
        printed_v=u.printed_v,
        output_speed_rpm=body.output_speed_rpm,
        motor_speed_rpm=u.motor_speed_rpm,
        gear_ratio=ratio,
        voltage_constant_v_per_krpm=k_e,
        max_current_a=i_max,
        resistance_ohm=r,
        inductance_mh=l_mh,
        pole_pairs=poles,
        bus_classes=[
            BusVoltageOut(
                bus_class=c.bus_class.value,
                dc_bus_voltage_v=c.dc_bus_voltage_v,
                available_voltage_v=c.available_voltage_v,
                sufficient=c.sufficient,
                margin_percent=c.margin_percent,
                message=c.message,
            )
            for c in buses
        ],
    )


def sensor_temperature(body: SensorTemperatureRequest, session: Session) -> SensorTemperatureOut:
    """A winding sensor's resistance read as temperature (KTY) or zone (PTC), and its state."""
    repo = ProtectionRepository(session)
    limits = repo.limits(body.family) if body.family is not None else None
    if body.sensor is TemperatureSensor.KTY84_130:
        kty = repo.kty()
        if limits is None:
            temperature = kty.temperature_c(body.resistance_ohm)
            why = "no family given" if body.family is None else f"Table 519.2 has no {body.family}"
            return SensorTemperatureOut(
                sensor=body.sensor.value,
                resistance_ohm=body.resistance_ohm,
                temperature_c=temperature,
                state=None,
                near_limit=None,
                ptc=None,
                family=body.family,
                message=f"{temperature:.4g} °C from the KTY 84-130 table; no state: {why}",
                reference="Fig. 519.1 (KTY 84-130 characteristic)",
            )
        assessment = classify_kty_reading(
            resistance_ohm=body.resistance_ohm, characteristic=kty, limits=limits
        )
    else:
        t_nat, count = body.nominal_response_temperature_c, body.sensor_count
        if body.family is not None and (t_nat is None or count is None):
            ptcs = [f for f in repo.fittings(body.family) if f.sensor is TemperatureSensor.PTC]
            temps = {f.nominal_response_temperature_c for f in ptcs}
            if len(temps) == 1 and None not in temps:
                t_nat = t_nat if t_nat is not None else ptcs[0].nominal_response_temperature_c
                count = count if count is not None else ptcs[0].sensor_count
            elif t_nat is None:
                raise InvalidInputError(
                    "nominal_response_temperature_c",
                    f"is required: Table 518.1 gives {body.family} "
                    + ("no PTC" if not ptcs else "several PTC response temperatures"),
                )
        if t_nat is None:
            raise InvalidInputError(
                "nominal_response_temperature_c", "is required for a PTC without a family"
            )
        assessment = classify_ptc_reading(
            resistance_ohm=body.resistance_ohm,
            nominal_response_temperature_c=t_nat,
            sensor_count=count or 1,
        )
    ptc = assessment.ptc
    return SensorTemperatureOut(
        sensor=body.sensor.value,
        resistance_ohm=body.resistance_ohm,
        temperature_c=assessment.temperature_c,
        state=assessment.state.value,
        near_limit=None if assessment.near_limit is None else assessment.near_limit.value,
        ptc=None
        if ptc is None
        else PtcOut(
            zone=ptc.zone.value,
            resistance_per_sensor_ohm=ptc.resistance_per_sensor_ohm,
            nominal_response_temperature_c=ptc.nominal_response_temperature_c,
            known_above_c=ptc.known_above_c,
            known_below_c=ptc.known_below_c,
        ),
        family=body.family,
        message=assessment.message,
        reference=assessment.reference,
    )


def overload_duration(body: OverloadDurationRequest, session: Session) -> OverloadDurationOut:
    """Time until the winding reaches its limit at overload factor k (model of Fig. 520.1)."""
    a = _actuator(session, body.model)
    tau = _need(
        body.thermal_time_constant_s,
        a,
        "thermal_time_constant_s",
        "thermal_time_constant_s",
        "thermal time constant",
    )
    if body.overload_factor <= 1:
        raise InvalidInputError(
            "overload_factor", "must be > 1: at or below the stall current there is no shutdown"
        )
    k_max = body.max_overload_factor
    if k_max is None and a is not None and a.max_current_a and a.stall_current_a:
        k_max = a.max_current_a / a.stall_current_a
    duration = finite_overload_duration_s(
        overload_factor=body.overload_factor,
        thermal_time_constant_s=tau,
        preload_factor=body.preload_factor,
    )
    curve = (
        None
        if k_max is None or k_max <= 1
        else [
            OverloadPointOut(overload_factor=p.overload_factor, time_to_shutdown_s=p.duration_s)
            for p in overload_curve(
                thermal_time_constant_s=tau,
                max_overload_factor=k_max,
                preload_factor=min(body.preload_factor, 1.0),
            )
        ]
    )
    return OverloadDurationOut(
        time_to_shutdown_s=duration,
        overload_factor=body.overload_factor,
        preload_factor=body.preload_factor,
        thermal_time_constant_s=tau,
        curve=curve,
    )


def output_torque(body: OutputTorqueRequest, session: Session) -> OutputTorqueOut:
    """Output torque from the measured current (Eq. 522.2, 522.3)."""
    a = _actuator(session, body.model)
    k_t = _need(
        body.torque_constant_nm_per_a,
        a,
        "torque_constant_nm_per_a",
        "torque_constant_nm_per_a",
        "output torque constant K_T",
    )
    i_nls = _need(
        body.no_load_starting_current_a,
        a,
        "no_load_starting_current_a",
        "no_load_starting_current_a",
        "no-load starting current I_NLS",
    )
    k_30 = _need(
        body.no_load_current_constant_30c_a_per_rpm,
        a,
        "no_load_current_constant_30c_a_per_rpm",
        "no_load_current_constant_30c_a_per_rpm",
        "K_INL at 30 °C",
    )
    k_80 = (
        body.no_load_current_constant_80c_a_per_rpm
        if body.no_load_current_constant_80c_a_per_rpm is not None
        else (a.no_load_current_constant_80c_a_per_rpm if a else None)
    )
    t = output_torque_from_current(
        current_a=body.current_a,
        output_speed_rpm=body.speed_rpm,
        torque_constant_nm_per_a=k_t,
        no_load_starting_current_a=i_nls,
        no_load_current_constant_30c_a_per_rpm=k_30,
        no_load_current_constant_80c_a_per_rpm=k_80,
        temperature_c=body.temperature_c,
        extrapolate=body.extrapolate,
    )
    return OutputTorqueOut(
        torque_nm=t.output_torque_nm,
        no_load_current_a=t.no_load_running_current_a,
        no_load_current_constant_a_per_rpm=t.no_load_current_constant_a_per_rpm,
        torque_producing_current_a=t.torque_producing_current_a,
        below_no_load_current=t.below_no_load_current,
        extrapolated=t.extrapolated,
        motor_speed_rpm=(
            motor_speed_rpm(output_speed_rpm=body.speed_rpm, gear_ratio=a.gear_ratio) if a else None
        ),
        message=t.message,
        reference=t.reference,
    )
