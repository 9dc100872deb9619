"""Price lists: CSV import (atomic, dry run, every problem named), reading, the example list."""

from __future__ import annotations

import argparse
import csv
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from tests.api._sales_fixtures import EXAMPLE_PRICE_LIST, SalesApi, api, sales_api_with

from actuator_selection.cli_keys import register
from actuator_selection.config import SEED_DIR
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.seed import load_seed

__all__ = ["api", "sales_api_with"]

HEADER = (
    "price_list,is_example,item_kind,item_code,description,unit_price,currency,"
    "valid_from,valid_to,source"
)
OTHER = "List 2026,false,actuator,CHA-20A-30,,2000.00,EUR,2026-01-01,,dealer list 2026"
GOOD = [
    "List 2026,false,actuator,FHA-25C-50-L,,3100.00,EUR,2026-01-01,,dealer list 2026",
    "List 2026,false,actuator,CHA-25A-50,,3525.5,EUR,2026-01-01,2026-06-30,dealer list 2026",
    "List 2026,false,actuator,CHA-25A-50,,3600.00,EUR,2026-07-01,,dealer list 2026",
    'List 2026,false,controller,CTRL-X,"Drive X, 5 A",999.99,CHF,2026-01-01,,dealer list 2026',
]


def csv_text(*rows: str, header: str = HEADER) -> bytes:
    return ("\n".join([header, *rows]) + "\n").encode("utf-8")


def upload(api: SalesApi, body: bytes, *, dry_run: bool = False, role: str = "admin") -> Any:
    return api.post(
        "/api/v1/price-lists/import",
        role=role,
        params={"dry_run": str(dry_run).lower()},
        content=body,
        extra={"Content-Type": "text/csv; charset=utf-8"},
    )


def names(api: SalesApi) -> set[str]:
    return {pl["name"] for pl in api.get("/api/v1/price-lists", role="admin").json()}


def test_import_reads_back_exactly(api: SalesApi) -> None:
    response = upload(api, csv_text(*GOOD))
    assert response.status_code == 200, response.text
    assert response.json() == {
        "dry_run": False,
        "price_lists": {"List 2026": {"inserted": 4, "updated": 0, "unchanged": 0, "retired": 0}},
    }
    listed = {pl["name"]: pl for pl in api.get("/api/v1/price-lists").json()}
    assert listed["List 2026"]["item_count"] == 4
    assert listed["List 2026"]["currencies"] == ["CHF", "EUR"]
    assert listed["List 2026"]["is_example"] is False
    detail = api.get("/api/v1/price-lists/List 2026").json()
    prices = {(p["item_code"], p["valid_from"]): p for p in detail["prices"]}
    assert prices[("CHA-25A-50", "2026-01-01")]["unit_price"] == "3525.50"
    assert prices[("CHA-25A-50", "2026-01-01")]["valid_to"] == "2026-06-30"
    assert prices[("CTRL-X", "2026-01-01")] | {"source": None} == {
        "item_kind": "controller",
        "item_code": "CTRL-X",
        "description": "Drive X, 5 A",
        "unit_price": "999.99",
        "currency": "CHF",
        "valid_from": "2026-01-01",
        "valid_to": None,
        "source": None,
    }
    assert api.get("/api/v1/price-lists/Nope").status_code == 404


def test_reimport_updates_removes_and_dry_run_writes_nothing(api: SalesApi) -> None:
    upload(api, csv_text(*GOOD))
    again = upload(api, csv_text(*GOOD)).json()["price_lists"]["List 2026"]
    assert again == {"inserted": 0, "updated": 0, "unchanged": 4, "retired": 0}
    changed = [GOOD[0].replace("3100.00", "3150.00"), GOOD[1], GOOD[2]]
    preview = upload(api, csv_text(*changed), dry_run=True)
    assert preview.status_code == 200
    assert preview.json() == {
        "dry_run": True,
        "price_lists": {"List 2026": {"inserted": 0, "updated": 1, "unchanged": 2, "retired": 1}},
    }
    detail = api.get("/api/v1/price-lists/List 2026").json()["prices"]
    assert len(detail) == 4
    assert "3100.00" in {p["unit_price"] for p in detail}
    done = upload(api, csv_text(*changed)).json()["price_lists"]["List 2026"]
    assert done == {"inserted": 0, "updated": 1, "unchanged": 2, "retired": 1}
    detail = api.get("/api/v1/price-lists/List 2026").json()["prices"]
    assert sorted(p["unit_price"] for p in detail) == ["3150.00", "3525.50", "3600.00"]
    # Other lists are not touched by an import that does not name them.
    example = api.get(f"/api/v1/price-lists/{EXAMPLE_PRICE_LIST}").json()
    with (SEED_DIR / "example_prices.csv").open(encoding="utf-8") as f:
        assert len(example["prices"]) == sum(1 for _ in csv.DictReader(f))


@pytest.mark.parametrize(
    ("row", "column", "rule"),
    [
        (GOOD[0].replace("3100.00", "3100.005"), "unit_price", "2 decimal places"),
        (GOOD[0].replace("3100.00", "-1"), "unit_price", "≥ 0"),
        (GOOD[0].replace("3100.00", "1e3"), "unit_price", "such as 1234.50"),
        (GOOD[0].replace("3100.00", "NaN"), "unit_price", "such as 1234.50"),
        (GOOD[0].replace("3100.00", "cheap"), "unit_price", "decimal"),
        (GOOD[0].replace(",EUR,", ",eur,"), "currency", "ISO 4217"),
        (GOOD[0].replace(",EUR,", ",EURO,"), "currency", "ISO 4217"),
        (GOOD[0].replace("2026-01-01", "01.01.2026"), "valid_from", "YYYY-MM-DD"),
        (GOOD[0].replace(",false,", ",yes,"), "is_example", "true or false"),
        (GOOD[0].replace(",actuator,", ",motor,"), "item_kind", "actuator, controller"),
        (GOOD[0].replace("FHA-25C-50-L", "FHA-99X"), "item_code", "unknown actuator model"),
        (GOOD[0].replace(",,3100.00", ",,"), "unit_price", "required"),
        (GOOD[0].replace("dealer list 2026", ""), "source", "required"),
        (OTHER.replace("2026-01-01,", "2026-01-01,2025-12-31"), "valid_to", "before"),
        (GOOD[0].replace(",,3100", ",,3200").replace("2026-01-01", "2026-03-01"), "valid_from",
         "overlaps"),
        (OTHER.replace("false", "true"), "is_example", "differs"),
        (GOOD[0], "price_list", "duplicates"),
    ],
)  # fmt: skip
def test_one_bad_cell_changes_nothing_and_is_named(
    api: SalesApi, row: str, column: str, rule: str
) -> None:
    before = names(api)
    response = upload(api, csv_text(*GOOD, row))
    assert response.status_code == 422, response.text
    line = len(GOOD) + 2
    errors = response.json()["detail"]
    named = [e for e in errors if e["loc"] == ["body", "prices.csv", line, column]]
    assert named, errors
    assert rule in named[0]["msg"]
    assert (named[0]["file"], named[0]["line"], named[0]["column"]) == ("prices.csv", line, column)
    assert names(api) == before


def test_every_problem_is_reported_at_once(api: SalesApi) -> None:
    rows = [GOOD[0].replace("3100.00", "x"), GOOD[1].replace(",EUR,", ",e,"), *GOOD[2:]]
    errors = upload(api, csv_text(*rows)).json()["detail"]
    assert {(e["line"], e["column"]) for e in errors} == {(2, "unit_price"), (3, "currency")}


def test_bad_header_and_media_type(api: SalesApi) -> None:
    missing = upload(api, csv_text(*GOOD, header=HEADER.replace(",source", "")))
    assert missing.status_code == 422
    assert any(e["column"] == "source" for e in missing.json()["detail"])
    as_json = api.post("/api/v1/price-lists/import", role="admin", json={"rows": []})
    assert as_json.status_code == 415
    not_utf8 = upload(api, HEADER.encode() + b"\n\xff\xfe\n")
    assert not_utf8.status_code == 422
    assert "UTF-8" in not_utf8.json()["detail"][0]["msg"]
    assert upload(api, csv_text(*GOOD), role="sales").status_code == 403


def test_prices_apply_by_date(api: SalesApi) -> None:
    today = api.clock.now().date()
    rows = [
        f"Dated,false,actuator,FHA-25C-50-L,,1000.00,EUR,{today.replace(year=today.year - 1)},"
        f"{today.replace(year=today.year - 1, month=12, day=31)},old",
        f"Dated,false,actuator,FHA-25C-50-L,,5000.00,EUR,{today.replace(year=today.year + 1)},,"
        "future",
    ]
    assert upload(api, csv_text(*rows)).status_code == 200
    selection = api.selection(models=["FHA-25C-50-L"])
    body = api.quote_body(selection["id"], price_list="Dated", controller=None)
    response = api.post("/api/v1/quotes", json=body)
    assert response.status_code == 422
    assert response.json()["detail"][0]["type"] == "no_price"
    current = f"Dated,false,actuator,FHA-25C-50-L,,2000.00,EUR,{today.replace(month=1, day=1)},,now"
    assert upload(api, csv_text(rows[0], current)).status_code == 200
    quote = api.post("/api/v1/quotes", json=body).json()
    assert quote["items"][0]["unit_price"] == "2000.00"
    assert quote["price_list"]["priced_on"] == today.isoformat()


def test_example_price_list_is_marked_as_such() -> None:
    with (SEED_DIR / "example_prices.csv").open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert rows
    assert {r["price_list"] for r in rows} == {EXAMPLE_PRICE_LIST}
    assert {r["is_example"] for r in rows} == {"true"}
    assert {r["source"] for r in rows} == {"example price list, not real prices"}


def test_cli_imports_a_price_list(
    backend: str,
    new_database: Callable[[str], str],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    url = new_database(backend)
    upgrade(url=url)
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            load_seed(session, SEED_DIR)
    finally:
        engine.dispose()

    def run(*argv: str) -> int:
        parser = argparse.ArgumentParser()
        parser.add_argument("--database-url", default=url)
        register(parser.add_subparsers(dest="command", required=True))
        args = parser.parse_args(list(argv))
        status: int = args.run(args)
        return status

    example = str(SEED_DIR / "example_prices.csv")
    assert run("prices", "import", example, "--dry-run") == 0
    assert "would change" in capsys.readouterr().out
    assert run("prices", "import", example) == 0
    out = capsys.readouterr().out
    with (SEED_DIR / "example_prices.csv").open(encoding="utf-8") as f:
        rows = sum(1 for _ in csv.DictReader(f))
    assert f"loaded '{EXAMPLE_PRICE_LIST}': inserted {rows}," in out  # the dry run wrote nothing
    assert run("prices", "import", example) == 0
    assert "inserted 0, updated 0" in capsys.readouterr().out
    bad = tmp_path / "bad.csv"
    bad.write_bytes(csv_text(GOOD[0].replace("3100.00", "-5")))
    assert run("prices", "import", str(bad)) == 1
    err = capsys.readouterr().err
    assert "bad.csv, line 2, column unit_price" in err
    assert "nothing loaded" in err
