"""The engineering report of a stored selection: CSV and PDF carry the answer's numbers."""

from __future__ import annotations

import csv
import gzip
import io
import re
from functools import cache
from typing import Any

import pypdf
import pytest
import zstandard
from fastapi.testclient import TestClient
from markupsafe import Markup
from tests import worked_example
from tests.api._ranking import whole_ranking

from actuator_selection.documents.pdf import DocumentPdf, unmarked
from actuator_selection.documents.quote_document_text import DocumentText, Language
from actuator_selection.documents.reports import COLUMNS
from actuator_selection.documents.symbols import symbols


def _selection(client: TestClient, **changes: Any) -> dict[str, Any]:
    body = {**worked_example.request(), "high_dynamics": True, **changes}
    response = client.post("/api/v1/selections", json=body)
    assert response.status_code == 201, response.text
    answer: dict[str, Any] = response.json()
    # the report lists the whole ranking: the answer's candidates and the rest by cursor
    answer["candidates"] = whole_ranking(client, answer)
    return answer


def _number(cell: str) -> float | None:
    return None if cell == "" else float(cell)


def _table(text: str) -> list[dict[str, str]]:
    """The CSV's one table (after its byte order mark), by its one header row."""
    assert text.startswith("\ufeff")
    rows = list(csv.reader(io.StringIO(text[1:], newline="")))
    assert rows[0] == list(COLUMNS)
    return [dict(zip(rows[0], r, strict=True)) for r in rows[1:]]


def test_csv_holds_the_answer_numbers_exactly(client: TestClient) -> None:
    answer = _selection(client)
    response = client.get(f"/api/v1/selections/{answer['id']}/report.csv")
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == "text/csv; charset=utf-8"
    assert f"selection-{answer['id']}.csv" in response.headers["content-disposition"]
    rows = _table(response.text)

    figures = rows[0]
    assert all(
        row[k] == figures[k] for row in rows for k in ("selection_id", "mean_speed_rpm")
    )  # the selection's figures on every row
    assert figures["selection_id"] == answer["id"]
    assert int(figures["catalogue_version"]) == answer["catalogue_version"]
    for name in ("speed_rpm", "torque_nm", "inertia_kgm2"):
        assert float(figures["load_" + name]) == answer["load"][name]
    for name in ("accel_s", "constant_s", "decel_s", "pause_s"):
        assert float(figures[name]) == answer["cycle"][name]
    for name in ("cycle_time_s", "mean_speed_rpm", "duty_cycle_percent"):
        assert float(figures[name]) == answer[name]
    # First principles for the worked example: t0 = 1.3 s, n_av = 40·(0.05+0.1+0.05)/1.3.
    assert float(figures["mean_speed_rpm"]) == pytest.approx(40 * 0.2 / 1.3, rel=1e-12)
    assert float(figures["duty_cycle_percent"]) == pytest.approx(0.3 / 1.3 * 100, rel=1e-12)

    rules = {r["name"]: r for r in answer["check_rules"]}
    expected = [(rank, c, k) for rank, c in enumerate(answer["candidates"], 1) for k in c["checks"]]
    assert len(rows) == len(expected) > 0
    for row, (rank, candidate, check) in zip(rows, expected, strict=True):
        assert int(row["rank"]) == rank
        assert (row["model"], row["family"], row["verdict"]) == (
            candidate["model"],
            candidate["family"],
            candidate["verdict"],
        )
        assert float(row["gear_ratio"]) == candidate["gear_ratio"]
        for name in ("accel_torque_nm", "constant_torque_nm", "decel_torque_nm", "rms_torque_nm"):
            assert _number(row[name]) == candidate[name]
        assert (row["check"], row["status"]) == (check["name"], check["status"])
        assert (row["reference"], row["unit"]) == (
            rules[check["name"]]["reference"],
            rules[check["name"]]["unit"],
        )
        value, limit = _number(row["value"]), _number(row["limit"])
        assert (value, limit) == (check["value"], check["limit"])
        if value is None or limit is None or limit <= 0:
            assert row["margin_percent"] == ""
        else:
            assert float(row["margin_percent"]) == pytest.approx((limit - value) / limit * 100)
        assert row["approximate"] == ("true" if check.get("approximate") else "false")
        assert row["missing"] == (check.get("missing") or "")


def test_csv_is_compressed_in_the_encoding_the_client_accepts(client: TestClient) -> None:
    """The report is text: zstd where accepted, else gzip, the same text either way."""
    url = f"/api/v1/selections/{_selection(client)['id']}/report.csv"
    plain = client.get(url, headers={"Accept-Encoding": "identity"})
    assert "content-encoding" not in plain.headers
    decoders = {"zstd": lambda b: zstandard.ZstdDecompressor().decompressobj().decompress(b),
                "gzip": gzip.decompress}  # fmt: skip
    for accepted, coding in (("gzip, zstd", "zstd"), ("gzip", "gzip")):
        with client.stream("GET", url, headers={"Accept-Encoding": accepted}) as response:
            assert response.headers["content-encoding"] == coding
            assert response.headers["vary"] == "Accept-Encoding"
            wire = b"".join(response.iter_raw())
        assert decoders[coding](wire) == plain.content


def test_csv_of_the_worked_example_actuator(client: TestClient) -> None:
    """FHA-25C-50-L alone: the chapter's figures T1 = 95.48 Nm, T3 = −85.48 Nm."""
    answer = _selection(client, models=["FHA-25C-50-L"])
    rows = _table(client.get(f"/api/v1/selections/{answer['id']}/report.csv").text)
    assert {r["model"] for r in rows} == {"FHA-25C-50-L"}
    assert float(rows[0]["accel_torque_nm"]) == pytest.approx(95.48, abs=0.01)
    assert float(rows[0]["decel_torque_nm"]) == pytest.approx(-85.48, abs=0.01)
    peak = next(r for r in rows if r["check"] == "peak_torque")
    assert (peak["reference"], peak["status"]) == ("Eq. 514.1", "pass")


def _pdf_text(content: bytes) -> tuple[str, int]:
    """The PDF's text, whitespace (and the table cells' line breaks) as single spaces."""
    reader = pypdf.PdfReader(io.BytesIO(content))
    text = "\n".join(page.extract_text() for page in reader.pages)
    return " ".join(text.split()), len(reader.pages)


@cache
def _printed(text: str | Markup) -> str:
    """``text`` as the PDF writes it: as it is in DejaVu Sans, in ASCII for the chapter's
    symbols where the system lacks that font (documents/pdf.py)."""
    return " ".join(unmarked(_document().words(text)).split())


@cache
def _document() -> DocumentPdf:
    return DocumentPdf(title="", lang="en", page_label="", of_label="")


def _read_number(text: str, language: str) -> float:
    """A number as the report prints it in ``language`` (German: decimal comma)."""
    text = text.replace("−", "-")
    return float(text.replace(".", "").replace(",", ".") if language == "de" else text)


@pytest.mark.parametrize("language", ["en", "de"])
def test_pdf_shows_the_answer_in_the_requests_language(
    client: TestClient, language: Language
) -> None:
    answer = _selection(client)
    asked = [answer["candidates"][2]["model"], answer["candidates"][-1]["model"]]
    response = client.get(
        f"/api/v1/selections/{answer['id']}/report.pdf",
        headers={"Accept-Language": language},
        params={"candidates": asked},
    )
    assert response.status_code == 200, response.text
    assert response.headers["content-type"] == "application/pdf"
    assert response.headers["content-language"] == language
    assert response.content.startswith(b"%PDF-")
    t = DocumentText(language)
    text, pages = _pdf_text(response.content)
    assert text.startswith(t("report_title"))
    assert answer["id"] in text
    assert f"{t('page')} {pages} {t('of')} {pages}" in text
    number = r"([−-]?[\d.,]+)"
    n_av = re.search(re.escape(_printed(t.words("mean_speed"))) + " " + number, text)
    assert n_av is not None
    assert _read_number(n_av.group(1), language) == pytest.approx(
        answer["mean_speed_rpm"], rel=5e-4
    )  # four significant digits
    assert _printed(f"{n_av.group(0)} {t.unit('rpm')}") in text
    torques = re.compile(
        " ".join(f"{_printed(symbols(s))} = ({number} Nm|–)," for s in ("T_1", "T_2", "T_3"))
        + f" {_printed(symbols('T_rms'))} = ({number} Nm|–)"
    )
    # The first candidate and those asked for, in the answer's order, with their verdict,
    # torques and checks; no other candidate's checks.
    place = 0
    detailed = [
        (rank, c)
        for rank, c in enumerate(answer["candidates"], start=1)
        if rank == 1 or c["model"] in asked
    ]
    assert f"{4}. {answer['candidates'][3]['model']} (" not in text
    for rank, candidate in detailed:
        place = text.index(f"{rank}. {candidate['model']} (", place)
        shown = torques.search(text, place)
        assert shown is not None
        verdict = f": {t('verdict.' + candidate['verdict'])} "
        assert text.index(verdict, place) < shown.start()  # a page's footer may fall between
        if candidate["accel_torque_nm"] is not None:
            values = [_read_number(shown.group(k), language) for k in (2, 4, 6, 8)]
            wanted = [
                candidate[k]
                for k in (
                    "accel_torque_nm",
                    "constant_torque_nm",
                    "decel_torque_nm",
                    "rms_torque_nm",
                )
            ]
            assert values == pytest.approx(wanted, rel=5e-4)
        following = text.find(f"{rank + 1}. ", shown.end())
        block = text[shown.end() : following if following > 0 else None]
        for check in candidate["checks"]:
            assert _printed(t.words(f"check.{check['name']}")) in block, check["name"]
            assert _printed(t(f"result_{check['status']}")) in block


def test_the_pdf_is_german_for_a_german_client(client: TestClient) -> None:
    answer = _selection(client)
    url = f"/api/v1/selections/{answer['id']}/report.pdf"
    german, _ = _pdf_text(client.get(url, params={"lang": "de"}).content)
    english, _ = _pdf_text(
        client.get(url, headers={"Accept-Language": "de"}, params={"lang": "en"}).content
    )
    for word in ("Auswahlbericht", "Lastdrehzahl", "Kandidaten", "Prüfung", "Seite 1 von"):
        assert word in german
        assert word not in english
    assert _printed("min⁻¹") in german
    assert "Selection report" in english


@pytest.mark.parametrize("suffix", ["csv", "pdf"])
def test_unknown_selection_is_404_in_the_error_shape(client: TestClient, suffix: str) -> None:
    response = client.get(f"/api/v1/selections/no-such-selection/report.{suffix}")
    assert response.status_code == 404
    assert response.json() == {
        "detail": [
            {
                "loc": ["path", "selection_id"],
                "msg": "no stored selection 'no-such-selection'",
                "type": "not_found",
                "code": "unknown_selection",
                "params": {"selection_id": "no-such-selection"},
            }
        ]
    }
    german = client.get(
        f"/api/v1/selections/no-such-selection/report.{suffix}", headers={"Accept-Language": "de"}
    )
    assert german.headers["content-language"] == "de"
    (entry,) = german.json()["detail"]
    assert entry["msg"] == "keine gespeicherte Auswahl 'no-such-selection'"
    assert entry["params"] == {"selection_id": "no-such-selection"}


def test_reports_are_in_the_openapi_document(client: TestClient) -> None:
    paths = client.get("/openapi.json").json()["paths"]
    csv_op = paths["/api/v1/selections/{selection_id}/report.csv"]["get"]
    pdf_op = paths["/api/v1/selections/{selection_id}/report.pdf"]["get"]
    assert "text/csv" in csv_op["responses"]["200"]["content"]
    assert "application/pdf" in pdf_op["responses"]["200"]["content"]
    assert "404" in csv_op["responses"]
    assert "404" in pdf_op["responses"]


OUTPUT_LOAD = {
    "radial_force_n": 2000,
    "axial_force_n": 150,
    "radial_lever_m": 0.02,
    "axial_lever_m": 0.01,
    "load_factor": 1.2,
    "static_safety_min": 2,
    "required_life_h": 90000,
}


@pytest.mark.parametrize("language", ["en", "de"])
def test_the_pdfs_inputs_list_the_output_load(client: TestClient, language: Language) -> None:
    """The inputs in words name the external load on the output flange when one was sent
    (issue 29 item 4): forces, levers, f_w, f_s and the required life, with their units;
    and the first page draws both figures, the cycle with its speed and torque panels."""
    from actuator_selection.documents.report_pdf import OUTPUT_LOAD_ROWS, number

    answer = _selection(client, output_load=OUTPUT_LOAD)
    url = f"/api/v1/selections/{answer['id']}/report.pdf"
    text, _ = _pdf_text(client.get(url, params={"lang": language}).content)
    t = DocumentText(language)
    for field, label, unit in OUTPUT_LOAD_ROWS:
        value = number(OUTPUT_LOAD[field], unit, t)
        assert f"{_printed(t.words(label))} {value}" in text, field
    for title in ("fig.time", "fig.speed", "fig.torque", "axis_torque"):
        assert _printed(t(title)) in text, title
    without, _ = _pdf_text(client.get(f"/api/v1/selections/{_selection(client)['id']}/report.pdf",
                                      params={"lang": language}).content)  # fmt: skip
    assert _printed(t.words("output_load_radial_force")) not in without
