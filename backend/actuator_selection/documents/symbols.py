"""The chapter's symbols and signs as documents print them, one rule for every document.

Texts and messages write a symbol ``X_sub`` (n_av, T_rms, J_L, η_tr), as the page's
``frontend/lib/symbols.js`` reads them; a document shows ``X<sub>sub</sub>`` in HTML
(:func:`symbols`); a PDF sets it in Unicode's subscript letters where they exist
(:func:`subscript`), else lowered and smaller (``documents/pdf.py``). A negative
number gets the minus sign (U+2212), as the page's ``frontend/lib/format.js`` writes it.
"""

from __future__ import annotations

import re

from markupsafe import Markup

MINUS = "\u2212"
"""The minus sign of negative numbers in documents, as the page writes them
(``frontend/lib/format.js``): ``−85.48``, not the hyphen ``-85.48``."""

_HYPHEN_MINUS = re.compile(r"(?<![\w.,])-(?=\d)")

SYMBOL = re.compile(r"(^|[^A-Za-z0-9_])([A-Za-zα-ωΑ-Ω])_([A-Za-z0-9]+)")
"""The chapter's symbols as texts write them, ``X_sub`` (n_av, T_rms, J_L): the page's
rule (``frontend/lib/symbols.js``), and Greek letters (η_tr)."""

_SUBSCRIPT = dict(zip("0123456789aehiklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢₖₗₘₙₒₚᵣₛₜᵤᵥₓ", strict=True))


def with_minus(text: str) -> str:
    """``text`` with the hyphen before a number written as the minus sign.

    >>> with_minus("T_3 = -85.48 Nm, CHA-25A-50, 514.1-2")
    'T_3 = −85.48 Nm, CHA-25A-50, 514.1-2'
    """
    return _HYPHEN_MINUS.sub(MINUS, text)


def symbols(text: str) -> Markup:
    """``text`` escaped, with the chapter's symbols ``X_sub`` as ``X<sub>sub</sub>`` and the
    minus sign before negative numbers: a label or message of a document (HTML, and the
    PDF through :func:`subscript`).

    >>> str(symbols("n_av < 3 & T_rms = -2"))
    'n<sub>av</sub> &lt; 3 &amp; T<sub>rms</sub> = −2'
    """
    escaped = str(Markup.escape(with_minus(text)))
    return Markup(SYMBOL.sub(r"\1\2<sub>\3</sub>", escaped))


def subscript(text: str) -> str:
    """A subscript in plain text: Unicode's subscript letters where each has one (``av`` →
    ``ₐᵥ``, ``rms`` → ``ᵣₘₛ``); else as it is (Unicode has no subscript capitals: a PDF
    then sets ``L`` of ``T_L`` lowered and smaller, ``documents.pdf.DocumentPdf``).

    >>> subscript("av"), subscript("max"), subscript("L")
    ('ₐᵥ', 'ₘₐₓ', 'L')
    """
    if all(ch in _SUBSCRIPT for ch in text):
        return "".join(_SUBSCRIPT[ch] for ch in text)
    return text
