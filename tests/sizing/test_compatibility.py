"""Actuator ↔ controller matching on the seeded Table 521.1."""

from __future__ import annotations

import csv
from pathlib import Path
from types import MappingProxyType

import pytest

from actuator_selection.catalogue.controllers import (
    MARK_COLUMNS,
    ActuatorInterface,
    BusClass,
    Controller,
    Criterion,
    FeedbackSystem,
    ProductFamily,
    SupportLevel,
    controller_from_record,
    parse_support_level,
    product_family,
)
from actuator_selection.catalogue.parts import TemperatureSensor
from actuator_selection.errors import InvalidInputError, NotFoundError
from actuator_selection.sizing.compatibility import (
    CriterionStatus,
    MatchVerdict,
    match_controller,
    match_controllers,
)

SEED = Path(__file__).parents[2] / "seed_data"
KTY = TemperatureSensor.KTY84_130
PTC = TemperatureSensor.PTC


def _controllers() -> list[Controller]:
    with (SEED / "controllers.csv").open(encoding="utf-8", newline="") as f:
        return [controller_from_record(r) for r in csv.DictReader(f)]


def _by_name() -> dict[str, Controller]:
    return {c.name: c for c in _controllers()}


def test_seed_has_28_distinct_controllers() -> None:
    controllers = _controllers()
    assert len(controllers) == 28
    assert [c.source_row for c in controllers] == list(range(1, 29))
    assert len({(c.manufacturer, c.type, c.variant) for c in controllers}) == 28


def test_mark_columns_follow_the_table() -> None:
    assert [column for _, _, column in MARK_COLUMNS] == [
        "cha_chm",
        "fha_c",
        "ffa_fpa",
        "lynxdrive",
        "torkdrive",
        "fha_mini",
        "bus_24vdc",
        "bus_320vdc",
        "bus_560vdc",
        "sensor_ptc",
        "sensor_kty84_130",
        "feedback_resolver_2pole",
        "feedback_sincos",
        "feedback_hiperface",
        "feedback_endat",
        "feedback_ttl",
    ]


def test_cha_with_kty_resolver_on_560_v_is_tested_on_the_siemens_drives() -> None:
    """Rows 1–4 carry ● in CHA/CHM, ≥ 560 VDC, KTY 84-130 and 2-pole resolver."""
    cha = ActuatorInterface(
        family=ProductFamily.CHA_CHM,
        bus_classes=frozenset({BusClass.V560}),
        temperature_sensors=frozenset({KTY}),
        feedback_systems=frozenset({FeedbackSystem.RESOLVER_2POLE}),
    )
    result = match_controllers(actuator=cha, controllers=_controllers())
    assert [m.controller.type for m in result.supported] == [
        "SIMODRIVE 611D",
        "SIMODRIVE 611U",
        "SINAMICS S120",
        "MASTERDRIVES MC",
    ]
    assert all(m.verdict is MatchVerdict.TESTED for m in result.supported)
    assert result.unconfirmed == ()
    assert len(result.excluded) == 24
    # Results are ordered: the fully tested come first.
    assert result.matches[:4] == result.supported


def test_excluding_criterion_is_named() -> None:
    cha = ActuatorInterface(
        family=ProductFamily.CHA_CHM,
        bus_classes=frozenset({BusClass.V560}),
        temperature_sensors=frozenset({KTY}),
        feedback_systems=frozenset({FeedbackSystem.RESOLVER_2POLE}),
    )
    unidrive = _by_name()["Control Techniques Unidrive"]
    m = match_controller(controller=unidrive, actuator=cha)
    assert m.verdict is MatchVerdict.EXCLUDED
    assert [c.criterion for c in m.excluded_by] == [Criterion.TEMPERATURE_SENSOR]
    assert "KTY 84-130" in m.excluded_by[0].message
    levels = {c.criterion: c.status for c in m.criteria}
    assert levels[Criterion.BUS_CLASS] is CriterionStatus.POSSIBLE  # ○ at ≥ 560 VDC
    assert levels[Criterion.FEEDBACK_SYSTEM] is CriterionStatus.TESTED


def test_unknown_criterion_is_no_data_not_a_guess() -> None:
    cha = ActuatorInterface(
        family=ProductFamily.CHA_CHM,
        bus_classes=frozenset({BusClass.V560}),
        temperature_sensors=frozenset({KTY}),
    )
    result = match_controllers(actuator=cha, controllers=_controllers())
    assert result.supported == ()
    unconfirmed = [m.controller.type for m in result.unconfirmed]
    # Every controller with ● or ○ for CHA/CHM, ≥ 560 VDC and KTY, whatever its feedback.
    assert unconfirmed[:4] == [
        "SIMODRIVE 611D",
        "SIMODRIVE 611U",
        "SINAMICS S120",
        "MASTERDRIVES MC",
    ]
    assert "MDLU" in unconfirmed  # sin/cos only: the resolver would exclude it
    assert "Unidrive" not in unconfirmed  # no KTY input
    for m in result.unconfirmed:
        (missing,) = m.no_data
        assert missing.criterion is Criterion.FEEDBACK_SYSTEM
        assert missing.message == "no data: feedback system unknown"
        assert missing.status is CriterionStatus.NO_DATA


def test_nothing_known_excludes_nothing() -> None:
    result = match_controllers(actuator=ActuatorInterface(), controllers=_controllers())
    assert len(result.unconfirmed) == 28
    assert all(len(m.no_data) == 4 for m in result.matches)


def test_tested_beats_possible_among_the_actuators_options() -> None:
    """TorkDrive carries 2 × KTY 84-130 and a PTC triplet (Table 518.1)."""
    tork = ActuatorInterface(
        family=product_family("TorkDrive"), temperature_sensors=frozenset({KTY, PTC})
    )
    by_name = _by_name()
    siemens = match_controller(controller=by_name["SIEMENS SIMODRIVE 611D"], actuator=tork)
    sensor = next(c for c in siemens.criteria if c.criterion is Criterion.TEMPERATURE_SENSOR)
    assert (sensor.status, sensor.option) == (CriterionStatus.TESTED, KTY)
    servo_one = match_controller(controller=by_name["LTI-Drives ServoOne"], actuator=tork)
    sensor = next(c for c in servo_one.criteria if c.criterion is Criterion.TEMPERATURE_SENSOR)
    assert (sensor.status, sensor.option) == (CriterionStatus.POSSIBLE, PTC)  # ○ PTC, no KTY
    harmonica = match_controller(controller=by_name["ELMO Harmonica"], actuator=tork)
    family = next(c for c in harmonica.criteria if c.criterion is Criterion.FAMILY)
    assert family.status is CriterionStatus.POSSIBLE  # ○ TorkDrive (printed TorqDrive)


def test_ordering_tested_possible_unconfirmed_excluded() -> None:
    """FHA-C mini on a 24 V bus: Harmonica ● ●, ECOVARIO ○ ○, S 400 (row 6) no 24 V mark."""
    mini = ActuatorInterface(
        family=product_family("FHA-C mini"), bus_classes=frozenset({BusClass.V24})
    )
    result = match_controllers(actuator=mini, controllers=_controllers())
    names = [m.controller.name for m in result.matches]
    verdicts = [m.verdict for m in result.matches]
    assert names[0] == "ELMO Harmonica"
    assert names[1] == "Jenaer Antriebstechnik ECOVARIO"
    order = [
        MatchVerdict.TESTED,
        MatchVerdict.POSSIBLE,
        MatchVerdict.UNCONFIRMED,
        MatchVerdict.EXCLUDED,
    ]
    assert [order.index(v) for v in verdicts] == sorted(order.index(v) for v in verdicts)
    s400 = next(m for m in result.matches if m.controller.name == "Danaher Motion S 400 (row 6)")
    assert s400.verdict is MatchVerdict.EXCLUDED
    assert [c.criterion for c in s400.excluded_by] == [Criterion.BUS_CLASS]


def test_product_family_names() -> None:
    assert product_family("CHA") is ProductFamily.CHA_CHM
    assert product_family("CHM") is ProductFamily.CHA_CHM
    assert product_family("FHA-C") is ProductFamily.FHA_C
    assert product_family("FHA-C mini") is ProductFamily.FHA_MINI
    assert product_family("TorqDrive") is ProductFamily.TORKDRIVE
    assert product_family("FFA / FPA") is ProductFamily.FFA_FPA
    with pytest.raises(NotFoundError) as err:
        product_family("PMA")
    assert err.value.field == "family"


def test_marks_parse_both_spellings() -> None:
    assert parse_support_level("●", field="x") is SupportLevel.TESTED
    assert parse_support_level("○", field="x") is SupportLevel.POSSIBLE
    assert parse_support_level("tested", field="x") is SupportLevel.TESTED
    assert parse_support_level(" ", field="x") is None
    with pytest.raises(InvalidInputError) as err:
        parse_support_level("yes", field="sensor_ptc")
    assert err.value.field == "sensor_ptc"


def test_controller_marks_are_frozen_copies() -> None:
    marks = {ProductFamily.CHA_CHM: SupportLevel.TESTED}
    c = Controller(manufacturer="M", type="T", families=marks)
    marks[ProductFamily.FHA_C] = SupportLevel.TESTED
    assert c.level(ProductFamily.FHA_C) is None
    assert isinstance(c.families, MappingProxyType)
    with pytest.raises(InvalidInputError) as err:
        Controller(manufacturer="M", type="T", families={"pma": SupportLevel.TESTED})  # type: ignore[dict-item]
    assert err.value.field == "families"


def test_empty_option_set_is_refused() -> None:
    with pytest.raises(InvalidInputError) as err:
        ActuatorInterface(feedback_systems=frozenset())
    assert err.value.field == "feedback_systems"
