"""The ratio study on the engineer's page (issue 31 part 1): asked for the request on the
form, its table of intervals shown and its chart drawn as the API defines it (the
answer's ``figure``, ``documents/figures.py: ratio_figure``): the same traces, points and names."""

from __future__ import annotations

from typing import Any, cast

import pytest
from playwright.sync_api import Page, expect

from .test_engineer_page import fill_worked_example, post_selection, traces

pytestmark = pytest.mark.browser


def test_the_page_draws_the_ratio_studys_chart(page: Page) -> None:
    page.goto("/")
    fill_worked_example(page)
    post_selection(page)
    page.locator("#ratio-variable").select_option("ratio")
    page.locator("#ratio-min").fill("1")
    page.locator("#ratio-max").fill("20")
    with page.expect_response(lambda r: "/api/v1/selections/ratio-study" in r.url) as info:
        page.locator("#ratio-run").click()
    answer = cast(dict[str, Any], info.value.json())
    assert info.value.status == 200
    figure = answer["figure"]
    expect(page.locator("#chart-ratio")).to_have_attribute("data-state", "ready")
    fitting = [a for a in answer["actuators"] if a["intervals"]]
    assert fitting
    rows = page.locator("#ratio-table tbody tr")
    expect(rows).to_have_count(min(10, len(fitting)))
    expect(rows.first.locator("th")).to_have_text(fitting[0]["model"])
    drawn = traces(page, "chart-ratio")
    assert list(drawn) == [t["uid"] for t in figure["data"]]
    assert any(uid.startswith("ratio-band-") for uid in drawn)
    for trace in figure["data"]:
        shown = drawn[trace["uid"]]
        assert (shown["x"], shown["y"]) == (trace["x"], trace["y"]), trace["uid"]
        assert shown["name"] == trace["name"], trace["uid"]
    # the same study asked of the API directly draws the same figure
    again = page.request.post(
        "/api/v1/selections/ratio-study?figure=true&lang=en",
        data={
            "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
            "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1},
            "ratio_study": {"variable": "ratio", "min": 1, "max": 20},
        },
    )
    assert again.ok
    assert [t["uid"] for t in again.json()["figure"]["data"]] == list(drawn)
