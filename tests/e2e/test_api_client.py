"""The pages' one API client (``frontend/lib/api.js``) and plotly.js loader (``lib/plotly.js``).

Error bodies come in two shapes today: ``{"detail": [{loc, msg, type}, …]}`` (400, 413,
422) and ``{"detail": "…"}`` (401, 403, 404, 409). The list shape is to become the only
one; these tests answer the pages' requests with it where the server still sends the
string, and check that the pages say the same.
"""

from __future__ import annotations

import re
from typing import Any, cast

import pytest
from playwright.sync_api import Page, Route, expect

from .conftest import Traffic
from .test_engineer_page import post_selection, wait_for_charts

pytestmark = pytest.mark.browser


def _list_shaped(route: Route, status: int, msg: str) -> None:
    body = {"detail": [{"loc": ["header", "authorization"], "msg": msg, "type": "auth"}]}
    route.fulfill(status=status, json=body)


def test_error_bodies_of_either_shape_make_the_same_error(page: Page) -> None:
    page.goto("/")
    result = cast(
        dict[str, Any],
        page.evaluate(
            """async () => {
      const { errorFromBody } = await import('/lib/api.js');
      const plain = (e) => ({status: e.status, detail: e.detail, message: e.message,
                             fieldErrors: e.fieldErrors, kind: e.kind});
      return {
        string404: plain(errorFromBody(404, {detail: "no quote 'Q-1'"})),
        list404: plain(errorFromBody(404, {detail: [{loc: ["path", "number"],
                                                     msg: "no quote 'Q-1'", type: "not_found"}]})),
        list422: plain(errorFromBody(422, {detail: [
          {loc: ["body", "cycle", "accel_s"], msg: "must be > 0", type: "greater_than"},
          {loc: ["body", "load"], msg: "field required", type: "missing"}]})),
        bare401: plain(errorFromBody(401, {detail: [{msg: "invalid API key"}]})),
        empty: plain(errorFromBody(502, null)),
        other: plain(errorFromBody(500, {detail: 42})),
      };
    }"""
        ),
    )
    assert result["string404"]["detail"] == "no quote 'Q-1'"
    assert result["string404"]["fieldErrors"] == []
    assert result["list404"]["detail"] == "no quote 'Q-1'"
    assert result["list404"]["message"] == "no quote 'Q-1'"
    assert result["list422"]["fieldErrors"][0] == {
        "loc": ["body", "cycle", "accel_s"],
        "msg": "must be > 0",
        "type": "greater_than",
        "code": "greater_than",  # an answer without a code: its type stands in
        "lang": "en",  # no Content-Language: the server's default
    }
    assert result["list422"]["detail"] == "must be > 0; field required"
    assert result["bare401"]["fieldErrors"] == [
        {"loc": [], "msg": "invalid API key", "type": "", "code": "", "lang": "en"}
    ]
    assert result["bare401"]["message"] == "invalid API key"
    assert result["empty"] == {
        "status": 502,
        "detail": None,
        "message": "HTTP 502",
        "fieldErrors": [],
        "kind": "http",
    }
    assert result["other"]["detail"] is None


def test_sales_page_takes_a_list_shaped_401_as_a_rejected_key(page: Page) -> None:
    page.route("**/api/v1/auth/me", lambda route: _list_shaped(route, 401, "invalid API key"))
    page.goto("/sales.html")
    page.fill("#api-key", "not-a-key")
    page.locator("#key-form button[type=submit]").click()
    rejected = "The API key was not accepted. Enter a valid key."
    expect(page.locator("#key-error")).to_have_text(rejected)
    expect(page.locator("#key-panel")).to_be_visible()
    expect(page.locator("#create-panel")).to_be_hidden()
    assert page.evaluate("() => sessionStorage.length") == 0


def test_engineer_page_names_a_list_shaped_404(page: Page) -> None:
    page.route(
        "**/api/v1/selections/gone",
        lambda route: _list_shaped(route, 404, "no selection 'gone'"),
    )
    page.goto("/?selection=gone")
    expect(page.locator("#results-alert")).to_contain_text(
        "Stored selection not found: no selection 'gone'"
    )


def test_charts_drawn_when_the_pages_own_bundle_fails(page: Page, traffic: Traffic) -> None:
    """A page naming a bundle the server no longer has: the loader asks where it is now."""
    failed: list[str] = []

    def first_fails(route: Route) -> None:
        if not failed:
            failed.append(route.request.url)
            route.fulfill(status=404, body="gone")
        else:
            route.continue_()

    page.route(re.compile(r"/vendor/plotly-basic-[\d.]+\.min\.js$"), first_fails)
    page.goto("/")
    page.locator("#example").click()
    post_selection(page)
    wait_for_charts(page)
    assert failed
    assert any(url.endswith("/vendor/plotly.js") for url in traffic.requests)
    assert page.evaluate("() => typeof window.Plotly.react") == "function"
