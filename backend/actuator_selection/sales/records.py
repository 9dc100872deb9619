"""Sales records: API keys, price lists and prices, quotes and their lines.

Repositories hand these out; the API's schemas and the quote document are built from
them. Money is ``Decimal`` throughout (``sales.money``).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from datetime import date, datetime
from decimal import Decimal
from typing import Any

from actuator_selection.sales.quote_status import QuoteStatus
from actuator_selection.sales.quote_terms import SellerParty, TaxTotals


@dataclass(frozen=True, slots=True, kw_only=True)
class ApiKeyRecord:
    """An API key without its secret: the public prefix names it."""

    id: int
    prefix: str
    name: str
    role: str
    created_at: datetime
    revoked_at: datetime | None


@dataclass(frozen=True, slots=True, kw_only=True)
class PriceListRecord:
    """A price list and what it holds."""

    name: str
    is_example: bool
    imported_at: datetime
    item_count: int
    currencies: tuple[str, ...]


@dataclass(frozen=True, slots=True, kw_only=True)
class PriceRecord:
    """One price of a price list."""

    price_list: str
    is_example: bool
    item_kind: str
    item_code: str
    description: str | None
    unit_price: Decimal
    currency: str
    valid_from: date
    valid_to: date | None
    source: str


@dataclass(frozen=True, slots=True, kw_only=True)
class QuoteItem:
    """One priced line of a quote."""

    position: int
    item_kind: str
    item_code: str
    description: str
    quantity: int
    unit_price: Decimal
    line_total: Decimal
    axis: str | None = None
    """The machine project's axis the line is for; None on a selection's quote."""


@dataclass(frozen=True, slots=True, kw_only=True)
class NewQuote:
    """Everything a quote holds before it has a number."""

    created_at: datetime
    valid_until: date
    api_key_id: int
    idempotency_key: str | None
    request_sha256: str
    selection_id: str | None
    """The selection the quote rests on; None for a machine project's (``project_id``)."""
    selection_catalogue_version: int
    catalogue_version: int
    customer_name: str
    customer_address: str | None
    customer_reference: str | None
    notes: str | None
    actuator_model: str
    verdict: str
    verdict_reasons: tuple[str, ...]
    actuator_snapshot: Mapping[str, Any]
    price_list_name: str
    price_list_is_example: bool
    price_date: date
    currency: str
    subtotal: Decimal
    discount_percent: Decimal
    discount_amount: Decimal
    total: Decimal
    """The net total: subtotal − discount."""
    items: tuple[QuoteItem, ...]
    # The commercial terms (migration 0008). None on quotes made before: they stated
    # no VAT and no terms, and their document shows the seller as configured now.
    tax: TaxTotals | None = None
    payment_terms: str | None = None
    """As entered for this quote; None: the seller's standard terms."""
    delivery_terms: str | None = None
    """As entered for this quote; None: the seller's standard terms."""
    seller: SellerParty | None = None
    """The seller as configured when the quote was made."""
    project_id: str | None = None
    """The machine project the quote rests on (migration 0016); None for a selection's."""
    axes: tuple[Mapping[str, Any], ...] | None = None
    """A project quote's axes as quoted: name, actuator (its catalogue entry), verdict,
    reasons, controller; None for a selection's quote."""


@dataclass(frozen=True, slots=True, kw_only=True)
class QuoteRecord(NewQuote):
    """A stored quote: the new quote with its number and stored status.

    ``status`` is the stored one (``expired`` is computed by the caller).
    """

    number: str
    year: int
    sequence: int
    status: QuoteStatus
    status_changed_at: datetime
