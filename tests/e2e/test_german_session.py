"""A whole German session in Chromium, with no English word on the screen: the engineer's
form, its results, a field error, a candidate's detail, the sales page, a quote, its
printable document and its PDF, three clicks from the engineer's result to the PDF.

"No English" is checked against words, not phrases: every word of the English texts (the
msgids of the German catalogue: the page's words, the server's messages and the
documents' labels, ``docs/i18n.md``) that none of their German texts use (so "Nm",
"Harmonic Drive", "Status" or model names never count). The
visible text of the page and its ``aria-label``, ``title`` and ``placeholder`` attributes
are read; text in an element marked ``translate="no"`` (names and data: a controller's
type, a catalogue source, a price list's own description) and data the test itself
entered or the catalogue holds (the price list's name) are left out, as they stay as
written in every language.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from functools import cache
from pathlib import Path

import pytest
from babel.messages.pofile import read_po
from playwright.sync_api import Browser, Locator, Page, expect
from tests.api._sales_fixtures import EXAMPLE_PRICE_LIST

from actuator_selection.i18n.localize import catalog_path

from .conftest import SalesSite
from .test_engineer_page import SELECTIONS_URL, fill_worked_example, wait_for_charts

pytestmark = pytest.mark.browser

SLOW_MS = 30_000
WORD = re.compile(r"[A-Za-zÄÖÜäöüß]{3,}")

VISIBLE_TEXT_JS = """() => {
  // the rendered text of every element, its label attributes, less what is marked translate=no
  const skip = (el) => el.closest('[translate="no"]') !== null;
  const parts = [];
  const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
  for (let node = walker.nextNode(); node; node = walker.nextNode()) {
    const el = node.parentElement;
    if (!el || skip(el) || ["SCRIPT", "STYLE", "NOSCRIPT"].includes(el.tagName)) continue;
    if (!el.checkVisibility({ visibilityProperty: true })) {
      if (!el.closest(".visually-hidden")) continue;  // read out by a screen reader
    }
    parts.push(node.textContent);
  }
  for (const el of document.querySelectorAll("[aria-label], [title], [placeholder]")) {
    if (skip(el)) continue;
    for (const name of ["aria-label", "title", "placeholder"]) {
      const value = el.getAttribute(name);
      if (value) parts.push(value);
    }
  }
  for (const el of document.querySelectorAll("option")) if (!skip(el)) parts.push(el.textContent);
  return parts.join("\\n");
}"""


UUID = re.compile(r"\b[0-9a-f]{8}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{4}-[0-9a-f]{12}\b")
"""An identifier the page shows (a selection's, a quote's): data, not words."""


def _words(texts: list[str]) -> set[str]:
    return {w.lower() for t in texts for w in WORD.findall(re.sub(r"\{[^}]*\}", " ", t))}


@cache
def english_words() -> frozenset[str]:
    """Words only the English texts use: the page's, the server's and the documents' (one
    catalogue), less every word of their German texts."""
    english: list[str] = []
    german: list[str] = []
    with catalog_path("de").open("rb") as file:
        for message in read_po(file):
            if isinstance(message.id, str) and message.id and isinstance(message.string, str):
                english.append(message.id)
                german.append(message.string)
    return frozenset(_words(english) - _words(german))


def english_on(page: Page, *, data: tuple[str, ...] = ()) -> list[tuple[str, str]]:
    """(word, its line) for each English word on ``page`` (see the module's docstring)."""
    text = str(page.evaluate(VISIBLE_TEXT_JS))
    for value in data:
        text = text.replace(value, " ")
    text = UUID.sub(" ", text)  # an id is data: "8aad244f-add6-…" holds no word
    found = []
    for line in text.splitlines():
        for word in WORD.findall(line):
            if word.lower() in english_words():
                found.append((word, line.strip()))
    return found


def assert_german(page: Page, where: str, *, data: tuple[str, ...] = ()) -> None:
    leaks = english_on(page, data=data)
    assert not leaks, f"English on the German {where}: {leaks[:20]}"


def test_the_word_list_finds_english() -> None:
    words = english_words()
    # the page's and the server's English, not their German or what both share
    assert {"acceleration", "exceeds", "retired", "quote", "unconfirmed"} <= words
    assert not {"nm", "harmonic", "drive", "status", "tabelle", "beschleunigungsmoment"} & words


@pytest.fixture
def german_page(browser: Browser, site: SalesSite) -> Iterator[Page]:
    context = browser.new_context(
        viewport={"width": 1280, "height": 900},
        locale="de-DE",
        base_url=site.url,
        accept_downloads=True,
    )
    context.set_default_timeout(SLOW_MS)
    try:
        yield context.new_page()
    finally:
        context.close()


class Clicks:
    """Counts the clicks a person makes (Playwright's clicks go through here)."""

    def __init__(self) -> None:
        self.count = 0

    def click(self, locator: Locator) -> None:
        self.count += 1
        locator.click()


def test_a_german_session_from_the_form_to_the_pdf(german_page: Page, site: SalesSite) -> None:
    page = german_page
    page.goto("/")
    expect(page.locator("html")).to_have_attribute(
        "lang", "de", timeout=SLOW_MS
    )  # the browser's language
    assert_german(page, "empty form")

    # a field error, in German
    fill_worked_example(page)
    page.locator("#f-t1").fill("0")
    with page.expect_response(lambda r: SELECTIONS_URL.search(r.url) is not None) as refused:
        page.locator("#submit").click()
    assert refused.value.status == 422
    error = page.locator("#err-t1")
    expect(error).to_contain_text("Eingabe muss größer", timeout=SLOW_MS)
    assert_german(page, "form with a field error")

    # the results and the first candidate's detail
    page.locator("#f-t1").fill("0.1")
    with page.expect_response(
        lambda r: SELECTIONS_URL.search(r.url) is not None and r.status == 201
    ) as created:
        page.locator("#submit").click()
    chosen = str(created.value.json()["candidates"][0]["model"])
    page.wait_for_selector(f'#detail[data-model="{chosen}"][data-detail="ready"]')
    wait_for_charts(page, chosen)
    expect(page.locator("#controllers-table")).to_be_visible(timeout=SLOW_MS)
    assert_german(page, f"results with {chosen}'s detail")

    # an unconfirmed candidate: its missing catalogue values and its controllers' notes
    unconfirmed = "FHA-25C-50-L"
    page.locator(f'#ranking-table tr[data-model="{unconfirmed}"] .model-button').click()
    page.wait_for_selector(f'#detail[data-model="{unconfirmed}"][data-detail="ready"]')
    expect(page.locator("#detail .controllers")).to_contain_text("keine Daten zu", timeout=SLOW_MS)
    assert_german(page, f"detail of {unconfirmed}")
    page.locator(f'#ranking-table tr[data-model="{chosen}"] .model-button').click()
    page.wait_for_selector(f'#detail[data-model="{chosen}"][data-detail="ready"]')

    # from the result to the PDF: three clicks (typing the key and the customer is no click)
    clicks = Clicks()
    clicks.click(page.locator(".sales-link"))  # 1: the quotes page on this selection and model
    page.fill("#api-key", site.sales_key)
    page.press("#api-key", "Enter")  # signing in: the key typed and sent with Enter
    expect(page.locator("#quote-form")).to_be_visible(timeout=SLOW_MS)
    expect(page.locator("#f-model")).to_have_value(chosen, timeout=SLOW_MS)
    assert_german(page, "sales page", data=(EXAMPLE_PRICE_LIST,))
    page.fill("#f-customer", "Beispiel Maschinenbau GmbH")
    clicks.click(page.get_by_role("button", name="Angebot erstellen"))  # 2
    created_box = page.locator("#created")
    expect(created_box).to_contain_text("erstellt: Gesamtbetrag", timeout=SLOW_MS)
    number = created_box.locator(".quote-number").inner_text()
    assert_german(page, "sales page with the quote", data=(EXAMPLE_PRICE_LIST,))
    with page.expect_download() as download_info:
        clicks.click(created_box.get_by_role("button", name="PDF"))  # 3
    download = download_info.value
    assert clicks.count == 3
    assert download.suggested_filename == f"{number}.pdf"
    pdf = Path(download.path()).read_bytes()
    assert pdf.startswith(b"%PDF-")

    # the printable document in German
    with page.expect_popup() as popup:
        created_box.get_by_role("button", name="Dokument öffnen").click()
    document = popup.value
    expect(document.locator("html")).to_have_attribute("lang", "de", timeout=SLOW_MS)
    expect(document.locator("[data-field=total]")).to_contain_text(",", timeout=SLOW_MS)
    document.wait_for_selector("html[data-figure=ready]")
    assert_german(document, "quote document", data=(EXAMPLE_PRICE_LIST,))
