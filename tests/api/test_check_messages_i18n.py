"""The flowchart's check messages in the user's language: a stable code and params beside the
text, German by Accept-Language with German numbers and min⁻¹, English unchanged."""

from __future__ import annotations

import dataclasses
import itertools
import math
import string
from collections.abc import Iterator
from typing import Any

import pytest
from babel.messages.pofile import read_po
from fastapi.testclient import TestClient
from tests import worked_example
from tests.oracle.flowchart import operands

from actuator_selection.i18n.localize import (
    catalog_path,
    check_templates,
    localizer,
    render_check,
)
from actuator_selection.phrases.check_messages import CHECK_MESSAGES, Phrase
from actuator_selection.sizing.checks import ALL_RULES, BEARING_STATIC, RULES, Operands, Status
from actuator_selection.sizing.checks.rule import _floor_message
from actuator_selection.sizing.selection import evaluate

SELECTIONS = "/api/v1/selections"
EXAMPLE_REQUEST: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
    "high_dynamics": True,
    "models": ["FHA-25C-50-L"],
}
MODEL = "FHA-25C-50-L"

ENGLISH_WORDS = (
    " the ",
    "rpm",
    "load ",
    "torque ",
    "speed",
    "exceeds",
    "approximate",
    "inside",
    "above",
    "within",
    "outside",
    "beyond",
    "winding",
    "catalogue",
    "no data",
    "for this actuator",
    "at its least",
    "governs",
    "short against",
    "braking",
    "allowable",
    "bearing",
    "required",
    "below",
    "holding",
    "current",
    "moment of inertia",
    "maximum",
    "continuous",
    "published",
    "needs",
)
"""Words no German check message may contain."""


def _german_catalog() -> dict[str, str]:
    with catalog_path("de").open("rb") as file:
        catalog = read_po(file, locale="de")
    return {str(m.id): str(m.string) for m in catalog if m.id}


def _fields(template: str) -> set[tuple[str, str]]:
    return {(name, spec or "") for _, name, spec, _ in string.Formatter().parse(template) if name}


def _assert_german(text: str) -> None:
    for word in ENGLISH_WORDS:
        assert word not in text, (word, text)


# --- the API ---------------------------------------------------------------------------


@pytest.fixture
def selection_id(client: TestClient) -> str:
    response = client.post(SELECTIONS, json=EXAMPLE_REQUEST)
    assert response.status_code == 201, response.text
    return str(response.json()["id"])


def _detail(client: TestClient, selection_id: str, language: str | None) -> Any:
    headers = {"Accept-Language": language} if language else {}
    response = client.get(f"{SELECTIONS}/{selection_id}/candidates/{MODEL}", headers=headers)
    assert response.status_code == 200, response.text
    return response


def test_the_worked_example_in_german_and_english(client: TestClient, selection_id: str) -> None:
    english = _detail(client, selection_id, "en")
    german = _detail(client, selection_id, "de-DE,de;q=0.9,en;q=0.5")
    assert english.headers["content-language"] == "en"
    assert german.headers["content-language"] == "de"
    en_checks, de_checks = english.json()["checks"], german.json()["checks"]
    assert [(c["name"], c["message_code"], c["message_params"]) for c in en_checks] == [
        (c["name"], c["message_code"], c["message_params"]) for c in de_checks
    ]
    de = {c["name"]: c for c in de_checks}
    assert de["peak_torque"]["message_code"] == "peak_torque.pass"
    assert de["peak_torque"]["message_params"]["limit"] == 151
    assert de["peak_torque"]["message_params"]["value"] == pytest.approx(95.48, abs=0.005)
    assert de["peak_torque"]["message"] == "Beschleunigungsmoment T_1 = 95,48 Nm ≤ T_max = 151 Nm"
    assert de["decel_torque"]["message"] == "Verzögerungsmoment |T_3| = 85,48 Nm ≤ T_max = 151 Nm"
    assert de["max_speed"]["message"] == "Lastdrehzahl n_2 = 40 min⁻¹ ≤ n_max = 90 min⁻¹"
    assert de["continuous_duty"]["message_code"] == "no_data"
    assert de["continuous_duty"]["message_params"] == {
        "what": "continuous-duty zone or continuous torque"  # params stay English
    }
    for check in de_checks:
        _assert_german(check["message"])
    reasons = german.json()["reasons"]
    assert reasons == [
        de["continuous_duty"]["message"],
        de["continuous_speed"]["message"],
        de["drive_voltage"]["message"],
    ]
    assert "Dauerbetriebsbereich oder Dauerdrehmoment" in reasons[0]
    assert "Dauerbetriebsbereich oder zulässige Dauer- bzw. Nenndrehzahl" in reasons[1]


def test_the_english_answer_is_the_scalar_flowcharts_text(
    client: TestClient, selection_id: str
) -> None:
    """Without Accept-Language and with English, the messages are the core's, unchanged."""
    expected = evaluate(worked_example.FHA_25C_50_L, worked_example.APPLICATION)
    for language in (None, "en", "fr"):
        body = _detail(client, selection_id, language).json()
        assert [c["message"] for c in body["checks"]] == [c.message for c in expected.checks]
        assert body["reasons"] == list(expected.reasons)
    assert expected.checks[2].message == "acceleration torque T_1 = 95.48 Nm ≤ T_max = 151 Nm"


def test_the_batch_answers_reasons_and_checks_in_german(client: TestClient) -> None:
    case = {k: v for k, v in EXAMPLE_REQUEST.items() if k != "models"} | {"models": [MODEL]}
    body = {"cases": [case], "include_checks": True, "include_messages": True}
    english = client.post(f"{SELECTIONS}/batch", json=body).json()
    response = client.post(f"{SELECTIONS}/batch", json=body, headers={"Accept-Language": "de"})
    assert response.status_code == 200, response.text
    assert response.headers["content-language"] == "de"
    (candidate,) = response.json()["results"][0]["candidates"]
    (en_candidate,) = english["results"][0]["candidates"]
    assert [c["message_code"] for c in candidate["checks"]] == [
        c["message_code"] for c in en_candidate["checks"]
    ]
    for text in (*candidate["reasons"], *(c["message"] for c in candidate["checks"])):
        _assert_german(text)
    assert "95,48 Nm" in candidate["checks"][2]["message"]


def test_the_batchs_controllers_are_the_details_in_german(
    client: TestClient, selection_id: str
) -> None:
    """Table 521.1's criteria, the voltage checks (Eq. 521.2) and the controllers note of a
    batch candidate with ``include_controllers``: the candidate detail's, in German too."""
    case = {k: v for k, v in EXAMPLE_REQUEST.items() if k != "models"} | {"models": [MODEL]}
    body = {"cases": [case], "include_controllers": True, "include_messages": True}
    german = client.post(f"{SELECTIONS}/batch", json=body, headers={"Accept-Language": "de"})
    assert german.status_code == 200, german.text
    (candidate,) = german.json()["results"][0]["candidates"]
    detail = _detail(client, selection_id, "de").json()
    assert candidate["controllers"] == detail["controllers"]
    assert candidate["controllers_note"] == detail["controllers_note"]
    english = client.post(f"{SELECTIONS}/batch", json=body).json()
    (en_candidate,) = english["results"][0]["candidates"]
    assert candidate["controllers_note"] != en_candidate["controllers_note"]
    _assert_german(candidate["controllers_note"])
    texts = [
        text
        for option in candidate["controllers"]
        for text in (option["voltage"]["message"], *(c["message"] for c in option["criteria"]))
    ]
    assert texts
    for text in texts:
        _assert_german(text)


def test_the_limits_name_their_checks_in_german(client: TestClient) -> None:
    response = client.post(
        f"{SELECTIONS}/limits",
        json=EXAMPLE_REQUEST | {"model": MODEL},
        headers={"Accept-Language": "de"},
    )
    assert response.status_code == 200, response.text
    assert response.headers["content-language"] == "de"
    limiting = [c for limit in response.json()["limits"] for c in limit["limiting_checks"]]
    assert limiting
    for check in limiting:
        assert check["message_code"]
        _assert_german(check["message"])


# --- every rule's messages -------------------------------------------------------------


def _base_operands(**changes: Any) -> Operands:
    """The worked example's operands with every optional datum published."""
    actuator = dataclasses.replace(worked_example.FHA_25C_50_L, stall_torque_nm=36)
    app = worked_example.APPLICATION
    torques = evaluate(actuator, app).torques
    q = operands(actuator, app, torques, app.profile)
    return q._replace(
        continuous_torque_nm=30.0,
        continuous_speed_rpm=30.0,
        rated_speed_rpm=30.0,
        load_torque_nm=5.0,
        brake_holding_torque_nm=20.0,
        torque_constant_nm_per_a=10.0,
        max_current_a=12.0,
        no_load_starting_current_a=0.2,
        no_load_current_constant_a_per_rpm=0.001,
        motor_voltage_constant_v_per_krpm=30.0,
        resistance_line_ohm=1.2,
        inductance_line_h=0.004,
        pole_pairs=5.0,
        dc_bus_voltage_v=560.0,
        radial_force_n=500.0,
        axial_force_n=200.0,
        radial_lever_m=0.05,
        axial_lever_m=0.02,
        load_factor=1.2,
        static_safety_min=1.5,
        required_life_h=20000.0,
        bearing_pitch_diameter_m=0.1,
        bearing_offset_m=0.02,
        bearing_dynamic_load_rating_n=30000.0,
        bearing_static_load_rating_n=40000.0,
        bearing_moment_load_nm=400.0,
        bearing_dynamic_tilting_moment_nm=300.0,
        zone_max_speed_rpm=60.0,
        zone_torque_nm=40.0,
        # issue 28, items 4, 7–9 (TEST VALUES for the gear ratings: none is published)
        gear_required_life_h=20000.0,
        momentary_torque_nm=150.0,
        momentary_count=10.0,
        min_natural_frequency_hz=10.0,
        emergency_stops=100.0,
        limit_torque_t1_nm=2.0,
        limit_torque_t2_nm=6.9,
        stiffness_k1_nm_per_rad=25000.0,
        stiffness_k2_nm_per_rad=34000.0,
        stiffness_k3_nm_per_rad=44000.0,
        brake_emergency_stop_count=200.0,
        brake_closing_time_s=0.07,
        gear_average_torque_limit_nm=80.0,
        gear_repeated_peak_torque_nm=120.0,
        gear_momentary_peak_torque_nm=200.0,
        gear_momentary_peak_count=1000.0,
        gear_average_input_speed_limit_rpm=3000.0,
        gear_rated_torque_nm=50.0,
        gear_rated_life_h=10000.0,
        gear_life_basis=50.0,
        bearing_radial_load_n=4900.0,
        bearing_axial_load_n=14700.0,
    )._replace(**changes)


VARIANTS: tuple[dict[str, Any], ...] = (
    {},
    {"has_zone": True},
    {"has_zone": True, "zone_torque_nm": math.nan},
    {"stall_torque_nm": math.nan, "continuous_speed_rpm": math.nan},
    {"thermal_time_constant_assumed": True, "thermal_time_constant_s": 1.0},
    {"no_load_starting_current_a": math.nan, "rms_torque_nm": math.nan},
    {"decel_torque_nm": math.nan},
    {"bearing_moment_load_nm": math.nan},
    {"radial_force_n": 0.0, "axial_force_n": 0.0},
    {"no_load_torque_slope_nm_per_rpm": 0.05},
    {"bearing_life_exponent": 3.0},
    {"bearing_life_exponent": 10.0 / 3.0},
    {"swing_deg": 0.0},
    {"swing_deg": 2.0},
    {"brake_safety_factor": 2.0},
    {"brake_closing_time_s": math.nan},
    {"drop_torque_nm": 0.0},  # a horizontal axis: nothing falls
    {"drop_torque_nm": 3.0, "travel_mm_per_rad": 1.6},  # a linear axis: the fall in mm
    {"stiffness_k2_nm_per_rad": math.nan},
    {"bearing_radial_load_n": math.nan, "bearing_axial_load_n": math.nan},
)
"""Operands that lead each rule to each of its messages."""


def _messages() -> Iterator[str]:
    """Every rule's message for pass, fail, warn, no data and a failure for any J_A."""
    for rule, variant in itertools.product(ALL_RULES, VARIANTS):
        q = _base_operands(**variant)
        value, limit = rule.value(q, _ops()), rule.limit(q, _ops())
        for status in (Status.PASS, Status.FAIL, Status.WARN):
            if status is Status.WARN and rule.binding is None:
                continue
            message = rule.message(q, status, value, limit)
            yield message
            yield _floor_message(message)
        yield rule.check(q).message
        for need in rule.requires:
            missing = rule.check(q._replace(**dict.fromkeys(need.any_of, math.nan), has_zone=False))
            yield missing.message


def _drive_messages() -> Iterator[str]:
    """Every message of Table 521.1 and Eq. 521.2 around a candidate's controllers: each
    criterion's four outcomes, the voltage check's pass, fail and three kinds of missing
    data, the three notes on a controller list, the output bearing's three notes and a
    stored lean check written from its numbers."""
    from tests.sizing.test_drive import BUSES, CHA, CHA_INTERFACE, CONTROLLERS

    from actuator_selection.catalogue.controllers import (
        BusClass,
        Controller,
        FeedbackSystem,
        ProductFamily,
        SupportLevel,
    )
    from actuator_selection.schemas.controllers import controllers_note
    from actuator_selection.schemas.output_load import OutputLoadIn, output_bearing_note
    from actuator_selection.schemas.quotes import StoredCheck
    from actuator_selection.sizing.compatibility import match_controllers
    from actuator_selection.sizing.drive import DriveOptions, drive_options, shared_voltage_check

    possible = Controller(
        manufacturer="Test",
        type="possible",
        source_row=90,
        families={ProductFamily.CHA_CHM: SupportLevel.POSSIBLE},
        bus_classes={BusClass.V320: SupportLevel.TESTED},
        feedback_systems={FeedbackSystem.SINCOS: SupportLevel.TESTED},
    )
    no_bus = dataclasses.replace(CHA_INTERFACE, bus_classes=None)
    for interface in (CHA_INTERFACE, no_bus):
        matching = match_controllers(actuator=interface, controllers=(*CONTROLLERS, possible))
        for match in matching.matches:
            yield from (r.message for r in match.criteria)
        drive = drive_options(
            actuator=CHA, interface=interface, matching=matching, buses=BUSES, speed_rpm=40.0
        )
        yield controllers_note(drive)
        yield from (o.voltage.message for o in drive.options)
    yield controllers_note(DriveOptions(options=(), excluded=3))
    for speed_rpm in (40.0, 4000.0):  # the 320 V bus reaches n_max at 40 rpm, not at 4000
        for max_speed_rpm in (112.0, 4000.0):
            actuator = dataclasses.replace(CHA, max_speed_rpm=max_speed_rpm)
            yield shared_voltage_check(
                actuator=actuator, interface=CHA_INTERFACE, shared=BUSES[1:2], speed_rpm=speed_rpm
            ).message
    no_constants = dataclasses.replace(CHA, motor_voltage_constant_v_per_krpm=None)
    for actuator, shared in ((no_constants, BUSES), (CHA, ())):
        yield shared_voltage_check(
            actuator=actuator, interface=CHA_INTERFACE, shared=shared, speed_rpm=40.0
        ).message
    bearing = {
        "radial_force_n": 100.0,
        "axial_force_n": 0.0,
        "radial_lever_m": 0.01,
        "axial_lever_m": 0.0,
    }
    for output_load in (None, {**bearing}, {**bearing, "required_life_h": 1000.0}):
        value = None if output_load is None else OutputLoadIn.model_validate(output_load)
        yield output_bearing_note(value)
    for status in ("pass", "fail", "not_applicable"):
        yield StoredCheck(name="max_speed", status=status, value=40, limit=90, unit="rpm").phrase


def test_the_drive_messages_have_codes_and_german_texts() -> None:
    seen: set[str] = set()
    for message in _drive_messages():
        assert isinstance(message, Phrase), message
        seen |= set(_codes(message))
        text = render_check(message, "de")
        assert text != message, message
        _assert_german(text)
        assert render_check(message, "en") == message
    drive_codes = {
        c for c in CHECK_MESSAGES if c.split(".")[0] in {*DRIVE_MESSAGE_GROUPS, "output_voltage"}
    }
    assert seen == drive_codes, drive_codes ^ seen


DRIVE_MESSAGE_GROUPS = (
    "criterion",
    "controllers_note",
    "controller_voltage",
    "output_bearing",
    "stored",
)


def _ops() -> Any:
    from actuator_selection.sizing.checks import FLOAT_OPS

    return FLOAT_OPS


def _codes(message: Phrase) -> Iterator[str]:
    yield message.code
    for value in message.params.values():
        if isinstance(value, Phrase):
            yield from _codes(value)


def test_every_rule_message_has_a_code_and_a_german_text() -> None:
    german = _german_catalog()
    seen: set[str] = set()
    for message in _messages():
        assert isinstance(message, Phrase), message
        seen |= set(_codes(message))
        text = render_check(message, "de")
        assert text != message or not any(c.isalpha() for c in message), message
        _assert_german(text)
        assert render_check(message, "en") == message
    rules = {c for c in CHECK_MESSAGES if c.split(".")[0] not in (*DRIVE_MESSAGE_GROUPS, "limit")}
    retired = {
        "output_voltage.pass",
        "output_voltage.fail",
        # continuous_duty's words before its speed moved to continuous_speed: kept for the
        # answers stored with them (codes are never reused)
        "continuous_duty.approximate_pass",
        "continuous_duty.approximate_fail",
    }
    assert seen == rules - retired, rules - seen
    missing = {key: t for key, t in check_templates().items() if not german.get(t)}
    assert not missing


def test_the_german_templates_keep_the_fields_and_their_formats() -> None:
    german = _german_catalog()
    for template in CHECK_MESSAGES.values():
        assert _fields(german[template]) == _fields(template), template
        words = "".join(literal for literal, *_ in string.Formatter().parse(german[template]))
        assert "rpm" not in words, template


def test_every_template_is_names_and_format_specs_only() -> None:
    """A batch words a message field by field from its template (``batch_messages.
    message_words``): each field a plain name with a format spec at most, no
    conversion (``!r``) and no attribute or index, in English and in German."""
    german = _german_catalog()
    for template in CHECK_MESSAGES.values():
        for text in (template, german[template]):
            for _, name, _, conversion in string.Formatter().parse(text):
                assert conversion is None, text
                assert name is None or name.isidentifier(), text


@pytest.mark.parametrize("spec", [".4g", ".3g", "g", ".6g", ".0f", ""])
def test_a_column_of_numbers_reads_as_its_numbers_one_by_one(spec: str) -> None:
    """A batch writes a message's numbers a column at a time (``Renderer.numbers``):
    each as the message writes it alone, in German and in English."""
    values = [95.48123, -0.0, 1e-7, 123456.7, 2.5e17, -3.25, math.inf, -math.inf, math.nan]
    for language in ("de", "en"):
        phrases = localizer(language).phrases
        assert phrases.numbers(values, spec) == [phrases.format_field(v, spec) for v in values]


def test_german_numbers_use_a_decimal_comma_and_infinity_a_sign() -> None:
    q = _base_operands(radial_force_n=0.0, axial_force_n=0.0)
    static = BEARING_STATIC.check(q).message
    assert "inf" in static
    assert "∞" in render_check(static, "de")
    speed = RULES[0].message(q, Status.FAIL, 1234.5678, 90.5)
    assert (
        render_check(speed, "de")
        == "Lastdrehzahl n_2 = 1235 min⁻¹ überschreitet n_max = 90,5 min⁻¹"
    )
    assert str(speed) == "load speed n_2 = 1235 rpm exceeds n_max = 90.5 rpm"


def test_every_reason_a_limit_has_no_value_has_a_german_text() -> None:
    """The inverse solve's reasons (sizing/inverse.py), each from a real solve: a speed above
    n_max at any pause or t_1, an inertia ratio failed already at J_L = 0 with J_A's 3×
    beyond reach, and a cycle that does not start with a ramp."""
    from actuator_selection.sizing.cycle import Load
    from actuator_selection.sizing.inverse import largest_load_inertia, shortest_accel
    from actuator_selection.sizing.motion import Motion, Segment
    from actuator_selection.sizing.selection import Application

    fha = worked_example.FHA_25C_50_L
    app = worked_example.APPLICATION
    too_fast = dataclasses.replace(
        app, pattern=dataclasses.replace(worked_example.PATTERN, speed_rpm=500)
    )
    too_heavy = dataclasses.replace(app, load=Load(torque_nm=1000, inertia_kgm2=0))
    dwell_first = Application(
        motion=Motion(
            segments=(
                Segment(duration_s=0.1, start_rpm=0, end_rpm=0),
                Segment(duration_s=0.1, start_rpm=0, end_rpm=40),
                Segment(duration_s=0.1, start_rpm=40, end_rpm=0),
            ),
            load=worked_example.APPLICATION.cycle.load,
        )
    )
    reasons = [
        shortest_accel(fha, too_fast).reason,
        largest_load_inertia(fha, too_heavy).reason,
        shortest_accel(fha, dwell_first).reason,
    ]
    seen: set[str] = set()
    for reason in reasons:
        assert isinstance(reason, Phrase), reason
        seen |= set(_codes(reason))
        text = render_check(reason, "de")
        assert text != reason
        _assert_german(text)
    assert {c for c in seen if c.startswith("limit.")} == {
        c for c in CHECK_MESSAGES if c.startswith("limit.")
    }
