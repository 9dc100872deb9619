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


def test_briefs_are_the_checks_unbuilt(session: Session) -> None:
    """A batch candidate's checks as briefs (read before the checks are built) state what
    the checks built from the same decisions state: name, unit, reference, status, value,
    limit, approximate and message, with its words."""
    catalogue = CatalogueCache().snapshot(session)
    apps = random_cases(60, seed=9)
    briefed = select_batch(list(catalogue.actuators), apps, top=3)
    built = select_batch(list(catalogue.actuators), apps, top=3)
    statuses = set()
    for one, other in zip(briefed, built, strict=True):
        for candidate, twin in zip(one.candidates, other.candidates, strict=True):
            pairs = candidate.briefs()  # checks not built yet: from the rules
            for (rule, brief), check in zip(pairs, twin.checks, strict=True):
                assert (rule.name, rule.unit, rule.reference) == (
                    check.name,
                    check.unit,
                    check.reference,
                )
                assert brief == (
                    check.status,
                    check.value,
                    check.limit,
                    check.approximate,
                    check.message,
                )
                statuses.add(check.status.value)
            assert candidate.open_checks == twin.open_checks
            checks = candidate.checks  # once built, the briefs come from the checks
            assert candidate.briefs() == [
                (c, (c.status, c.value, c.limit, c.approximate, c.message)) for c in checks
            ]
    assert {"pass", "fail", "no_data"} <= statuses
