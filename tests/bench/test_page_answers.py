"""``bench.page`` reads the server's answers after the submit from the page's Resource
Timing as documented (``Answers``)."""

from __future__ import annotations

import math
from typing import Any

import pytest
from bench.page import Answers

BASE = "http://127.0.0.1:8000"


def entry(path: str, start: float, end: float) -> dict[str, Any]:
    """A resource entry as ``charts_load`` collects it (ms since navigation start)."""
    return {"name": f"{BASE}{path}", "start": start, "end": end}


def test_the_selection_then_what_was_asked_once_it_answered() -> None:
    entries = [
        entry("/api/v1/mechanisms", 100, 140),  # the form's, before the submit
        entry("/api/v1/selections?top=25", 1_000, 1_120),
        entry("/api/v1/selections/abc/candidates/X", 1_125, 1_180),
        entry("/api/v1/selections/abc/candidates/X/cycle?lang=en", 1_126, 1_230),
        entry("/api/v1/selections/abc/candidates/X/diagram?lang=en", 1_127, 1_210),
    ]
    answers = Answers.of(entries, submitted_ms=990)
    assert answers.selection_ms == pytest.approx(120)
    assert answers.detail_ms == pytest.approx(1_230 - 1_125)


def test_a_selection_asked_before_the_submit_is_not_the_one_waited_for() -> None:
    entries = [
        entry("/api/v1/selections", 500, 560),  # an earlier selection (a permalink's, say)
        entry("/api/v1/selections?top=25", 1_000, 1_050),
    ]
    answers = Answers.of(entries, submitted_ms=990)
    assert answers.selection_ms == pytest.approx(50)
    assert math.isnan(answers.detail_ms)  # nothing asked after it


def test_without_a_selection_after_the_submit_nothing_is_read() -> None:
    answers = Answers.of([entry("/api/v1/mechanisms", 100, 140)], submitted_ms=990)
    assert math.isnan(answers.selection_ms)
    assert math.isnan(answers.detail_ms)
