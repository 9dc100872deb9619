"""Catalogue management: actuator and zone writes by the seed rules, retirement, import/export."""

from __future__ import annotations

import csv
import io
import json
import zipfile
from typing import Any

import pytest
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.catalogue.csvio import parse
from actuator_selection.catalogue.files import ACTUATORS, CATALOGUE_SPECS
from actuator_selection.config import SEED_DIR

__all__ = ["api", "sales_api_with"]

NEW: dict[str, Any] = {
    "model": "CHA-99A-50",
    "family": "CHA",
    "gear_ratio": 50,
    "max_torque_nm": 120,
    "max_speed_rpm": 80,
    "inertia_kgm2": 2.5,
    "stall_torque_nm": 60,
    "no_load_current_constant_30c_ma_per_rpm": 6,
    "notes": "test actuator",
    "source": "test data",
}


def admin(api: SalesApi, method: str, path: str, **kwargs: Any) -> Any:
    call = getattr(api.client, method)
    return call(path, headers={**api.headers("admin"), **kwargs.pop("headers", {})}, **kwargs)


def version(api: SalesApi) -> int:
    return int(api.get("/api/v1/catalogue/version", role=None).json()["version"])


def test_create_an_actuator(api: SalesApi) -> None:
    before = version(api)
    response = admin(api, "post", "/api/v1/actuators", json=NEW)
    assert response.status_code == 201, response.text
    assert response.headers["location"] == "/api/v1/actuators/CHA-99A-50"
    body = response.json()
    assert (body["model"], body["family"], body["max_torque_nm"]) == ("CHA-99A-50", "CHA", 120)
    # the published unit is converted as the seed loader does: 6 mA/rpm → 0.006 A/rpm
    assert body["no_load_current_constant_30c_a_per_rpm"] == pytest.approx(0.006)
    assert body["mass_kg"] is None
    assert version(api) == before + 1
    assert api.get("/api/v1/actuators/CHA-99A-50", role=None).json() == body
    again = admin(api, "post", "/api/v1/actuators", json=NEW)
    assert again.status_code == 409
    assert version(api) == before + 1


def seed_message(column: str, value: str) -> str:
    """What the seed loader says about ``value`` in ``column`` of actuators.csv."""
    header = [c.name for c in ACTUATORS.columns]
    row = dict.fromkeys(header, "") | {
        "model": "X",
        "family": "CHA",
        "gear_ratio": "50",
        "source": "s",
    }
    row[column] = value
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=header)
    writer.writeheader()
    writer.writerow(row)
    _, problems = parse(ACTUATORS, out.getvalue())
    (problem,) = [p for p in problems if p.column == column]
    return problem.message


@pytest.mark.parametrize(
    ("column", "value", "csv_value"),
    [
        ("max_torque_nm", -98, "-98"),
        ("max_torque_nm", "-98", "-98"),
        ("inertia_kgm2", "nan", "nan"),
        ("max_speed_rpm", "fast", "fast"),
        ("gear_ratio", None, ""),
        ("source", "", ""),
        ("temperature", 1, None),
        ("model", "M" * 61, "M" * 61),
        ("mass_kg", True, "true"),
        ("gear_ratio", "1e308", "1e308"),
        ("max_speed_rpm", "1000001", "1000001"),
    ],
)
def test_writes_obey_the_seed_files_rules(
    api: SalesApi, column: str, value: Any, csv_value: str | None
) -> None:
    """The same value gets the same message from the API and from the seed loader."""
    before = version(api)
    response = admin(api, "post", "/api/v1/actuators", json={**NEW, column: value})
    assert response.status_code == 422
    errors = response.json()["detail"]
    named = [e for e in errors if e["loc"] == ["body", column]]
    assert named, errors
    if csv_value is not None:
        assert seed_message(column, csv_value) in named[0]["msg"]
    else:
        assert "unknown column" in named[0]["msg"]
    assert version(api) == before
    assert api.get("/api/v1/actuators/CHA-99A-50", role=None).status_code == 404


def test_unknown_family_is_refused(api: SalesApi) -> None:
    response = admin(api, "post", "/api/v1/actuators", json={**NEW, "family": "CHX"})
    assert response.status_code == 422
    assert response.json()["detail"][0]["loc"] == ["body", "family"]
    assert "unknown family 'CHX'" in response.json()["detail"][0]["msg"]


def test_replace_an_actuator(api: SalesApi) -> None:
    admin(api, "post", "/api/v1/actuators", json=NEW)
    before = version(api)
    same = admin(api, "put", "/api/v1/actuators/CHA-99A-50", json=NEW)
    assert same.status_code == 200
    assert version(api) == before  # nothing changed, no new version
    changed = admin(
        api, "put", "/api/v1/actuators/CHA-99A-50", json={**NEW, "max_torque_nm": "130"}
    )
    assert changed.json()["max_torque_nm"] == 130
    assert changed.json()["notes"] == "test actuator"
    assert version(api) == before + 1
    without_notes = {k: v for k, v in NEW.items() if k != "notes"}
    assert admin(api, "put", "/api/v1/actuators/CHA-99A-50", json=without_notes).json()[
        "notes"
    ] is None  # fmt: skip
    mismatch = admin(api, "put", "/api/v1/actuators/CHA-99A-50", json={**NEW, "model": "Y"})
    assert mismatch.status_code == 422
    assert mismatch.json()["detail"][0]["loc"] == ["body", "model"]
    assert admin(api, "put", "/api/v1/actuators/NOPE-1", json=NEW).status_code == 404
    assert admin(api, "put", "/api/v1/actuators/CHA-99A-50", json=[1, 2]).status_code == 422


def test_retire_keeps_the_row_and_bring_back(api: SalesApi) -> None:
    admin(api, "post", "/api/v1/actuators", json=NEW)
    before = version(api)
    assert admin(api, "delete", "/api/v1/actuators/CHA-99A-50").status_code == 204
    assert version(api) == before + 1
    assert admin(api, "delete", "/api/v1/actuators/CHA-99A-50").status_code == 204
    assert version(api) == before + 1  # retiring twice changes nothing
    assert admin(api, "delete", "/api/v1/actuators/NOPE-1").status_code == 404
    exported = export_json(api)
    assert "CHA-99A-50" not in {a["model"] for a in exported["actuators"]}
    assert admin(api, "post", "/api/v1/actuators", json=NEW).status_code == 409
    assert admin(api, "put", "/api/v1/actuators/CHA-99A-50/zone", json=ZONE).status_code == 409
    back = admin(api, "put", "/api/v1/actuators/CHA-99A-50", json=NEW)
    assert back.status_code == 200
    assert "CHA-99A-50" in {a["model"] for a in export_json(api)["actuators"]}


def test_retired_actuators_leave_listings_and_selections(api: SalesApi) -> None:
    assert admin(api, "delete", "/api/v1/actuators/CHA-25A-50").status_code == 204
    listed = {a["model"] for a in api.get("/api/v1/actuators", role=None).json()["actuators"]}
    assert "CHA-25A-50" not in listed
    assert api.get("/api/v1/actuators/CHA-25A-50", role=None).status_code == 404
    whole = api.selection()
    assert "CHA-25A-50" not in {c["model"] for c in whole["candidates"]}
    named = api.client.post(
        "/api/v1/selections",
        json={
            "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
            "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
            "models": ["CHA-25A-50"],
        },
    )
    assert named.status_code == 422


ZONE: dict[str, Any] = {
    "points": [{"speed_rpm": 0, "torque_nm": 60}, {"speed_rpm": 90, "torque_nm": "40"}],
    "source": "test zone",
}
NO_ZERO = [{"speed_rpm": 10, "torque_nm": 1}, {"speed_rpm": 20, "torque_nm": 0}]


def test_zone_is_set_used_and_removed(api: SalesApi) -> None:
    before = version(api)
    response = admin(api, "put", "/api/v1/actuators/FHA-25C-50-L/zone", json=ZONE)
    assert response.status_code == 200, response.text
    assert response.json()["continuous_duty_zone"] == [
        {"speed_rpm": 0, "torque_nm": 60},
        {"speed_rpm": 90, "torque_nm": 40},
    ]
    assert response.json()["continuous_duty_zone_source"] == "test zone"
    assert version(api) == before + 1
    assert admin(api, "put", "/api/v1/actuators/FHA-25C-50-L/zone", json=ZONE).status_code == 200
    assert version(api) == before + 1
    # The worked example now has its continuous-duty check: T_rms 35.57 Nm ≤ 58.6 Nm at 6.15 rpm.
    candidate = api.selection(models=["FHA-25C-50-L"])["candidates"][0]
    checks = {c["name"]: c for c in candidate["checks"]}
    assert checks["continuous_duty"]["status"] == "pass"
    # still unconfirmed: the chapter gives no winding constants for the drive's voltage
    assert checks["drive_voltage"]["status"] == "no_data"
    assert candidate["verdict"] == "unconfirmed"
    assert admin(api, "delete", "/api/v1/actuators/FHA-25C-50-L/zone").status_code == 204
    assert api.get("/api/v1/actuators/FHA-25C-50-L", role=None).json()[
        "continuous_duty_zone"
    ] is None  # fmt: skip
    assert version(api) == before + 2


@pytest.mark.parametrize(
    ("zone", "loc", "rule"),
    [
        ({**ZONE, "points": ZONE["points"][:1]}, ["body", "points", 0, "speed_rpm"], "two points"),
        (
            {**ZONE, "points": NO_ZERO},
            ["body", "points", 0, "speed_rpm"],
            "0 rpm",
        ),
        (
            {**ZONE, "points": [ZONE["points"][0], {"speed_rpm": 90, "torque_nm": -1}]},
            ["body", "points", 1, "torque_nm"],
            "≥ 0",
        ),
        (
            {**ZONE, "points": [*ZONE["points"], {"speed_rpm": 90, "torque_nm": 30}]},
            ["body", "points", 2, "speed_rpm"],
            "duplicates",
        ),
        ({**ZONE, "source": ""}, ["body", "source"], "required"),
    ],
)  # fmt: skip
def test_bad_zone_is_named_and_changes_nothing(
    api: SalesApi, zone: dict[str, Any], loc: list[Any], rule: str
) -> None:
    before = version(api)
    response = admin(api, "put", "/api/v1/actuators/FHA-25C-50-L/zone", json=zone)
    assert response.status_code == 422
    errors = response.json()["detail"]
    assert any(e["loc"] == loc and rule in e["msg"] for e in errors), errors
    assert version(api) == before


def export_json(api: SalesApi) -> dict[str, Any]:
    response = admin(api, "get", "/api/v1/catalogue/export", params={"format": "json"})
    assert response.status_code == 200
    result: dict[str, Any] = response.json()
    return result


def export_zip(api: SalesApi) -> dict[str, str]:
    response = admin(api, "get", "/api/v1/catalogue/export")
    assert response.status_code == 200
    assert response.headers["content-type"] == "application/zip"
    with zipfile.ZipFile(io.BytesIO(response.content)) as archive:
        return {name: archive.read(name).decode("utf-8") for name in archive.namelist()}


def zipped(files: dict[str, str]) -> bytes:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        for name, text in files.items():
            archive.writestr(f"catalogue/{name}", text)
    return buffer.getvalue()


def import_(api: SalesApi, body: bytes, media_type: str, *, dry_run: bool = False) -> Any:
    return admin(
        api,
        "post",
        "/api/v1/catalogue/import",
        params={"dry_run": str(dry_run).lower()},
        content=body,
        headers={"Content-Type": media_type},
    )


def unchanged(files: dict[str, Any]) -> bool:
    return all(c["inserted"] == c["updated"] == c["retired"] == 0 for c in files.values())


def test_export_is_the_seed_format_and_imports_unchanged(api: SalesApi) -> None:
    files = export_zip(api)
    assert set(files) == {spec.file for spec in CATALOGUE_SPECS}
    assert set(files) == {p.name for p in SEED_DIR.glob("*.csv")} - {"example_prices.csv"}
    for name, text in files.items():
        seed = (SEED_DIR / name).read_text(encoding="utf-8")
        assert text.splitlines()[0] == seed.splitlines()[0]
        assert _rows(text) == _rows(seed), name
    seed_rows = sum(1 for _ in csv.DictReader(io.StringIO(files["actuators.csv"])))
    assert seed_rows == len(api.get("/api/v1/actuators", role=None).json()["actuators"])
    before = version(api)
    response = import_(api, zipped(files), "application/zip")
    assert response.status_code == 200, response.text
    assert unchanged(response.json()["files"])
    assert response.json()["files"]["actuators.csv"]["unchanged"] == seed_rows
    as_json = import_(api, _json(export_json(api)), "application/json")
    assert as_json.status_code == 200, as_json.text
    assert unchanged(as_json.json()["files"])
    assert version(api) == before


def _rows(text: str) -> list[list[tuple[str, str]]]:
    """The rows of a CSV text in any order, numbers compared as numbers (0.86 = .86)."""

    def cell(value: str) -> str:
        try:
            return repr(float(value))
        except ValueError:
            return value

    return sorted([(k, cell(v)) for k, v in r.items()] for r in csv.DictReader(io.StringIO(text)))


def _json(document: dict[str, Any]) -> bytes:
    return json.dumps(document).encode()


def edited(files: dict[str, str]) -> dict[str, str]:
    """CHA-20A-30 gets T_max 28 Nm, CHA-20A-50 is left out, FHA-25C-50-L gets a zone."""
    rows = list(csv.DictReader(io.StringIO(files["actuators.csv"])))
    for row in rows:
        if row["model"] == "CHA-20A-30":
            row["max_torque_nm"] = "28"
    rows = [r for r in rows if r["model"] != "CHA-20A-50"]
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=list(rows[0]), lineterminator="\n")
    writer.writeheader()
    writer.writerows(rows)
    zones = files["zone_points.csv"] + "FHA-25C-50-L,0,60,test\nFHA-25C-50-L,90,40,test\n"
    interfaces = "".join(
        line
        for line in files["actuator_interfaces.csv"].splitlines(keepends=True)
        if not line.startswith("CHA-20A-50,")
    )
    return {
        **files,
        "actuators.csv": out.getvalue(),
        "zone_points.csv": zones,
        "actuator_interfaces.csv": interfaces,
    }


def test_dry_run_reports_and_changes_nothing_then_import_applies(api: SalesApi) -> None:
    files = edited(export_zip(api))
    before = version(api)
    nothing = {"inserted": 0, "updated": 0, "retired": 0}
    expected = {
        **{spec.file: nothing for spec in CATALOGUE_SPECS},
        "actuators.csv": {"inserted": 0, "updated": 1, "retired": 1},
        "zone_points.csv": {"inserted": 2, "updated": 0, "retired": 0},
    }
    dry = import_(api, zipped(files), "application/zip", dry_run=True)
    assert dry.status_code == 200, dry.text
    assert dry.json()["dry_run"] is True
    assert {
        f: {k: v for k, v in c.items() if k != "unchanged"} for f, c in dry.json()["files"].items()
    } == expected
    assert dry.json()["catalogue_version"] == before
    assert version(api) == before
    assert api.get("/api/v1/actuators/CHA-20A-30", role=None).json()["max_torque_nm"] == 27
    assert "CHA-20A-50" in {a["model"] for a in export_json(api)["actuators"]}

    done = import_(api, zipped(files), "application/zip")
    assert done.status_code == 200
    assert done.json()["files"] == dry.json()["files"]
    assert done.json()["catalogue_version"] == before + 1
    assert api.get("/api/v1/actuators/CHA-20A-30", role=None).json()["max_torque_nm"] == 28
    assert "CHA-20A-50" not in {a["model"] for a in export_json(api)["actuators"]}
    zone = api.get("/api/v1/actuators/FHA-25C-50-L", role=None).json()["continuous_duty_zone"]
    assert zone == [{"speed_rpm": 0, "torque_nm": 60}, {"speed_rpm": 90, "torque_nm": 40}]


def test_a_bad_row_imports_nothing_and_is_named(api: SalesApi) -> None:
    files = edited(export_zip(api))
    # The last file is wrong: the earlier (valid) files must not be written either.
    files["zone_points.csv"] += "FHA-25C-50-L,45,-3,test\n"
    line = len(files["zone_points.csv"].splitlines())
    before = version(api)
    response = import_(api, zipped(files), "application/zip")
    assert response.status_code == 422
    errors = response.json()["detail"]
    assert {
        "loc": ["body", "zone_points.csv", line, "torque_nm"],
        "file": "zone_points.csv",
        "line": line,
        "column": "torque_nm",
    }.items() <= errors[0].items()
    assert "≥ 0" in errors[0]["msg"]
    assert version(api) == before
    assert api.get("/api/v1/actuators/CHA-20A-30", role=None).json()["max_torque_nm"] == 27


def test_cross_file_problems_are_named(api: SalesApi) -> None:
    files = export_zip(api)
    files["zone_points.csv"] += "NOPE-1,0,1,test\nNOPE-1,10,1,test\n"
    errors = import_(api, zipped(files), "application/zip").json()["detail"]
    assert any(e["file"] == "zone_points.csv" and e["column"] == "actuator_model" for e in errors)


@pytest.mark.parametrize(
    ("body", "media_type", "status", "text"),
    [
        (b"not a zip", "application/zip", 422, "ZIP"),
        (b"[1, 2]", "application/json", 422, "JSON object"),
        (b"{", "application/json", 422, "JSON object"),
        (b'{"families": [], "actuators": {}, "zone_points": []}', "application/json", 422,
         "array of objects"),
        (b"model\n", "text/csv", 415, "application/zip"),
    ],
)  # fmt: skip
def test_bad_uploads(api: SalesApi, body: bytes, media_type: str, status: int, text: str) -> None:
    response = import_(api, body, media_type)
    assert response.status_code == status
    assert text in str(response.json()["detail"])


def test_missing_file_in_the_zip(api: SalesApi) -> None:
    files = export_zip(api)
    del files["families.csv"]
    errors = import_(api, zipped(files), "application/zip").json()["detail"]
    assert errors[0]["file"] == "families.csv"
    assert "missing" in errors[0]["msg"]


def test_json_import_names_array_and_index(api: SalesApi) -> None:
    document = export_json(api)
    document["actuators"][3]["max_speed_rpm"] = -1
    errors = import_(api, _json(document), "application/json").json()["detail"]
    assert errors[0]["loc"] == ["body", "actuators", 3, "max_speed_rpm"]
