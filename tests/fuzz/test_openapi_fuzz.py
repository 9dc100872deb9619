"""A bounded fuzz run of every operation in the app's OpenAPI schema (schemathesis).

Schemathesis generates requests from ``/openapi.json`` — valid ones and ones that
break the schema on purpose — and checks every answer: never a 5xx
(``not_a_server_error``), and a body that matches the documented schema of its
status code (``response_schema_conformance``).

The requests go through Starlette's test client to the app on the seeded database
of ``tests/conftest.py`` (SQLite and PostgreSQL). Each pytest test is one operation
under one key and runs in the test's rolled-back transaction, so catalogue imports,
deletions and quotes made by the fuzzer never reach the shared seeded database or
the next operation's test.

Three runs: anonymous (every operation), an ``admin`` key (catalogue management and
prices) and a ``sales`` key (quotes and prices). The catalogue import and the price
import get payloads built from the starter catalogue's own files, broken at random,
so that the CSV parsers are reached rather than stopped at the first byte.

The run is deterministic (``derandomize``), so a failure in CI reproduces locally.
``FUZZ_MAX_EXAMPLES`` raises the number of generated requests per operation for a
longer exploratory run; ``FUZZ_RANDOM=1`` draws new ones each run.
"""

from __future__ import annotations

import io
import json
import os
import zipfile
from collections.abc import Iterator
from dataclasses import dataclass
from datetime import timedelta
from typing import Any

import pytest
import schemathesis
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, settings
from hypothesis import strategies as st
from schemathesis.checks import not_a_server_error
from schemathesis.specs.openapi.checks import response_schema_conformance
from sqlalchemy import Connection, Engine
from sqlalchemy.orm import Session, sessionmaker
from tests import worked_example
from tests.api._sales_fixtures import create_keys, load_example_prices

from actuator_selection.app import create_app
from actuator_selection.config import SEED_DIR, Settings

MAX_EXAMPLES = int(os.environ.get("FUZZ_MAX_EXAMPLES", "15"))
RANDOM = os.environ.get("FUZZ_RANDOM") == "1"
CHECKS = [not_a_server_error, response_schema_conformance]
CATALOGUE_FILES = sorted(p.name for p in SEED_DIR.glob("*.csv") if p.name != "example_prices.csv")

FUZZ_SETTINGS = settings(
    max_examples=MAX_EXAMPLES,
    # Generous: one example is one request, some rank the whole catalogue; a bound
    # so that a pathological request fails the run instead of stalling it.
    deadline=timedelta(seconds=5),
    derandomize=not RANDOM,
    database=None,  # no .hypothesis/ example store: the run depends on the code alone
    # Generating request bodies from the big schemas is slow by Hypothesis's measure,
    # and the function-scoped fixture is meant: one transaction for an operation's run.
    suppress_health_check=[
        HealthCheck.too_slow,
        HealthCheck.filter_too_much,
        HealthCheck.data_too_large,
        HealthCheck.function_scoped_fixture,
    ],
)


def _openapi_document() -> dict[str, Any]:
    """The app's OpenAPI document; the app is only built, its database never opened."""
    app = create_app(Settings(database_url="sqlite://"))
    try:
        return app.openapi()
    finally:
        app.state.engine.dispose()


def _mutated_csv(draw: st.DrawFn, text: str) -> str:
    """``text`` as it is, or with a line replaced, dropped or doubled, a cell replaced, or cut."""
    lines = text.splitlines()
    index = draw(st.integers(min_value=0, max_value=len(lines) - 1))
    how = draw(st.sampled_from(["keep", "cell", "line", "drop", "double", "truncate"]))
    if how == "keep":
        pass
    elif how == "cell":
        cells = lines[index].split(",")
        cell = draw(st.integers(min_value=0, max_value=len(cells) - 1))
        cells[cell] = draw(st.text(max_size=20))
        lines[index] = ",".join(cells)
    elif how == "line":
        lines[index] = draw(st.text(max_size=60))
    elif how == "drop":
        del lines[index]
    elif how == "double":
        lines.insert(index, lines[index])
    else:
        lines = lines[:index]
    return "\n".join(lines) + "\n"


@st.composite
def catalogue_zips(draw: st.DrawFn) -> bytes:
    """A zip of the starter catalogue's files, perhaps some left out, one perhaps broken."""
    every = frozenset(CATALOGUE_FILES)
    names = draw(st.one_of(st.just(every), st.frozensets(st.sampled_from(CATALOGUE_FILES))))
    broken = draw(st.sampled_from(sorted(names))) if names else None
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        for name in sorted(names):
            text = (SEED_DIR / name).read_text(encoding="utf-8")
            archive.writestr(name, _mutated_csv(draw, text) if name == broken else text)
    return buffer.getvalue()


@st.composite
def price_csvs(draw: st.DrawFn) -> bytes:
    """The example price list with one line or cell broken."""
    text = (SEED_DIR / "example_prices.csv").read_text(encoding="utf-8")
    return _mutated_csv(draw, text).encode()


@st.composite
def job_cases(draw: st.DrawFn) -> bytes:
    """A batch job's body (POST /batch-jobs): the worked example as JSON lines, a few
    times, one line perhaps broken."""
    line = json.dumps(worked_example.request()).encode()
    lines = [line] * draw(st.integers(min_value=1, max_value=3))
    if draw(st.booleans()):
        k = draw(st.integers(min_value=0, max_value=len(lines) - 1))
        lines[k] = draw(st.binary(max_size=40))
    return b"\n".join(lines) + b"\n"


schemathesis.openapi.media_type("application/zip", st.one_of(st.binary(), catalogue_zips()))
schemathesis.openapi.media_type("application/x-ndjson", st.one_of(st.binary(), job_cases()))
schemathesis.openapi.media_type("text/csv", st.one_of(st.binary(), price_csvs()))
# An IDTA 02021 record (POST /selections/from-aas): bytes, zips among them.
schemathesis.openapi.media_type(
    "application/asset-administration-shell-package", st.one_of(st.binary(), catalogue_zips())
)

SCHEMA = schemathesis.openapi.from_dict(_openapi_document())

FuzzCase = schemathesis.Case[Any]

ANONYMOUS = SCHEMA
ADMIN = SCHEMA.include(tag=["catalogue management", "prices"])
SALES = SCHEMA.include(tag=["quotes", "prices"])


@dataclass(frozen=True)
class FuzzApi:
    """The app on the test's rolled-back connection, and an API key per role."""

    client: TestClient
    keys: dict[str, str]

    def check(self, case: FuzzCase, role: str | None) -> None:
        """Send ``case`` (with ``role``'s key) and run the checks on the answer."""
        kwargs = case.as_transport_kwargs(base_url="http://testserver")
        # The schema has no cookie parameters; httpx deprecates per-request cookies.
        assert not kwargs.pop("cookies", None)
        if "data" in kwargs:  # the serialised body; httpx names raw bodies `content`
            kwargs["content"] = kwargs.pop("data")
        if role is not None:
            kwargs["headers"] = {**kwargs.get("headers", {}), "Authorization": self.bearer(role)}
        response = self.client.request(**kwargs)
        case.validate_response(response, checks=CHECKS)

    def bearer(self, role: str) -> str:
        return f"Bearer {self.keys[role]}"


@pytest.fixture
def fuzz_api(seeded_engine: Engine, connection: Connection) -> Iterator[FuzzApi]:
    """The app on the seeded database, inside the test's rolled-back transaction."""
    with Session(bind=connection, join_transaction_mode="create_savepoint") as session:
        keys, _ = create_keys(session)
        load_example_prices(session)  # so that quotes can name a price list
        session.commit()
    app = create_app(Settings(database_url=seeded_engine.url.render_as_string(hide_password=False)))
    app.state.session_factory = sessionmaker(
        bind=connection, join_transaction_mode="create_savepoint", expire_on_commit=False
    )
    with TestClient(app, raise_server_exceptions=False) as client:
        yield FuzzApi(client=client, keys=keys)


@ANONYMOUS.parametrize()
@FUZZ_SETTINGS
def test_anonymous(case: FuzzCase, fuzz_api: FuzzApi) -> None:
    """Every operation without a key: open ones answer, the others refuse with 401."""
    fuzz_api.check(case, None)


@ADMIN.parametrize()
@FUZZ_SETTINGS
def test_admin(case: FuzzCase, fuzz_api: FuzzApi) -> None:
    """Catalogue management and prices with an admin key."""
    fuzz_api.check(case, "admin")


@SALES.parametrize()
@FUZZ_SETTINGS
def test_sales(case: FuzzCase, fuzz_api: FuzzApi) -> None:
    """Quotes and prices with a sales key."""
    fuzz_api.check(case, "sales")
