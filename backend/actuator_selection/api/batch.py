"""Batch selection: the flowchart for thousands of load cases in one request (ERP)."""

from __future__ import annotations

import itertools
from collections.abc import Iterator, Sequence
from datetime import UTC, datetime
from functools import partial
from typing import Any

import pydantic_core
from fastapi import APIRouter, Request, Response
from fastapi.responses import StreamingResponse

from actuator_selection.api.deps import (
    SessionDep,
    catalogue_snapshot,
    reads_only,
    write_transaction,
)
from actuator_selection.api.errors import (
    RequestFieldError,
    domain_entry,
    field_error,
    language_of,
    service_error,
)
from actuator_selection.api.messages import localizer
from actuator_selection.core.actuators import Actuator
from actuator_selection.core.batch import select_batch
from actuator_selection.core.errors import DomainError
from actuator_selection.core.selection import Application, Selection
from actuator_selection.schemas.batch import (
    MAX_BATCH_CANDIDATES,
    MAX_CANDIDATES_WITH_CONTROLLERS,
    MAX_STORED_CASES,
    BatchSelectionOut,
    BatchSelectionRequest,
    candidate_body,
    controllers_summary,
    result_body,
)
from actuator_selection.schemas.checks import Localize
from actuator_selection.schemas.controllers import DriveOptionBodies, controllers_note
from actuator_selection.schemas.selections import RANKING_RULE
from actuator_selection.services.catalogue import CatalogueSnapshot, DriveContext
from actuator_selection.services.selections import dump_json, size_selection, store_selections

router = APIRouter(tags=["selections"])


def _limits(body: BatchSelectionRequest) -> list[dict[str, Any]]:
    """The limits that depend on more than one field of the request."""
    errors = []
    n = len(body.cases)
    if body.store and n > MAX_STORED_CASES:
        errors.append(
            field_error(
                ["body", "store"],
                f"store: true takes at most {MAX_STORED_CASES} cases per request, got {n}: "
                "send the rest in further requests",
                "too_many_to_store",
            )
        )
    if n * body.top > MAX_BATCH_CANDIDATES:
        errors.append(
            field_error(
                ["body", "top"],
                f"cases × top must be ≤ {MAX_BATCH_CANDIDATES}, got {n} × {body.top}: "
                "ask for fewer candidates or send fewer cases",
                "too_many_candidates",
            )
        )
    if body.include_controllers and n * body.top > MAX_CANDIDATES_WITH_CONTROLLERS:
        errors.append(
            field_error(
                ["body", "include_controllers"],
                f"with controllers, cases × top must be ≤ {MAX_CANDIDATES_WITH_CONTROLLERS}, "
                f"got {n} × {body.top}: each candidate then lists every controller not "
                "excluded; leave include_controllers false or send fewer cases",
                "too_many_candidates",
            )
        )
    return errors


def _applications(
    body: BatchSelectionRequest, known: set[str]
) -> tuple[list[Application], list[dict[str, Any]]]:
    """Each case as the core sees it, and every error, its loc naming the case's index."""
    apps: list[Application] = []
    errors: list[dict[str, Any]] = []
    for i, case in enumerate(body.cases):
        if case.models is not None:
            errors += [
                service_error(
                    ["body", "cases", i, "models", j], "unknown_model", "unknown_actuator", model=m
                )
                for j, m in enumerate(case.models)
                if m not in known
            ]
        try:
            apps.append(case.to_core())
        except DomainError as exc:
            loc: list[str | int] = ["body", "cases", i, *exc.field.split(".")]
            errors.append(domain_entry(loc, exc))
    return apps, errors


class _Drives:
    """Drive options of the candidates answered, each computed once per request."""

    def __init__(self, context: DriveContext, localize: Localize) -> None:
        self._context = context
        self._summaries: dict[str, dict[str, Any]] = {}
        self._localize = localize
        self._lists: dict[tuple[str, float], list[dict[str, Any]]] = {}
        self._bodies = DriveOptionBodies(localize)  # criteria and voltage checks in words

    def summary(self, actuator: Actuator, speed_rpm: float) -> dict[str, Any]:
        """``controllers_excluded`` and ``controllers_note`` (:func:`controllers_summary`).

        Both rest on the Table 521.1 matching alone, which depends on the actuator and
        not on the load speed, so one computation per model serves every case.
        """
        found = self._summaries.get(actuator.model)
        if found is None:
            drive = self._context.options(actuator, speed_rpm=speed_rpm)
            found = self._summaries[actuator.model] = controllers_summary(
                drive.excluded, controllers_note(drive), self._localize
            )
        return found

    def controllers(self, actuator: Actuator, speed_rpm: float) -> list[dict[str, Any]]:
        """The ``controllers`` list of a single selection at load speed n_2."""
        key = (actuator.model, speed_rpm)
        found = self._lists.get(key)
        if found is None:
            drive = self._context.options(actuator, speed_rpm=speed_rpm)
            found = self._lists[key] = [
                o.model_dump(mode="json") for o in self._bodies.controllers(drive)
            ]
        return found


def _store(
    request: Request,
    body: BatchSelectionRequest,
    apps: list[Application],
    catalogue: CatalogueSnapshot,
    context: DriveContext,
) -> list[str | None]:
    """Store each case as POST /selections does (the whole ranking); their ids.

    The selections are computed first and then written in a transaction of their
    own (the request's own transaction only reads: the endpoint is :func:`reads_only`),
    so on SQLite the write lock is held for the inserts alone.
    """
    created_at = datetime.now(UTC)
    sized = [
        size_selection(case, app, catalogue.actuators_of(case.models), catalogue, created_at)
        for case, app in zip(body.cases, apps, strict=True)
    ]
    store_selections(partial(write_transaction, request), sized)
    return [s.id for s in sized]


def _candidates(
    selection: Selection,
    speed_rpm: float,
    body: BatchSelectionRequest,
    drives: _Drives,
    localize: Localize,
) -> list[dict[str, Any]]:
    out = []
    for c in selection.candidates:
        out.append(
            candidate_body(
                c,
                include_checks=body.include_checks,
                controllers=(
                    drives.controllers(c.actuator, speed_rpm) if body.include_controllers else None
                ),
                controllers_summary=drives.summary(c.actuator, speed_rpm),
                localize=localize,
            )
        )
    return out


@router.post(
    "/selections/batch",
    response_model=BatchSelectionOut,
    responses={
        201: {
            "description": "with `store: true`: the cases were stored",
            "model": BatchSelectionOut,
        },
        422: {
            "description": "an invalid case (`loc` names its index), a model the catalogue "
            "lacks, or a limit exceeded"
        },
    },
    description="Runs the flowchart for every case against the catalogue (or the case's "
    "`models`) and answers the best `top` candidates of each, in the order of the cases, "
    f"each as in a single selection. Ranking: {RANKING_RULE}. Nothing is stored unless "
    "`store` is true.",
)
@reads_only
def create_batch(body: BatchSelectionRequest, request: Request, session: SessionDep) -> Response:
    """Size many load cases against the catalogue."""
    if errors := _limits(body):
        raise RequestFieldError(errors)
    catalogue = catalogue_snapshot(request, session)
    version = catalogue.version
    actuators = list(catalogue.actuators)
    apps, errors = _applications(body, {a.model for a in actuators})
    if errors:
        raise RequestFieldError(errors)
    context = DriveContext(catalogue)
    ids: list[str | None] = [None] * len(apps)
    if body.store:
        ids = _store(request, body, apps, catalogue, context)
    models = [case.models for case in body.cases]
    # The cases are in ``apps`` now; their request models (36 MB for 20,000 cases) are let
    # go before the answer streams, which keeps the peak memory of a large batch down.
    body.cases.clear()
    language = language_of(request.scope)
    localize = localizer(language)
    chunks = _result_chunks(
        body, actuators, apps, models, ids, _Drives(context, localize), localize
    )
    head = (
        b'{"catalogue_version":'
        + pydantic_core.to_json(version)
        + b',"ranking":'
        + pydantic_core.to_json(RANKING_RULE)
        + b',"results":['
    )
    # The first slice is computed before the answer starts, so that a fault in it is
    # still an error answer; the rest is computed while the answer is sent.
    first = next(chunks, b"")
    return StreamingResponse(
        itertools.chain((head, first), chunks, (b"]}",)),
        media_type="application/json",
        status_code=201 if body.store else 200,
        headers={"Content-Language": language, "Vary": "Accept-Language"},
    )


STREAM_CASES = 200
"""Cases computed and written per slice of a batch answer: memory stays flat in the
number of cases (20,000 cases peaked at 622 MB when the answer was built whole). A slice
of 500 cases with checks held 27 MB of Python objects at its peak, one of 200 holds 11 MB
(tracemalloc), at no measurable cost in time."""


def _select(
    actuators: list[Actuator],
    apps: list[Application],
    models: Sequence[list[str] | None],
    top: int,
) -> list[Selection]:
    """``select_batch`` for cases whose checks may differ (a brake adds one): each set of
    checks run on its own cases, the selections back in the order of the cases."""
    groups: dict[object, list[int]] = {}
    for i, app in enumerate(apps):
        groups.setdefault(app.rules, []).append(i)
    out: list[Selection | None] = [None] * len(apps)
    for indexes in groups.values():
        chosen = select_batch(
            actuators,
            [apps[i] for i in indexes],
            top=top,
            models=[models[i] for i in indexes],
        )
        for i, selection in zip(indexes, chosen, strict=True):
            out[i] = selection
    return [s for s in out if s is not None]


def _result_chunks(
    body: BatchSelectionRequest,
    actuators: list[Actuator],
    apps: list[Application],
    models: list[list[str] | None],
    ids: list[str | None],
    drives: _Drives,
    localize: Localize,
) -> Iterator[bytes]:
    """The ``results`` array's JSON, ``STREAM_CASES`` cases at a time, comma-joined.

    These dicts are BatchSelectionOut's JSON (the tests validate them); validating
    them again as models would take longer than the whole flowchart.
    """
    for start in range(0, len(apps), STREAM_CASES):
        end = start + STREAM_CASES
        selections = _select(actuators, apps[start:end], models[start:end], body.top)
        results = [
            dump_json(
                result_body(
                    id=id_,
                    selection=selection,
                    candidates=_candidates(
                        selection, selection.profile.peak_speed_rpm, body, drives, localize
                    ),
                )
            )
            for id_, selection in zip(ids[start:end], selections, strict=True)
        ]
        yield (b"," if start else b"") + b",".join(results)
