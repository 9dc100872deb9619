"""The values of a catalogue actuator, each declared once.

One :class:`CatalogueField` per column of ``actuators.csv`` says what the value is (its
name, unit, symbol and words), how the file writes it (header, published unit), what a
valid cell is (rule, width, choices), where it must come from (:class:`Source`) and
whether the engine's checks read it. Everything else is derived from
:data:`ACTUATOR_FIELDS`:

- the columns and rules of ``actuators.csv`` (:data:`~.catalogue_files.ACTUATORS`), so
  the seed loader, the catalogue import and export and the admin API's writes;
- the table ``actuators``'s columns (``db/models/catalogue.py``);
- the repository's row → :class:`~.catalogue.ActuatorRecord` mapping (``db/repositories.py``);
- the API's ``ActuatorOut``, its properties and their descriptions (``schemas/actuators.py``).

- the engine's record :class:`~.actuators.Actuator` (generated from the fields marked
  ``engine=True``) and the engine's catalogue operands (the fields with an ``operand``,
  :func:`~.engine.catalogue.catalogue_arrays`).

The words (:attr:`CatalogueField.label`)
are gettext msgids: ``make messages`` extracts them and the German catalogue
(``locale/de/LC_MESSAGES/messages.po``) translates them. How to add a value:
``docs/catalogue.md``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from enum import Enum
from typing import Final

from actuator_selection.catalogue.csvio import Column, NamePattern, Rule, one_of
from actuator_selection.catalogue.parts import BearingType
from actuator_selection.phrases.messages import N_, Text

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
MODEL_LENGTH: Final = 60
"""The most characters of a model name (its column's width, here and in the files that
refer to an actuator)."""
FAMILY_LENGTH: Final = 40
"""The most characters of a family name."""

MILLI: Final = 1e-3
KILO: Final = 1e3


class Kind(Enum):
    """What a value is: a number (stored as a float in its SI unit) or text."""

    NUMBER = "number"
    TEXT = "text"


class Source(Enum):
    """Where a value must come from (the house rule: never invent catalogue data)."""

    PUBLISHED = "published"
    """A public manufacturer's document gives it; the row's ``source`` cites the document
    (title, number, edition, page or table). Empty where no public source gives it: the
    service then says "no data"."""
    PUBLISHED_OR_DERIVED = "published_or_derived"
    """As :attr:`PUBLISHED`, or derived from published values; the row's ``derivation``
    names the value and says how it was obtained."""
    ROW = "row"
    """The row's own bookkeeping (notes, the derivation, the citations), not a value."""


@dataclass(frozen=True, slots=True, kw_only=True)
class CatalogueField:
    """One value of a catalogue actuator: a column of ``actuators.csv``, of the table
    ``actuators`` and of the API's actuator.

    ``name`` is the stored attribute: the table's column, the API's property and, for an
    ``engine`` field, the attribute of :class:`~.actuators.Actuator`. It carries the unit
    in which the value is stored (house style, ``_nm``, ``_rpm``). ``csv`` is the file's
    header where the file publishes another unit (``output_bearing_radial_load_kn``);
    ``scale`` turns the published unit into the stored one (kN → N: 10³).
    """

    name: str
    label: Text
    """The value in words, English; the msgid of its translations (``N_``)."""
    kind: Kind = Kind.NUMBER
    symbol: str | None = None
    """The catalogue's symbol (``T_max``, ``M_dyn(max)``), where it prints one."""
    unit: str | None = None
    """The stored unit as the documentation writes it (``Nm``, ``kgm²``); None: a count,
    a ratio or text."""
    csv: str | None = None
    scale: float = 1.0
    required: bool = False
    rule: Rule = Rule.POSITIVE
    """What a number must satisfy (a number only)."""
    max_length: int | None = None
    """The most characters of a text (its column's width); None: free text."""
    pattern: NamePattern | None = None
    choices: tuple[str, ...] | None = None
    """The values a text may take (a choice)."""
    source: Source = Source.PUBLISHED
    engine: bool = False
    """The engine's checks read it: :class:`~.actuators.Actuator` carries it."""
    operand: bool | str = False
    """The rules read it as published, as the :class:`~.checks.Operands` field of its name
    (True) or of the name given (``bearing_offset_m`` for ``output_bearing_offset_m``): the
    engine's catalogue arrays (:func:`~.engine.catalogue.catalogue_arrays`) carry it under
    that name. False: no rule reads it, or only derived (``engine/catalogue.py``)."""
    remark: str | None = None
    """Words the API's description adds after the unit (a derivation, an equation)."""
    optional: bool = False
    """A file may leave the column out (one added after files were written without it)."""

    @property
    def operand_name(self) -> str | None:
        """The :class:`~.checks.Operands` field it feeds as published, or None."""
        if isinstance(self.operand, str):
            return self.operand
        return self.name if self.operand else None

    @property
    def header(self) -> str:
        """The column's header in ``actuators.csv``."""
        return self.csv or self.name

    @property
    def column(self) -> Column:
        """The column of ``actuators.csv`` (:data:`~.catalogue_files.ACTUATORS`)."""
        return Column(
            name=self.header,
            numeric=self.kind is Kind.NUMBER,
            required=self.required,
            rule=self.rule if self.kind is Kind.NUMBER else Rule.ANY,
            scale=self.scale,
            target=self.name if self.csv else None,
            max_length=self.max_length,
            pattern=self.pattern,
            convert=one_of(*self.choices) if self.choices else None,
            optional=self.optional,
        )

    @property
    def description(self) -> str:
        """The API's description: symbol, words, choices, unit and remark, e.g.
        ``M_dyn(max), allowable dynamic tilting moment [Nm]``."""
        text = f"{self.symbol}, {self.label}" if self.symbol else str(self.label)
        if self.choices:
            text += f" ({' or '.join(f'`{c}`' for c in self.choices)})"
        if self.unit:
            text += f" [{self.unit}]"
        return text + (self.remark or "")


_P, _N = Rule.POSITIVE, Rule.NON_NEGATIVE

ACTUATOR_FIELDS: Final[tuple[CatalogueField, ...]] = (
    CatalogueField(
        name="model",
        label=N_("catalogue model"),
        kind=Kind.TEXT,
        required=True,
        max_length=MODEL_LENGTH,
        pattern=MODEL_NAME,
        engine=True,
    ),
    CatalogueField(
        name="family",
        label=N_("actuator family"),
        kind=Kind.TEXT,
        required=True,
        max_length=FAMILY_LENGTH,
        pattern=FAMILY_NAME,
        engine=True,
    ),
    CatalogueField(
        name="gear_ratio",
        label=N_("gear ratio"),
        symbol="i",
        required=True,
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="max_torque_nm",
        label=N_("repeated peak torque"),
        symbol="T_max",
        unit="Nm",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="max_speed_rpm",
        label=N_("maximum output speed"),
        symbol="n_max",
        unit="rpm",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="inertia_kgm2",
        label=N_("moment of inertia at the output"),
        symbol="J_A",
        unit="kgm²",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="stall_torque_nm",
        label=N_("continuous stall torque"),
        symbol="T_0",
        unit="Nm",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="continuous_torque_nm",
        label=N_("allowable continuous torque"),
        unit="Nm",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="max_current_a",
        label=N_("maximum current"),
        symbol="I_max",
        unit="A_rms",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="stall_current_a",
        label=N_("continuous stall current"),
        symbol="I_0",
        unit="A_rms",
        engine=True,
    ),
    CatalogueField(name="continuous_current_a", label=N_("allowable continuous current"), unit="A"),
    CatalogueField(
        name="torque_constant_nm_per_a",
        label=N_("torque constant at the output"),
        symbol="k_T",
        unit="Nm/A",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="motor_torque_constant_nm_per_a",
        label=N_("torque constant of the motor"),
        symbol="k_TM",
        unit="Nm/A",
    ),
    CatalogueField(
        name="motor_voltage_constant_v_per_krpm",
        label=N_("voltage constant of the motor, line-to-line"),
        symbol="K_E",
        unit="V per 1000 rpm motor speed",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="output_voltage_constant_v_per_rpm",
        label=N_("voltage constant referred to the output"),
        symbol="k_E",
        unit="V per output rpm",
        engine=True,
    ),
    CatalogueField(
        name="resistance_line_ohm",
        label=N_("winding resistance, line-to-line"),
        unit="Ω",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="resistance_phase_ohm",
        label=N_("winding resistance per phase"),
        unit="Ω",
        engine=True,
    ),
    CatalogueField(
        name="inductance_line_mh",
        label=N_("winding inductance, line-to-line"),
        symbol="L",
        unit="mH",
        engine=True,
    ),
    CatalogueField(name="inductance_phase_mh", label=N_("winding inductance per phase"), unit="mH"),
    CatalogueField(
        name="no_load_starting_current_a",
        label=N_("no-load starting current"),
        symbol="I_NLS",
        unit="A",
        rule=_N,
        remark=" (Eq. 522.2)",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="no_load_current_constant_30c_a_per_rpm",
        label=N_("no-load current constant at 30 °C"),
        symbol="K_INL",
        unit="A/rpm",
        csv="no_load_current_constant_30c_ma_per_rpm",
        scale=MILLI,
        rule=_N,
        remark=" (Eq. 522.2)",
        engine=True,
        operand="no_load_current_constant_a_per_rpm",
    ),
    CatalogueField(
        name="no_load_current_constant_80c_a_per_rpm",
        label=N_("no-load current constant at 80 °C"),
        symbol="K_INL",
        unit="A/rpm",
        csv="no_load_current_constant_80c_ma_per_rpm",
        scale=MILLI,
        rule=_N,
        remark=" (Eq. 522.2)",
        engine=True,
    ),
    CatalogueField(
        name="thermal_time_constant_s", label=N_("thermal time constant"), unit="s", engine=True
    ),
    CatalogueField(name="mass_kg", label=N_("mass of the actuator"), unit="kg"),
    CatalogueField(name="max_dc_bus_voltage_v", label=N_("maximum DC bus voltage"), unit="V"),
    CatalogueField(
        name="supply_voltage",
        label=N_("supply voltage, as the catalogue writes it"),
        kind=Kind.TEXT,
        max_length=40,
    ),
    CatalogueField(
        name="feedback",
        label=N_("feedback system, as the catalogue writes it"),
        kind=Kind.TEXT,
        max_length=80,
    ),
    # Revision 0006 (the second audit of public copies): allowable continuous and rated
    # output speed, brake holding torque and the output bearing's data.
    CatalogueField(
        name="continuous_speed_rpm",
        label=N_("allowable continuous output speed"),
        unit="rpm",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="rated_speed_rpm",
        label=N_("rated output speed"),
        unit="rpm",
        source=Source.PUBLISHED_OR_DERIVED,
        remark=" (CHA: derived, rated motor speed / i; see derivation)",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="brake_holding_torque_nm",
        label=N_("holding torque of the motor brake at the output"),
        symbol="T_Br",
        unit="Nm",
        engine=True,
        operand=True,
    ),
    CatalogueField(
        name="output_bearing_pitch_diameter_m",
        label=N_("pitch circle diameter of the output bearing"),
        symbol="d_p",
        unit="m",
        engine=True,
        operand="bearing_pitch_diameter_m",
    ),
    CatalogueField(
        name="output_bearing_offset_m",
        label=N_("output bearing offset"),
        symbol="R",
        unit="m",
        rule=_N,
        engine=True,
        operand="bearing_offset_m",
    ),
    CatalogueField(
        name="output_bearing_dynamic_load_rating_n",
        label=N_("dynamic load rating of the output bearing"),
        symbol="C",
        unit="N",
        engine=True,
        operand="bearing_dynamic_load_rating_n",
    ),
    CatalogueField(
        name="output_bearing_static_load_rating_n",
        label=N_("static load rating of the output bearing"),
        symbol="C_0",
        unit="N",
        engine=True,
        operand="bearing_static_load_rating_n",
    ),
    CatalogueField(
        name="output_bearing_dynamic_tilting_moment_nm",
        label=N_("allowable dynamic tilting moment"),
        symbol="M_dyn(max)",
        unit="Nm",
        engine=True,
        operand="bearing_dynamic_tilting_moment_nm",
    ),
    CatalogueField(
        name="output_bearing_static_tilting_moment_nm",
        label=N_("allowable static tilting moment"),
        symbol="M_0(max)",
        unit="Nm",
        engine=True,
    ),
    CatalogueField(
        name="output_bearing_radial_load_n",
        label=N_("allowable radial load on the output bearing"),
        unit="N",
        csv="output_bearing_radial_load_kn",
        scale=KILO,
        engine=True,
        operand="bearing_radial_load_n",
    ),
    CatalogueField(
        name="output_bearing_axial_load_n",
        label=N_("allowable axial load on the output bearing"),
        unit="N",
        csv="output_bearing_axial_load_kn",
        scale=KILO,
        engine=True,
        operand="bearing_axial_load_n",
    ),
    CatalogueField(
        name="output_bearing_moment_load_nm",
        label=N_("allowable moment load on the output bearing"),
        unit="Nm",
        engine=True,
        operand="bearing_moment_load_nm",
    ),
    CatalogueField(
        name="output_bearing_moment_stiffness_nm_per_rad",
        label=N_("moment stiffness of the output bearing"),
        unit="Nm/rad",
        csv="output_bearing_moment_stiffness_knm_per_rad",
        scale=KILO,
        engine=True,
    ),
    # Revision 0007
    CatalogueField(
        name="pole_pairs",
        label=N_("number of pole pairs of the motor"),
        symbol="p",
        engine=True,
        operand=True,
    ),
    # Revision 0009: the bearing's type sets its life exponent.
    CatalogueField(
        name="output_bearing_type",
        label=N_("type of the output bearing"),
        kind=Kind.TEXT,
        max_length=40,
        choices=tuple(t.value for t in BearingType),
        remark=": it sets the life exponent (10/3 or 3)",
        engine=True,
    ),
    # Revision 0013 (issue 28, items 7–9): torsional stiffness, brake limits, gear ratings.
    # Every column optional: files written before it leave it out.
    CatalogueField(
        name="limit_torque_t1_nm",
        label=N_("limit torque T_1 of the torsional stiffness curve"),
        symbol="T_1",
        unit="Nm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="limit_torque_t2_nm",
        label=N_("limit torque T_2 of the torsional stiffness curve"),
        symbol="T_2",
        unit="Nm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="torsional_stiffness_k1_nm_per_rad",
        label=N_("torsional stiffness K_1 (0 to T_1)"),
        symbol="K_1",
        unit="Nm/rad",
        engine=True,
        operand="stiffness_k1_nm_per_rad",
        optional=True,
    ),
    CatalogueField(
        name="torsional_stiffness_k2_nm_per_rad",
        label=N_("torsional stiffness K_2 (T_1 to T_2)"),
        symbol="K_2",
        unit="Nm/rad",
        engine=True,
        operand="stiffness_k2_nm_per_rad",
        optional=True,
    ),
    CatalogueField(
        name="torsional_stiffness_k3_nm_per_rad",
        label=N_("torsional stiffness K_3 (above T_2)"),
        symbol="K_3",
        unit="Nm/rad",
        engine=True,
        operand="stiffness_k3_nm_per_rad",
        optional=True,
    ),
    CatalogueField(
        name="brake_emergency_stop_count",
        label=N_("allowable number of emergency stops with the brake"),
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="brake_closing_time_s",
        label=N_("closing time of the motor brake"),
        unit="s",
        csv="brake_closing_time_ms",
        scale=MILLI,
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_average_torque_limit_nm",
        label=N_("limit for average torque of the gear"),
        symbol="T_A",
        unit="Nm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_repeated_peak_torque_nm",
        label=N_("limit for repeated peak torque of the gear"),
        symbol="T_R",
        unit="Nm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_momentary_peak_torque_nm",
        label=N_("limit for momentary peak torque of the gear"),
        symbol="T_M",
        unit="Nm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_momentary_peak_count",
        label=N_("allowable number of momentary peak torques of the gear"),
        symbol="N_M",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_average_input_speed_limit_rpm",
        label=N_("allowable average input speed of the gear"),
        symbol="n_in,av(max)",
        unit="rpm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_rated_torque_nm",
        label=N_("rated torque of the gear at 2000 rpm input speed"),
        symbol="T_N",
        unit="Nm",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_rated_life_h",
        label=N_("nominal life of the wave generator"),
        symbol="L_n",
        unit="h",
        engine=True,
        operand=True,
        optional=True,
    ),
    CatalogueField(
        name="gear_life_basis",
        label=N_("whether the gear's nominal life is an L_10 or an L_50"),
        kind=Kind.TEXT,
        max_length=10,
        choices=("L10", "L50"),
        engine=True,
        optional=True,
    ),
    CatalogueField(name="notes", label=N_("notes"), kind=Kind.TEXT, source=Source.ROW),
    CatalogueField(
        name="derivation",
        label=N_("how the row's derived values were obtained"),
        kind=Kind.TEXT,
        source=Source.ROW,
    ),
    CatalogueField(
        name="source",
        label=N_("the manufacturer's documents the row's values come from"),
        kind=Kind.TEXT,
        required=True,
        source=Source.ROW,
        remark="publisher, title, document number, edition, page or table; never a mirror",
    ),
    CatalogueField(
        name="read_at",
        label=N_("where the values were read or checked"),
        kind=Kind.TEXT,
        source=Source.ROW,
        remark="public copies of the documents that source cites, beside the citation",
        optional=True,
    ),
)
"""Every value of a catalogue actuator, in the order of ``actuators.csv``'s columns. Each
is empty (None) where no public source gives it, except the required ones."""

FIELDS_BY_NAME: Final = {f.name: f for f in ACTUATOR_FIELDS}

ENGINE_FIELDS: Final = tuple(f for f in ACTUATOR_FIELDS if f.engine)
"""The values the engine's checks read: the catalogue attributes of
:class:`~.actuators.Actuator`."""

OPERAND_FIELDS: Final = tuple(f for f in ENGINE_FIELDS if f.operand_name is not None)
"""The values the rules read as published, each an :class:`~.checks.Operands` field."""

DERIVED_ACTUATOR_ATTRIBUTES: Final = {
    "zone": "the continuous-duty zone, from zone_points.csv",
    "dc_bus_voltage_v": "the highest DC bus voltage of its interface, from the snapshot",
}
"""Attributes of :class:`~.actuators.Actuator` that are not columns of ``actuators.csv``."""

CatalogueValue = float | str | None
"""A stored value: a number in its SI unit, a text or None (no data)."""
