"""Quotes for sales engineers and ERP systems: from a stored selection to a printable offer.

Rules (the README's "Quotes" section says the same):

- The chosen actuator must be a candidate of the selection. ``unsuitable``:
  refused (422, with the failed checks); ``unconfirmed``: allowed, flagged on the
  quote and its document with the checks that lack data.
- Prices come from the named price list, valid on the day the quote is made.
  All lines share one currency (422 otherwise). Figures follow
  ``core.money.ROUNDING_RULE``.
- ``Idempotency-Key`` (optional, ≤ 200 visible ASCII characters, scoped to the
  API key): a retry returns the first quote with 201 and ``Idempotent-Replayed:
  true``; the same key with a different body is a 422 (the IETF draft
  "The Idempotency-Key HTTP Header Field" answers 422 for a reused key).
- Status flow draft → sent → accepted | rejected; expired by date (computed).
  Illegal moves are 409.
"""

from __future__ import annotations

import hashlib
import json
import re
from datetime import UTC, date, datetime
from typing import Annotated
from urllib.parse import quote as quote_path

from fastapi import APIRouter, Depends, Header, Query, Response
from fastapi.responses import HTMLResponse

from actuator_selection.api.auth import PrincipalDep, SalesDep, authorize
from actuator_selection.api.deps import SessionDep, reads_only
from actuator_selection.api.errors import (
    ConflictError,
    RequestFieldError,
    ResourceNotFoundError,
    UnauthorizedError,
    field_error,
)
from actuator_selection.api.quote_document import (
    DOCUMENT_SCRIPT,
    DOCUMENT_SCRIPT_PATH,
    render_quote_document,
)
from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.money import QuoteLine, quote_totals
from actuator_selection.core.quote_status import IllegalTransitionError, QuoteStatus, transition
from actuator_selection.core.sales import NewQuote, PriceRecord, QuoteItem, QuoteRecord
from actuator_selection.db.admin import CatalogueAdminRepository
from actuator_selection.db.repositories import (
    CatalogueRepository,
    CatalogueVersionRepository,
)
from actuator_selection.db.sales import (
    ApiKeyRepository,
    IdempotencyKeyReusedError,
    PriceRepository,
    QuoteRepository,
    QuoteSearch,
)
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.documents import DocumentLinkOut
from actuator_selection.schemas.quotes import (
    QuoteCreate,
    QuoteListOut,
    QuoteOut,
    QuoteStatusIn,
    StoredCandidate,
    StoredSelection,
)
from actuator_selection.services.selections import stored_answer_json

router = APIRouter(tags=["quotes"])

API_PREFIX = "/api/v1"
_IDEMPOTENCY_KEY = re.compile(r"[\x21-\x7e]{1,200}")
DOCUMENT_LINK_TTL_S = 300
"""How long a signed document link works [s]."""
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


def _out(record: QuoteRecord, clock: Clock) -> QuoteOut:
    return QuoteOut.from_record(record, today=clock.today(), prefix=API_PREFIX)


def _request_sha256(body: QuoteCreate) -> str:
    canonical = json.dumps(body.model_dump(mode="json"), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


def _reused(number: str) -> RequestFieldError:
    return RequestFieldError(
        [
            field_error(
                ["header", "Idempotency-Key"],
                f"this key was used for quote {number} with a different request body; "
                "use a new key for a new quote",
                "idempotency_key_reused",
            )
        ]
    )


def _invalid(loc: list[str | int], message: str, type_: str) -> RequestFieldError:
    return RequestFieldError([field_error(loc, message, type_)])


def _candidate(body: QuoteCreate, selection: StoredSelection) -> StoredCandidate:
    """The chosen candidate; 422 when it is not one or it is unsuitable."""
    model = body.actuator.model
    candidate = next((c for c in selection.candidates if c.model == model), None)
    loc: list[str | int] = ["body", "actuator", "model"]
    if candidate is None:
        listed = [c.model for c in selection.candidates if c.verdict != "unsuitable"]
        shown = ", ".join(listed[:10]) + (" …" if len(listed) > 10 else "")
        raise _invalid(
            loc,
            f"{model!r} is not a candidate of selection {selection.id}"
            + (f" (choose one of: {shown})" if listed else " (it has no usable candidate)"),
            "not_a_candidate",
        )
    if candidate.verdict == "unsuitable":
        raise _invalid(
            loc,
            f"{model} is unsuitable for this load case and cannot be quoted: "
            + "; ".join(candidate.reasons),
            "unsuitable",
        )
    return candidate


def _price(
    repository: PriceRepository,
    *,
    body: QuoteCreate,
    kind: str,
    code: str,
    on: date,
    currency: str | None,
    loc: list[str | int],
) -> PriceRecord:
    """The one price of an item on ``on``, in ``currency`` when given; 422 otherwise."""
    prices = repository.lookup(
        price_list=body.price_list, item_kind=kind, item_code=code, on=on, currency=None
    )
    if not prices:
        raise _invalid(
            loc,
            f"the price list {body.price_list!r} has no {kind} price for {code!r} valid on "
            f"{on.isoformat()}",
            "no_price",
        )
    if currency is not None:
        matching = [p for p in prices if p.currency == currency]
        if not matching:
            raise _invalid(
                loc,
                f"{code} is priced in {', '.join(p.currency for p in prices)}, not in {currency}"
                " (one currency per quote)",
                "currency_mismatch",
            )
        return matching[0]
    if len(prices) > 1:
        raise _invalid(
            ["body", "currency"],
            f"{code} is priced in {', '.join(p.currency for p in prices)}: choose one",
            "currency_required",
        )
    return prices[0]


def _new_quote(
    body: QuoteCreate,
    *,
    session: SessionDep,
    key_id: int,
    idempotency_key: str | None,
    now: datetime,
) -> NewQuote:
    """Everything the quote holds, checked and priced (422s name the field)."""
    today = now.date()
    # First, so that the actuator data and the version below come from one snapshot.
    catalogue_version = CatalogueVersionRepository(session).pin()
    if body.valid_until < today:
        raise _invalid(
            ["body", "valid_until"],
            f"must be today ({today.isoformat()}) or later",
            "valid_until_past",
        )
    stored = stored_answer_json(session, body.selection_id)
    if stored is None:
        raise _invalid(
            ["body", "selection_id"], f"no stored selection {body.selection_id!r}", "unknown"
        )
    selection = StoredSelection.model_validate(stored)
    candidate = _candidate(body, selection)

    model_loc: list[str | int] = ["body", "actuator", "model"]
    state = CatalogueAdminRepository(session).state(candidate.model)
    record = CatalogueRepository(session).actuator(candidate.model)
    if state is None or state.retired_at is not None or record is None:
        raise _invalid(
            model_loc,
            f"{candidate.model} has been retired from the catalogue and can no longer be quoted",
            "retired",
        )

    prices = PriceRepository(session)
    is_example = prices.is_example(body.price_list)
    if is_example is None:
        raise _invalid(["body", "price_list"], f"no price list {body.price_list!r}", "unknown")
    actuator_price = _price(
        prices,
        body=body,
        kind="actuator",
        code=candidate.model,
        on=today,
        currency=body.currency,
        loc=model_loc,
    )
    currency = actuator_price.currency
    items = [
        (
            "actuator",
            candidate.model,
            actuator_price.description
            or f"Servo actuator {candidate.model} ({candidate.family}, "
            f"gear ratio {candidate.gear_ratio:g})",
            body.actuator.quantity,
            actuator_price,
        )
    ]
    if body.controller is not None:
        controller_price = _price(
            prices,
            body=body,
            kind="controller",
            code=body.controller.item_code,
            on=today,
            currency=currency,
            loc=["body", "controller", "item_code"],
        )
        items.append(
            (
                "controller",
                body.controller.item_code,
                f"Servo controller {body.controller.type_name}",
                body.controller.quantity,
                controller_price,
            )
        )
    try:
        totals = quote_totals(
            [QuoteLine(unit_price=p.unit_price, quantity=q) for _, _, _, q, p in items],
            discount_percent=body.discount_percent,
        )
    except InvalidInputError as exc:
        raise _invalid(["body", *exc.field.split(".")], exc.message, "invalid_amount") from None
    return NewQuote(
        created_at=now,
        valid_until=body.valid_until,
        api_key_id=key_id,
        idempotency_key=idempotency_key,
        request_sha256=_request_sha256(body),
        selection_id=selection.id,
        selection_catalogue_version=selection.catalogue_version,
        catalogue_version=catalogue_version,
        customer_name=body.customer.name,
        customer_address=body.customer.address,
        customer_reference=body.customer.reference,
        notes=body.notes,
        actuator_model=candidate.model,
        verdict=candidate.verdict,
        verdict_reasons=tuple(candidate.reasons),
        actuator_snapshot=ActuatorOut.from_record(record).model_dump(mode="json"),
        price_list_name=body.price_list,
        price_list_is_example=is_example,
        price_date=today,
        currency=currency,
        subtotal=totals.subtotal,
        discount_percent=totals.discount_percent,
        discount_amount=totals.discount_amount,
        total=totals.total,
        items=tuple(
            QuoteItem(
                position=position,
                item_kind=kind,
                item_code=code,
                description=description,
                quantity=quantity,
                unit_price=price.unit_price,
                line_total=line,
            )
            for position, ((kind, code, description, quantity, price), line) in enumerate(
                zip(items, totals.line_totals, strict=True), start=1
            )
        ),
    )


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
        raise _invalid(
            ["header", "Idempotency-Key"],
            "must be 1 to 200 visible ASCII characters (no spaces)",
            "idempotency_key",
        )
    repository = QuoteRepository(session)
    if idempotency_key is not None:
        found = repository.by_idempotency_key(principal.id, idempotency_key)
        if found is not None:
            if found.request_sha256 != _request_sha256(body):
                raise _reused(found.number)
            response.headers["Idempotent-Replayed"] = "true"
            response.headers["Location"] = f"{API_PREFIX}/quotes/{found.number}"
            return _out(found, clock)
    new = _new_quote(
        body,
        session=session,
        key_id=principal.id,
        idempotency_key=idempotency_key,
        now=clock.now(),
    )
    try:
        record, created = repository.create(new)
    except IdempotencyKeyReusedError as exc:
        raise _reused(exc.number) from None
    if not created:
        response.headers["Idempotent-Replayed"] = "true"
    response.headers["Location"] = f"{API_PREFIX}/quotes/{record.number}"
    return _out(record, clock)


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
    records, total = QuoteRepository(session).search(
        QuoteSearch(today=clock.today(), text=q, status=status, limit=limit, offset=offset)
    )
    return QuoteListOut(total=total, quotes=[_out(r, clock) for r in records])


def _quote(session: SessionDep, number: str, *, for_update: bool = False) -> QuoteRecord:
    record = QuoteRepository(session).by_number(number, for_update=for_update)
    if record is None:
        raise ResourceNotFoundError.at(["path", "number"], f"no quote {number!r}", "not_found")
    return record


@router.get("/quotes/{number}", responses={404: {"description": "unknown quote"}})
def get_quote(number: str, _: SalesDep, session: SessionDep, clock: ClockDep) -> QuoteOut:
    """One quote, its status as of today."""
    return _out(_quote(session, number), clock)


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
    record = _quote(session, number, for_update=True)
    target = QuoteStatus(body.status)
    try:
        transition(record.status, target, valid_until=record.valid_until, today=clock.today())
    except IllegalTransitionError as exc:
        raise ConflictError.at(["body", "status"], exc.message, "illegal_transition") from None
    repository = QuoteRepository(session)
    repository.set_status(number, target, now=clock.now())
    return _out(_quote(session, number), clock)


def _document_resource(number: str) -> str:
    return f"quote-document:{number}"


@router.post(
    "/quotes/{number}/document-link",
    responses={404: {"description": "unknown quote"}},
)
@reads_only
def quote_document_link(
    number: str, principal: SalesDep, session: SessionDep, clock: ClockDep
) -> DocumentLinkOut:
    """A link to the quote's document that a new browser window can open by itself.

    The window then loads the document from the server with the document's own
    headers (its Content-Security-Policy among them). The link works for
    ``DOCUMENT_LINK_TTL_S`` seconds and no longer than the key that asked for it.
    """
    _quote(session, number)
    expires_at = int(clock.now().timestamp()) + DOCUMENT_LINK_TTL_S
    token = ApiKeyRepository(session).sign_access(
        principal, _document_resource(number), expires_at=expires_at
    )
    return DocumentLinkOut(
        url=f"{API_PREFIX}/quotes/{quote_path(number, safe='')}/document?access={token}",
        expires_at=datetime.fromtimestamp(expires_at, UTC),
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
    if principal is None and access is not None:
        principal = ApiKeyRepository(session).check_access(
            access, _document_resource(number), now=clock.now()
        )
        if principal is None:
            raise UnauthorizedError.at(
                ["query", "access"],
                "this document link has expired or is not valid; open the document "
                "again from the quote list",
                "link_invalid",
            )
    authorize(principal, "sales")
    record = _quote(session, number)
    stored = stored_answer_json(session, record.selection_id)
    selection = StoredSelection.model_validate(stored) if stored is not None else None
    html = render_quote_document(_out(record, clock), selection=selection, record=record)
    return HTMLResponse(
        html,
        headers={
            # Belt and braces besides escaping: only this app's own script files run
            # (the document has no inline code); nothing is loaded from elsewhere.
            "Content-Security-Policy": "default-src 'none'; script-src 'self'; "
            "style-src 'unsafe-inline'; img-src 'self' data:; font-src 'self'; "
            "base-uri 'none'; form-action 'none'; frame-ancestors 'self'",
            "X-Content-Type-Options": "nosniff",
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
