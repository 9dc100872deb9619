"""Quotes over HTTP: from a stored selection to figures, numbers, idempotency, status, document."""

from __future__ import annotations

import json
import re
from datetime import UTC, datetime
from decimal import Decimal
from typing import Any, cast

import pytest
from sqlalchemy import Connection
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import (
    EXAMPLE_PRICE_LIST,
    SalesApi,
    api,
    sales_api_with,
    today_plus,
)

from actuator_selection.db.sales import ApiKeyRepository
from actuator_selection.http.static import PLOTLY_URL

__all__ = ["api", "sales_api_with"]

NUMBER = re.compile(r"Q-(\d{4})-(\d{5})")
QUANTITY = ["body", "actuator", "quantity"]


def create(api: SalesApi, body: dict[str, Any], key: str | None = None, role: str = "sales") -> Any:
    extra = {"Idempotency-Key": key} if key is not None else None
    return api.post("/api/v1/quotes", role=role, extra=extra, json=body)


def sequence(number: str) -> int:
    match = NUMBER.fullmatch(number)
    assert match, number
    return int(match.group(2))


@pytest.fixture
def selection_id(api: SalesApi) -> str:
    return str(api.selection(models=["FHA-25C-50-L", "FHA-8C-30"])["id"])


def test_quote_of_the_worked_example(api: SalesApi, selection_id: str) -> None:
    response = create(api, api.quote_body(selection_id))
    assert response.status_code == 201, response.text
    quote = response.json()
    year = api.clock.now().year
    assert NUMBER.fullmatch(quote["number"])
    assert quote["number"].startswith(f"Q-{year}-")
    assert response.headers["location"] == f"/api/v1/quotes/{quote['number']}"
    assert (quote["status"], quote["allowed_transitions"]) == ("draft", ["sent"])
    # Example prices: FHA-25C-50-L 2950.00 EUR (from 2026-01-01), SINAMICS S120 1840.00 EUR.
    assert [(i["kind"], i["item_code"], i["quantity"], i["unit_price"], i["line_total"])
            for i in quote["items"]] == [
        ("actuator", "FHA-25C-50-L", 2, "2950.00", "5900.00"),
        ("controller", "CTRL-SINAMICS-S120", 2, "1840.00", "3680.00"),
    ]  # fmt: skip
    assert quote["items"][1]["description"] == "Servo controller SINAMICS S120, 400 V"
    # 9580.00 × 7.5 % = 718.50; money is exact decimal text, never a float.
    assert (quote["subtotal"], quote["discount_percent"]) == ("9580.00", "7.50")
    assert (quote["discount_amount"], quote["total"]) == ("718.50", "8861.50")
    assert quote["currency"] == "EUR"
    assert quote["price_list"]["name"] == EXAMPLE_PRICE_LIST
    assert quote["price_list"]["is_example"] is True
    # The chapter's example has no continuous-duty data: quotable, flagged.
    assert (quote["verdict"], quote["unconfirmed"]) == ("unconfirmed", True)
    assert any("continuous" in r.lower() for r in quote["verdict_reasons"])
    assert quote["selection_id"] == selection_id
    assert quote["document_url"] == f"/api/v1/quotes/{quote['number']}/document"
    fetched = api.get(f"/api/v1/quotes/{quote['number']}")
    assert fetched.status_code == 200
    assert fetched.json() == quote


def test_totals_follow_the_rounding_rule(api: SalesApi, selection_id: str) -> None:
    body = api.quote_body(
        selection_id,
        actuator={"model": "FHA-25C-50-L", "quantity": 3},
        controller=None,
        discount_percent="33.33",
    )
    quote = create(api, body).json()
    # 3 × 2950.00 = 8850.00; 8850.00 × 33.33 % = 2949.705 → 2949.71 (half up).
    assert (quote["subtotal"], quote["discount_amount"], quote["total"]) == (
        "8850.00",
        "2949.71",
        "5900.29",
    )
    assert Decimal(quote["subtotal"]) - Decimal(quote["discount_amount"]) == Decimal(quote["total"])


@pytest.mark.parametrize(
    ("change", "loc"),
    [
        ({"discount_percent": 7.5}, ["body", "discount_percent"]),
        ({"discount_percent": "100.01"}, ["body", "discount_percent"]),
        ({"discount_percent": "-1"}, ["body", "discount_percent"]),
        ({"discount_percent": "1.005"}, ["body", "discount_percent"]),
        ({"discount_percent": "NaN"}, ["body", "discount_percent"]),
        ({"actuator": {"model": "FHA-25C-50-L", "quantity": 0}}, ["body", "actuator", "quantity"]),
        (
            {"actuator": {"model": "FHA-25C-50-L", "quantity": 1.5}},
            ["body", "actuator", "quantity"],
        ),
        ({"customer": {"name": ""}}, ["body", "customer", "name"]),
        ({"customer": {"name": "x", "phone": "1"}}, ["body", "customer", "phone"]),
        ({"currency": "eur"}, ["body", "currency"]),
        ({"valid_until": "2020-01-01"}, ["body", "valid_until"]),
        ({"valid_until": "someday"}, ["body", "valid_until"]),
        ({"selection_id": "no-such-selection"}, ["body", "selection_id"]),
        ({"price_list": "No such list"}, ["body", "price_list"]),
        ({"actuator": {"model": "CHA-25A-50"}}, ["body", "actuator", "model"]),
        (
            {"controller": {"type_name": "X", "item_code": "CTRL-NONE", "quantity": 1}},
            ["body", "controller", "item_code"],
        ),
        ({"currency": "USD"}, ["body", "actuator", "model"]),
    ],
)
def test_bad_input_is_422_naming_the_field_and_writes_nothing(
    api: SalesApi, selection_id: str, change: dict[str, Any], loc: list[str]
) -> None:
    before = api.get("/api/v1/quotes").json()["total"]
    response = create(api, api.quote_body(selection_id, **change))
    assert response.status_code == 422, response.text
    assert loc in [e["loc"] for e in response.json()["detail"]]
    assert api.get("/api/v1/quotes").json()["total"] == before


@pytest.mark.parametrize(
    ("change", "code", "german"),
    [
        ({"selection_id": "no-such-selection"}, "unknown_selection",
         "keine gespeicherte Auswahl 'no-such-selection'"),
        ({"price_list": "No such list"}, "unknown_price_list", "keine Preisliste 'No such list'"),
        ({"actuator": {"model": "CHA-25A-50"}}, "not_a_candidate",
         "'CHA-25A-50' ist kein Kandidat der Auswahl "),
        ({"currency": "USD"}, "currency_mismatch",
         "FHA-25C-50-L hat Preise in 'EUR', nicht in USD"),
    ],
)  # fmt: skip
def test_a_refused_quote_is_worded_in_the_requests_language(
    api: SalesApi, selection_id: str, change: dict[str, Any], code: str, german: str
) -> None:
    """The use case's rule by code, with the same params in English and German; the
    message in the language asked for."""
    body = api.quote_body(selection_id, **change)
    answers = {
        language: api.post("/api/v1/quotes", json=body, extra={"Accept-Language": language})
        for language in ("en", "de")
    }
    (english,), (in_german,) = (answers[x].json()["detail"] for x in ("en", "de"))
    assert answers["de"].headers["content-language"] == "de"
    assert (english["code"], in_german["code"]) == (code, code)
    assert english["params"] == in_german["params"]
    assert english["type"] == in_german["type"]
    assert in_german["msg"].startswith(german), in_german["msg"]
    assert english["msg"] != in_german["msg"]


def test_unsuitable_actuator_is_refused_with_its_reasons(api: SalesApi, selection_id: str) -> None:
    body = api.quote_body(selection_id, actuator={"model": "FHA-8C-30", "quantity": 1})
    response = create(api, body)
    assert response.status_code == 422
    (error,) = response.json()["detail"]
    assert error["loc"] == ["body", "actuator", "model"]
    assert error["type"] == "unsuitable"
    assert "T_max" in error["msg"] or "torque" in error["msg"]


def test_suitable_actuator_carries_no_flag(api: SalesApi) -> None:
    selection = api.selection()
    suitable = [c["model"] for c in selection["candidates"] if c["verdict"] == "suitable"]
    assert suitable, "the worked example has suitable actuators in the starter catalogue"
    body = api.quote_body(
        selection["id"], actuator={"model": suitable[0], "quantity": 1}, controller=None
    )
    quote = create(api, body).json()
    assert (quote["verdict"], quote["unconfirmed"], quote["verdict_reasons"]) == (
        "suitable",
        False,
        [],
    )


def test_currencies_must_agree(api: SalesApi, selection_id: str) -> None:
    prices = (
        "price_list,is_example,item_kind,item_code,description,unit_price,currency,"
        "valid_from,valid_to,source\n"
        "Two currencies,false,actuator,FHA-25C-50-L,,1000.00,EUR,2020-01-01,,test\n"
        "Two currencies,false,actuator,FHA-25C-50-L,,1100.00,USD,2020-01-01,,test\n"
        "Two currencies,false,controller,C-USD,,500.00,USD,2020-01-01,,test\n"
    )
    imported = api.post(
        "/api/v1/price-lists/import",
        role="admin",
        content=prices.encode(),
        extra={"Content-Type": "text/csv"},
    )
    assert imported.status_code == 200, imported.text
    controller = {"type_name": "USD drive", "item_code": "C-USD", "quantity": 1}
    undecided = create(api, api.quote_body(selection_id, price_list="Two currencies"))
    assert undecided.status_code == 422
    assert undecided.json()["detail"][0]["loc"] == ["body", "currency"]
    mixed = create(
        api,
        api.quote_body(
            selection_id, price_list="Two currencies", currency="EUR", controller=controller
        ),
    )
    assert mixed.status_code == 422
    assert mixed.json()["detail"][0]["loc"] == ["body", "controller", "item_code"]
    assert "USD" in mixed.json()["detail"][0]["msg"]
    in_usd = create(
        api,
        api.quote_body(
            selection_id, price_list="Two currencies", currency="USD", controller=controller
        ),
    )
    assert in_usd.status_code == 201, in_usd.text
    assert (in_usd.json()["currency"], in_usd.json()["subtotal"]) == ("USD", "2700.00")
    assert in_usd.json()["price_list"]["is_example"] is False


def test_idempotency_key_returns_the_first_quote(api: SalesApi, selection_id: str) -> None:
    body = api.quote_body(selection_id)
    first = create(api, body, key="erp-order-4711")
    assert first.status_code == 201
    assert "idempotent-replayed" not in first.headers
    again = create(api, body, key="erp-order-4711")
    assert again.status_code == 201
    assert again.headers["idempotent-replayed"] == "true"
    assert again.json() == first.json()
    assert api.get("/api/v1/quotes").json()["total"] == 1
    # A different body under the same key: refused, nothing new.
    changed = create(api, {**body, "discount_percent": "10"}, key="erp-order-4711")
    assert changed.status_code == 422
    (error,) = changed.json()["detail"]
    assert error["loc"] == ["header", "Idempotency-Key"]
    assert first.json()["number"] in error["msg"]
    # Without a key, every request is a new quote; a new key is a new quote.
    assert create(api, body).json()["number"] != first.json()["number"]
    assert create(api, body, key="erp-order-4712").json()["number"] != first.json()["number"]
    assert api.get("/api/v1/quotes").json()["total"] == 3


def test_idempotency_keys_belong_to_their_api_key(
    api: SalesApi, selection_id: str, connection: Connection
) -> None:
    with Session(bind=connection, join_transaction_mode="create_savepoint") as session:
        _, other = ApiKeyRepository(session).create(
            name="other ERP", role="sales", now=datetime.now(UTC)
        )
        session.commit()
    body = api.quote_body(selection_id)
    mine = create(api, body, key="order-1").json()
    theirs = api.client.post(
        "/api/v1/quotes",
        json=body,
        headers={"Authorization": f"Bearer {other}", "Idempotency-Key": "order-1"},
    )
    assert theirs.status_code == 201
    assert theirs.json()["number"] != mine["number"]


@pytest.mark.parametrize("key", ["has space", "x" * 201, "tab\there", ""])
def test_bad_idempotency_key_is_422(api: SalesApi, selection_id: str, key: str) -> None:
    response = create(api, api.quote_body(selection_id), key=key)
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["header", "Idempotency-Key"]


def test_numbers_are_consecutive_and_failures_leave_no_gap(
    api: SalesApi, selection_id: str
) -> None:
    numbers = [create(api, api.quote_body(selection_id)).json()["number"]]
    bad = api.quote_body(
        selection_id, controller={"type_name": "X", "item_code": "CTRL-NONE", "quantity": 1}
    )
    assert create(api, bad).status_code == 422
    numbers += [create(api, api.quote_body(selection_id)).json()["number"] for _ in range(3)]
    sequences = [sequence(n) for n in numbers]
    assert sequences == list(range(sequences[0], sequences[0] + 4))


def test_status_flow(api: SalesApi, selection_id: str) -> None:
    number = create(api, api.quote_body(selection_id)).json()["number"]

    def move(status: str) -> Any:
        return api.post(f"/api/v1/quotes/{number}/status", json={"status": status})

    refused = move("accepted")
    assert refused.status_code == 409
    (entry,) = refused.json()["detail"]
    assert (entry["loc"], entry["type"]) == (["body", "status"], "illegal_transition")
    assert (entry["code"], entry["params"]) == (
        "quote_transition",
        {"status": "draft", "target": "accepted", "allowed": ["sent"]},
    )
    assert entry["msg"] == "a quote in status 'draft' cannot move to 'accepted'; allowed: 'sent'"
    german = api.post(
        f"/api/v1/quotes/{number}/status",
        json={"status": "accepted"},
        extra={"Accept-Language": "de"},
    ).json()["detail"][0]
    assert german["params"] == entry["params"]
    assert german["msg"] == (
        "ein Angebot im Status 'draft' kann nicht nach 'accepted' wechseln; erlaubt: 'sent'"
    )
    assert move("rejected").status_code == 409
    sent = move("sent")
    assert sent.status_code == 200
    assert (sent.json()["status"], sent.json()["allowed_transitions"]) == (
        "sent",
        ["accepted", "rejected"],
    )
    assert move("sent").status_code == 409
    accepted = move("accepted")
    assert accepted.status_code == 200
    assert (accepted.json()["status"], accepted.json()["allowed_transitions"]) == ("accepted", [])
    for status in ("rejected", "sent", "accepted"):
        assert move(status).status_code == 409
    assert move("sent").json()["detail"][0]["code"] == "quote_final"
    assert move("expired").status_code == 422
    assert move("draft").status_code == 422
    assert api.get(f"/api/v1/quotes/{number}").json()["status"] == "accepted"
    assert (
        api.post("/api/v1/quotes/Q-1999-00001/status", json={"status": "sent"}).status_code == 404
    )


def test_sent_quote_can_be_rejected(api: SalesApi, selection_id: str) -> None:
    number = create(api, api.quote_body(selection_id)).json()["number"]
    assert api.post(f"/api/v1/quotes/{number}/status", json={"status": "sent"}).status_code == 200
    rejected = api.post(f"/api/v1/quotes/{number}/status", json={"status": "rejected"})
    assert rejected.json()["status"] == "rejected"


def test_expired_quote_cannot_be_accepted(api: SalesApi, selection_id: str) -> None:
    body = api.quote_body(selection_id, valid_until=api.clock.now().date().isoformat())
    number = create(api, body).json()["number"]
    assert api.post(f"/api/v1/quotes/{number}/status", json={"status": "sent"}).status_code == 200
    api.clock.advance(days=1)
    quote = api.get(f"/api/v1/quotes/{number}").json()
    assert (quote["status"], quote["allowed_transitions"]) == ("expired", [])
    refused = api.post(f"/api/v1/quotes/{number}/status", json={"status": "accepted"})
    assert refused.status_code == 409
    assert "expired" in refused.json()["detail"][0]["msg"]
    expired = api.get("/api/v1/quotes", params={"status": "expired"}).json()
    assert [q["number"] for q in expired["quotes"]] == [number]
    assert api.get("/api/v1/quotes", params={"status": "sent"}).json()["total"] == 0


def test_last_valid_day_still_accepts(api: SalesApi, selection_id: str) -> None:
    body = api.quote_body(selection_id, valid_until=today_plus(3))
    number = create(api, body).json()["number"]
    api.post(f"/api/v1/quotes/{number}/status", json={"status": "sent"})
    api.clock.advance(days=3)
    accepted = api.post(f"/api/v1/quotes/{number}/status", json={"status": "accepted"})
    assert accepted.status_code == 200


def test_search(api: SalesApi, selection_id: str) -> None:
    first = create(api, api.quote_body(selection_id, customer={"name": "Alpha Robotics AG"})).json()
    second = create(
        api, api.quote_body(selection_id, customer={"name": "Beta 100% Automation"})
    ).json()
    found = api.get("/api/v1/quotes", params={"q": "alpha"}).json()
    assert [q["number"] for q in found["quotes"]] == [first["number"]]
    assert api.get("/api/v1/quotes", params={"q": "100%"}).json()["total"] == 1
    assert api.get("/api/v1/quotes", params={"q": "_"}).json()["total"] == 0
    by_number = api.get("/api/v1/quotes", params={"q": second["number"]}).json()
    assert [q["number"] for q in by_number["quotes"]] == [second["number"]]
    newest_first = api.get("/api/v1/quotes", params={"q": "fha-25c"}).json()["quotes"]
    assert [q["number"] for q in newest_first] == [second["number"], first["number"]]
    page = api.get("/api/v1/quotes", params={"limit": 1, "offset": 1}).json()
    assert (page["total"], [q["number"] for q in page["quotes"]]) == (2, [first["number"]])
    assert api.get("/api/v1/quotes", params={"limit": 0}).status_code == 422
    assert api.get("/api/v1/quotes", params={"status": "lost"}).status_code == 422


def test_retired_actuator_is_not_quoted_but_old_quotes_stay(
    api: SalesApi, selection_id: str
) -> None:
    number = create(api, api.quote_body(selection_id)).json()["number"]
    assert (
        api.client.delete(
            "/api/v1/actuators/FHA-25C-50-L", headers=api.headers("admin")
        ).status_code
        == 204
    )
    refused = create(api, api.quote_body(selection_id))
    assert refused.status_code == 422
    assert refused.json()["detail"][0]["type"] == "retired"
    assert api.get(f"/api/v1/quotes/{number}").status_code == 200
    document = api.get(f"/api/v1/quotes/{number}/document")
    assert document.status_code == 200
    assert "FHA-25C-50-L" in document.text


def test_document_is_printable_escaped_and_self_contained(api: SalesApi, selection_id: str) -> None:
    hostile = "<script>alert('x')</script> & Söhne"
    body = api.quote_body(
        selection_id,
        customer={"name": hostile, "address": "<img src=x onerror=alert(1)>", "reference": "\"'"},
        notes="</section><b>bold</b>",
    )
    quote = create(api, body).json()
    response = api.get(f"/api/v1/quotes/{quote['number']}/document")
    assert response.status_code == 200
    assert response.headers["content-type"].startswith("text/html")
    assert "script-src 'self';" in response.headers["content-security-policy"]  # no inline
    html = response.text
    assert "<script>alert" not in html
    assert "<img src=x" not in html
    assert "<b>bold</b>" not in html
    assert "&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp; Söhne" in html
    assert "@media print" in html
    assert "size: A4" in html
    assert quote["number"] in html
    assert "EXAMPLE PRICES" in html
    assert "unconfirmed" in html.lower()
    for figure in ("8,861.50 EUR", "718.50 EUR", "9,580.00 EUR"):
        assert figure in html
    # the engineering: load, cycle, checks with values, limits and references
    for text in ("Table 515.1", "Eq. 514.1", "95.48 Nm", "35.57 Nm", "151.00 Nm", "90.00 rpm"):
        assert text in html, text
    assert f"catalogue version {quote['selection_catalogue_version']}" in html
    # plotly from the app itself, nothing from a CDN, no inline code
    assert f'<script src="{PLOTLY_URL}"></script>' in html
    assert "cdn" not in html.lower()
    scripts = re.findall(r"<script([^>]*)>(.*?)</script>", html, flags=re.S)
    assert all("src=" in attrs or "application/json" in attrs for attrs, _ in scripts)
    data = re.search(r'<script type="application/json" id="figure-data">(.*?)</script>', html, re.S)
    assert data is not None
    figure = json.loads(data.group(1))
    names = [trace["name"] for trace in figure["data"]]
    assert "T<sub>rms</sub> at n<sub>av</sub>" in names
    assert any(n.startswith("T<sub>max</sub> = 151") for n in names)
    rms = next(t for t in figure["data"] if t["name"] == "T<sub>rms</sub> at n<sub>av</sub>")
    assert rms["x"][0] == pytest.approx(6.15, abs=0.01)
    assert rms["y"][0] == pytest.approx(35.57, abs=0.01)
    script = api.client.get("/api/v1/quote-document.js")
    assert script.status_code == 200
    assert "Plotly.newPlot" in script.text


def _document_figure(html: str) -> dict[str, Any]:
    data = re.search(r'<script type="application/json" id="figure-data">(.*?)</script>', html, re.S)
    assert data is not None
    return cast(dict[str, Any], json.loads(data.group(1)))


@pytest.mark.parametrize(
    ("model", "edge_field"),
    [
        ("FHA-25C-50", "continuous_speed_rpm"),
        ("CHA-32A-50", "rated_speed_rpm"),
        ("FHA-8C-30", None),
    ],
)
def test_document_draws_the_continuous_rectangle_the_check_compares_with(
    api: SalesApi, model: str, edge_field: str | None
) -> None:
    """Without a published zone, the diagram's rectangle runs up to the speed the
    continuous_speed check bounds it by (allowable continuous speed, else rated speed),
    never to n_max; with neither published it is not drawn, as that check lacks data."""
    # a load within every model's peaks, so that each can be quoted
    light = {"speed_rpm": 20, "torque_nm": 0.1, "inertia_kgm2": 0.0005}
    selection = api.selection(models=[model], load=light)
    candidate = selection["candidates"][0]
    duty = next(c for c in candidate["checks"] if c["name"] == "continuous_duty")
    speed = next(c for c in candidate["checks"] if c["name"] == "continuous_speed")
    body = api.quote_body(str(selection["id"]), actuator={"model": model, "quantity": 1})
    del body["controller"]
    quote = create(api, body)
    assert quote.status_code == 201, quote.text
    html = api.get(f"/api/v1/quotes/{quote.json()['number']}/document").text
    traces = {t["uid"]: t for t in _document_figure(html)["data"]}
    actuator = api.get(f"/api/v1/actuators/{model}", role=None).json()
    if edge_field is None:
        assert speed["status"] == "no_data"
        assert "zone-approx" not in traces
        return
    assert duty["approximate"] is True
    rectangle = traces["zone-approx"]
    assert max(rectangle["x"]) == actuator[edge_field] < actuator["max_speed_rpm"]
    assert speed["limit"] == actuator[edge_field]
    # its upper edge (T_0 falling with speed where k_T and K_INL are published) at n_av is
    # the limit the continuous_duty check compared T_rms with
    (_, t_zero, t_edge, _, _), edge = rectangle["y"], rectangle["x"][2]
    n_av = selection["mean_speed_rpm"]
    assert t_zero + (t_edge - t_zero) * n_av / edge == pytest.approx(duty["limit"], rel=1e-9)


def test_document_keeps_the_catalogue_as_quoted(api: SalesApi, selection_id: str) -> None:
    quote = create(api, api.quote_body(selection_id)).json()
    current = api.get("/api/v1/actuators/FHA-25C-50-L", role=None).json()
    changed = {k: v for k, v in current.items() if k in _ACTUATOR_COLUMNS}
    changed["max_torque_nm"] = 160
    changed["no_load_current_constant_30c_ma_per_rpm"] = None
    changed["no_load_current_constant_80c_ma_per_rpm"] = None
    replaced = api.client.put(
        "/api/v1/actuators/FHA-25C-50-L", json=changed, headers=api.headers("admin")
    )
    assert replaced.status_code == 200, replaced.text
    assert replaced.json()["max_torque_nm"] == 160
    html = api.get(f"/api/v1/quotes/{quote['number']}/document").text
    assert "151.00 Nm" in html
    assert "160.00 Nm" not in html


_ACTUATOR_COLUMNS = {
    "model",
    "family",
    "gear_ratio",
    "max_torque_nm",
    "max_speed_rpm",
    "inertia_kgm2",
    "source",
    "notes",
}


def test_unknown_quote_is_404(api: SalesApi) -> None:
    assert api.get("/api/v1/quotes/Q-1999-00001").status_code == 404
    assert api.get("/api/v1/quotes/Q-1999-00001/document").status_code == 404


def test_document_lists_the_brake_check_of_a_braked_selection(api: SalesApi) -> None:
    """A selection with ``brake``: the quote document lists the brake's check, titled, with
    the no-data reason for FHA-25C-50-L (no brake data published for that row)."""
    braked = str(api.selection(models=["FHA-25C-50-L"], brake=True)["id"])
    quote = create(api, api.quote_body(braked)).json()
    html = api.get(f"/api/v1/quotes/{quote['number']}/document").text
    assert '<tr data-check="brake_holding"><td>Holding brake: T<sub>L</sub> at standstill' in html
    assert "the catalogue gives no brake holding torque for this actuator" in html
