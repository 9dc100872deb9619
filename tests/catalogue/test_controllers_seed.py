"""seed_data/controllers.csv against Table 521.1 as the chapter prints it.

The chapter's table keeps its empty cells as empty tab-separated fields, so each
row has 2 name fields and 16 mark fields read by position. The manufacturer is
a merged cell: an empty field repeats the manufacturer above. Every difference
between the seed and that reading must be a documented correction.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import pytest

CHAPTER = Path(__file__).parents[2].parent / "shared/seed/engineering-data-servo-actuators.txt"
SEED = Path(__file__).parents[2] / "seed_data" / "controllers.csv"
SOURCE = "Harmonic Drive AG, Engineering Data for Harmonic Drive Servo Actuators, Table 521.1"

# The 16 mark columns in the chapter's order (second heading row of Table 521.1).
HEADINGS = (
    ("CHA / CHM", "cha_chm"),
    ("FHAC", "fha_c"),
    ("FFA / FPA", "ffa_fpa"),
    ("LynxDrive", "lynxdrive"),
    ("TorqDrive", "torkdrive"),
    ("FHA-mini", "fha_mini"),
    ("24 VDC", "bus_24vdc"),
    ("320 VDC", "bus_320vdc"),
    ("≥ 560 VDC", "bus_560vdc"),
    ("PTC", "sensor_ptc"),
    ("KTY 84-130", "sensor_kty84_130"),
    ("Resolver", "feedback_resolver_2pole"),
    ("Sinus/Cosinus", "feedback_sincos"),
    ("HIPERFACE", "feedback_hiperface"),
    ("EnDat", "feedback_endat"),
    ("TTL", "feedback_ttl"),
)
MARKS = {"●": "tested", "○": "possible", "": ""}

# Rows whose manufacturer the seed corrects (merged-cell labels one row off).
MANUFACTURER_CORRECTIONS = {
    4: ("NUM AG", "SIEMENS"),  # MASTERDRIVES MC
    5: ("Danaher Motion", "NUM AG"),  # MDLU
    23: ("LTI-Drives", "ELMO"),  # Harmonica
    27: ("Control Techniques", "SEW"),  # MOVIDRIVE B
}


@dataclass(frozen=True, slots=True, kw_only=True)
class PrintedRow:
    number: int
    manufacturer: str  # as the merged cell reads, filled down
    type: str
    marks: tuple[str, ...]


def _chapter_rows() -> list[PrintedRow]:
    if not CHAPTER.is_file():
        pytest.skip(f"the chapter's text is not at {CHAPTER} (shared folder missing)")
    lines = CHAPTER.read_text(encoding="utf-8").split("\n")
    start = next(i for i, line in enumerate(lines) if line.startswith("Tabelle / Table 521.1"))
    header = next(i for i in range(start, len(lines)) if lines[i].startswith("Hersteller"))
    sub = lines[header + 1].split("\t")
    assert len(sub) == 18
    for (label, _), cell in zip(HEADINGS, sub[2:], strict=True):
        assert label in cell, (label, cell)
    rows: list[PrintedRow] = []
    manufacturer = ""
    for line in lines[header + 2 :]:
        if not line.strip():
            break
        fields = line.split("\t")
        assert len(fields) == 18, line
        manufacturer = fields[0] or manufacturer
        rows.append(
            PrintedRow(
                number=len(rows) + 1,
                manufacturer=manufacturer,
                type=fields[1],
                marks=tuple(MARKS[f] for f in fields[2:]),
            )
        )
    return rows


def _seed_rows() -> list[dict[str, str]]:
    with SEED.open(encoding="utf-8", newline="") as f:
        return list(csv.DictReader(f))


def test_one_seed_row_per_source_row_in_order() -> None:
    printed, seed = _chapter_rows(), _seed_rows()
    assert len(printed) == 28
    assert [int(r["source_row"]) for r in seed] == [p.number for p in printed]
    assert [r["type"] for r in seed] == [p.type for p in printed]
    assert all(r["source"] == SOURCE for r in seed)


def test_marks_equal_the_chapter_row_by_row() -> None:
    for p, r in zip(_chapter_rows(), _seed_rows(), strict=True):
        seeded = tuple(r[column] for _, column in HEADINGS)
        assert seeded == p.marks, f"row {p.number} {p.type}"


def test_manufacturers_equal_the_chapter_except_documented_corrections() -> None:
    for p, r in zip(_chapter_rows(), _seed_rows(), strict=True):
        if p.number in MANUFACTURER_CORRECTIONS:
            printed, corrected = MANUFACTURER_CORRECTIONS[p.number]
            assert p.manufacturer == printed, f"row {p.number}"
            assert r["manufacturer"] == corrected, f"row {p.number}"
            assert r["correction"].startswith("manufacturer:"), f"row {p.number}"
            assert printed in r["correction"]
        else:
            assert r["manufacturer"] == p.manufacturer, f"row {p.number}"
            assert "manufacturer:" not in r["correction"], f"row {p.number}"


def test_repeated_types_are_kept_apart_by_variant() -> None:
    printed, seed = _chapter_rows(), _seed_rows()
    counts: dict[str, int] = {}
    for p in printed:
        counts[p.type] = counts.get(p.type, 0) + 1
    for p, r in zip(printed, seed, strict=True):
        if counts[p.type] > 1:
            assert r["variant"] == f"row {p.number}"
            assert "variant:" in r["correction"]
        else:
            assert r["variant"] == ""
    assert {p.type for p in printed if counts[p.type] > 1} == {"S 400", "IndraDrive"}


def test_torqdrive_column_is_read_as_torkdrive() -> None:
    for p, r in zip(_chapter_rows(), _seed_rows(), strict=True):
        has_mark = p.marks[4] != ""
        assert ("TorqDrive read as TorkDrive" in r["correction"]) == has_mark, f"row {p.number}"


def test_every_correction_is_explained() -> None:
    corrected = {int(r["source_row"]) for r in _seed_rows() if r["correction"]}
    # manufacturer rows, variant rows, and rows with a TorkDrive mark
    assert corrected == {1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 22, 23, 27}
