"""Every kind of load the API lists (``GET /api/v1/mechanisms``) is offered on the
engineer's page with its fields: the page builds them from the same declaration
(``schemas/mechanism_spec.py`` → ``pages/engineer/mechanism-spec.js``), so a field added
to a request model appears on the page, with its symbol, unit and words."""

from __future__ import annotations

from typing import Any

import pytest
from playwright.sync_api import Locator, Page, expect

pytestmark = pytest.mark.browser


def _assert_field(page: Page, box: Locator, path: str, field: dict[str, Any]) -> None:
    input_ = box.locator(f'input[data-path="{path}"]')
    expect(input_).to_have_count(1)
    expect(input_).to_be_visible()
    expect(input_).to_have_attribute("data-number", "units" if field["units"] else "")
    row = box.locator(".field").filter(has=page.locator(f'input[data-path="{path}"]'))
    expect(row.locator(".unit")).to_have_text(field["unit"])
    letter, _, sub = field["symbol"].partition("_")
    expect(row.locator(".sym var")).to_have_text(letter)
    if sub:
        expect(row.locator(".sym sub")).to_have_text(sub)
    expect(row.locator(f'[data-i18n="{field["label"]}"]')).not_to_be_empty()
    expect(row.locator(".optional")).to_have_count(0 if field["required"] else 1)


def test_every_kind_the_api_lists_is_on_the_page_with_its_fields(page: Page) -> None:
    answer = page.request.get("/api/v1/mechanisms")
    assert answer.ok
    spec = answer.json()
    page.goto("/")
    radios = page.locator('input[name="load-kind"]')
    expect(radios).to_have_count(len(spec["kinds"]))
    for kind in spec["kinds"]:
        page.locator(f'input[name="load-kind"][value="{kind["type"]}"]').check()
        box = page.locator(f'fieldset.mechanism[data-kind="{kind["type"]}"]')
        expect(box).to_be_visible()
        expect(box).to_be_enabled()
        # only the chosen kind's fields are shown (and sent)
        expect(page.locator("fieldset.mechanism:visible")).to_have_count(1)
        for field in kind["fields"]:
            _assert_field(page, box, f"load.{field['name']}", field)
        expect(page.locator("#f-speed")).to_have_attribute(
            "data-path", f"load.{kind['speed_field']}"
        )
        expect(page.locator("#u-speed")).to_have_attribute(
            "data-unit", "mm/s" if kind["linear"] else "rpm"
        )
        toggle = box.locator(".transmission-toggle")
        expect(toggle).to_have_count(1 if kind["transmission"] else 0)
        if kind["transmission"]:
            toggle.check()
            for field in spec["transmission"]:
                _assert_field(page, box, f"load.transmission.{field['name']}", field)


def test_a_kind_s_fieldset_is_built_when_first_chosen(page: Page) -> None:
    """The page starts with the default kind's fieldset only; another kind's is built
    the first time it is chosen, worded in the page's language at that moment, and kept
    (with what was typed into it) when the user switches away and back."""
    page.goto("/")
    expect(page.locator("#results-body .notice")).to_be_attached()  # the page's script ran
    mechanisms = page.locator("fieldset.mechanism")
    expect(mechanisms).to_have_count(1)
    page.locator('.lang-button[data-lang="de"]').click()
    page.locator('input[name="load-kind"][value="belt"]').check()
    expect(mechanisms).to_have_count(2)
    box = page.locator("#mech-belt")
    expect(box).to_be_visible()
    words = box.locator("[data-i18n]")
    built_in_german = words.all_inner_texts()
    assert all(built_in_german)
    speed = box.locator("input[data-number]").first
    speed.fill("12")
    page.locator('.lang-button[data-lang="en"]').click()
    assert words.all_inner_texts() != built_in_german
    page.locator('.lang-button[data-lang="de"]').click()
    assert words.all_inner_texts() == built_in_german  # as the language switch words it
    page.locator('input[name="load-kind"][value="direct"]').check()
    expect(box).to_be_hidden()
    page.locator('input[name="load-kind"][value="belt"]').check()
    expect(mechanisms).to_have_count(2)
    expect(speed).to_have_value("12")
