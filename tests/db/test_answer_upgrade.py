"""Stored answers of the historical shapes are upgraded once (migration 0011), then read
strictly, on SQLite and PostgreSQL.

The old answers are the ones the old code wrote (``data/selection_answers_v0.json``: the
answer before the lean one, commit 2cc9373^; ``…_v1.json``: the lean answer as first
stored, commit 2cc9373; ``data/generate_old_answers.py`` made them). They are stored
in a database at revision 0010 as those versions stored them, beside an answer of today
and a quote made from an old one; after the upgrade every answer is today's
``SelectionOut``, with the same figures, and the quotes render.
"""

from __future__ import annotations

import gzip
import json
from collections.abc import Callable, Iterator
from datetime import UTC, date, datetime, timedelta
from decimal import Decimal
from pathlib import Path
from typing import Any

import orjson
import pydantic
import pytest
from alembic import command
from fastapi.testclient import TestClient
from sqlalchemy import JSON, Date, DateTime, Engine, Numeric, column, insert, table, text
from sqlalchemy.orm import Session
from tests import worked_example
from tests.api._sales_fixtures import EXAMPLE_PRICE_LIST, create_keys, load_example_prices

from actuator_selection.app import create_app
from actuator_selection.config import SEED_DIR, Settings
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import alembic_config
from actuator_selection.db.seed import load_seed
from actuator_selection.schemas.quotes import StoredSelection
from actuator_selection.schemas.selections import SelectionOut, SelectionRequest
from actuator_selection.services.catalogue import CatalogueCache
from actuator_selection.services.presenters.selection import ANSWER_VERSION
from actuator_selection.services.selections import (
    cursor,
    read_ranking,
    size_selection,
    store_selections,
    stored_answer_json,
)

DATA = Path(__file__).parent / "data"
OLD: dict[int, dict[str, Any]] = {
    version: json.loads((DATA / f"selection_answers_v{version}.json").read_text("utf-8"))["cases"]
    for version in (0, 1)
}
"""Per version, per case: the request and the answer as the old code stored them."""

SELECTIONS = table(
    "selections",
    column("id"),
    column("created_at", DateTime(timezone=True)),
    column("catalogue_version"),
    column("request", JSON),
    column("answer_gzip"),
)
"""The selections table at revision 0010."""

ADDED = {
    "brake": False,
    "drive": False,
    "output_load": None,
    "output_bearing": "not checked: no output_load given",
    "output_bearing_code": "output_bearing.not_checked",
    "binding": None,
}
"""What the upgrade gives an old answer's fields added since (what they meant then)."""


def _stored_as_written(version: int, answer: dict[str, Any]) -> bytes:
    """The answer's gzip as its version's code stored it: version 0 as a JSON column that
    0005 compressed, version 1 as pydantic wrote it (compact either way)."""
    text_ = json.dumps(answer, ensure_ascii=False, separators=(",", ":"))
    return gzip.compress(text_.encode(), mtime=0)


def _quote_row(selection_id: str, api_key_id: int, now: datetime) -> dict[str, Any]:
    """A quote as stored before the upgrade, made from the old selection ``selection_id``."""
    return {
        "number": "Q-2025-00001", "year": 2025, "sequence": 1, "status": "sent",
        "created_at": now, "status_changed_at": now, "valid_until": date(2099, 12, 31),
        "api_key_id": api_key_id, "idempotency_key": None, "request_sha256": "0" * 64,
        "selection_id": selection_id, "selection_catalogue_version": 1, "catalogue_version": 1,
        "customer_name": "Muster GmbH", "customer_address": None, "customer_reference": None,
        "notes": None, "actuator_model": "FHA-25C-50-L", "verdict": "unconfirmed",
        "verdict_reasons": ["continuous_duty: no data"],
        "actuator_snapshot": {"model": "FHA-25C-50-L"},
        "price_list_name": EXAMPLE_PRICE_LIST, "price_list_is_example": True,
        "price_date": date(2026, 11, 20), "currency": "EUR", "subtotal": Decimal("2950.00"),
        "discount_percent": Decimal("0.00"), "discount_amount": Decimal("0.00"),
        "total": Decimal("2950.00"),
    }  # fmt: skip


_QUOTE_TYPES: dict[str, Any] = {
    "verdict_reasons": JSON(),
    "actuator_snapshot": JSON(),
    "created_at": DateTime(timezone=True),
    "status_changed_at": DateTime(timezone=True),
    "valid_until": Date(),
    "price_date": Date(),
    **{name: Numeric(14, 2) for name in ("subtotal", "discount_amount", "total")},
    "discount_percent": Numeric(5, 2),
}


@pytest.fixture
def upgraded(backend: str, new_database: Callable[[str], str]) -> Iterator[tuple[Engine, bytes]]:
    """A database at 0010 holding old answers of each version, today's answer (id
    ``today``) and a quote from an old answer, upgraded to head; and today's answer."""
    now = datetime(2026, 11, 20, tzinfo=UTC)
    # Today's answer comes from a database of today's schema: the catalogue's tables at
    # 0010 lack the columns added since, which the ORM reads.
    today_url = new_database(backend)
    command.upgrade(alembic_config(url=today_url), "head")
    today_engine = make_engine(today_url)
    try:
        with make_session_factory(today_engine).begin() as session:
            load_seed(session, SEED_DIR)
            request = SelectionRequest.model_validate(worked_example.request())
            catalogue = CatalogueCache().snapshot(session)
            today = size_selection(
                request, request.to_core(), catalogue.actuators_of(None), catalogue, now
            )
    finally:
        today_engine.dispose()
    url = new_database(backend)
    config = alembic_config(url=url)
    command.upgrade(config, "0010")
    engine = make_engine(url)
    try:
        with engine.begin() as conn:
            for version, cases in OLD.items():
                for case in cases.values():
                    answer = case["answer"]
                    conn.execute(
                        insert(SELECTIONS).values(
                            id=answer["id"],
                            created_at=now,
                            catalogue_version=answer["catalogue_version"],
                            request=case["request"],
                            answer_gzip=_stored_as_written(version, answer),
                        )
                    )
            conn.execute(
                insert(SELECTIONS).values(
                    id="today",
                    created_at=now,
                    catalogue_version=catalogue.version,
                    request=today.request,
                    answer_gzip=today.answer_gzip,
                )
            )
            api_keys = table("api_keys", column("id"), column("prefix"), column("key_sha256"),
                             column("name"), column("role"), column("created_at"))  # fmt: skip
            key_id = conn.execute(
                insert(api_keys)
                .values(prefix="p", key_sha256="0" * 64, name="k", role="sales", created_at=now)
                .returning(api_keys.c.id)
            ).scalar_one()
            quote = _quote_row(OLD[0]["worked_example"]["answer"]["id"], key_id, now)
            quotes = table("quotes", *(column(k, _QUOTE_TYPES.get(k)) for k in quote))
            conn.execute(insert(quotes).values(**quote))
        command.upgrade(config, "head")
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
            assert CatalogueCache().snapshot(session).version == catalogue.version
        yield engine, today.answer_gzip
    finally:
        engine.dispose()


def _stored(engine: Engine, selection_id: str) -> tuple[bytes, int]:
    with engine.connect() as conn:
        row = conn.execute(
            text("SELECT answer_gzip, answer_version FROM selections WHERE id = :id"),
            {"id": selection_id},
        ).one()
    return bytes(row[0]), int(row[1])


def _answer(engine: Engine, selection_id: str) -> dict[str, Any]:
    stored, version = _stored(engine, selection_id)
    assert version == ANSWER_VERSION
    answer: dict[str, Any] = orjson.loads(gzip.decompress(stored))
    return answer


def _same_case(answer: dict[str, Any]) -> dict[str, Any]:
    """The answer less what differs between two runs of one case (its id and time)."""
    return {k: v for k, v in answer.items() if k not in ("id", "created_at")}


def test_old_answers_are_upgraded_to_todays_shape(upgraded: tuple[Engine, bytes]) -> None:
    engine, today = upgraded
    assert _stored(engine, "today") == (today, ANSWER_VERSION)  # byte for byte
    for name in OLD[1]:
        v0, v1 = (OLD[version][name]["answer"] for version in (0, 1))
        up0, up1 = _answer(engine, v0["id"]), _answer(engine, v1["id"])
        for up in (up0, up1):
            assert set(up) == set(SelectionOut.model_fields)
            parsed = SelectionOut.model_validate(up)
            assert parsed.model_dump(mode="json", exclude_unset=True) == up
        # The lean answer keeps every figure; the added fields say what they meant then.
        kept = [k for k in v1 if k != "load"]
        assert {k: up1[k] for k in kept} == {k: v1[k] for k in kept}
        assert up1["load"] == {**v1["load"], "gravity_torque_nm": 0.0, "efficiency": 1.0}
        assert {k: up1[k] for k in ADDED} == ADDED
        n_2 = v1["load"]["speed_rpm"]
        assert [(s["start_rpm"], s["end_rpm"]) for s in up1["segments"]] == [
            (0.0, n_2), (n_2, n_2), (n_2, 0.0), (0.0, 0.0)
        ]  # fmt: skip
        t_0 = sum(s["duration_s"] for s in up1["segments"])
        assert t_0 == pytest.approx(v1["cycle_time_s"])
        # The answer before the lean one becomes what the lean code answered to its case.
        assert _same_case(up0) == _same_case(up1)
        # And both read back to the same answer.
        read0, read1 = StoredSelection.model_validate(up0), StoredSelection.model_validate(up1)
        run = {"id", "created_at"}
        assert read0.model_dump(exclude=run) == read1.model_dump(exclude=run)
        full = {c["model"]: c for c in v0["candidates"]}
        for candidate in read0.candidates:
            old_checks = full[candidate.model]["checks"]
            assert [
                (c.name, c.status, c.value, c.limit, c.unit, c.reference) for c in candidate.checks
            ] == [
                (c["name"], c["status"], c["value"], c["limit"], c["unit"], c["reference"])
                for c in old_checks
            ]
            assert len(candidate.reasons) == len(full[candidate.model]["reasons"])


def test_old_shapes_are_no_longer_read() -> None:
    """The reader is strict: an answer of version 0 or 1 is refused, not read tolerantly."""
    for version in (0, 1):
        for case in OLD[version].values():
            with pytest.raises(pydantic.ValidationError, match="today's shape"):
                StoredSelection.model_validate(case["answer"])


def test_quotes_from_old_selections_render(upgraded: tuple[Engine, bytes]) -> None:
    """A quote made before the upgrade from an old selection renders (HTML and PDF), and
    new quotes are made from both old selections and render."""
    engine, _ = upgraded
    with Session(engine) as session:
        keys, _ids = create_keys(session)
        load_example_prices(session)
        session.commit()
    url = engine.url.render_as_string(hide_password=False)
    app = create_app(Settings(database_url=url))
    auth = {"Authorization": f"Bearer {keys['sales']}"}
    numbers = ["Q-2025-00001"]
    try:
        with TestClient(app) as client:
            for version in (0, 1):
                answer = OLD[version]["worked_example"]["answer"]
                body = {
                    "selection_id": answer["id"],
                    "customer": {"name": "Muster GmbH"},
                    "actuator": {"model": "FHA-25C-50-L", "quantity": 1},
                    "price_list": EXAMPLE_PRICE_LIST,
                    "valid_until": (datetime.now(UTC).date() + timedelta(days=30)).isoformat(),
                }
                made = client.post("/api/v1/quotes", json=body, headers=auth)
                assert made.status_code == 201, made.text
                assert made.json()["verdict"] == "unconfirmed"
                numbers.append(made.json()["number"])
            for number in numbers:
                for lang in ("en", "de"):
                    headers = {**auth, "Accept-Language": lang}
                    html = client.get(f"/api/v1/quotes/{number}/document", headers=headers)
                    assert html.status_code == 200, html.text
                    assert "FHA-25C-50-L" in html.text
                    pdf = client.get(f"/api/v1/quotes/{number}/document.pdf", headers=headers)
                    assert pdf.status_code == 200, pdf.text
                    assert pdf.content.startswith(b"%PDF")
    finally:
        app.state.engine.dispose()


def _whole_answer_of_version_2(session: Session, copies: int) -> dict[str, Any]:
    """A version-2 answer (every candidate listed) of ``copies`` × the starter catalogue's
    ranking, the copies renamed (``~k``): an answer longer than version 3 lists."""
    request = SelectionRequest.model_validate(worked_example.request())
    catalogue = CatalogueCache().snapshot(session)
    sized = size_selection(
        request, request.to_core(), catalogue.actuators_of(None), catalogue, datetime.now(UTC),
        top=1000,
    )  # fmt: skip
    answer: dict[str, Any] = orjson.loads(sized.answer)
    for key in ("total_candidates", "verdict_counts", "next_cursor"):
        del answer[key]
    first = answer["candidates"]
    answer["candidates"] = [
        {**c, "model": f"{c['model']}~{k}", "drive_options": c["drive_options"] if k == 0 else None}
        for k in range(copies)
        for c in first
    ]
    answer["id"] = "whole-v2"
    return answer


def test_a_long_version_2_answer_is_split_and_paged_as_it_was(
    backend: str, new_database: Callable[[str], str]
) -> None:
    url = new_database(backend)
    config = alembic_config(url=url)
    command.upgrade(config, "0017")
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
            old = _whole_answer_of_version_2(session, copies=3)
            session.execute(
                text(
                    "INSERT INTO selections (id, created_at, catalogue_version, request, "
                    "answer_gzip, answer_version) VALUES (:id, :at, 1, :request, :answer, 2)"
                ),
                {
                    "id": old["id"],
                    "at": datetime.now(UTC),
                    "request": json.dumps(worked_example.request()),
                    "answer": gzip.compress(json.dumps(old).encode(), mtime=0),
                },
            )
        total = len(old["candidates"])
        assert total > 100
        command.upgrade(config, "head")
        lean = _answer(engine, old["id"])
        SelectionOut.model_validate(lean)
        assert lean["candidates"] == old["candidates"][:100]
        assert lean["total_candidates"] == total
        counts = dict.fromkeys(("suitable", "unconfirmed", "unsuitable"), 0)
        for c in old["candidates"]:
            counts[c["verdict"]] += 1
        assert lean["verdict_counts"] == counts
        assert lean["next_cursor"] == cursor(old["id"], 100)
        with make_session_factory(engine)() as session:
            ranking = read_ranking(session, old["id"], lean["next_cursor"])
            assert ranking.page(1000)["candidates"] == old["candidates"][100:]
            whole = stored_answer_json(session, old["id"])
            assert whole is not None
            assert whole["candidates"] == old["candidates"]
            # and one stored today, its rest as arrays: the downgrade lists it whole again
            request = SelectionRequest.model_validate(worked_example.request())
            catalogue = CatalogueCache().snapshot(session)
            now = datetime.now(UTC)
            sized = [
                size_selection(request, request.to_core(), catalogue.actuators_of(None),
                               catalogue, now, top=top)
                for top in (5, 1000)
            ]  # fmt: skip
            store_selections(make_session_factory(engine).begin, sized[:1])
        command.downgrade(config, "0017")
        stored, version = _stored(engine, old["id"])
        assert version == 2
        assert orjson.loads(gzip.decompress(stored)) == old
        stored, version = _stored(engine, sized[0].id)
        assert version == 2
        whole = orjson.loads(sized[1].answer)["candidates"]
        listed = orjson.loads(gzip.decompress(stored))["candidates"]
        assert listed[:5] == whole[:5]
        assert listed[5:] == [{**c, "drive_options": None} for c in whole[5:]]
    finally:
        engine.dispose()
