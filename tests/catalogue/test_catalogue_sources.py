"""Every catalogue row cites the manufacturer's document, never a mirror website (issue 28,
item 11).

A ``source`` cell names publisher, title, document number, edition and page or table; a
website where a value was read (a public copy of the manual) belongs in ``read_at`` beside
it. The check covers the seed catalogue and the data prepared for new fields under
``docs/catalogue-data/``.
"""

from __future__ import annotations

import csv
import io
from pathlib import Path

import pytest

from actuator_selection.catalogue.citations import citation, mirror_addresses
from actuator_selection.catalogue.csvio import parse, read
from actuator_selection.catalogue.files import ACTUATORS, CATALOGUE_SPECS
from actuator_selection.config import SEED_DIR

CATALOGUE_DATA = Path(__file__).resolve().parents[2] / "docs" / "catalogue-data"


def test_the_pattern_finds_the_mirrors_the_catalogue_was_read_on() -> None:
    """The check can fail: the addresses the seed's sources held before item 11 are found."""
    assert mirror_addresses(
        "Table 36.1, p. 36 (checked: easymanua.ls/harmonic-drive/cha/manual?p=36)"
    )
    assert mirror_addresses("manualshive.com/en/manual/harmonic-drive/fha-series/3976486?page=9")
    assert mirror_addresses("see https://www.yumpu.com/en/document/view/44572722")
    assert not mirror_addresses("https://www.harmonicdrive.de/en/downloads")
    assert not mirror_addresses(
        citation("p. 36 (checked: easymanua.ls/harmonic-drive/cha/manual?p=36)")
    )
    assert not mirror_addresses(
        "Harmonic Drive AG, Engineering Data AC Servo Actuators CHA, 1018854 12/2015 V01, "
        "Table 36.3, p. 36; §1-4-2; Eq. 68.1; 10^3 Nm/rad"
    )


@pytest.mark.parametrize("spec", CATALOGUE_SPECS, ids=lambda spec: spec.file)
def test_no_seed_source_holds_a_mirror_address(spec: object) -> None:
    rows, problems = read(spec, SEED_DIR)  # type: ignore[arg-type]
    assert not problems
    found = {r.line: mirror_addresses(r.values["source"]) for r in rows}
    assert {line: a for line, a in found.items() if a} == {}


def test_the_actuators_keep_where_values_were_read_beside_the_citation() -> None:
    rows, problems = read(ACTUATORS, SEED_DIR)
    assert not problems
    read_at = [r.values["read_at"] for r in rows if r.values["read_at"]]
    assert read_at, "the public copies the values were checked on are kept"
    assert all(mirror_addresses(text) for text in read_at if "page" in text or "?p=" in text)


@pytest.mark.parametrize("path", sorted(CATALOGUE_DATA.glob("*.csv")), ids=lambda p: p.name)
def test_no_prepared_source_holds_a_mirror_address(path: Path) -> None:
    with path.open(encoding="utf-8", newline="") as file:
        rows = list(csv.DictReader(file))
    assert rows
    assert {
        i: mirror_addresses(r["source"])
        for i, r in enumerate(rows, 2)
        if mirror_addresses(r["source"])
    } == {}
    assert all(r["source"].strip() for r in rows), "every row names where it looked"


def test_an_actuators_file_written_before_read_at_still_reads() -> None:
    """``read_at`` came later (revision 0010): a file without the column reads, its cells
    empty, and every other column is still required."""
    rows = list(csv.reader(io.StringIO((SEED_DIR / "actuators.csv").read_text())))
    at = rows[0].index("read_at")
    without = [row[:at] + row[at + 1 :] for row in rows]
    text = io.StringIO()
    csv.writer(text, lineterminator="\n").writerows(without)
    records, problems = parse(ACTUATORS, text.getvalue())
    assert problems == []
    assert len(records) == len(rows) - 1
    assert all(r.values["read_at"] is None for r in records)
    source = rows[0].index("source")
    no_source = [row[:source] + row[source + 1 :] for row in rows]
    text = io.StringIO()
    csv.writer(text, lineterminator="\n").writerows(no_source)
    _, problems = parse(ACTUATORS, text.getvalue())
    assert [(p.column, p.message) for p in problems] == [("source", "column missing")]
