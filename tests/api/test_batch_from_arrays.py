"""A per-case batch's answer written from the ranking's arrays (``services.batch.
_ranked_results``: no profile per case, no candidate per cell) is the answer written from
the selections (``_select``, ``result_body``), byte for byte: varied cases (a brake, the
drive, a thermal time constant, a model list, case ids), with and without checks and
controllers, in English and German, with and without ``include_messages``."""

from __future__ import annotations

import random

import pytest
from sqlalchemy.orm import Session
from tests.api.test_batch_checks_json import _varied

from actuator_selection.i18n.localize import localizer
from actuator_selection.schemas.batch import BatchSelectionRequest
from actuator_selection.services import batch
from actuator_selection.services.catalogue import CatalogueCache, DriveContext
from actuator_selection.services.presenters.batch import CodedChecks, result_body
from actuator_selection.services.presenters.selection import dump_json
from actuator_selection.sizing.engine import catalogue_arrays


@pytest.mark.parametrize(
    ("language", "checks", "controllers", "messages", "top"),
    [
        ("en", True, False, False, 3),
        ("de", True, True, False, 2),
        ("en", False, False, False, 5),
        ("de", False, True, False, 1),
        ("en", True, True, True, 3),
        ("de", True, False, True, 4),
        ("en", False, False, True, 2),
        ("de", False, True, True, 3),
    ],
)
def test_answer_from_arrays_is_the_answer_from_selections(
    session: Session, language: str, checks: bool, controllers: bool, messages: bool, top: int
) -> None:
    catalogue = CatalogueCache().snapshot(session)
    actuators = tuple(catalogue.actuators)  # each with its drive data
    arrays = catalogue_arrays(actuators)
    rng = random.Random(top)
    n = batch.STREAM_CASES + 50  # two slices
    apps = _varied(n, seed=top)
    names = [a.model for a in actuators]
    models = [rng.sample(names, rng.randint(1, 8)) if rng.random() < 0.2 else None for _ in apps]
    ids: list[tuple[str | None, str | None]] = [
        (None, f"case-{i}" if rng.random() < 0.5 else None) for i in range(n)
    ]
    body = BatchSelectionRequest.model_construct(
        cases=[],
        top=top,
        include_checks=checks,
        include_controllers=controllers,
        include_messages=messages,
    )
    localize = localizer(language)

    def drives() -> batch.Drives:
        return batch.Drives(DriveContext(catalogue), localize)

    cases = batch._Cases(body, actuators, arrays, apps, models, ids, drives(), localize)
    written = b"".join(batch._result_chunks(cases))
    # written from the arrays, not from selections, in words too (a language's Localizer)
    assert batch._from_arrays(cases, slice(0, n), each=False) is not None
    expected = []
    for start in range(0, n, batch.STREAM_CASES):
        end = start + batch.STREAM_CASES
        found = batch._select(actuators, arrays, apps[start:end], models[start:end], top)
        coded, of_models = CodedChecks(), drives()
        for (id_, case_id), selection in zip(ids[start:end], found, strict=True):
            speed = selection.profile.peak_speed_rpm
            candidates = batch._candidates(selection, speed, body, of_models, localize, coded)
            expected.append(
                dump_json(
                    result_body(id=id_, case_id=case_id, selection=selection, candidates=candidates)
                )
            )
    assert written == b",".join(expected)
    assert written.count(b'"case_id":"case-') == sum(1 for _, c in ids if c)
