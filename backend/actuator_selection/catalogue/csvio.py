"""Reading and validating catalogue CSV files (units in the column names, a source on every row).

A file is read whole and every problem is collected, so that one run names all
the bad cells at once; the caller loads nothing while any problem remains.

The CSV dialect, read and written:

- **Line endings.** LF, CRLF and CR alone are all read as line ends (CR alone is
  what Excel for Mac's "CSV (Macintosh)" still writes; refusing it would refuse a
  common file for no gain). Files are written with LF.
- **Line breaks in cells.** A cell holding a line break (LF, CR or CRLF; only free
  text may, see :func:`text_problem`) is always written in double quotes, so that
  the file reads back with the same cells. (The ``csv`` module alone quotes only
  what the line terminator contains, and would write a bare CR unquoted.)
- **Formula injection (OWASP, "CSV Injection").** A spreadsheet runs a cell that
  begins with ``=``, ``+``, ``-``, ``@``, tab or CR as a formula. On export a text
  cell (not a number, date or other converted value) that begins with one of them,
  or with a single quote ``'``, gets a single quote put in front; on import a text
  cell that begins with a single quote loses that one quote. So ``=1+1`` is
  exported as ``'=1+1`` and ``'quoted`` as ``''quoted``, and export → import gives
  back exactly the stored text. Numeric columns are numbers, not text: ``-40``
  stays ``-40``. The JSON form carries text as it is.
- **Size.** A cell longer than the ``csv`` module's limit (131,072 characters, far
  beyond any column) is a problem naming file and line, not a crash. A row given as a
  JSON object (the JSON import, the admin API's writes) obeys the same limit, counting
  the quote mark its export will put before a formula start, so that whatever is
  stored exports to files that import again.
"""

from __future__ import annotations

import csv
import io
import math
import re
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from datetime import date
from decimal import Decimal
from enum import Enum
from pathlib import Path
from typing import Any

from actuator_selection.text import text_problem


class Rule(Enum):
    """What a numeric cell must satisfy."""

    ANY = "a finite number"
    POSITIVE = "a finite number > 0"
    NON_NEGATIVE = "a finite number ≥ 0"


@dataclass(frozen=True, slots=True)
class NamePattern:
    """The characters a name cell may hold (a regular expression) and the rule in words."""

    regex: re.Pattern[str]
    rule: str


@dataclass(frozen=True, slots=True, kw_only=True)
class Column:
    """One CSV column: its name (with unit), kind and rule, and where the value goes.

    ``scale`` converts the published unit into the stored SI unit once, at the
    edge (e.g. 10⁻³ A/rpm → A/rpm); ``target`` names the stored attribute when it
    differs from the column name. ``magnitude`` bounds a number's size in the
    published unit: no catalogue value comes near 10⁶ (torques, speeds, voltages,
    ohms, seconds), so a larger one is a typo or garbage, not a part.
    ``max_length`` bounds a text cell (the column's width in the database); ``pattern``
    restricts the characters of a name that identifies a row (a model, a family).
    ``convert`` turns a non-empty text cell into its value (a date, a decimal
    a choice, ...) and raises ``ValueError("must be ...")`` naming the
    rule; see :func:`iso_date`, :func:`one_of`. A header may leave out
    an ``optional`` column (one added after files were written without it): its cells
    are then empty.
    """

    name: str
    numeric: bool = False
    required: bool = False
    rule: Rule = Rule.ANY
    magnitude: float = 1e6
    scale: float = 1.0
    target: str | None = None
    max_length: int | None = None
    pattern: NamePattern | None = None
    convert: Callable[[str], Any] | None = None
    optional: bool = False

    @property
    def attribute(self) -> str:
        """Name of the stored attribute."""
        return self.target or self.name

    @property
    def text(self) -> bool:
        """A text column: its cell is stored as written (neither a number nor converted)."""
        return not self.numeric and self.convert is None

    @property
    def free_text(self) -> bool:
        """Free text (not a number, no converter, no width: notes, sources, descriptions),
        which may hold tabs and line breaks; names and codes (a width) are one line."""
        return not self.numeric and self.convert is None and self.max_length is None


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
    values: Mapping[str, Any]


class Cells(Mapping[str, Any]):
    """A row's values by their stored names, compact: the names' places shared by every
    row of a file, the values one tuple. A file of 64,000 actuators is held whole until
    it is validated; a dict per row took 1.6 kB of its 4 kB, this takes 0.5 kB."""

    __slots__ = ("_places", "_values")

    def __init__(self, places: Mapping[str, int], values: Iterable[Any]) -> None:
        self._places = places
        self._values = tuple(values)

    def __getitem__(self, name: str) -> Any:
        return self._values[self._places[name]]

    def __iter__(self) -> Iterator[str]:
        return iter(self._places)

    def __len__(self) -> int:
        return len(self._places)


MAX_CELL_CHARS = csv.field_size_limit()
"""The most characters a cell may hold: the ``csv`` module's limit (131,072), which
reading a file enforces."""
CELL_TOO_LONG = f"has a cell longer than {MAX_CELL_CHARS} characters, the most a CSV cell may hold"


def iso_date(text: str) -> date:
    """A calendar date written YYYY-MM-DD."""
    try:
        return date.fromisoformat(text)
    except ValueError:
        raise ValueError("must be a date written YYYY-MM-DD") from None


def boolean(text: str) -> bool:
    """``true`` or ``false`` (any case)."""
    lowered = text.lower()
    if lowered not in {"true", "false"}:
        raise ValueError("must be true or false")
    return lowered == "true"


WHOLE_NUMBER_MAX = 1_000_000
SMALLEST_MAGNITUDE = 1e-9
"""Smallest non-zero catalogue number: far below any published value (the smallest are
inertias of about 1e-6 kgm²), and large enough that no margin or ratio computed from a
catalogue value overflows (T_max = 1e-300 gave an infinite margin)."""


def whole_number(text: str) -> int:
    """A whole number from 1 to 10⁶ written in digits (a row number, a count)."""
    if not (
        text.isascii() and text.isdigit() and len(text) <= 7 and 1 <= int(text) <= WHOLE_NUMBER_MAX
    ):
        raise ValueError(f"must be a whole number from 1 to {WHOLE_NUMBER_MAX}")
    return int(text)


def one_of(*choices: str) -> Callable[[str], str]:
    """A converter accepting exactly one of ``choices``."""

    def convert(text: str) -> str:
        if text not in choices:
            raise ValueError(f"must be one of: {', '.join(choices)}")
        return text

    return convert


def _cell(spec: CsvSpec, column: Column, raw: str, line: int) -> tuple[Any, Problem | None]:
    text = raw.strip()
    if len(neutralised(text) if column.text else text) > MAX_CELL_CHARS:
        # A file's reader stops at the limit; a cell from JSON, or one that its export
        # would lengthen by the quote mark, stops here.
        return None, Problem(file=spec.file, line=line, column=column.name, message=CELL_TOO_LONG)
    if (rule := text_problem(text, line_breaks=column.free_text)) is not None:
        return None, Problem(file=spec.file, line=line, column=column.name, message=rule)
    if not text.isascii():
        try:
            text.encode("utf-8")
        except UnicodeEncodeError:  # a lone surrogate such as "\ud800" from JSON
            return None, Problem(
                file=spec.file, line=line, column=column.name, message="must be valid Unicode text"
            )
    if not text:
        if column.required:
            return None, Problem(
                file=spec.file, line=line, column=column.name, message="is required but empty"
            )
        return None, None
    if column.convert is not None:
        try:
            return column.convert(text), None
        except ValueError as exc:
            return None, Problem(
                file=spec.file, line=line, column=column.name, message=f"{exc}, got {text!r}"
            )
    if not column.numeric:
        if column.max_length is not None and len(text) > column.max_length:
            return None, Problem(
                file=spec.file,
                line=line,
                column=column.name,
                message=f"must be at most {column.max_length} characters, got {len(text)}",
            )
        if column.pattern is not None and not column.pattern.regex.fullmatch(text):
            return None, Problem(
                file=spec.file,
                line=line,
                column=column.name,
                message=f"{column.pattern.rule}, got {text!r}",
            )
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
    if abs(value) > column.magnitude:
        return None, Problem(
            file=spec.file,
            line=line,
            column=column.name,
            message=f"must be at most {column.magnitude:g} in size, got {text!r}",
        )
    if value != 0 and abs(value) < SMALLEST_MAGNITUDE:
        return None, Problem(
            file=spec.file,
            line=line,
            column=column.name,
            message=f"must be 0 or at least {SMALLEST_MAGNITUDE:g} in size, got {text!r}",
        )
    return value * column.scale, None


def _row(
    spec: CsvSpec, cells: Iterable[tuple[str, str]], line: int
) -> tuple[dict[str, Any], list[Problem]]:
    """Validate the (column name, raw text) pairs of one row; names are known columns."""
    known = {c.name: c for c in spec.columns}
    values: dict[str, Any] = {}
    problems: list[Problem] = []
    for name, raw in cells:
        column = known[name]
        value, problem = _cell(spec, column, raw, line)
        if problem:
            problems.append(problem)
        values[column.attribute] = value
    return values, problems


def _as_text(value: object) -> str | None:
    """A JSON value as the text a CSV cell would hold; None for lists, objects and the like."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str | int | float | Decimal):
        return str(value)
    if isinstance(value, date):
        return value.isoformat()
    return None


def check_values(
    spec: CsvSpec, values: Mapping[str, object], *, line: int = 0
) -> tuple[dict[str, Any], list[Problem]]:
    """Validate one row given as a mapping (e.g. a JSON object) by the rules of ``spec``.

    Keys are the CSV column names; a missing key is an empty cell, an unknown key
    is a problem. Numbers, text and booleans are checked as the text a CSV cell
    would hold, so the API and the seed files share one rulebook and one set of
    messages. Returns the values under their stored names, and the problems.
    """
    known = {c.name for c in spec.columns}
    problems = [
        Problem(
            file=spec.file,
            line=line,
            column=name,
            message="unknown column (columns name their unit, e.g. max_torque_nm; "
            f"expected one of: {', '.join(c.name for c in spec.columns)})",
        )
        for name in values
        if name not in known
    ]
    pairs: list[tuple[str, str]] = []
    for column in spec.columns:
        text = _as_text(values.get(column.name))
        if text is None:
            problems.append(
                Problem(
                    file=spec.file,
                    line=line,
                    column=column.name,
                    message="must be text, a number or null",
                )
            )
            text = ""
        pairs.append((column.name, text))
    checked, cell_problems = _row(spec, pairs, line)
    return checked, problems + cell_problems


def to_cells(spec: CsvSpec, values: Mapping[str, Any]) -> dict[str, str]:
    """The CSV cells of stored ``values`` (the inverse of :func:`parse` for one row).

    Scaled columns are divided back into their published unit; ``repr`` keeps
    floats exact, so writing and reading again gives the same stored numbers.
    """
    cells: dict[str, str] = {}
    for column in spec.columns:
        value = values.get(column.attribute)
        if value is None:
            cells[column.name] = ""
        elif isinstance(value, bool):
            cells[column.name] = "true" if value else "false"
        elif isinstance(value, float):
            shown = value / column.scale if column.scale != 1.0 else value
            cells[column.name] = _float_text(shown, value, column)
        elif isinstance(value, date):
            cells[column.name] = value.isoformat()
        else:
            cells[column.name] = str(value)
    return cells


def to_json_values(spec: CsvSpec, values: Mapping[str, Any]) -> dict[str, Any]:
    """Stored ``values`` as a JSON object keyed by column name, numbers in the published unit.

    Reading the object back with :func:`check_values` gives the same stored values.
    """
    out: dict[str, Any] = {}
    for column, (name, text) in zip(spec.columns, to_cells(spec, values).items(), strict=True):
        value = values.get(column.attribute)
        if value is None:
            out[name] = None
        elif column.numeric:
            out[name] = float(text)
        elif isinstance(value, str | bool | int | float):
            out[name] = value
        else:
            out[name] = text
    return out


def _float_text(shown: float, stored: float, column: Column) -> str:
    """The shortest text of ``shown`` that reads back (after scaling) to ``stored``."""
    text = repr(shown)
    if text.endswith(".0"):
        text = text[:-2]
    if float(text) * column.scale != stored:
        # Division by the scale and multiplication back are not always inverse in
        # binary floating point; fall back to the digits that round-trip.
        for digits in range(1, 18):
            candidate = f"{shown:.{digits}g}"
            if float(candidate) * column.scale == stored:
                return candidate
    return text


FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")
"""First characters that make a spreadsheet read a cell as a formula (OWASP CSV Injection)."""
_TEXT_MARK = "'"
"""Put before a text cell that starts like a formula, or with this mark itself."""


def neutralised(text: str) -> str:
    """``text`` as a CSV text cell: a single quote before a formula start or a single quote.

    >>> neutralised("=HYPERLINK(1)"), neutralised("'quoted"), neutralised("plain")
    ("'=HYPERLINK(1)", "''quoted", 'plain')
    """
    return _TEXT_MARK + text if text.startswith((*FORMULA_STARTS, _TEXT_MARK)) else text


def restored(raw: str) -> str:
    """The text of a CSV text cell: :func:`neutralised` undone (one leading quote removed).

    >>> restored("'=HYPERLINK(1)"), restored("''quoted"), restored(" plain ")
    ('=HYPERLINK(1)', "'quoted", ' plain ')
    """
    stripped = raw.strip()
    return stripped[1:] if stripped.startswith(_TEXT_MARK) else raw


def _line(cells: Sequence[str]) -> str:
    """One CSV record ending in LF, every cell holding CR or LF in double quotes."""
    buffer = io.StringIO()
    # A terminator holding both CR and LF makes the writer quote a cell with either;
    # the record then ends in LF like the rest of the file.
    csv.writer(buffer, lineterminator="\r\n").writerow(cells)
    return buffer.getvalue()[:-2] + "\n"


def write(spec: CsvSpec, rows: Iterable[Mapping[str, Any]]) -> str:
    """CSV text of ``spec`` (header first) for rows of stored values.

    Text cells are :func:`neutralised`; :func:`parse` reads the file back to the same
    stored values.
    """
    out = io.StringIO()
    out.write(_line([c.name for c in spec.columns]))
    for row in rows:
        cells = to_cells(spec, row)
        out.write(
            _line(
                [
                    neutralised(cells[c.name]) if c.text and cells[c.name] else cells[c.name]
                    for c in spec.columns
                ]
            )
        )
    return out.getvalue()


def _duplicate(spec: CsvSpec, record: Record, seen: dict[tuple[Any, ...], int]) -> Problem | None:
    """A problem when ``record`` repeats the key of an earlier row (remembered in ``seen``)."""
    known = {c.name: c for c in spec.columns}
    key = tuple(record.values[known[k].attribute] for k in spec.key)
    if key in seen:
        return Problem(
            file=spec.file,
            line=record.line,
            column=spec.key[0],
            message=f"duplicates line {seen[key]} ({', '.join(map(str, key))})",
        )
    seen[key] = record.line
    return None


def parse_rows(
    spec: CsvSpec, rows: Sequence[Mapping[str, object]]
) -> tuple[list[Record], list[Problem]]:
    """Validate rows given as mappings (a JSON array); a row's ``line`` is its array index."""
    records: list[Record] = []
    problems: list[Problem] = []
    seen: dict[tuple[Any, ...], int] = {}
    for index, row in enumerate(rows):
        values, row_problems = check_values(spec, row, line=index)
        problems.extend(row_problems)
        record = Record(line=index, values=values)
        if not row_problems and (duplicate := _duplicate(spec, record, seen)):
            problems.append(duplicate)
        records.append(record)
    return records, problems


MAX_ROWS = 250_000
"""The most data rows a catalogue file may hold: four times a catalogue of 64,000 actuators
with a zone of three points each. Together with :data:`MAX_CELL_CHARS` it bounds what an
import reads, however well the file compresses (a ZIP bomb is refused by its rows)."""


class TooManyRowsError(ValueError):
    """A file holds more than ``limit`` data rows: the import is refused (413), not read on."""

    def __init__(self, file: str, line: int, limit: int) -> None:
        self.problem = Problem(
            file=file, line=line, column=None, message=f"holds more than {limit} rows"
        )
        super().__init__(str(self.problem))


def _records(
    spec: CsvSpec, text: str | Iterable[str], problems: list[Problem]
) -> Iterator[tuple[int, list[str]]]:
    """The CSV records of ``text`` (the whole file, or its lines as they are read from a
    stream opened with ``newline=""``) with the line each starts on; a record the ``csv``
    module cannot read (e.g. a cell beyond its size limit) ends the file as a problem."""
    # newline="": CR, LF and CRLF all end lines, and line breaks inside quoted cells stay.
    reader = csv.reader(io.StringIO(text, newline="") if isinstance(text, str) else text)
    start = 1
    while True:
        try:
            cells = next(reader)
        except StopIteration:
            return
        except UnicodeDecodeError as exc:  # a stream decodes as it is read
            message = f"is not UTF-8 text ({exc.reason})"
            problems.append(Problem(file=spec.file, line=start, column=None, message=message))
            return
        except csv.Error as exc:
            message = (
                CELL_TOO_LONG
                if "field larger than field limit" in str(exc)
                else f"is not valid CSV ({exc})"
            )
            problems.append(Problem(file=spec.file, line=start, column=None, message=message))
            return
        yield start, cells
        start = reader.line_num + 1


def parse(
    spec: CsvSpec, text: str | Iterable[str], *, max_rows: int = MAX_ROWS
) -> tuple[list[Record], list[Problem]]:
    """Validate the CSV ``text`` against ``spec``; returns the records and every problem.

    ``text`` is the whole file or a stream of its lines (opened with ``newline=""``), read
    row by row: an import never holds the file itself, only its validated rows. A file of
    more than ``max_rows`` data rows raises :class:`TooManyRowsError` at the first row
    beyond. Lines are the lines of the file (a record with a quoted line break spans two);
    text cells are :func:`restored` (see the module's notes on formula injection).
    """
    problems: list[Problem] = []
    reader = _records(spec, text, problems)
    first = next(reader, None)
    if first is None:
        if problems:
            return [], problems
        return [], [Problem(file=spec.file, line=1, column=None, message="file is empty")]
    header = [h.strip() for h in first[1]]
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
    for name, column in known.items():
        if name not in header and not column.optional:
            problems.append(Problem(file=spec.file, line=1, column=name, message="column missing"))
    absent = [(name, "") for name in known if name not in header]
    if len(set(header)) != len(header):
        problems.append(
            Problem(file=spec.file, line=1, column=None, message="a column name appears twice")
        )
    if problems:
        return [], problems
    order = [*header, *(name for name, _ in absent)]
    places = {known[name].attribute: place for place, name in enumerate(order)}
    records: list[Record] = []
    seen: dict[tuple[Any, ...], int] = {}
    rows = 0
    for line, cells in reader:
        if not any(c.strip() for c in cells):
            continue
        rows += 1
        if rows > max_rows:
            raise TooManyRowsError(spec.file, line, max_rows)
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
        pairs = [
            (name, restored(raw) if known[name].text else raw)
            for name, raw in zip(header, cells, strict=True)
        ] + absent
        values, row_problems = _row(spec, pairs, line)
        problems.extend(row_problems)
        record = Record(line=line, values=Cells(places, values.values()))
        if duplicate := _duplicate(spec, record, seen):
            problems.append(duplicate)
        records.append(record)
    return records, problems


def read(spec: CsvSpec, directory: Path) -> tuple[list[Record], list[Problem]]:
    """Validate ``directory / spec.file``; a missing or undecodable file is a problem too."""
    path = directory / spec.file
    try:
        # Bytes, not read_text: its universal newlines would turn a CR inside a quoted
        # cell into LF; parse() reads every line ending itself.
        text = path.read_bytes().decode("utf-8-sig")
    except FileNotFoundError:
        return [], [Problem(file=spec.file, line=0, column=None, message="file not found")]
    except UnicodeDecodeError as exc:
        return [], [
            Problem(
                file=spec.file, line=0, column=None, message=f"is not UTF-8 text ({exc.reason})"
            )
        ]
    return parse(spec, text)
