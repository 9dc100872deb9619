"""A machine project as one quote (issue 31): a line per axis for its actuator, and one for
its controller where given, priced from the price list like a selection's quote; the
document (HTML and PDF, the PDF read back with pypdf) shows every axis."""

from __future__ import annotations

import copy
import io
import re
from typing import Any

from pypdf import PdfReader
from tests.api._sales_fixtures import SalesApi, api, sales_api_with
from tests.api.test_projects import PICK_AND_PLACE_CELL

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
