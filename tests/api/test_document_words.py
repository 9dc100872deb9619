"""Documents worth sending (issue 29 items 2–4): the German quote and report name every
input in words, write symbols with subscripts and negative numbers with the minus sign,
hold no English line; the report's first page can be signed (inputs, both diagrams, the
first candidate's checks, the top five) and the whole-catalogue report is at most three
pages; the CSV is one tidy table. PDFs are read back with pypdf, independent of fpdf2."""

from __future__ import annotations

import csv
import io
import itertools
import os
import re
from pathlib import Path
from typing import Any

import pypdf
import pytest
from fastapi.testclient import TestClient
from tests import worked_example
from tests.api._ranking import whole_ranking
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.documents.pdf import DocumentPdf, unicode_font
from actuator_selection.documents.quote_document_text import DOCUMENT, DocumentText, Language
from actuator_selection.i18n.localize import words

__all__ = ["api", "sales_api_with"]

ROTARY_TABLE = {
    "type": "rotary_table",
    "speed_rpm": 45.0,
    "mass_kg": 30.0,
    "diameter_m": 0.4,
    "friction_coefficient": 0.02,
    "friction_radius_m": 0.15,
}
IDENTIFIER = re.compile(r"[A-Za-z]_[A-Za-z0-9]|speed_rpm|mass_kg|rotary_table")
HYPHEN_NUMBER = re.compile(r"(?<![\w.,])-\d")
WORD = re.compile(r"[A-Za-zÄÖÜäöüß]{3,}")
CHAPTER = "Engineering Data for Harmonic Drive Servo Actuators"
"""The chapter's title, cited as it is in both languages."""


def _dump(name: str, body: bytes) -> None:
    """Keep a PDF for a look (``DOCUMENT_DUMP=/some/dir``)."""
    if where := os.environ.get("DOCUMENT_DUMP"):
        Path(where, name).write_bytes(body)


def _pdf(body: bytes) -> tuple[str, int]:
    reader = pypdf.PdfReader(io.BytesIO(body))
    text = "\n".join(page.extract_text() or "" for page in reader.pages)
    return text, len(reader.pages)


def _english_only() -> set[str]:
    """Words only the documents' English texts use."""
    labels = [key for key in words("en") if key.startswith(DOCUMENT)]
    english = {w.lower() for key in labels for w in WORD.findall(words("en")[key])}
    german = {w.lower() for key in labels for w in WORD.findall(words("de")[key])}
    return english - german


def _english_lines(text: str, *, data: tuple[str, ...] = ()) -> list[str]:
    """The lines of ``text`` with an English-only word (``data``: cited or entered text)."""
    words = _english_only()
    for value in (CHAPTER, *data):
        text = text.replace(value, " ")
    return [
        line for line in text.splitlines() if any(w.lower() in words for w in WORD.findall(line))
    ]


def _selection(client: TestClient, **changes: Any) -> dict[str, Any]:
    body = {**worked_example.request(), "high_dynamics": True, **changes}
    response = client.post("/api/v1/selections", json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    # the report lists the whole ranking: the answer's candidates and the rest by cursor
    answer["candidates"] = whole_ranking(client, answer)
    return answer


@pytest.mark.slow
def test_the_whole_catalogue_report_is_three_pages_with_both_diagrams(
    client: TestClient,
) -> None:
    answer = _selection(client)
    assert len(answer["candidates"]) > 20  # the whole catalogue
    response = client.get(f"/api/v1/selections/{answer['id']}/report.pdf?lang=de")
    assert response.status_code == 200, response.text
    _dump("report-de.pdf", response.content)
    text, pages = _pdf(response.content)
    t = DocumentText("de")
    assert pages <= 3
    # both diagrams: their axes, the cycle's time and the speed/torque diagram's torque
    assert t("fig.time") in text
    assert t("fig.torque") in text  # the cycle's torque panel
    assert t("axis_torque") in text
    # the inputs in words, the first-ranked candidate's checks, the top five
    first = answer["candidates"][0]
    assert t("load_inertia").split(" J_")[0] in text
    assert f"1. {first['model']}" in text
    for model in (c["model"] for c in answer["candidates"][:5]):
        assert model in text
    assert answer["candidates"][6]["model"] not in text  # no details unless asked for
    assert not IDENTIFIER.findall(text), IDENTIFIER.findall(text)
    assert not HYPHEN_NUMBER.findall(text), HYPHEN_NUMBER.findall(text)
    assert "−" in text  # T₃ of the first candidate is negative
    assert not _english_lines(text), _english_lines(text)
    if unicode_font() is not None:
        assert "nₐᵥ" in text
        assert "Tᵣₘₛ" in text


def test_the_report_details_the_candidates_asked_for(client: TestClient) -> None:
    answer = _selection(client)
    far = answer["candidates"][-1]
    url = f"/api/v1/selections/{answer['id']}/report.pdf"
    text, _ = _pdf(client.get(url, params={"candidates": far["model"], "lang": "en"}).content)
    rank = len(answer["candidates"])
    assert f"{rank}. {far['model']} (" in text
    missing = client.get(url, params={"candidates": "NO-SUCH-MODEL"})
    assert missing.status_code == 422
    error = missing.json()
    assert error["detail"][0]["loc"] == ["query", "candidates", 0]
    assert error["detail"][0]["code"] == "unknown_actuator"


def test_the_csv_is_one_tidy_table(client: TestClient) -> None:
    from actuator_selection.documents.reports import COLUMNS

    answer = _selection(client)
    response = client.get(f"/api/v1/selections/{answer['id']}/report.csv")
    assert response.status_code == 200
    rows = list(csv.reader(io.StringIO(response.content.decode("utf-8-sig"), newline="")))
    assert rows[0] == list(COLUMNS)
    assert [] not in rows
    assert all(len(row) == len(COLUMNS) for row in rows)
    records = [dict(zip(rows[0], row, strict=True)) for row in rows[1:]]
    assert len(records) == sum(len(c["checks"]) for c in answer["candidates"])
    by_model = {c["model"]: c for c in answer["candidates"]}
    for record in records:
        assert record["selection_id"] == answer["id"]
        assert float(record["mean_speed_rpm"]) == answer["mean_speed_rpm"]
        assert float(record["load_inertia_kgm2"]) == answer["load"]["inertia_kgm2"]
        candidate = by_model[record["model"]]
        assert int(record["rank"]) == answer["candidates"].index(candidate) + 1
        check = next(c for c in candidate["checks"] if c["name"] == record["check"])
        if check["value"] is not None and check["limit"]:
            assert float(record["utilisation_percent"]) == pytest.approx(
                check["value"] / check["limit"] * 100
            )


@pytest.mark.parametrize("language", ["de", "en"])
def test_quote_documents_name_the_mechanism_in_words(api: SalesApi, language: Language) -> None:
    selection = api.selection(models=["FHA-25C-50-L"], load=ROTARY_TABLE)
    created = api.post("/api/v1/quotes", json=api.quote_body(selection["id"], vat_percent="19"))
    assert created.status_code == 201, created.text
    number = created.json()["number"]
    headers = api.headers("sales", **{"Accept-Language": language})
    pdf = api.client.get(f"/api/v1/quotes/{number}/document.pdf", headers=headers)
    assert pdf.status_code == 200
    _dump(f"quote-{language}.pdf", pdf.content)
    html = api.client.get(f"/api/v1/quotes/{number}/document", headers=headers)
    assert html.status_code == 200
    t = DocumentText(language)
    text, _ = _pdf(pdf.content)
    assert not IDENTIFIER.findall(text), IDENTIFIER.findall(text)
    assert not HYPHEN_NUMBER.findall(text), HYPHEN_NUMBER.findall(text)
    assert "−" in text  # T₃ < 0
    for shown in (text, re.sub(r"<[^>]+>", "", html.text)):
        assert t("load_rotary_table") in shown
        assert t("field_mass_kg") in shown
        assert t("field_diameter_m") in shown
        assert t.unit("rpm") in shown
    assert "CTRL-SINAMICS-S120" in text  # an item code is never broken
    # the diagram is in the PDF too: its axes' titles
    assert t("axis_torque") in text
    assert t("axis_speed", rpm=t.unit("rpm")) in text
    # the HTML writes the symbols with <sub>, never X_sub
    assert "n<sub>2</sub>" in html.text
    assert "T<sub>L</sub>" in html.text
    assert not re.search(r">[^<]*\b[A-Za-z]_[A-Za-z0-9][^<]*<", html.text.split("<body")[1])
    if language == "de":
        data = (
            "Muster GmbH",
            "Hauptstr.",
            "Musterstadt",
            "EXAMPLE — not real prices",
            "Your company",
            "Your street 1",
            "Your town",
            "Your country",
            "sales@example.com",
            "Servo actuator FHA-25C-50-L (example price)",
            "CTRL-SINAMICS-S120",
        )  # data: as entered
        assert not _english_lines(text, data=data), _english_lines(text, data=data)
        body = html.text.split("<body", 1)[1].split("<script", 1)[0]
        shown = re.sub(r"<[^>]+>", "\n", re.sub(r"</?(?:sub|var|em|strong)>", "", body))
        assert not _english_lines(shown, data=data), _english_lines(shown, data=data)


def _blank_pdf() -> DocumentPdf:
    pdf = DocumentPdf(title="Test", lang="en", page_label="Page", of_label="of")
    pdf.add_page()
    return pdf


def test_document_tables_are_not_justified() -> None:
    """A wrapped cell is left-aligned: no word spacing stretched over the line (the TJ
    operator with which fpdf2 justifies)."""
    pdf = _blank_pdf()
    label = "Output voltage with ωL·I over a label long enough to wrap in its cell " * 2
    pdf.facts([(label, "1 V")])
    pdf.paragraph(label * 3)
    reader = pypdf.PdfReader(io.BytesIO(bytes(pdf.output())))
    stream = reader.pages[0].get_contents()
    assert stream is not None
    assert b" TJ" not in stream.get_data()


def test_a_table_that_would_break_moves_to_the_next_page_whole() -> None:
    pdf = _blank_pdf()
    pdf.paragraph("before")
    pdf.set_y(pdf.h - 45)
    rows = [(f"row {k}", f"{k} Nm") for k in range(12)]
    pdf.grid(("check", "value"), rows, (60, 30), right=(1,))
    reader = pypdf.PdfReader(io.BytesIO(bytes(pdf.output())))
    first, second = (page.extract_text() for page in reader.pages)
    assert "before" in first
    assert "row 0" not in first
    for k in range(12):
        assert f"row {k} " in second.replace("\n", " ")


def _subscripts(body: bytes) -> set[tuple[str, str]]:
    """(letter, subscript) of every subscript the PDF sets: a run of text in a smaller size
    than the run before it, on its line, right after a letter (``T`` and ``L`` of T_L).
    Read back with pypdf's text visitor, independent of fpdf2."""
    found: set[tuple[str, str]] = set()
    for page in pypdf.PdfReader(io.BytesIO(body)).pages:
        runs: list[tuple[str, float, float]] = []

        def visit(text: str, cm: Any, tm: Any, font: Any, size: float) -> None:
            if text.strip():
                runs.append((text, size * tm[0], tm[5]))  # noqa: B023 (called at once)

        page.extract_text(visitor_text=visit)
        for (before, size, y), (text, sub_size, sub_y) in itertools.pairwise(runs):
            if sub_size < 0.8 * size and abs(sub_y - y) < 1 and before[-1:].isalpha():
                found.add((before[-1], text.strip()))
    return found


CAPITAL_SUBSCRIPTS = {("T", "L"), ("J", "L"), ("J", "A")}
"""Symbols whose subscript Unicode has no letter for: T_L, J_L, J_A (issue 29: "T_L"
printed as "TL")."""


@pytest.mark.parametrize("language", ["de", "en"])
def test_the_report_sets_capital_subscripts_lowered_and_smaller(
    client: TestClient, language: Language
) -> None:
    answer = _selection(client)
    response = client.get(f"/api/v1/selections/{answer['id']}/report.pdf?lang={language}")
    assert response.status_code == 200, response.text
    assert _subscripts(response.content) >= CAPITAL_SUBSCRIPTS
    text, _ = _pdf(response.content)
    assert not re.findall(r"</?sub>|&lt;|&gt;|&amp;", text)  # no markup printed as text
    assert not IDENTIFIER.findall(text), IDENTIFIER.findall(text)
    assert not HYPHEN_NUMBER.findall(text), HYPHEN_NUMBER.findall(text)
    assert "−" in text


@pytest.mark.parametrize("language", ["de", "en"])
def test_the_quote_sets_capital_subscripts_lowered_and_smaller(
    api: SalesApi, language: Language
) -> None:
    selection = api.selection(models=["FHA-25C-50-L"], load=ROTARY_TABLE)
    created = api.post("/api/v1/quotes", json=api.quote_body(selection["id"], vat_percent="19"))
    assert created.status_code == 201, created.text
    headers = api.headers("sales", **{"Accept-Language": language})
    number = created.json()["number"]
    pdf = api.client.get(f"/api/v1/quotes/{number}/document.pdf", headers=headers)
    assert pdf.status_code == 200
    assert _subscripts(pdf.content) >= CAPITAL_SUBSCRIPTS
    text, _ = _pdf(pdf.content)
    assert not re.findall(r"</?sub>|&lt;|&gt;|&amp;", text)  # no markup printed as text


def test_without_a_unicode_font_every_subscript_is_set_smaller() -> None:
    """The built-in Helvetica has no subscript letters: n_av is set as n and a smaller av."""
    from markupsafe import Markup

    pdf = _blank_pdf()
    pdf._unicode = False
    pdf._family = "Helvetica"
    pdf.font(8.5)
    pdf.paragraph(Markup("n<sub>av</sub> and T<sub>L</sub>"))
    assert _subscripts(bytes(pdf.output())) == {("n", "av"), ("T", "L")}


def test_every_check_has_a_title_in_both_languages(client: TestClient) -> None:
    """A check without one would be titled by its name (``peak_torque``) in the documents
    and on the page: every rule a selection may run has its words in the catalogue."""
    output_load = {"radial_force_n": 500, "radial_lever_m": 0.05, "axial_force_n": 100}
    answer = _selection(
        client,
        brake=True,
        drive=True,
        output_load={**output_load, "axial_lever_m": 0.01, "required_life_h": 20000},
    )
    names = {rule["name"] for rule in answer["check_rules"]}
    assert {"peak_torque", "brake_holding", "drive_current", "bearing_life"} <= names
    for language in ("de", "en"):
        t = DocumentText(language)
        assert all(t.has(f"check.{name}") for name in names), language
        assert all(f"check.short.{name}" in words(language) for name in names), language
