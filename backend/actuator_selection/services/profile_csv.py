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
from array import array
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from typing import Any

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
    time_s: array[float]
    motion: array[float]
    from_positions: bool
    load: array[float] | None
    acceleration: array[float] | None
    columns: dict[str, str] = field(default_factory=dict)
    """Each role read, and the heading it was read from."""
    ignored: list[str] = field(default_factory=list)
    """Headings of columns not read."""
    lines: int = 0


def _error(line: int, column: int | None, code: str, **params: object) -> UseCaseError:
    loc: Loc = ["body", line] if column is None else ["body", line, column]
    where: dict[str, Any] = {"line": line} if column is None else {"line": line, "column": column}
    return invalid(loc, code, None, **where, **params)


def lines_of(chunks: Iterable[bytes]) -> Iterator[tuple[int, str]]:
    """The file's lines, numbered from 1, decoded as UTF-8 as the chunks arrive (a
    leading BOM dropped; LF, CRLF or CR end a line); a 422 for a file past
    :data:`MAX_PROFILE_BYTES`, binary content or a line past :data:`MAX_LINE_CHARS`."""
    decoder = codecs.getincrementaldecoder("utf-8")("strict")
    pending = ""
    number = 0
    size = 0
    for chunk in chunks:
        size += len(chunk)
        if size > MAX_PROFILE_BYTES:
            raise _error(number + 1, None, "profile_too_large", max=MAX_PROFILE_BYTES)
        try:
            text = decoder.decode(chunk)
        except UnicodeDecodeError as exc:
            before = pending.count("\n") + chunk[: max(exc.start, 0)].count(b"\n")
            raise _error(number + 1 + before, None, "profile_binary") from None
        if number == 0 and not pending and text.startswith("\ufeff"):
            text = text[1:]
        pending += text
        parts = pending.splitlines(keepends=True)
        pending = ""
        if parts and not parts[-1].endswith("\n"):
            pending = parts.pop()  # an incomplete line, or a CR whose LF may follow
        for part in parts:
            number += 1
            yield number, _checked(number, part.rstrip("\r\n"))
        if len(pending) > MAX_LINE_CHARS:
            raise _error(number + 1, None, "profile_line_too_long", max=MAX_LINE_CHARS)
    try:
        pending += decoder.decode(b"", final=True)
    except UnicodeDecodeError:
        raise _error(number + 1, None, "profile_binary") from None
    if pending.rstrip("\r\n"):
        yield number + 1, _checked(number + 1, pending.rstrip("\r\n"))


def _checked(number: int, line: str) -> str:
    if len(line) > MAX_LINE_CHARS:
        raise _error(number, None, "profile_line_too_long", max=MAX_LINE_CHARS)
    if _CONTROL.search(line):
        raise _error(number, None, "profile_binary")
    return line


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


def read_profile(chunks: Iterable[bytes], units: ColumnUnits) -> ProfileSamples:
    """The samples of a profile file (module docstring)."""
    deadline = time.monotonic() + READ_SECONDS
    lines = lines_of(chunks)
    header_line, header = 0, ""
    for number, text in lines:
        if text.strip() and not text.lstrip().startswith("#"):
            header_line, header = number, text
            break
    if not header:
        raise _error(max(header_line, 1), None, "profile_empty")
    sep = ";" if ";" in header else "\t" if "\t" in header else ","
    cells = header.split(sep)
    columns, ignored = _columns(header_line, cells, units)
    kind, scales = _scales(header_line, columns)
    width = len(cells)
    read = [(c.index, c.role) for c in columns]
    values: dict[str, array[float]] = {c.role: array("d") for c in columns}
    comma: bool | None = None if sep != "," else False
    last_time = -math.inf
    rows = 0
    for number, text in lines:
        if not text.strip() or text.lstrip().startswith("#"):
            continue
        rows += 1
        if rows > MAX_SAMPLES:
            raise _error(number, None, "profile_too_many_samples", max=MAX_SAMPLES)
        if rows % 4096 == 0 and time.monotonic() > deadline:
            raise _error(number, None, "profile_too_slow", seconds=READ_SECONDS)
        row = text.split(sep)
        if len(row) == width + 1 and not row[-1].strip():
            row.pop()  # a separator closing the row
        if len(row) != width:
            raise _error(
                number, min(len(row), width) + 1, "profile_cells", count=len(row), width=width
            )
        if comma is None:  # decided by the first row with a decimal mark
            if any("," in row[i] for i, _ in read):
                comma = True
            elif any("." in row[i] for i, _ in read):
                comma = False
        for index, role in read:
            value = _number(row[index], comma)
            if value is None:
                cell = row[index].strip()
                code = (
                    "profile_not_finite"
                    if cell.lower().lstrip("+-") in {"nan", "inf", "infinity"}
                    else "profile_not_a_number"
                )
                raise _error(number, index + 1, code, text=cell[:40])
            value *= scales[role]
            if not math.isfinite(value):
                raise _error(number, index + 1, "profile_not_finite", text=row[index].strip()[:40])
            if role == "time":
                if not value > last_time:
                    raise _error(number, index + 1, "profile_time_not_increasing", time=value)
                last_time = value
            values[role].append(value)
    if rows < 3:
        raise _error(header_line, None, "profile_too_few_samples", count=rows, min=3)
    motion_role = "velocity" if "velocity" in values else "position"
    motion = values[motion_role]
    if motion_role == "position" and kind == "rotary":
        motion = array("d", (x / 360.0 for x in motion))  # degrees → revolutions
    return ProfileSamples(
        kind=kind,
        time_s=values["time"],
        motion=motion,
        from_positions=motion_role == "position",
        load=values.get("load"),
        acceleration=values.get("acceleration"),
        columns={c.role: c.heading for c in columns},
        ignored=ignored,
        lines=rows,
    )
