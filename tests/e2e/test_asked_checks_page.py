"""The checks that run when asked (issue 28, items 7–9; decisions/0024) asked for at the
page: the gear's own limits and its required life, the least natural frequency, the
brake's safety factor and emergency stops, τ_th. Typed as a person types them, in German
and in English, checked in the request the page sends and in the stored request a
permalink refills the form from; the checks then shown with their references and the
quantities that bind. A blank field is not asked: the request leaves it out.

Worked example (Table 516.1) over CHA-25A-50 and CHA-32A-50: f_n = (1/2π)·√(K_1/J_L) is
22.07 Hz for CHA-25A-50 and 32.44 Hz for CHA-32A-50 with J_L = 1.3 kgm², so a least
natural frequency of 22.5 Hz fails the one and passes the other.
"""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import pytest
from playwright.sync_api import Browser, Page, expect

from .test_number_input import answered, context_page, type_in, type_worked_example

pytestmark = pytest.mark.browser

FAILS, PASSES = "CHA-25A-50", "CHA-32A-50"
ASKED = ("gear", "min_natural_frequency_hz", "brake_safety_factor", "emergency_stops")

TYPED = {
    # field: (German, English, what the request carries)
    "#f-min_natural_frequency_hz": ("22,5", "22.5", 22.5),
    "#f-brake_safety_factor": ("1,3", "1.3", 1.3),
    "#f-emergency_stops": ("150", "150", 150),
    "#f-gear-required_life_h": ("7000", "7000", 7000),
    "#f-thermal_time_constant_s": ("1200,5", "1200.5", 1200.5),
}

WORDS = {
    "de": {
        "ref": "S. 68",
        "fail": "nicht erfüllt",
        "no_data": "keine Daten",
        "ref_table": "Tabelle 36.3",
    },
    "en": {"ref": "p. 68", "fail": "fail", "no_data": "no data", "ref_table": "Table 36.3"},
}


@pytest.fixture(params=["de", "en"])
def lang_page(request: pytest.FixtureRequest, browser: Browser, base_url: str) -> Iterator[Page]:
    locale = "de-DE" if request.param == "de" else "en-US"
    yield from context_page(browser, base_url, locale)


def lang_of(page: Page) -> str:
    return str(page.locator("html").get_attribute("lang"))


def ask_everything(page: Page) -> None:
    """The worked example over two actuators, every check asked for, typed key by key."""
    lang = lang_of(page)
    type_worked_example(page, inertia="1,3" if lang == "de" else "1.3", accel="0,1")
    type_in(page.locator("#f-models"), f"{FAILS}, {PASSES}")
    page.locator("#f-brake").check()
    page.locator("#more-checks > summary").click()
    page.locator("#f-gear").check()
    for field, (de, en, _) in TYPED.items():
        type_in(page.locator(field), de if lang == "de" else en)


def open_detail(page: Page, model: str) -> None:
    page.locator(f'#ranking-table tbody tr[data-model="{model}"] .model-button').click()
    page.wait_for_selector(f'#detail[data-model="{model}"][data-detail="ready"]')


def test_asked_checks_go_as_typed_and_show_with_their_references(lang_page: Page) -> None:
    page = lang_page
    page.goto("/")
    lang = lang_of(page)
    words = WORDS[lang]
    ask_everything(page)
    body, answer = answered(page)
    # the numbers as typed, whatever the decimal mark ("1,3" is 1.3), each where it belongs
    assert body["min_natural_frequency_hz"] == 22.5
    assert body["brake_safety_factor"] == 1.3
    assert body["emergency_stops"] == 150
    assert body["gear"] == {"required_life_h": 7000}
    assert body["thermal_time_constant_s"] == 1200.5
    assert body["brake"] is True

    by_model = {c["model"]: c for c in answer["candidates"]}
    stiffness = {
        m: next(x for x in c["checks"] if x["name"] == "natural_frequency")
        for m, c in by_model.items()
    }
    assert stiffness[FAILS]["status"] == "fail"
    assert stiffness[PASSES]["status"] == "pass"

    # the failing candidate: the stiffness check fails on the page, with its reference and
    # the frequencies it compares
    open_detail(page, FAILS)
    row = page.locator('#checks-table tr[data-check="natural_frequency"]')
    expect(row).to_have_attribute("data-status", "fail")
    expect(row.locator("th .ref")).to_contain_text(words["ref"])
    expect(row.locator(".status-cell")).to_contain_text(words["fail"])
    expect(row.locator("td.num").first).to_contain_text("22,5" if lang == "de" else "22.5")
    expect(row.locator("td.num").first).to_contain_text("Hz")
    expect(row.locator("td.num").nth(1)).to_contain_text("22,07" if lang == "de" else "22.07")
    expect(row.locator("td.message")).to_contain_text("22,07 Hz" if lang == "de" else "22.07 Hz")

    # the brake: S·T_L against the holding torque, the stops against the brake's 200
    holding = page.locator('#checks-table tr[data-check="brake_holding"]')
    expect(holding).to_have_attribute("data-status", "pass")
    expect(holding.locator("td.message")).to_contain_text(
        "1,3 × 5 Nm" if lang == "de" else "1.3 × 5 Nm"
    )
    stops = page.locator('#checks-table tr[data-check="brake_emergency_stops"]')
    expect(stops).to_have_attribute("data-status", "pass")
    expect(stops.locator("th .ref")).to_contain_text(words["ref_table"])
    expect(stops.locator("td.num").first).to_have_text("150")
    expect(stops.locator("td.num").nth(1)).to_have_text("200")

    # the gear: asked for, and the catalogue has no ratings for it: no data, said so
    for name in ("gear_average_torque", "gear_repeated_peak", "gear_input_speed", "gear_life"):
        gear = page.locator(f'#checks-table tr[data-check="{name}"]')
        expect(gear).to_have_attribute("data-status", "no_data")
        expect(gear.locator(".status-cell")).to_contain_text(words["no_data"])
        expect(gear.locator("th .ref")).to_contain_text("CSD-2A 1019659")
    # no momentary peak typed: that check is not asked
    expect(page.locator('#checks-table tr[data-check="gear_momentary_peak"]')).to_have_count(0)

    open_detail(page, PASSES)
    row = page.locator('#checks-table tr[data-check="natural_frequency"]')
    expect(row).to_have_attribute("data-status", "pass")


def test_a_permalink_refills_the_checks_asked_for(lang_page: Page) -> None:
    page = lang_page
    page.goto("/")
    lang = lang_of(page)
    ask_everything(page)
    answered(page)
    url = page.url
    assert "selection=" in url
    selection_id = url.split("selection=")[1].split("&")[0]
    stored: dict[str, Any] = page.request.get(f"/api/v1/selections/{selection_id}/request").json()
    assert stored["min_natural_frequency_hz"] == 22.5
    assert stored["brake_safety_factor"] == 1.3
    assert stored["gear"]["required_life_h"] == 7000

    page.goto("/")
    page.goto(url)
    expect(page.locator("#detail")).to_be_visible()
    expect(page.locator("#more-checks")).to_have_attribute("open", "")
    expect(page.locator("#f-gear")).to_be_checked()
    expect(page.locator("#f-brake")).to_be_checked()
    for field, (de, en, _) in TYPED.items():
        expect(page.locator(field)).to_have_value(de if lang == "de" else en)
    # sent again unchanged
    body, _ = answered(page)
    for field, (_, _, value) in TYPED.items():
        name = field.removeprefix("#f-").removeprefix("gear-")
        got = body["gear"][name] if field.startswith("#f-gear-") else body[name]
        assert got == value, field


def test_blank_means_not_asked(lang_page: Page) -> None:
    page = lang_page
    page.goto("/")
    type_worked_example(page, inertia="1,3", accel="0,1")
    type_in(page.locator("#f-models"), FAILS)
    page.locator("#more-checks > summary").click()
    page.locator("#f-gear").check()
    page.locator("#f-gear").uncheck()
    # the brake's fields are typed but the brake is not ticked: they are not sent
    page.locator("#f-brake").check()
    type_in(page.locator("#f-emergency_stops"), "150")
    page.locator("#f-brake").uncheck()
    expect(page.locator("#f-emergency_stops")).to_be_hidden()
    body, answer = answered(page)
    for name in (*ASKED, "thermal_time_constant_s"):
        assert name not in body, name
    names = {c["name"] for c in answer["candidates"][0]["checks"]}
    assert not names & {"natural_frequency", "gear_average_torque", "brake_emergency_stops"}
