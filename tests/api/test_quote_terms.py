"""Quote terms over HTTP: VAT, seller block, payment and delivery terms, the document in
English and German, and quotes made before these existed (on SQLite and PostgreSQL)."""

from __future__ import annotations

import re
from collections.abc import Callable
from datetime import date, timedelta
from decimal import ROUND_HALF_UP, Decimal
from typing import Any

import pytest
from sqlalchemy import update
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.db.models.sales import QuoteRow
from actuator_selection.documents.quote_document_text import DOCUMENT
from actuator_selection.i18n.localize import words

__all__ = ["api", "sales_api_with"]

SELLER = {
    "seller_name": "Antriebstechnik Muster AG",
    "seller_address": "Werkstraße 5\\n65549 Limburg\\nDeutschland",
    "seller_vat_id": "DE123456789",
    "seller_email": "vertrieb@muster-antriebe.example",
    "seller_phone": "+49 6431 0000",
}


def vat_from_first_principles(net: str, rate: str) -> tuple[Decimal, Decimal]:
    """VAT and gross: net × rate / 100 in exact decimals, rounded once to cents, half up."""
    vat = (Decimal(net) * Decimal(rate) / Decimal(100)).quantize(
        Decimal("0.01"), rounding=ROUND_HALF_UP
    )
    return vat, Decimal(net) + vat


def create(api: SalesApi, body: dict[str, Any]) -> Any:
    return api.post("/api/v1/quotes", json=body)


def document(api: SalesApi, number: str, **params: str) -> Any:
    headers = {}
    if "accept_language" in params:
        headers["Accept-Language"] = params.pop("accept_language")
    return api.client.get(
        f"/api/v1/quotes/{number}/document",
        params=params,
        headers={**api.headers("sales"), **headers},
    )


@pytest.fixture
def seller_api(sales_api_with: Callable[..., SalesApi]) -> SalesApi:
    """The app with a configured seller (not the placeholders)."""
    return sales_api_with(**SELLER)


@pytest.fixture
def selection_id(api: SalesApi) -> str:
    return str(api.selection(models=["FHA-25C-50-L"])["id"])


ONE_ACTUATOR = {"actuator": {"model": "FHA-25C-50-L", "quantity": 1}, "controller": None}
"""Net 2950.00 EUR (example price list, no discount)."""


@pytest.mark.parametrize(
    ("changes", "rate", "net", "vat", "gross"),
    [
        ({**ONE_ACTUATOR, "discount_percent": "0"}, "0", "2950.00", "0.00", "2950.00"),
        ({**ONE_ACTUATOR, "discount_percent": "0"}, "19", "2950.00", "560.50", "3510.50"),
        ({**ONE_ACTUATOR, "discount_percent": "0"}, "7", "2950.00", "206.50", "3156.50"),
        # 2950.00 × 0.03 % = 0.885: half up → 0.89 (half-even and floats give 0.88).
        ({**ONE_ACTUATOR, "discount_percent": "0"}, "0.03", "2950.00", "0.89", "2950.89"),
        # Net 8861.50 (2 actuators, 2 controllers, 7.5 % off); × 19 % = 1683.685 → 1683.69,
        # once on the net total, not per line.
        ({}, "19", "8861.50", "1683.69", "10545.19"),
        ({}, 20, "8861.50", "1772.30", "10633.80"),
        ({}, "100", "8861.50", "8861.50", "17723.00"),
    ],
)
def test_vat_from_first_principles(
    api: SalesApi,
    selection_id: str,
    changes: dict[str, Any],
    rate: str | int,
    net: str,
    vat: str,
    gross: str,
) -> None:
    assert vat_from_first_principles(net, str(rate)) == (Decimal(vat), Decimal(gross))
    response = create(api, api.quote_body(selection_id, vat_percent=rate, **changes))
    assert response.status_code == 201, response.text
    quote = response.json()
    assert (quote["net_total"], quote["total"]) == (net, net)
    assert Decimal(quote["vat_percent"]) == Decimal(str(rate))
    assert (quote["vat_amount"], quote["gross_total"]) == (vat, gross)
    assert Decimal(quote["net_total"]) + Decimal(quote["vat_amount"]) == Decimal(
        quote["gross_total"]
    )
    assert "VAT = net total × rate / 100, rounded once to cents, half up" in quote["rounding"]
    assert api.get(f"/api/v1/quotes/{quote['number']}").json() == quote


def test_defaults_come_from_settings(
    sales_api_with: Callable[..., SalesApi], selection_id: str, api: SalesApi
) -> None:
    quote = create(api, api.quote_body(selection_id)).json()
    # The documented defaults: 19 % and placeholder seller values.
    assert (quote["vat_percent"], quote["vat_amount"], quote["gross_total"]) == (
        "19.00",
        "1683.69",
        "10545.19",
    )
    assert quote["seller"]["name"] == "Your company"
    assert (quote["payment_terms"], quote["delivery_terms"]) == (None, None)
    assert set(quote["seller"]["payment_terms"]) == {"en", "de"}

    other = sales_api_with(quote_vat_percent=Decimal("7.7"), **SELLER)
    quote = create(other, other.quote_body(selection_id)).json()
    assert quote["vat_percent"] == "7.70"
    # 8861.50 × 7.7 % = 682.3355 → 682.34
    assert (quote["vat_amount"], quote["gross_total"]) == ("682.34", "9543.84")
    assert quote["seller"]["name"] == SELLER["seller_name"]
    assert quote["seller"]["address"] == "Werkstraße 5\n65549 Limburg\nDeutschland"
    assert quote["seller"]["vat_id"] == "DE123456789"


@pytest.mark.parametrize(
    "value",
    [-1, "-1", 101, "100.01", "abc", "NaN", "Infinity", "-0.01", 19.5, True, "1.005", "", None],
)
def test_bad_vat_percent_is_422_naming_the_field(
    api: SalesApi, selection_id: str, value: Any
) -> None:
    body = api.quote_body(selection_id, vat_percent=value)
    if value is None:
        # null means "the default", so it is accepted.
        assert create(api, body).status_code == 201
        return
    before = api.get("/api/v1/quotes").json()["total"]
    response = create(api, body)
    assert response.status_code == 422, response.text
    assert ["body", "vat_percent"] in [e["loc"] for e in response.json()["detail"]]
    assert api.get("/api/v1/quotes").json()["total"] == before


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("payment_terms", ""),
        ("payment_terms", "x" * 1001),
        ("delivery_terms", "\u202eevil"),
        ("delivery_terms", 30),
    ],
)
def test_bad_terms_are_422(api: SalesApi, selection_id: str, field: str, value: Any) -> None:
    response = create(api, api.quote_body(selection_id, **{field: value}))
    assert response.status_code == 422, response.text
    assert ["body", field] in [e["loc"] for e in response.json()["detail"]]


def _text(html: str) -> str:
    """The page's visible text, roughly: tags dropped, the figure's JSON left out."""
    html = re.sub(r"<script.*?</script>|<style.*?</style>", " ", html, flags=re.S)
    return re.sub(r"\s+", " ", re.sub(r"<[^>]+>", " ", html))


def test_document_in_english(seller_api: SalesApi, selection_id: str) -> None:
    body = seller_api.quote_body(
        selection_id,
        vat_percent="19",
        payment_terms="50 % with order, 50 % before shipment",
        delivery_terms="DAP Musterstadt (Incoterms® 2020)",
        valid_until=(seller_api.clock.now().date() + timedelta(days=30)).isoformat(),
    )
    quote = create(seller_api, body).json()
    response = document(seller_api, quote["number"], lang="en")
    assert response.status_code == 200
    assert response.headers["content-language"] == "en"
    html = response.text
    assert '<html lang="en">' in html
    text = _text(html)
    for expected in (
        "Quotation",
        "Seller",
        "Antriebstechnik Muster AG",
        "Werkstraße 5\n65549 Limburg",
        "VAT ID",
        "DE123456789",
        "vertrieb@muster-antriebe.example",
        "Customer",
        "Muster GmbH",
    ):
        assert expected in (html if "\n" in expected else text), expected
    assert 'data-field="seller-vat-id">DE123456789<' in html
    for field, figure in (
        ("subtotal", "9,580.00 EUR"),
        ("total", "8,861.50 EUR"),
        ("vat", "1,683.69 EUR"),
        ("gross", "10,545.19 EUR"),
    ):
        assert re.search(rf"data-field=.{field}.>[^<]*{re.escape(figure)}<", html), field
    assert "VAT 19 %" in text
    assert "Total (EUR, including VAT)" in text
    assert "VAT = net total × rate / 100, rounded once to cents, half up" in text
    assert "Payment terms 50 % with order, 50 % before shipment" in text
    assert "Delivery terms DAP Musterstadt (Incoterms® 2020)" in text
    valid = date.fromisoformat(quote["valid_until"])
    assert f"valid until {valid.day} {valid.strftime('%b')} {valid.year} (inclusive)" in text
    assert '"Page " counter(page) " of " counter(pages)' in html
    assert "90.00 rpm" in text
    assert "placeholder" not in text.lower()


def test_document_in_german(seller_api: SalesApi, selection_id: str) -> None:
    quote = create(seller_api, seller_api.quote_body(selection_id, vat_percent="19")).json()
    response = document(seller_api, quote["number"], lang="de")
    assert response.status_code == 200
    assert response.headers["content-language"] == "de"
    html = response.text
    assert '<html lang="de">' in html
    text = _text(html)
    for field, figure in (
        ("subtotal", "9.580,00 EUR"),
        ("total", "8.861,50 EUR"),
        ("vat", "1.683,69 EUR"),
        ("gross", "10.545,19 EUR"),
    ):
        assert re.search(rf"data-field=.{field}.>[^<]*{re.escape(figure)}<", html), field
    valid = date.fromisoformat(quote["valid_until"])
    for expected in (
        "Angebot",
        "Anbieter",
        "Antriebstechnik Muster AG",
        "USt-IdNr. DE123456789",
        "Kunde",
        "Zwischensumme",
        "Rabatt 7,5 %",
        "Nettobetrag",
        "zzgl. 19 % USt.",
        "Gesamtbetrag (EUR)",
        "USt. = Nettobetrag × Steuersatz / 100, einmal kaufmännisch auf Cent gerundet",
        # No terms in the request: the seller's standard terms, in German.
        "Zahlungsbedingungen Zahlbar innerhalb von 30 Tagen ab Rechnungsdatum ohne Abzug.",
        "Lieferbedingungen FCA Werk des Verkäufers (Incoterms® 2020)",
        f"gültig bis einschließlich {valid:%d.%m.%Y}",
        "Technische Begründung",
        "90,00 min⁻¹",
        "95,48 Nm",
        "Tabelle 515.1",
        "Gl. 514.1",
    ):
        assert expected in text, expected
    assert '"Seite " counter(page) " von " counter(pages)' in html
    # The labels of the English document do not appear.
    for english in (
        "Quotation",
        "Subtotal",
        "Net total",
        "including VAT",
        "Payment terms",
        "Delivery terms",
        "Valid until",
        "Engineering justification",
        "Your reference",
        " rpm",
        "Payable within",
        "Rounding:",
        "Table 515.1",
        "Eq. 514.1",
    ):
        assert english not in text, english


@pytest.mark.parametrize(
    ("lang", "accept", "expected"),
    [
        (None, "de-CH, en;q=0.5", "de"),
        (None, "fr-FR, en;q=0.8, de;q=0.7", "en"),
        (None, None, "en"),
        ("en", "de-DE,de;q=0.9", "en"),
        ("de", "en-US", "de"),
    ],
)
def test_document_language_from_query_or_accept_language(
    seller_api: SalesApi, selection_id: str, lang: str | None, accept: str | None, expected: str
) -> None:
    number = create(seller_api, seller_api.quote_body(selection_id)).json()["number"]
    params: dict[str, str] = {}
    if lang is not None:
        params["lang"] = lang
    if accept is not None:
        params["accept_language"] = accept
    response = document(seller_api, number, **params)
    assert response.status_code == 200
    assert response.headers["content-language"] == expected
    assert f'<html lang="{expected}">' in response.text
    assert "Accept-Language" in response.headers["vary"]


def test_unknown_language_is_422(seller_api: SalesApi, selection_id: str) -> None:
    number = create(seller_api, seller_api.quote_body(selection_id)).json()["number"]
    response = document(seller_api, number, lang="fr")
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["query", "lang"]


def test_every_label_has_both_languages() -> None:
    english, german = words("en"), words("de")
    labels = [key for key in english if key.startswith(DOCUMENT)]
    assert len(labels) > 150
    assert all(english[key] and german.get(key) for key in labels)


def test_quote_keeps_the_seller_it_was_made_with(
    sales_api_with: Callable[..., SalesApi], selection_id: str, api: SalesApi
) -> None:
    made = sales_api_with(**SELLER)
    number = create(made, made.quote_body(selection_id)).json()["number"]
    later = sales_api_with(seller_name="Renamed Holding", seller_vat_id="DE999999999")
    assert later.get(f"/api/v1/quotes/{number}").json()["seller"]["name"] == SELLER["seller_name"]
    html = document(later, number).text
    assert "Antriebstechnik Muster AG" in html
    assert "Renamed Holding" not in html
    assert "DE999999999" not in html


def test_placeholder_seller_is_flagged(api: SalesApi, selection_id: str) -> None:
    number = create(api, api.quote_body(selection_id)).json()["number"]
    html = document(api, number, lang="de").text
    assert 'data-field="placeholder-seller"' in html
    assert "Your company" in html  # the placeholder itself, as configured


def test_quote_made_before_terms_existed_still_renders(
    seller_api: SalesApi, selection_id: str, session: Session
) -> None:
    """A quote stored before migration 0008 has no VAT, terms or seller: it answers them as
    null and its document shows the net total as it was sent, the seller as configured now
    and the seller's standard terms."""
    number = create(seller_api, seller_api.quote_body(selection_id)).json()["number"]
    session.execute(
        update(QuoteRow)
        .where(QuoteRow.number == number)
        .values(
            vat_percent=None,
            vat_amount=None,
            gross_total=None,
            payment_terms=None,
            delivery_terms=None,
            seller=None,
        )
    )
    session.commit()
    quote = seller_api.get(f"/api/v1/quotes/{number}").json()
    assert (quote["vat_percent"], quote["vat_amount"], quote["gross_total"]) == (None, None, None)
    assert (quote["seller"], quote["payment_terms"], quote["delivery_terms"]) == (None, None, None)
    assert (quote["total"], quote["net_total"]) == ("8861.50", "8861.50")
    for lang, total_label, terms in (
        ("en", "Total (EUR, excluding taxes)", "Payable within 30 days"),
        ("de", "Gesamt (EUR, ohne Steuern)", "Zahlbar innerhalb von 30 Tagen"),
    ):
        response = document(seller_api, number, lang=lang)
        assert response.status_code == 200
        text = _text(response.text)
        assert total_label in text
        assert 'data-field="vat"' not in response.text
        assert "Antriebstechnik Muster AG" in text
        assert terms in text


def test_a_document_link_carries_the_language(seller_api: SalesApi, selection_id: str) -> None:
    number = create(seller_api, seller_api.quote_body(selection_id)).json()["number"]
    link = seller_api.post(f"/api/v1/quotes/{number}/document-link?lang=de")
    assert link.status_code == 200, link.text
    url = link.json()["url"]
    assert url.endswith("&lang=de")
    # A browser window with an English Accept-Language still gets the German document.
    response = seller_api.client.get(url, headers={"Accept-Language": "en-US"})
    assert response.status_code == 200
    assert response.headers["content-language"] == "de"
    assert "Nettobetrag" in response.text
    bad = seller_api.post(f"/api/v1/quotes/{number}/document-link?lang=xx")
    assert bad.status_code == 422
    assert bad.json()["detail"][0]["loc"] == ["query", "lang"]


TWO_WAY_SEGMENTS: dict[str, Any] = {
    "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {
        "segments": [
            {"speed": 40, "duration_s": 0.1},
            {"duration_s": 0.1},
            {"speed": 0, "duration_s": 0.1},
            {"duration_s": 0.5},
            {"speed": -40, "duration_s": 0.1},
            {"duration_s": 0.1},
            {"speed": 0, "duration_s": 0.1},
            {"duration_s": 0.5},
        ]
    },
    "high_dynamics": True,
    "models": ["FHA-25C-50-L"],
}


def test_a_cycle_of_segments_is_listed_in_either_language(seller_api: SalesApi) -> None:
    response = seller_api.client.post("/api/v1/selections", json=TWO_WAY_SEGMENTS)
    assert response.status_code == 201, response.text
    number = create(seller_api, seller_api.quote_body(response.json()["id"])).json()["number"]
    english = _text(document(seller_api, number, lang="en").text)
    german = _text(document(seller_api, number, lang="de").text)
    assert "Segment 8: duration 0.5 s" in english
    assert "Segment 5: end speed −40.00 rpm" in english
    assert "Abschnitt 8: Dauer 0,5 s" in german
    assert "Abschnitt 5: Enddrehzahl −40,00 min⁻¹" in german
    assert "Segment" not in german
