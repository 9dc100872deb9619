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

import re
from collections.abc import Callable
from enum import StrEnum

from actuator_selection.core.bearing import BearingType
from actuator_selection.core.compatibility import (
    MARK_COLUMNS,
    BusClass,
    FeedbackSystem,
    parse_support_level,
)
from actuator_selection.core.csvio import (
    Column,
    CsvSpec,
    NamePattern,
    Rule,
    one_of,
    whole_number,
)
from actuator_selection.core.errors import DomainError
from actuator_selection.core.thermal import TemperatureSensor

_P, _N = Rule.POSITIVE, Rule.NON_NEGATIVE

MODEL_NAME = NamePattern(
    re.compile(r"[A-Za-z0-9]+(?:[-._+][A-Za-z0-9]+)*"),
    "must be a model name of ASCII letters and digits in groups joined by one of - . _ + "
    "(e.g. FHA-25C-50-L)",
)
"""An actuator's model: it is the key of its row and a segment of its URL
(``/actuators/{model}``). ASCII letters and digits only, so that no model has a twin that
looks the same (a Cyrillic С or a zero-width joiner beside a Latin C) and none needs
escaping or is lost in a URL (``/``, ``?``, ``#``, ``%``, ``..``); every seed model fits."""
FAMILY_NAME = NamePattern(
    re.compile(r"[A-Za-z0-9]+(?:[-._+/ ][A-Za-z0-9]+)*"),
    "must be a family name of ASCII letters and digits in groups joined by one of - . _ + / "
    "or a space (e.g. FHA-C mini, FFA/FPA)",
)
"""An actuator family's name, a key its actuators and Table 521.1's columns refer to: the
rule of :data:`MODEL_NAME` with ``/`` and single spaces, as the seed's families have
them (``FHA-C mini``, ``FFA/FPA``); a family is never a URL segment."""
MILLI = 1e-3
KILO = 1e3

FAMILIES = CsvSpec(
    file="families.csv",
    key=("name",),
    columns=(
        Column(name="name", required=True, max_length=40, pattern=FAMILY_NAME),
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
    columns=(
        Column(name="model", required=True, max_length=60, pattern=MODEL_NAME),
        Column(name="family", required=True, max_length=40, pattern=FAMILY_NAME),
        Column(name="gear_ratio", numeric=True, required=True, rule=_P),
        Column(name="max_torque_nm", numeric=True, rule=_P),
        Column(name="max_speed_rpm", numeric=True, rule=_P),
        Column(name="inertia_kgm2", numeric=True, rule=_P),
        Column(name="stall_torque_nm", numeric=True, rule=_P),
        Column(name="continuous_torque_nm", numeric=True, rule=_P),
        Column(name="max_current_a", numeric=True, rule=_P),
        Column(name="stall_current_a", numeric=True, rule=_P),
        Column(name="continuous_current_a", numeric=True, rule=_P),
        Column(name="torque_constant_nm_per_a", numeric=True, rule=_P),
        Column(name="motor_torque_constant_nm_per_a", numeric=True, rule=_P),
        Column(name="motor_voltage_constant_v_per_krpm", numeric=True, rule=_P),
        Column(name="output_voltage_constant_v_per_rpm", numeric=True, rule=_P),
        Column(name="resistance_line_ohm", numeric=True, rule=_P),
        Column(name="resistance_phase_ohm", numeric=True, rule=_P),
        Column(name="inductance_line_mh", numeric=True, rule=_P),
        Column(name="inductance_phase_mh", numeric=True, rule=_P),
        Column(name="no_load_starting_current_a", numeric=True, rule=_N),
        Column(
            name="no_load_current_constant_30c_ma_per_rpm",
            numeric=True,
            rule=_N,
            scale=MILLI,
            target="no_load_current_constant_30c_a_per_rpm",
        ),
        Column(
            name="no_load_current_constant_80c_ma_per_rpm",
            numeric=True,
            rule=_N,
            scale=MILLI,
            target="no_load_current_constant_80c_a_per_rpm",
        ),
        Column(name="thermal_time_constant_s", numeric=True, rule=_P),
        Column(name="mass_kg", numeric=True, rule=_P),
        Column(name="max_dc_bus_voltage_v", numeric=True, rule=_P),
        Column(name="supply_voltage", max_length=40),
        Column(name="feedback", max_length=80),
        Column(name="continuous_speed_rpm", numeric=True, rule=_P),
        Column(name="rated_speed_rpm", numeric=True, rule=_P),
        Column(name="brake_holding_torque_nm", numeric=True, rule=_P),
        Column(name="output_bearing_pitch_diameter_m", numeric=True, rule=_P),
        Column(name="output_bearing_offset_m", numeric=True, rule=_N),
        Column(name="output_bearing_dynamic_load_rating_n", numeric=True, rule=_P),
        Column(name="output_bearing_static_load_rating_n", numeric=True, rule=_P),
        Column(name="output_bearing_dynamic_tilting_moment_nm", numeric=True, rule=_P),
        Column(name="output_bearing_static_tilting_moment_nm", numeric=True, rule=_P),
        Column(
            name="output_bearing_radial_load_kn",
            numeric=True,
            rule=_P,
            scale=KILO,
            target="output_bearing_radial_load_n",
        ),
        Column(
            name="output_bearing_axial_load_kn",
            numeric=True,
            rule=_P,
            scale=KILO,
            target="output_bearing_axial_load_n",
        ),
        Column(name="output_bearing_moment_load_nm", numeric=True, rule=_P),
        Column(
            name="output_bearing_moment_stiffness_knm_per_rad",
            numeric=True,
            rule=_P,
            scale=KILO,
            target="output_bearing_moment_stiffness_nm_per_rad",
        ),
        Column(name="pole_pairs", numeric=True, rule=_P),
        Column(name="output_bearing_type", max_length=40, convert=one_of(*BearingType)),
        Column(name="notes"),
        Column(name="derivation"),
        Column(name="source", required=True),
        Column(name="read_at", optional=True),
    ),
)
"""Columns after ``feedback`` came with the second audit of public copies (revision 0006):
allowable continuous and rated output speed, brake holding torque and the output
bearing's data; ``output_bearing_type`` (revision 0009) the bearing's type, which sets
its life exponent. Each is empty where no public source gives it; ``derivation`` says how a
derived value (e.g. rated output speed = rated motor speed / i) was obtained. ``source``
cites the manufacturer's documents only (publisher, title, document number, edition, page
or table); ``read_at`` (revision 0010) names the public copies (mirror websites) the values
were read or checked on, beside the citation and never printed in its place; a file
written before it may leave the column out."""

ZONE_POINTS = CsvSpec(
    file="zone_points.csv",
    key=("actuator_model", "speed_rpm"),
    columns=(
        Column(name="actuator_model", required=True, max_length=60, pattern=MODEL_NAME),
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
        Column(name="family", required=True, max_length=40, pattern=FAMILY_NAME),
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
        Column(name="actuator_model", required=True, max_length=60, pattern=MODEL_NAME),
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
