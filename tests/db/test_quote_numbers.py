"""Quote numbers: per year, sequential, no gaps, no duplicates, also under concurrent creation.

The concurrency tests run against PostgreSQL with committed transactions on a
database of their own (each thread with its own connection and session), since
the rolled-back test transaction of the other tests cannot show concurrency.
"""

from __future__ import annotations

import gzip
import threading
from collections.abc import Callable, Iterator
from dataclasses import replace
from datetime import UTC, date, datetime, timedelta
from decimal import Decimal

import pytest
from sqlalchemy import Engine, create_engine, func, select
from sqlalchemy.orm import Session, sessionmaker

from actuator_selection.db.engine import make_engine, normalise_url
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.models import SelectionRow
from actuator_selection.db.models.sales import QuoteCounterRow, QuoteRow
from actuator_selection.db.sales import (
    ApiKeyRepository,
    IdempotencyKeyReusedError,
    QuoteRepository,
)
from actuator_selection.sales.records import NewQuote, QuoteItem, QuoteRecord

THREADS = 20
NOW = datetime(2026, 11, 21, 12, 0, tzinfo=UTC)


def new_quote(api_key_id: int, *, created_at: datetime = NOW, **changes: object) -> NewQuote:
    quote = NewQuote(
        created_at=created_at,
        valid_until=date(2027, 1, 31),
        api_key_id=api_key_id,
        idempotency_key=None,
        request_sha256="0" * 64,
        selection_id="selection-1",
        selection_catalogue_version=1,
        catalogue_version=1,
        customer_name="Muster GmbH",
        customer_address=None,
        customer_reference=None,
        notes=None,
        actuator_model="FHA-25C-50-L",
        verdict="unconfirmed",
        verdict_reasons=("no continuous-duty data",),
        actuator_snapshot={"model": "FHA-25C-50-L"},
        price_list_name="test",
        price_list_is_example=True,
        price_date=created_at.date(),
        currency="EUR",
        subtotal=Decimal("2950.00"),
        discount_percent=Decimal("0.00"),
        discount_amount=Decimal("0.00"),
        total=Decimal("2950.00"),
        items=(
            QuoteItem(
                position=1,
                item_kind="actuator",
                item_code="FHA-25C-50-L",
                description="Servo actuator FHA-25C-50-L",
                quantity=1,
                unit_price=Decimal("2950.00"),
                line_total=Decimal("2950.00"),
            ),
        ),
    )
    return replace(quote, **changes)  # type: ignore[arg-type]


def _database(url: str, *, postgres: bool) -> Iterator[Engine]:
    upgrade(url=url)
    engine = (
        create_engine(normalise_url(url), pool_size=THREADS + 2, max_overflow=0)
        if postgres
        else make_engine(url)
    )
    with sessionmaker(engine).begin() as session:
        session.add(
            SelectionRow(
                id="selection-1",
                created_at=NOW,
                catalogue_version=1,
                request={},
                answer_gzip=gzip.compress(b"{}"),
                answer_version=2,
            )
        )
    yield engine
    engine.dispose()


@pytest.fixture
def engine(backend: str, new_database: Callable[[str], str]) -> Iterator[Engine]:
    """A migrated database of its own with one selection, for committed transactions."""
    yield from _database(new_database(backend), postgres=backend == "postgresql")


@pytest.fixture
def pg_engine(new_database: Callable[[str], str]) -> Iterator[Engine]:
    """The same on PostgreSQL, whose row locks let writers run concurrently (SQLite would
    serialise whole transactions), with a connection for every thread."""
    yield from _database(new_database("postgresql"), postgres=True)


def sales_key(engine: Engine) -> int:
    with sessionmaker(engine).begin() as session:
        record, _ = ApiKeyRepository(session).create(name="erp", role="sales", now=NOW)
        return record.id


def stored(engine: Engine) -> list[tuple[str, int, int]]:
    with Session(engine) as session:
        rows = session.execute(
            select(QuoteRow.number, QuoteRow.year, QuoteRow.sequence).order_by(QuoteRow.id)
        )
        return [(n, y, s) for n, y, s in rows]


def test_sequential_per_year_and_restarting_each_year(engine: Engine) -> None:
    key = sales_key(engine)
    factory = sessionmaker(engine)
    numbers = []
    for created_at in (NOW, NOW, NOW + timedelta(days=45), NOW + timedelta(days=46), NOW):
        with factory.begin() as session:
            record, created = QuoteRepository(session).create(new_quote(key, created_at=created_at))
            assert created
            numbers.append(record.number)
    assert numbers == [
        "Q-2026-00001",
        "Q-2026-00002",
        "Q-2027-00001",
        "Q-2027-00002",
        "Q-2026-00003",
    ]


def test_a_rolled_back_quote_gives_its_number_back(engine: Engine) -> None:
    key = sales_key(engine)
    factory = sessionmaker(engine)
    with factory.begin() as session:
        QuoteRepository(session).create(new_quote(key))
    session = factory()
    try:
        record, _ = QuoteRepository(session).create(new_quote(key))
        assert record.number == "Q-2026-00002"
        session.rollback()  # e.g. a later step of the request failed
    finally:
        session.close()
    with factory.begin() as session:
        record, _ = QuoteRepository(session).create(new_quote(key))
    assert record.number == "Q-2026-00002"
    assert [s for _, _, s in stored(engine)] == [1, 2]
    with Session(engine) as session:
        assert session.get(QuoteCounterRow, 2026) is not None
        assert session.scalar(select(QuoteCounterRow.last_number)) == 2


def test_idempotency_key_returns_the_stored_quote(engine: Engine) -> None:
    key = sales_key(engine)
    factory = sessionmaker(engine)
    quote = new_quote(key, idempotency_key="order-1", request_sha256="a" * 64)
    with factory.begin() as session:
        first, created = QuoteRepository(session).create(quote)
    assert created
    with factory.begin() as session:
        again, created = QuoteRepository(session).create(quote)
    assert not created
    assert again == first
    with factory.begin() as session, pytest.raises(IdempotencyKeyReusedError) as caught:
        QuoteRepository(session).create(replace(quote, request_sha256="b" * 64))
    assert caught.value.number == first.number
    assert len(stored(engine)) == 1


def run_together(work: Callable[[], QuoteRecord]) -> list[QuoteRecord]:
    """Run ``work`` in THREADS threads released at once; re-raise the first failure."""
    barrier = threading.Barrier(THREADS)
    results: list[QuoteRecord] = []
    failures: list[BaseException] = []
    lock = threading.Lock()

    def run() -> None:
        try:
            barrier.wait(timeout=30)
            result = work()
            with lock:
                results.append(result)
        except BaseException as exc:  # collected and re-raised in the test's thread
            with lock:
                failures.append(exc)

    threads = [threading.Thread(target=run) for _ in range(THREADS)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join(timeout=120)
    assert not any(t.is_alive() for t in threads), "a thread hung"
    if failures:
        raise failures[0]
    return results


@pytest.mark.postgres
def test_concurrent_creation_numbers_without_gaps_or_duplicates(pg_engine: Engine) -> None:
    key = sales_key(pg_engine)
    factory = sessionmaker(pg_engine)
    with factory.begin() as session:  # some quotes exist already: the counter row is there
        QuoteRepository(session).create(new_quote(key))

    def work() -> QuoteRecord:
        with factory.begin() as session:
            record, created = QuoteRepository(session).create(new_quote(key))
            assert created
            return record

    results = run_together(work)
    numbers = [r.number for r in results]
    assert len(set(numbers)) == THREADS
    rows = stored(pg_engine)
    assert len(rows) == THREADS + 1
    assert sorted(s for _, _, s in rows) == list(range(1, THREADS + 2))
    assert {n for n, _, _ in rows} == {f"Q-2026-{s:05d}" for s in range(1, THREADS + 2)}


@pytest.mark.postgres
def test_concurrent_first_quotes_of_a_year(pg_engine: Engine) -> None:
    """No counter row yet: every thread may try to create it; one wins, none fails."""
    key = sales_key(pg_engine)
    factory = sessionmaker(pg_engine)

    def work() -> QuoteRecord:
        with factory.begin() as session:
            record, _ = QuoteRepository(session).create(
                new_quote(key, created_at=NOW + timedelta(days=400))
            )
            return record

    results = run_together(work)
    assert sorted(r.sequence for r in results) == list(range(1, THREADS + 1))
    assert all(r.number.startswith("Q-2027-") for r in results)


@pytest.mark.postgres
def test_concurrent_retries_with_one_idempotency_key_make_one_quote(pg_engine: Engine) -> None:
    key = sales_key(pg_engine)
    factory = sessionmaker(pg_engine)
    quote = new_quote(key, idempotency_key="erp-order-4711", request_sha256="c" * 64)

    def work() -> QuoteRecord:
        with factory.begin() as session:
            record, _ = QuoteRepository(session).create(quote)
            return record

    results = run_together(work)
    assert {r.number for r in results} == {"Q-2026-00001"}
    assert len(stored(pg_engine)) == 1
    with Session(pg_engine) as session:
        # the losers' counter increments were rolled back with their savepoints
        assert session.scalar(select(QuoteCounterRow.last_number)) == 1
        assert session.scalar(select(func.count()).select_from(QuoteRow)) == 1
    with factory.begin() as session:
        record, _ = QuoteRepository(session).create(new_quote(key))
    assert record.number == "Q-2026-00002"
