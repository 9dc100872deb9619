"""A batch's checks written from the engine's arrays (``CodedChecks``) are the text the
check-by-check path writes (a dict per check, ``coded_check_body``), byte for byte; so
are their words and the candidates' reasons written from the arrays (``check_body``,
``candidate_body``), in English and in German."""

from __future__ import annotations

import dataclasses
import math
import random
from typing import Any

import orjson
import pytest
from bench.batch import synthetic_catalogue
from bench.selection import random_cases
from sqlalchemy.orm import Session

from actuator_selection.i18n.localize import localizer
from actuator_selection.phrases.check_messages import codes_only, jsonable_params, phrase
from actuator_selection.services.catalogue import CatalogueCache
from actuator_selection.services.presenters.batch import (
    CodedChecks,
    check_body,
    coded_check_body,
    coded_checks_json,
    worded_reasons,
)
from actuator_selection.services.presenters.batch_messages import filled, param_items
from actuator_selection.services.presenters.selection import dump_json
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.checks import Rule, rules_for
from actuator_selection.sizing.engine import select_batch


def _varied(n: int, seed: int) -> list[Application]:
    """Random cases, some with the drive sized, a brake, a thermal time constant, or a
    cycle so long against it that the heating follows its segments."""
    rng = random.Random(seed)
    out = []
    for app in random_cases(n, seed=seed):
        changes: dict[str, Any] = {}
        if rng.random() < 0.3:
            changes["drive"] = True
        if rng.random() < 0.2:
            changes["brake"] = True
        if rng.random() < 0.3:
            changes["thermal_time_constant_s"] = rng.choice([0.5, 5.0, 60.0, 3000.0])
        out.append(dataclasses.replace(app, **changes) if changes else app)
    return out


@pytest.mark.parametrize("seed", [3, 11])
def test_checks_from_arrays_are_the_checks_one_by_one(session: Session, seed: int) -> None:
    catalogue = CatalogueCache().snapshot(session)
    # the starter catalogue, and made-up actuators some without J_A or T_0 (no data, and
    # failures at the least value for every J_A)
    actuators = [*catalogue.actuators, *synthetic_catalogue(40, seed=seed)]
    apps = _varied(40, seed)
    groups: dict[tuple[Rule, ...], list[Application]] = {}
    for app in apps:
        groups.setdefault(rules_for(app), []).append(app)
    seen: set[tuple[str, str | None]] = set()
    for rules, cases in groups.items():
        selections = select_batch(actuators, cases, top=len(actuators), rules=rules)
        coded = CodedChecks()
        for selection in selections:
            for candidate in selection.candidates:
                with codes_only():
                    one_by_one = [coded_check_body(*named) for named in candidate.briefs()]
                written = dump_json(coded.of(candidate))
                assert written == dump_json(one_by_one)
                seen.update((c["status"], c["message_code"]) for c in orjson.loads(written))
    statuses = {status for status, _ in seen}
    assert {"pass", "fail", "warn", "no_data"} <= statuses
    codes = {code for _, code in seen}
    for code in (
        "continuous_duty.current_pass",
        "continuous_duty.rectangle_fail",
        "continuous_duty.beyond_zone",
        "thermal_peak.fail",
        "thermal_peak.current_pass",
        "continuous_speed.fail",
        "inertia_ratio.warn",
        "drive_voltage.pass",
        "fail_for_any_inertia",
        "no_data",
    ):
        assert code in codes


@pytest.mark.parametrize(("seed", "language"), [(3, "en"), (11, "de"), (5, "de")])
def test_words_from_arrays_are_the_checks_worded_one_by_one(
    session: Session, seed: int, language: str
) -> None:
    """Each check's ``message`` and each candidate's ``reasons`` written over the cells
    at once (``coded_checks_json`` with words, ``worded_reasons``) are what the checks
    built one by one say in that language (``check_body``, ``Candidate.reasons``)."""
    catalogue = CatalogueCache().snapshot(session)
    actuators = [*catalogue.actuators, *synthetic_catalogue(40, seed=seed)]
    words = localizer(language)
    groups: dict[tuple[Rule, ...], list[Application]] = {}
    for app in _varied(40, seed):
        groups.setdefault(rules_for(app), []).append(app)
    reasons = worded = 0
    for rules, cases in groups.items():
        kept: dict[int, tuple[Any, list[bytes], list[bytes], list[bytes]]] = {}
        for selection in select_batch(actuators, cases, top=len(actuators), rules=rules):
            for candidate in selection.candidates:
                found = candidate.decided()
                assert found is not None
                decided, cell = found
                if id(decided) not in kept:  # the cells detailed together, written at once
                    written = coded_checks_json(decided, words)
                    kept[id(decided)] = (
                        decided,
                        written.checks,
                        written.reasons(decided.not_passing),
                        worded_reasons(decided, words),
                    )
                _, checks, its_reasons, reasons_alone = kept[id(decided)]
                one_by_one = [check_body(c, words) for c in candidate.checks]
                assert checks[cell] == dump_json(one_by_one)
                said = dump_json([words(r) for r in candidate.reasons])
                assert its_reasons[cell] == said
                assert reasons_alone[cell] == said
                reasons += len(candidate.reasons)
                worded += len(one_by_one)
    assert reasons > 0
    assert worded > 1000


def test_params_as_numbers_are_written_as_the_dicts_write_them() -> None:
    """Floats as orjson writes them (shortest round trip, exponents included), and a NaN or
    an infinite param as its repr, a string (``jsonable_params``)."""
    import numpy as np

    values = [0.1, 5.0, 1e-7, 1.5e16, 123456789.0, -2.5e-300, 1e300, math.nan, math.inf, -math.inf]
    items = param_items(np.array(values))
    for value, item in zip(values, items, strict=True):
        params = jsonable_params(phrase("max_speed.pass", value=value, limit=1.0))
        assert params is not None
        assert item == dump_json(params["value"])
        if math.isfinite(value):
            assert item == orjson.dumps(value)


def test_cells_are_their_parts_and_members_joined() -> None:
    """Each cell's text is the parts with each None taken by the next member's item of
    that cell, literal text as it is (a ``%`` too); members that do not fit are refused."""
    parts = [b'{"a":', None, b',"b":"100%"', b',"c":', None, None, b"}"]
    members = [[b"1", b"2", b"3"], [b"x", b"", b"z"], [b"!", b"?", b"."]]
    assert filled(parts, members, 3) == [
        b'{"a":1,"b":"100%","c":x!}',
        b'{"a":2,"b":"100%","c":?}',
        b'{"a":3,"b":"100%","c":z.}',
    ]
    assert filled([b"[]"], [], 2) == [b"[]", b"[]"]
    with pytest.raises(ValueError, match="more members"):
        filled([None], [[b"1"], [b"2"]], 1)
    with pytest.raises(ValueError, match="each of the 3 cells"):
        filled([None, None], [[b"1", b"2", b"3"], [b"1", b"2"]], 3)
