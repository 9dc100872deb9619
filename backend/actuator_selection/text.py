r"""The rules every text the service accepts obeys: no NUL, no control characters, no BiDi.

Request bodies (``schemas.common.StrictModel``), catalogue and price cells
(``catalogue.csvio``) and URLs (``http.errors``) are checked by the same function.

>>> text_problem("FHA-25C-50-L") is None
True
>>> text_problem("Hauptstr. 1\n12345 Musterstadt", line_breaks=True) is None
True
>>> text_problem("evil\u202eman").endswith("found U+202E at character 5")
True
"""

from __future__ import annotations

import re

NUL_RULE = "must not contain the NUL character (U+0000)"
"""Every text the service stores obeys it: PostgreSQL's text types cannot hold U+0000
(catalogue cells here, request bodies in ``schemas.common``, URLs in ``http.errors``)."""

_CONTROLS = "U+0000–U+001F, U+007F–U+009F"
_BIDI = "U+202A–U+202E, U+2066–U+2069"
ONE_LINE_RULE = (
    f"must be one line of text without control characters ({_CONTROLS}) or bidirectional "
    f"overrides ({_BIDI})"
)
MULTI_LINE_RULE = (
    f"must not contain control characters other than tab and line breaks ({_CONTROLS}) or "
    f"bidirectional overrides ({_BIDI})"
)
_ONE_LINE_BAD = re.compile("[\x00-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")
_MULTI_LINE_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\u202a-\u202e\u2066-\u2069]")


def text_problem(text: str, *, line_breaks: bool = False) -> str | None:
    """The rule ``text`` breaks, naming the first offending character; None if it is clean.

    The one rule for every text the service accepts (request bodies through
    ``schemas.common.StrictModel``, catalogue and price cells here), because text ends
    up in documents, spreadsheets and terminals: C0 and C1 control characters (ESC
    starts terminal escape sequences, BEL rings) and the bidirectional embeddings,
    overrides and isolates (U+202A–U+202E, U+2066–U+2069, "Trojan Source") make text
    display other than it reads. Multi-line text (``line_breaks``: a quote's address
    and notes, free-text catalogue columns) may hold tab, LF and CR; names, codes and
    other one-line text may not. U+0000 has its own rule (:data:`NUL_RULE`).
    """
    if "\x00" in text:
        return NUL_RULE
    found = (_MULTI_LINE_BAD if line_breaks else _ONE_LINE_BAD).search(text)
    if found is None:
        return None
    rule = MULTI_LINE_RULE if line_breaks else ONE_LINE_RULE
    return f"{rule}; found U+{ord(found.group()):04X} at character {found.start() + 1}"
