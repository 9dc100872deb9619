"""Table 521.1 as the catalogue holds it: the servo controllers and their marks.

Table 521.1 marks, per controller, the actuator families it drives, the DC bus
voltage classes, the temperature sensor inputs and the motor feedback systems:
``●`` practically tested, ``○`` theoretically possible, empty = not supported. A
:class:`Controller` is one row of it; an :class:`ActuatorInterface` is what an
actuator offers in the same columns (its family, bus classes, sensors and feedback
systems). Which controllers match an actuator, and how well, is the sizing's
(:mod:`actuator_selection.sizing.compatibility`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from types import MappingProxyType

from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.errors import InvalidInputError, NotFoundError
from actuator_selection.phrases.messages import N_


class SupportLevel(StrEnum):
    """A mark of Table 521.1."""

    TESTED = "tested"
    """``●`` practically tested."""
    POSSIBLE = "possible"
    """``○`` theoretically possible."""


class ProductFamily(StrEnum):
    """The product columns of Table 521.1 (value = seed column name)."""

    CHA_CHM = "cha_chm"
    FHA_C = "fha_c"
    FFA_FPA = "ffa_fpa"
    LYNXDRIVE = "lynxdrive"
    TORKDRIVE = "torkdrive"
    FHA_MINI = "fha_mini"


class BusClass(StrEnum):
    """The DC bus voltage classes of Table 521.1 (seed column ``bus_<value>``)."""

    V24 = "24vdc"
    V320 = "320vdc"
    V560 = "560vdc"


class FeedbackSystem(StrEnum):
    """The motor feedback systems of Table 521.1 (seed column ``feedback_<value>``)."""

    RESOLVER_2POLE = "resolver_2pole"
    SINCOS = "sincos"
    HIPERFACE = "hiperface"
    ENDAT = "endat"
    TTL = "ttl"


class Criterion(StrEnum):
    """The four groups of columns of Table 521.1."""

    FAMILY = "family"
    BUS_CLASS = "bus_class"
    TEMPERATURE_SENSOR = "temperature_sensor"
    FEEDBACK_SYSTEM = "feedback_system"


Option = ProductFamily | BusClass | TemperatureSensor | FeedbackSystem

LABELS: Mapping[str, str] = MappingProxyType(
    {
        ProductFamily.CHA_CHM: "CHA / CHM",
        ProductFamily.FHA_C: "FHA-C",
        ProductFamily.FFA_FPA: "FFA / FPA",
        ProductFamily.LYNXDRIVE: "LynxDrive",
        ProductFamily.TORKDRIVE: "TorkDrive",
        ProductFamily.FHA_MINI: "FHA-C mini",
        BusClass.V24: N_("24 VDC bus"),
        BusClass.V320: N_("320 VDC bus"),
        BusClass.V560: N_("≥ 560 VDC bus"),
        TemperatureSensor.PTC: "PTC",
        TemperatureSensor.KTY84_130: "KTY 84-130",
        FeedbackSystem.RESOLVER_2POLE: N_("2-pole resolver"),
        FeedbackSystem.SINCOS: N_("incremental sine/cosine encoder"),
        FeedbackSystem.HIPERFACE: N_("HIPERFACE encoder"),
        FeedbackSystem.ENDAT: N_("EnDat encoder"),
        FeedbackSystem.TTL: N_("incremental TTL encoder"),
        Criterion.FAMILY: N_("actuator family"),
        Criterion.BUS_CLASS: N_("DC bus voltage"),
        Criterion.TEMPERATURE_SENSOR: N_("temperature sensor"),
        Criterion.FEEDBACK_SYSTEM: N_("feedback system"),
    }
)
"""Human-readable names of the columns and criteria (Table 521.1 headings); those in
words are marked for the catalogs (:func:`N_`), product names are the same in every language."""

MARK_COLUMNS: tuple[tuple[Criterion, Option, str], ...] = (
    *((Criterion.FAMILY, f, f.value) for f in ProductFamily),
    *((Criterion.BUS_CLASS, b, f"bus_{b.value}") for b in BusClass),
    *((Criterion.TEMPERATURE_SENSOR, s, f"sensor_{s.value}") for s in TemperatureSensor),
    *((Criterion.FEEDBACK_SYSTEM, s, f"feedback_{s.value}") for s in FeedbackSystem),
)
"""The 16 mark columns in the order of Table 521.1: (criterion, option, seed column)."""

_FAMILY_NAMES: Mapping[str, ProductFamily] = MappingProxyType(
    {
        "cha": ProductFamily.CHA_CHM,
        "chm": ProductFamily.CHA_CHM,
        "cha/chm": ProductFamily.CHA_CHM,
        "fha-c": ProductFamily.FHA_C,
        "fhac": ProductFamily.FHA_C,
        "ffa/fpa": ProductFamily.FFA_FPA,
        "ffa": ProductFamily.FFA_FPA,
        "fpa": ProductFamily.FFA_FPA,
        "lynxdrive": ProductFamily.LYNXDRIVE,
        "torkdrive": ProductFamily.TORKDRIVE,
        "torqdrive": ProductFamily.TORKDRIVE,
        "fha-c mini": ProductFamily.FHA_MINI,
        "fha-mini": ProductFamily.FHA_MINI,
    }
)


def product_family(family: str) -> ProductFamily:
    """The column of Table 521.1 for a catalogue family name (case and spaces ignored).

    ``TorqDrive`` (Table 521.1) and ``TorkDrive`` (Table 518.1) are one family;
    ``FHA-mini`` is the FHA-C mini series.

    >>> product_family("CHA").value, product_family("FHA-C mini").value
    ('cha_chm', 'fha_mini')
    """
    key = " ".join(family.casefold().replace(" / ", "/").split())
    try:
        return _FAMILY_NAMES[key]
    except KeyError:
        raise NotFoundError(
            "family", f"{family!r} is not an actuator family of Table 521.1"
        ) from None


_MARK_TEXT: Mapping[str, SupportLevel | None] = MappingProxyType(
    {
        "tested": SupportLevel.TESTED,
        "●": SupportLevel.TESTED,
        "possible": SupportLevel.POSSIBLE,
        "○": SupportLevel.POSSIBLE,
        "": None,
    }
)


def parse_support_level(text: str | None, *, field: str) -> SupportLevel | None:
    """A mark as stored (``tested``/``possible``/empty) or printed (``●``/``○``/empty).

    >>> parse_support_level("●", field="cha_chm"), parse_support_level("", field="cha_chm")
    (<SupportLevel.TESTED: 'tested'>, None)
    """
    key = (text or "").strip()
    if key not in _MARK_TEXT:
        raise InvalidInputError(
            field, f"{text!r} is not a mark of Table 521.1 (tested ●, possible ○ or empty)"
        )
    return _MARK_TEXT[key]


def _freeze(
    name: str, marks: Mapping[str, SupportLevel], option_type: type[StrEnum]
) -> Mapping[str, SupportLevel]:
    frozen: dict[str, SupportLevel] = {}
    for key, level in marks.items():
        try:
            option = option_type(key)
        except ValueError:
            raise InvalidInputError(name, f"{key!r} is not a column of Table 521.1") from None
        frozen[option] = SupportLevel(level)
    return MappingProxyType(frozen)


@dataclass(frozen=True, slots=True, kw_only=True)
class Controller:
    """One row of Table 521.1: a servo controller and its marks.

    Parameters
    ----------
    manufacturer
        Manufacturer as corrected (see the seed's ``correction`` column).
    type
        Controller type as printed, e.g. ``"SIMODRIVE 611D"``.
    variant
        Tells apart rows whose type repeats with other marks (names lost in the
        source), e.g. ``"row 6"``; None otherwise.
    source_row
        Row of the compatibility matrix: Table 521.1's rows keep their printed
        number, counted from 1 below the heading; rows added later take further
        numbers.
    families, bus_classes, temperature_sensors, feedback_systems
        The marks per column; a column that is absent is not supported.
    correction
        What was changed against the source row and why, if anything.
    """

    manufacturer: str
    type: str
    variant: str | None = None
    source_row: int | None = None
    families: Mapping[ProductFamily, SupportLevel] = field(
        default_factory=lambda: MappingProxyType({}), hash=False
    )
    bus_classes: Mapping[BusClass, SupportLevel] = field(
        default_factory=lambda: MappingProxyType({}), hash=False
    )
    temperature_sensors: Mapping[TemperatureSensor, SupportLevel] = field(
        default_factory=lambda: MappingProxyType({}), hash=False
    )
    feedback_systems: Mapping[FeedbackSystem, SupportLevel] = field(
        default_factory=lambda: MappingProxyType({}), hash=False
    )
    correction: str | None = None

    def __post_init__(self) -> None:
        if not self.manufacturer.strip() or not self.type.strip():
            raise InvalidInputError("type", "a controller needs a manufacturer and a type")
        for name, option_type in (
            ("families", ProductFamily),
            ("bus_classes", BusClass),
            ("temperature_sensors", TemperatureSensor),
            ("feedback_systems", FeedbackSystem),
        ):
            object.__setattr__(self, name, _freeze(name, getattr(self, name), option_type))

    @property
    def name(self) -> str:
        """Manufacturer, type and variant, e.g. ``"Danaher Motion S 400 (row 6)"``."""
        base = f"{self.manufacturer} {self.type}"
        return f"{base} ({self.variant})" if self.variant else base

    def level(self, option: Option) -> SupportLevel | None:
        """The mark for one column (the option's type names the criterion); None = no mark."""
        if isinstance(option, ProductFamily):
            return self.families.get(option)
        if isinstance(option, BusClass):
            return self.bus_classes.get(option)
        if isinstance(option, TemperatureSensor):
            return self.temperature_sensors.get(option)
        return self.feedback_systems.get(option)


def controller_from_record(record: Mapping[str, str | int | None]) -> Controller:
    """A :class:`Controller` from a seed row (``seed_data/controllers.csv`` column names).

    The marks are read from the 16 columns of :data:`MARK_COLUMNS`; empty text
    and None are "no mark".
    """
    marks: dict[Option, SupportLevel] = {}
    for _, option, column in MARK_COLUMNS:
        raw = record.get(column)
        level = parse_support_level(None if raw is None else str(raw), field=column)
        if level is not None:
            marks[option] = level

    def text(key: str) -> str | None:
        value = record.get(key)
        return None if value is None or str(value).strip() == "" else str(value).strip()

    row = text("source_row")
    try:
        source_row = int(row) if row is not None else None
    except ValueError:
        raise InvalidInputError("source_row", f"{row!r} is not a row number") from None
    return Controller(
        manufacturer=text("manufacturer") or "",
        type=text("type") or "",
        variant=text("variant"),
        source_row=source_row,
        families={o: v for o, v in marks.items() if isinstance(o, ProductFamily)},
        bus_classes={o: v for o, v in marks.items() if isinstance(o, BusClass)},
        temperature_sensors={o: v for o, v in marks.items() if isinstance(o, TemperatureSensor)},
        feedback_systems={o: v for o, v in marks.items() if isinstance(o, FeedbackSystem)},
        correction=text("correction"),
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class ActuatorInterface:
    """What the matching needs to know of an actuator; None = unknown (no data).

    A set lists the options the actuator offers (e.g. a TorkDrive carries both a
    KTY 84-130 and a PTC triplet, Table 518.1); any one supported is enough.

    Parameters
    ----------
    family
        Product column of Table 521.1 (see :func:`product_family`).
    bus_classes
        DC bus classes the actuator can run on.
    temperature_sensors
        Temperature sensors fitted.
    feedback_systems
        Motor feedback systems fitted.
    """

    family: ProductFamily | None = None
    bus_classes: frozenset[BusClass] | None = None
    temperature_sensors: frozenset[TemperatureSensor] | None = None
    feedback_systems: frozenset[FeedbackSystem] | None = None

    def __post_init__(self) -> None:
        for name in ("bus_classes", "temperature_sensors", "feedback_systems"):
            value = getattr(self, name)
            if value is not None:
                value = frozenset(value)
                if not value:
                    raise InvalidInputError(
                        name, "must name at least one option; give None when it is unknown"
                    )
                object.__setattr__(self, name, value)

    def options(self, criterion: Criterion) -> tuple[Option, ...] | None:
        """The actuator's options for ``criterion`` in table order; None when unknown."""
        if criterion is Criterion.FAMILY:
            return None if self.family is None else (self.family,)
        given: frozenset[Option] | None = {
            Criterion.BUS_CLASS: self.bus_classes,
            Criterion.TEMPERATURE_SENSOR: self.temperature_sensors,
            Criterion.FEEDBACK_SYSTEM: self.feedback_systems,
        }[criterion]
        if given is None:
            return None
        return tuple(o for c, o, _ in MARK_COLUMNS if c is criterion and o in given)
