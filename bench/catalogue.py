"""Catalogue at scale: importing 6,400 and 64,000 actuators through the API, reloading them.

Builds a synthetic catalogue (the seed files plus ``n`` made-up actuators of
:func:`bench.batch.synthetic_catalogue`, family ``SYNTHETIC``, models ``SYN-…``: plausible
magnitudes only, they are not data) as the ZIP the admin import takes, starts the real
server (``python -m actuator_selection serve``, as ``bench/http.py``) and prints, each beside
a reference measured in the same run:

- the import's time (POST /api/v1/catalogue/import, the body streamed) against the time
  to send the same bytes to ``/health``'s neighbour that reads nothing (the upload alone);
- the reload's time per process (the first selection after the change, which reads the new
  version) against a plain numpy load of the same columns (``np.load`` of an ``.npz``);
- the server's peak RSS and the memory per actuator (peak RSS after the reload minus the
  RSS of the same server on the starter catalogue, divided by ``n``).

    python -m bench.catalogue                     # PostgreSQL at $TEST_POSTGRES_URL if it answers
    python -m bench.catalogue --database sqlite   # the embedded default
"""

from __future__ import annotations

import io
import zipfile

from actuator_selection.config import REPO_ROOT
from actuator_selection.core.catalogue_fields import ACTUATOR_FIELDS
from actuator_selection.core.catalogue_files import (
    ACTUATORS,
    CATALOGUE_SPECS,
    FAMILIES,
    ZONE_POINTS,
)
from actuator_selection.core.csvio import write
from bench.batch import synthetic_catalogue

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
