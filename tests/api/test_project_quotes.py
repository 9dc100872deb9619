"""A machine project as one quote (issue 31): a line per axis for its actuator, and one for
its controller where given, priced from the price list like a selection's quote; the
document (HTML and PDF, the PDF read back with pypdf) shows every axis."""

from __future__ import annotations

import copy
import gzip
import io
import re
import unicodedata
from dataclasses import replace
from html import unescape
from typing import Any

import orjson
from pypdf import PdfReader
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import WORKED_EXAMPLE, SalesApi, api, sales_api_with
from tests.api.test_projects import PICK_AND_PLACE_CELL

from actuator_selection.db.projects import ProjectRepository

__all__ = ["api", "sales_api_with"]


def _project(api: SalesApi) -> dict[str, Any]:
    """The three-axis cell, each axis with its actuator and (where one runs on the bus) the
    first controller the project lists for it."""
    first = api.client.post("/api/v1/projects", json=PICK_AND_PLACE_CELL).json()
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    for axis, sized in zip(body["axes"], first["axes"], strict=True):
        axis["model"] = sized["model"]
        if sized["controllers"]:
            axis["controller"] = sized["controllers"][0]["source_row"]
    response = api.client.put(f"/api/v1/projects/{first['id']}", json=body)
    assert response.status_code == 200, response.text
    project: dict[str, Any] = response.json()
    return project


def _quote_body(api: SalesApi, project: dict[str, Any], **changes: Any) -> dict[str, Any]:
    body = api.quote_body("unused", **changes)
    for key in ("selection_id", "actuator", "controller"):
        body.pop(key)
    body["project_id"] = project["id"]
    body["axes"] = [
        {
            "quantity": 1,
            **(
                {"controller": {"type_name": "400 V", "item_code": "CTRL-SINAMICS-S120"}}
                if axis["controller"] is not None
                else {}
            ),
        }
        for axis in project["axes"]
    ]
    return body


def _created(api: SalesApi, project: dict[str, Any], **changes: Any) -> dict[str, Any]:
    response = api.post("/api/v1/quotes", json=_quote_body(api, project, **changes))
    assert response.status_code == 201, response.text
    quote: dict[str, Any] = response.json()
    return quote


def test_a_project_is_one_quote_with_a_line_per_axis(api: SalesApi) -> None:
    project = _project(api)
    quote = _created(api, project)
    assert quote["project_id"] == project["id"]
    assert quote["selection_id"] is None
    names = [a["name"] for a in project["axes"]]
    assert [a["name"] for a in quote["axes"]] == names
    assert [a["actuator_model"] for a in quote["axes"]] == [a["model"] for a in project["axes"]]
    lines = [(i["axis"], i["kind"], i["item_code"]) for i in quote["items"]]
    want = []
    for a in project["axes"]:
        want.append((a["name"], "actuator", a["model"]))
        if a["controller"] is not None:
            want.append((a["name"], "controller", "CTRL-SINAMICS-S120"))
    assert lines == want
    for axis, sized in zip(quote["axes"], project["axes"], strict=True):
        if sized["controller"] is None:
            assert axis["controller"] is None
        else:
            assert axis["controller"]["source_row"] == sized["controller"]["source_row"]
    controller_lines = [i for i in quote["items"] if i["kind"] == "controller"]
    assert controller_lines
    for line in controller_lines:
        assert "Table 521.1 row" in line["description"]
    # priced as a selection's quote is: the sum of the lines, each from the price list
    assert sum(float(i["line_total"]) for i in quote["items"]) == float(quote["subtotal"])
    # stored: read back the same
    again = api.get(f"/api/v1/quotes/{quote['number']}")
    assert again.status_code == 200
    assert again.json()["axes"] == quote["axes"]
    assert [i["axis"] for i in again.json()["items"]] == [i["axis"] for i in quote["items"]]


def test_the_document_shows_every_axis(api: SalesApi) -> None:
    project = _project(api)
    quote = _created(api, project)
    html = api.client.get(
        quote["document_url"], headers=api.headers("sales", **{"Accept-Language": "en"})
    )
    assert html.status_code == 200, html.text
    for axis in project["axes"]:
        assert f'data-axis="{axis["name"]}"' in html.text
        assert f"Axis {axis['name']}: " in html.text
        assert axis["model"] in html.text
    assert project["id"] in html.text


def _pdf_text(body: bytes) -> str:
    reader = PdfReader(io.BytesIO(body))
    return re.sub(r"\s+", " ", " ".join(page.extract_text() or "" for page in reader.pages))


def test_the_pdf_read_back_with_pypdf_lists_every_axis(api: SalesApi) -> None:
    project = _project(api)
    quote = _created(api, project)
    for language, axis_word in (("en", "Axis"), ("de", "Achse")):
        response = api.client.get(
            f"/api/v1/quotes/{quote['number']}/document.pdf",
            headers=api.headers("sales", **{"Accept-Language": language}),
        )
        assert response.status_code == 200, response.text
        text = _pdf_text(response.content)
        for axis in project["axes"]:
            assert f"{axis_word} {axis['name']}:" in text, (language, axis["name"], text)
            assert axis["model"] in text
        for axis in quote["axes"]:
            if axis["controller"] is not None:
                assert f"{axis['controller']['source_row']}" in text


def test_refusals_name_the_field(api: SalesApi) -> None:
    project = _project(api)
    body = _quote_body(api, project)
    body["axes"] = body["axes"][:1]
    response = api.post("/api/v1/quotes", json=body)
    assert response.status_code == 422, response.text
    assert response.json()["detail"][0]["loc"] == ["body", "axes"]
    assert response.json()["detail"][0]["code"] == "project_axes"

    body = _quote_body(api, project)
    body["project_id"] = "no-such-project"
    response = api.post("/api/v1/quotes", json=body)
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["body", "project_id"]

    body = _quote_body(api, project)
    k = next(k for k, a in enumerate(project["axes"]) if a["controller"] is not None)
    listed = {c["source_row"] for c in project["axes"][k]["controllers"]}
    body["axes"][k]["controller"]["source_row"] = max(listed) + 1000
    response = api.post("/api/v1/quotes", json=body)
    assert response.status_code == 422, response.text
    assert response.json()["detail"][0]["loc"] == ["body", "axes", k, "controller", "source_row"]

    both = _quote_body(api, project)
    both["selection_id"] = api.selection(models=["FHA-25C-50-L"])["id"]
    response = api.client.post(
        "/api/v1/quotes", json=both, headers=api.headers("sales", **{"Accept-Language": "de"})
    )
    assert response.status_code == 422
    assert response.json()["detail"][0]["type"] == "quote_source"
    assert "Maschinenprojekt" in response.json()["detail"][0]["msg"]


UNCONFIRMED_AXIS: dict[str, Any] = {
    "name": "W",
    "offset_s": 0.0,
    **WORKED_EXAMPLE,
    "cycle": {**WORKED_EXAMPLE["cycle"], "pause_s": 2.1},  # the cell's 2.4 s machine cycle
    "model": "FHA-25C-50-L",
}
"""The chapter's worked example as an axis of the cell, on its FHA-25C-50-L: unconfirmed,
the entry publishes no continuous-duty data (tests/api/test_quotes.py)."""


def _banner(html: str) -> list[str]:
    """The reasons the document's unconfirmed banner lists, as text."""
    found = re.search(r'data-field="unconfirmed">.*?<ul>(.*?)</ul>', html, re.S)
    assert found is not None, html
    items = re.findall(r"<li>(.*?)</li>", found.group(1), re.S)
    return [unescape(re.sub(r"<[^>]+>", "", item)) for item in items]


def _document(api: SalesApi, number: str, language: str, pdf: bool = False) -> Any:
    response = api.client.get(
        f"/api/v1/quotes/{number}/document{'.pdf' if pdf else ''}",
        headers=api.headers("sales", **{"Accept-Language": language}),
    )
    assert response.status_code == 200, response.text
    return response


def test_an_unconfirmed_axis_is_quoted_with_its_checks_as_a_selection_is(api: SalesApi) -> None:
    """Each axis that is not confirmed suitable carries the checks that did not pass, in the
    answer and in the document (HTML and PDF, English and German), worded as the quote of a
    selection of the same load case words them."""
    cell = {**PICK_AND_PLACE_CELL, "axes": [*PICK_AND_PLACE_CELL["axes"], UNCONFIRMED_AXIS]}
    project = api.client.post("/api/v1/projects", json=cell).json()
    assert [a["verdict"] for a in project["axes"]] == ["suitable"] * 3 + ["unconfirmed"]
    quote = _created(api, project)
    assert quote["verdict"] == "unconfirmed"
    *confirmed, axis = quote["axes"]
    assert [a["verdict_reasons"] for a in confirmed] == [[], [], []]
    # the same load case as a selection, quoted on the same actuator
    selection = api.selection(models=["FHA-25C-50-L"], cycle=UNCONFIRMED_AXIS["cycle"])
    alone = api.post("/api/v1/quotes", json=api.quote_body(selection["id"])).json()
    assert alone["verdict_reasons"]
    assert axis["verdict_reasons"] == alone["verdict_reasons"]
    assert quote["verdict_reasons"] == [f"axis W: {r}" for r in alone["verdict_reasons"]]
    for language, on_axis in (("en", "Axis W: "), ("de", "Achse W: ")):
        reasons = _banner(_document(api, alone["number"], language).text)
        assert reasons
        assert _banner(_document(api, quote["number"], language).text) == [
            on_axis + r for r in reasons
        ]
        text = _pdf_text(_document(api, quote["number"], language, pdf=True).content)
        for reason in reasons:
            # the PDF writes subscripts as such (nₐᵥ): compared in their compatibility form
            flat = re.sub(r"\s+", "", unicodedata.normalize("NFKC", text))
            assert re.sub(r"\s+", "", on_axis + reason) in flat, (language, reason, text)


def test_a_project_quote_names_no_actuator_of_its_own(api: SalesApi) -> None:
    """A project's quote quotes an actuator per axis: ``actuator_model`` is null (not the
    first axis's), the models are the axes' and the lines'; as stored, listed and read back
    (a quote stored before this rule holds the first axis's in its row: read the same)."""
    project = _project(api)
    quote = _created(api, project)
    assert quote["actuator_model"] is None
    models = [a["model"] for a in project["axes"]]
    assert [a["actuator_model"] for a in quote["axes"]] == models
    assert [i["item_code"] for i in quote["items"] if i["kind"] == "actuator"] == models
    assert api.get(f"/api/v1/quotes/{quote['number']}").json()["actuator_model"] is None
    listed = api.get("/api/v1/quotes", params={"q": quote["number"]}).json()["quotes"]
    assert [q["actuator_model"] for q in listed] == [None]
    selection = api.selection(models=["FHA-25C-50-L"])
    alone = api.post("/api/v1/quotes", json=api.quote_body(selection["id"])).json()
    assert alone["actuator_model"] == "FHA-25C-50-L"
    schema = api.client.get("/openapi.json").json()["components"]["schemas"]["QuoteOut"]
    assert {"type": "null"} in schema["properties"]["actuator_model"]["anyOf"]


def test_a_project_stored_before_it_kept_its_checks_is_quoted_as_before(
    api: SalesApi, session: Session
) -> None:
    """A project stored before its axes' checks were (``checks`` absent): quoted, the
    unconfirmed axis named as it was; sized again, with its checks."""
    cell = {**PICK_AND_PLACE_CELL, "axes": [*PICK_AND_PLACE_CELL["axes"], UNCONFIRMED_AXIS]}
    project = api.client.post("/api/v1/projects", json=cell).json()
    repository = ProjectRepository(session)
    stored = repository.get(project["id"])
    assert stored is not None
    answer = orjson.loads(gzip.decompress(stored.answer_gzip))
    for axis in answer["axes"]:
        del axis["checks"]
    assert repository.replace(replace(stored, answer_gzip=gzip.compress(orjson.dumps(answer))))
    session.commit()
    assert (
        api.client.get(f"/api/v1/projects/{project['id']}").json()["axes"][3].get("checks") is None
    )
    quote = _created(api, project)
    assert quote["verdict"] == "unconfirmed"
    assert [a["verdict_reasons"] for a in quote["axes"]] == [[], [], [], []]
    assert quote["verdict_reasons"] == ["axis W: FHA-25C-50-L unconfirmed"]
    for language in ("en", "de"):
        assert _banner(_document(api, quote["number"], language).text) == [
            "axis W: FHA-25C-50-L unconfirmed"
        ]
        _document(api, quote["number"], language, pdf=True)
    assert api.client.post(f"/api/v1/projects/{project['id']}/size").status_code == 200
    assert _created(api, project)["axes"][3]["verdict_reasons"]


def test_an_unsuitable_axis_is_refused_naming_its_failing_checks(api: SalesApi) -> None:
    """As a selection's unsuitable candidate is refused: 422 at the axis, naming the checks
    that fail."""
    axis = {**UNCONFIRMED_AXIS, "model": "CHA-14A-E-30"}
    cell = {**PICK_AND_PLACE_CELL, "axes": [*PICK_AND_PLACE_CELL["axes"], axis]}
    project = api.client.post("/api/v1/projects", json=cell).json()
    assert project["axes"][3]["verdict"] == "unsuitable"
    response = api.post("/api/v1/quotes", json=_quote_body(api, project))
    assert response.status_code == 422, response.text
    (error,) = response.json()["detail"]
    assert (error["loc"], error["type"]) == (["body", "axes", 3], "unsuitable")
    failing = [c["name"] for c in project["axes"][3]["checks"] if c["status"] == "fail"]
    assert failing
    assert error["msg"].startswith("CHA-14A-E-30 is unsuitable")
    for name in failing:
        assert f"{name}: " in error["msg"], (name, error["msg"])
