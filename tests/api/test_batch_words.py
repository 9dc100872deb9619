"""A batch candidate's reasons are its checks' messages: each is worded once."""

from __future__ import annotations

from bench.selection import random_cases
from sqlalchemy.orm import Session

from actuator_selection.i18n.localize import localizer
from actuator_selection.services.catalogue import CatalogueCache
from actuator_selection.services.presenters.batch import candidate_body
from actuator_selection.sizing.engine import select_batch


def test_reasons_take_the_words_of_the_checks(session: Session) -> None:
    catalogue = CatalogueCache().snapshot(session)
    german = localizer("de")
    worded: list[str] = []

    def counted(message: str) -> str:
        worded.append(message)
        return german(message)

    selections = select_batch(list(catalogue.actuators), random_cases(40, seed=5), top=3)
    reasons = 0
    for selection in selections:
        for candidate in selection.candidates:
            before = len(worded)
            body = candidate_body(
                candidate, include_checks=True, controllers=None, controllers_summary={},
                localize=counted,
            )  # fmt: skip
            assert len(worded) - before == len(candidate.checks)  # the reasons: none more
            assert body["reasons"] == [german(r) for r in candidate.reasons]
            assert body["reasons"] == list(
                dict.fromkeys(c["message"] for c in body["checks"] if c["status"] != "pass")
            )
            reasons += len(body["reasons"])
    assert reasons > 0
