"""The page's words, exported from the gettext catalogue: ``frontend/lib/messages.js``.

The catalogue (``locale/de/LC_MESSAGES/messages.po``) is the one home of every word: the
server's messages (msgids marked with ``N_`` in the code), the documents' labels
(msgctxt ``document.<key>``) and the page's (msgctxt = the key the page asks for, such as
``results.heading``); English is the msgid, German the msgstr (:func:`i18n.localize.words`).
The page reads its words synchronously from a module, so ``make messages`` writes that
module from the catalogue (``python -m actuator_selection.i18n.page_words export``) and a
test fails when the checked-in module differs from what the catalogue gives
(``tests/api/test_page_words.py``). ``docs/i18n.md`` says how a word is added.

The pages' HTML (``frontend/index.html``, ``frontend/sales.html``) holds the same words for
its first paint, before the page's script has run: ``make messages`` writes each
``data-i18n`` element's text and each ``data-i18n-attr`` attribute from the catalogue in
the pages' default language (:data:`PAGE_LANGUAGE`, ``initialLang``'s fallback), so the
HTML holds no word of its own (:func:`first_paint`).

The module holds, per language, the page's keyed words, ``words.<English>`` for the
catalogue values a check lacks (their German is the server's, the context-less msgid),
and plotly.js's own words (msgctxt ``plotly``, the mode bar's tooltips).
"""

from __future__ import annotations

import html
import json
import re
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Final

from babel.messages.pofile import read_po, write_po

from actuator_selection.config import REPO_ROOT
from actuator_selection.i18n.localize import (
    DEFAULT_LANGUAGE,
    DOMAIN,
    LANGUAGES,
    PLOTLY,
    SOURCE_CATALOG,
    catalog,
    check_templates,
    reference_pattern,
    translate,
    words,
)

PAGE_MODULE: Final = REPO_ROOT / "frontend" / "lib" / "messages.js"
"""The page's words as a JavaScript module (checked in; written by ``make messages``)."""

PAGES: Final = (REPO_ROOT / "frontend" / "index.html", REPO_ROOT / "frontend" / "sales.html")
"""The pages whose first paint holds the catalogue's words (written by ``make messages``)."""

PAGE_LANGUAGE: Final = "de"
"""The pages' default language: ``initialLang`` (``frontend/lib/i18n.js``) falls back to
German, and the HTML says so (``<html lang="de">``)."""

PAGE_SYMBOL: Final = re.compile(r"(^|[^A-Za-z0-9_])([A-Za-z])_([A-Za-z0-9]+)")
"""The page's rule for a symbol ``X_sub`` (``frontend/lib/symbols.js`` ``SYMBOL``)."""

_TEXT_ELEMENT: Final = re.compile(
    r'(?P<open><(?P<tag>[a-z][a-z0-9]*)\b[^>]*?\sdata-i18n="(?P<key>[^"]+)"[^>]*>)'
    r"(?:[^<]|</?sub>)*(?P<close></(?P=tag)>)"
)
"""An element with ``data-i18n`` and its text (which may hold the ``<sub>`` of a symbol)."""

_ATTR_ELEMENT: Final = re.compile(
    r'<[a-z][a-z0-9]*\b[^>]*\sdata-i18n-attr="(?P<pairs>[^"]*)"[^>]*>'
)

DOCUMENT: Final = "document."
"""The contexts of the documents' labels (not the page's)."""

WORDS_PREFIX: Final = "words."
"""The page's key of a catalogue value a check lacks: ``words.<English>``."""

HEADER: Final = """\
// The page's words in German and English, exported by `make messages` from the gettext
// catalogue (backend/actuator_selection/i18n/locale/de/LC_MESSAGES/messages.po: msgctxt = key,
// msgid = English, msgstr = German). Do not edit: change the catalogue and run
// `make messages` (docs/i18n.md); tests/api/test_page_words.py fails when this is stale.
"""


def check_words() -> list[str]:
    """The catalogue values a check may lack, in English (the server's msgids)."""
    return sorted({t for k, t in check_templates().items() if k.startswith("check_word:")})


def page_words() -> dict[str, dict[str, str]]:
    """Language → key → text of every word the page may ask for."""
    out: dict[str, dict[str, str]] = {}
    for language in LANGUAGES:
        keyed = {key: text for key, text in words(language).items() if not key.startswith(DOCUMENT)}
        keyed |= {f"{WORDS_PREFIX}{w}": translate(w, language) for w in check_words()}
        out[language] = dict(sorted(keyed.items()))
    return out


def plotly_words() -> dict[str, dict[str, str]]:
    """Language → plotly.js's English → its words in that language (English needs none)."""
    return {
        language: dict(
            sorted(
                (str(m.id), str(m.string))
                for m in catalog(language)
                if m.context == PLOTLY and m.string and not m.fuzzy
            )
        )
        for language in LANGUAGES
        if language != DEFAULT_LANGUAGE
    }


def module_text() -> str:
    """``frontend/lib/messages.js`` as the catalogue gives it."""

    def constant(name: str, doc: str, value: Mapping[str, Mapping[str, str]]) -> str:
        body = json.dumps(value, ensure_ascii=False, indent=2)
        kind = "@type {Record<string, Record<string, string>>}"
        return f"/** {doc} {kind} */\nexport const {name} = {body};\n"

    pattern = json.dumps(reference_pattern(), ensure_ascii=False)
    return "\n".join(
        (
            HEADER,
            constant("WORDS", "Language → key → the page's text.", page_words()),
            constant("PLOTLY_WORDS", "Language → plotly.js's English → its text.", plotly_words()),
            "/** The words of a reference the catalogue translates (a RegExp source). */\n"
            f"export const REFERENCE_PATTERN = {pattern};\n",
        )
    )


def page_html(text: str) -> str:
    """A word as the page shows it (``appendSymbols``), as HTML: escaped, each symbol
    ``X_sub`` as ``X<sub>sub</sub>``.

    >>> page_html("T_1 & t_p < 1 s")
    'T<sub>1</sub> &amp; t<sub>p</sub> &lt; 1 s'
    """
    return PAGE_SYMBOL.sub(r"\1\2<sub>\3</sub>", html.escape(text, quote=False))


def page_plain(text: str) -> str:
    """A word as an attribute of the page holds it (``plainSymbols``): ``T_1`` → ``T1``."""
    return PAGE_SYMBOL.sub(r"\1\2\3", text)


def first_paint(page: str, language: str = PAGE_LANGUAGE) -> str:
    """``page`` (HTML) with every ``data-i18n`` element's text and every ``data-i18n-attr``
    attribute the catalogue's word in ``language``, as the page's script fills them
    (``applyStaticTexts``); an unknown key is a KeyError."""
    table = words(language)

    def text(match: re.Match[str]) -> str:
        return match["open"] + page_html(table[match["key"]]) + match["close"]

    def attributes(match: re.Match[str]) -> str:
        tag = match[0]
        for pair in match["pairs"].split(";"):
            attr, _, key = (part.strip() for part in pair.partition(":"))
            if attr and key:
                value = html.escape(page_plain(table[key]), quote=True)
                written = f'{attr}="{value}"'
                pattern = re.compile(rf'(?<=\s){re.escape(attr)}="[^"]*"')
                if pattern.search(tag):
                    tag = pattern.sub(written.replace("\\", "\\\\"), tag)
                else:
                    tag = tag[:-1].rstrip("/").rstrip() + f" {written}>"
        return tag

    return _ATTR_ELEMENT.sub(attributes, _TEXT_ELEMENT.sub(text, page))


def keep_keyed_in_template(template: Path) -> None:
    """Add the catalogue's keyed words (with a msgctxt) to the extracted ``template``, so
    that ``pybabel update`` keeps them: they are declared in the catalogue, not in code."""
    with template.open("rb") as file:
        pot = read_po(file, domain=DOMAIN)
    for message in catalog(SOURCE_CATALOG):
        if message.context and message.id:
            pot.add(message.id, context=message.context, flags=message.flags - {"fuzzy"})
    with template.open("wb") as file:
        write_po(file, pot, width=100, sort_output=True, omit_header=False)


def main(argv: Sequence[str]) -> int:
    """``export``: write :data:`PAGE_MODULE` and the first paint of :data:`PAGES`;
    ``template FILE``: :func:`keep_keyed_in_template`."""
    match list(argv):
        case ["export"]:
            PAGE_MODULE.write_text(module_text(), encoding="utf-8")
            for page in PAGES:
                page.write_text(first_paint(page.read_text(encoding="utf-8")), encoding="utf-8")
        case ["template", path]:
            keep_keyed_in_template(Path(path))
        case _:
            print("usage: python -m actuator_selection.i18n.page_words export | template FILE")
            return 2
    return 0


if __name__ == "__main__":  # pragma: no cover (make messages)
    raise SystemExit(main(sys.argv[1:]))
