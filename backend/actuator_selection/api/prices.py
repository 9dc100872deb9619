"""Price lists: read by sales and admin keys, imported as CSV by admin keys.

An import is one transaction: one bad cell changes nothing, and the 422 names
file, line, column and rule. ``?dry_run=true`` reports what would change.
"""

from __future__ import annotations

from datetime import UTC, datetime
from typing import Annotated

from fastapi import APIRouter, Depends, Query

from actuator_selection.api.uploads import Upload, file_errors, raw_upload, text_of, unsupported
from actuator_selection.catalogue.csvio import CatalogueFileError
from actuator_selection.db.sales import PRICES, PriceRepository, parse_prices
from actuator_selection.http.auth import AdminDep, PriceReaderDep
from actuator_selection.http.deps import SessionDep
from actuator_selection.http.errors import ResourceNotFoundError, service_error
from actuator_selection.schemas.prices import (
    ChangesOut,
    PriceImportOut,
    PriceListDetailOut,
    PriceListOut,
    PriceOut,
)

router = APIRouter(tags=["prices"])

PRICE_CSV_HELP = (
    "Body: the CSV file itself (`Content-Type: text/csv`, UTF-8), columns "
    f"{', '.join(c.name for c in PRICES.columns)}. Each price list named in the file is "
    "replaced by the file's rows; lists not named stay as they are. `unit_price` is decimal "
    "text with at most two decimal places; `valid_to` is inclusive and may be empty."
)


@router.get("/price-lists")
def list_price_lists(_: PriceReaderDep, session: SessionDep) -> list[PriceListOut]:
    """Every price list, with its item count and currencies."""
    return [PriceListOut.from_record(r) for r in PriceRepository(session).price_lists()]


@router.get("/price-lists/{name}", responses={404: {"description": "unknown price list"}})
def get_price_list(name: str, _: PriceReaderDep, session: SessionDep) -> PriceListDetailOut:
    """One price list with all its prices."""
    repository = PriceRepository(session)
    prices = repository.prices(name)
    if prices is None:
        raise ResourceNotFoundError(
            [service_error(["path", "name"], "not_found", "unknown_price_list", name=name)]
        )
    return PriceListDetailOut(
        name=name,
        is_example=bool(repository.is_example(name)),
        prices=[PriceOut.from_record(p) for p in prices],
    )


@router.post(
    "/price-lists/import",
    description=PRICE_CSV_HELP,
    responses={
        415: {"description": "not text/csv"},
        422: {"description": "a bad file: every problem with file, line, column and rule"},
    },
    openapi_extra={
        "requestBody": {"required": True, "content": {"text/csv": {"schema": {"type": "string"}}}}
    },
)
def import_prices(
    _: AdminDep,
    upload: Annotated[Upload, Depends(raw_upload)],
    session: SessionDep,
    dry_run: Annotated[bool, Query(description="report what would change, change nothing")] = False,
) -> PriceImportOut:
    """Import price lists from CSV, atomically."""
    if upload.media_type not in ("text/csv", "text/plain"):
        raise unsupported(upload.media_type, ("text/csv",))
    text = text_of(upload.body, file=PRICES.file)
    try:
        records = parse_prices(text)
        savepoint = session.begin_nested()
        try:
            report = PriceRepository(session).replace(records, now=datetime.now(UTC))
        except BaseException:
            savepoint.rollback()
            raise
        if dry_run:
            savepoint.rollback()
        else:
            savepoint.commit()
    except CatalogueFileError as exc:
        raise file_errors(exc) from None
    return PriceImportOut(
        dry_run=dry_run,
        price_lists={name: ChangesOut.from_changes(c) for name, c in report.items()},
    )
