"""The quote document prints the manufacturer's document the catalogue values come from,
never the mirror website a value was read on (issue 28, item 11)."""

from __future__ import annotations

from sqlalchemy import Connection, select
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.catalogue.citations import mirror_addresses
from actuator_selection.db.models.sales import QuoteRow

__all__ = ["api", "sales_api_with"]

OLD_SOURCE = (
    "Harmonic Drive AG, Engineering Data for Harmonic Drive Servo Actuators, Table 516.3 "
    "(checked: easymanua.ls/harmonic-drive/cha/manual?p=36; CHA 8/2018 V03 agrees)"
)
"""A source as stored before the citation and the public copy were split."""


def _quote(api: SalesApi) -> str:
    selection = api.selection(models=["FHA-25C-50-L"])
    created = api.post("/api/v1/quotes", json=api.quote_body(selection["id"]))
    assert created.status_code == 201, created.text
    number: str = created.json()["number"]
    return number


def test_the_document_prints_the_citation(api: SalesApi) -> None:
    number = _quote(api)
    document = api.get(f"/api/v1/quotes/{number}/document")
    assert document.status_code == 200
    assert "Engineering Data for Harmonic Drive Servo Actuators, Table 516.3" in document.text


def test_a_quote_stored_with_a_mirror_address_prints_the_document_only(
    api: SalesApi, connection: Connection
) -> None:
    number = _quote(api)
    with Session(bind=connection, join_transaction_mode="create_savepoint") as session:
        for row in session.scalars(select(QuoteRow)):
            row.actuator_snapshot = {**row.actuator_snapshot, "source": OLD_SOURCE}
        session.commit()
    document = api.get(f"/api/v1/quotes/{number}/document")
    assert document.status_code == 200
    text = document.text
    assert "Table 516.3 (CHA 8/2018 V03 agrees)" in text
    assert "easymanua" not in text
    assert "checked:" not in text
    assert not mirror_addresses(OLD_SOURCE.split("Table 516.3")[0])  # the citation itself
