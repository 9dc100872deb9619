"""Numbers typed as people type them (issue 29, item 1): "1,3" and "1.3" are 1.3 in every
number field of both pages, in a German and an English browser; text with two decimal
marks ("1.300,5", "1,300.5", "1.000.000") is refused at its field and nothing is sent;
what was typed stays as typed, and what it was read as is shown beside it.

Every number is typed with the keyboard (``press_sequentially``), as a person would, and
checked in the request the page sends (POST /selections, POST /quotes), not in the page.
Chromium's ``<input type="number">`` read "1,3" as 13 (J_L = 13 kgm², t_0 = 16.2 s).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Any, cast

import pytest
from playwright.sync_api import Browser, Locator, Page, Request, expect

from actuator_selection.schemas.mechanism_spec import mechanism_spec

from .conftest import DESKTOP, SalesSite
from .test_engineer_page import SELECTIONS_URL
from .test_sales_page import selection_id, sign_in

pytestmark = pytest.mark.browser

SLOW_MS = 20_000
FORM = "#selection-form"
NUMBER_FIELDS = f'{FORM} input[inputmode="decimal"]:enabled:visible'
"""The engineer form's number fields as they stand (those shown and sent)."""
LOAD_KINDS = [kind.type for kind in mechanism_spec().kinds]
"""Every kind of load, as the API declares them (the page builds its form from the same)."""
AMBIGUOUS = ["1.300,5", "1,300.5", "1.000.000"]


def context_page(browser: Browser, url: str, locale: str) -> Iterator[Page]:
    context = browser.new_context(viewport=DESKTOP, locale=locale, base_url=url)
    context.set_default_timeout(SLOW_MS)
    try:
        yield context.new_page()
    finally:
        context.close()


@pytest.fixture
def german(browser: Browser, base_url: str) -> Iterator[Page]:
    """The engineer's page in a German browser (the page then speaks German)."""
    yield from context_page(browser, base_url, "de-DE")


@pytest.fixture
def english(browser: Browser, base_url: str) -> Iterator[Page]:
    yield from context_page(browser, base_url, "en-US")


def type_in(field: Locator, text: str) -> None:
    """Empty the field, then type ``text`` key by key."""
    field.fill("")
    field.press_sequentially(text)


def is_selection_post(request: Request) -> bool:
    return SELECTIONS_URL.search(request.url) is not None and request.method == "POST"


def submit(page: Page) -> dict[str, Any]:
    """Press submit; the body of the POST /selections the page sent, once it is answered."""
    return answered(page)[0]


def answered(page: Page) -> tuple[dict[str, Any], dict[str, Any]]:
    """Press submit; the request's body and the answer's once the page has taken it."""
    with page.expect_response(lambda r: is_selection_post(r.request)) as info:
        page.locator("#submit").click()
    expect(page.locator("#submit")).to_be_enabled()
    response = info.value
    return cast(dict[str, Any], response.request.post_data_json), response.json()


def at(body: dict[str, Any], path: str) -> Any:
    """The value at a field's data-path in the request: "cycle.segments.0.speed"."""
    value: Any = body
    for part in path.split("."):
        value = value[int(part)] if part.isdigit() else value.get(part, "(absent)")
    return value


def type_worked_example(page: Page, inertia: str, accel: str) -> None:
    """Table 516.1 typed in, with J_L and t_1 as given."""
    for field, text in (
        ("#f-speed", "40"),
        ("#f-direct-torque_nm", "5"),
        ("#f-direct-inertia_kgm2", inertia),
        ("#f-t1", accel),
        ("#f-t2", "0,1"),
        ("#f-t3", "0.1"),
        ("#f-tp", "1"),
    ):
        type_in(page.locator(field), text)


def test_german_decimal_commas_reach_the_api_as_typed(german: Page) -> None:
    page = german
    page.goto("/")
    expect(page.locator("html")).to_have_attribute("lang", "de")
    type_worked_example(page, inertia="1,3", accel="0,15")
    body, answer = answered(page)
    assert body["load"]["inertia_kgm2"] == 1.3
    assert body["cycle"]["accel_s"] == 0.15
    assert body["cycle"]["constant_s"] == 0.1  # "0,1" and "0.1" alike
    assert body["cycle"]["decel_s"] == 0.1
    # sized with what was typed: J_L = 1.3 kgm², t_0 = 0.15 + 0.1 + 0.1 + 1 s (not 16.2 s)
    assert answer["load"]["inertia_kgm2"] == 1.3
    assert answer["cycle_time_s"] == pytest.approx(1.35)
    expect(page.locator("#f-direct-inertia_kgm2")).to_have_value("1,3")  # never rewritten
    expect(page.locator("#f-t1")).to_have_value("0,15")
    # a point in a German page is read as a decimal point too, and the page says so
    expect(page.locator("#read-f-t3")).to_have_text("gelesen als 0,1")
    expect(page.locator("#read-f-t3")).to_be_visible()
    expect(page.locator("#read-f-direct-inertia_kgm2")).to_have_count(0)  # "1,3" says it already


def test_the_page_writes_its_numbers_in_its_language(german: Page) -> None:
    page = german
    page.goto("/")
    page.locator("#example").click()  # Table 516.1, written by the page
    expect(page.locator("#f-direct-inertia_kgm2")).to_have_value("1,3")
    expect(page.locator("#f-t1")).to_have_value("0,1")
    expect(page.locator(f"{FORM} .number-reading:visible")).to_have_count(0)
    page.locator('input[name="cycle-mode"][value="segments"]').check()
    expect(page.locator("#seg-0-time")).to_have_value("0,1")  # the phases restated as segments
    body = submit(page)
    assert body["load"]["inertia_kgm2"] == 1.3
    assert [s.get("duration_s") for s in body["cycle"]["segments"]] == [0.1, 0.1, 0.1, 1]


@pytest.mark.parametrize(
    ("fixture", "text"),
    # the other mark in each language is typed in the tests below ("0.1", "0,15", "0,5")
    [("german", "1,3"), ("english", "1.3")],
)
def test_every_number_field_reads_one_comma_three(
    request: pytest.FixtureRequest, fixture: str, text: str
) -> None:
    page = cast(Page, request.getfixturevalue(fixture))
    page.goto("/")
    page.locator("#f-ol").check()  # the output bearing's fields too
    page.locator("#f-brake").check()  # the brake's safety factor and emergency stops
    page.locator("#more-checks > summary").click()  # the checks that run when asked
    page.locator("#f-gear").check()
    typed: set[str] = set()
    for kind in LOAD_KINDS:
        page.locator(f'input[name="load-kind"][value="{kind}"]').check()
        toggle = page.locator(f"#mech-{kind} .transmission-toggle")
        if toggle.count():
            toggle.check()
        typed |= type_everywhere_and_check(page, text)
    # the segment editor: its start speed and every row's fields
    page.locator('input[name="load-kind"][value="direct"]').check()
    page.locator('input[name="cycle-mode"][value="segments"]').check()
    page.locator("#seg-add").click()
    typed |= type_everywhere_and_check(page, text)
    # every kind of number field was met: static, generated, transmission, output load,
    # the checks asked for, segments
    for path in (
        "load.speed_rpm",
        "load.inertia_kgm2",
        "load.friction_radius_m",
        "load.pulley_diameter_mm",
        "load.transmission.ratio",
        "output_load.radial_force_n",
        "gear.required_life_h",
        "gear.momentary_count",
        "min_natural_frequency_hz",
        "brake_safety_factor",
        "emergency_stops",
        "thermal_time_constant_s",
        "cycle.accel_s",
        "cycle.start_speed",
        "cycle.segments.0.speed",
        "cycle.segments.4.duration_s",
        "cycle.segments.4.jerk_share",
        "cycle.segments.4.process_load",
    ):
        assert path in typed, path
    assert len(typed) > 60, len(typed)


def type_everywhere_and_check(page: Page, text: str) -> set[str]:
    """Type ``text`` into every number field shown and submit: each is 1.3 in the request."""
    fields = page.locator(NUMBER_FIELDS)
    paths = []
    for k in range(fields.count()):
        field = fields.nth(k)
        type_in(field, text)
        paths.append(str(field.get_attribute("data-path")))
    body = submit(page)
    wrong = {path: at(body, path) for path in paths if at(body, path) != 1.3}
    assert not wrong, wrong
    return set(paths)


@pytest.mark.parametrize("ambiguous", AMBIGUOUS)
def test_two_decimal_marks_are_refused_at_the_field_and_nothing_is_sent(
    german: Page, ambiguous: str
) -> None:
    page = german
    posts: list[Request] = []
    page.on("request", lambda r: posts.append(r) if is_selection_post(r) else None)
    page.goto("/")
    type_worked_example(page, inertia=ambiguous, accel="0,1")
    page.locator("#f-direct-inertia_kgm2").press("Tab")  # left: named at once
    error = page.locator("#err-f-direct-inertia_kgm2")
    expect(error).to_be_visible()
    expect(error).to_contain_text("Nicht eindeutig")
    expect(page.locator("#f-direct-inertia_kgm2")).to_have_attribute("aria-invalid", "true")
    page.locator("#submit").click()
    expect(page.locator("#form-status")).to_contain_text("1 Eingabe(n) abgelehnt")
    expect(page.locator("#f-direct-inertia_kgm2")).to_be_focused()
    expect(page.locator("#f-direct-inertia_kgm2")).to_have_value(
        ambiguous
    )  # as typed, not "corrected"
    # the message follows the page's language
    page.locator('.lang-button[data-lang="en"]').click()
    expect(error).to_contain_text("Ambiguous")
    # corrected, the form goes: the one request seen is this one (none went before)
    type_in(page.locator("#f-direct-inertia_kgm2"), "1,3")
    expect(error).to_be_hidden()
    body = submit(page)
    assert body["load"]["inertia_kgm2"] == 1.3
    assert len(posts) == 1


def test_a_segment_and_a_mechanism_field_refuse_two_marks_too(english: Page) -> None:
    page = english
    posts: list[Request] = []
    page.on("request", lambda r: posts.append(r) if is_selection_post(r) else None)
    page.goto("/")
    type_worked_example(page, inertia="1.3", accel="0.1")
    page.locator('input[name="cycle-mode"][value="segments"]').check()
    type_in(page.locator("#seg-1-time"), "1,000.5")
    page.locator('input[name="load-kind"][value="belt"]').check()
    type_in(page.locator("#f-belt-mass_kg"), "1.000.000 kg")  # a unit does not make it readable
    type_in(page.locator("#f-belt-pulley_diameter_mm"), "0,5 in")  # one mark and a unit: read
    page.locator("#submit").click()
    expect(page.locator("#err-seg-1-time")).to_contain_text("Ambiguous")
    expect(page.locator("#err-f-belt-mass_kg")).to_contain_text("Ambiguous")
    expect(page.locator("#seg-1-time")).to_have_attribute("aria-invalid", "true")
    expect(page.locator("#form-status")).to_contain_text("2 input(s) rejected")
    expect(page.locator("#read-f-belt-pulley_diameter_mm")).to_have_text("read as 0.5 in")
    assert not posts
    type_in(page.locator("#seg-1-time"), "0,5")
    type_in(page.locator("#f-belt-mass_kg"), "4")
    body = submit(page)
    assert body["cycle"]["segments"][1]["duration_s"] == 0.5
    assert body["load"]["pulley_diameter_mm"] == "0.5 in"  # the API converts the unit


def test_what_a_comma_was_read_as_is_shown_and_described(english: Page) -> None:
    page = english
    page.goto("/")
    type_in(page.locator("#f-t1"), "0,15")
    reading = page.locator("#read-f-t1")
    expect(reading).to_have_text("read as 0.15")
    expect(page.locator("#f-t1")).to_have_attribute(
        "aria-describedby", re.compile(r"\bread-f-t1\b")
    )
    page.locator('.lang-button[data-lang="de"]').click()
    expect(reading).to_be_hidden()  # a comma is the German page's own mark
    page.locator('.lang-button[data-lang="en"]').click()
    expect(reading).to_have_text("read as 0.15")
    type_in(page.locator("#f-t1"), "0.15")
    expect(reading).to_be_hidden()


# ---------------------------------------------------------------- the sales page


@pytest.fixture
def german_sales(browser: Browser, site: SalesSite) -> Iterator[Page]:
    yield from context_page(browser, site.url, "de-DE")


def is_quote_post(request: Request) -> bool:
    return request.url.endswith("/api/v1/quotes") and request.method == "POST"


def open_quote_form(page: Page, site: SalesSite) -> None:
    page.goto(f"/sales.html?selection={selection_id(site, ['FHA-25C-50-L'])}")
    sign_in(page, site.sales_key)
    expect(page.locator("#quote-form")).to_be_visible()
    expect(page.locator("#create-quote")).to_be_enabled()
    page.fill("#f-customer", "Beispiel Maschinenbau GmbH")
    page.fill("#f-ctrl-name", "SINAMICS S120, 400 V")
    page.fill("#f-ctrl-code", "CTRL-SINAMICS-S120")


def create(page: Page) -> tuple[int, dict[str, Any]]:
    with page.expect_response(lambda r: is_quote_post(r.request)) as info:
        page.locator("#create-quote").click()
    response = info.value
    expect(page.locator("#create-quote")).to_be_enabled()
    return response.status, cast(dict[str, Any], response.request.post_data_json)


@pytest.mark.parametrize("text", ["1,3", "1.3"])
def test_the_quote_forms_numbers_read_one_comma_three(
    german_sales: Page, site: SalesSite, text: str
) -> None:
    page = german_sales
    open_quote_form(page, site)
    for field in ("#f-qty", "#f-ctrl-qty", "#f-discount"):
        type_in(page.locator(field), text)
    status, body = create(page)
    assert body["actuator"]["quantity"] == 1.3
    assert body["controller"]["quantity"] == 1.3
    assert body["discount_percent"] == "1.3"  # a decimal as text: money is never a float
    assert status == 422  # a quantity is a whole number: the API says so at the field
    expect(page.locator("#err-actuator-quantity")).to_be_visible()
    expect(page.locator("#f-qty")).to_have_value(text)


def test_the_quote_form_refuses_two_marks_and_takes_a_comma(
    german_sales: Page, site: SalesSite
) -> None:
    page = german_sales
    posts: list[Request] = []
    page.on("request", lambda r: posts.append(r) if is_quote_post(r) else None)
    open_quote_form(page, site)
    type_in(page.locator("#f-qty"), "2")
    type_in(page.locator("#f-ctrl-qty"), "1")
    type_in(page.locator("#f-discount"), "1.300,5")
    page.locator("#f-discount").press("Tab")
    expect(page.locator("#err-discount_percent")).to_contain_text("Nicht eindeutig")
    expect(page.locator("#f-discount")).to_have_attribute("aria-invalid", "true")
    page.locator("#create-quote").click()
    expect(page.locator("#form-status")).to_be_visible()
    expect(page.locator("#err-discount_percent")).to_be_visible()
    assert not posts
    type_in(page.locator("#f-discount"), "7,5")
    page.locator("#f-discount").press("Tab")
    expect(page.locator("#err-discount_percent")).to_be_hidden()
    status, body = create(page)
    assert status == 201
    assert body["discount_percent"] == "7.5"
    assert len(posts) == 1
