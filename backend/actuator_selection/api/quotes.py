"""Quotes for sales engineers and ERP systems: from a stored selection to a printable offer.

The use cases (rules, pricing, numbering, status flow) live in ``services/quotes.py``;
each endpoint here reads the request and calls one.
"""

from __future__ import annotations

import re
from datetime import UTC, date, datetime
from typing import Annotated, Any, Literal
from urllib.parse import quote as quote_path

from fastapi import APIRouter, Depends, Header, Query, Request, Response
from fastapi.responses import HTMLResponse
from sqlalchemy.orm import Session

from actuator_selection.config import PLACEHOLDER_SELLER_NAME, Settings
from actuator_selection.db.sales import ApiKeyRepository, QuoteSearch
from actuator_selection.documents.quote_document import (
    DOCUMENT_SCRIPT,
    DOCUMENT_SCRIPT_PATH,
    quote_document_context,
    render_quote_document,
)
from actuator_selection.documents.quote_document_text import Language
from actuator_selection.http.auth import PrincipalDep, SalesDep, authorize
from actuator_selection.http.deps import DocumentLanguageDep, SessionDep, SettingsDep, reads_only
from actuator_selection.http.errors import RequestFieldError, UnauthorizedError, field_error
from actuator_selection.http.static import PLOTLY_URL
from actuator_selection.sales.quote_status import QuoteStatus
from actuator_selection.sales.records import ApiKeyRecord
from actuator_selection.schemas.documents import DocumentLinkOut
from actuator_selection.schemas.quotes import QuoteCreate, QuoteListOut, QuoteOut, QuoteStatusIn
from actuator_selection.services import quotes
from actuator_selection.services.quotes import (
    API_PREFIX,
    DOCUMENT_LINK_MAX_TTL_S,
    DOCUMENT_LINK_TTL_S,
)

__all__ = [
    "API_PREFIX",
    "DOCUMENT_LINK_MAX_TTL_S",
    "DOCUMENT_LINK_TTL_S",
    "Clock",
    "get_clock",
    "router",
]

router = APIRouter(tags=["quotes"])

_IDEMPOTENCY_KEY = re.compile(r"[\x21-\x7e]{1,200}")
MAX_OFFSET = 1_000_000_000
"""Largest ``offset`` of the quote search: far beyond any real number of quotes."""


class Clock:
    """The time of a request; tests replace it to step past a quote's validity."""

    def now(self) -> datetime:
        """Now, in UTC."""
        return datetime.now(UTC)

    def today(self) -> date:
        """Today's date in UTC: quotes expire and prices apply by UTC calendar days."""
        return self.now().date()


def get_clock() -> Clock:
    """The real clock (override ``get_clock`` in tests)."""
    return Clock()


ClockDep = Annotated[Clock, Depends(get_clock)]


def link_secret(request: Request) -> bytes:
    """The secret that signs document links, read when the app was built
    (``services/link_secret.py``)."""
    secret: bytes = request.app.state.link_secret
    return secret


LinkSecretDep = Annotated[bytes, Depends(link_secret)]


@router.post(
    "/quotes",
    status_code=201,
    responses={
        401: {"description": "no or a bad API key"},
        403: {"description": "the key lacks the sales role"},
        422: {"description": "a bad field, an unsuitable actuator, a missing price, a reused key"},
    },
)
def create_quote(
    body: QuoteCreate,
    principal: SalesDep,
    session: SessionDep,
    clock: ClockDep,
    settings: SettingsDep,
    response: Response,
    idempotency_key: Annotated[
        str | None,
        Header(
            alias="Idempotency-Key",
            description="a client-chosen key (≤ 200 visible ASCII characters): a retry with "
            "the same key and body returns the first quote, never a second one",
        ),
    ] = None,
) -> QuoteOut:
    """Make a quote from a stored selection; numbered Q-<year>-<5 digits>."""
    if idempotency_key is not None and not _IDEMPOTENCY_KEY.fullmatch(idempotency_key):
        raise RequestFieldError(
            [
                field_error(
                    ["header", "Idempotency-Key"],
                    "must be 1 to 200 visible ASCII characters (no spaces)",
                    "idempotency_key",
                )
            ]
        )
    created = quotes.create_quote(
        session,
        body,
        key_id=principal.id,
        idempotency_key=idempotency_key,
        now=clock.now(),
        defaults=settings.quote_defaults(),
    )
    if created.replayed:
        response.headers["Idempotent-Replayed"] = "true"
    response.headers["Location"] = created.location
    return created.quote


@router.get("/quotes")
def list_quotes(
    _: SalesDep,
    session: SessionDep,
    clock: ClockDep,
    q: Annotated[
        str | None,
        Query(max_length=200, description="part of the number, customer, reference or model"),
    ] = None,
    status: Annotated[QuoteStatus | None, Query(description="as of today")] = None,
    limit: Annotated[int, Query(ge=1, le=200)] = 50,
    # Bounded so that it fits a 64-bit OFFSET (PostgreSQL answered 500 above 2^63 − 1).
    offset: Annotated[int, Query(ge=0, le=MAX_OFFSET)] = 0,
) -> QuoteListOut:
    """Search quotes, newest first."""
    search = QuoteSearch(today=clock.today(), text=q, status=status, limit=limit, offset=offset)
    return quotes.search_quotes(session, search)


@router.get("/quotes/{number}", responses={404: {"description": "unknown quote"}})
def get_quote(number: str, _: SalesDep, session: SessionDep, clock: ClockDep) -> QuoteOut:
    """One quote, its status as of today."""
    return quotes.get_quote(session, number, today=clock.today())


@router.post(
    "/quotes/{number}/status",
    responses={
        404: {"description": "unknown quote"},
        409: {"description": "the flow does not allow this move (e.g. accepting an expired quote)"},
    },
)
def change_status(
    number: str, body: QuoteStatusIn, _: SalesDep, session: SessionDep, clock: ClockDep
) -> QuoteOut:
    """Move a quote along draft → sent → accepted | rejected."""
    return quotes.change_status(session, number, QuoteStatus(body.status), now=clock.now())


@router.post(
    "/quotes/{number}/document-link",
    responses={404: {"description": "unknown quote"}},
)
@reads_only
def quote_document_link(
    number: str,
    principal: SalesDep,
    session: SessionDep,
    clock: ClockDep,
    secret: LinkSecretDep,
    lang: Annotated[
        Literal["de", "en"] | None,
        Query(description="the document's language, carried in the link (`&lang=`)"),
    ] = None,
    lifetime_s: Annotated[
        int,
        Query(
            ge=1,
            le=DOCUMENT_LINK_MAX_TTL_S,
            description=f"how long the link works [s]; at most {DOCUMENT_LINK_MAX_TTL_S} (30 days)",
        ),
    ] = DOCUMENT_LINK_TTL_S,
) -> DocumentLinkOut:
    """A link to the quote's document that a new browser window can open by itself.

    The window then loads the document from the server with the document's own
    headers (its Content-Security-Policy among them). The link works for
    ``lifetime_s`` seconds (default 300, at most 30 days) and no longer than the key
    that asked for it.
    """
    return quotes.document_link(
        session,
        principal,
        number,
        now=clock.now(),
        secret=secret,
        lifetime_s=lifetime_s,
        language=lang,
    )


def _document_reader(
    principal: ApiKeyRecord | None,
    access: str | None,
    *,
    number: str,
    session: SessionDep,
    now: datetime,
    secret: bytes,
) -> ApiKeyRecord:
    """The sales key that reads a document: the request's own, or the one that signed
    the ``access`` link (401 for an expired or bad link, 403 without the sales role)."""
    if principal is None and access is not None:
        principal = ApiKeyRepository(session).check_access(
            access,
            quotes.document_resource(number),
            now=now,
            secret=secret,
            max_lifetime_s=DOCUMENT_LINK_MAX_TTL_S,
        )
        if principal is None:
            raise UnauthorizedError.at(
                ["query", "access"],
                "this document link has expired or is not valid; open the document "
                "again from the quote list",
                "link_invalid",
            )
    return authorize(principal, "sales")


DOCUMENT_HEADERS = {
    # Belt and braces besides escaping: only this app's own script files run
    # (the document has no inline code); nothing is loaded from elsewhere.
    "Content-Security-Policy": "default-src 'none'; script-src 'self'; "
    "style-src 'unsafe-inline'; img-src 'self' data:; font-src 'self'; "
    "base-uri 'none'; form-action 'none'; frame-ancestors 'self'",
    "X-Content-Type-Options": "nosniff",
    "Cache-Control": "no-store",
}


def _document_context(
    session: Session, number: str, clock: Clock, settings: Settings, language: Language
) -> dict[str, Any]:
    """The quote document's content (:func:`quote_document_context`) in ``language``."""
    data = quotes.quote_document(session, number, today=clock.today())
    return quote_document_context(
        data.quote,
        selection=data.selection,
        record=data.record,
        language=language,
        current_seller=settings.seller(),
        placeholder_seller_name=PLACEHOLDER_SELLER_NAME,
    )


@router.get(
    "/quotes/{number}/document",
    response_class=HTMLResponse,
    responses={404: {"description": "unknown quote"}},
)
def quote_document(
    number: str,
    principal: PrincipalDep,
    session: SessionDep,
    clock: ClockDep,
    settings: SettingsDep,
    language: DocumentLanguageDep,
    secret: LinkSecretDep,
    access: Annotated[
        str | None,
        Query(
            max_length=100,
            description="a token from POST /quotes/{number}/document-link, for a browser "
            "window that cannot send the API key",
        ),
    ] = None,
) -> HTMLResponse:
    """The quote as an HTML page laid out for A4 print (print to PDF from the browser)."""
    _document_reader(
        principal, access, number=number, session=session, now=clock.now(), secret=secret
    )
    context = _document_context(session, number, clock, settings, language)
    html = render_quote_document(context, plotly_url=PLOTLY_URL)
    return HTMLResponse(
        html,
        headers={**DOCUMENT_HEADERS, "Content-Language": language, "Vary": "Accept-Language"},
    )


@router.get(
    "/quotes/{number}/document.pdf",
    response_class=Response,
    responses={
        200: {
            "content": {"application/pdf": {"schema": {"type": "string", "format": "binary"}}},
            "description": "A4, the quote document's words and numbers in its language (seller "
            "block, customer, items, net/VAT/gross, terms, engineering justification), with "
            "page numbers; the speed/torque diagram is in the HTML document only",
        },
        404: {"description": "unknown quote"},
    },
)
def quote_document_pdf(
    number: str,
    principal: PrincipalDep,
    session: SessionDep,
    clock: ClockDep,
    settings: SettingsDep,
    language: DocumentLanguageDep,
    secret: LinkSecretDep,
    access: Annotated[
        str | None,
        Query(
            max_length=100,
            description="a token from POST /quotes/{number}/document-link, for a browser "
            "that downloads the file without the API key",
        ),
    ] = None,
) -> Response:
    """The quote document as a PDF download (A4), in German or English."""
    from actuator_selection.documents.quote_pdf import render_quote_pdf  # fpdf2: on first use

    _document_reader(
        principal, access, number=number, session=session, now=clock.now(), secret=secret
    )
    context = _document_context(session, number, clock, settings, language)
    name = quote_path(f"{context['number']}.pdf", safe="")
    return Response(
        render_quote_pdf(context),
        media_type="application/pdf",
        headers={
            "Content-Disposition": f'attachment; filename="{name}"',
            "Content-Language": language,
            "Vary": "Accept-Language",
            "Cache-Control": "no-store",
        },
    )


@router.get(DOCUMENT_SCRIPT_PATH, include_in_schema=False)
def quote_document_script() -> Response:
    """The quote document's figure script (no inline code in the document)."""
    return Response(
        DOCUMENT_SCRIPT,
        media_type="text/javascript",
        headers={"Cache-Control": "public, max-age=3600"},
    )
