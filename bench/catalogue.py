"""Catalogue at scale: importing 6,400 and 64,000 actuators through the API, reloading them.

Builds a synthetic catalogue (the seed files plus ``n`` made-up actuators of
:func:`bench.batch.synthetic_catalogue`, family ``SYNTHETIC``, models ``SYN-…``: plausible
magnitudes only, they are not data) as the ZIP the admin import takes, starts the real
server (``python -m actuator_selection serve``, as ``bench/http.py``) and prints, each beside
a reference measured in the same run:

- the import's time (POST /api/v1/catalogue/import of the ZIP) against the ``csv`` module
  reading the same files in this process;
- the reload's time per process (the first selection after a change of one actuator,
  which reads the new version, minus a warm selection) against ``np.load`` of the
  engine's numeric columns of as many actuators from an ``.npz``;
- the server's RSS before and after the import and its peak, and the memory per actuator
  (RSS after the import and reload minus before, divided by ``n``).

    python -m bench.catalogue                     # PostgreSQL at $TEST_POSTGRES_URL if it answers
    python -m bench.catalogue --database sqlite   # the embedded default
"""

from __future__ import annotations

import argparse
import csv
import io
import tempfile
import time
import zipfile
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import httpx
import numpy as np
from sqlalchemy.engine import make_url

from actuator_selection.catalogue.csvio import write
from actuator_selection.catalogue.fields import ACTUATOR_FIELDS, ENGINE_FIELDS, Kind
from actuator_selection.catalogue.files import ACTUATORS, CATALOGUE_SPECS, FAMILIES, ZONE_POINTS
from actuator_selection.config import REPO_ROOT
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.sales import ApiKeyRepository
from bench import targets
from bench.batch import synthetic_catalogue
from bench.http import WORKED_EXAMPLE, _peak_rss_mb, _postgres_database, _serve
from bench.selection import starter_catalogue

SIZES = (6_400, 64_000)
SEED = REPO_ROOT / "seed_data"
SYNTHETIC_SOURCE = "synthetic bench data (bench/catalogue.py), not a catalogue"
ROW_CHARS = 1_450
"""About the length of a row of the 93 MB file of issue 32 (64,000 actuators): the row's
``notes`` say what it is, padded to this length, so the files weigh what a catalogue with
its citations and derivations weighs."""


def synthetic_rows(n: int) -> tuple[list[dict[str, object]], list[dict[str, object]]]:
    """The actuators.csv and zone_points.csv rows (stored values) of ``n`` made-up actuators."""
    actuators: list[dict[str, object]] = []
    zones: list[dict[str, object]] = []
    notes = "made-up actuator of the bench, not data. "
    for a in synthetic_catalogue(n):
        values: dict[str, object] = {f.name: getattr(a, f.name, None) for f in ACTUATOR_FIELDS}
        values.update(family="SYNTHETIC", source=SYNTHETIC_SOURCE)
        values["notes"] = (notes * (ROW_CHARS // len(notes)))[: ROW_CHARS - 200].strip()
        actuators.append(values)
        if a.zone is not None:
            zones.extend(
                {
                    "actuator_model": a.model,
                    "speed_rpm": p.speed_rpm,
                    "torque_nm": p.torque_nm,
                    "source": SYNTHETIC_SOURCE,
                }
                for p in a.zone.points
            )
    return actuators, zones


def catalogue_zip(n: int, *, bad_line: int | None = None) -> bytes:
    """The seed catalogue plus ``n`` synthetic actuators as the ZIP the import takes.

    ``bad_line``: actuators.csv's line of that number (the header is line 1) gets a
    negative ``max_torque_nm``, which the import refuses naming line and column.
    """
    actuators, zones = synthetic_rows(n)
    family: dict[str, object] = {c.attribute: None for c in FAMILIES.columns}
    family.update(
        name="SYNTHETIC", description="made-up actuators of the bench", source=SYNTHETIC_SOURCE
    )
    seeded = (SEED / ACTUATORS.file).read_text(encoding="utf-8").count("\n") - 1
    if bad_line is not None:
        actuators[bad_line - 2 - seeded]["max_torque_nm"] = -1.0
    added = {FAMILIES: [family], ACTUATORS: actuators, ZONE_POINTS: zones}
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for spec in CATALOGUE_SPECS:
            text = (SEED / spec.file).read_text(encoding="utf-8")
            if spec in added:
                text += write(spec, added[spec]).split("\n", 1)[1]
            archive.writestr(spec.file, text)
    return buffer.getvalue()


def _admin_key(url: str) -> str:
    """An admin API key on the database at ``url``."""
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            _, key = ApiKeyRepository(session).create(
                name="bench admin", role="admin", now=datetime.now(UTC)
            )
        return key
    finally:
        engine.dispose()


def _rss_mb(pid: int) -> float:
    """The process's resident memory now [MB] (Linux /proc)."""
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return float("nan")


def _plain_csv_s(body: bytes) -> float:
    """Reference for the import: the ``csv`` module reading every member of ``body``."""
    started = time.perf_counter()
    with zipfile.ZipFile(io.BytesIO(body)) as archive:
        for name in archive.namelist():
            with archive.open(name) as member:
                for _ in csv.reader(io.TextIOWrapper(member, encoding="utf-8", newline="")):
                    pass
    return time.perf_counter() - started


def _numpy_load_s(n: int, folder: Path) -> float:
    """Reference for the reload: ``np.load`` of the engine's numeric columns of ``n``
    actuators (float64 each, as the engine's arrays hold them), saved as one ``.npz``."""
    numeric = [f.name for f in ENGINE_FIELDS if f.kind is Kind.NUMBER]
    path = folder / f"columns-{n}.npz"
    rng = np.random.default_rng(1)
    np.savez(path, *[rng.random(n) for _ in numeric])
    started = time.perf_counter()
    with np.load(path) as loaded:
        _ = [loaded[name] for name in loaded.files]
    return time.perf_counter() - started


def _timed_select(client: httpx.Client, model: str) -> float:
    started = time.perf_counter()
    answer = client.post("/api/v1/selections", json={**WORKED_EXAMPLE, "models": [model]})
    assert answer.status_code == 201, answer.text
    return time.perf_counter() - started


def measure(n: int, url: str, folder: Path) -> None:
    """Import ``n`` synthetic actuators into a fresh server on ``url`` and print the lines."""
    starter_catalogue(url)
    key = _admin_key(url)
    body = catalogue_zip(n)
    process, base = _serve(url, {"WORKERS": "1"})
    try:
        with httpx.Client(base_url=base, timeout=900) as client:
            admin = {"Authorization": f"Bearer {key}"}
            one = "FHA-25C-50-L"
            warm = min(_timed_select(client, one) for _ in range(5))
            started = time.perf_counter()
            for _ in range(200):
                client.get("/api/v1/health")
            health_ms = (time.perf_counter() - started) / 200 * 1e3
            rss_before = _rss_mb(process.pid)
            started = time.perf_counter()
            imported = client.post(
                "/api/v1/catalogue/import",
                content=body,
                headers={**admin, "Content-Type": "application/zip"},
            )
            import_s = time.perf_counter() - started
            assert imported.status_code == 200, imported.text[:500]
            # The import's request left the snapshot alone: the next request reads it.
            first_s = _timed_select(client, one) - warm
            rss_after = _rss_mb(process.pid)
            # A change of one actuator, then the reload every process does on its next request.
            gone = client.delete("/api/v1/actuators/SYN-0000", headers=admin)
            assert gone.status_code == 204, gone.text
            reload_s = _timed_select(client, one) - warm
            peak = _peak_rss_mb(process.pid)
        plain = _plain_csv_s(body)
        load = _numpy_load_s(n, folder)
        unpacked = sum(i.file_size for i in zipfile.ZipFile(io.BytesIO(body)).infolist())
        print(
            f"{n:>6} actuators ({len(body) / 1e6:.1f} MB ZIP, {unpacked / 1e6:.0f} MB CSV):\n"
            f"  import {import_s:6.2f} s = {import_s / plain:5.1f}× the csv module reading "
            f"the same files ({plain:.2f} s); /health {health_ms:.1f} ms\n"
            f"  reload after the import {first_s:5.2f} s, after a change of one actuator "
            f"{reload_s:5.2f} s per process = {reload_s / load:6.0f}× np.load of the same "
            f"columns ({load * 1e3:.1f} ms)\n"
            f"  server RSS {rss_before:.0f} → {rss_after:.0f} MB, peak {peak:.0f} MB; "
            f"{(rss_after - rss_before) * 1e6 / n:.0f} bytes per actuator"
        )
        if n == 64_000:
            print(
                f"  reload after a change: "
                f"{targets.RELOAD_64000.judged(reload_s, f'np.load {load * 1e3:.0f} ms')}; "
                f"peak RSS: {targets.PEAK_RSS_64000.judged(peak)}"
            )
    finally:
        process.terminate()
        process.wait(30)


def main() -> None:
    """Measure and print; see the module docstring."""
    parser = argparse.ArgumentParser(prog="python -m bench.catalogue")
    parser.add_argument("--database", choices=["postgresql", "sqlite"], default="postgresql")
    parser.add_argument("--sizes", type=int, nargs="+", default=list(SIZES))
    args = parser.parse_args()
    for n in args.sizes:
        with tempfile.TemporaryDirectory() as folder:
            found = _postgres_database() if args.database == "postgresql" else None
            drop: Callable[[], None] = lambda: None  # noqa: E731
            if found is None:
                url = f"sqlite:///{Path(folder) / 'bench.sqlite3'}"
                if args.database == "postgresql":
                    print("PostgreSQL unreachable: measuring on SQLite")
            else:
                url, drop = found
            try:
                print(make_url(url).get_backend_name(), end=", ")
                measure(n, url, Path(folder))
            finally:
                drop()


if __name__ == "__main__":
    main()
