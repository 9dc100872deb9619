"""The quote document as PDF: German and English text read back from the file with pypdf
(independent of fpdf2, which wrote it), the totals from the quote's own answer in each
language's number format, page numbers, the seller block, VAT and the terms."""

from __future__ import annotations

import io
import re
from decimal import Decimal
from typing import Any

import pytest
from babel.numbers import format_decimal
from pypdf import PdfReader
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.documents.pdf import unicode_font

__all__ = ["api", "sales_api_with"]

LOCALES = {"de": "de_DE", "en": "en_GB"}
RPM_DE = "min⁻¹" if unicode_font() is not None else "1/min"
"""The chapter's German speed unit; Helvetica's Latin-1 (no DejaVu Sans here) writes 1/min."""


def _quote(api: SalesApi, **changes: Any) -> dict[str, Any]:
    selection = api.selection(models=["FHA-25C-50-L"])
    created = api.post(
        "/api/v1/quotes", json=api.quote_body(selection["id"], vat_percent="19", **changes)
    )
    assert created.status_code == 201, created.text
    quote: dict[str, Any] = created.json()
    return quote


def _text(body: bytes) -> tuple[str, int]:
    """All pages' text (whitespace runs as one space) and the number of pages."""
    reader = PdfReader(io.BytesIO(body))
    text = " ".join(page.extract_text() or "" for page in reader.pages)
    return re.sub(r"\s+", " ", text), len(reader.pages)


def _money(amount: str, language: str) -> str:
    return str(format_decimal(Decimal(amount), "#,##0.00", locale=LOCALES[language]))


def _pdf(api: SalesApi, number: str, **headers: str) -> Any:
    return api.client.get(
        f"/api/v1/quotes/{number}/document.pdf",
        headers=api.headers("sales", **headers),
    )


@pytest.mark.parametrize("language", ["de", "en"])
@pytest.mark.slow
def test_the_pdf_is_the_document_in_the_asked_language(api: SalesApi, language: str) -> None:
    quote = _quote(api)
    response = _pdf(api, quote["number"], **{"Accept-Language": language})
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == "application/pdf"
    assert response.headers["content-language"] == language
    assert response.headers["content-disposition"] == (
        f'attachment; filename="{quote["number"]}.pdf"'
    )
    assert response.content.startswith(b"%PDF-")
    text, pages = _text(response.content)
    # every money figure of the answer, in the language's format
    for field in ("subtotal", "discount_amount", "net_total", "vat_amount", "gross_total"):
        assert f"{_money(quote[field], language)} EUR" in text, (field, text)
    assert f"{pages}" in text
    words = {
        "de": [
            "Angebot",
            "Anbieter",
            "Kunde",
            "USt.",
            "Zahlungsbedingungen",
            "Lieferbedingungen",
            "Technische Begründung",
            f"Seite 1 von {pages}",
            RPM_DE,
            "Beschleunigungsmoment",
        ],
        "en": [
            "Quote",
            "Seller",
            "Customer",
            "VAT",
            "Payment",
            "Delivery",
            "Engineering justification",
            f"Page 1 of {pages}",
            "rpm",
        ],
    }[language]
    for word in words:
        assert word in text, (word, text)
    assert quote["number"] in text
    assert "Muster GmbH" in text  # the customer as entered
    assert "Hauptstr. 1" in text
    if language == "de":
        # the service's own words come in German; English words of the other document do not
        for english in ("Payment terms", "Engineering justification", "Servo controller"):
            assert english not in text, english
        assert "Servoregler SINAMICS S120, 400 V" in text
        assert f"40,00 {RPM_DE}" in text  # the load speed n_2, with the chapter's German unit


def test_the_query_chooses_the_language_and_a_signed_link_downloads_it(api: SalesApi) -> None:
    quote = _quote(api)
    number = quote["number"]
    german = _pdf(api, number, **{"Accept-Language": "en"})
    assert german.headers["content-language"] == "en"
    link = api.post(f"/api/v1/quotes/{number}/document-link?lang=de")
    assert link.status_code == 200, link.text
    url = link.json()["url"].replace("/document?", "/document.pdf?")
    response = api.client.get(url)  # no key: the link's token speaks for it
    assert response.status_code == 200, response.text
    assert response.headers["content-language"] == "de"
    text, _ = _text(response.content)
    assert f"{_money(quote['gross_total'], 'de')} EUR" in text
    assert api.client.get(url.replace("access=", "access=x")).status_code == 401


def test_the_pdf_needs_a_sales_key_and_a_known_quote(api: SalesApi) -> None:
    quote = _quote(api)
    path = f"/api/v1/quotes/{quote['number']}/document.pdf"
    assert api.client.get(path).status_code == 401
    assert api.get(path, role="admin").status_code == 403
    assert api.get("/api/v1/quotes/Q-1999-00001/document.pdf").status_code == 404


def test_the_pdf_route_is_documented_as_a_pdf(api: SalesApi) -> None:
    schema = api.client.get("/openapi.json").json()
    route = schema["paths"]["/api/v1/quotes/{number}/document.pdf"]["get"]
    assert "application/pdf" in route["responses"]["200"]["content"]
    assert {p["name"] for p in route["parameters"]} >= {"number", "access", "lang"}
