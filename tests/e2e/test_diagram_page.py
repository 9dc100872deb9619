"""The speed/torque diagram and the cycle chart on the page are the figures the documents
print: the page draws the API's figures (``GET …/candidates/{model}/diagram`` and
``…/cycle``, from ``documents/figures.py``, the definitions the quote's HTML and the PDFs draw)
and keeps plotly.js's interactivity."""

from __future__ import annotations

from typing import Any, cast

import pytest
from playwright.sync_api import Page, expect

from .test_engineer_page import FHA, choose, fill_worked_example, post_selection, traces

pytestmark = pytest.mark.browser


def test_the_page_draws_the_apis_figure(page: Page) -> None:
    page.goto("/")
    fill_worked_example(page)
    _, body = post_selection(page)
    choose(page, FHA)
    for lang in ("en", "de"):
        if lang == "de":
            page.get_by_role("button", name="Deutsch").click()
            page.wait_for_function(
                "() => document.getElementById('chart-diagram').layout?.separators === ',.'"
            )
        answer = page.request.get(
            f"/api/v1/selections/{body['id']}/candidates/{FHA}/diagram", params={"lang": lang}
        )
        assert answer.ok
        figure = cast(dict[str, Any], answer.json())
        cycle = page.request.get(
            f"/api/v1/selections/{body['id']}/candidates/{FHA}/cycle", params={"lang": lang}
        )
        assert cycle.ok
        assert cycle.json()["layout"]["meta"] == {"torques": "segments"}
        expect(page.locator("#chart-cycle")).to_have_attribute("data-torques", "detail")
        _same_traces(page, "chart-cycle", cast(dict[str, Any], cycle.json()))
        drawn = traces(page, "chart-diagram")
        assert list(drawn) == [t["uid"] for t in figure["data"]]
        for trace in figure["data"]:
            shown = drawn[trace["uid"]]
            assert (shown["x"], shown["y"]) == (trace["x"], trace["y"]), trace["uid"]
            assert shown["name"] == trace["name"], trace["uid"]  # a wide chart: not wrapped
    # still plotly.js's chart: hover labels and the mode bar
    assert page.locator("#chart-diagram .modebar").count() == 1
    assert page.evaluate("document.getElementById('chart-diagram').layout.hovermode") == "closest"


def _same_traces(page: Page, chart: str, figure: dict[str, Any]) -> None:
    """The chart ``chart`` draws ``figure``'s traces, in its order, with its points and names,
    and its axes' titles."""
    drawn = traces(page, chart)
    assert list(drawn) == [t["uid"] for t in figure["data"]]
    for trace in figure["data"]:
        shown = drawn[trace["uid"]]
        assert (shown["x"], shown["y"]) == (trace["x"], trace["y"]), trace["uid"]
        assert shown["name"] == trace["name"], trace["uid"]
    titles = page.evaluate(
        f"""() => {{
          const layout = document.getElementById('{chart}').layout;
          return [layout.xaxis.title.text, layout.yaxis.title.text, layout.separators];
        }}"""
    )
    layout = figure["layout"]
    assert titles == [
        layout["xaxis"]["title"]["text"],
        layout["yaxis"]["title"]["text"],
        layout["separators"],
    ]
