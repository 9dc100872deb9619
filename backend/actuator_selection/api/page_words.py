"""The page's words, exported from the gettext catalogue: ``frontend/lib/messages.js``.

The catalogue (``locale/de/LC_MESSAGES/messages.po``) is the one home of every word: the
server's messages (msgids marked with ``N_`` in the code), the documents' labels
(msgctxt ``document.<key>``) and the page's (msgctxt = the key the page asks for, such as
``results.heading``); English is the msgid, German the msgstr (:func:`api.messages.words`).
The page reads its words synchronously from a module, so ``make messages`` writes that
module from the catalogue (``python -m actuator_selection.api.page_words export``) and a
test fails when the checked-in module differs from what the catalogue gives
(``tests/api/test_page_words.py``). ``docs/i18n.md`` says how a word is added.

The module holds, per language, the page's keyed words, ``words.<English>`` for the
catalogue values a check lacks (their German is the server's, the context-less msgid),
and plotly.js's own words (msgctxt ``plotly``, the mode bar's tooltips).
"""

from __future__ import annotations

import json
import sys
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Final

from babel.messages.pofile import read_po, write_po

from actuator_selection.api.messages import (
    DEFAULT_LANGUAGE,
    DOMAIN,
    LANGUAGES,
    PLOTLY,
    SOURCE_CATALOG,
    catalog,
    check_templates,
    translate,
    words,
)
from actuator_selection.config import REPO_ROOT

PAGE_MODULE: Final = REPO_ROOT / "frontend" / "lib" / "messages.js"
"""The page's words as a JavaScript module (checked in; written by ``make messages``)."""

DOCUMENT: Final = "document."
"""The contexts of the documents' labels (not the page's)."""

WORDS_PREFIX: Final = "words."
"""The page's key of a catalogue value a check lacks: ``words.<English>``."""

HEADER: Final = """\
// The page's words in German and English, exported by `make messages` from the gettext
// catalogue (backend/actuator_selection/locale/de/LC_MESSAGES/messages.po: msgctxt = key,
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

    return "\n".join(
        (
            HEADER,
            constant("WORDS", "Language → key → the page's text.", page_words()),
            constant("PLOTLY_WORDS", "Language → plotly.js's English → its text.", plotly_words()),
        )
    )


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
    """``export``: write :data:`PAGE_MODULE`; ``template FILE``: :func:`keep_keyed_in_template`."""
    match list(argv):
        case ["export"]:
            PAGE_MODULE.write_text(module_text(), encoding="utf-8")
        case ["template", path]:
            keep_keyed_in_template(Path(path))
        case _:
            print("usage: python -m actuator_selection.api.page_words export | template FILE")
            return 2
    return 0


if __name__ == "__main__":  # pragma: no cover (make messages)
    raise SystemExit(main(sys.argv[1:]))
