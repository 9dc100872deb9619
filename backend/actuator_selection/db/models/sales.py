"""Sales: API keys, price lists, quotes and their per-year number counters.

Money columns are ``Numeric(14, 2)`` (whole cents, exact decimals on both
backends); a quote keeps copies of everything it showed (prices, the
actuator's catalogue data), so later price or catalogue changes never alter it.
"""

from __future__ import annotations

from datetime import date, datetime
from decimal import Decimal
from typing import Any

from sqlalchemy import (
    Boolean,
    CheckConstraint,
    Date,
    DateTime,
    ForeignKey,
    Integer,
    Numeric,
    String,
    Text,
    UniqueConstraint,
)
from sqlalchemy.orm import Mapped, mapped_column, relationship

from actuator_selection.db.models.base import Base
from actuator_selection.db.models.selections import JSONDocument

Money = Numeric(14, 2, asdecimal=True)
"""Whole cents up to 999 999 999 999.99."""


class ApiKeyRow(Base):
    """A client's API key: only its SHA-256 hash is stored, found by its public prefix."""

    __tablename__ = "api_keys"
    __table_args__ = (CheckConstraint("role IN ('admin', 'sales')", name="role"),)

    id: Mapped[int] = mapped_column(primary_key=True)
    prefix: Mapped[str] = mapped_column(String(16), unique=True)
    """Public, non-secret part of the key; names the key in listings and revocation."""
    key_sha256: Mapped[str] = mapped_column(String(64))
    name: Mapped[str] = mapped_column(String(100))
    role: Mapped[str] = mapped_column(String(16))
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    revoked_at: Mapped[datetime | None] = mapped_column(DateTime(timezone=True))


class PriceListRow(Base):
    """A named price list; ``is_example`` marks invented prices that must never reach a customer."""

    __tablename__ = "price_lists"

    id: Mapped[int] = mapped_column(primary_key=True)
    name: Mapped[str] = mapped_column(String(120), unique=True)
    is_example: Mapped[bool] = mapped_column(Boolean)
    imported_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))

    prices: Mapped[list[PriceRow]] = relationship(
        back_populates="price_list", cascade="all, delete-orphan"
    )


class PriceRow(Base):
    """The price of one item (an actuator model or a controller code) for a validity period."""

    __tablename__ = "prices"
    __table_args__ = (
        UniqueConstraint("price_list_id", "item_kind", "item_code", "currency", "valid_from"),
        CheckConstraint("item_kind IN ('actuator', 'controller')", name="item_kind"),
        CheckConstraint("unit_price >= 0", name="unit_price"),
    )

    id: Mapped[int] = mapped_column(primary_key=True)
    price_list_id: Mapped[int] = mapped_column(
        ForeignKey("price_lists.id", ondelete="CASCADE"), index=True
    )
    item_kind: Mapped[str] = mapped_column(String(16))
    item_code: Mapped[str] = mapped_column(String(80))
    description: Mapped[str | None] = mapped_column(Text)
    unit_price: Mapped[Decimal] = mapped_column(Money)
    currency: Mapped[str] = mapped_column(String(3))
    valid_from: Mapped[date] = mapped_column(Date)
    valid_to: Mapped[date | None] = mapped_column(Date)
    """Last day the price applies (inclusive); NULL: until further notice."""
    source: Mapped[str] = mapped_column(Text)

    price_list: Mapped[PriceListRow] = relationship(back_populates="prices")


class QuoteCounterRow(Base):
    """The last quote number given out in a year; raised in the quote's own transaction."""

    __tablename__ = "quote_counters"

    year: Mapped[int] = mapped_column(Integer, primary_key=True, autoincrement=False)
    last_number: Mapped[int] = mapped_column(Integer)


class QuoteRow(Base):
    """A quote made from a stored selection; its figures are computed by the service."""

    __tablename__ = "quotes"
    __table_args__ = (
        UniqueConstraint("year", "sequence"),
        UniqueConstraint("api_key_id", "idempotency_key"),
        CheckConstraint("status IN ('draft', 'sent', 'accepted', 'rejected')", name="status"),
        CheckConstraint("discount_percent >= 0 AND discount_percent <= 100", name="discount"),
        CheckConstraint("vat_percent >= 0 AND vat_percent <= 100", name="vat"),
        CheckConstraint("(selection_id IS NULL) <> (project_id IS NULL)", name="source"),
    )

    id: Mapped[int] = mapped_column(primary_key=True)
    number: Mapped[str] = mapped_column(String(20), unique=True)
    year: Mapped[int] = mapped_column(Integer)
    sequence: Mapped[int] = mapped_column(Integer)
    status: Mapped[str] = mapped_column(String(10))
    created_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    status_changed_at: Mapped[datetime] = mapped_column(DateTime(timezone=True))
    valid_until: Mapped[date] = mapped_column(Date)
    api_key_id: Mapped[int] = mapped_column(ForeignKey("api_keys.id"), index=True)
    idempotency_key: Mapped[str | None] = mapped_column(String(200))
    request_sha256: Mapped[str] = mapped_column(String(64))
    selection_id: Mapped[str | None] = mapped_column(ForeignKey("selections.id"), index=True)
    project_id: Mapped[str | None] = mapped_column(ForeignKey("projects.id"), index=True)
    """Migration 0016: a quote rests on a selection or on a machine project, one of them."""
    axes: Mapped[list[dict[str, Any]] | None] = mapped_column(JSONDocument)
    """A project quote's axes as quoted (actuator data, verdict, controller); NULL for a
    selection's quote."""
    selection_catalogue_version: Mapped[int] = mapped_column(Integer)
    catalogue_version: Mapped[int] = mapped_column(Integer)
    """The catalogue's version when the quote was made (the selection's may be older)."""
    customer_name: Mapped[str] = mapped_column(String(200))
    customer_address: Mapped[str | None] = mapped_column(Text)
    customer_reference: Mapped[str | None] = mapped_column(String(200))
    notes: Mapped[str | None] = mapped_column(Text)
    actuator_model: Mapped[str] = mapped_column(String(60))
    verdict: Mapped[str] = mapped_column(String(12))
    verdict_reasons: Mapped[list[str]] = mapped_column(JSONDocument)
    actuator_snapshot: Mapped[dict[str, Any]] = mapped_column(JSONDocument)
    """The actuator's catalogue entry as it stood when the quote was made."""
    price_list_name: Mapped[str] = mapped_column(String(120))
    price_list_is_example: Mapped[bool] = mapped_column(Boolean)
    price_date: Mapped[date] = mapped_column(Date)
    currency: Mapped[str] = mapped_column(String(3))
    subtotal: Mapped[Decimal] = mapped_column(Money)
    discount_percent: Mapped[Decimal] = mapped_column(Numeric(5, 2, asdecimal=True))
    discount_amount: Mapped[Decimal] = mapped_column(Money)
    total: Mapped[Decimal] = mapped_column(Money)
    """The net total: subtotal − discount."""
    # Migration 0008: NULL on quotes made before, which stated no VAT and no terms.
    vat_percent: Mapped[Decimal | None] = mapped_column(Numeric(5, 2, asdecimal=True))
    vat_amount: Mapped[Decimal | None] = mapped_column(Money)
    gross_total: Mapped[Decimal | None] = mapped_column(Money)
    payment_terms: Mapped[str | None] = mapped_column(Text)
    """As entered; NULL: the seller's standard terms (``seller``)."""
    delivery_terms: Mapped[str | None] = mapped_column(Text)
    """As entered; NULL: the seller's standard terms (``seller``)."""
    seller: Mapped[dict[str, Any] | None] = mapped_column(JSONDocument)
    """The seller block (name, address, VAT id, contact, standard terms by language) as
    configured when the quote was made."""

    items: Mapped[list[QuoteItemRow]] = relationship(
        back_populates="quote", order_by="QuoteItemRow.position", cascade="all, delete-orphan"
    )


class QuoteItemRow(Base):
    """One priced line of a quote, with the unit price copied from the price list."""

    __tablename__ = "quote_items"
    __table_args__ = (
        UniqueConstraint("quote_id", "position"),
        CheckConstraint("quantity >= 1", name="quantity"),
    )

    id: Mapped[int] = mapped_column(primary_key=True)
    quote_id: Mapped[int] = mapped_column(ForeignKey("quotes.id", ondelete="CASCADE"))
    position: Mapped[int] = mapped_column(Integer)
    item_kind: Mapped[str] = mapped_column(String(16))
    item_code: Mapped[str] = mapped_column(String(80))
    description: Mapped[str] = mapped_column(Text)
    quantity: Mapped[int] = mapped_column(Integer)
    unit_price: Mapped[Decimal] = mapped_column(Money)
    line_total: Mapped[Decimal] = mapped_column(Money)
    axis: Mapped[str | None] = mapped_column(String(80))
    """The project axis the line belongs to (migration 0016); NULL on a selection's quote."""

    quote: Mapped[QuoteRow] = relationship(back_populates="items")
