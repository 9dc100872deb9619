"""Loading controllers (Table 521.1), sensors (Tables 518.1, 519.2) and actuator interfaces.

Works like :mod:`actuator_selection.db.seed`: every file is validated first (with
the same CSV rules), one bad cell loads nothing, loading again changes nothing.
Runs after the families and actuators are loaded, in the same transaction.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from actuator_selection.core.compatibility import (
    MARK_COLUMNS,
    BusClass,
    FeedbackSystem,
    parse_support_level,
)
from actuator_selection.core.errors import DomainError
from actuator_selection.core.thermal import TemperatureSensor
from actuator_selection.db.csvio import (
    CatalogueFileError,
    Column,
    CsvSpec,
    Problem,
    Record,
    Rule,
    read,
)
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorInterfaceRow,
    ActuatorRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
)
from actuator_selection.db.repositories import CatalogueVersionRepository
from actuator_selection.db.seed import SeedReport

CONTROLLERS = CsvSpec(
    file="controllers.csv",
    key=("source_row",),
    columns=(
        Column(name="source_row", numeric=True, required=True, rule=Rule.POSITIVE),
        Column(name="manufacturer", required=True),
        Column(name="type", required=True),
        Column(name="variant"),
        *(Column(name=column) for _, _, column in MARK_COLUMNS),
        Column(name="correction"),
        Column(name="source", required=True),
    ),
)

SENSOR_FITTINGS = CsvSpec(
    file="temperature_sensors.csv",
    key=("family", "variant", "sensor"),
    columns=(
        Column(name="family", required=True),
        Column(name="variant"),
        Column(name="sensor", required=True),
        Column(name="designation"),
        Column(name="sensor_count", numeric=True, required=True, rule=Rule.POSITIVE),
        Column(name="nominal_response_temperature_c", numeric=True),
        Column(name="note"),
        Column(name="source", required=True),
    ),
)

KTY_POINTS = CsvSpec(
    file="kty84_130.csv",
    key=("temperature_c",),
    columns=(
        Column(name="temperature_c", numeric=True, required=True),
        Column(name="resistance_ohm", numeric=True, required=True, rule=Rule.POSITIVE),
        Column(name="source", required=True),
    ),
)

BUS_CLASSES = CsvSpec(
    file="dc_bus_classes.csv",
    key=("bus_class",),
    columns=(
        Column(name="bus_class", required=True),
        Column(name="label", required=True),
        Column(name="nominal_dc_voltage_v", numeric=True, required=True, rule=Rule.POSITIVE),
        Column(name="derivation"),
        Column(name="source", required=True),
    ),
)

INTERFACES = CsvSpec(
    file="actuator_interfaces.csv",
    key=("actuator_model",),
    columns=(
        Column(name="actuator_model", required=True),
        Column(name="dc_bus_classes"),
        Column(name="temperature_sensors"),
        Column(name="feedback_systems"),
        Column(name="derivation"),
        Column(name="source", required=True),
    ),
)

_OPTION_TYPES: dict[str, type[BusClass] | type[TemperatureSensor] | type[FeedbackSystem]] = {
    "dc_bus_classes": BusClass,
    "temperature_sensors": TemperatureSensor,
    "feedback_systems": FeedbackSystem,
}


def _problem(spec: CsvSpec, record: Record, column: str, message: str) -> Problem:
    return Problem(file=spec.file, line=record.line, column=column, message=message)


def _check_rows(
    session: Session,
    controllers: list[Record],
    fittings: list[Record],
    buses: list[Record],
    interfaces: list[Record],
) -> list[Problem]:
    """The rules that plain CSV typing cannot express: marks, option names, known keys."""
    problems: list[Problem] = []
    for r in controllers:
        for _, _, column in MARK_COLUMNS:
            try:
                parse_support_level(r.values[column], field=column)
            except DomainError as exc:
                problems.append(_problem(CONTROLLERS, r, column, exc.message))
    families = set(session.scalars(select(ActuatorFamilyRow.name)))
    sensors = {s.value for s in TemperatureSensor}
    for r in fittings:
        if r.values["family"] not in families:
            problems.append(_problem(SENSOR_FITTINGS, r, "family", "unknown family"))
        if r.values["sensor"] not in sensors:
            problems.append(
                _problem(
                    SENSOR_FITTINGS, r, "sensor", f"must be one of {', '.join(sorted(sensors))}"
                )
            )
    bus_names = {b.value for b in BusClass}
    for r in buses:
        if r.values["bus_class"] not in bus_names:
            problems.append(
                _problem(
                    BUS_CLASSES, r, "bus_class", f"must be one of {', '.join(sorted(bus_names))}"
                )
            )
    models = set(session.scalars(select(ActuatorRow.model)))
    for r in interfaces:
        if r.values["actuator_model"] not in models:
            problems.append(_problem(INTERFACES, r, "actuator_model", "unknown actuator model"))
        for column, option_type in _OPTION_TYPES.items():
            allowed = {o.value for o in option_type}
            for option in (r.values[column] or "").split():
                if option not in allowed:
                    problems.append(
                        _problem(
                            INTERFACES,
                            r,
                            column,
                            f"unknown option {option!r} (one of {', '.join(sorted(allowed))})",
                        )
                    )
    return problems


def _upsert(
    session: Session, model: type[Any], key: tuple[str, ...], rows: list[dict[str, Any]]
) -> tuple[int, int, int]:
    """Insert or update ``rows`` of ``model`` matched on ``key``; (inserted, updated, unchanged)."""
    existing = {tuple(getattr(o, k) for k in key): o for o in session.scalars(select(model))}
    inserted = updated = unchanged = 0
    for values in rows:
        row = existing.get(tuple(values[k] for k in key))
        if row is None:
            session.add(model(**values))
            inserted += 1
            continue
        changed = [k for k, v in values.items() if getattr(row, k) != v]
        for k in changed:
            setattr(row, k, values[k])
        if changed:
            updated += 1
        else:
            unchanged += 1
    session.flush()
    return inserted, updated, unchanged


def load_controllers(session: Session, directory: Path) -> SeedReport:
    """Validate and upsert the controller and winding-protection files (the caller commits).

    Raises
    ------
    CatalogueFileError
        Listing every problem; nothing has been written then.
    """
    results = [
        read(spec, directory)
        for spec in (CONTROLLERS, SENSOR_FITTINGS, KTY_POINTS, BUS_CLASSES, INTERFACES)
    ]
    problems = [p for _, found in results for p in found]
    (controllers, _), (fittings, _), (kty, _), (buses, _), (interfaces, _) = results
    if not problems:
        problems = _check_rows(session, controllers, fittings, buses, interfaces)
    if problems:
        raise CatalogueFileError(problems)

    family_ids = {f.name: f.id for f in session.scalars(select(ActuatorFamilyRow))}
    actuator_ids = {a.model: a.id for a in session.scalars(select(ActuatorRow))}

    def controller(values: dict[str, Any]) -> dict[str, Any]:
        return {**values, "source_row": int(values["source_row"])}

    def fitting(values: dict[str, Any]) -> dict[str, Any]:
        out = {k: v for k, v in values.items() if k != "family"}
        return {
            **out,
            "family_id": family_ids[values["family"]],
            "sensor_count": int(values["sensor_count"]),
        }

    def interface(values: dict[str, Any]) -> dict[str, Any]:
        out = {k: v for k, v in values.items() if k != "actuator_model"}
        return {**out, "actuator_id": actuator_ids[values["actuator_model"]]}

    totals = [0, 0, 0]
    for model, key, rows in (
        (ControllerRow, ("source_row",), [controller(r.values) for r in controllers]),
        (
            SensorFittingRow,
            ("family_id", "variant", "sensor"),
            [fitting(r.values) for r in fittings],
        ),
        (
            SensorPointRow,
            ("sensor", "temperature_c"),
            [{**r.values, "sensor": TemperatureSensor.KTY84_130.value} for r in kty],
        ),
        (DcBusClassRow, ("bus_class",), [r.values for r in buses]),
        (ActuatorInterfaceRow, ("actuator_id",), [interface(r.values) for r in interfaces]),
    ):
        for i, n in enumerate(_upsert(session, model, key, rows)):
            totals[i] += n
    if totals[0] or totals[1]:
        CatalogueVersionRepository(session).bump()
    return SeedReport(inserted=totals[0], updated=totals[1], unchanged=totals[2])
