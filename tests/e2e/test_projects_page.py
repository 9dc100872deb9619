"""The machine project page in Chromium (issue 31): three axes of a pick-and-place entered,
sized on one DC bus, drawn as a stacked power chart with the bus summary; kept at its
permalink, edited, and refused at the field where an axis is wrong."""

from __future__ import annotations

import re

import httpx
import pytest
from playwright.sync_api import Page, expect

from .conftest import Traffic

pytestmark = pytest.mark.browser
SLOW_MS = 20_000
"""Timeout for steps that wait for the server or for plotly.js under a loaded CI."""


def test_a_pick_and_place_is_sized_on_one_bus_and_kept(
    page: Page, base_url: str, traffic: Traffic
) -> None:
    page.goto("/projects.html")
    expect(page.locator("html[data-ready='true']")).to_have_count(1)
    page.get_by_role("button", name="English").click()
    page.get_by_role("button", name="Example: pick-and-place (three axes)").click()
    expect(page.locator("#axes fieldset")).to_have_count(3)
    page.get_by_label("Name", exact=True).fill("Cell 7")
    page.get_by_role("button", name="Size the machine").click()
    expect(page.locator("#status")).to_have_text("3 axis/axes sized and stored.", timeout=SLOW_MS)
    expect(page).to_have_url(re.compile(r"\?id=[0-9a-f-]{36}$"))
    project_id = page.url.split("=")[-1]
    stored = httpx.get(f"{base_url}/api/v1/projects/{project_id}").json()
    # the chart stacks one trace per axis
    chart = page.locator("#power-chart")
    expect(chart).to_have_attribute("data-traces", "3", timeout=SLOW_MS)
    expect(chart.locator(".scatterlayer .trace")).to_have_count(3)
    # the summary shows the API's figures
    regen = page.locator("#bus-summary tr[data-row='regen_energy'] td")
    assert stored["bus"]["power"]["regen_energy_j"] > 0
    expect(regen).to_contain_text("J")
    expect(page.locator("#bus-summary tr[data-row='resistor'] td")).to_have_text("needed")
    expect(page.locator("#bus-summary tr[data-row='capacitor'] td")).to_have_text("no data")
    expect(page.locator("#bus-summary tr[data-row='resistance'] td")).to_contain_text("≤")
    rows = page.locator("#axes-table tbody tr")
    expect(rows).to_have_count(3)
    for k, axis in enumerate(stored["axes"]):
        expect(rows.nth(k).locator("td").nth(1)).to_have_text(axis["model"])
    # the permalink shows it again, in German
    page.goto(f"/projects.html?id={project_id}")
    page.get_by_role("button", name="Deutsch").click()
    expect(page.locator("#p-name")).to_have_value("Cell 7")
    expect(page.locator("#bus-summary tr[data-row='resistor'] td")).to_have_text("nötig")
    heading = page.get_by_role("heading", name="Der Zwischenkreis über den Maschinenzyklus")
    expect(heading).to_be_visible()
    # an edit: the wrist later in the cycle, stored in place
    page.locator("#axis-2-offset_s").fill("1.5")
    page.get_by_role("button", name="Maschine auslegen").click()
    expect(page.locator("#status")).to_have_text(
        "3 Achse(n) ausgelegt und gespeichert.", timeout=SLOW_MS
    )
    edited = httpx.get(f"{base_url}/api/v1/projects/{project_id}").json()
    assert edited["request"]["axes"][2]["offset_s"] == 1.5
    assert edited["created_at"] == stored["created_at"]
    assert not traffic.console_errors


def test_an_unknown_actuator_is_refused_at_its_axis(page: Page) -> None:
    page.goto("/projects.html")
    expect(page.locator("html[data-ready='true']")).to_have_count(1)
    page.get_by_role("button", name="English").click()
    page.get_by_role("button", name="Example: pick-and-place (three axes)").click()
    page.get_by_label("Name", exact=True).fill("Cell 8")
    page.locator("#axis-1-model").fill("NO-SUCH-ACTUATOR")
    page.get_by_role("button", name="Size the machine").click()
    expect(page.locator("#status")).to_contain_text("Refused", timeout=SLOW_MS)
    expect(page.locator("#axis-1-model")).to_have_attribute("aria-invalid", "true")
    expect(page.locator("#axis-0-model")).not_to_have_attribute("aria-invalid", "true")


def test_a_controller_is_chosen_per_axis_from_the_matching_ones(
    page: Page, base_url: str, traffic: Traffic
) -> None:
    page.goto("/projects.html")
    expect(page.locator("html[data-ready='true']")).to_have_count(1)
    page.get_by_role("button", name="English").click()
    page.get_by_role("button", name="Example: pick-and-place (three axes)").click()
    page.get_by_label("Name", exact=True).fill("Cell 9")
    page.get_by_role("button", name="Size the machine").click()
    expect(page).to_have_url(re.compile(r"\?id=[0-9a-f-]{36}$"), timeout=SLOW_MS)
    project_id = page.url.split("=")[-1]
    stored = httpx.get(f"{base_url}/api/v1/projects/{project_id}").json()
    # the choice offers exactly the controllers the answer lists for the axis
    listed = [str(c["source_row"]) for c in stored["axes"][0]["controllers"]]
    assert listed
    select = page.locator("#axis-0-controller")
    expect(select.locator("option")).to_have_count(len(listed) + 1)
    select.select_option(listed[0])
    page.get_by_role("button", name="Size the machine").click()
    expect(page.locator("#status")).to_have_text("3 axis/axes sized and stored.", timeout=SLOW_MS)
    edited = httpx.get(f"{base_url}/api/v1/projects/{project_id}").json()
    assert edited["request"]["axes"][0]["controller"] == int(listed[0])
    cell = page.locator("#axes-table tbody tr").nth(0).locator("td").nth(3)
    expect(cell).to_contain_text(edited["axes"][0]["controller"]["name"])
    expect(page.locator("#quote-link")).to_have_attribute(
        "href", f"/sales.html?project={project_id}"
    )
    aasx = page.locator("#aas-link").get_attribute("href")
    assert aasx == f"/api/v1/projects/{project_id}/aas.aasx"
    assert httpx.get(f"{base_url}{aasx}").status_code == 200
    assert not traffic.console_errors
