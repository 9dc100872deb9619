"""Price lists: their contents and what an import changed.

Money is exact decimal text in JSON (``"1234.50"``), never a binary float.
"""

from __future__ import annotations

from datetime import date, datetime
from decimal import Decimal

from pydantic import Field

from actuator_selection.catalogue.changes import FileChanges
from actuator_selection.sales.records import PriceListRecord, PriceRecord
from actuator_selection.schemas.common import ResponseModel


class PriceListOut(ResponseModel):
    """A price list; ``is_example`` lists hold invented prices for trying the service out."""

    name: str
    is_example: bool = Field(description="true: example prices, not real ones")
    imported_at: datetime
    item_count: int
    currencies: list[str]

    @classmethod
    def from_record(cls, record: PriceListRecord) -> PriceListOut:
        """The response body of one price list."""
        return cls(
            name=record.name,
            is_example=record.is_example,
            imported_at=record.imported_at,
            item_count=record.item_count,
            currencies=list(record.currencies),
        )


class PriceOut(ResponseModel):
    """One price for a validity period (``valid_to`` inclusive, null: open-ended)."""

    item_kind: str
    item_code: str
    description: str | None
    unit_price: Decimal = Field(description='exact decimal as a string, e.g. "1234.50"')
    currency: str
    valid_from: date
    valid_to: date | None
    source: str

    @classmethod
    def from_record(cls, record: PriceRecord) -> PriceOut:
        """The response body of one price."""
        return cls(
            item_kind=record.item_kind,
            item_code=record.item_code,
            description=record.description,
            unit_price=record.unit_price,
            currency=record.currency,
            valid_from=record.valid_from,
            valid_to=record.valid_to,
            source=record.source,
        )


class PriceListDetailOut(ResponseModel):
    """A price list with its prices."""

    name: str
    is_example: bool
    prices: list[PriceOut]


class ChangesOut(ResponseModel):
    """Rows inserted, updated, left unchanged and retired (removed) by a load."""

    inserted: int
    updated: int
    unchanged: int
    retired: int

    @classmethod
    def from_changes(cls, changes: FileChanges) -> ChangesOut:
        """The response body of one file's or list's changes."""
        return cls(
            inserted=changes.inserted,
            updated=changes.updated,
            unchanged=changes.unchanged,
            retired=changes.retired,
        )


class PriceImportOut(ResponseModel):
    """What a price list import changed (``dry_run``: would change; nothing was written)."""

    dry_run: bool
    price_lists: dict[str, ChangesOut] = Field(
        description="per price list in the file; `retired`: prices removed from the list"
    )
