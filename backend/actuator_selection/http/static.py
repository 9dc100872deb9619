"""The web page's files: ``frontend/`` and plotly.js from the npm package the project pins.

Nothing is fetched from a CDN, so the page works on a shop floor without internet.
The charts (the engineer's page, the quote document) draw only ``scatter`` traces
(lines, markers, text, filled areas) with shapes and annotations, so the smallest
official bundle that has them is enough: ``plotly.js-basic-dist-min`` (scatter, bar,
pie; ≈ 1.2 MB, 0.4 MB with gzip, against 4.8 MB / 1.5 MB for the full plotly.min.js).
It is pinned with its integrity hash in ``package-lock.json`` and installed into
``node_modules/`` by ``npm ci --ignore-scripts`` (``make install``).

The bundle is gzip-compressed once per process and served with a strong ETag and a
long cache lifetime; its URL carries the locked version, so an upgrade changes the
URL. ``index.html`` names that URL in a deferred ``<script>``, so the download starts
with the page and runs after the page's own module (``tests/api/test_static_files.py``
checks that the page and this module agree); ``/vendor/plotly.js`` says where it is
for anything that must look it up. Without the installed bundle (or with another
version than the lock's) its URL answers 503 naming the fix.

The bundle is served behind one added line, V8's explicit compile hint
``//# allFunctionsCalledOnLoad`` (Chrome and Edge 136+; other engines read a comment):
the browser compiles all of plotly.js on a background thread while it streams the file,
instead of compiling each function on the main thread the first time it runs. In a
lab page (the bundle, then the page's two charts; Chromium's trace, four cold loads)
lazy compiling (``V8.CompileCode``) was 245 ms of the main thread; with the hint it
leaves the main thread, which is then free for the user's clicks. The bytes after that
line are the package's file as installed.

The page's own files (``frontend/``) are served by :class:`FrontendFiles`: Starlette's
``StaticFiles`` (its path rules, ETag, 304, ``index.html`` and redirects), each file
read once and held in memory with its zstd and gzip forms, compressed once at a high
level, for as long as the file on disk is unchanged (checked at each request, so an edit
is served at once). A cold load of the engineer's page asks for 21 of them.
"""

from __future__ import annotations

import gzip
import hashlib
import json
import os
from functools import cache
from os import PathLike
from pathlib import Path
from typing import NamedTuple

import anyio.to_thread
import zstandard
from fastapi import APIRouter, Request, Response
from starlette.datastructures import Headers
from starlette.responses import FileResponse
from starlette.staticfiles import NotModifiedResponse, StaticFiles
from starlette.types import Scope
from werkzeug.http import parse_accept_header

from actuator_selection.config import REPO_ROOT

router = APIRouter(include_in_schema=False)

PLOTLY_PACKAGE = "plotly.js-basic-dist-min"
"""The npm package of the bundle, as ``package.json`` names it."""
PLOTLY_FILE = "plotly-basic.min.js"
LOCKFILE = REPO_ROOT / "package-lock.json"
PLOTLY_DIR = REPO_ROOT / "node_modules" / PLOTLY_PACKAGE
ONE_YEAR_S = 365 * 24 * 3600
COMPILE_HINT = b"//# allFunctionsCalledOnLoad\n"
"""V8's magic comment, the first line of the served bundle (https://v8.dev/blog/explicit-compile-hints)."""


def locked_version(lockfile: Path = LOCKFILE) -> str:
    """The bundle's version as ``package-lock.json`` pins it."""
    lock = json.loads(lockfile.read_text(encoding="utf-8"))
    return str(lock["packages"][f"node_modules/{PLOTLY_PACKAGE}"]["version"])


PLOTLY_VERSION: str = locked_version()
PLOTLY_URL = f"/vendor/plotly-basic-{PLOTLY_VERSION}.min.js"


class PlotlyNotInstalledError(RuntimeError):
    """``node_modules`` lacks the locked bundle: ``make install`` not run since the lock changed."""


@cache
def _plotly() -> tuple[bytes, bytes, str]:
    """The bundle as served (the compile hint, then the package's file) raw and
    gzip-compressed, and its ETag; checked against the lock."""
    try:
        installed = json.loads((PLOTLY_DIR / "package.json").read_text(encoding="utf-8"))
        raw = (PLOTLY_DIR / PLOTLY_FILE).read_bytes()
    except OSError as exc:
        raise PlotlyNotInstalledError(f"{PLOTLY_PACKAGE} is not installed in {PLOTLY_DIR}") from exc
    if installed.get("version") != PLOTLY_VERSION:
        raise PlotlyNotInstalledError(
            f"{PLOTLY_PACKAGE} {installed.get('version')} is installed, "
            f"package-lock.json pins {PLOTLY_VERSION}"
        )
    served = COMPILE_HINT + raw
    packed = gzip.compress(served, compresslevel=9, mtime=0)
    return served, packed, hashlib.sha256(served).hexdigest()[:32]


@router.get(PLOTLY_URL)
def plotly_js(request: Request) -> Response:
    """plotly.js, compressed when the client accepts gzip, cacheable for a year."""
    try:
        raw, packed, etag = _plotly()
    except PlotlyNotInstalledError as exc:
        # Not cached, so that the file is served as soon as `make install` has put it there.
        return Response(
            f"{exc}: run `make install` (npm ci --ignore-scripts)\n",
            status_code=503,
            media_type="text/plain",
            headers={"Cache-Control": "no-store"},
        )
    headers = {
        "Cache-Control": f"public, max-age={ONE_YEAR_S}, immutable",
        "ETag": f'"{etag}"',
        "Vary": "Accept-Encoding",
    }
    if request.headers.get("if-none-match") == f'"{etag}"':
        return Response(status_code=304, headers=headers)
    if "gzip" in request.headers.get("accept-encoding", ""):
        headers["Content-Encoding"] = "gzip"
        return Response(packed, media_type="text/javascript", headers=headers)
    return Response(raw, media_type="text/javascript", headers=headers)


@router.get("/vendor/plotly.js")
def plotly_location() -> dict[str, str]:
    """Where the page finds the versioned plotly.js."""
    return {"url": PLOTLY_URL, "version": PLOTLY_VERSION, "bundle": PLOTLY_PACKAGE}


HELD_MAX_BYTES = 1 << 20
"""The largest page file :class:`FrontendFiles` holds in memory (the largest is ~60 KB)."""
HELD_ZSTD_LEVEL = 15
HELD_GZIP_LEVEL = 9
"""Compression levels of the files held: each is compressed once per process and version of
the file, in a worker thread (``frontend/lib/messages.js``, 82 KB: 25 KB at the answers'
zstd level 1, 19.8 KB at 15 in 17 ms, 19.7 KB at 19 in 47 ms; gzip 9: 23 KB)."""


class _Held(NamedTuple):
    """A page file as served: its identity on disk, its headers, and its three forms."""

    full_path: str
    stat_key: tuple[int, int, int]
    headers: dict[str, str]
    forms: dict[str, bytes]
    """By content coding: ``identity`` always, ``zstd`` and ``gzip`` where smaller."""


def _stat_key(stat_result: os.stat_result) -> tuple[int, int, int]:
    """What changes when the file is edited or replaced."""
    return stat_result.st_mtime_ns, stat_result.st_size, stat_result.st_ino


class FrontendFiles(StaticFiles):
    """``StaticFiles`` whose files, once found, are answered from memory (see the module).

    A file ``StaticFiles`` answers (its path rules: nothing outside the directory, an
    ``index.html`` for a directory URL ending in ``/``, else a redirect) is held under
    the request's path; later requests for that path take the held file while the file
    on disk has the same modification time, size and inode. A stat of the file is the
    only system call on that way: ``StaticFiles`` takes four thread hops (the lookup,
    and the open, read and close of its ``FileResponse``), and the answers' middleware
    compressed the file again each time (2.3–3.3 ms of the server's CPU a file, against
    1.0–1.1 ms held; ``bench/http.py``'s page file, 2026-11-29)."""

    def __init__(self, *, directory: str | PathLike[str], html: bool = False) -> None:
        super().__init__(directory=directory, html=html)
        self._held: dict[tuple[str, bool], _Held] = {}

    async def get_response(self, path: str, scope: Scope) -> Response:
        key = (path, scope["path"].endswith("/"))  # a directory's URL without it: redirected
        held = self._held.get(key)
        if held is not None and scope["method"] in ("GET", "HEAD"):
            try:
                fresh = _stat_key(os.stat(held.full_path)) == held.stat_key
            except OSError:
                fresh = False
            if fresh:
                return self._answer(held, scope)
        response = await super().get_response(path, scope)
        if (
            type(response) is FileResponse
            and response.status_code == 200
            and response.stat_result is not None
            and response.stat_result.st_size <= HELD_MAX_BYTES
        ):
            # read and compressed in a worker thread: the event loop goes on meanwhile
            found = await anyio.to_thread.run_sync(_held, response)
            if found is not None:
                self._held[key] = found
                return self._answer(found, scope)
        return response

    def _answer(self, held: _Held, scope: Scope) -> Response:
        request = Headers(scope=scope)
        headers = dict(held.headers)
        if self.is_not_modified(Headers(headers), request):
            return NotModifiedResponse(Headers(headers))
        # zstd before gzip at the client's equal preference, as the answers' middleware
        accepted = parse_accept_header(request.get("accept-encoding", ""))
        coding = accepted.best_match([c for c in ("zstd", "gzip") if c in held.forms])
        if coding is None:
            return Response(held.forms["identity"], headers=headers)
        headers |= {"content-encoding": coding, "vary": "Accept-Encoding"}
        return Response(held.forms[coding], headers=headers)


_NOT_HELD = frozenset({"content-length", "accept-ranges"})
"""``FileResponse``'s headers a held file's answer does not take: its length is its form's."""


def _held(found: FileResponse) -> _Held | None:
    """The file ``StaticFiles`` found, read and compressed; None where it changed meanwhile
    (then served as ``StaticFiles`` serves it, and held at a later request)."""
    assert found.stat_result is not None
    # whole files only: no ranges offered (a Range asked for is answered with the whole)
    headers = {k: v for k, v in found.headers.items() if k not in _NOT_HELD}
    try:
        with open(found.path, "rb") as file:
            raw, now = file.read(), os.fstat(file.fileno())
    except OSError:
        return None
    if _stat_key(now) != _stat_key(found.stat_result) or len(raw) != now.st_size:
        return None
    return _Held(str(found.path), _stat_key(now), headers, _forms(raw))


def _forms(raw: bytes) -> dict[str, bytes]:
    """``raw`` as served to each content coding: compressed where that is smaller."""
    forms = {"identity": raw}
    for coding, packed in (
        ("zstd", zstandard.ZstdCompressor(level=HELD_ZSTD_LEVEL).compress(raw)),
        ("gzip", gzip.compress(raw, compresslevel=HELD_GZIP_LEVEL, mtime=0)),
    ):
        if len(packed) < len(raw):
            forms[coding] = packed
    return forms
