"""One catalogue of words (issue 27 item 4): the page's words are the gettext catalogue's,
exported to ``frontend/lib/messages.js`` by ``make messages``; every word is in German and
English; every key the page asks for is in the catalogue; the German words of the
catalogue values a check lacks are the server's."""

from __future__ import annotations

import re
import string
from html.parser import HTMLParser
from pathlib import Path

import pytest

from actuator_selection.i18n import page_words
from actuator_selection.i18n.localize import (
    catalog,
    catalog_path,
    check_templates,
    translate,
    words,
)
from actuator_selection.i18n.page_words import PAGE_MODULE, module_text
from actuator_selection.i18n.page_words import page_words as exported

ROOT = Path(__file__).resolve().parents[2]
FRONTEND = ROOT / "frontend"
LITERAL = re.compile(r"""["'`]([a-z][a-z_]*(?:\.[A-Za-z0-9_]+)+)["'`]""")
"""A string literal shaped like a page key (``"results.heading"``)."""
PREFIX = re.compile(r"`([a-z][a-z_]*(?:\.[A-Za-z0-9_]+)*\.)\$\{")
"""A key built at run time (``t(`verdict.${v}`)``): its fixed prefix."""
DATA_PATH = re.compile(
    r'data-path="([^"]+)"|(?:readNumber|readQuantities|setField)\("([^"]+)"'
    r'|"([a-z_]+\.[a-z0-9_]+)": -?[0-9]'
)
"""A field's path in the request (``load.mass_kg``, also as the key of an example's
number): shaped like a key, but no word."""
COMMENT = re.compile(r"``[^`]*``|^\s*(?://|\*|/\*\*).*$", re.MULTILINE)
"""A comment line, and code quoted in a comment."""
ATTRIBUTE = re.compile(r"""data-i18n="([^"]+)"|data-i18n-attr="([^"]+)"|i18n: "([^"]+)\"""")
"""A key an element names for :func:`applyStaticTexts` (HTML, or ``dataset`` in JS)."""


def _fields(text: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(text) if name}


def test_the_page_module_is_what_the_catalogue_gives() -> None:
    """``make messages`` was run after the last change to the catalogue."""
    assert PAGE_MODULE.read_text(encoding="utf-8") == module_text(), (
        "frontend/lib/messages.js is stale: run `make messages`"
    )


def test_a_changed_catalogue_makes_the_module_stale(monkeypatch: pytest.MonkeyPatch) -> None:
    changed = {**words("de"), "results.heading": "Resultat"}
    monkeypatch.setattr(
        page_words, "words", lambda language: changed if language == "de" else words(language)
    )
    assert PAGE_MODULE.read_text(encoding="utf-8") != module_text()


def test_every_word_is_in_german_and_english() -> None:
    """No entry without its German (missing or fuzzy), no obsolete entry, and both
    languages name the same placeholders."""
    entries = [m for m in catalog("de") if m.id]
    assert len(entries) > 900
    for message in entries:
        where = (message.context, message.id)
        assert isinstance(message.id, str), where
        assert isinstance(message.string, str), where
        assert message.id.strip(), where
        assert message.string.strip(), where
        assert not message.fuzzy, where
        assert _fields(message.id) == _fields(message.string), where
    assert not catalog("de").obsolete
    assert "#~" not in catalog_path("de").read_text(encoding="utf-8")


def test_english_and_german_have_the_same_keys() -> None:
    english, german = exported()["en"], exported()["de"]
    assert set(english) == set(german), set(english) ^ set(german)
    assert set(words("en")) == set(words("de"))


def _page_sources() -> list[Path]:
    return sorted(
        path for path in (*FRONTEND.rglob("*.js"), *FRONTEND.glob("*.html")) if path != PAGE_MODULE
    )


def test_every_key_the_page_uses_is_in_the_catalogue() -> None:
    keys = set(exported()["en"])
    namespaces = {key.split(".")[0] for key in keys}
    used: dict[str, Path] = {}
    prefixes: dict[str, Path] = {}
    sources = {path: COMMENT.sub(" ", path.read_text(encoding="utf-8")) for path in _page_sources()}
    data_paths = {a or b or c for text in sources.values() for a, b, c in DATA_PATH.findall(text)}
    for path, text in sources.items():
        for key in LITERAL.findall(text):
            if key.split(".")[0] in namespaces and key not in data_paths:
                used[key] = path
        for prefix in PREFIX.findall(text):
            if prefix.split(".")[0] in namespaces and prefix[:-1] not in data_paths:
                prefixes[prefix] = path
        if path.name == "i18n.js":
            continue  # it reads the attributes; its comments show their shape
        for plain, pairs, dataset in ATTRIBUTE.findall(text):
            named = [plain, dataset, *(p.partition(":")[2].strip() for p in pairs.split(";"))]
            used |= {key: path for key in named if key}
    assert len(used) > 300
    missing = {key: str(path.relative_to(ROOT)) for key, path in used.items() if key not in keys}
    assert not missing, missing
    assert all(any(key.startswith(p) for key in keys) for p in prefixes), prefixes


def test_the_page_words_every_missing_value_as_the_catalog_does() -> None:
    page = {
        key.removeprefix("words."): text
        for key, text in exported()["de"].items()
        if key.startswith("words.")
    }
    server = {t for key, t in check_templates().items() if key.startswith("check_word:")}
    assert set(page) == server, set(page) ^ server
    for english, german in page.items():
        assert german == translate(english, "de"), english
        assert german != english, english


def test_no_hand_written_dictionary_is_left_in_the_page() -> None:
    source = (FRONTEND / "lib" / "i18n.js").read_text(encoding="utf-8")
    assert len(source.splitlines()) < 150
    assert not re.search(r'^\s*"[a-z_]+\.[\w.]+":\s*"', source, re.MULTILINE)


class _StaticTexts(HTMLParser):
    """Each ``data-i18n`` element's key and text, and each ``data-i18n-attr`` pair's key
    and attribute value, as a browser reads the HTML (independent of the writer's regex)."""

    VOID = frozenset({"input", "br", "img", "meta", "link", "hr", "source", "wbr"})

    def __init__(self) -> None:
        super().__init__()
        self.open: list[tuple[str, str | None, list[str]]] = []
        self.texts: list[tuple[str, str]] = []
        self.attributes: list[tuple[str, str]] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        values = dict(attrs)
        for pair in (values.get("data-i18n-attr") or "").split(";"):
            attr, _, key = (part.strip() for part in pair.partition(":"))
            if attr and key:
                self.attributes.append((key, values.get(attr) or ""))
        if tag not in self.VOID:
            self.open.append((tag, values.get("data-i18n"), []))

    def handle_endtag(self, tag: str) -> None:
        while self.open:
            name, key, parts = self.open.pop()
            text = "".join(parts)
            if key is not None:
                self.texts.append((key, text))
            if self.open:
                self.open[-1][2].append(text)
            if name == tag:
                break

    def handle_data(self, data: str) -> None:
        if self.open:
            self.open[-1][2].append(data)


@pytest.mark.parametrize("page", page_words.PAGES, ids=lambda p: p.name)
def test_the_pages_first_paint_is_the_catalogues(page: Path) -> None:
    """Every ``data-i18n`` element of the HTML holds the catalogue's word for its key in the
    page's default language, as the script would fill it in (symbols ``X_sub`` shown with
    their subscript), and every ``data-i18n-attr`` attribute too: the HTML holds no word
    of its own (issue 27 item 4; ``make messages`` writes them)."""
    source = page.read_text(encoding="utf-8")
    language = page_words.PAGE_LANGUAGE
    assert f'<html lang="{language}">' in source
    parser = _StaticTexts()
    parser.feed(source)
    table = words(language)
    assert len(parser.texts) > 30
    differ = [
        (key, text) for key, text in parser.texts if text != page_words.page_plain(table[key])
    ]
    assert not differ, differ
    differ = [
        (key, value)
        for key, value in parser.attributes
        if value != page_words.page_plain(table[key])
    ]
    assert not differ, differ
    assert page_words.first_paint(source) == source  # make messages is idempotent
