"""The controller files of the catalogue: Table 521.1, sensors (Tables 518.1, 519.2), interfaces.

Their rules (``CsvSpec``) are in :mod:`actuator_selection.catalogue.files`
with the actuator files' rules; :mod:`actuator_selection.db.seed` reads, checks
and writes all catalogue files together, this module knows what the
controller-side files must agree on across rows and how they are stored.
"""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterator, Mapping, Sequence
from datetime import datetime
from typing import Any

from sqlalchemy import select
from sqlalchemy.orm import Session

from actuator_selection.catalogue.changes import FileChanges
from actuator_selection.catalogue.controllers import BusClass
from actuator_selection.catalogue.csvio import CsvSpec, Problem, Record
from actuator_selection.catalogue.files import (
    BUS_CLASSES,
    CONTROLLERS,
    INTERFACES,
    KTY_POINTS,
    SENSOR_FITTINGS,
)
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.db.changes import delete_in, retire_at, sync_rows
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorInterfaceRow,
    ActuatorRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
)
from actuator_selection.db.repositories import mark_changed
from actuator_selection.errors import DomainError
from actuator_selection.sizing.thermal import KtyCharacteristic


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
    points, rising strictly: :class:`~actuator_selection.sizing.thermal.KtyCharacteristic`
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
    actuator_ids: dict[str, int] = dict(
        session.execute(select(ActuatorRow.model, ActuatorRow.id)).all()
    )

    def stored(
        spec: CsvSpec, convert: Callable[[dict[str, Any]], dict[str, Any]]
    ) -> Iterator[dict[str, Any]]:
        return (convert(dict(r.values)) for r in rows[spec.file])

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
        touched = sync_rows(
            session,
            model,
            key,
            stored(spec, convert),
            changes[spec.file],
            withdraw=withdraw if replace else None,
        )
        if spec is INTERFACES:
            mark_changed(session, [actuator_id for (actuator_id,) in touched])
