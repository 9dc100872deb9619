"""The documents' words in English and German, and numbers, money and dates per locale.

Every label of the quote document and the selection report is a keyed word of the gettext
catalogue (``locale/de/LC_MESSAGES/messages.po``, msgctxt ``document.<key>``, English the
msgid, German the msgstr; :func:`i18n.localize.words`), so a missing translation is a test
failure rather than an English word on a German page (``tests/api/test_page_words.py``
holds the catalogue complete, ``tests/api/test_quote_terms.py`` every key the documents
use). Numbers,
money and dates are formatted by Babel from the CLDR data of the locale
(``8.861,50 EUR`` and ``24.11.2026`` in German, ``8,861.50 EUR`` and
``24 Nov 2026`` in English).

Text that was entered or stored (customer, notes, terms, item descriptions, the
stored selection's check messages) is shown as it was written.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass
from datetime import date
from decimal import Decimal
from typing import Any, Final, Literal

from babel.dates import format_date
from babel.numbers import format_currency, format_decimal
from markupsafe import Markup

from actuator_selection.documents.symbols import MINUS, symbols
from actuator_selection.i18n.localize import (
    REFERENCE_KEY,
    reference_pattern,
    translate,
    word,
    words,
)
from actuator_selection.sales.quote_terms import LANGUAGES
from actuator_selection.schemas.mechanism_spec import UNIT_SUFFIXES

Language = Literal["en", "de"]

LOCALES: dict[str, str] = {"en": "en_GB", "de": "de_DE"}
"""The Babel locale of each document language (en_GB: day before month, unambiguous
for customers outside the US too)."""

DOCUMENT: Final = "document."
"""The catalogue's context of a document label: ``document.<key>``. A key with a dot is a
word the page shares (``verdict.suitable``, ``quote.status.draft``, ``ref.Table``,
``unit.rpm``)."""


def context(key: str) -> str:
    """The catalogue's msgctxt of the label ``key``.

    >>> context("title"), context("verdict.suitable")
    ('document.title', 'verdict.suitable')
    """
    return key if "." in key else DOCUMENT + key


_SEGMENT_FACT = re.compile(r"segment_(\d+)_(duration_s|start_rpm|end_rpm)")
_CYCLE_FACTS = {
    "accel_s": "accel_time",
    "constant_s": "constant_time",
    "decel_s": "decel_time",
    "pause_s": "pause_time",
}


def negotiate_language(query: str | None, accept_language: str | None) -> Language:
    """The document's language: ``query`` (``?lang=``) if given, else the first language of
    ``Accept-Language`` (by quality) that the document is written in, else English.

    >>> negotiate_language(None, "fr-CH, fr;q=0.9, de;q=0.8, en;q=0.7")
    'de'
    >>> negotiate_language("en", "de-DE")
    'en'
    >>> negotiate_language(None, "de;q=0, en-US")
    'en'
    >>> negotiate_language(None, None)
    'en'
    """
    if query in LANGUAGES:
        return "de" if query == "de" else "en"
    ranked: list[tuple[float, int, str]] = []
    for index, part in enumerate((accept_language or "").split(",")):
        tag, _, params = part.strip().partition(";")
        quality = 1.0
        for param in params.split(";"):
            name, _, value = param.strip().partition("=")
            if name.strip().lower() == "q":
                try:
                    quality = float(value)
                except ValueError:
                    quality = 0.0
        primary = tag.strip().lower().split("-")[0]
        if primary in LANGUAGES and quality > 0:
            ranked.append((-quality, index, primary))
    if not ranked:
        return "en"
    return "de" if min(ranked)[2] == "de" else "en"


@dataclass(frozen=True, slots=True)
class DocumentText:
    """The document's words and formats in one language."""

    language: Language

    @property
    def locale(self) -> str:
        """The Babel locale."""
        return LOCALES[self.language]

    def __call__(self, key: str, **params: object) -> str:
        """The label ``key`` in this language, with ``params`` filled in (not escaped)."""
        text = word(context(key), self.language)
        return text.format(**params) if params else text

    def has(self, key: str) -> bool:
        """Whether the catalogue has the label ``key``."""
        return context(key) in words(self.language)

    def translate(self, text: str) -> str:
        """A server message (a context-less msgid, such as a rule) in this language."""
        return translate(text, self.language)

    def number(self, value: float, pattern: str) -> str:
        """``value`` by a CLDR number ``pattern`` (``#,##0.00``) with this locale's symbols."""
        return format_decimal(value, format=pattern, locale=self.locale).replace("-", MINUS)

    def words(self, key: str, **params: object) -> Markup:
        """The label ``key`` as a document shows it: symbols subscripted (:func:`symbols`)."""
        return symbols(self(key, **params))

    def message(self, text: str) -> Markup:
        """A check's message (already in this language) as a document shows it."""
        return symbols(text)

    def load_rows(self, load: Mapping[str, Any]) -> list[tuple[Markup, str]]:
        """The load as entered, in this language (:func:`load_rows`)."""
        return load_rows(self, load)

    def money(self, amount: Decimal, currency: str) -> str:
        """``8,861.50 EUR`` / ``8.861,50 EUR``: always two decimals (whole cents), the ISO
        code after the amount."""
        return format_currency(
            amount, currency, format="#,##0.00 ¤¤", locale=self.locale, currency_digits=False
        ).replace("-", MINUS)

    def percent(self, value: Decimal) -> str:
        """A rate as written on the document: ``7.5`` / ``7,5``, ``19``."""
        return format_decimal(value, format="#,##0.##", locale=self.locale)

    def date(self, value: date) -> str:
        """``24 Nov 2026`` / ``24.11.2026``."""
        return format_date(value, format="medium", locale=self.locale)

    def reference(self, reference: str) -> str:
        """A stored reference (``Table 515.1; Eq. 514.1``) with the chapter's words in this
        language (``Tabelle 515.1; Gl. 514.1``).

        >>> DocumentText("de").reference("Table 515.1, Eq. 514.2 and Fig. 517.1")
        'Tabelle 515.1, Gl. 514.2 and Abb. 517.1'
        >>> DocumentText("de").reference("Fig. 520.1 (model); Eq. 514.2")
        'Abb. 520.1 (Modell); Gl. 514.2'
        >>> DocumentText("de").reference("Eq. 521.2 with ωL·I in quadrature (560vdc bus)")
        'Gl. 521.2 mit ωL·I in Quadratur (560vdc bus)'
        >>> DocumentText("de").reference("CHA manual 1018854 12/2015, p. 69")
        'CHA Handbuch 1018854 12/2015, S. 69'
        """
        words = re.compile(reference_pattern())
        return words.sub(lambda m: self(f"{REFERENCE_KEY}{m.group(0)}"), reference)

    def cycle_label(self, key: str, label: str) -> str:
        """The label of a cycle fact (``schemas.quotes.cycle_facts``: its key and English
        label) in this language.

        >>> DocumentText("de").cycle_label("segment_2_end_rpm", "segment 2: end speed")
        'Abschnitt 2: Enddrehzahl'
        """
        if key in _CYCLE_FACTS:
            return self(_CYCLE_FACTS[key])
        if (match := _SEGMENT_FACT.fullmatch(key)) is not None:
            return self(f"segment_{match.group(2)}", k=match.group(1))
        return label[:1].upper() + label[1:]

    def unit(self, unit: str) -> str:
        """A unit as the chapter prints it in this language (min⁻¹ for rpm in German)."""
        return self("unit.rpm") if unit == "rpm" else unit


_FIELD_UNITS = UNIT_SUFFIXES
"""A load field's unit by the suffix of its name (``schemas/mechanism_spec.py``: SI or mm,
as the request sends them)."""


def field_unit(name: str, load_type: str | None) -> str:
    """The unit of the load field ``name`` (``speed`` is mm/s on a linear axis, rpm on a
    rotary load).

    >>> field_unit("pulley_diameter_mm", "belt"), field_unit("speed", "belt")
    ('mm', 'mm/s')
    """
    if name == "speed":
        return "rpm" if load_type == "rotary" else "mm/s"
    return next((unit for suffix, unit in _FIELD_UNITS if name.endswith(suffix)), "")


def load_rows(t: DocumentText, load: Mapping[str, Any]) -> list[tuple[Markup, str]]:
    """The load as it was entered (a stored request's ``load``), one (label, value) row a
    field, in ``t``'s words: the load type named, each field by its name and symbol, each
    number with its unit as the chapter prints it; a value sent as text with its own unit
    (``"0.5 in"``) as it was sent.

    >>> rows = load_rows(DocumentText("de"), {"type": "rotary_table", "speed_rpm": 45.0,
    ...     "mass_kg": 30.0, "friction_coefficient": -0.5})
    >>> for label, value in rows:
    ...     print(f"{label}: {value}")
    Mechanik (wie eingegeben): Drehtisch
    Lastdrehzahl n<sub>2</sub>: 45 min⁻¹
    Bewegte Masse m: 30 kg
    Reibungskoeffizient μ: −0,5
    """
    kind = load.get("type")
    rows: list[tuple[Markup, str]] = []
    if isinstance(kind, str):
        rows.append((t.words("mechanism"), _label_or(t, f"load_{kind}", kind)))
    for name, value in load.items():
        if name == "type" or value is None:
            continue
        if isinstance(value, dict):
            rows += [
                (t.words(f"field_{name}_{sub}") if t.has(f"field_{name}_{sub}")
                 else symbols(f"{name} {sub}".replace("_", " ")),
                 _field_value(t, v, field_unit(sub, kind)))
                for sub, v in value.items()
                if v is not None
            ]  # fmt: skip
            continue
        label = (
            t.words(f"field_{name}") if t.has(f"field_{name}") else symbols(name.replace("_", " "))
        )
        rows.append((label, _field_value(t, value, field_unit(name, kind))))
    return rows


def _label_or(t: DocumentText, key: str, fallback: str) -> str:
    return t(key) if t.has(key) else fallback.replace("_", " ")


def _field_value(t: DocumentText, value: object, unit: str) -> str:
    if isinstance(value, bool):
        return t("yes" if value else "no")
    if isinstance(value, int | float):
        return f"{t.number(value, '#,##0.######')} {t.unit(unit)}".strip()
    return str(value)
