"""The controller files of the catalogue: Table 521.1, sensors (Tables 518.1, 519.2), interfaces.

Their rules (``CsvSpec``) serve the seed loader, the catalogue import and the
admin API alike, as the actuator files' rules in :mod:`actuator_selection.db.seed`
do; that module reads, checks and writes all catalogue files together, this
one knows what the controller-side files hold and how they are stored.

Rows of ``controllers.csv`` are numbered by ``source_row``: Table 521.1's rows
keep their printed numbers (1 below the heading), rows added later take
further numbers, and ``source`` says where each row comes from.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Mapping, Sequence
from datetime import datetime
from enum import StrEnum
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from actuator_selection.core.compatibility import (
    MARK_COLUMNS,
    BusClass,
    FeedbackSystem,
    parse_support_level,
)
from actuator_selection.core.csvio import (
    Column,
    CsvSpec,
    Problem,
    Record,
    Rule,
    one_of,
    whole_number,
)
from actuator_selection.core.errors import DomainError
from actuator_selection.core.thermal import KtyCharacteristic, TemperatureSensor
from actuator_selection.db.changes import FileChanges, delete_in, retire_at, sync_rows
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorInterfaceRow,
    ActuatorRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
)


def mark(text: str) -> str:
    """A mark of Table 521.1, stored as ``tested`` (●) or ``possible`` (○)."""
    try:
        level = parse_support_level(text, field="mark")
    except DomainError:
        raise ValueError("must be tested (●), possible (○) or empty") from None
    assert level is not None, "an empty cell never reaches a converter"
    return level.value


def options(kind: type[StrEnum]) -> Callable[[str], str]:
    """A converter for a space-separated list of distinct ``kind`` values."""
    allowed = [o.value for o in kind]

    def convert(text: str) -> str:
        given = text.split()
        unknown = [o for o in given if o not in allowed]
        if unknown:
            raise ValueError(
                f"must be space-separated options of {', '.join(allowed)} (unknown: "
                f"{', '.join(unknown)})"
            )
        if len(set(given)) != len(given):
            raise ValueError("must name each option once")
        return " ".join(given)

    return convert


CONTROLLERS = CsvSpec(
    file="controllers.csv",
    key=("source_row",),
    columns=(
        Column(name="source_row", required=True, convert=whole_number),
        Column(name="manufacturer", required=True, max_length=80),
        Column(name="type", required=True, max_length=80),
        Column(name="variant", max_length=40),
        *(Column(name=column, convert=mark) for _, _, column in MARK_COLUMNS),
        Column(name="correction"),
        Column(name="source", required=True),
    ),
)

SENSOR_FITTINGS = CsvSpec(
    file="temperature_sensors.csv",
    key=("family", "variant", "sensor"),
    columns=(
        Column(name="family", required=True, max_length=40),
        Column(name="variant", max_length=40),
        Column(name="sensor", required=True, convert=one_of(*TemperatureSensor)),
        Column(name="designation", max_length=60),
        Column(name="sensor_count", required=True, convert=whole_number),
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
        Column(name="bus_class", required=True, convert=one_of(*BusClass)),
        Column(name="label", required=True, max_length=40),
        Column(name="nominal_dc_voltage_v", numeric=True, required=True, rule=Rule.POSITIVE),
        Column(name="derivation"),
        Column(name="source", required=True),
    ),
)

INTERFACES = CsvSpec(
    file="actuator_interfaces.csv",
    key=("actuator_model",),
    columns=(
        Column(name="actuator_model", required=True, max_length=60),
        Column(name="dc_bus_classes", convert=options(BusClass)),
        Column(name="temperature_sensors", convert=options(TemperatureSensor)),
        Column(name="feedback_systems", convert=options(FeedbackSystem)),
        Column(name="derivation"),
        Column(name="source", required=True),
    ),
)

OPTION_COLUMNS = frozenset({"dc_bus_classes", "temperature_sensors", "feedback_systems"})
"""The columns of actuator_interfaces.csv that hold space-separated option names."""

PROTECTION_SPECS = (CONTROLLERS, SENSOR_FITTINGS, KTY_POINTS, BUS_CLASSES, INTERFACES)
"""The controller-side files, in loading order (after the actuator files)."""


def controller_name_problems(
    records: Sequence[Record], *, others: Mapping[tuple[str, str, str | None], int] | None = None
) -> list[Problem]:
    """Rows naming the same controller (manufacturer, type and variant) twice.

    ``others``: rows already stored, by name → ``source_row`` (the admin API's case).
    """
    seen = dict(others or {})
    problems: list[Problem] = []
    for r in records:
        v = r.values
        name = (v["manufacturer"], v["type"], v["variant"])
        row = seen.setdefault(name, v["source_row"])
        if row != v["source_row"]:
            label = " ".join(n for n in name if n)
            problems.append(
                Problem(
                    file=CONTROLLERS.file,
                    line=r.line,
                    column="type",
                    message=f"{label} is row {row} already; a variant tells rows apart",
                )
            )
    return problems


def _whole_file_problems(rows: Mapping[str, Sequence[Record]]) -> list[Problem]:
    """Rules on a file as a whole: the KTY table as the runtime reads it (at least two
    points, rising strictly: :class:`~actuator_selection.core.thermal.KtyCharacteristic`
    checks it), and a nominal voltage for every bus class Table 521.1 marks."""
    problems: list[Problem] = []
    kty = rows[KTY_POINTS.file]
    try:
        KtyCharacteristic.from_points(
            (r.values["temperature_c"], r.values["resistance_ohm"]) for r in kty
        )
    except DomainError as exc:
        column = {"temperatures_c": "temperature_c"}.get(exc.field, "resistance_ohm")
        line = min((r.line for r in kty), default=0)
        problems.append(
            Problem(file=KTY_POINTS.file, line=line, column=column, message=exc.message)
        )
    listed = {r.values["bus_class"] for r in rows[BUS_CLASSES.file]}
    missing = [b.value for b in BusClass if b.value not in listed]
    if missing:
        problems.append(
            Problem(
                file=BUS_CLASSES.file,
                line=0,
                column="bus_class",
                message=f"every bus class of Table 521.1 needs its row; missing: "
                f"{', '.join(missing)}",
            )
        )
    return problems


def protection_problems(
    rows: Mapping[str, Sequence[Record]], *, families: Collection[str], models: Collection[str]
) -> list[Problem]:
    """Problems that need more than one row: unknown families and actuators, repeated
    controllers, a KTY table the runtime cannot read, a bus class without its voltage."""
    problems = controller_name_problems(rows[CONTROLLERS.file])
    problems.extend(_whole_file_problems(rows))
    for r in rows[SENSOR_FITTINGS.file]:
        if r.values["family"] not in families:
            problems.append(
                Problem(
                    file=SENSOR_FITTINGS.file,
                    line=r.line,
                    column="family",
                    message=f"unknown family {r.values['family']!r}",
                )
            )
    for r in rows[INTERFACES.file]:
        if r.values["actuator_model"] not in models:
            problems.append(
                Problem(
                    file=INTERFACES.file,
                    line=r.line,
                    column="actuator_model",
                    message=f"unknown actuator model {r.values['actuator_model']!r}",
                )
            )
    return problems


def apply_protection(
    session: Session,
    rows: Mapping[str, Sequence[Record]],
    changes: Mapping[str, FileChanges],
    *,
    replace: bool,
    now: datetime,
    listed_models: Collection[str] = (),
) -> None:
    """Upsert the validated controller-side files (after the actuator files; the caller commits).

    With ``replace`` the files are the whole catalogue: controllers they lack are
    retired (listed ones brought back), sensor fittings, KTY points and bus
    classes they lack are removed, and so are the interfaces of the actuators
    they list (``listed_models``) without one; a retired actuator keeps its
    interface for when it comes back. Without ``replace`` nothing is retired or removed.
    """
    family_ids = {f.name: f.id for f in session.scalars(select(ActuatorFamilyRow))}
    actuator_ids = {a.model: a.id for a in session.scalars(select(ActuatorRow))}

    def stored(spec: CsvSpec, convert: Callable[[dict[str, Any]], dict[str, Any]]) -> list[Any]:
        return [convert(dict(r.values)) for r in rows[spec.file]]

    def controller(v: dict[str, Any]) -> dict[str, Any]:
        return {**v, "retired_at": None} if replace else v

    def fitting(v: dict[str, Any]) -> dict[str, Any]:
        v["family_id"] = family_ids[v.pop("family")]
        return v

    def kty_point(v: dict[str, Any]) -> dict[str, Any]:
        return {**v, "sensor": TemperatureSensor.KTY84_130.value}

    def interface(v: dict[str, Any]) -> dict[str, Any]:
        v["actuator_id"] = actuator_ids[v.pop("actuator_model")]
        return v

    listed = {actuator_ids[m] for m in listed_models}
    for spec, model, key, convert, withdraw in (
        (CONTROLLERS, ControllerRow, ("source_row",), controller, retire_at(now)),
        (
            SENSOR_FITTINGS,
            SensorFittingRow,
            ("family_id", "variant", "sensor"),
            fitting,
            delete_in(session),
        ),
        (
            KTY_POINTS,
            SensorPointRow,
            ("sensor", "temperature_c"),
            kty_point,
            delete_in(session, keep=lambda r: r.sensor != TemperatureSensor.KTY84_130.value),
        ),
        (BUS_CLASSES, DcBusClassRow, ("bus_class",), lambda v: v, delete_in(session)),
        (
            INTERFACES,
            ActuatorInterfaceRow,
            ("actuator_id",),
            interface,
            delete_in(session, keep=lambda r: r.actuator_id not in listed),
        ),
    ):
        sync_rows(
            session,
            model,
            key,
            stored(spec, convert),
            changes[spec.file],
            withdraw=withdraw if replace else None,
        )
