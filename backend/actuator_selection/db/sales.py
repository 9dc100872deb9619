"""All SQL of sales: API keys, price lists, quotes and quote numbers.

Repositories flush at most (the request's session commits) and hand out frozen
dataclasses, never ORM rows.

Quote numbers are ``Q-<year>-<5 digits>``, sequential per year without gaps or
duplicates: the per-year counter row is raised with ``UPDATE … RETURNING`` in
the quote's own transaction. On PostgreSQL the UPDATE locks the row until the
transaction ends, so concurrent quotes queue for their numbers; a transaction
that rolls back takes its number back with it.
"""

from __future__ import annotations

import hashlib
import hmac
import re
import secrets
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import UTC, date, datetime
from typing import Any

from sqlalchemy import and_, delete, func, or_, select, update
from sqlalchemy.dialects.postgresql import insert as postgresql_insert
from sqlalchemy.dialects.sqlite import insert as sqlite_insert
from sqlalchemy.exc import IntegrityError
from sqlalchemy.orm import Session, selectinload

from actuator_selection.catalogue.changes import FileChanges
from actuator_selection.catalogue.csvio import (
    CatalogueFileError,
    Column,
    CsvSpec,
    Problem,
    Record,
    boolean,
    iso_date,
    one_of,
    parse,
)
from actuator_selection.db.models import ActuatorRow
from actuator_selection.db.models.sales import (
    ApiKeyRow,
    PriceListRow,
    PriceRow,
    QuoteCounterRow,
    QuoteItemRow,
    QuoteRow,
)
from actuator_selection.sales.money import amount_cell, currency_cell
from actuator_selection.sales.quote_status import QuoteStatus
from actuator_selection.sales.quote_terms import SellerParty, TaxTotals
from actuator_selection.sales.records import (
    ApiKeyRecord,
    NewQuote,
    PriceListRecord,
    PriceRecord,
    QuoteItem,
    QuoteRecord,
)

# --- API keys -------------------------------------------------------------------------

ROLES = ("admin", "sales")
NAME_LENGTH = 100
KEY_SCHEME = "asel"
_KEY = re.compile(rf"{KEY_SCHEME}_([0-9a-f]{{12}})_([A-Za-z0-9_-]{{43}})")
_DUMMY_SHA256 = hashlib.sha256(b"no such key").hexdigest()


def _utc(moment: datetime) -> datetime:
    """``moment`` with its UTC zone (SQLite hands stored UTC times back without one)."""
    return moment if moment.tzinfo is not None else moment.replace(tzinfo=UTC)


def _sha256(key: str) -> str:
    return hashlib.sha256(key.encode("ascii")).hexdigest()


_ACCESS_TOKEN = re.compile(r"([0-9a-f]{12})\.([0-9]{1,12})\.([0-9a-f]{64})")


def _access_mac(secret: bytes, prefix: str, resource: str, expires_at: int) -> str:
    message = f"{prefix}|{resource}|{expires_at}".encode()
    return hmac.new(secret, message, hashlib.sha256).hexdigest()


def _key_record(row: ApiKeyRow) -> ApiKeyRecord:
    return ApiKeyRecord(
        id=row.id,
        prefix=row.prefix,
        name=row.name,
        role=row.role,
        created_at=_utc(row.created_at),
        revoked_at=_utc(row.revoked_at) if row.revoked_at else None,
    )


class ApiKeyRepository:
    """API keys: created with a 256-bit secret shown once, stored as its SHA-256 hash.

    A key reads ``asel_<prefix>_<secret>``: the 48-bit hexadecimal prefix is not
    secret and finds the row; the secret is 32 random bytes (43 URL-safe base64
    characters). A fast hash suffices for a 256-bit random secret (no dictionary
    to guess from); the comparison runs in constant time.
    """

    def __init__(self, session: Session) -> None:
        self._session = session

    def create(self, *, name: str, role: str, now: datetime) -> tuple[ApiKeyRecord, str]:
        """A new key; returns its record and the key itself (the only time it is seen)."""
        if role not in ROLES:
            raise ValueError(f"role must be one of {', '.join(ROLES)}")
        name = name.strip()
        if not 1 <= len(name) <= NAME_LENGTH:
            raise ValueError(f"name must be 1 to {NAME_LENGTH} characters")
        prefix = secrets.token_hex(6)
        key = f"{KEY_SCHEME}_{prefix}_{secrets.token_urlsafe(32)}"
        row = ApiKeyRow(
            prefix=prefix, key_sha256=_sha256(key), name=name, role=role, created_at=now
        )
        self._session.add(row)
        self._session.flush()
        return _key_record(row), key

    def authenticate(self, key: str) -> ApiKeyRecord | None:
        """The active key matching ``key``; None for unknown, revoked or malformed keys."""
        match = _KEY.fullmatch(key)
        row = (
            self._session.scalar(select(ApiKeyRow).where(ApiKeyRow.prefix == match.group(1)))
            if match
            else None
        )
        # Compare even without a row, so timing does not tell whether a prefix exists.
        stored = row.key_sha256 if row is not None else _DUMMY_SHA256
        presented = _sha256(key) if key.isascii() else ""
        if not hmac.compare_digest(stored, presented) or row is None or row.revoked_at:
            return None
        return _key_record(row)

    def keys(self) -> list[ApiKeyRecord]:
        """Every key, oldest first."""
        rows = self._session.scalars(select(ApiKeyRow).order_by(ApiKeyRow.id))
        return [_key_record(r) for r in rows]

    @staticmethod
    def sign_access(key: ApiKeyRecord, resource: str, *, expires_at: int, secret: bytes) -> str:
        """A token that lends ``key``'s access to ``resource`` until ``expires_at`` [Unix s].

        For a link a browser opens without headers (the quote document in a new
        window). It reads ``<prefix>.<expires_at>.<HMAC-SHA256>``, keyed with the
        server's ``secret`` (``services/link_secret.py``), never with anything the
        database holds, so reading the database does not let anyone mint a token;
        revoking the key revokes its tokens.
        """
        return f"{key.prefix}.{expires_at}.{_access_mac(secret, key.prefix, resource, expires_at)}"

    def check_access(
        self, token: str, resource: str, *, now: datetime, secret: bytes, max_lifetime_s: int
    ) -> ApiKeyRecord | None:
        """The active key that signed ``token`` for ``resource``, if it has not expired and
        expires at most ``max_lifetime_s`` from ``now`` (a longer-lived token was not made
        by this service)."""
        match = _ACCESS_TOKEN.fullmatch(token)
        if match is None:
            return None
        prefix, expires_at, mac = match.group(1), int(match.group(2)), match.group(3)
        if not 0 <= expires_at - now.timestamp() <= max_lifetime_s:
            return None
        if not hmac.compare_digest(_access_mac(secret, prefix, resource, expires_at), mac):
            return None
        row = self._session.scalar(select(ApiKeyRow).where(ApiKeyRow.prefix == prefix))
        if row is None or row.revoked_at:
            return None
        return _key_record(row)

    def revoke(self, prefix: str, *, now: datetime) -> ApiKeyRecord | None:
        """Revoke the key of ``prefix`` (idempotent); None when there is no such key."""
        row = self._session.scalar(select(ApiKeyRow).where(ApiKeyRow.prefix == prefix))
        if row is None:
            return None
        if row.revoked_at is None:
            row.revoked_at = now
            self._session.flush()
        return _key_record(row)


# --- price lists ----------------------------------------------------------------------

ITEM_KINDS = ("actuator", "controller")

PRICES = CsvSpec(
    file="prices.csv",
    key=("price_list", "item_kind", "item_code", "currency", "valid_from"),
    columns=(
        Column(name="price_list", required=True, max_length=120),
        Column(name="is_example", required=True, convert=boolean),
        Column(name="item_kind", required=True, convert=one_of(*ITEM_KINDS)),
        Column(name="item_code", required=True, max_length=80),
        Column(name="description"),
        Column(name="unit_price", required=True, convert=amount_cell),
        Column(name="currency", required=True, convert=currency_cell),
        Column(name="valid_from", required=True, convert=iso_date),
        Column(name="valid_to", convert=iso_date),
        Column(name="source", required=True),
    ),
)
"""A price list file: one row per item, currency and validity period (``valid_to`` inclusive).

Amounts are decimal text with at most two decimal places (``1234.50``), never
binary floating point.
"""


def _price_record(row: PriceRow, price_list: PriceListRow) -> PriceRecord:
    return PriceRecord(
        price_list=price_list.name,
        is_example=price_list.is_example,
        item_kind=row.item_kind,
        item_code=row.item_code,
        description=row.description,
        unit_price=row.unit_price,
        currency=row.currency,
        valid_from=row.valid_from,
        valid_to=row.valid_to,
        source=row.source,
    )


def parse_prices(text: str, *, file: str = PRICES.file) -> list[Record]:
    """Validate a price list file; :class:`CatalogueFileError` names every bad cell.

    Besides the cell rules: one ``is_example`` per price list, ``valid_to`` not
    before ``valid_from``, and no two periods of the same item and currency that
    overlap (a price lookup must find one price).
    """
    spec = CsvSpec(file=file, columns=PRICES.columns, key=PRICES.key)
    records, problems = parse(spec, text)
    if problems:
        raise CatalogueFileError(problems)
    example: dict[str, tuple[bool, int]] = {}
    periods: dict[tuple[str, str, str, str], list[Record]] = {}
    for r in records:
        v = r.values
        flag, first = example.setdefault(v["price_list"], (v["is_example"], r.line))
        if flag != v["is_example"]:
            problems.append(
                Problem(
                    file=file,
                    line=r.line,
                    column="is_example",
                    message=f"differs from line {first} of the same price list",
                )
            )
        if v["valid_to"] is not None and v["valid_to"] < v["valid_from"]:
            problems.append(
                Problem(file=file, line=r.line, column="valid_to", message="is before valid_from")
            )
            continue
        key = (v["price_list"], v["item_kind"], v["item_code"], v["currency"])
        for other in periods.setdefault(key, []):
            o = other.values
            if _overlap(v["valid_from"], v["valid_to"], o["valid_from"], o["valid_to"]):
                problems.append(
                    Problem(
                        file=file,
                        line=r.line,
                        column="valid_from",
                        message=f"its period overlaps line {other.line} "
                        f"({v['item_kind']} {v['item_code']}, {v['currency']})",
                    )
                )
        periods[key].append(r)
    if problems:
        raise CatalogueFileError(problems)
    return records


def _overlap(a_from: date, a_to: date | None, b_from: date, b_to: date | None) -> bool:
    return (a_to is None or b_from <= a_to) and (b_to is None or a_from <= b_to)


class PriceRepository:
    """Price lists: read, looked up by item and date, replaced whole by an import."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def price_lists(self) -> list[PriceListRecord]:
        """Every price list with its item count and currencies, by name."""
        rows = self._session.scalars(
            select(PriceListRow)
            .options(selectinload(PriceListRow.prices))
            .order_by(PriceListRow.name)
        )
        return [
            PriceListRecord(
                name=r.name,
                is_example=r.is_example,
                imported_at=_utc(r.imported_at),
                item_count=len(r.prices),
                currencies=tuple(sorted({p.currency for p in r.prices})),
            )
            for r in rows
        ]

    def prices(self, price_list: str) -> list[PriceRecord] | None:
        """The prices of one list by kind, code, currency and start; None for an unknown list."""
        row = self._session.scalar(select(PriceListRow).where(PriceListRow.name == price_list))
        if row is None:
            return None
        prices = self._session.scalars(
            select(PriceRow)
            .where(PriceRow.price_list_id == row.id)
            .order_by(
                PriceRow.item_kind, PriceRow.item_code, PriceRow.currency, PriceRow.valid_from
            )
        )
        return [_price_record(p, row) for p in prices]

    def is_example(self, price_list: str) -> bool | None:
        """Whether the list holds example prices; None for an unknown list."""
        return self._session.scalar(
            select(PriceListRow.is_example).where(PriceListRow.name == price_list)
        )

    def lookup(
        self, *, price_list: str, item_kind: str, item_code: str, on: date, currency: str | None
    ) -> list[PriceRecord]:
        """Prices of the item valid on ``on`` (one per currency), optionally of one currency."""
        stmt = (
            select(PriceRow, PriceListRow)
            .join(PriceRow.price_list)
            .where(
                PriceListRow.name == price_list,
                PriceRow.item_kind == item_kind,
                PriceRow.item_code == item_code,
                PriceRow.valid_from <= on,
                or_(PriceRow.valid_to.is_(None), PriceRow.valid_to >= on),
            )
            .order_by(PriceRow.currency)
        )
        if currency is not None:
            stmt = stmt.where(PriceRow.currency == currency)
        return [_price_record(p, pl) for p, pl in self._session.execute(stmt)]

    def replace(self, records: Sequence[Record], *, now: datetime) -> dict[str, FileChanges]:
        """Make each price list named in ``records`` hold exactly those rows.

        Rows are matched by (kind, code, currency, valid_from); lists not named
        are left alone. Actuator prices must name a catalogue model (retired
        ones included); :class:`CatalogueFileError` otherwise, with nothing written.
        """
        models = set(self._session.scalars(select(ActuatorRow.model)))
        unknown = [
            Problem(
                file=PRICES.file,
                line=r.line,
                column="item_code",
                message=f"unknown actuator model {r.values['item_code']!r}",
            )
            for r in records
            if r.values["item_kind"] == "actuator" and r.values["item_code"] not in models
        ]
        if unknown:
            raise CatalogueFileError(unknown)
        by_list: dict[str, list[Record]] = {}
        for r in records:
            by_list.setdefault(r.values["price_list"], []).append(r)
        report: dict[str, FileChanges] = {}
        for name, rows in by_list.items():
            changes = report.setdefault(name, FileChanges())
            price_list = self._session.scalar(select(PriceListRow).where(PriceListRow.name == name))
            if price_list is None:
                price_list = PriceListRow(
                    name=name, is_example=rows[0].values["is_example"], imported_at=now
                )
                self._session.add(price_list)
                self._session.flush()
            price_list.is_example = rows[0].values["is_example"]
            price_list.imported_at = now
            existing = {
                (p.item_kind, p.item_code, p.currency, p.valid_from): p
                for p in self._session.scalars(
                    select(PriceRow).where(PriceRow.price_list_id == price_list.id)
                )
            }
            wanted: set[tuple[str, str, str, date]] = set()
            for r in rows:
                v = {k: val for k, val in r.values.items() if k not in {"price_list", "is_example"}}
                key = (v["item_kind"], v["item_code"], v["currency"], v["valid_from"])
                wanted.add(key)
                row = existing.get(key)
                if row is None:
                    self._session.add(PriceRow(price_list_id=price_list.id, **v))
                    changes.inserted += 1
                    continue
                changed = False
                for attribute, value in v.items():
                    if getattr(row, attribute) != value:
                        setattr(row, attribute, value)
                        changed = True
                changes.count(is_new=False, changed=changed)
            gone = [p.id for key, p in existing.items() if key not in wanted]
            if gone:
                self._session.execute(delete(PriceRow).where(PriceRow.id.in_(gone)))
                changes.retired += len(gone)
        self._session.flush()
        return report


# --- quotes ---------------------------------------------------------------------------

NUMBER_FORMAT = "Q-{year}-{sequence:05d}"


def quote_number(year: int, sequence: int) -> str:
    """The printed number of a quote.

    >>> quote_number(2026, 42)
    'Q-2026-00042'
    """
    return NUMBER_FORMAT.format(year=year, sequence=sequence)


class IdempotencyKeyReusedError(Exception):
    """An Idempotency-Key sent again with a different request body."""

    def __init__(self, number: str) -> None:
        super().__init__(number)
        self.number = number


def _quote_record(row: QuoteRow) -> QuoteRecord:
    return QuoteRecord(
        number=row.number,
        year=row.year,
        sequence=row.sequence,
        status=QuoteStatus(row.status),
        created_at=_utc(row.created_at),
        status_changed_at=_utc(row.status_changed_at),
        valid_until=row.valid_until,
        api_key_id=row.api_key_id,
        idempotency_key=row.idempotency_key,
        request_sha256=row.request_sha256,
        selection_id=row.selection_id,
        selection_catalogue_version=row.selection_catalogue_version,
        catalogue_version=row.catalogue_version,
        customer_name=row.customer_name,
        customer_address=row.customer_address,
        customer_reference=row.customer_reference,
        notes=row.notes,
        actuator_model=row.actuator_model,
        verdict=row.verdict,
        verdict_reasons=tuple(row.verdict_reasons),
        actuator_snapshot=dict(row.actuator_snapshot),
        price_list_name=row.price_list_name,
        price_list_is_example=row.price_list_is_example,
        price_date=row.price_date,
        currency=row.currency,
        subtotal=row.subtotal,
        discount_percent=row.discount_percent,
        discount_amount=row.discount_amount,
        total=row.total,
        items=tuple(
            QuoteItem(
                position=i.position,
                item_kind=i.item_kind,
                item_code=i.item_code,
                description=i.description,
                quantity=i.quantity,
                unit_price=i.unit_price,
                line_total=i.line_total,
                axis=i.axis,
            )
            for i in row.items
        ),
        project_id=row.project_id,
        axes=tuple(row.axes) if row.axes is not None else None,
        tax=(
            TaxTotals(
                net=row.total,
                vat_percent=row.vat_percent,
                vat_amount=row.vat_amount,
                gross=row.gross_total,
            )
            if row.vat_percent is not None
            and row.vat_amount is not None
            and row.gross_total is not None
            else None
        ),
        payment_terms=row.payment_terms,
        delivery_terms=row.delivery_terms,
        seller=SellerParty.from_json(row.seller) if row.seller is not None else None,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class QuoteSearch:
    """A quote query: ``text`` in number, customer, reference or model; ``status`` as of
    ``today`` (``expired`` included)."""

    today: date
    text: str | None = None
    status: QuoteStatus | None = None
    limit: int = 50
    offset: int = 0


class QuoteRepository:
    """Quotes: numbered on insert, read back, moved through their status flow."""

    def __init__(self, session: Session) -> None:
        self._session = session

    def _next_sequence(self, year: int) -> int:
        """Raise the year's counter inside the caller's transaction; returns the new number."""
        bump = (
            update(QuoteCounterRow)
            .where(QuoteCounterRow.year == year)
            .values(last_number=QuoteCounterRow.last_number + 1)
            .returning(QuoteCounterRow.last_number)
        )
        number = self._session.execute(bump).scalar()
        if number is None:
            # The year's first quote: create the counter row; a concurrent first quote
            # may create it too, so conflicts are ignored and the UPDATE decides.
            dialect = self._session.get_bind().dialect.name
            insert = postgresql_insert if dialect == "postgresql" else sqlite_insert
            self._session.execute(
                insert(QuoteCounterRow)
                .values(year=year, last_number=0)
                .on_conflict_do_nothing(index_elements=["year"])
            )
            number = self._session.execute(bump).scalar_one()
        return number

    def create(self, new: NewQuote) -> tuple[QuoteRecord, bool]:
        """Store ``new`` under the year's next number; returns the quote and whether it is new.

        With an idempotency key already used by the same API key, the stored quote
        comes back instead (``False``), also when a concurrent request with the same
        key won the race; a different request body under that key raises
        :class:`IdempotencyKeyReusedError`.
        """
        if new.idempotency_key is not None:
            found = self.by_idempotency_key(new.api_key_id, new.idempotency_key)
            if found is not None:
                return self._replay(found, new), False
        year = new.created_at.year
        try:
            with self._session.begin_nested():
                sequence = self._next_sequence(year)
                row = QuoteRow(
                    number=quote_number(year, sequence),
                    year=year,
                    sequence=sequence,
                    status=QuoteStatus.DRAFT.value,
                    status_changed_at=new.created_at,
                    verdict_reasons=list(new.verdict_reasons),
                    actuator_snapshot=dict(new.actuator_snapshot),
                    vat_percent=new.tax.vat_percent if new.tax is not None else None,
                    vat_amount=new.tax.vat_amount if new.tax is not None else None,
                    gross_total=new.tax.gross if new.tax is not None else None,
                    seller=new.seller.to_json() if new.seller is not None else None,
                    items=[
                        QuoteItemRow(
                            position=i.position,
                            item_kind=i.item_kind,
                            item_code=i.item_code,
                            description=i.description,
                            quantity=i.quantity,
                            unit_price=i.unit_price,
                            line_total=i.line_total,
                            axis=i.axis,
                        )
                        for i in new.items
                    ],
                    axes=[dict(a) for a in new.axes] if new.axes is not None else None,
                    **{
                        name: getattr(new, name)
                        for name in (
                            "created_at",
                            "valid_until",
                            "api_key_id",
                            "idempotency_key",
                            "request_sha256",
                            "selection_id",
                            "project_id",
                            "selection_catalogue_version",
                            "catalogue_version",
                            "customer_name",
                            "customer_address",
                            "customer_reference",
                            "notes",
                            "actuator_model",
                            "verdict",
                            "price_list_name",
                            "price_list_is_example",
                            "price_date",
                            "currency",
                            "subtotal",
                            "discount_percent",
                            "discount_amount",
                            "total",
                            "payment_terms",
                            "delivery_terms",
                        )
                    },
                )
                self._session.add(row)
                self._session.flush()
        except IntegrityError:
            # The savepoint is gone, and with it this attempt's counter increment.
            if new.idempotency_key is None:
                raise
            found = self.by_idempotency_key(new.api_key_id, new.idempotency_key)
            if found is None:
                raise
            return self._replay(found, new), False
        return _quote_record(row), True

    @staticmethod
    def _replay(found: QuoteRecord, new: NewQuote) -> QuoteRecord:
        if not hmac.compare_digest(found.request_sha256, new.request_sha256):
            raise IdempotencyKeyReusedError(found.number)
        return found

    def _one(self, *criteria: Any, for_update: bool = False) -> QuoteRecord | None:
        stmt = select(QuoteRow).options(selectinload(QuoteRow.items)).where(*criteria)
        if for_update:
            stmt = stmt.with_for_update()
        row = self._session.scalar(stmt)
        return _quote_record(row) if row is not None else None

    def by_number(self, number: str, *, for_update: bool = False) -> QuoteRecord | None:
        """One quote; ``for_update`` locks its row (PostgreSQL) until the transaction ends."""
        return self._one(QuoteRow.number == number, for_update=for_update)

    def by_idempotency_key(self, api_key_id: int, key: str) -> QuoteRecord | None:
        """The quote an API key created under an idempotency key, or None."""
        return self._one(QuoteRow.api_key_id == api_key_id, QuoteRow.idempotency_key == key)

    def search(self, query: QuoteSearch) -> tuple[list[QuoteRecord], int]:
        """Quotes matching ``query``, newest first, and how many match in all."""
        criteria: list[Any] = []
        if query.text:
            needle = query.text.lower()
            criteria.append(
                or_(
                    *(
                        func.lower(column).contains(needle, autoescape=True)
                        for column in (
                            QuoteRow.number,
                            QuoteRow.customer_name,
                            QuoteRow.customer_reference,
                            QuoteRow.actuator_model,
                        )
                    )
                )
            )
        if query.status is not None:
            expiring = QuoteRow.status.in_([QuoteStatus.DRAFT.value, QuoteStatus.SENT.value])
            past = QuoteRow.valid_until < query.today
            if query.status is QuoteStatus.EXPIRED:
                criteria.append(and_(expiring, past))
            elif query.status in (QuoteStatus.DRAFT, QuoteStatus.SENT):
                criteria.append(and_(QuoteRow.status == query.status.value, ~past))
            else:
                criteria.append(QuoteRow.status == query.status.value)
        total = self._session.scalar(select(func.count()).select_from(QuoteRow).where(*criteria))
        rows = self._session.scalars(
            select(QuoteRow)
            .options(selectinload(QuoteRow.items))
            .where(*criteria)
            .order_by(QuoteRow.year.desc(), QuoteRow.sequence.desc())
            .limit(query.limit)
            .offset(query.offset)
        )
        return [_quote_record(r) for r in rows], total or 0

    def set_status(self, number: str, status: QuoteStatus, *, now: datetime) -> None:
        """Store a new status (the caller has checked the flow)."""
        self._session.execute(
            update(QuoteRow)
            .where(QuoteRow.number == number)
            .values(status=status.value, status_changed_at=now)
        )
        self._session.flush()
