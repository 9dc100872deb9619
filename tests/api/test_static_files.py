"""The page's static files: plotly.js as ``http/static.py`` serves it, and how the pages load it."""

from __future__ import annotations

import gzip
import json
import posixpath
import re
from collections.abc import Iterator
from html.parser import HTMLParser
from pathlib import Path

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient

from actuator_selection.config import FRONTEND_DIR, REPO_ROOT
from actuator_selection.http import static


@pytest.fixture
def client() -> Iterator[TestClient]:
    app = FastAPI()
    app.include_router(static.router)
    with TestClient(app) as client:
        yield client


def test_the_lock_pins_the_bundle_with_its_integrity_hash() -> None:
    manifest = json.loads((REPO_ROOT / "package.json").read_text(encoding="utf-8"))
    lock = json.loads((REPO_ROOT / "package-lock.json").read_text(encoding="utf-8"))
    # an exact version, the only dependency: nothing else reaches the browser from npm
    assert manifest["dependencies"] == {static.PLOTLY_PACKAGE: static.PLOTLY_VERSION}
    entry = lock["packages"][f"node_modules/{static.PLOTLY_PACKAGE}"]
    assert entry["version"] == static.PLOTLY_VERSION
    assert entry["integrity"].startswith("sha512-")
    assert f"/vendor/plotly-basic-{static.PLOTLY_VERSION}.min.js" == static.PLOTLY_URL


def test_location_names_the_versioned_url(client: TestClient) -> None:
    response = client.get("/vendor/plotly.js")
    assert response.status_code == 200
    assert response.json() == {
        "url": static.PLOTLY_URL,
        "version": static.PLOTLY_VERSION,
        "bundle": static.PLOTLY_PACKAGE,
    }


def test_bundle_is_gzipped_once_and_cached_for_a_year(client: TestClient) -> None:
    plain = client.get(static.PLOTLY_URL, headers={"Accept-Encoding": "identity"})
    assert plain.status_code == 200
    assert plain.headers["content-type"].startswith("text/javascript")
    assert "content-encoding" not in plain.headers
    raw = plain.content
    # V8's compile hint as the first line, then the package's file byte for byte
    hint, _, bundle = raw.partition(b"\n")
    assert hint == b"//# allFunctionsCalledOnLoad"
    assert bundle == (static.PLOTLY_DIR / static.PLOTLY_FILE).read_bytes()
    version = static.PLOTLY_VERSION.encode()
    assert bundle.startswith(b"/**\n* plotly.js (basic - minified) v" + version)
    assert b"window.Plotly = Plotly" in raw

    # httpx would decompress; the bytes on the wire are read from the raw stream
    with client.stream("GET", static.PLOTLY_URL, headers={"Accept-Encoding": "gzip"}) as packed:
        assert packed.headers["content-encoding"] == "gzip"
        wire = b"".join(packed.iter_raw())
    assert gzip.decompress(wire) == raw
    assert len(wire) < len(raw) / 2
    for response in (plain, packed):
        assert response.headers["cache-control"] == "public, max-age=31536000, immutable"
        assert response.headers["vary"] == "Accept-Encoding"
    etag = plain.headers["etag"]
    assert packed.headers["etag"] == etag

    again = client.get(static.PLOTLY_URL, headers={"If-None-Match": etag})
    assert again.status_code == 304
    assert again.content == b""


def test_a_missing_bundle_is_a_503_naming_the_fix(
    client: TestClient, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(static, "PLOTLY_DIR", tmp_path)
    static._plotly.cache_clear()
    try:
        response = client.get(static.PLOTLY_URL)
        assert response.status_code == 503
        assert "make install" in response.text
        assert response.headers["cache-control"] == "no-store"

        # another version than the lock's is not served under the lock's URL
        (tmp_path / "package.json").write_text('{"version": "0.0.1"}', encoding="utf-8")
        (tmp_path / static.PLOTLY_FILE).write_text("window.Plotly = {};", encoding="utf-8")
        response = client.get(static.PLOTLY_URL)
        assert response.status_code == 503
        assert "0.0.1" in response.text
    finally:
        static._plotly.cache_clear()


class _Head(HTMLParser):
    """The scripts and module preloads of a page, in document order."""

    def __init__(self) -> None:
        super().__init__()
        self.scripts: list[dict[str, str | None]] = []
        self.preloads: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        names = dict(attrs)
        if tag == "script":
            self.scripts.append(names)
        elif tag == "link" and names.get("rel") == "modulepreload":
            self.preloads.append(str(names["href"]))


def _head(page: str) -> _Head:
    parser = _Head()
    parser.feed((FRONTEND_DIR / page).read_text(encoding="utf-8"))
    return parser


_IMPORT = re.compile(r'^(?:import|export)\b[^;]*?\bfrom\s+"([^"]+)"', re.M | re.S)


def _module_graph(entry: str) -> set[str]:
    """Every module URL ``entry`` imports, directly or not (static imports)."""
    seen: set[str] = set()
    todo = [entry]
    while todo:
        url = todo.pop()
        if url in seen:
            continue
        seen.add(url)
        source = (FRONTEND_DIR / url.lstrip("/")).read_text(encoding="utf-8")
        for target in _IMPORT.findall(source):
            assert target.startswith("."), f"{url}: {target} is not a relative import"
            todo.append(posixpath.normpath(posixpath.join(posixpath.dirname(url), target)))
    return seen - {entry}


@pytest.mark.parametrize(
    ("page", "entry"),
    [
        ("index.html", "/pages/engineer/app.js"),
        ("sales.html", "/pages/sales/app.js"),
        ("projects.html", "/pages/projects/app.js"),
    ],
)
def test_pages_load_their_module_and_preload_its_whole_graph(page: str, entry: str) -> None:
    head = _head(page)
    modules = [s for s in head.scripts if s.get("type") == "module"]
    assert [m.get("src") for m in modules] == [entry]
    assert sorted(head.preloads) == sorted(_module_graph(entry))
    assert len(head.preloads) == len(set(head.preloads))


@pytest.mark.parametrize("page", ["index.html", "projects.html"])
def test_chart_pages_name_the_served_bundle_after_their_module(page: str) -> None:
    """Deferred, after the module: fetched with the page, run once the form is set up."""
    scripts = _head(page).scripts
    bundles = [s for s in scripts if "data-plotly" in s]
    assert bundles == [{"defer": None, "data-plotly": None, "src": static.PLOTLY_URL}]
    assert scripts.index(bundles[0]) > next(
        i for i, s in enumerate(scripts) if s.get("type") == "module"
    )
    assert not [s for s in _head("sales.html").scripts if "plotly" in str(s.get("src"))]
