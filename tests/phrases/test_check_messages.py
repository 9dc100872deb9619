"""A check message's parameters as the API sends them (phrases/check_messages.py)."""

from __future__ import annotations

import json
import math

import orjson
import pytest

from actuator_selection.phrases.check_messages import (
    ENGLISH,
    Phrase,
    codes_only,
    jsonable_params,
    phrase,
)
from actuator_selection.phrases.messages import Text


def _of_every_kind() -> Phrase:
    """A message whose params are numbers (NaN and −∞ among them), words, a count and a
    clause (with +∞)."""
    return phrase(
        "continuous_duty.approximate_pass",
        value=17.25,
        limit=float("nan"),
        mean_speed_rpm=-math.inf,
        what=Text("continuous stall torque T_0"),
        speed_rpm=3,
        speed_what=phrase("thermal_peak.short", rms_torque_nm=math.inf),
    )


def test_params_travel_as_json_with_clauses_words_and_non_finite_numbers_spelled_out() -> None:
    params = jsonable_params(_of_every_kind())
    assert params == {
        "value": 17.25,
        "limit": "nan",
        "mean_speed_rpm": "-inf",
        "what": "continuous stall torque T_0",
        "speed_rpm": 3,
        "speed_what": {"code": "thermal_peak.short", "params": {"rms_torque_nm": "inf"}},
    }
    assert type(params["what"]) is str  # words as plain text, not the marker class
    # the same document from both encoders: nothing left that only one of them can write
    assert orjson.loads(orjson.dumps(params)) == json.loads(json.dumps(params, allow_nan=False))


def test_lists_and_alternatives_keep_their_items_and_a_plain_string_has_no_params() -> None:
    listed = Phrase("controllers_note.unconfirmed", {"count": 2, "excluded": 1, "missing": [
        Text("feedback system"), Text("DC bus")]})  # fmt: skip
    assert jsonable_params(listed) == {
        "count": 2,
        "excluded": 1,
        "missing": ["feedback system", "DC bus"],
    }
    assert jsonable_params("a rule's own words") is None


def test_codes_only_keeps_code_and_params_and_writes_no_words() -> None:
    """Within ``codes_only`` a message is its code and params (the same JSON), its English
    text not written; outside, and after an error within, the text is back."""
    clause = phrase("thermal_peak.short", rms_torque_nm=12.5)
    worded = phrase("peak_torque.fail", value=95.48, limit=float("inf"))
    with codes_only():
        coded = phrase("peak_torque.fail", value=95.48, limit=float("inf"))
        nested = phrase("continuous_duty.pass", value=1.0, limit=2.0, mean_speed_rpm=3.0)
        assert isinstance(coded, Phrase)
        assert str(coded) == ""
        assert (coded.code, jsonable_params(coded)) == (worded.code, jsonable_params(worded))
        assert jsonable_params(phrase("fail_for_any_inertia", message=clause)) == {
            "message": {"code": "thermal_peak.short", "params": {"rms_torque_nm": 12.5}}
        }
        assert nested.code == "continuous_duty.pass"
    assert str(phrase("peak_torque.fail", value=95.48, limit=151.0)).startswith(
        "acceleration torque T_1 = 95.48 Nm exceeds"
    )
    with pytest.raises(RuntimeError), codes_only():
        raise RuntimeError
    assert str(phrase("peak_torque.fail", value=95.48, limit=151.0)) != ""


def test_the_english_renderer_writes_a_phrase_as_its_own_text() -> None:
    """``ENGLISH`` (what a batch words its English messages with, field by field) reads
    as the :class:`Phrase` itself: numbers by their spec, words, a clause, a clause left
    out, lists and alternatives, counts and non-finite numbers; and its numbers over a
    column are its fields one by one."""
    messages = [
        phrase("peak_torque.fail", value=95.48123, limit=151.0),
        _of_every_kind(),
        phrase("fail_for_any_inertia", message=phrase("thermal_peak.short", rms_torque_nm=1.5)),
        phrase("controller_voltage.at_speed", output="U_OUT", speed_rpm=12.0, at_max_speed=None),
        Phrase(
            "controllers_note.unconfirmed",
            {"count": 2, "excluded": 1, "missing": [Text("feedback system"), Text("DC bus")]},
        ),
        Phrase(
            "criterion.excluded",
            {"criterion": Text("sensor"), "options": ("A", "B"), "reference": "Table 521.1"},
        ),
    ]
    for message in messages:
        assert ENGLISH(message) == str(message)
    assert ENGLISH("a rule's own words") == "a rule's own words"
    values = [95.48123, 1e-7, 123456.0, -0.0, math.nan]
    assert ENGLISH.numbers(values, ".4g") == [ENGLISH.format_field(v, ".4g") for v in values]
