"""The machine project's answer (``ProjectOut``): each axis's sizing and power, the bus's
figures, what absorbs the regeneration, and the curve for the stacked chart."""

from __future__ import annotations

from dataclasses import asdict
from datetime import datetime
from typing import Any

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.schemas.projects import AxisIn, ProjectRequest
from actuator_selection.sizing.bus import (
    SIGMAS,
    AxisPower,
    BrakingResistor,
    Bus,
    Capacitor,
    PowerFigures,
    sample_curve,
)

JSON = dict[str, Any]

PHASING_METHOD = (
    "worst case: every axis's own peak at one instant (Σ max P_i, the largest any offsets "
    f"give); statistical: μ + {SIGMAS:g}σ of the bus power at a random instant with "
    "independent phases uniform over the cycle (μ = Σ μ_i, σ² = Σ σ_i², exact; the "
    "quantile by the normal approximation)"
)


def _power(f: PowerFigures) -> JSON:
    out = {
        k: v
        for k, v in asdict(f).items()
        if k not in ("cycle_s", "variance_w2", "regen_pulse_energies_j")
    }
    out["std_w"] = f.variance_w2**0.5
    return out


def _checks(candidate: JSON, rules: list[JSON]) -> list[JSON]:
    """The candidate's checks, each whole (``AxisCheckOut``) with its rule's unit and
    reference."""
    by_name = {r["name"]: r for r in rules}
    return [
        {
            "name": c["name"],
            "status": c["status"],
            "value": c["value"],
            "limit": c["limit"],
            "approximate": c.get("approximate", False),
            "missing": c.get("missing"),
            "unit": by_name[c["name"]]["unit"],
            "reference": by_name[c["name"]]["reference"],
        }
        for c in candidate["checks"]
    ]


def axis_body(
    axis: AxisIn, actuator: Actuator, candidate: JSON, rules: list[JSON], power: AxisPower
) -> JSON:
    """One axis: its actuator, its selection's candidate figures and checks (``rules``: the
    selection's ``check_rules``), and its power."""
    return {
        "name": axis.name,
        "offset_s": axis.offset_s,
        "model": actuator.model,
        "chosen": axis.model is not None,
        "verdict": candidate["verdict"],
        "checks": _checks(candidate, rules),
        "gear_ratio": actuator.gear_ratio,
        "accel_torque_nm": candidate["accel_torque_nm"],
        "decel_torque_nm": candidate["decel_torque_nm"],
        "rms_torque_nm": candidate["rms_torque_nm"],
        "copper_loss_published": power.copper_loss_published,
        "no_load_loss_published": power.no_load_loss_published,
        "energies": {f"{name}_j": value for name, value in power.energies_j().items()},
        "power": _power(power.figures()),
    }


def project_answer(
    *,
    id: str,
    created_at: datetime,
    updated_at: datetime,
    catalogue_version: int,
    body: ProjectRequest,
    axes: list[JSON],
    bus: Bus,
    cap: Capacitor,
    resistor: BrakingResistor,
    controllers: JSON,
) -> JSON:
    """The whole answer, as JSON data."""
    times, values = sample_curve(bus)
    return {
        "id": id,
        "created_at": created_at,
        "updated_at": updated_at,
        "catalogue_version": catalogue_version,
        "request": body.model_dump(mode="json"),
        "cycle_time_s": bus.cycle_s,
        "axes": axes,
        "bus": {
            "bus_class": body.bus.bus_class.value,
            "nominal_voltage_v": cap.nominal_voltage_v,
            **controllers,
            "power": _power(bus.figures),
            "capacitor": {
                "capacitance_uf": body.bus.capacitance_uf,
                "nominal_voltage_v": cap.nominal_voltage_v,
                "max_voltage_v": cap.max_voltage_v,
                "energy_j": cap.energy_j,
                "absorbs_every_pulse": cap.absorbs_every_pulse,
                "reference": cap.reference,
            },
            "braking_resistor": {**asdict(resistor), "min_resistance_ohm": None},
            "random_phasing": {**asdict(bus.phasing), "method": PHASING_METHOD},
        },
        "curve": {"times_s": times, "axes_w": values},
    }
