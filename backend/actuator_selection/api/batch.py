"""Batch selection: the flowchart for thousands of load cases in one request (ERP).

The use case is ``services/batch.py``; here the request's cases become the core's load
cases, each error naming its case's index.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable, Coroutine
from functools import partial
from typing import Any

import anyio.to_thread
import pydantic_core
from fastapi import APIRouter, Depends, Request, Response
from fastapi.exceptions import RequestValidationError
from fastapi.responses import StreamingResponse
from fastapi.routing import APIRoute

from actuator_selection.api.selections import (
    refuse_unknown_models,
    selection_location,
    unknown_models,
)
from actuator_selection.errors import DomainError
from actuator_selection.http.deps import (
    SessionDep,
    catalogue_snapshot,
    reads_only,
    write_transaction,
)
from actuator_selection.http.errors import RequestFieldError, domain_entry, language_of
from actuator_selection.i18n.localize import localizer
from actuator_selection.schemas.batch import BatchSelectionOut, BatchSelectionRequest
from actuator_selection.schemas.batch_columns import BatchColumnsOut, BatchColumnsRequest
from actuator_selection.schemas.selections import RANKING_RULE
from actuator_selection.services.batch import check_limits, size_batch
from actuator_selection.services.batch_columns import check_columns, size_columns
from actuator_selection.services.profiles import with_profiles
from actuator_selection.sizing.selection import Application


class _BulkRequest(Request):
    """A request whose JSON body pydantic's parser (jiter) reads: a batch's megabytes of
    numbers in a fifth to a half of the standard library's time (20,000 cases as columns:
    7 ms, not 46; as cases: 51 ms, not 90), into the same objects and with no more memory
    than they take (orjson, as fast, peaked at 40 and 81 MB on the way). Its errors are
    the standard library's ``JSONDecodeError`` at the same place, which FastAPI answers as
    ``json_invalid``; NaN and Infinity, which JSON does not have, are such errors here
    rather than numbers that validation refuses."""

    async def json(self) -> Any:
        if not hasattr(self, "_json"):
            body = await self.body()
            try:
                self._json = pydantic_core.from_json(body, allow_inf_nan=False)
            except ValueError as exc:
                raise _decode_error(str(exc), body) from None
        return self._json


def _decode_error(message: str, body: bytes) -> json.JSONDecodeError:
    """jiter's error ("… at line 3 column 4") as the standard library's, at its offset."""
    found = re.search(r" at line (\d+) column (\d+)$", message)
    if found is None:
        return json.JSONDecodeError(message, body.decode(errors="replace"), 0)
    line, column = int(found[1]), int(found[2])
    text = body.decode(errors="replace")
    start = 0
    for _ in range(line - 1):
        start = text.index("\n", start) + 1
    return json.JSONDecodeError(message[: found.start()], text, start + column - 1)


class _BulkRoute(APIRoute):
    """A route whose request body is parsed by :class:`_BulkRequest`."""

    def get_route_handler(self) -> Callable[[Request], Coroutine[Any, Any, Response]]:
        handler = super().get_route_handler()

        async def parse_with_jiter(request: Request) -> Response:
            return await handler(_BulkRequest(request.scope, request.receive))

        return parse_with_jiter


router = APIRouter(tags=["selections"], route_class=_BulkRoute)


async def cases_validated_in_a_thread(request: Request) -> None:
    """The per-case batch's body validated in a worker thread, not on the event loop.

    FastAPI validates a body on the event loop, where nothing else of the process runs
    meanwhile: 20,000 cases of 40 segments (21 MB, within the bulk limit) took 3.5 s to
    validate, and the process answered nothing else, ``/health`` included. Here (a
    dependency of the route: after the media type and the API key are checked, as
    FastAPI's own validation comes after them) the route's body is validated as FastAPI
    validates it (its ``body_field``, the same errors), in a worker thread: pydantic
    calls the cases' discriminators, Python code, case by case, so the interpreter
    passes to the event loop meanwhile. A refused body is the 422 FastAPI gives; an
    accepted one's cases replace the parsed ones, so that FastAPI's validation then takes
    them as they are (an instance of the model is not validated again). What stays on
    the event loop is the parse of the JSON text (pydantic's parser, ~20 ms a MB here),
    which holds the interpreter as it builds the objects."""
    route = request.scope.get("route")
    field = getattr(route, "body_field", None)
    if field is None or not await request.body():
        return  # FastAPI names the missing body
    body = await request.json()  # parsed already (the endpoint's body), kept
    cases = body.get("cases") if isinstance(body, dict) else None
    if not isinstance(cases, list):
        return  # no cases to validate: FastAPI's validation names what is wrong
    value, errors = await anyio.to_thread.run_sync(partial(field.validate, body, {}, loc=("body",)))
    if errors:
        raise RequestValidationError(errors, body=body)
    cases[:] = value.cases


def _applications(
    body: BatchSelectionRequest, known: set[str]
) -> tuple[list[Application], list[dict[str, Any]]]:
    """Each case as the core sees it, and every error, its loc naming the case's index."""
    apps: list[Application] = []
    errors: list[dict[str, Any]] = []
    for i, case in enumerate(body.cases):
        if case.models is not None:
            errors += unknown_models(["body", "cases", i, "models"], case.models, known)
        try:
            apps.append(case.to_core())
        except DomainError as exc:
            loc: list[str | int] = ["body", "cases", i, *exc.field.split(".")]
            errors.append(domain_entry(loc, exc))
    return apps, errors


@router.post(
    "/selections/batch",
    response_model=BatchSelectionOut,
    dependencies=[Depends(cases_validated_in_a_thread)],
    responses={
        201: {
            "description": "with `store: true`: the cases were stored; `Location` names the "
            "first case's selection, each result's `id` its own",
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
    check_limits(body)
    cases = with_profiles(
        session, body.cases, [["body", "cases", i] for i in range(len(body.cases))]
    )
    body = body.model_copy(update={"cases": cases})
    catalogue = catalogue_snapshot(request, session)
    apps, errors = _applications(body, {a.model for a in catalogue.actuators})
    if errors:
        raise RequestFieldError(errors)
    language = language_of(request.scope)
    answer = size_batch(
        body,
        apps,
        catalogue=catalogue,
        writer=partial(write_transaction, request),
        localize=localizer(language),
    )
    headers = {"Content-Language": language, "Vary": "Accept-Language"}
    if answer.stored:  # the first stored case's selection; each result names its own `id`
        headers["Location"] = selection_location(request, answer.stored[0])
    return StreamingResponse(
        answer.chunks,
        media_type="application/json",
        status_code=201 if body.store else 200,
        headers=headers,
    )


@router.post(
    "/selections/batch/columns",
    response_model=BatchColumnsOut,
    responses={
        422: {
            "description": "a value outside its rule (`loc` names the column and the case's "
            "index), columns of unequal lengths, or a limit exceeded"
        }
    },
    description="The batch for a table of load cases in the chapter's shorthand: each "
    "figure of Table 516.1 as a column (case i is the i-th value of every column), the "
    "best `top` candidates of each case answered as a table (a row per candidate, "
    "`candidates.case` naming its case) with each check as a column and each model's "
    "controller summary once. The numbers are the per-case batch's, bit for bit. "
    f"Ranking: {RANKING_RULE}. Nothing is stored.",
)
@reads_only
def create_batch_columns(
    body: BatchColumnsRequest, request: Request, session: SessionDep
) -> Response:
    """Size a table of load cases against the catalogue."""
    check_columns(body)
    catalogue = catalogue_snapshot(request, session)
    refuse_unknown_models(body.models, catalogue)
    language = language_of(request.scope)
    answer = size_columns(body, catalogue=catalogue, localize=localizer(language))
    return StreamingResponse(
        answer,
        media_type="application/json",
        headers={"Content-Language": language, "Vary": "Accept-Language"},
    )
