"""axe-core over both pages in the states a user sees them (issue 13): the form, results
with a candidate's detail, stale results after an edit, the segment editor and a machine
axis, the limits table, the comparison of candidates (a fifth mark refused), both
languages, and the sales page's key prompt. No serious or critical violation of WCAG 2
A/AA.

axe-core comes from the npm lock (node_modules/axe-core, a dev dependency installed by
``make install``; never served by the app) and is injected into a context that bypasses
the pages' Content-Security-Policy, which otherwise refuses any script not served by the
app itself (as it should).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any, cast

import pytest
from playwright.sync_api import Browser, Page

from .conftest import DESKTOP, SalesSite
from .test_engineer_page import fill_worked_example, post_selection
from .test_sales_page import selection_id, sign_in

pytestmark = pytest.mark.browser

AXE = Path(__file__).resolve().parents[2] / "node_modules" / "axe-core" / "axe.min.js"
BLOCKING = ("serious", "critical")


@pytest.fixture
def axe_page(browser: Browser, base_url: str) -> Iterator[Page]:
    assert AXE.is_file(), "axe-core is missing: run `make install` (npm ci)"
    context = browser.new_context(
        viewport=DESKTOP, locale="en-US", base_url=base_url, bypass_csp=True
    )
    context.set_default_timeout(15_000)
    try:
        yield context.new_page()
    finally:
        context.close()


def violations(page: Page) -> list[dict[str, Any]]:
    """The serious and critical WCAG 2 A/AA violations axe finds on the page as it is."""
    if not page.evaluate("() => typeof window.axe === 'object'"):
        page.add_script_tag(path=str(AXE))
    found = cast(
        list[dict[str, Any]],
        page.evaluate(
            """async () => {
              const result = await axe.run(document, {
                runOnly: {type: "tag", values: ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]},
              });
              return result.violations.map((v) => ({
                id: v.id, impact: v.impact, help: v.help,
                nodes: v.nodes.map((n) => n.target.join(" ")).slice(0, 5),
              }));
            }"""
        ),
    )
    return [v for v in found if v["impact"] in BLOCKING]


def test_the_engineers_page_in_every_state(axe_page: Page) -> None:
    page = axe_page
    page.goto("/")
    assert violations(page) == [], "form"
    fill_worked_example(page)
    status, _ = post_selection(page)
    assert status == 201
    page.wait_for_selector('#detail[data-detail="ready"]')
    assert violations(page) == [], "results with the detail"
    page.locator("#limits-button").click()
    page.wait_for_selector("#limits-table")
    assert violations(page) == [], "limits"
    for model in page.locator("#ranking-table .compare-toggle").evaluate_all(
        "boxes => boxes.slice(0, 3).map(b => b.dataset.model)"
    ):
        page.locator(f'#ranking-table .compare-toggle[data-model="{model}"]').check()
    page.wait_for_selector("#compare-table thead th[data-model] >> nth=2")
    assert violations(page) == [], "comparison of three candidates"
    page.locator("#ranking-table .compare-toggle:not(:checked)").first.check()
    page.locator("#ranking-table .compare-toggle:not(:checked)").first.click()
    page.wait_for_selector("#compare-status:has-text('at most 4')")
    assert violations(page) == [], "comparison with a fifth mark refused"
    page.locator("#f-direct-torque_nm").fill("6")  # an edit makes the results stale
    page.wait_for_selector("#results.is-stale")
    assert violations(page) == [], "stale results"
    page.get_by_role("button", name="Deutsch").click()
    assert violations(page) == [], "German"


def test_nothing_fits_and_a_limit_without_a_value(axe_page: Page) -> None:
    """The "why nothing fits" panel (issue 29 item 7) and a limits row with its reason."""
    page = axe_page
    page.goto("/")
    fill_worked_example(page)
    page.locator("#f-speed").fill("1000")  # above every n_max of the catalogue
    status, body = post_selection(page)
    assert status == 201
    assert body["binding"] is not None
    page.wait_for_selector("#binding")
    page.wait_for_selector('#detail[data-detail="ready"]')
    page.locator("#limits-button").click()
    page.wait_for_selector("#limits-table .limit-reason")
    assert violations(page) == [], "nothing fits, with the limits"


def test_the_segment_editor_and_a_machine_axis(axe_page: Page) -> None:
    page = axe_page
    page.goto("/")
    page.get_by_label("Belt axis").check()
    page.get_by_label("Segments (several moves").check()
    assert violations(page) == [], "segment editor with the belt axis"


def test_the_checks_asked_for_unfolded(axe_page: Page) -> None:
    """The brake's fields, the gear's and the stiffness' (issue 28) open, one refused."""
    page = axe_page
    page.goto("/")
    page.locator("#f-brake").check()
    page.locator("#more-checks > summary").click()
    page.locator("#f-gear").check()
    page.locator("#f-gear-momentary_count").press_sequentially("1.000,5")
    page.locator("#f-gear-momentary_count").press("Tab")
    page.wait_for_selector("#err-f-gear-momentary_count:not([hidden])")
    assert violations(page) == [], "gear, stiffness and brake fields"


def test_number_fields_with_their_reading_and_a_refusal(axe_page: Page) -> None:
    page = axe_page
    page.goto("/")
    page.locator("#f-t1").press_sequentially("0,15")  # "read as 0.15" beside it
    page.locator("#f-direct-inertia_kgm2").press_sequentially("1.300,5")  # refused at the field
    page.locator("#f-direct-inertia_kgm2").press("Tab")
    page.wait_for_selector("#err-f-direct-inertia_kgm2:not([hidden])")
    page.wait_for_selector("#read-f-t1:not([hidden])")
    assert violations(page) == [], "a number's reading and a refused number"


def test_the_batch_jobs_page_with_a_job_and_a_refusal(axe_page: Page) -> None:
    page = axe_page
    page.goto("/jobs.html")
    page.wait_for_selector("#job-form")
    assert violations(page) == [], "an empty form"
    page.fill("#job-example-count", "20")
    page.click("#job-example")
    page.click("#job-submit")
    page.wait_for_selector("#job-results:not([hidden])", timeout=120_000)
    assert violations(page) == [], "a job done"
    page.fill("#job-cases", "")
    page.click("#job-submit")
    page.wait_for_selector("#job-error .notice")
    assert violations(page) == [], "a refused job"


def test_the_sales_pages_key_prompt(axe_page: Page) -> None:
    page = axe_page
    page.goto("/sales.html")
    page.wait_for_selector("form")
    assert violations(page) == [], "key prompt"


def test_the_sales_page_signed_in_with_a_selection(browser: Browser, site: SalesSite) -> None:
    context = browser.new_context(
        viewport=DESKTOP, locale="de-DE", base_url=site.url, bypass_csp=True
    )
    context.set_default_timeout(15_000)
    try:
        page = context.new_page()
        chosen = selection_id(site, ["FHA-25C-50-L", "FHA-8C-30"])
        page.goto(f"/sales.html?selection={chosen}")
        sign_in(page, site.sales_key)
        page.wait_for_selector("#f-model option", state="attached")
        assert violations(page) == [], "quote form with the selection"
    finally:
        context.close()
