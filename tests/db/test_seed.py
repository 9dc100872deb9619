"""Seeding the starter catalogue: complete, idempotent, atomic, precise about bad rows."""

from __future__ import annotations

import csv
import io
from collections.abc import Callable
from datetime import UTC, datetime
from pathlib import Path

import pytest
from sqlalchemy import Engine, func, select
from sqlalchemy.orm import Session

from actuator_selection.catalogue.csvio import CatalogueFileError, check_values, parse, read, write
from actuator_selection.catalogue.files import ACTUATORS, CATALOGUE_SPECS, FAMILIES
from actuator_selection.cli import main
from actuator_selection.config import SEED_DIR
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.engine import make_engine, make_session_factory
from actuator_selection.db.models import (
    ActuatorFamilyRow,
    ActuatorInterfaceRow,
    ActuatorRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
    ZonePointRow,
)
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.db.seed import apply_catalogue, load_seed, read_catalogue

TABLES = {
    "families.csv": ActuatorFamilyRow,
    "actuators.csv": ActuatorRow,
    "zone_points.csv": ZonePointRow,
    "controllers.csv": ControllerRow,
    "temperature_sensors.csv": SensorFittingRow,
    "kty84_130.csv": SensorPointRow,
    "dc_bus_classes.csv": DcBusClassRow,
    "actuator_interfaces.csv": ActuatorInterfaceRow,
}


def counts(engine: Engine) -> tuple[int, int, int]:
    with Session(engine) as s:
        return (
            s.scalar(select(func.count()).select_from(ActuatorFamilyRow)) or 0,
            s.scalar(select(func.count()).select_from(ActuatorRow)) or 0,
            s.scalar(select(func.count()).select_from(ZonePointRow)) or 0,
        )


def rows_per_file(engine: Engine) -> dict[str, int]:
    with Session(engine) as s:
        return {
            file: s.scalar(select(func.count()).select_from(model)) or 0
            for file, model in TABLES.items()
        }


def csv_rows(name: str) -> int:
    with (SEED_DIR / name).open(encoding="utf-8") as f:
        return sum(1 for _ in csv.DictReader(f))


def edit_cell(directory: Path, file: str, model_or_name: str, column: str, value: str) -> int:
    """Set one cell of ``file``; returns the 1-based line of the edited row."""
    path = directory / file
    rows = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8"))))
    key = "model" if "model" in rows[0] else "name"
    index = next(i for i, r in enumerate(rows) if r[key] == model_or_name)
    rows[index][column] = value
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    path.write_text(out.getvalue(), encoding="utf-8")
    return index + 2


DROPPED_FROM = ("actuators.csv", "actuator_interfaces.csv")


def drop_model(directory: Path, model: str) -> None:
    """Remove ``model`` from the files that list it by name first (its row and interface)."""
    for file in DROPPED_FROM:
        path = directory / file
        lines = path.read_text(encoding="utf-8").splitlines()
        kept = [line for line in lines if not line.startswith(f"{model},")]
        assert len(kept) == len(lines) - 1
        path.write_text("\n".join(kept) + "\n", encoding="utf-8")


def test_seed_loads_every_row_then_changes_nothing(empty_engine: Engine) -> None:
    assert set(TABLES) == {spec.file for spec in CATALOGUE_SPECS}
    factory = make_session_factory(empty_engine)
    with factory.begin() as s:
        first = load_seed(s, SEED_DIR)
    expected = {file: csv_rows(file) for file in TABLES}
    assert rows_per_file(empty_engine) == expected
    assert first.inserted == sum(expected.values())
    assert first.updated == 0
    with factory.begin() as s:
        second = load_seed(s, SEED_DIR)
    assert (second.inserted, second.updated, second.unchanged) == (0, 0, sum(expected.values()))
    assert rows_per_file(empty_engine) == expected


def test_seed_converts_units_and_keeps_sources(empty_engine: Engine) -> None:
    with make_session_factory(empty_engine).begin() as s:
        load_seed(s, SEED_DIR)
    with Session(empty_engine) as s:
        cha = CatalogueRepository(s).actuator("CHA-25A-50")
        assert cha is not None
        # The CHA catalogue prints K_INL in 10⁻³ A/rpm: 6 → 0.006 A/rpm.
        assert cha.actuator.no_load_current_constant_30c_a_per_rpm == pytest.approx(0.006)
        assert cha.actuator.max_torque_nm == 98
        assert cha.actuator.max_speed_rpm == 112
        assert "CHA" in str(cha.values["source"])
        example = CatalogueRepository(s).actuator("FHA-25C-50-L")
        assert example is not None
        assert (example.actuator.max_torque_nm, example.actuator.inertia_kgm2) == (151, 0.86)
        assert example.actuator.stall_torque_nm is None  # not published: stays empty
        assert "Table 516.3" in str(example.values["source"])
        assert all(r.values["source"] for r in CatalogueRepository(s).actuators())


def test_seed_stores_the_citation_and_where_it_was_read_apart(empty_engine: Engine) -> None:
    """``source`` holds the manufacturer's document, ``read_at`` the public copy (issue 28,
    item 11); the FHA-C output bearing's d_p, R, C, C_0 (FHA-C manual §2-3, Table 1) load."""
    with make_session_factory(empty_engine).begin() as s:
        load_seed(s, SEED_DIR)
    with Session(empty_engine) as s:
        fha = CatalogueRepository(s).actuator("FHA-25C-50")
        assert fha is not None
        bearing = fha.actuator
        assert (
            bearing.output_bearing_pitch_diameter_m,
            bearing.output_bearing_offset_m,
            bearing.output_bearing_dynamic_load_rating_n,
            bearing.output_bearing_static_load_rating_n,
            bearing.text("output_bearing_type"),
        ) == (0.0962, 0.018, 18000, 33300, "cross_roller")
        source, read_at = fha.values["source"], fha.values["read_at"]
        assert isinstance(source, str)
        assert "§2-3" in source
        assert "Table 1" in source
        assert isinstance(read_at, str)
        assert "fha-series/3976486?page=23" in read_at
        stored = s.scalars(select(ActuatorRow)).all()
        assert all("easymanua" not in r.source and "manualshive" not in r.source for r in stored)
        assert {r.model for r in stored if r.read_at} >= {"CHA-25A-50", "FHA-8C-30"}


def test_seed_updates_a_changed_value(empty_engine: Engine, seed_dir: Path) -> None:
    factory = make_session_factory(empty_engine)
    with factory.begin() as s:
        load_seed(s, seed_dir)
    edit_cell(seed_dir, "actuators.csv", "CHA-20A-30", "max_torque_nm", "28")
    with factory.begin() as s:
        report = load_seed(s, seed_dir)
    assert report.updated == 1
    assert report.inserted == 0
    with Session(empty_engine) as s:
        row = s.scalars(select(ActuatorRow).where(ActuatorRow.model == "CHA-20A-30")).one()
        assert row.max_torque_nm == 28


def test_seed_loads_and_replaces_zone_points(empty_engine: Engine, seed_dir: Path) -> None:
    (seed_dir / "zone_points.csv").write_text(
        "actuator_model,speed_rpm,torque_nm,source\n"
        "FHA-25C-50-L,0,60,test\nFHA-25C-50-L,90,40,test\n",
        encoding="utf-8",
    )
    factory = make_session_factory(empty_engine)
    with factory.begin() as s:
        load_seed(s, seed_dir)
    (seed_dir / "zone_points.csv").write_text(
        "actuator_model,speed_rpm,torque_nm,source\n"
        "FHA-25C-50-L,0,61,test\nFHA-25C-50-L,90,40,test\n",
        encoding="utf-8",
    )
    with factory.begin() as s:
        load_seed(s, seed_dir)
    with Session(empty_engine) as s:
        record = CatalogueRepository(s).actuator("FHA-25C-50-L")
        assert record is not None
        assert record.actuator.zone is not None
        assert [(p.speed_rpm, p.torque_nm) for p in record.actuator.zone.points] == [
            (0, 61),
            (90, 40),
        ]


@pytest.mark.parametrize(
    ("file", "row", "column", "value", "rule"),
    [
        ("actuators.csv", "CHA-25A-50", "max_torque_nm", "-98", "> 0"),
        ("actuators.csv", "CHA-25A-50", "inertia_kgm2", "nan", "> 0"),
        ("actuators.csv", "CHA-25A-50", "max_speed_rpm", "fast", "> 0"),
        ("actuators.csv", "CHA-25A-50", "gear_ratio", "", "required"),
        ("actuators.csv", "CHA-25A-50", "source", "", "required"),
        ("actuators.csv", "CHA-25A-50", "family", "CHX", "unknown family"),
        ("families.csv", "CHA", "warning_resistance_ohm", "0", "> 0"),
    ],
)
def test_bad_cell_loads_nothing_and_is_named(
    empty_engine: Engine, seed_dir: Path, file: str, row: str, column: str, value: str, rule: str
) -> None:
    line = edit_cell(seed_dir, file, row, column, value)
    with (
        pytest.raises(CatalogueFileError) as caught,
        make_session_factory(empty_engine).begin() as s,
    ):
        load_seed(s, seed_dir)
    message = str(caught.value)
    assert f"{file}, line {line}, column {column}" in message
    assert rule in message
    assert counts(empty_engine) == (0, 0, 0)


def test_unknown_column_names_its_unit_rule(empty_engine: Engine, seed_dir: Path) -> None:
    path = seed_dir / "actuators.csv"
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace("max_torque_nm", "max_torque_kgm", 1), encoding="utf-8")
    with (
        pytest.raises(CatalogueFileError) as caught,
        make_session_factory(empty_engine).begin() as s,
    ):
        load_seed(s, seed_dir)
    problems = {(p.file, p.line, p.column) for p in caught.value.problems}
    assert ("actuators.csv", 1, "max_torque_kgm") in problems
    assert ("actuators.csv", 1, "max_torque_nm") in problems  # missing now
    assert counts(empty_engine) == (0, 0, 0)


def test_duplicate_and_ragged_rows(empty_engine: Engine, seed_dir: Path) -> None:
    path = seed_dir / "actuators.csv"
    lines = path.read_text(encoding="utf-8").splitlines()
    lines.append(lines[2])  # duplicate model
    lines.append("CHA-99A-50,CHA,50")  # too few cells
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    with (
        pytest.raises(CatalogueFileError) as caught,
        make_session_factory(empty_engine).begin() as s,
    ):
        load_seed(s, seed_dir)
    messages = [str(p) for p in caught.value.problems]
    assert any(f"line {len(lines) - 1}" in m and "duplicates line 3" in m for m in messages)
    assert any(f"line {len(lines)}" in m and "cells" in m for m in messages)


def test_not_utf8_and_missing_file(empty_engine: Engine, seed_dir: Path) -> None:
    (seed_dir / "families.csv").write_bytes(b"name,source\n\xff\xfe,x\n")
    (seed_dir / "zone_points.csv").unlink()
    with (
        pytest.raises(CatalogueFileError) as caught,
        make_session_factory(empty_engine).begin() as s,
    ):
        load_seed(s, seed_dir)
    messages = " | ".join(str(p) for p in caught.value.problems)
    assert "families.csv" in messages
    assert "UTF-8" in messages
    assert "zone_points.csv" in messages
    assert "not found" in messages


def test_cli_migrates_and_seeds(
    backend: str,
    new_database: Callable[[str], str],
    seed_dir: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    url = new_database(backend)
    assert main(["--database-url", url, "migrate"]) == 0
    assert main(["--database-url", url, "seed"]) == 0
    assert "inserted" in capsys.readouterr().out
    edit_cell(seed_dir, "actuators.csv", "CHA-25A-50", "max_speed_rpm", "-1")
    assert main(["--database-url", url, "seed", "--directory", str(seed_dir)]) == 1
    err = capsys.readouterr().err
    assert "nothing loaded" in err
    assert "column max_speed_rpm" in err


def test_seed_raises_the_catalogue_version_only_on_change(
    empty_engine: Engine, seed_dir: Path
) -> None:
    factory = make_session_factory(empty_engine)

    def version() -> int:
        with Session(empty_engine) as s:
            return CatalogueVersionRepository(s).current()

    assert version() == 0
    with factory.begin() as s:
        load_seed(s, seed_dir)
    assert version() == 1
    with factory.begin() as s:
        load_seed(s, seed_dir)
    assert version() == 1
    edit_cell(seed_dir, "actuators.csv", "CHA-20A-30", "mass_kg", "4.3")
    with factory.begin() as s:
        load_seed(s, seed_dir)
    assert version() == 2


def test_seed_never_retires_and_keeps_what_was_retired(
    empty_engine: Engine, seed_dir: Path
) -> None:
    factory = make_session_factory(empty_engine)
    with factory.begin() as s:
        load_seed(s, seed_dir)
    with factory.begin() as s:
        row = s.scalars(select(ActuatorRow).where(ActuatorRow.model == "CHA-20A-30")).one()
        row.retired_at = datetime.now(UTC)
    drop_model(seed_dir, "CHA-25A-50")
    with factory.begin() as s:
        report = load_seed(s, seed_dir)
    assert (report.inserted, report.updated) == (0, 0)
    with Session(empty_engine) as s:
        retired = set(
            s.scalars(select(ActuatorRow.model).where(ActuatorRow.retired_at.is_not(None)))
        )
    assert retired == {"CHA-20A-30"}  # still retired; CHA-25A-50 is missing but not retired


def test_import_mode_retires_brings_back_and_removes_zones(
    empty_engine: Engine, seed_dir: Path
) -> None:
    (seed_dir / "zone_points.csv").write_text(
        "actuator_model,speed_rpm,torque_nm,source\n"
        "FHA-25C-50-L,0,60,test\nFHA-25C-50-L,90,40,test\n",
        encoding="utf-8",
    )
    factory = make_session_factory(empty_engine)
    with factory.begin() as s:
        load_seed(s, seed_dir)
    (seed_dir / "zone_points.csv").write_text(
        "actuator_model,speed_rpm,torque_nm,source\n", encoding="utf-8"
    )
    full = {f: (seed_dir / f).read_text(encoding="utf-8") for f in DROPPED_FROM}
    drop_model(seed_dir, "CHA-25A-50")
    with factory.begin() as s:
        changes = apply_catalogue(s, read_catalogue(seed_dir), replace=True)
    assert changes.files["actuators.csv"].retired == 1
    assert changes.files["zone_points.csv"].retired == 2
    with Session(empty_engine) as s:
        row = s.scalars(select(ActuatorRow).where(ActuatorRow.model == "CHA-25A-50")).one()
        assert row.retired_at is not None
        assert s.scalar(select(func.count()).select_from(ZonePointRow)) == 0
    for file, text in full.items():
        (seed_dir / file).write_text(text, encoding="utf-8")
    with factory.begin() as s:
        changes = apply_catalogue(s, read_catalogue(seed_dir), replace=True)
    assert (changes.files["actuators.csv"].updated, changes.files["actuators.csv"].retired) == (
        1,
        0,
    )
    with Session(empty_engine) as s:
        row = s.scalars(select(ActuatorRow).where(ActuatorRow.model == "CHA-25A-50")).one()
        assert row.retired_at is None


def test_written_csv_reads_back_to_the_same_values() -> None:
    """Export writes published units; reading them back gives the stored SI values exactly."""
    for spec in (FAMILIES, ACTUATORS):
        records, problems = read(spec, SEED_DIR)
        assert not problems
        again, problems = parse(spec, write(spec, [r.values for r in records]))
        assert not problems
        assert [r.values for r in again] == [r.values for r in records]


def test_check_values_shares_the_rules_and_messages_of_the_files() -> None:
    values, problems = check_values(
        ACTUATORS,
        {"model": "X", "family": "CHA", "gear_ratio": 50, "max_torque_nm": -1, "source": "s"},
    )
    (problem,) = problems
    assert (problem.column, problem.message) == (
        "max_torque_nm",
        "must be a finite number > 0, got '-1'",
    )
    values, problems = check_values(
        ACTUATORS,
        {
            "model": "X",
            "family": "CHA",
            "gear_ratio": "50",
            "no_load_current_constant_30c_ma_per_rpm": 6,
            "source": "s",
        },
    )
    assert not problems
    assert values["no_load_current_constant_30c_a_per_rpm"] == pytest.approx(0.006)
    assert values["mass_kg"] is None
    _, problems = check_values(ACTUATORS, {"model": ["X"], "unit": 1})
    assert {p.column for p in problems} >= {"model", "unit", "family", "gear_ratio", "source"}


def test_cli_seed_if_empty_keeps_a_written_catalogue(
    backend: str,
    new_database: Callable[[str], str],
    seed_dir: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """`make run` seeds with --if-empty: an admin's later changes survive a restart."""
    url = new_database(backend)
    assert main(["--database-url", url, "migrate"]) == 0
    assert main(["--database-url", url, "seed", "--if-empty"]) == 0
    assert "inserted" in capsys.readouterr().out
    edit_cell(seed_dir, "actuators.csv", "CHA-25A-50", "max_torque_nm", "1")
    assert main(["--database-url", url, "seed", "--if-empty", "--directory", str(seed_dir)]) == 0
    assert "left as it is" in capsys.readouterr().out
    engine = make_engine(url)
    try:
        with Session(engine) as s:
            record = CatalogueRepository(s).actuator("CHA-25A-50")
            assert record is not None
            assert record.actuator.max_torque_nm == 98
    finally:
        engine.dispose()


def _drop_lines(directory: Path, file: str, starts: str) -> None:
    path = directory / file
    lines = path.read_text(encoding="utf-8").splitlines()
    kept = [line for line in lines if not line.startswith(starts)]
    assert len(kept) == len(lines) - 1, (file, starts)
    path.write_text("\n".join(kept) + "\n", encoding="utf-8")


def test_controller_files_follow_the_same_two_modes(empty_engine: Engine, seed_dir: Path) -> None:
    """Seeding never withdraws a controller-side row; an import retires controllers (kept,
    brought back later) and removes the other rows it lacks, except a retired actuator's
    interface, which waits for the actuator."""
    factory = make_session_factory(empty_engine)
    with factory.begin() as s:
        load_seed(s, seed_dir)
    full = {f: (seed_dir / f).read_text(encoding="utf-8") for f in TABLES}
    _drop_lines(seed_dir, "controllers.csv", "5,NUM AG,MDLU,")
    _drop_lines(seed_dir, "kty84_130.csv", "-40,")
    _drop_lines(seed_dir, "temperature_sensors.csv", "FHA-C,L,ptc,")
    drop_model(seed_dir, "CHA-25A-50")
    _drop_lines(seed_dir, "actuator_interfaces.csv", "CHA-20A-30,")
    before = rows_per_file(empty_engine)

    with factory.begin() as s:
        assert load_seed(s, seed_dir).inserted == 0
    assert rows_per_file(empty_engine) == before

    with factory.begin() as s:
        changes = apply_catalogue(s, read_catalogue(seed_dir), replace=True)
    withdrawn = {f: c.retired for f, c in changes.files.items() if c.retired}
    assert withdrawn == {
        "actuators.csv": 1,
        "controllers.csv": 1,
        "kty84_130.csv": 1,
        "temperature_sensors.csv": 1,
        "actuator_interfaces.csv": 1,  # CHA-20A-30's; the retired CHA-25A-50 keeps its own
    }
    after = rows_per_file(empty_engine)
    assert after == {
        **before,
        "kty84_130.csv": before["kty84_130.csv"] - 1,
        "temperature_sensors.csv": before["temperature_sensors.csv"] - 1,
        "actuator_interfaces.csv": before["actuator_interfaces.csv"] - 1,
    }
    with Session(empty_engine) as s:
        mdlu = s.scalars(select(ControllerRow).where(ControllerRow.source_row == 5)).one()
        assert mdlu.retired_at is not None
        assert 5 not in {r.controller.source_row for r in ProtectionRepository(s).controllers()}

    for file, text in full.items():
        (seed_dir / file).write_text(text, encoding="utf-8")
    with factory.begin() as s:
        changes = apply_catalogue(s, read_catalogue(seed_dir), replace=True)
    assert changes.files["controllers.csv"].updated == 1  # brought back
    assert changes.files["actuator_interfaces.csv"].inserted == 1  # CHA-20A-30's again
    assert rows_per_file(empty_engine) == before
    with Session(empty_engine) as s:
        assert len(ProtectionRepository(s).controllers()) == csv_rows("controllers.csv")
