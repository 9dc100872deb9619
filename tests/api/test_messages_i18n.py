"""Error messages in the user's language: code and params beside the text, German and English
by Accept-Language, units as the chapter prints them, and catalogs that cover every template."""

from __future__ import annotations

import re
import string
from pathlib import Path
from typing import Any

import pytest
from babel.messages.extract import extract_from_dir
from babel.messages.pofile import read_po
from fastapi.testclient import TestClient

from actuator_selection.errors import DomainError, InvalidInputError
from actuator_selection.i18n import localize as messages
from actuator_selection.i18n.localize import all_templates, catalog_path, negotiate
from actuator_selection.sizing.mechanisms import BeltDrive

SELECTIONS = "/api/v1/selections"
BACKEND = Path(messages.__file__).resolve().parents[2]

ENGLISH_WORDS = (
    "Input",
    "should",
    "greater",
    "less",
    "than",
    "equal",
    "required",
    "must",
    "valid",
    "number",
    "permitted",
    "segment ",
    "speed",
    "cycle ",
    "rpm",
    " the ",
    " is ",
    " or ",
)
"""Words that no German message of a translated type may contain."""


def _post(client: TestClient, body: dict[str, Any], language: str | None) -> Any:
    headers = {"Accept-Language": language} if language else {}
    response = client.post(SELECTIONS, json=body, headers=headers)
    assert response.status_code == 422, response.text
    return response


BAD_REQUEST: dict[str, Any] = {
    "load": {"speed_rpm": -40, "torque_nm": 5, "inertia_kgm2": "x", "colour": "red"},
    "cycle": {"accel_s": 0.00001, "constant_s": 0.1, "decel_s": 0.1},
}
"""One request that breaks several rules: a bound with a unit (t_1 ≥ 0.0001 s, n_2 > 0
rpm), a missing field, a wrong type and an unknown field."""


def _shape(entries: list[dict[str, Any]]) -> list[tuple[Any, ...]]:
    return [(e["loc"], e["type"], e["code"], e["params"]) for e in entries]


def test_the_same_request_in_english_and_german_differs_only_in_msg(client: TestClient) -> None:
    english = _post(client, BAD_REQUEST, "en").json()["detail"]
    german = _post(client, BAD_REQUEST, "de").json()["detail"]
    assert _shape(english) == _shape(german)
    assert {e["type"] for e in german} >= {
        "greater_than",
        "greater_than_equal",
        "missing",
        "float_type",
        "extra_forbidden",
    }
    for entry in german:
        assert entry["msg"], entry
        for word in ENGLISH_WORDS:
            assert word not in entry["msg"], (word, entry)
    assert all(e["msg"] != g["msg"] for e, g in zip(english, german, strict=True))


def test_the_t1_error_names_its_unit(client: TestClient) -> None:
    responses = {lang: _post(client, BAD_REQUEST, lang) for lang in ("en", "de")}
    entries = {
        lang: next(e for e in r.json()["detail"] if e["loc"] == ["body", "cycle", "accel_s"])
        for lang, r in responses.items()
    }
    assert entries["en"]["code"] == "greater_than_equal"
    assert entries["en"]["params"] == {"ge": 0.0001, "unit": "s"}
    assert entries["en"]["msg"] == "Input should be greater than or equal to 0.0001 s"
    assert entries["de"]["msg"] == "Eingabe muss größer oder gleich 0,0001 s sein"
    assert responses["de"].headers["content-language"] == "de"


def test_german_writes_min_1_where_english_says_rpm(client: TestClient) -> None:
    body = {**BAD_REQUEST, "load": {"speed_rpm": 1e9, "torque_nm": 5, "inertia_kgm2": 1}}
    body["cycle"] = {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1}
    (english,) = _post(client, body, "en").json()["detail"]
    (german,) = _post(client, body, "de").json()["detail"]
    assert english["params"]["unit"] == german["params"]["unit"] == "rpm"
    assert english["msg"].endswith(" rpm")
    assert german["msg"].endswith(" min⁻¹ sein")


@pytest.mark.parametrize(
    ("header", "language"),
    [
        ("de-DE", "de"),
        ("de-CH,de;q=0.9", "de"),
        ("de;q=0.9,en;q=0.8", "de"),
        ("en;q=0.8,de;q=0.9", "de"),
        ("de;q=0.5,en", "en"),
        ("en-GB,de;q=0.1", "en"),
        ("fr", "en"),
        ("fr,de;q=0.2", "de"),
        ("*", "en"),
        ("de;q=0", "en"),
        ("", "en"),
        (";;q=x,,", "en"),
        (None, "en"),
    ],
)
def test_accept_language_is_negotiated(header: str | None, language: str) -> None:
    assert negotiate(header) == language


def test_the_answer_follows_the_negotiated_language(client: TestClient) -> None:
    for header, expected in (("de-DE", "de"), ("fr", "en"), ("de;q=0.9,en;q=0.8", "de")):
        (entry,) = client.get(
            "/api/v1/actuators/NOPE-1", headers={"Accept-Language": header}
        ).json()["detail"]
        assert (entry["type"], entry["code"], entry["params"]) == (
            "not_found",
            "unknown_actuator",
            {"model": "NOPE-1"},
        )
        german = entry["msg"] == "unbekanntes Antriebsmodell 'NOPE-1'"
        assert german == (expected == "de"), entry


def test_a_segment_cycle_error_in_german(client: TestClient) -> None:
    """A domain error from sizing/motion: its code and params, its text translated."""
    body = {
        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"segments": [{"speed": 40, "duration_s": 0.1}, {"duration_s": 0.5}]},
    }
    english = _post(client, body, "en").json()["detail"]
    german = _post(client, body, "de").json()["detail"]
    assert _shape(english) == _shape(german)
    (entry,) = german
    assert entry["loc"] == ["body", "cycle", "segments"]
    assert entry["type"] == "InvalidInputError"
    assert entry["code"] == "cycle_not_closed"
    assert english[0]["msg"] == "the cycle must end at the speed it starts at: it repeats"
    assert entry["msg"] == (
        "der Zyklus muss mit der Drehzahl enden, mit der er beginnt: er wiederholt sich"
    )


def test_a_segment_rule_with_a_reason_translates_the_reason(client: TestClient) -> None:
    body = {
        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"segments": [{"speed": 40, "duration_s": 0.1, "accel": 100}]},
    }
    (english,) = _post(client, body, "en").json()["detail"]
    (german,) = _post(client, body, "de").json()["detail"]
    assert english["loc"] == german["loc"] == ["body", "cycle", "segments", "0", "duration_s"]
    assert english["code"] == german["code"] == "duration_or_accel"
    assert german["msg"] == "entweder duration_s oder accel angeben"


def test_a_mechanism_rule_names_its_reason_in_german() -> None:
    """A core rule whose reason is a word of its own (the kind of mechanism)."""
    with pytest.raises(DomainError) as caught:
        BeltDrive(mass_kg=5, pulley_diameter_m=0.05, friction_coefficient=0.1, efficiency=1.5)
    exc = caught.value
    assert (exc.field, exc.code, exc.params) == (
        "efficiency",
        "efficiency_above_one",
        {"what": "belt drive"},
    )
    assert exc.template is not None
    assert exc.message == "must be ≤ 1: no belt drive returns more than it takes"
    assert messages.render(exc.template, exc.params, "en") == exc.message
    german = messages.render(exc.template, exc.params, "de")
    assert german == (
        "muss ≤ 1 sein: mit η > 1 gäbe das Übertragungsglied (Riementrieb) mehr Leistung ab, "
        "als ihm zugeführt wird"
    )


def test_a_renamed_domain_error_keeps_its_code() -> None:
    exc = InvalidInputError("segments", code="segments_too_many", params={"max": 200})
    moved = exc.moved("cycle.segments")
    assert (moved.field, moved.code, moved.params, moved.message) == (
        "cycle.segments",
        "segments_too_many",
        {"max": 200},
        "must hold at most 200 segments",
    )
    assert str(moved) == "cycle.segments: must hold at most 200 segments"
    assert type(moved) is InvalidInputError


def test_unknown_types_name_the_allowed_ones_in_both_languages(client: TestClient) -> None:
    body = {**BAD_REQUEST, "load": {"type": "nope"}}
    body["cycle"] = {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1}
    (english,) = _post(client, body, "en").json()["detail"]
    (german,) = _post(client, body, "de").json()["detail"]
    assert english["code"] == german["code"] == "load_type"
    assert english["params"] == german["params"]
    assert "'direct'" in german["msg"]
    assert german["msg"].startswith("type muss einer dieser Werte sein: ")


def test_service_errors_in_german(client: TestClient) -> None:
    headers = {"Accept-Language": "de"}
    (missing,) = client.get("/api/v1/no-such-route", headers=headers).json()["detail"]
    assert (missing["type"], missing["code"]) == ("not_found", "route_not_found")
    assert missing["msg"].startswith("diese Ressource gibt es nicht")
    (anonymous,) = client.get("/api/v1/quotes", headers=headers).json()["detail"]
    assert anonymous["code"] == "unauthorized"
    assert anonymous["msg"].startswith("ein gültiger API-Schlüssel ist nötig")


# --- the catalogs ---------------------------------------------------------------------


def _german() -> dict[str, str]:
    """The server's messages (msgids marked ``N_`` in the code); the keyed words (with a
    msgctxt: the page's and the documents') are declared in the catalogue itself
    (``tests/api/test_page_words.py``)."""
    with catalog_path("de").open("rb") as file:
        catalog = read_po(file, locale="de")
    return {str(m.id): str(m.string) for m in catalog if m.id and not m.context}


def _fields(template: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def test_every_entry_of_the_german_catalog_is_translated() -> None:
    german = _german()
    assert german
    assert not [msgid for msgid, msgstr in german.items() if not msgstr.strip()]
    for msgid, msgstr in german.items():
        # The German text names only values the English one has (it may leave one out).
        assert _fields(msgstr) <= _fields(msgid), msgid


def test_every_template_the_handler_can_emit_has_a_german_entry() -> None:
    german = _german()
    untranslated = {key: t for key, t in all_templates().items() if not german.get(t)}
    assert not untranslated


def test_the_catalog_holds_every_marked_string_and_no_other() -> None:
    """What ``make messages`` extracts (every ``N_("…")``) is what the catalog holds."""
    marked = {
        str(message)
        for _, _, message, _, _ in extract_from_dir(
            str(BACKEND), [("**.py", "python")], keywords={"N_": None}
        )
    }
    german = _german()
    assert marked - german.keys() == set(), "run make messages and translate"
    assert german.keys() - marked == set(), "obsolete entries: run make messages"


def test_no_template_uses_conversions_or_positional_fields() -> None:
    for template in all_templates().values():
        for _, name, spec, conversion in string.Formatter().parse(template):
            if name is not None:
                assert re.fullmatch(r"[a-z_]+", name), template
                assert not spec, template
                assert not conversion, template
