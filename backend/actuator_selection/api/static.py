"""The web page's files: ``frontend/`` and plotly.js from the installed plotly package.

Nothing is fetched from a CDN, so the page works on a shop floor without internet.
plotly.min.js (≈ 4.8 MB) is gzip-compressed once per process and served with a
strong ETag and a long cache lifetime; its URL carries the plotly.js version, so
an upgrade changes the URL.
"""

from __future__ import annotations

import gzip
import hashlib
from functools import cache
from importlib.resources import files

from fastapi import APIRouter, Request, Response
from plotly.offline import get_plotlyjs_version

router = APIRouter(include_in_schema=False)

PLOTLY_VERSION: str = get_plotlyjs_version()
PLOTLY_URL = f"/vendor/plotly-{PLOTLY_VERSION}.min.js"
ONE_YEAR_S = 365 * 24 * 3600


@cache
def _plotly() -> tuple[bytes, bytes, str]:
    """plotly.min.js as shipped, gzip-compressed, and its ETag."""
    raw = files("plotly").joinpath("package_data", "plotly.min.js").read_bytes()
    return raw, gzip.compress(raw, compresslevel=9, mtime=0), hashlib.sha256(raw).hexdigest()[:32]


@router.get(PLOTLY_URL)
def plotly_js(request: Request) -> Response:
    """plotly.js, compressed when the client accepts gzip, cacheable for a year."""
    raw, packed, etag = _plotly()
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
    return {"url": PLOTLY_URL, "version": PLOTLY_VERSION}
