"""The selection flowchart over the catalogue, stored and retrievable."""

from __future__ import annotations

import gzip
from collections.abc import Callable
from datetime import UTC, datetime
from functools import partial
from typing import Annotated, Any, Literal
from urllib.parse import quote

from fastapi import APIRouter, Path, Query, Request, Response
from fastapi.responses import StreamingResponse

from actuator_selection.api.actuators import Cursor
from actuator_selection.documents.figures import cycle_figure, diagram_figure, ratio_figure
from actuator_selection.documents.quote_document import diagram_points, speed_torque_figure
from actuator_selection.documents.quote_document_text import DocumentText
from actuator_selection.documents.reports import (
    COLUMNS,
    candidate_diagram,
    report_csv,
    selection_report,
)
from actuator_selection.errors import ConflictError, NotFoundError
from actuator_selection.http.deps import (
    DocumentLanguageDep,
    SessionDep,
    catalogue_snapshot,
    read_transaction,
    reads_only,
    route_path,
    write_transaction,
)
from actuator_selection.http.errors import RequestFieldError, language_of, service_error
from actuator_selection.i18n.localize import localizer
from actuator_selection.schemas.jobs import NDJSON
from actuator_selection.schemas.limits import LimitsOut, LimitsRequest
from actuator_selection.schemas.ratio import RatioStudyOut, RatioStudyRequest
from actuator_selection.schemas.selections import (
    RANKING_RULE,
    CandidateDetailOut,
    CandidatePageOut,
    ProfileCycleIn,
    SelectionOut,
    SelectionRequest,
)
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.limits import solve_limits, stored_limits
from actuator_selection.services.presenters.selection import DEFAULT_TOP, TOP_MAX, dump_json
from actuator_selection.services.profiles import with_profiles
from actuator_selection.services.ratio import DEFAULT_TOP as RATIO_TOP
from actuator_selection.services.ratio import study
from actuator_selection.services.selections import (
    candidate_detail,
    read_ranking,
    segment_torques,
    stored_answer,
    stored_request,
)
from actuator_selection.services.selections import (
    create_selection as store_new_selection,
)

router = APIRouter(tags=["selections"])


def _localize(request: Request, response: Response) -> Callable[[str], str]:
    """The check messages in the request's language (``Accept-Language``), which the
    answer names in ``Content-Language``."""
    language = language_of(request.scope)
    response.headers["Content-Language"] = language
    response.headers["Vary"] = "Accept-Language"
    return localizer(language)


UNKNOWN_ACTUATOR = "unknown_actuator"
"""The rule a requested model breaks that the catalogue lacks: its ``type`` and ``code``."""


def unknown_models(
    loc: list[str | int], models: list[str], known: set[str]
) -> list[dict[str, Any]]:
    """An error entry for each of ``models`` not ``known``, at ``[*loc, index]``."""
    return [
        service_error([*loc, i], UNKNOWN_ACTUATOR, UNKNOWN_ACTUATOR, model=m)
        for i, m in enumerate(models)
        if m not in known
    ]


def refuse_unknown_models(models: list[str] | None, catalogue: CatalogueSnapshot) -> None:
    """422 naming each of ``models`` that ``catalogue`` lacks."""
    if catalogue.has_all(models):
        return
    assert models is not None
    known = {a.model for a in catalogue.actuators_of(models)}
    unknown = unknown_models(["body", "models"], models, known)
    if unknown:
        raise RequestFieldError(unknown)


@router.post(
    "/selections",
    status_code=201,
    response_model=SelectionOut,
    responses={422: {"description": "invalid load case, or a model the catalogue lacks"}},
    description="Runs the flowchart for every catalogue actuator (or the `models` listed) and "
    f"stores the result. Ranking: {RANKING_RULE}.",
)
@reads_only  # no request transaction: it writes in its own (services.selections)
def create_selection(
    body: SelectionRequest,
    request: Request,
    top: Annotated[
        int,
        Query(
            ge=1,
            le=TOP_MAX,
            description="how many of the ranking's candidates the answer lists; the rest "
            "are read by its `next_cursor`",
        ),
    ] = DEFAULT_TOP,
) -> Response:
    """Size the load case against the catalogue and store the selection."""
    if isinstance(body.cycle, ProfileCycleIn):
        with read_transaction(request) as session:
            (body,) = with_profiles(session, [body], [["body"]])
    sized = store_new_selection(
        body,
        catalogue=request.app.state.catalogue,
        reader=partial(read_transaction, request),
        writer=partial(write_transaction, request),
        now=datetime.now(UTC),
        check=partial(refuse_unknown_models, body.models),
        top=top,
    )
    # The answer is JSON already (see services.selections); returning a model would
    # have FastAPI validate and encode it again.
    location = selection_location(request, sized.id)
    return _json(request, sized.answer, sized.answer_gzip, status_code=201, location=location)


def selection_location(request: Request, selection_id: str) -> str:
    """The path of a stored selection (``GET /selections/{id}``): a 201's ``Location``."""
    return route_path(request, "get_selection", selection_id=selection_id)


def _accepts_gzip(request: Request) -> bool:
    return "gzip" in request.headers.get("accept-encoding", "")


def _json(
    request: Request,
    plain: bytes,
    compressed: bytes,
    *,
    status_code: int = 200,
    location: str | None = None,
) -> Response:
    """The answer as the client takes it: the stored gzip bytes, or the JSON."""
    headers = {"Location": location} if location is not None else {}
    if _accepts_gzip(request):
        headers |= {"Content-Encoding": "gzip", "Vary": "Accept-Encoding"}
        return Response(compressed, status_code, headers, media_type="application/json")
    return Response(plain, status_code, headers, media_type="application/json")


@router.post(
    "/selections/limits",
    responses={422: {"description": "invalid load case, or a model the catalogue lacks"}},
)
@reads_only
def solve_selection_limits(
    body: LimitsRequest, request: Request, response: Response, session: SessionDep
) -> LimitsOut:
    """How far the load case may go for one actuator: the shortest pause, the shortest
    acceleration time (t_1…t_p cycle) and the largest load inertia with no check failing,
    each with the check that fails just beyond it (bisection over the flowchart)."""
    (body,) = with_profiles(session, [body], [["body"]])
    return solve_limits(body, catalogue_snapshot(request, session), _localize(request, response))


@router.post(
    "/selections/ratio-study",
    responses={422: {"description": "invalid load case or study"}},
)
@reads_only
def solve_ratio_study(
    body: RatioStudyRequest,
    request: Request,
    session: SessionDep,
    language: DocumentLanguageDep,
    figure: Annotated[
        bool,
        Query(
            description="with the chart (`figure`, `documents/figures.py`), in `lang`'s language"
        ),
    ] = False,
    top: Annotated[
        int,
        Query(
            ge=1,
            le=TOP_MAX,
            description="how many of the ranking's actuators the answer lists (their "
            "interval ends alone are bisected; every actuator's best value is searched)",
        ),
    ] = RATIO_TOP,
) -> RatioStudyOut:
    """For the ranking's first `top` actuators, the interval(s) of a free transmission value
    (an external ratio, a lead, a pulley or pinion diameter) in which every check passes,
    the value of least binding utilisation and the checks that bind at each end (the engine
    over a grid of values × the catalogue, the best values refined, the listed actuators'
    ends bisected); those that fit first, by their best utilisation."""
    (body,) = with_profiles(session, [body], [["body"]])
    answer = study(body, catalogue_snapshot(request, session), top)
    if figure:
        chart = ratio_figure(answer, DocumentText(language))
        answer = answer.model_copy(update={"figure": chart})
    return answer


@router.get(
    "/selections/{selection_id}",
    response_model=SelectionOut,
    responses={404: {"description": "unknown selection"}},
)
def get_selection(
    selection_id: Annotated[str, Path(max_length=36)], request: Request, session: SessionDep
) -> Response:
    """A stored selection, exactly as it was answered."""
    stored = stored_answer(session, selection_id)
    if "gzip" in request.headers.get("accept-encoding", ""):
        return Response(stored, media_type="application/json", headers={"Content-Encoding": "gzip"})
    return Response(gzip.decompress(stored), media_type="application/json")


@router.get(
    "/selections/{selection_id}/request",
    response_model=SelectionRequest,
    responses={404: {"description": "unknown selection"}},
)
def get_selection_request(
    selection_id: Annotated[str, Path(max_length=36)], session: SessionDep
) -> Any:
    """The load case of a stored selection as it was asked: the request's fields with
    their defaults stated (what the page refills its form from, the checks asked for
    among them)."""
    return stored_request(session, selection_id)


@router.get(
    "/selections/{selection_id}/candidates",
    response_model=CandidatePageOut,
    responses={
        200: {
            "content": {
                NDJSON: {
                    "schema": {"type": "string"},
                    "example": '{"model":"CHA-25A-50","verdict":"suitable",…}\n',
                }
            },
            "description": "a page of the ranking (JSON), or with `format=jsonl` every "
            "candidate from the cursor on, one `CandidateOut` a line, streamed",
        },
        404: {"description": "unknown selection"},
        422: {"description": "a cursor that is not one of this selection's"},
    },
)
def get_candidates(
    selection_id: Annotated[str, Path(max_length=36)],
    session: SessionDep,
    cursor: Cursor = None,
    limit: Annotated[
        int, Query(ge=1, le=TOP_MAX, description="the most candidates a page lists")
    ] = DEFAULT_TOP,
    format: Annotated[
        Literal["json", "jsonl"],
        Query(description="`jsonl`: the whole ranking from the cursor on, a line a candidate"),
    ] = "json",
) -> Response:
    """A stored selection's ranking, page by page from the answer's `next_cursor`, or
    whole as JSON lines. The ranking is stored with the selection as it was sized, so a
    cursor reads the same candidates after a catalogue change (that selection's
    catalogue version; a candidate's detail then answers 409)."""
    ranking = read_ranking(session, selection_id, cursor)
    if format == "jsonl":
        return StreamingResponse(ranking.lines(), media_type=NDJSON)
    return Response(dump_json(ranking.page(limit)), media_type="application/json")


@router.get(
    "/selections/{selection_id}/candidates/{model}",
    responses={
        404: {"description": "unknown selection, or a model that is no candidate of it"},
        409: {"description": "the catalogue has changed since the selection"},
    },
)
@reads_only
def get_candidate(
    selection_id: Annotated[str, Path(max_length=36)],
    model: Annotated[str, Path(max_length=60)],
    request: Request,
    response: Response,
    session: SessionDep,
) -> CandidateDetailOut:
    """One candidate of a stored selection in full: every check in words, every controller
    of Table 521.1 with its criteria and voltage check, the actuator's catalogue data."""
    return candidate_detail(
        session,
        catalogue_snapshot(request, session),
        selection_id,
        model,
        _localize(request, response),
    )


@router.get(
    "/selections/{selection_id}/candidates/{model}/diagram",
    responses={404: {"description": "unknown selection, or a model that is no candidate of it"}},
)
@reads_only
def get_candidate_diagram(
    selection_id: Annotated[str, Path(max_length=36)],
    model: Annotated[str, Path(max_length=60)],
    session: SessionDep,
    language: DocumentLanguageDep,
    response: Response,
    catalogue: Annotated[
        bool,
        Query(description="with the actuator's catalogue limits and zone (false: without)"),
    ] = True,
) -> dict[str, Any]:
    """The candidate's speed/torque diagram (Fig. 517.1) as a plotly figure (`data` and
    `layout`, JSON), in the document's language: the figure the quote and the report
    print, from the same definition (`documents/figures.py`). The page draws it with plotly.js."""
    found = candidate_diagram(session, selection_id, model, catalogue=catalogue)
    response.headers["Content-Language"] = language
    response.headers["Vary"] = "Accept-Language"
    points = diagram_points(found.candidate, found.selection)
    return diagram_figure(points, found.actuator, DocumentText(language))


@router.get(
    "/selections/{selection_id}/candidates/{model}/cycle",
    responses={
        404: {"description": "unknown selection, or a model that is no candidate of it"},
        409: {"description": "the catalogue has changed since the selection (with torques)"},
    },
)
@reads_only
def get_candidate_cycle(
    selection_id: Annotated[str, Path(max_length=36)],
    model: Annotated[str, Path(max_length=60)],
    request: Request,
    session: SessionDep,
    language: DocumentLanguageDep,
    response: Response,
    torques: Annotated[
        bool,
        Query(
            description="with the torque along each segment, computed again from the load "
            "case as the candidate's detail gives it (false: the stored answer's T_1, T_2, "
            "T_3 only, which also reads a selection whose catalogue has changed since)"
        ),
    ] = True,
) -> dict[str, Any]:
    """The candidate's cycle chart (Fig. 516.2: speed and torque over one period) as a
    plotly figure (`data` and `layout`, JSON), in the document's language: the figure the
    report prints, from the same definition (`documents/figures.py`). The page draws it with
    plotly.js."""
    found = candidate_diagram(session, selection_id, model, catalogue=False)
    along = (
        segment_torques(session, catalogue_snapshot(request, session), selection_id, model)
        if torques
        else None
    )
    response.headers["Content-Language"] = language
    response.headers["Vary"] = "Accept-Language"
    return cycle_figure(
        found.selection,
        found.candidate,
        DocumentText(language),
        [(st.times_s, st.torques_nm) for st in along] if along else None,
    )


@router.get(
    "/selections/{selection_id}/candidates/{model}/limits",
    responses={
        404: {"description": "unknown selection, or a model that is no candidate of it"},
        409: {"description": "the catalogue has changed since the selection"},
    },
)
@reads_only
def get_candidate_limits(
    selection_id: Annotated[str, Path(max_length=36)],
    model: Annotated[str, Path(max_length=60)],
    request: Request,
    response: Response,
    session: SessionDep,
) -> LimitsOut:
    """How far the stored load case may go for one of its candidates (as
    POST /selections/limits answers for it)."""
    return stored_limits(
        session,
        catalogue_snapshot(request, session),
        selection_id,
        model,
        _localize(request, response),
    )


_REPORT_ERRORS: dict[int | str, dict[str, Any]] = {404: {"description": "unknown selection"}}


@router.get(
    "/selections/{selection_id}/report.csv",
    response_class=Response,
    responses={
        200: {
            "content": {"text/csv": {"schema": {"type": "string"}}},
            "description": "one table, one header row, one row per check of each "
            "candidate: " + ",".join(COLUMNS) + ". Numbers are the stored answer's exactly; "
            "unknown values are empty cells.",
        },
        **_REPORT_ERRORS,
    },
)
def get_selection_report_csv(
    selection_id: Annotated[str, Path(max_length=36)], session: SessionDep
) -> Response:
    """The selection's engineering report as CSV: one row per check of each candidate, with
    the load case, the cycle and the candidate's figures on every row."""
    text = report_csv(selection_report(session, selection_id))
    return Response(
        text, media_type="text/csv; charset=utf-8", headers=_attachment(selection_id, "csv")
    )


@router.get(
    "/selections/{selection_id}/report.pdf",
    response_class=Response,
    responses={
        200: {
            "content": {"application/pdf": {"schema": {"type": "string", "format": "binary"}}},
            "description": "A4, the same content as the CSV for print, with page numbers, in "
            "German or English",
        },
        **_REPORT_ERRORS,
    },
)
def get_selection_report_pdf(
    selection_id: Annotated[str, Path(max_length=36)],
    request: Request,
    session: SessionDep,
    language: DocumentLanguageDep,
    candidates: Annotated[
        list[str],
        Query(
            max_length=100,
            description="models whose checks the report lists after its first page",
        ),
    ] = [],  # noqa: B006 - FastAPI copies a query default
) -> Response:
    """The selection's engineering report as PDF: a first page with the inputs, the cycle and
    speed/torque diagrams, the first-ranked candidate's checks and the top five; then the
    checks of the ``candidates`` asked for."""
    from actuator_selection.documents.report_pdf import render_pdf  # fpdf2: on first use

    report = selection_report(session, selection_id, candidates)
    t = DocumentText(language)
    first = report.selection.candidates[0] if report.selection.candidates else None
    along = None
    if first is not None:
        try:
            along = segment_torques(
                session, catalogue_snapshot(request, session), selection_id, first.model
            )
        except (ConflictError, NotFoundError):  # a changed catalogue: the stored steps
            along = None
    figures = [
        cycle_figure(report.selection, first, t, [(a.times_s, a.torques_nm) for a in along or ()])
    ]
    if first is not None:
        figures.append(speed_torque_figure(first, report.selection, report.actuator, t))
    body = render_pdf(report, t, figures)
    headers = {**_attachment(selection_id, "pdf"), "Content-Language": language}
    return Response(body, media_type="application/pdf", headers=headers)


def _attachment(selection_id: str, extension: str) -> dict[str, str]:
    # The id is a UUID the service made; quote() keeps any other path value a header.
    name = quote(f"selection-{selection_id}.{extension}", safe="")
    return {"Content-Disposition": f'attachment; filename="{name}"'}
