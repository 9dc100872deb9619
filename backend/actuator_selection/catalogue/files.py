"""The files of the catalogue: their columns, units and rules (one ``CsvSpec`` per file).

Families, actuators and their zones; Table 521.1's controllers, sensor data
(Tables 518.1, 519.2), bus classes and actuator interfaces. These rules are the
one rulebook of the catalogue: the seed loader and the catalogue import
(:mod:`actuator_selection.db.seed`, :mod:`actuator_selection.db.seed_controllers`),
the admin API's writes and the schemas of its bodies all read them, so none of
them can disagree on what a valid row is.

Rows of ``controllers.csv`` are numbered by ``source_row``: Table 521.1's rows
keep their printed numbers (1 below the heading), rows added later take
further numbers, and ``source`` says where each row comes from.
"""

from __future__ import annotations

from collections.abc import Callable
from enum import StrEnum

from actuator_selection.catalogue.controllers import (
    MARK_COLUMNS,
    BusClass,
    FeedbackSystem,
    parse_support_level,
)
from actuator_selection.catalogue.csvio import Column, CsvSpec, Rule, one_of, whole_number
from actuator_selection.catalogue.fields import (
    ACTUATOR_FIELDS,
    FAMILY_LENGTH,
    FAMILY_NAME,
    MODEL_LENGTH,
    MODEL_NAME,
)
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.errors import DomainError

_P, _N = Rule.POSITIVE, Rule.NON_NEGATIVE

FAMILIES = CsvSpec(
    file="families.csv",
    key=("name",),
    columns=(
        Column(name="name", required=True, max_length=FAMILY_LENGTH, pattern=FAMILY_NAME),
        Column(name="description"),
        Column(name="temperature_sensors"),
        Column(name="warning_temperature_c", numeric=True),
        Column(name="shutdown_temperature_c", numeric=True),
        Column(name="temperature_tolerance_percent", numeric=True, rule=_N),
        Column(name="warning_resistance_ohm", numeric=True, rule=_P),
        Column(name="shutdown_resistance_ohm", numeric=True, rule=_P),
        Column(name="resistance_tolerance_percent", numeric=True, rule=_N),
        Column(name="source", required=True),
    ),
)

ACTUATORS = CsvSpec(
    file="actuators.csv",
    key=("model",),
    columns=tuple(f.column for f in ACTUATOR_FIELDS),
)
"""The columns of an actuator's row: one per declared value (:mod:`.catalogue_fields`),
in its order, each empty where no public source gives it."""

ZONE_POINTS = CsvSpec(
    file="zone_points.csv",
    key=("actuator_model", "speed_rpm"),
    columns=(
        Column(name="actuator_model", required=True, max_length=MODEL_LENGTH, pattern=MODEL_NAME),
        Column(name="speed_rpm", numeric=True, required=True, rule=_N),
        Column(name="torque_nm", numeric=True, required=True, rule=_N),
        Column(name="source", required=True),
    ),
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
        Column(name="family", required=True, max_length=FAMILY_LENGTH, pattern=FAMILY_NAME),
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
        Column(name="actuator_model", required=True, max_length=MODEL_LENGTH, pattern=MODEL_NAME),
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

CATALOGUE_SPECS = (FAMILIES, ACTUATORS, ZONE_POINTS, *PROTECTION_SPECS)
"""The files of a whole catalogue, in loading order."""

JSON_KEYS = {spec.file: spec.file.removesuffix(".csv") for spec in CATALOGUE_SPECS}
"""The key of each file's rows in the JSON form of a catalogue (the file's stem)."""
