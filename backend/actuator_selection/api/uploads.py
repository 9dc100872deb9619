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
import zipfile
import zlib
from dataclasses import dataclass
from pathlib import PurePosixPath

from fastapi import Request

from actuator_selection.api.errors import (
    PayloadTooLargeError,
    RequestFieldError,
    UnsupportedMediaTypeError,
)
from actuator_selection.api.media_types import unsupported_media_type
from actuator_selection.core.csvio import CatalogueFileError, Problem
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


def unzip_csv(body: bytes, *, wanted: tuple[str, ...]) -> dict[str, str | None]:
    """The ``wanted`` CSV files of a ZIP archive as text, by file name (None: not in it).

    Files may sit at the archive's root or in one folder; other CSV files are
    returned too (so that the caller can name them as unknown).
    """
    try:
        archive = zipfile.ZipFile(io.BytesIO(body))
    except (zipfile.BadZipFile, EOFError, OSError, ValueError):  # a damaged directory too
        problem = Problem(file="(upload)", line=0, column=None, message="is not a ZIP archive")
        raise file_errors(CatalogueFileError([problem])) from None
    texts: dict[str, str | None] = dict.fromkeys(wanted)
    problems: list[Problem] = []
    with archive:
        for info in archive.infolist():
            path = PurePosixPath(info.filename)
            if info.is_dir() or path.suffix.lower() != ".csv" or "__MACOSX" in path.parts:
                continue
            if info.file_size > MAX_UPLOAD_BYTES:
                raise _too_large(f"{path.name} is too large unpacked")
            data, message = _member(archive, info)
            if message is not None:
                problems.append(Problem(file=path.name, line=0, column=None, message=message))
                continue
            if len(data) > MAX_UPLOAD_BYTES:
                raise _too_large(f"{path.name} is too large unpacked")
            texts[path.name] = text_of(data, file=path.name)
    if problems:
        raise file_errors(CatalogueFileError(problems))
    return texts


_COMPRESSION = {
    zipfile.ZIP_STORED: "stored",
    zipfile.ZIP_DEFLATED: "deflate",
    zipfile.ZIP_BZIP2: "bzip2",
    zipfile.ZIP_LZMA: "LZMA",
}
"""The compression methods ``zipfile`` unpacks (ZIP method numbers 0, 8, 12, 14)."""
_ENCRYPTED = 0x1
"""General purpose bit 0 of a ZIP entry: the member is encrypted."""


def _member(archive: zipfile.ZipFile, info: zipfile.ZipInfo) -> tuple[bytes, str | None]:
    """A member's bytes (at most ``MAX_UPLOAD_BYTES + 1``), or why it cannot be read.

    Each way ``zipfile`` fails on a member (an encrypted one raises RuntimeError, an
    unknown method NotImplementedError, a bad CRC BadZipFile, damaged data zlib.error,
    EOFError, the decompressor's error, or ValueError for an impossible offset) becomes
    a rule the 422 states.
    """
    if info.flag_bits & _ENCRYPTED:
        return b"", "is encrypted: the archive must hold the files without a password"
    if info.compress_type not in _COMPRESSION:
        return b"", (
            f"uses compression method {info.compress_type}, which is not supported: "
            f"pack the files with {', '.join(_COMPRESSION.values())} (a plain ZIP uses deflate)"
        )
    try:
        with archive.open(info) as member:
            return member.read(MAX_UPLOAD_BYTES + 1), None
    except (zipfile.BadZipFile, zlib.error, lzma.LZMAError, EOFError, OSError, ValueError) as exc:
        # ValueError: e.g. "negative seek value" from a directory whose offsets are garbage
        return b"", f"is damaged in the archive and cannot be unpacked ({exc})"
    except (RuntimeError, NotImplementedError) as exc:
        return b"", f"cannot be unpacked ({exc})"
