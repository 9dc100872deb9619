"""The page's static files: plotly.js and ``frontend/`` as ``http/static.py`` serves them, and
how the pages load them."""

from __future__ import annotations

import gzip
import json
import posixpath
import re
from collections.abc import Iterator
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import pytest
import zstandard
from fastapi import FastAPI
from fastapi.testclient import TestClient
from starlette.applications import Starlette
from starlette.routing import Mount

from actuator_selection.app import create_app
from actuator_selection.config import FRONTEND_DIR, REPO_ROOT, Settings
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


def _files(directory: Path) -> list[str]:
    return sorted(p.relative_to(directory).as_posix() for p in directory.rglob("*") if p.is_file())


def _files_client(directory: Path) -> TestClient:
    """The page's files of ``directory`` as the app mounts them."""
    files = static.FrontendFiles(directory=directory, html=True)
    return TestClient(Starlette(routes=[Mount("/", app=files)]))


def _wire(client: TestClient, path: str, coding: str, **headers: str) -> tuple[bytes, Any]:
    """The bytes on the wire (httpx would decode them) and the answer's headers."""
    with client.stream("GET", path, headers={"Accept-Encoding": coding, **headers}) as answer:
        assert answer.status_code == 200, path
        return b"".join(answer.iter_raw()), answer.headers


def _decoded(wire: bytes, coding: str | None) -> bytes:
    """Decoded by the codecs' own libraries (zstandard, the standard library's gzip)."""
    if coding == "zstd":
        return zstandard.ZstdDecompressor().decompressobj().decompress(wire)
    if coding == "gzip":
        return gzip.decompress(wire)
    assert coding is None
    return wire


def test_each_page_file_is_served_as_on_disk_in_each_coding(tmp_path: Path) -> None:
    """Every file of ``frontend/`` from the app, asked twice (found, then held) in each
    coding: the file's bytes, with one ETag for all forms, and 304 for it; compressed,
    all of them together, at least as well as zstd's and gzip's default levels (3, 6)
    compress them (the answers' middleware compresses at level 1: 17 % more bytes with
    zstd than the files held)."""
    client = TestClient(create_app(Settings(database_url=f"sqlite:///{tmp_path / 'x.db'}")))
    sent = {"zstd": 0, "gzip": 0}
    default = {"zstd": 0, "gzip": 0}
    for name in _files(FRONTEND_DIR):
        raw = (FRONTEND_DIR / name).read_bytes()
        default["zstd"] += min(len(raw), len(zstandard.ZstdCompressor(level=3).compress(raw)))
        default["gzip"] += min(len(raw), len(gzip.compress(raw, compresslevel=6, mtime=0)))
        etags = set()
        for coding in ("zstd", "gzip", "identity"):
            for _ in range(2):
                wire, headers = _wire(client, f"/{name}", coding)
                used = headers.get("content-encoding")
                assert used in (coding, None), name
                assert _decoded(wire, used) == raw, (name, coding)
                if used is not None:
                    assert headers["vary"] == "Accept-Encoding"
                assert "accept-ranges" not in headers, name  # whole files, no ranges
                if coding in sent:
                    sent[coding] += len(wire)
                etags.add(headers["etag"])
        assert len(etags) == 1, name
        again = client.get(f"/{name}", headers={"If-None-Match": etags.pop()})
        assert again.status_code == 304, name
        assert again.content == b""
    for coding, size in sent.items():
        assert size <= 2 * default[coding], coding  # each file asked twice


def test_an_edited_page_file_is_served_at_once(tmp_path: Path) -> None:
    page = tmp_path / "app.js"
    page.write_bytes(b"export const answer = 41;\n")
    client = _files_client(tmp_path)
    first, headers = _wire(client, "/app.js", "identity")
    assert first == b"export const answer = 41;\n"
    # the same size: the modification time and the inode tell the edit
    page.write_bytes(b"export const answer = 42;\n")
    second, edited = _wire(client, "/app.js", "identity")
    assert second == b"export const answer = 42;\n"
    assert edited["etag"] != headers["etag"]
    page.unlink()
    assert client.get("/app.js").status_code == 404


def test_a_held_index_does_not_answer_its_directory_url_without_a_slash(tmp_path: Path) -> None:
    (tmp_path / "docs").mkdir()
    (tmp_path / "docs" / "index.html").write_bytes(b"<!doctype html><title>docs</title>")
    client = _files_client(tmp_path)
    for _ in range(2):
        assert client.get("/docs/").content == b"<!doctype html><title>docs</title>"
        moved = client.get("/docs", follow_redirects=False)
        assert moved.status_code in (307, 308)
        assert moved.headers["location"].endswith("/docs/")
    assert client.get("/../conftest.py").status_code == 404


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
