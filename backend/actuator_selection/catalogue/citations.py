"""Citations of catalogue values: the manufacturer's document, never a mirror website.

A catalogue row's ``source`` names publisher, title, document number, edition and page or
table of the manufacturer's document; the public copy on which a value was read (a mirror
website such as a manual-sharing site) is kept beside it in ``read_at`` and never printed
in its place (issue 28, item 11; shared/reference/public-catalogue-data.md, "How to cite a
value"). Quotes stored before the two were split keep the old text in their snapshot:
:func:`citation` takes the mirror addresses out of such a text before it is printed.
"""

from __future__ import annotations

import re

MANUFACTURER_DOMAINS = ("harmonicdrive.de", "harmonicdrive.net", "hds.co.jp")
"""Harmonic Drive AG, Harmonic Drive LLC and Harmonic Drive Systems Inc.: an address on the
manufacturer's own site is its document; any other address is a mirror."""

WEB_ADDRESS = re.compile(
    r"(?:https?://|www\.)[^\s;()]+|\b(?:[a-z0-9-]+\.)+(?:com|ls|net|org|de|io|tips|top|jp)/[^\s;()]*",
    re.IGNORECASE,
)
"""A web address with or without scheme (``easymanua.ls/harmonic-drive/cha/manual?p=36``)."""

_GROUP = re.compile(r"\(([^()]*)\)")
_READ_WORDS = re.compile(r"^\s*(?:checked:|public copy)\s*", re.IGNORECASE)


def _is_mirror(address: str) -> bool:
    return not any(domain in address.lower() for domain in MANUFACTURER_DOMAINS)


def mirror_addresses(text: str) -> list[str]:
    """The web addresses in ``text`` that are not on a manufacturer's site.

    >>> mirror_addresses("p. 36 (checked: easymanua.ls/harmonic-drive/cha/manual?p=36)")
    ['easymanua.ls/harmonic-drive/cha/manual?p=36']
    >>> mirror_addresses("https://www.harmonicdrive.de/en/downloads; Table 36.3, p. 36")
    []
    """
    return [a for a in WEB_ADDRESS.findall(text) if _is_mirror(a)]


def citation(text: str) -> str:
    """``text`` as a citation to print: every mirror address removed, with the words that
    only introduced it ("checked:", "public copy") and the brackets it leaves empty.

    >>> citation("CHA, 1018854 12/2015 V01, Table 36.1, p. 36 (checked: easymanua.ls/x?p=36)")
    'CHA, 1018854 12/2015 V01, Table 36.1, p. 36'
    >>> citation("Table 38.3, p. 38 (checked: easymanua.ls/x?p=38; 8/2018 V03 Table 42.3 agrees)")
    'Table 38.3, p. 38 (8/2018 V03 Table 42.3 agrees)'
    >>> citation("Table 516.3")
    'Table 516.3'
    """
    if not mirror_addresses(text):
        return text

    def group(match: re.Match[str]) -> str:
        inner = match.group(1)
        if not mirror_addresses(inner):
            return match.group(0)
        parts = [
            _READ_WORDS.sub(
                "", WEB_ADDRESS.sub(lambda a: "" if _is_mirror(a.group(0)) else a.group(0), part)
            ).strip()
            for part in inner.split(";")
        ]
        kept = "; ".join(p for p in parts if p)
        return f"({kept})" if kept else ""

    previous = None
    while previous != text:
        previous, text = text, _GROUP.sub(group, text)
    text = WEB_ADDRESS.sub(lambda a: "" if _is_mirror(a.group(0)) else a.group(0), text)
    return re.sub(r"\s+([;,.)])", r"\1", re.sub(r"[ \t]{2,}", " ", text)).strip()
