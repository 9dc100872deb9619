"""The data prepared for fields not declared yet (``docs/catalogue-data/``, issue 28 items
7–10) is loadable as it stands: one row per seed actuator, numbers finite and positive in
the stored unit, and the published values where the manual prints them."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from actuator_selection.catalogue.csvio import read
from actuator_selection.catalogue.files import ACTUATORS
from actuator_selection.config import SEED_DIR

DATA = Path(__file__).resolve().parents[2] / "docs" / "catalogue-data"
PER_MODEL = ("stiffness.csv", "brake.csv")
TEXT = {"actuator_model", "notes", "source", "read_at"}


def rows(name: str) -> dict[str, dict[str, str]]:
    with (DATA / name).open(encoding="utf-8", newline="") as file:
        return {r["actuator_model"]: r for r in csv.DictReader(file)}


@pytest.mark.parametrize("name", PER_MODEL)
def test_one_row_per_seed_actuator_with_positive_numbers(name: str) -> None:
    seed, problems = read(ACTUATORS, SEED_DIR)
    assert not problems
    data = rows(name)
    assert set(data) == {r.values["model"] for r in seed}
    for model, row in data.items():
        numbers = {k: v for k, v in row.items() if k not in TEXT and v}
        assert all(math.isfinite(float(v)) and float(v) > 0 for v in numbers.values()), model
        if not numbers:
            assert row["notes"].startswith("not "), model  # says why it is empty


def test_cha_stiffness_is_the_printed_table() -> None:
    """CHA 1018854 12/2015 p. 50: CHA-32A, ratio > 50, the values of the manual's own
    example on p. 68 (T_1 29 Nm, K_1 6.7·10⁴, K_2 1.1·10⁵, T_2 108 Nm, K_3 1.2·10⁵)."""
    row = rows("stiffness.csv")["CHA-32A-100"]
    assert [float(row[k]) for k in list(row)[1:6]] == [29, 108, 67e3, 110e3, 120e3]
    assert rows("stiffness.csv")["CHA-40A-50"]["torsional_stiffness_k1_nm_per_rad"] == "100000"


def test_cha_emergency_stops_only_where_printed() -> None:
    brake = rows("brake.csv")
    assert brake["CHA-25A-50"]["emergency_stop_count"] == "200"
    assert brake["CHA-40A-160"]["brake_closing_time_ms"] == "70"
    assert brake["CHA-14A-E-30"]["emergency_stop_count"] == ""  # printed "-"
    assert brake["CHA-20A-50"]["emergency_stop_count"] == ""  # page not read: not guessed


def test_no_gear_rating_is_filled_without_a_document() -> None:
    with (DATA / "gear-ratings.csv").open(encoding="utf-8", newline="") as file:
        ratings = list(csv.DictReader(file))
    numbers = [k for k in ratings[0] if k.endswith(("_nm", "_rpm", "_h", "_count"))]
    assert all(not r[k] for r in ratings for k in numbers)
    assert all(r["notes"].startswith("not published for this actuator") for r in ratings)
