"""Reading a motion profile file: a CSV of samples, streamed, bounded in size and time.

Two forms are read, told apart by the heading line:

- the motion file of IDTA 02021 §2.2.2: headings ``idShort [unit]``, ``;`` between
  columns, ``.`` as the decimal point (``Time [s];AngularVelocity [rad/s]``);
- a plain CSV with a heading line: ``;``, tab or ``,`` between columns (the heading line
  tells which), a decimal point or, with ``;`` or tab, a decimal comma (the first row of
  numbers tells which); units in the headings (``[unit]`` or ``(unit)``) or chosen on
  upload (:class:`ColumnUnits`).

Columns are recognised by their heading's name (:data:`COLUMN_NAMES`): the time, and the
position or the velocity (the velocity where both are given), optionally the
acceleration and the process load (a torque or a force). Other columns are listed and not
read. A file that breaks a rule is a 422 whose entry names the line and the column
(``loc``: ``["body", line, column]``, both counted from 1).
"""

from __future__ import annotations

import codecs
import math
import re
import time
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt
from pydantic_core import PydanticCustomError

from actuator_selection.schemas.quantities import (
    ANGLE_DEG,
    FORCE_N,
    LENGTH_MM,
    LINEAR_ACCEL_MM_PER_S2,
    LINEAR_SPEED_MM_PER_S,
    ROTARY_ACCEL_RPM_PER_S,
    ROTARY_SPEED_RPM,
    TIME_S,
    TORQUE_NM,
    QuantityKind,
    to_unit,
)
from actuator_selection.services.errors import Loc, UseCaseError, invalid

MAX_PROFILE_BYTES = 32 * 1024 * 1024
"""Largest profile file [bytes]: 1,000,000 rows of four columns at full precision."""

MAX_SAMPLES = 1_000_000
"""Most rows of samples: an hour at 4 ms, or 1000 s of a 1 kHz trace."""

MAX_LINE_CHARS = 2000
"""Longest line [characters]: a row of 32 numbers at full precision needs ~800."""

MAX_COLUMNS = 32
"""Most columns: a trace of many signals of which a few are read."""

READ_SECONDS = 10.0
"""Longest time reading one file may take [s]: a bound on the work a request can cause."""

ROLES = ("time", "position", "velocity", "acceleration", "load")

COLUMN_NAMES: dict[str, frozenset[str]] = {
    "time": frozenset({"time", "t", "zeit"}),
    "position": frozenset(
        {"position", "angularposition", "linearposition", "pos", "angle", "winkel", "weg", "x"}
    ),
    "velocity": frozenset(
        {
            "velocity",
            "angularvelocity",
            "linearvelocity",
            "speed",
            "v",
            "n",
            "omega",
            "geschwindigkeit",
            "drehzahl",
        }
    ),
    "acceleration": frozenset(
        {"acceleration", "angularacceleration", "linearacceleration", "a", "alpha"}
        | {"beschleunigung"}
    ),
    "load": frozenset(
        {
            "torque",
            "loadtorque",
            "processtorque",
            "moment",
            "drehmoment",
            "lastmoment",
            "force",
            "loadforce",
            "processforce",
            "kraft",
            "lastkraft",
        }
    ),
}
"""Heading names of each column, lower case without spaces, ``_`` and ``-`` (the IDTA
idShorts ``Time``, ``AngularPosition``, ``AngularVelocity``, ``AngularAcceleration``,
``LinearPosition``, … among them)."""

_ROTARY: dict[str, QuantityKind] = {
    "position": ANGLE_DEG,
    "velocity": ROTARY_SPEED_RPM,
    "acceleration": ROTARY_ACCEL_RPM_PER_S,
    "load": TORQUE_NM,
}
_LINEAR: dict[str, QuantityKind] = {
    "position": LENGTH_MM,
    "velocity": LINEAR_SPEED_MM_PER_S,
    "acceleration": LINEAR_ACCEL_MM_PER_S2,
    "load": FORCE_N,
}

_PER_MINUTE = re.compile(r"\s*(?:1\s*/\s*min|min\^?-1|min⁻¹|U\s*/\s*min)\s*")
"""Drive engineering's spellings of revolutions per minute (``1/min``, ``min⁻¹``,
``U/min``), read as rpm in a velocity column: pint reads ``1/min`` as a frequency."""

_NUMBER = re.compile(r"[+-]?(?:[0-9]+(?:\.[0-9]*)?|\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
_HEADING = re.compile(r"\s*(?P<name>[^\[\(]*?)\s*(?:[\[\(](?P<unit>[^\]\)]*)[\]\)])?\s*")
_CONTROL = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\x7f]")


@dataclass(frozen=True, slots=True, kw_only=True)
class ColumnUnits:
    """Units chosen on upload, for columns whose heading gives none (pint's spelling)."""

    time: str | None = "s"
    position: str | None = None
    velocity: str | None = None
    acceleration: str | None = None
    load: str | None = None


@dataclass(slots=True, kw_only=True)
class ProfileSamples:
    """The columns read, in the profile's units: times [s], the motion in rpm or mm/s (or
    positions in rev or mm), the load in Nm or N."""

    kind: str
    """``rotary`` or ``linear``."""
    time_s: npt.NDArray[np.float64]
    motion: npt.NDArray[np.float64]
    from_positions: bool
    load: npt.NDArray[np.float64] | None
    acceleration: npt.NDArray[np.float64] | None
    columns: dict[str, str] = field(default_factory=dict)
    """Each role read, and the heading it was read from."""
    ignored: list[str] = field(default_factory=list)
    """Headings of columns not read."""
    lines: int = 0


def _error(line: int, column: int | None, code: str, **params: object) -> UseCaseError:
    loc: Loc = ["body", line] if column is None else ["body", line, column]
    where: dict[str, Any] = {"line": line} if column is None else {"line": line, "column": column}
    return invalid(loc, code, None, **where, **params)


def blocks_of(chunks: Iterable[bytes]) -> Iterator[tuple[int, list[str]]]:
    """The file's lines in blocks as the chunks arrive: the number of each block's first
    line (from 1) and its lines, decoded as UTF-8 (a leading BOM dropped; LF, CRLF or CR
    end a line); a 422 for a file past :data:`MAX_PROFILE_BYTES`, binary content or a line
    past :data:`MAX_LINE_CHARS`."""
    decoder = codecs.getincrementaldecoder("utf-8")("strict")
    pending = ""
    number = 0  # lines handed out so far
    size = 0
    started = False
    for chunk in [*chunks, None]:
        if chunk is not None:
            size += len(chunk)
            if size > MAX_PROFILE_BYTES:
                raise _error(number + 1, None, "profile_too_large", max=MAX_PROFILE_BYTES)
        try:
            text = decoder.decode(chunk or b"", final=chunk is None)
        except UnicodeDecodeError as exc:
            before = pending.count("\n") + (chunk or b"")[: max(exc.start, 0)].count(b"\n")
            raise _error(number + 1 + before, None, "profile_binary") from None
        if not started and text:
            text, started = text.removeprefix("\ufeff"), True
        text = pending + text
        if chunk is not None and text.endswith("\r"):
            text, pending = text[:-1], "\r"  # a CR whose LF may follow
        else:
            pending = ""
        if "\r" in text:
            text = text.replace("\r\n", "\n").replace("\r", "\n")
        lines = text.split("\n")
        if chunk is not None:
            pending = lines.pop() + pending  # the line not yet ended
            if len(pending) > MAX_LINE_CHARS:
                raise _error(
                    number + 1 + len(lines), None, "profile_line_too_long", max=MAX_LINE_CHARS
                )
        bad = _CONTROL.search(text)
        if bad is not None and (chunk is None or bad.start() < len(text) - len(pending)):
            raise _error(number + 1 + text.count("\n", 0, bad.start()), None, "profile_binary")
        if lines and max(map(len, lines)) > MAX_LINE_CHARS:
            longest = next(i for i, line in enumerate(lines) if len(line) > MAX_LINE_CHARS)
            raise _error(number + 1 + longest, None, "profile_line_too_long", max=MAX_LINE_CHARS)
        if lines:
            yield number + 1, lines
            number += len(lines)


def _role(name: str) -> str | None:
    key = re.sub(r"[\s_\-]", "", name).lower()
    for role, names in COLUMN_NAMES.items():
        if key in names:
            return role
    return None


def _factor(unit: str, kind: QuantityKind) -> float | None:
    """The unit's size in ``kind.unit`` (a profile's units scale, they never offset), or
    None where it is no unit of that kind."""
    try:
        return to_unit(f"1 {unit}", kind)
    except PydanticCustomError:
        return None


@dataclass(frozen=True, slots=True)
class _Column:
    index: int
    role: str
    heading: str
    unit: str | None


def _columns(line: int, cells: list[str], units: ColumnUnits) -> tuple[list[_Column], list[str]]:
    if len(cells) > MAX_COLUMNS:
        raise _error(line, MAX_COLUMNS + 1, "profile_too_many_columns", max=MAX_COLUMNS)
    columns: dict[str, _Column] = {}
    ignored = []
    for index, cell in enumerate(cells):
        match = _HEADING.fullmatch(cell)
        name = match["name"] if match else cell
        role = _role(name) if match else None
        if role is None:
            ignored.append(cell.strip())
            continue
        if role in columns:
            raise _error(line, index + 1, "profile_column_twice", heading=cell.strip()[:80])
        unit = (match["unit"] if match else None) or getattr(units, role)
        columns[role] = _Column(index, role, cell.strip()[:80], unit.strip() if unit else None)
    if "time" not in columns:
        raise _error(line, None, "profile_no_time_column")
    if "velocity" not in columns and "position" not in columns:
        raise _error(line, None, "profile_no_motion_column")
    if "velocity" in columns and "position" in columns:
        ignored.append(columns.pop("position").heading)
    return list(columns.values()), ignored


def _scales(line: int, columns: list[_Column]) -> tuple[str, dict[str, float]]:
    """The profile's kind (rotary or linear, from the motion column's unit) and each
    column's factor to its unit."""
    scales: dict[str, float] = {}
    kind = "rotary"
    order = {"time": 0, "velocity": 1, "position": 1, "acceleration": 2, "load": 2}
    for col in sorted(columns, key=lambda c: order[c.role]):
        if col.unit is None:
            raise _error(line, col.index + 1, "profile_unit_missing", heading=col.heading)
        unit = col.unit
        if col.role == "velocity" and _PER_MINUTE.fullmatch(unit):
            unit = "rpm"
        if col.role == "time":
            choices: tuple[QuantityKind, ...] = (TIME_S,)
        elif order[col.role] == 1:
            choices = (_ROTARY[col.role], _LINEAR[col.role])
        else:
            choices = ((_ROTARY if kind == "rotary" else _LINEAR)[col.role],)
        factor = None
        for choice in choices:
            factor = _factor(unit, choice)
            if factor is not None:
                if order[col.role] == 1:
                    kind = "rotary" if choice is _ROTARY[col.role] else "linear"
                break
        if factor is None and order[col.role] == 2:
            other = (_LINEAR if kind == "rotary" else _ROTARY)[col.role]
            if _factor(unit, other) is not None:
                raise _error(
                    line, col.index + 1, "profile_unit_kinds", heading=col.heading, unit=unit
                )
        if factor is None or not math.isfinite(factor) or factor <= 0:
            raise _error(
                line,
                col.index + 1,
                "profile_unit_wrong",
                heading=col.heading,
                unit=col.unit[:40],
                expected=" or ".join(c.label for c in choices),
            )
        scales[col.role] = factor
    return kind, scales


def _number(text: str, comma: bool | None) -> float | None:
    text = text.strip()
    if comma:
        text = text.replace(",", ".")
    if not _NUMBER.fullmatch(text):
        return None
    return float(text)


def _skipped(line: str) -> bool:
    """A blank line or a comment (``#``)."""
    stripped = line.lstrip()
    return not stripped or stripped.startswith("#")


@dataclass(slots=True)
class _Reader:
    """The rows after the heading line, block by block (:meth:`block`)."""

    sep: str
    width: int
    read: list[tuple[int, str]]
    scales: dict[str, float]
    deadline: float
    comma: bool | None = None
    rows: int = 0
    last_time: float = -math.inf
    values: dict[str, list[Any]] = field(default_factory=dict)

    def block(self, first: int, lines: list[str]) -> None:
        """Read ``lines`` (the first numbered ``first``): all at once where every line is
        a row of plain numbers, else line by line, which names the line and cell that
        breaks a rule."""
        if time.monotonic() > self.deadline:
            raise _error(first, None, "profile_too_slow", seconds=READ_SECONDS)
        text = "\n".join(lines)
        if self.comma is None and self.sep != ",":  # decided by the first decimal mark
            self.comma = True if "," in text else False if "." in text else None
        if not self._fast(first, lines, text):
            for k, line in enumerate(lines):
                if not _skipped(line):
                    self._line(first + k, line)

    def _fast(self, first: int, lines: list[str], text: str) -> bool:
        if not text.isascii() or "_" in text or "#" in text or "" in lines:
            return False  # Unicode digits, 1_000, comments, blank lines: line by line
        if self.comma:
            text = text.replace(",", ".")
        cells = text.replace("\n", self.sep).split(self.sep)
        if len(cells) != self.width * len(lines):
            return False
        columns = {}
        try:
            for index, role in self.read:
                columns[role] = np.array(cells[index :: self.width], dtype=np.float64)
        except ValueError:
            return False
        if self.rows + len(lines) > MAX_SAMPLES:
            return False
        for _, role in self.read:
            column = columns[role] * self.scales[role]
            wrong = ~np.isfinite(column)
            if role == "time":
                steps = np.diff(column, prepend=self.last_time)
                wrong |= ~(steps > 0)
            if wrong.any():
                return False  # the line-by-line reading names it
            columns[role] = column
        for role, column in columns.items():
            self.values.setdefault(role, []).append(column)
        self.rows += len(lines)
        self.last_time = float(columns["time"][-1])
        return True

    def _line(self, number: int, text: str) -> None:
        self.rows += 1
        if self.rows > MAX_SAMPLES:
            raise _error(number, None, "profile_too_many_samples", max=MAX_SAMPLES)
        row = text.split(self.sep)
        if len(row) == self.width + 1 and not row[-1].strip():
            row.pop()  # a separator closing the row
        if len(row) != self.width:
            column = min(len(row), self.width) + 1
            raise _error(number, column, "profile_cells", count=len(row), width=self.width)
        values: dict[str, float] = {}
        for index, role in self.read:
            value = _number(row[index], self.comma)
            cell = row[index].strip()[:40]
            if value is None:
                finite = cell.lower().lstrip("+-") not in {"nan", "inf", "infinity"}
                code = "profile_not_a_number" if finite else "profile_not_finite"
                raise _error(number, index + 1, code, text=cell)
            value *= self.scales[role]
            if not math.isfinite(value):
                raise _error(number, index + 1, "profile_not_finite", text=cell)
            values[role] = value
        time_s = values["time"]
        if not time_s > self.last_time:
            # A row at the time of the one before with the same motion: where the
            # acceleration jumps, IDTA 02021 motion files (this service's too) repeat
            # the time; the second row says nothing new and is left out.
            if time_s == self.last_time and self._repeats(values):
                self.rows -= 1
                return
            column = self._index("time") + 1
            raise _error(number, column, "profile_time_not_increasing", time=time_s)
        self.last_time = time_s
        for role, value in values.items():
            self.values.setdefault(role, []).append(np.array([value]))

    def _index(self, role: str) -> int:
        return next(index for index, r in self.read if r == role)

    def _repeats(self, values: dict[str, float]) -> bool:
        """Whether ``values`` repeat the last row's speed (or position)."""
        for role in ("velocity", "position"):
            if role in values:
                return bool(values[role] == self.values[role][-1][-1])
        return False

    def column(self, role: str) -> npt.NDArray[np.float64] | None:
        parts = self.values.get(role)
        return None if parts is None else np.concatenate(parts)


def read_profile(chunks: Iterable[bytes], units: ColumnUnits) -> ProfileSamples:
    """The samples of a profile file (module docstring)."""
    deadline = time.monotonic() + READ_SECONDS
    reader: _Reader | None = None
    header_line = 1
    columns: list[_Column] = []
    ignored: list[str] = []
    kind = "rotary"
    for first, lines in blocks_of(chunks):
        if reader is None:
            start = next((k for k, line in enumerate(lines) if not _skipped(line)), None)
            if start is None:
                continue
            header_line, header = first + start, lines[start]
            sep = ";" if ";" in header else "\t" if "\t" in header else ","
            cells = header.split(sep)
            columns, ignored = _columns(header_line, cells, units)
            kind, scales = _scales(header_line, columns)
            read = [(c.index, c.role) for c in columns]
            reader = _Reader(
                sep, len(cells), read, scales, deadline, comma=False if sep == "," else None
            )
            first, lines = header_line + 1, lines[start + 1 :]
        reader.block(first, lines)
    if reader is None:
        raise _error(1, None, "profile_empty")
    if reader.rows < 3:
        raise _error(header_line, None, "profile_too_few_samples", count=reader.rows, min=3)
    time_s = reader.column("time")
    velocity = reader.column("velocity")
    from_positions = velocity is None
    motion = velocity if velocity is not None else reader.column("position")
    assert time_s is not None
    assert motion is not None
    if from_positions and kind == "rotary":
        motion = motion / 360.0  # degrees → revolutions
    return ProfileSamples(
        kind=kind,
        time_s=time_s,
        motion=motion,
        from_positions=from_positions,
        load=reader.column("load"),
        acceleration=reader.column("acceleration"),
        columns={c.role: c.heading for c in columns},
        ignored=ignored,
        lines=reader.rows,
    )
