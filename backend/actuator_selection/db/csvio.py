"""Reading and validating catalogue CSV files (units in the column names, a source on every row).

A file is read whole and every problem is collected, so that one run names all
the bad cells at once; the caller loads nothing while any problem remains.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import Enum
from pathlib import Path
from typing import Any


class Rule(Enum):
    """What a numeric cell must satisfy."""

    ANY = "a finite number"
    POSITIVE = "a finite number > 0"
    NON_NEGATIVE = "a finite number ≥ 0"


@dataclass(frozen=True, slots=True, kw_only=True)
class Column:
    """One CSV column: its name (with unit), kind and rule, and where the value goes.

    ``scale`` converts the published unit into the stored SI unit once, at the
    edge (e.g. 10⁻³ A/rpm → A/rpm); ``target`` names the stored attribute when it
    differs from the column name.
    """

    name: str
    numeric: bool = False
    required: bool = False
    rule: Rule = Rule.ANY
    scale: float = 1.0
    target: str | None = None

    @property
    def attribute(self) -> str:
        """Name of the stored attribute."""
        return self.target or self.name


@dataclass(frozen=True, slots=True, kw_only=True)
class CsvSpec:
    """The expected layout of one catalogue file."""

    file: str
    columns: tuple[Column, ...]
    key: tuple[str, ...]


@dataclass(frozen=True, slots=True, kw_only=True)
class Problem:
    """A bad cell, row or header: file, 1-based line (the header is line 1), column, rule."""

    file: str
    line: int
    column: str | None
    message: str

    def __str__(self) -> str:
        where = f"{self.file}, line {self.line}"
        if self.column:
            where += f", column {self.column}"
        return f"{where}: {self.message}"


class CatalogueFileError(ValueError):
    """One or more problems in catalogue files; nothing was loaded."""

    def __init__(self, problems: Sequence[Problem]) -> None:
        self.problems = tuple(problems)
        super().__init__("\n".join(str(p) for p in self.problems))


@dataclass(frozen=True, slots=True, kw_only=True)
class Record:
    """A validated row: its line in the file and its values under their stored names."""

    line: int
    values: dict[str, Any]


def _cell(spec: CsvSpec, column: Column, raw: str, line: int) -> tuple[Any, Problem | None]:
    text = raw.strip()
    if not text:
        if column.required:
            return None, Problem(
                file=spec.file, line=line, column=column.name, message="is required but empty"
            )
        return None, None
    if not column.numeric:
        return text, None
    try:
        value = float(text)
    except ValueError:
        return None, Problem(
            file=spec.file,
            line=line,
            column=column.name,
            message=f"must be {column.rule.value}, got {text!r}",
        )
    ok = math.isfinite(value) and (
        column.rule is Rule.ANY
        or (column.rule is Rule.POSITIVE and value > 0)
        or (column.rule is Rule.NON_NEGATIVE and value >= 0)
    )
    if not ok:
        return None, Problem(
            file=spec.file,
            line=line,
            column=column.name,
            message=f"must be {column.rule.value}, got {text!r}",
        )
    return value * column.scale, None


def parse(spec: CsvSpec, text: str) -> tuple[list[Record], list[Problem]]:
    """Validate the CSV ``text`` against ``spec``; returns the records and every problem."""
    problems: list[Problem] = []
    reader = csv.reader(io.StringIO(text))
    header = next(reader, None)
    if header is None:
        return [], [Problem(file=spec.file, line=1, column=None, message="file is empty")]
    header = [h.strip() for h in header]
    known = {c.name: c for c in spec.columns}
    for name in header:
        if name not in known:
            problems.append(
                Problem(
                    file=spec.file,
                    line=1,
                    column=name,
                    message="unknown column (columns name their unit, e.g. max_torque_nm; "
                    f"expected one of: {', '.join(known)})",
                )
            )
    for name in known:
        if name not in header:
            problems.append(Problem(file=spec.file, line=1, column=name, message="column missing"))
    if len(set(header)) != len(header):
        problems.append(
            Problem(file=spec.file, line=1, column=None, message="a column name appears twice")
        )
    if problems:
        return [], problems
    records: list[Record] = []
    seen: dict[tuple[Any, ...], int] = {}
    for line, cells in enumerate(reader, start=2):
        if not any(c.strip() for c in cells):
            continue
        if len(cells) != len(header):
            problems.append(
                Problem(
                    file=spec.file,
                    line=line,
                    column=None,
                    message=f"has {len(cells)} cells, the header {len(header)}",
                )
            )
            continue
        values: dict[str, Any] = {}
        for name, raw in zip(header, cells, strict=True):
            column = known[name]
            value, problem = _cell(spec, column, raw, line)
            if problem:
                problems.append(problem)
            values[column.attribute] = value
        key = tuple(values[known[k].attribute] for k in spec.key)
        if key in seen:
            problems.append(
                Problem(
                    file=spec.file,
                    line=line,
                    column=spec.key[0],
                    message=f"duplicates line {seen[key]} ({', '.join(map(str, key))})",
                )
            )
        else:
            seen[key] = line
        records.append(Record(line=line, values=values))
    return records, problems


def read(spec: CsvSpec, directory: Path) -> tuple[list[Record], list[Problem]]:
    """Validate ``directory / spec.file``; a missing or undecodable file is a problem too."""
    path = directory / spec.file
    try:
        text = path.read_text(encoding="utf-8-sig")
    except FileNotFoundError:
        return [], [Problem(file=spec.file, line=0, column=None, message="file not found")]
    except UnicodeDecodeError as exc:
        return [], [
            Problem(
                file=spec.file, line=0, column=None, message=f"is not UTF-8 text ({exc.reason})"
            )
        ]
    return parse(spec, text)
