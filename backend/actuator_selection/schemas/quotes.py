"""The quote contract: what sales engineers and ERP systems send and receive.

Money and percentages are exact decimals: in requests a JSON string (``"7.5"``)
or an integer, never a JSON number with a fraction (a binary float cannot hold
most cents exactly); in responses always a string with two decimal places
(``"2561.30"``).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from datetime import UTC, date, datetime, timedelta
from decimal import Decimal
from typing import Annotated, Any, Literal

from pydantic import (
    AfterValidator,
    BeforeValidator,
    ConfigDict,
    Field,
    StrictInt,
    StringConstraints,
    model_validator,
)
from pydantic_core import PydanticCustomError

from actuator_selection.phrases.check_messages import phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.phrases.messages import Text as Words
from actuator_selection.sales.money import MAX_QUANTITY, PLAIN_DECIMAL, ROUNDING_RULE
from actuator_selection.sales.quote_status import QuoteStatus, allowed_transitions, effective_status
from actuator_selection.sales.quote_terms import LANGUAGES, VAT_ROUNDING_RULE, SellerParty
from actuator_selection.sales.records import QuoteRecord
from actuator_selection.schemas.common import ResponseModel, StrictModel
from actuator_selection.schemas.output_load import OutputLoadIn
from actuator_selection.schemas.selections import (
    CandidateFigures,
    CheckBrief,
    CheckRuleOut,
    ControllerRef,
    DriveOptionGroup,
    ResolvedLoad,
    SegmentOut,
    SelectionOut,
)
from actuator_selection.sizing.checks import margin_percent

DECIMAL_TEXT_RULE = N_(
    'must be a decimal number written with the digits 0–9 and perhaps a point, e.g. "7.5"'
)
"""The rule of a decimal given as text (:data:`~actuator_selection.sales.money.PLAIN_DECIMAL`,
error type ``decimal_text``)."""


def _no_float(value: Any) -> Any:
    if isinstance(value, float):
        raise ValueError('give decimals as a string such as "7.5", not as a JSON number')
    if isinstance(value, bool):
        raise ValueError("must be a decimal number")
    if isinstance(value, str) and not PLAIN_DECIMAL.fullmatch(value.strip()):
        # Decimal() would read "١٢" (Arabic-Indic digits) or "１２" as 12, and "1e1" or "1_0"
        raise PydanticCustomError("decimal_text", DECIMAL_TEXT_RULE)
    return value


# Not strict (StrictModel): a decimal comes as a JSON string or integer; _no_float refuses
# floats, booleans and text other than plain decimals before the lax conversion.
DecimalIn = Annotated[Decimal, Field(strict=False), BeforeValidator(_no_float)]

MAX_VALIDITY_DAYS = 731
"""``valid_until`` at most two years after today (UTC): a quote is priced from today's
price list, and a validity of decades ("9999-12-31") is a typo, not a commercial term."""
_ISO_DATE = re.compile(r"\d{4}-\d{2}-\d{2}")


def _date_text(value: Any) -> Any:
    # Only a YYYY-MM-DD string: pydantic would also read 1893456000 (Unix seconds) or
    # "2030-01-01T00:00" as a date.
    if not isinstance(value, str) or not _ISO_DATE.fullmatch(value):
        raise ValueError("must be a date written YYYY-MM-DD (a JSON string)")
    try:
        return date.fromisoformat(value)
    except ValueError:
        raise ValueError(f"must be a calendar date, got {value!r}") from None


def _not_too_late(value: date) -> date:
    latest = datetime.now(UTC).date() + timedelta(days=MAX_VALIDITY_DAYS)
    if value > latest:
        raise ValueError(
            f"must be at most {MAX_VALIDITY_DAYS} days after today ({latest.isoformat()}): "
            "prices are quoted from the current price list"
        )
    return value


ValidUntil = Annotated[date, BeforeValidator(_date_text), AfterValidator(_not_too_late)]
Text = Annotated[str, StringConstraints(strip_whitespace=True)]
Quantity = Annotated[StrictInt, Field(ge=1, le=MAX_QUANTITY, description="pieces, ≥ 1")]
Percent = Annotated[DecimalIn, Field(ge=0, le=100, decimal_places=2)]
"""A percentage 0–100 with at most two decimal places, as a JSON string or integer."""
Terms = Annotated[Text, Field(min_length=1, max_length=1000)]


class CustomerIn(StrictModel):
    """Who the quote is for; free text, shown escaped on the document.

    The address may span lines (tab, LF, CR); name and reference are one line.
    """

    line_break_fields = frozenset({"address"})

    name: Annotated[Text, Field(min_length=1, max_length=200)]
    address: Annotated[Text, Field(max_length=2000)] | None = None
    reference: Annotated[Text, Field(max_length=200)] | None = Field(
        default=None, description="the customer's enquiry or order reference"
    )


class ActuatorItemIn(StrictModel):
    """The chosen actuator: one of the selection's candidates, priced by its model."""

    model: Annotated[str, Field(min_length=1, max_length=60)]
    quantity: Quantity = 1


class ControllerItemIn(StrictModel):
    """A servo controller: its type as the customer should read it, priced by ``item_code``,
    and (``source_row``) which controller of Table 521.1 it is."""

    type_name: Annotated[Text, Field(min_length=1, max_length=200)] = Field(
        description="free text, e.g. 'SINAMICS S120, 400 V, 5 A'"
    )
    item_code: Annotated[str, Field(min_length=1, max_length=80)] = Field(
        description="the controller's code in the price list"
    )
    source_row: StrictInt | None = Field(
        default=None,
        ge=1,
        le=1_000_000,
        description="the controller's row in Table 521.1 (`source_row` of the selection "
        "answer's `controllers`): it must be one the selection lists for the chosen actuator "
        "(its drive options), else 422; the line then names the controller and its match level",
    )
    quantity: Quantity = 1


class AxisItemIn(StrictModel):
    """A machine project's axis on the quote: how many of its actuator, and its controller
    line (priced by ``item_code``; its Table 521.1 row is the axis's chosen controller unless
    ``source_row`` names another the project lists for the axis)."""

    quantity: Quantity = 1
    controller: ControllerItemIn | None = None


PROJECT_OR_SELECTION = N_(
    "give selection_id with actuator (a selection's quote), or project_id (a machine "
    "project's, a line per axis)"
)
"""The rule of a quote's source, in words (error type ``quote_source``)."""


class QuoteCreate(StrictModel):
    """A quote for the selection ``selection_id`` or for the machine project ``project_id``
    (a line per axis: its actuator, and its controller where one is given); prices come
    from ``price_list``.

    ``notes`` and the terms may span lines (tab, LF, CR); every other text is one line.
    VAT and terms left out take the server's defaults (``QUOTE_VAT_PERCENT``; the seller's
    standard terms, shown in the document's language).
    """

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "selection_id": "0b6f1c1e-8d4a-4f0e-9a57-2f1e0c3d5b7a",
                    "customer": {"name": "Example Maschinenbau GmbH", "reference": "RFQ 2026-117"},
                    "actuator": {"model": "FHA-25C-50-L", "quantity": 2},
                    "price_list": "EXAMPLE — not real prices",
                    "discount_percent": "5",
                    "valid_until": "2026-12-31",
                    "vat_percent": "19",
                    "payment_terms": "30 days net",
                    "delivery_terms": "FCA Musterstadt (Incoterms® 2020), 6 weeks after order",
                    "notes": "delivery 6 weeks after order",
                }
            ]
        }
    )

    line_break_fields = frozenset({"notes", "payment_terms", "delivery_terms"})

    selection_id: Annotated[str, Field(min_length=1, max_length=36)] | None = None
    project_id: Annotated[str, Field(min_length=1, max_length=36)] | None = Field(
        default=None,
        description="a stored machine project instead of a selection: a line per axis with "
        "its actuator (the project's, each must not be unsuitable) and, where `axes` gives "
        "one, its controller",
    )
    customer: CustomerIn
    actuator: ActuatorItemIn | None = Field(
        default=None, description="the chosen candidate of the selection; with selection_id"
    )
    controller: ControllerItemIn | None = None
    axes: list[AxisItemIn] | None = Field(
        default=None,
        max_length=64,
        description="with project_id: one entry per axis of the project, in its order; "
        "omitted: one actuator per axis and no controller lines",
    )
    price_list: Annotated[str, Field(min_length=1, max_length=120)]
    currency: Annotated[str, Field(pattern=r"^[A-Z]{3}$")] | None = Field(
        default=None,
        description="ISO 4217 code; needed only when the price list prices an item in several",
    )
    discount_percent: DecimalIn = Field(
        default=Decimal(0), ge=0, le=100, decimal_places=2, description='0–100, e.g. "7.5"'
    )
    valid_until: ValidUntil = Field(
        description="last day the customer may accept (inclusive), YYYY-MM-DD, today at the "
        f"earliest and at most {MAX_VALIDITY_DAYS} days ahead"
    )
    vat_percent: Percent | None = Field(
        default=None,
        description='VAT rate [%], 0–100, e.g. "19"; left out: the server\'s QUOTE_VAT_PERCENT. '
        "Applied once to the net total (after discount)",
    )
    payment_terms: Terms | None = Field(
        default=None,
        description="as the customer should read them; left out: the seller's standard "
        "payment terms, in the document's language",
    )
    delivery_terms: Terms | None = Field(
        default=None,
        description="e.g. an Incoterm with its place; left out: the seller's standard "
        "delivery terms, in the document's language",
    )
    notes: Annotated[Text, Field(max_length=4000)] | None = None

    @model_validator(mode="after")
    def _one_source(self) -> QuoteCreate:
        selection = (
            self.selection_id is not None
            and self.actuator is not None
            and self.project_id is None
            and self.axes is None
        )
        project = (
            self.project_id is not None
            and self.selection_id is None
            and self.actuator is None
            and self.controller is None
        )
        if not (selection or project):
            raise PydanticCustomError("quote_source", PROJECT_OR_SELECTION)
        return self


class QuoteStatusIn(StrictModel):
    """A status change: ``sent``, ``accepted`` or ``rejected`` (``expired`` happens by date)."""

    model_config = ConfigDict(json_schema_extra={"examples": [{"status": "sent"}]})

    status: Literal["sent", "accepted", "rejected"]


class CustomerOut(ResponseModel):
    """Who the quote is for."""

    name: str
    address: str | None
    reference: str | None


class QuoteItemOut(ResponseModel):
    """One priced line."""

    position: int
    kind: Literal["actuator", "controller"]
    item_code: str
    description: str
    quantity: int
    unit_price: Decimal = Field(description="decimal string, from the price list")
    line_total: Decimal = Field(description="unit_price × quantity, rounded to cents half up")
    axis: str | None = Field(
        default=None, description="the machine project's axis the line is for; null: a selection's"
    )


class QuoteAxisControllerOut(ResponseModel):
    """An axis's controller as quoted (Table 521.1)."""

    source_row: int
    name: str
    level: Literal["tested", "possible", "unconfirmed"]


class QuoteAxisOut(ResponseModel):
    """One axis of a machine project as quoted."""

    name: str
    actuator_model: str
    verdict: Literal["suitable", "unconfirmed"]
    verdict_reasons: list[str]
    controller: QuoteAxisControllerOut | None


def _by_language(texts: Mapping[str, str]) -> dict[str, str]:
    return {language: texts[language] for language in LANGUAGES if language in texts}


class SellerOut(ResponseModel):
    """Who makes the offer (the seller block), as configured when the quote was made."""

    name: str
    address: str
    vat_id: str
    email: str
    phone: str | None
    payment_terms: dict[str, str] = Field(description="standard payment terms by language")
    delivery_terms: dict[str, str] = Field(description="standard delivery terms by language")

    @classmethod
    def from_party(cls, party: SellerParty) -> SellerOut:
        """The seller block of a quote."""
        return cls(
            name=party.name,
            address=party.address,
            vat_id=party.vat_id,
            email=party.email,
            phone=party.phone,
            payment_terms=_by_language(party.payment_terms),
            delivery_terms=_by_language(party.delivery_terms),
        )


class PriceListRef(ResponseModel):
    """The price list the quote was priced from, and the day it was priced."""

    name: str
    is_example: bool = Field(description="true: example prices, not real ones")
    priced_on: date


class QuoteOut(ResponseModel):
    """A quote: its figures, its status as of today, and the engineering it rests on."""

    number: str = Field(description="Q-<year>-<5 digits>, sequential per year")
    status: QuoteStatus = Field(description="as of today: draft or sent quotes expire by date")
    allowed_transitions: list[QuoteStatus]
    created_at: datetime
    status_changed_at: datetime
    valid_until: date
    customer: CustomerOut
    selection_id: str | None = Field(description="null: the quote rests on a project")
    project_id: str | None = Field(description="the machine project quoted; null: a selection")
    selection_catalogue_version: int = Field(
        description="catalogue version the selection (or the project) used"
    )
    catalogue_version: int = Field(description="catalogue version when the quote was made")
    actuator_model: str | None = Field(
        description="the actuator quoted; null on a machine project's quote, which quotes one "
        "per axis: read `axes[].actuator_model` and the `items` of kind `actuator`"
    )
    axes: list[QuoteAxisOut] | None = Field(
        description="a project quote's axes, in the project's order; null: a selection's quote"
    )
    verdict: Literal["suitable", "unconfirmed"]
    unconfirmed: bool = Field(description="true: some check lacked catalogue data")
    verdict_reasons: list[str]
    price_list: PriceListRef
    currency: str
    items: list[QuoteItemOut]
    subtotal: Decimal
    discount_percent: Decimal
    discount_amount: Decimal
    total: Decimal = Field(
        description="deprecated, read `net_total` (the same value) or `gross_total`: the net "
        "total, subtotal − discount; left out of the answer in the next API version",
        json_schema_extra={"deprecated": True},
    )
    net_total: Decimal = Field(description="subtotal − discount, before VAT")
    vat_percent: Decimal | None = Field(
        description="VAT rate [%]; null on quotes made before VAT was stated"
    )
    vat_amount: Decimal | None = Field(
        description="net_total × vat_percent / 100, rounded once to cents, half up"
    )
    gross_total: Decimal | None = Field(description="net_total + vat_amount")
    rounding: str = Field(default=f"{ROUNDING_RULE}; {VAT_ROUNDING_RULE}")
    payment_terms: str | None = Field(
        description="as entered; null: the seller's standard terms (seller.payment_terms)"
    )
    delivery_terms: str | None = Field(
        description="as entered; null: the seller's standard terms (seller.delivery_terms)"
    )
    seller: SellerOut | None = Field(
        description="null on quotes made before the seller was stored (their document shows "
        "the seller as configured now)"
    )
    notes: str | None
    document_url: str

    @classmethod
    def from_record(cls, record: QuoteRecord, *, today: date, prefix: str) -> QuoteOut:
        """The response body of a stored quote as of ``today``; ``prefix`` is the API's path."""
        return cls(
            number=record.number,
            status=effective_status(record.status, valid_until=record.valid_until, today=today),
            allowed_transitions=list(
                allowed_transitions(record.status, valid_until=record.valid_until, today=today)
            ),
            created_at=record.created_at,
            status_changed_at=record.status_changed_at,
            valid_until=record.valid_until,
            customer=CustomerOut(
                name=record.customer_name,
                address=record.customer_address,
                reference=record.customer_reference,
            ),
            selection_id=record.selection_id,
            project_id=record.project_id,
            axes=(
                [QuoteAxisOut.model_validate(_axis_out(a)) for a in record.axes]
                if record.axes is not None
                else None
            ),
            selection_catalogue_version=record.selection_catalogue_version,
            catalogue_version=record.catalogue_version,
            # a project's quote quotes an actuator per axis, none as the quote's (its
            # stored column holds the first axis's, as quotes made before this rule do)
            actuator_model=record.actuator_model if record.project_id is None else None,
            verdict="suitable" if record.verdict == "suitable" else "unconfirmed",
            unconfirmed=record.verdict == "unconfirmed",
            verdict_reasons=list(record.verdict_reasons),
            price_list=PriceListRef(
                name=record.price_list_name,
                is_example=record.price_list_is_example,
                priced_on=record.price_date,
            ),
            currency=record.currency,
            items=[
                QuoteItemOut(
                    position=i.position,
                    kind="actuator" if i.item_kind == "actuator" else "controller",
                    item_code=i.item_code,
                    description=i.description,
                    quantity=i.quantity,
                    unit_price=i.unit_price,
                    line_total=i.line_total,
                    axis=i.axis,
                )
                for i in record.items
            ],
            subtotal=record.subtotal,
            discount_percent=record.discount_percent,
            discount_amount=record.discount_amount,
            total=record.total,
            net_total=record.total,
            vat_percent=record.tax.vat_percent if record.tax is not None else None,
            vat_amount=record.tax.vat_amount if record.tax is not None else None,
            gross_total=record.tax.gross if record.tax is not None else None,
            payment_terms=record.payment_terms,
            delivery_terms=record.delivery_terms,
            seller=SellerOut.from_party(record.seller) if record.seller is not None else None,
            notes=record.notes,
            document_url=f"{prefix}/quotes/{record.number}/document",
        )


def _axis_out(axis: Mapping[str, Any]) -> dict[str, Any]:
    """A stored axis of a project quote (``NewQuote.axes``) as :class:`QuoteAxisOut` reads it."""
    return {k: axis[k] for k in QuoteAxisOut.model_fields}


class QuoteListOut(ResponseModel):
    """A page of quotes, newest first."""

    total: int = Field(description="how many quotes match in all")
    quotes: list[QuoteOut]


_UNNAMED_NEED = N_("value this check needs")
"""What a no-data check lacks where the answer does not name it (answers upgraded from
before the lean one, migration 0010)."""


class StoredCheck(CheckBrief):
    """A check of a stored candidate: its numbers as the answer lists them, and its rule's
    unit and reference (the answer's ``check_rules``, set by :class:`StoredSelection`)."""

    unit: str = ""
    reference: str = ""

    @property
    def margin_percent(self) -> float | None:
        """Headroom (limit − value)/limit [%], as the core computes it."""
        return margin_percent(self.value, self.limit)

    @property
    def summary(self) -> str:
        """The check in words (English), after the check's name where it has numbers
        (``max_speed: 40 rpm ≤ 90 rpm``)."""
        said = self.phrase
        return said if self.status == "no_data" else f"{self.name}: {said}"

    @property
    def open(self) -> bool:
        """Whether the check is a reason (it fails, warns or lacks data): neither a pass
        nor a check that does not apply."""
        return self.status not in ("pass", "not_applicable")

    @property
    def phrase(self) -> str:
        """The check in words as a message with a code (``phrases/check_messages.py``), which
        the API renders in a reader's language (the check's name, which :attr:`summary` puts
        before the numbers, stands beside it where it is shown)."""
        if self.status == "no_data":
            return phrase("no_data", what=Words(self.missing or _UNNAMED_NEED))
        if self.status == "not_applicable":
            return phrase("stored.not_applicable")
        if self.value is None or self.limit is None:
            return self.name
        return phrase(
            "stored.pass" if self.status == "pass" else "stored.fail",
            value=self.value,
            limit=self.limit,
            unit=Words(self.unit),
        )


class StoredCandidate(CandidateFigures):
    """A candidate as stored with the selection: its figures and its checks."""

    checks: list[StoredCheck]
    drive_options: list[DriveOptionGroup] | None

    @property
    def reasons(self) -> list[str]:
        """The checks that did not pass, in words."""
        return [c.summary for c in self.checks if c.open]


class StoredCycle(ResponseModel):
    """The cycle as sent: the chapter's t_1…t_p [s], or segments (then the times are None
    and the selection's :attr:`StoredSelection.segments` list them at the output)."""

    accel_s: float | None = None
    constant_s: float | None = None
    decel_s: float | None = None
    pause_s: float | None = None

    @property
    def is_trapezoid(self) -> bool:
        """Whether the cycle is the chapter's t_1…t_p pattern."""
        return self.accel_s is not None


def cycle_facts(
    cycle: StoredCycle, segments: list[SegmentOut]
) -> list[tuple[str, str, float | None, str]]:
    """The cycle as a report lists it: (key, label, value, unit) per time of the chapter's
    t_1…t_p, or per segment its duration and its speeds at the output."""
    if cycle.is_trapezoid:
        return [
            ("accel_s", "acceleration t₁", cycle.accel_s, "s"),
            ("constant_s", "constant speed t₂", cycle.constant_s, "s"),
            ("decel_s", "deceleration t₃", cycle.decel_s, "s"),
            ("pause_s", "pause t_p", cycle.pause_s, "s"),
        ]
    facts: list[tuple[str, str, float | None, str]] = []
    for k, seg in enumerate(segments, start=1):
        facts += [
            (f"segment_{k}_duration_s", f"segment {k}: duration", seg.duration_s, "s"),
            (f"segment_{k}_start_rpm", f"segment {k}: start speed", seg.start_rpm, "rpm"),
            (f"segment_{k}_end_rpm", f"segment {k}: end speed", seg.end_rpm, "rpm"),
        ]
    return facts


class StoredSelection(ResponseModel):
    """What quotes, reports and the AAS export read of a stored selection (``GET
    /selections/{id}``'s body), read strictly: the answer must be today's
    ``SelectionOut`` with every field, as the selection presenter writes it
    (``ANSWER_VERSION``); the migration 0010 upgraded the answers of older shapes."""

    id: str
    created_at: datetime
    catalogue_version: int
    load: ResolvedLoad
    mechanism: dict[str, Any] | None
    output_load: OutputLoadIn | None = None
    cycle: StoredCycle
    segments: list[SegmentOut]
    high_dynamics: bool
    cycle_time_s: float
    mean_speed_rpm: float
    duty_cycle_percent: float
    candidates: list[StoredCandidate]
    check_rules: list[CheckRuleOut]
    controllers: list[ControllerRef]

    @model_validator(mode="before")
    @classmethod
    def _todays_shape(cls, data: Any) -> Any:
        """The stored answer is a whole ``SelectionOut``: every field present and valid."""
        if isinstance(data, dict):
            missing = sorted(set(SelectionOut.model_fields) - set(data))
            if missing:
                raise ValueError(f"not an answer of today's shape, it lacks {missing}")
            SelectionOut.model_validate(data)
        return data

    @model_validator(mode="after")
    def _rules_on_checks(self) -> StoredSelection:
        """Each check with its rule's unit and reference (the answer lists them once)."""
        rules = {r.name: r for r in self.check_rules}
        for candidate in self.candidates:
            for i, check in enumerate(candidate.checks):
                rule = rules.get(check.name)
                if rule is None:
                    raise ValueError(f"check {check.name!r} is not among the check_rules")
                candidate.checks[i] = check.model_copy(
                    update={"unit": rule.unit, "reference": rule.reference}
                )
        return self
