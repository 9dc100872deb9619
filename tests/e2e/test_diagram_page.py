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


# When the chosen candidate's panel first appears.
PANEL_SEEN = """
(() => {
  new MutationObserver((_, observer) => {
    if (document.getElementById("detail")) {
      window.__panelAt = performance.now();
      observer.disconnect();
    }
  }).observe(document, {subtree: true, childList: true});
})();
"""


def test_the_chart_data_is_asked_before_the_results_are_drawn(page: Page) -> None:
    """The best candidate's detail and both figures are asked as soon as the selection
    answers, so that the server answers them while the page lays the results out (the results
    then wait a moment at most for the detail, to draw the panel once, with it)."""
    page.add_init_script(PANEL_SEEN)
    page.goto("/")
    fill_worked_example(page)
    _, body = post_selection(page)
    model = body["candidates"][0]["model"]
    timing = cast(
        dict[str, list[float]],
        page.evaluate(
            """model => Object.fromEntries(performance.getEntriesByType("resource")
                 .filter((e) => e.name.includes(`/candidates/${model}`))
                 .map((e) => [new URL(e.name).pathname.split("/").pop(),
                              [e.startTime, e.responseEnd]]))""",
            model,
        ),
    )
    assert set(timing) == {model, "cycle", "diagram"}
    panel_at = page.evaluate("() => window.__panelAt")
    assert all(started < panel_at for started, _ in timing.values()), (timing, panel_at)
    # Whether the detail came within the page's wait (DETAIL_WAIT_MS) is the machine's
    # speed, not the page's order: not asserted (no timing in tests).
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
