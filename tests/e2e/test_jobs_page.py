"""The batch jobs page (issue 32 item 4): a job submitted there shows its progress bar
until it is done, then offers its results; German labels in a German session."""

from __future__ import annotations

import json

import httpx
from playwright.sync_api import Page, expect

from .conftest import Traffic

JOB_WAIT_MS = 180_000
"""A deadline for 600 cases on two shared cores, not an expectation."""


def test_a_job_submitted_on_the_page_runs_to_done_with_its_progress_bar(
    page: Page, base_url: str, traffic: Traffic
) -> None:
    page.goto("/jobs.html")
    page.fill("#job-example-count", "600")
    page.click("#job-example")
    assert len(page.input_value("#job-cases").splitlines()) == 600
    page.click("#job-submit")
    expect(page.locator("#job-section")).to_be_visible()
    expect(page.locator("#job-results")).to_be_visible(timeout=JOB_WAIT_MS)
    assert page.locator("#job-progress").evaluate("bar => bar.value") == 1
    expect(page.locator("#job-status")).to_contain_text("done · 600 of 600 cases (100 %)")
    expect(page.locator("#job-cancel")).to_be_hidden()
    href = page.locator("#job-results").get_attribute("href")
    assert href is not None
    lines = httpx.get(f"{base_url}{href}").text.splitlines()
    assert [json.loads(line)["case_id"] for line in lines] == [
        f"example-{i + 1}" for i in range(600)
    ]
    csv_href = page.locator("#job-results-csv").get_attribute("href")
    assert csv_href == f"{href}?format=csv"
    assert httpx.get(f"{base_url}{csv_href}").text.startswith("case,case_id,")
    assert not traffic.console_errors


def test_a_refused_job_names_the_line_in_german(page: Page) -> None:
    page.goto("/jobs.html")
    page.click("button[data-lang=de]")
    expect(page.locator("#job-submit")).to_have_text("Auftrag starten")
    page.fill("#job-cases", "")
    page.click("#job-submit")
    expect(page.locator("#job-error")).to_contain_text("mindestens einen Lastfall")
    expect(page.locator("#job-section")).to_be_hidden()
