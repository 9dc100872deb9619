"""The page's German words for the catalogue values a check lacks (``words.…`` of
``frontend/lib/i18n.js``) are the server catalog's: one German word for one thing."""

from __future__ import annotations

import json
import re
from pathlib import Path

from actuator_selection.api.messages import check_templates, translate

I18N = Path(__file__).resolve().parents[2] / "frontend" / "lib" / "i18n.js"
ENTRY = re.compile(r'^\s*"words\.((?:[^"\\]|\\.)*)":\s*("(?:[^"\\]|\\.)*"),$', re.MULTILINE)


def test_the_page_words_every_missing_value_as_the_catalog_does() -> None:
    page = {
        json.loads(f'"{key}"'): json.loads(text) for key, text in ENTRY.findall(I18N.read_text())
    }
    words = {t for key, t in check_templates().items() if key.startswith("check_word:")}
    assert set(page) == words, set(page) ^ words
    for english, german in page.items():
        assert german == translate(english, "de"), english
        assert german != english, english
