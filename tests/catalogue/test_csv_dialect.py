"""The catalogue CSV dialect: line endings, quoted line breaks, formula neutralisation, the
text rule and the csv module's cell limit (``catalogue/csvio.py``), without a database."""

from __future__ import annotations

import doctest

import pytest

from actuator_selection.catalogue import csvio
from actuator_selection.catalogue.csvio import (
    Column,
    CsvSpec,
    Rule,
    neutralised,
    parse,
    restored,
    write,
)
from actuator_selection.text import NUL_RULE, text_problem

SPEC = CsvSpec(
    file="t.csv",
    columns=(
        Column(name="name", required=True, max_length=40),
        Column(name="value_nm", numeric=True, rule=Rule.ANY),
        Column(name="notes"),
    ),
    key=("name",),
)

AWKWARD = [
    "=1+1",
    "+49 30",
    "-5 V",
    "@SUM(A1)",
    "'quoted",
    "''twice",
    "it's fine",
    "a\rb",
    "a\nb",
    "a\r\nb",
    'say "hi", then go',
    "tab\tinside",
    "x",
]


def test_doctests() -> None:
    assert doctest.testmod(csvio).failed == 0


@pytest.mark.parametrize("notes", AWKWARD)
def test_write_then_parse_gives_the_stored_text(notes: str) -> None:
    rows = [{"name": "row", "value_nm": -40.0, "notes": notes}]
    text = write(SPEC, rows)
    records, problems = parse(SPEC, text)
    assert problems == []
    assert [r.values for r in records] == rows
    if notes[0] in "=+-@'":
        assert f"'{notes}" in text
    assert text.endswith("\n")
    assert ",-40," in text


@pytest.mark.parametrize("ending", ["\n", "\r\n", "\r"])
def test_every_line_ending_reads(ending: str) -> None:
    text = ending.join(["name,value_nm,notes", "a,1,x", "b,2,y", ""])
    records, problems = parse(SPEC, text)
    assert problems == []
    assert [(r.line, r.values["name"]) for r in records] == [(2, "a"), (3, "b")]


def test_lines_are_lines_of_the_file_after_a_quoted_line_break() -> None:
    text = 'name,value_nm,notes\na,1,"two\nlines"\nb,x,y\n'
    _, problems = parse(SPEC, text)
    assert [(p.line, p.column) for p in problems] == [(4, "value_nm")]


def test_an_enormous_cell_is_a_problem_not_a_crash() -> None:
    text = f"name,value_nm,notes\na,1,x\nb,2,{'x' * 200_000}\n"
    _, problems = parse(SPEC, text)
    assert [(p.line, p.column) for p in problems] == [(3, None)]
    assert "longer than 131072 characters" in problems[0].message


def test_restored_undoes_neutralised() -> None:
    for text in AWKWARD:
        assert restored(neutralised(text)) == text


@pytest.mark.parametrize(
    ("text", "line_breaks", "found"),
    [
        ("plain text, Ω and ü", False, None),
        ("a\x1bb", True, "U+001B"),
        ("\u202eevil", True, "U+202E"),
        ("a\u2069", False, "U+2069"),
        ("a\x9bb", True, "U+009B"),
        ("line\nbreak", False, "U+000A"),
        ("line\nbreak\r\nand\ttab", True, None),
    ],
)
def test_text_rule(text: str, line_breaks: bool, found: str | None) -> None:
    problem = text_problem(text, line_breaks=line_breaks)
    if found is None:
        assert problem is None
    else:
        assert problem is not None
        assert f"found {found}" in problem


def test_nul_keeps_its_own_rule() -> None:
    assert text_problem("a\x00b", line_breaks=True) == NUL_RULE
