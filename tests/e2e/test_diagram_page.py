"""The speed/torque diagram on the page is the figure the documents print: the page draws
the API's figure (``GET …/candidates/{model}/diagram``, from ``api/figures.py``, the
definition the quote's HTML and the PDFs draw) and keeps plotly.js's interactivity."""

from __future__ import annotations

from typing import Any, cast

import pytest
from playwright.sync_api import Page

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
        drawn = traces(page, "chart-diagram")
        assert list(drawn) == [t["uid"] for t in figure["data"]]
        for trace in figure["data"]:
            shown = drawn[trace["uid"]]
            assert (shown["x"], shown["y"]) == (trace["x"], trace["y"]), trace["uid"]
            assert shown["name"] == trace["name"], trace["uid"]  # a wide chart: not wrapped
    # still plotly.js's chart: hover labels and the mode bar
    assert page.locator("#chart-diagram .modebar").count() == 1
    assert page.evaluate("document.getElementById('chart-diagram').layout.hovermode") == "closest"
