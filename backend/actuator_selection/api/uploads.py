"""Uploaded files for imports: raw request bodies (CSV, ZIP, JSON), bounded in size.

Files are sent as the request body itself with their media type (no multipart),
so ``curl --data-binary @prices.csv -H 'Content-Type: text/csv'`` suffices and
no form parser is needed. Problems in a file become one 422 whose entries name
file, line, column and rule: ``{"loc": ["body", file, line, column], "msg": ...,
"type": "invalid_file", "file": ..., "line": ..., "column": ...}``.
"""

from __future__ import annotations

import io
import lzma
import tempfile
import zipfile
import zlib
from collections.abc import AsyncIterator, Iterable, Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import PurePosixPath
from typing import IO

from fastapi import Request

from actuator_selection.catalogue.csvio import (
    MAX_CELL_CHARS,
    CatalogueFileError,
    Problem,
    TooManyRowsError,
)
from actuator_selection.catalogue.files import CATALOGUE_SPECS
from actuator_selection.http.errors import (
    PayloadTooLargeError,
    RequestFieldError,
    UnsupportedMediaTypeError,
)
from actuator_selection.http.media_types import unsupported_media_type
from actuator_selection.services.errors import problem_entry

MAX_UPLOAD_BYTES = 20 * 1024 * 1024
"""Largest body or unpacked ZIP member accepted [bytes]: the starter catalogue is < 50 kB."""


@dataclass(frozen=True, slots=True)
class Upload:
    """A request body and its media type (parameters such as charset stripped)."""

    media_type: str
    body: bytes


async def raw_upload(request: Request) -> Upload:
    """The request body, at most ``MAX_UPLOAD_BYTES`` (413 beyond)."""
    declared = request.headers.get("content-length")
    if declared is not None and declared.isdigit() and int(declared) > MAX_UPLOAD_BYTES:
        raise _too_large(f"at most {MAX_UPLOAD_BYTES} bytes")
    chunks: list[bytes] = []
    size = 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > MAX_UPLOAD_BYTES:
            raise _too_large(f"at most {MAX_UPLOAD_BYTES} bytes")
        chunks.append(chunk)
    media_type = request.headers.get("content-type", "").split(";")[0].strip().lower()
    return Upload(media_type=media_type, body=b"".join(chunks))


def _too_large(message: str) -> PayloadTooLargeError:
    return PayloadTooLargeError.at(["body"], message, "body_too_large")


def unsupported(media_type: str, accepted: tuple[str, ...]) -> UnsupportedMediaTypeError:
    """415 naming what is accepted."""
    return unsupported_media_type(media_type, accepted)


def too_many_rows(exc: TooManyRowsError) -> PayloadTooLargeError:
    """The 413 for a file beyond the rows an import may hold, naming file and line."""
    return PayloadTooLargeError([{**problem_entry(exc.problem), "type": "too_many_rows"}])


def file_errors(exc: CatalogueFileError) -> RequestFieldError:
    """The 422 for every problem of a file (raise it)."""
    return RequestFieldError([problem_entry(p) for p in exc.problems])


def text_of(body: bytes, *, file: str) -> str:
    """``body`` as UTF-8 text (a byte-order mark is dropped); 422 naming ``file`` otherwise."""
    try:
        return body.decode("utf-8-sig")
    except UnicodeDecodeError as exc:
        problem = Problem(file=file, line=0, column=None, message=f"is not UTF-8 ({exc.reason})")
        raise file_errors(CatalogueFileError([problem])) from None


SPOOL_IN_MEMORY_BYTES = 1 << 20
"""A spooled upload stays in memory up to this size, then moves to a temporary file."""
MAX_UNPACKED_BYTES = 1 << 30
"""Most bytes a ZIP member may unpack to: a bound for the disk and the clock only (a
catalogue of 64,000 actuators unpacks to about 20–90 MB); the rules an import states are
rows per file (:data:`~actuator_selection.catalogue.csvio.MAX_ROWS`) and characters per cell."""


async def spooled_upload(request: Request) -> AsyncIterator[SpooledUpload]:
    """The request body in a temporary file (memory up to ``SPOOL_IN_MEMORY_BYTES``), read
    chunk by chunk as it arrives; closed (deleted) when the request ends.

    The body's size is bounded where it is received: the route's body limit
    (``MAX_BULK_BODY_BYTES``) and the admission's ``BODY_TIMEOUT_S``.
    """
    media_type = request.headers.get("content-type", "").split(";")[0].strip().lower()
    with tempfile.SpooledTemporaryFile(max_size=SPOOL_IN_MEMORY_BYTES) as file:
        async for chunk in request.stream():
            file.write(chunk)
        file.seek(0)
        yield SpooledUpload(media_type=media_type, file=file)


@dataclass(frozen=True, slots=True)
class SpooledUpload:
    """A request body in a (spooled) temporary file, and its media type."""

    media_type: str
    file: IO[bytes]


MAX_LINE_CHARS = max(len(spec.columns) for spec in CATALOGUE_SPECS) * (MAX_CELL_CHARS + 3)
"""The longest line a member may hold: every cell of the widest file at its limit, quoted
and separated, so that no valid row is refused and no line is held whole beyond it."""


class _MemberLines:
    """The lines of a ZIP member as they unpack (UTF-8, a byte-order mark dropped), each
    way the member fails to unpack a :class:`CatalogueFileError` naming the file and line,
    no line beyond ``MAX_LINE_CHARS`` held, and at most ``MAX_UNPACKED_BYTES`` unpacked
    (413 beyond)."""

    def __init__(self, name: str, member: IO[bytes]) -> None:
        self._name = name
        self._member = member
        self._text = io.TextIOWrapper(member, encoding="utf-8-sig", newline="")
        self._unpacked = 0
        self._lines = 0

    def __iter__(self) -> Iterator[str]:
        return self

    def __next__(self) -> str:
        try:
            line = self._text.readline(MAX_LINE_CHARS)
        except _UNPACK_ERRORS as exc:
            problem = Problem(file=self._name, line=self._lines, column=None, message=_damaged(exc))
            raise CatalogueFileError([problem]) from None
        if not line:
            self._text.close()
            raise StopIteration
        self._lines += 1
        if len(line) == MAX_LINE_CHARS and not line.endswith(("\n", "\r")):
            message = f"has a line longer than {MAX_LINE_CHARS} characters"
            problem = Problem(file=self._name, line=self._lines, column=None, message=message)
            raise CatalogueFileError([problem])
        self._unpacked += len(line)
        if self._unpacked > MAX_UNPACKED_BYTES:
            raise _too_large(f"{self._name} is too large unpacked")
        return line


@contextmanager
def unzip_csv(
    file: IO[bytes], *, wanted: tuple[str, ...]
) -> Iterator[dict[str, Iterable[str] | None]]:
    """The ``wanted`` CSV files of a ZIP archive as streams of their lines, by file name
    (None: not in it), read as they are consumed while the archive is open (a context).

    Files may sit at the archive's root or in one folder; other CSV files are
    returned too (so that the caller can name them as unknown).
    """
    try:
        archive = zipfile.ZipFile(file)
    except (zipfile.BadZipFile, EOFError, OSError, ValueError):  # a damaged directory too
        problem = Problem(file="(upload)", line=0, column=None, message="is not a ZIP archive")
        raise file_errors(CatalogueFileError([problem])) from None
    members: dict[str, Iterable[str] | None] = dict.fromkeys(wanted)
    problems: list[Problem] = []
    with archive:
        for info in archive.infolist():
            path = PurePosixPath(info.filename)
            if info.is_dir() or path.suffix.lower() != ".csv" or "__MACOSX" in path.parts:
                continue
            if info.file_size > MAX_UNPACKED_BYTES:
                raise _too_large(f"{path.name} is too large unpacked")
            member, message = _member(archive, info)
            if member is None:
                problems.append(Problem(file=path.name, line=0, column=None, message=message))
                continue
            members[path.name] = _MemberLines(path.name, member)
        if problems:
            raise file_errors(CatalogueFileError(problems))
        yield members


_COMPRESSION = {
    zipfile.ZIP_STORED: "stored",
    zipfile.ZIP_DEFLATED: "deflate",
    zipfile.ZIP_BZIP2: "bzip2",
    zipfile.ZIP_LZMA: "LZMA",
}
"""The compression methods ``zipfile`` unpacks (ZIP method numbers 0, 8, 12, 14)."""
_ENCRYPTED = 0x1
"""General purpose bit 0 of a ZIP entry: the member is encrypted."""


_UNPACK_ERRORS = (zipfile.BadZipFile, zlib.error, lzma.LZMAError, EOFError, OSError, ValueError)
"""How unpacking a member fails as it is read: a bad CRC (BadZipFile, at the member's end),
damaged data (zlib.error, EOFError, the decompressor's error), or ValueError for an
impossible offset."""


def _damaged(exc: BaseException) -> str:
    return f"is damaged in the archive and cannot be unpacked ({exc})"


def _member(archive: zipfile.ZipFile, info: zipfile.ZipInfo) -> tuple[IO[bytes] | None, str]:
    """A member opened for reading, or why it cannot be read.

    Each way ``zipfile`` fails to open a member (an encrypted one raises RuntimeError, an
    unknown method NotImplementedError, a damaged header BadZipFile, ...) becomes a rule
    the 422 states; failures while unpacking are :class:`_MemberLines`'.
    """
    if info.flag_bits & _ENCRYPTED:
        return None, "is encrypted: the archive must hold the files without a password"
    if info.compress_type not in _COMPRESSION:
        return None, (
            f"uses compression method {info.compress_type}, which is not supported: "
            f"pack the files with {', '.join(_COMPRESSION.values())} (a plain ZIP uses deflate)"
        )
    try:
        return archive.open(info), ""
    except _UNPACK_ERRORS as exc:
        # ValueError: e.g. "negative seek value" from a directory whose offsets are garbage
        return None, _damaged(exc)
    except (RuntimeError, NotImplementedError) as exc:
        return None, f"cannot be unpacked ({exc})"
