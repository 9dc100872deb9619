"""Engineering tools of the chapter's second half (Fig. 520.1, Eq. 521.2–522.3, Table 519.2);
the use cases are ``services/tools.py``."""

from __future__ import annotations

from fastapi import APIRouter

from actuator_selection.http.deps import SessionDep, reads_only
from actuator_selection.schemas.tools import (
    ControllerVoltageOut,
    ControllerVoltageRequest,
    OutputTorqueOut,
    OutputTorqueRequest,
    OverloadDurationOut,
    OverloadDurationRequest,
    SensorTemperatureOut,
    SensorTemperatureRequest,
)
from actuator_selection.services import tools

router = APIRouter(prefix="/tools", tags=["tools"])


@router.post("/controller-voltage")
@reads_only
def controller_voltage(body: ControllerVoltageRequest, session: SessionDep) -> ControllerVoltageOut:
    """Minimum controller output voltage U_OUT (Eq. 521.2) and what each bus class delivers."""
    return tools.controller_voltage(body, session)


@router.post("/sensor-temperature")
@reads_only
def sensor_temperature(body: SensorTemperatureRequest, session: SessionDep) -> SensorTemperatureOut:
    """A winding sensor's resistance read as temperature (KTY) or zone (PTC), and its state."""
    return tools.sensor_temperature(body, session)


@router.post("/overload-duration")
@reads_only
def overload_duration(body: OverloadDurationRequest, session: SessionDep) -> OverloadDurationOut:
    """Time until the winding reaches its limit at overload factor k (model of Fig. 520.1)."""
    return tools.overload_duration(body, session)


@router.post("/output-torque")
@reads_only
def output_torque(body: OutputTorqueRequest, session: SessionDep) -> OutputTorqueOut:
    """Output torque from the measured current (Eq. 522.2, 522.3)."""
    return tools.output_torque(body, session)
