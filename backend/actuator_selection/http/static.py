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
"""

from __future__ import annotations

import gzip
import hashlib
import json
from functools import cache
from pathlib import Path

from fastapi import APIRouter, Request, Response

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
