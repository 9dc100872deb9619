"""The engineer page shows the detail's check messages in the language the server wrote them
in (its Content-Language): German on a German page."""

from __future__ import annotations

from playwright.sync_api import Page, expect
from tests.e2e.test_engineer_page import FHA, fill_worked_example, is_detail


def test_a_german_page_shows_the_details_german_check_message(page: Page) -> None:
    page.goto("/")
    page.get_by_role("button", name="Deutsch").click()
    fill_worked_example(page)
    page.locator("#f-models").fill(FHA)
    with page.expect_response(lambda r: is_detail(r.url)) as info:
        page.locator("#submit").click()
    answer = info.value
    assert answer.status == 200
    assert answer.headers["content-language"] == "de"
    page.wait_for_selector(f'#detail[data-model="{FHA}"][data-detail="ready"]')
    message = page.locator('#checks-table tr[data-check="peak_torque"] td.message [lang]')
    expect(message).to_have_attribute("lang", "de")
    # symbols are drawn with subscripts (T₁ as T<sub>1</sub>)
    expect(message).to_contain_text("Beschleunigungsmoment T")
    expect(message).to_contain_text("= 95,48 Nm ≤ T")
    speed = page.locator('#checks-table tr[data-check="max_speed"] td.message [lang]')
    expect(speed).to_contain_text("min⁻¹")
    reason = page.locator("#detail .reasons .api-message").first
    expect(reason).to_have_attribute("lang", "de")
    expect(reason).to_contain_text("keine Daten")

    # in English once the page is English: the server's English words, marked as English
    page.get_by_role("button", name="English").click()
    with page.expect_response(lambda r: is_detail(r.url)):
        page.locator("#submit").click()
    page.wait_for_selector(f'#detail[data-model="{FHA}"][data-detail="ready"]')
    expect(message).to_have_attribute("lang", "en")
    expect(message).to_contain_text("acceleration torque T")
    expect(message).to_contain_text("= 95.48 Nm ≤ T")
