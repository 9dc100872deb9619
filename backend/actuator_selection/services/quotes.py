"""Quotes: from a stored selection to a priced, numbered offer and its document.

The use cases of ``api/quotes.py``. Rules (the README's "Quotes" section says the same):

- The chosen actuator must be a candidate of the selection. ``unsuitable``:
  refused (422, with the failed checks); ``unconfirmed``: allowed, flagged on the
  quote and its document with the checks that lack data.
- Prices come from the named price list, valid on the day the quote is made.
  All lines share one currency (422 otherwise). Figures follow
  ``sales.money.ROUNDING_RULE``; the VAT (the request's rate, else ``QUOTE_VAT_PERCENT``)
  is applied once to the net total (``sales.quote_terms.VAT_ROUNDING_RULE``).
- The seller block (settings) is copied into the quote, so a later change of the
  settings does not alter a quote already made; terms the request leaves out are the
  seller's standard terms, shown in the document's language.
- An ``Idempotency-Key`` repeated with the same body returns the first quote; with
  a different body it is a 422.
- Status flow draft → sent → accepted | rejected; expired by date (computed).
  Illegal moves are 409.
"""

from __future__ import annotations

import gzip
import hashlib
import json
from dataclasses import dataclass
from datetime import UTC, date, datetime
from typing import Any
from urllib.parse import quote as quote_path

import orjson
from sqlalchemy.orm import Session

from actuator_selection.db.admin import CatalogueAdminRepository
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.projects import ProjectRepository
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.db.sales import (
    ApiKeyRepository,
    IdempotencyKeyReusedError,
    PriceRepository,
    QuoteRepository,
    QuoteSearch,
)
from actuator_selection.errors import InvalidInputError
from actuator_selection.sales.money import QuoteLine, quote_totals
from actuator_selection.sales.quote_status import IllegalTransitionError, QuoteStatus, transition
from actuator_selection.sales.quote_terms import QuoteDefaults, tax_totals
from actuator_selection.sales.records import (
    ApiKeyRecord,
    NewQuote,
    PriceRecord,
    QuoteItem,
    QuoteRecord,
)
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.documents import DocumentLinkOut
from actuator_selection.schemas.quotes import (
    AxisItemIn,
    ControllerItemIn,
    QuoteCreate,
    QuoteListOut,
    QuoteOut,
    StoredCandidate,
    StoredCheck,
    StoredSelection,
)
from actuator_selection.services.errors import (
    UseCaseError,
    conflict_rule,
    invalid,
    invalid_rule,
    not_found,
)
from actuator_selection.services.messages import (
    CONTROLLER_RULE,
    PRICE_KINDS,
    PROJECT_CONTROLLER_RULE,
)
from actuator_selection.services.selections import stored_answer_json
from actuator_selection.sizing.compatibility import match_controller

API_PREFIX = "/api/v1"
DOCUMENT_LINK_TTL_S = 300
"""How long a signed document link works [s] unless its request asks for longer."""
DOCUMENT_LINK_MAX_TTL_S = 30 * 24 * 3600
"""The longest a signed document link may work [s]: 30 days (a link sent to a customer
with the quote). Longer is refused when a link is asked for (422) and when one is
presented, so that no link, however made, works for longer."""
SHOWN_CANDIDATES = 10
"""The usable candidates an answer names when the chosen actuator is not one."""
SHOWN_ROWS = 12
"""The Table 521.1 rows an answer names when the chosen controller is not one of them."""


def _out(record: QuoteRecord, today: date) -> QuoteOut:
    return QuoteOut.from_record(record, today=today, prefix=API_PREFIX)


def _request_sha256(body: QuoteCreate) -> str:
    canonical = json.dumps(body.model_dump(mode="json"), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(canonical.encode("utf-8")).hexdigest()


def _reused(number: str) -> UseCaseError:
    return invalid(["header", "Idempotency-Key"], "idempotency_key_reused", number=number)


def _candidate(body: QuoteCreate, selection: StoredSelection) -> StoredCandidate:
    """The chosen candidate; 422 when it is not one or it is unsuitable."""
    assert body.actuator is not None
    model = body.actuator.model
    candidate = next((c for c in selection.candidates if c.model == model), None)
    loc: list[str | int] = ["body", "actuator", "model"]
    if candidate is None:
        listed = [c.model for c in selection.candidates if c.verdict != "unsuitable"]
        if not listed:
            raise invalid(
                loc,
                "no_usable_candidate",
                "not_a_candidate",
                model=model,
                selection_id=selection.id,
            )
        raise invalid(
            loc,
            "not_a_candidate",
            model=model,
            selection_id=selection.id,
            models=listed[:SHOWN_CANDIDATES],
        )
    if candidate.verdict == "unsuitable":
        raise invalid(loc, "unsuitable", model=model, reasons="; ".join(candidate.reasons))
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
        raise invalid(
            loc,
            "no_price",
            price_list=body.price_list,
            kind=PRICE_KINDS[kind],
            item=code,
            day=on.isoformat(),
        )
    if currency is not None:
        matching = [p for p in prices if p.currency == currency]
        if not matching:
            raise invalid(
                loc,
                "currency_mismatch",
                item=code,
                currencies=[p.currency for p in prices],
                currency=currency,
            )
        return matching[0]
    if len(prices) > 1:
        raise invalid(
            ["body", "currency"],
            "currency_required",
            item=code,
            currencies=[p.currency for p in prices],
        )
    return prices[0]


def _compatible(selection: StoredSelection, model: str) -> dict[int, str]:
    """The Table 521.1 rows the stored answer lists for ``model``, with their level."""
    refs = selection.controllers
    candidate = next((c for c in selection.candidates if c.model == model), None)
    rows: dict[int, str] = {}
    for group in (candidate.drive_options if candidate is not None else None) or ():
        for index in group.controllers:
            row = refs[index].source_row if 0 <= index < len(refs) else None
            if row is not None:
                rows.setdefault(row, group.level)
    return rows


def _controller_description(
    session: Session, body: QuoteCreate, selection: StoredSelection, model: str
) -> str:
    """The controller line's text; with ``source_row``, checked against Table 521.1 as the
    selection matched it for ``model`` (422 naming the field and the rule otherwise)."""
    assert body.controller is not None
    item = body.controller
    if item.source_row is None:
        return f"Servo controller {item.type_name}"
    loc: list[str | int] = ["body", "controller", "source_row"]
    row = item.source_row
    repository = ProtectionRepository(session)
    record = repository.controller(row)
    if record is None:
        raise invalid(loc, "unknown_controller", row=row)
    controller = record.controller
    compatible = _compatible(selection, model)
    level = compatible.get(row)
    if level is None:
        interface = repository.interfaces([model]).get(model)
        reasons = (
            [
                r.message
                for r in match_controller(
                    controller=controller, actuator=interface.interface
                ).excluded_by
            ]
            if interface is not None
            else []
        )
        listed = sorted(compatible)[:SHOWN_ROWS]
        raise invalid(
            loc,
            "controller_not_compatible" if reasons else "controller_not_listed",
            "controller_not_compatible",
            controller=controller.name,
            row=row,
            model=model,
            rule=CONTROLLER_RULE,
            rows=listed,
            **({"reasons": "; ".join(reasons)} if reasons else {}),
        )
    return f"Servo controller {item.type_name} ({controller.name}, Table 521.1 row {row}: {level})"


@dataclass(frozen=True, slots=True, kw_only=True)
class _Line:
    """A line to price: its item, its quantity, where the request names it, and its words
    (an actuator's: the price list's description where it has one)."""

    kind: str
    code: str
    description: str
    quantity: int
    loc: list[str | int]
    axis: str | None = None


@dataclass(frozen=True, slots=True, kw_only=True)
class _Basis:
    """What a quote rests on: a selection's candidate or a project's axes, with its lines."""

    selection_id: str | None
    project_id: str | None
    catalogue_version: int
    actuator_model: str
    verdict: str
    reasons: tuple[str, ...]
    snapshot: dict[str, Any]
    lines: list[_Line]
    axes: tuple[dict[str, Any], ...] | None = None


def _quotable(session: Session, model: str, loc: list[str | int]) -> dict[str, Any]:
    """The actuator's catalogue entry as the quote copies it; 422 once it is retired."""
    state = CatalogueAdminRepository(session).state(model)
    record = CatalogueRepository(session).actuator(model)
    if state is None or state.retired_at is not None or record is None:
        raise invalid(loc, "retired_not_quoted", "retired", model=model)
    return ActuatorOut.from_record(record).model_dump(mode="json")


def _actuator_line(
    model: str, family: str, ratio: float, quantity: int, loc: list[str | int], axis: str | None
) -> _Line:
    return _Line(
        kind="actuator",
        code=model,
        description=f"Servo actuator {model} ({family}, gear ratio {ratio:g})",
        quantity=quantity,
        loc=loc,
        axis=axis,
    )


def _selection_basis(session: Session, body: QuoteCreate) -> _Basis:
    """A selection's quote: its chosen candidate, and a controller line where given."""
    assert body.selection_id is not None
    assert body.actuator is not None
    stored = stored_answer_json(session, body.selection_id)
    if stored is None:
        raise invalid(
            ["body", "selection_id"], "unknown_selection", "unknown", selection_id=body.selection_id
        )
    selection = StoredSelection.model_validate(stored)
    candidate = _candidate(body, selection)
    model_loc: list[str | int] = ["body", "actuator", "model"]
    snapshot = _quotable(session, candidate.model, model_loc)
    lines = [
        _actuator_line(
            candidate.model,
            candidate.family,
            candidate.gear_ratio,
            body.actuator.quantity,
            model_loc,
            None,
        )
    ]
    if body.controller is not None:
        lines.append(
            _Line(
                kind="controller",
                code=body.controller.item_code,
                description=_controller_description(session, body, selection, candidate.model),
                quantity=body.controller.quantity,
                loc=["body", "controller", "item_code"],
            )
        )
    return _Basis(
        selection_id=selection.id,
        project_id=None,
        catalogue_version=selection.catalogue_version,
        actuator_model=candidate.model,
        verdict=candidate.verdict,
        reasons=tuple(candidate.reasons),
        snapshot=snapshot,
        lines=lines,
    )


def _axis_controller(
    item: ControllerItemIn, axis: dict[str, Any], loc: list[str | int]
) -> tuple[str, dict[str, Any] | None]:
    """An axis's controller line's words, and the controller as quoted: the row the request
    names, else the axis's chosen one; it must be one the project lists for the axis."""
    chosen = axis.get("controller")
    row = item.source_row if item.source_row is not None else (chosen or {}).get("source_row")
    if row is None:
        return f"Servo controller {item.type_name}", None
    listed = {c["source_row"]: c for c in axis["controllers"]}
    found = listed.get(row)
    if found is None:
        raise invalid(
            [*loc, "source_row"],
            "controller_not_listed",
            "controller_not_compatible",
            controller=f"row {row}",
            row=row,
            model=axis["model"],
            rule=PROJECT_CONTROLLER_RULE,
            rows=sorted(listed)[:SHOWN_ROWS],
        )
    quoted = {k: found[k] for k in ("source_row", "name", "level")}
    words = (
        f"Servo controller {item.type_name} ({found['name']}, Table 521.1 row {row}: "
        f"{found['level']})"
    )
    return words, quoted


def _axis_reasons(axis: dict[str, Any]) -> dict[str, Any]:
    """An axis's reasons as a selection's quote has them (the checks that did not pass, in
    words) and, for its document, those checks as stored: from the project's checks of the
    axis's actuator; none (and no ``checks``) for a project stored before it kept them."""
    if axis.get("checks") is None:
        return {"verdict_reasons": []}
    checks = [StoredCheck.model_validate(c) for c in axis["checks"]]
    held = [c for c in checks if c.open]
    return {
        "verdict_reasons": [str(c.summary) for c in held],
        "checks": [c.model_dump(mode="json") for c in held],
    }


def _project_basis(session: Session, body: QuoteCreate) -> _Basis:
    """A machine project's quote: a line per axis for its actuator, and one for its
    controller where ``axes`` gives one."""
    assert body.project_id is not None
    found = ProjectRepository(session).get(body.project_id)
    if found is None:
        raise invalid(
            ["body", "project_id"], "unknown_project", "unknown", project_id=body.project_id
        )
    project = orjson.loads(gzip.decompress(found.answer_gzip))
    sized = project["axes"]
    asked = body.axes if body.axes is not None else [AxisItemIn() for _ in sized]
    if len(asked) != len(sized):
        raise invalid(["body", "axes"], "project_axes", axes=len(sized))
    lines: list[_Line] = []
    axes: list[dict[str, Any]] = []
    for k, (axis, item) in enumerate(zip(sized, asked, strict=True)):
        name = axis["name"] or str(k + 1)
        loc: list[str | int] = ["body", "axes", k]
        said = _axis_reasons(axis)
        if axis["verdict"] == "unsuitable":
            # the checks that fail, as a selection's refusal names them (where stored)
            failing = "; ".join(said["verdict_reasons"])
            refused = f"axis {name}: {failing}" if failing else f"axis {name}"
            raise invalid(loc, "unsuitable", model=axis["model"], reasons=refused)
        snapshot = _quotable(session, axis["model"], loc)
        lines.append(
            _actuator_line(
                axis["model"], snapshot["family"], axis["gear_ratio"], item.quantity, loc, name
            )
        )
        controller = None
        if item.controller is not None:
            words, controller = _axis_controller(item.controller, axis, [*loc, "controller"])
            lines.append(
                _Line(
                    kind="controller",
                    code=item.controller.item_code,
                    description=words,
                    quantity=item.controller.quantity,
                    loc=[*loc, "controller", "item_code"],
                    axis=name,
                )
            )
        axes.append(
            {
                "name": name,
                "actuator_model": axis["model"],
                "verdict": axis["verdict"],
                **said,
                "controller": controller,
                "actuator": snapshot,
            }
        )
    reasons = [
        f"axis {a['name']}: {reason}"
        for a in axes
        for reason in a["verdict_reasons"]
        or ([f"{a['actuator_model']} unconfirmed"] if a["verdict"] != "suitable" else [])
    ]
    return _Basis(
        selection_id=None,
        project_id=found.id,
        catalogue_version=found.catalogue_version,
        actuator_model=axes[0]["actuator_model"],
        verdict="suitable" if all(a["verdict"] == "suitable" for a in axes) else "unconfirmed",
        reasons=tuple(reasons),
        snapshot=axes[0]["actuator"],
        lines=lines,
        axes=tuple(axes),
    )


def _new_quote(
    body: QuoteCreate,
    *,
    session: Session,
    key_id: int,
    idempotency_key: str | None,
    now: datetime,
    defaults: QuoteDefaults,
) -> NewQuote:
    """Everything the quote holds, checked and priced (422s name the field)."""
    today = now.date()
    # First, so that the actuator data and the version below come from one snapshot.
    catalogue_version = CatalogueVersionRepository(session).pin()
    if body.valid_until < today:
        raise invalid(["body", "valid_until"], "valid_until_past", today=today.isoformat())
    basis = (
        _selection_basis(session, body)
        if body.selection_id is not None
        else _project_basis(session, body)
    )
    prices = PriceRepository(session)
    is_example = prices.is_example(body.price_list)
    if is_example is None:
        raise invalid(["body", "price_list"], "unknown_price_list", "unknown", name=body.price_list)
    currency = body.currency
    priced: list[tuple[_Line, PriceRecord, str]] = []
    for line in basis.lines:
        price = _price(
            prices,
            body=body,
            kind=line.kind,
            code=line.code,
            on=today,
            currency=currency,
            loc=line.loc,
        )
        currency = price.currency  # every later line in the first line's currency
        words = price.description if line.kind == "actuator" and price.description else None
        priced.append((line, price, words or line.description))
    assert currency is not None
    try:
        totals = quote_totals(
            [QuoteLine(unit_price=p.unit_price, quantity=line.quantity) for line, p, _ in priced],
            discount_percent=body.discount_percent,
        )
        tax = tax_totals(
            totals.total,
            vat_percent=defaults.vat_percent if body.vat_percent is None else body.vat_percent,
        )
    except InvalidInputError as exc:
        loc: list[str | int] = ["body", *exc.field.split(".")]
        raise invalid_rule(loc, exc, "invalid_amount") from None
    return NewQuote(
        created_at=now,
        valid_until=body.valid_until,
        api_key_id=key_id,
        idempotency_key=idempotency_key,
        request_sha256=_request_sha256(body),
        selection_id=basis.selection_id,
        project_id=basis.project_id,
        axes=basis.axes,
        selection_catalogue_version=basis.catalogue_version,
        catalogue_version=catalogue_version,
        customer_name=body.customer.name,
        customer_address=body.customer.address,
        customer_reference=body.customer.reference,
        notes=body.notes,
        actuator_model=basis.actuator_model,
        verdict=basis.verdict,
        verdict_reasons=basis.reasons,
        actuator_snapshot=basis.snapshot,
        price_list_name=body.price_list,
        price_list_is_example=is_example,
        price_date=today,
        currency=currency,
        subtotal=totals.subtotal,
        discount_percent=totals.discount_percent,
        discount_amount=totals.discount_amount,
        total=totals.total,
        tax=tax,
        payment_terms=body.payment_terms,
        delivery_terms=body.delivery_terms,
        seller=defaults.seller,
        items=tuple(
            QuoteItem(
                position=position,
                item_kind=line.kind,
                item_code=line.code,
                description=words,
                quantity=line.quantity,
                unit_price=price.unit_price,
                line_total=total,
                axis=line.axis,
            )
            for position, ((line, price, words), total) in enumerate(
                zip(priced, totals.line_totals, strict=True), start=1
            )
        ),
    )


@dataclass(frozen=True, slots=True)
class CreatedQuote:
    """A quote as POST /quotes answers it; ``replayed``: an earlier request's quote."""

    quote: QuoteOut
    replayed: bool

    @property
    def location(self) -> str:
        """The quote's path."""
        return f"{API_PREFIX}/quotes/{self.quote.number}"


def create_quote(
    session: Session,
    body: QuoteCreate,
    *,
    key_id: int,
    idempotency_key: str | None,
    now: datetime,
    defaults: QuoteDefaults,
) -> CreatedQuote:
    """Make a quote from a stored selection; numbered Q-<year>-<5 digits>.

    A key seen before with the same body answers the first quote (``replayed``).
    """
    repository = QuoteRepository(session)
    today = now.date()
    if idempotency_key is not None:
        found = repository.by_idempotency_key(key_id, idempotency_key)
        if found is not None:
            if found.request_sha256 != _request_sha256(body):
                raise _reused(found.number)
            return CreatedQuote(_out(found, today), replayed=True)
    new = _new_quote(
        body,
        session=session,
        key_id=key_id,
        idempotency_key=idempotency_key,
        now=now,
        defaults=defaults,
    )
    try:
        record, created = repository.create(new)
    except IdempotencyKeyReusedError as exc:
        raise _reused(exc.number) from None
    return CreatedQuote(_out(record, today), replayed=not created)


def search_quotes(session: Session, search: QuoteSearch) -> QuoteListOut:
    """Quotes matching ``search``, newest first, their status as of ``search.today``."""
    records, total = QuoteRepository(session).search(search)
    return QuoteListOut(total=total, quotes=[_out(r, search.today) for r in records])


def _quote(session: Session, number: str, *, for_update: bool = False) -> QuoteRecord:
    record = QuoteRepository(session).by_number(number, for_update=for_update)
    if record is None:
        raise not_found(["path", "number"], "unknown_quote", number=number)
    return record


def get_quote(session: Session, number: str, *, today: date) -> QuoteOut:
    """One quote, its status as of ``today``; 404 when unknown."""
    return _out(_quote(session, number), today)


def change_status(session: Session, number: str, target: QuoteStatus, *, now: datetime) -> QuoteOut:
    """Move a quote along draft → sent → accepted | rejected (409 for an illegal move)."""
    record = _quote(session, number, for_update=True)
    try:
        transition(record.status, target, valid_until=record.valid_until, today=now.date())
    except IllegalTransitionError as exc:
        raise conflict_rule(["body", "status"], exc, "illegal_transition") from None
    QuoteRepository(session).set_status(number, target, now=now)
    return _out(_quote(session, number), now.date())


def document_resource(number: str) -> str:
    """What a signed document link grants access to."""
    return f"quote-document:{number}"


def document_link(
    session: Session,
    principal: ApiKeyRecord,
    number: str,
    *,
    now: datetime,
    secret: bytes,
    lifetime_s: int = DOCUMENT_LINK_TTL_S,
    language: str | None = None,
) -> DocumentLinkOut:
    """A link to the quote's document, signed with the server's ``secret`` for
    ``principal``'s key for ``lifetime_s`` seconds (at most ``DOCUMENT_LINK_MAX_TTL_S``,
    and no longer than the key lives); with ``language``, the link asks for the
    document in it."""
    if not 0 < lifetime_s <= DOCUMENT_LINK_MAX_TTL_S:
        raise ValueError(f"lifetime_s must be 1 to {DOCUMENT_LINK_MAX_TTL_S}")
    _quote(session, number)
    expires_at = int(now.timestamp()) + lifetime_s
    token = ApiKeyRepository.sign_access(
        principal, document_resource(number), expires_at=expires_at, secret=secret
    )
    return DocumentLinkOut(
        url=f"{API_PREFIX}/quotes/{quote_path(number, safe='')}/document?access={token}"
        + (f"&lang={language}" if language is not None else ""),
        expires_at=datetime.fromtimestamp(expires_at, UTC),
    )


@dataclass(frozen=True, slots=True)
class QuoteDocumentData:
    """What the quote document shows: the quote as of today, its stored record (with the
    actuator's data as quoted) and the stored selection it rests on."""

    quote: QuoteOut
    record: QuoteRecord
    selection: StoredSelection | None


def quote_document(session: Session, number: str, *, today: date) -> QuoteDocumentData:
    """Everything the quote's printable document shows; 404 when unknown."""
    record = _quote(session, number)
    stored = (
        stored_answer_json(session, record.selection_id)
        if record.selection_id is not None
        else None
    )
    selection = StoredSelection.model_validate(stored) if stored is not None else None
    return QuoteDocumentData(_out(record, today), record, selection)
