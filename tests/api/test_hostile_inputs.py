"""Hostile and absurd inputs: each a clear 4xx naming the field and the rule, never a 500
and never a half-written record. Run on SQLite and PostgreSQL (``client``/``api`` fixtures).
"""

from __future__ import annotations

import io
import struct
import zipfile
from typing import Any

import pytest
from fastapi.testclient import TestClient
from tests import worked_example
from tests.api._sales_fixtures import SalesApi, api, sales_api_with
from tests.api.test_admin import (
    NEW,
    ZONE,
    admin,
    export_zip,
    import_,
    unchanged,
    version,
    zipped,
)

from actuator_selection.schemas.batch import MAX_BATCH_CASES

__all__ = ["api", "sales_api_with"]

CYCLE = {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0}
DAY = {"accel_s": 86_400, "constant_s": 86_400, "decel_s": 86_400, "pause_s": 0}
SCREW: dict[str, Any] = {
    "type": "ball_screw",
    "speed_rpm": 40,
    "mass_kg": 100,
    "lead_m": 0.01,
    "friction_coefficient": 0.1,
    "efficiency": 0.9,
}


def only_error(response: Any, status: int = 422) -> dict[str, Any]:
    """The single entry of an error body in the house shape."""
    assert response.status_code == status, response.text
    (error,) = response.json()["detail"]
    assert set(error) >= {"loc", "msg", "type"}
    return dict(error)


def selection(client: TestClient, load: dict[str, Any], cycle: dict[str, Any]) -> Any:
    body = {"load": load, "cycle": cycle, "models": ["FHA-25C-50-L"]}
    return client.post("/api/v1/selections", json=body)


# 1. Physical lower bounds: no overflow, no Infinity, no load that underflows to zero.


@pytest.mark.parametrize(
    ("changes", "cycle", "field", "rule"),
    [
        ({"efficiency": 1e-300}, CYCLE, "efficiency", "greater than or equal to 0.01"),
        ({"efficiency": 1e-152}, DAY, "efficiency", "greater than or equal to 0.01"),
        ({"efficiency": 0.0099}, CYCLE, "efficiency", "greater than or equal to 0.01"),
        ({"lead_m": 5e-324}, CYCLE, "lead_m", "greater than or equal to 0.000001"),
    ],
)
def test_absurd_ball_screw_is_refused(
    client: TestClient, changes: dict[str, Any], cycle: dict[str, Any], field: str, rule: str
) -> None:
    error = only_error(selection(client, {**SCREW, **changes}, cycle))
    assert error["loc"] == ["body", "load", field]
    assert rule in error["msg"]


def test_rotary_table_diameter_has_a_lower_bound(client: TestClient) -> None:
    table = {
        "type": "rotary_table",
        "speed_rpm": 10,
        "mass_kg": 50,
        "diameter_m": 5e-324,
        "friction_coefficient": 0.02,
        "friction_radius_m": 0.15,
    }
    error = only_error(selection(client, table, CYCLE))
    assert error["loc"] == ["body", "load", "diameter_m"]


def test_worst_case_inside_the_bounds_is_finite_and_stored(client: TestClient) -> None:
    """Every bound at its extreme at once: the README's promise of finite results holds, and
    the selection stores (PostgreSQL refuses Infinity in JSON) and reads back."""
    load = {
        "type": "ball_screw",
        "speed_rpm": 100_000,
        "mass_kg": 1_000_000,
        "lead_m": 100,
        "friction_coefficient": 10,
        "efficiency": 0.01,
        "screw_inertia_kgm2": 1_000_000,
    }
    cycle = {"accel_s": 1e-4, "constant_s": 86_400, "decel_s": 1e-4, "pause_s": 86_400}
    response = selection(client, load, cycle)
    assert response.status_code == 201, response.text
    body = response.json()
    (candidate,) = body["candidates"]
    for name in ("accel_torque_nm", "decel_torque_nm", "rms_torque_nm"):
        assert isinstance(candidate[name], float), name
    assert client.get(f"/api/v1/selections/{body['id']}").json() == body
    # The smallest lead and efficiency allowed give a load that is small, not zero.
    small = {**SCREW, "lead_m": 1e-6, "efficiency": 0.01}
    resolved = selection(client, small, CYCLE).json()["load"]
    assert resolved["torque_nm"] > 0
    assert resolved["inertia_kgm2"] > 0


# 2. Location headers: a model is percent-encoded in its URL.


def test_location_of_a_model_is_percent_encoded(api: SalesApi) -> None:
    """Models are ASCII letters and digits joined by - . _ + (``MODEL_NAME``): a non-Latin-1
    model such as "FHA-Ω" is refused (test_hostile_corpus.py), "+" is escaped."""
    response = admin(api, "post", "/api/v1/actuators", json={**NEW, "model": "FHA-25C+B"})
    assert response.status_code == 201, response.text
    location = response.headers["location"]
    assert location == "/api/v1/actuators/FHA-25C%2BB"
    assert api.get(location, role=None).json()["model"] == "FHA-25C+B"


# 9. The batch's size is checked before its cases are validated.


def test_too_many_batch_cases_are_refused_at_once(client: TestClient) -> None:
    case = {**worked_example.request(), "high_dynamics": True}
    bad = worked_example.request()
    bad["load"]["torque_nm"] = -1  # would be an error of its own, were the cases validated
    body = {"cases": [case] * MAX_BATCH_CASES + [bad], "top": 1}
    response = client.post("/api/v1/selections/batch", json=body)
    # Only the count is named: the cases were not validated one by one (that took ~3.4 s).
    error = only_error(response)
    assert error["loc"] == ["body", "cases"]
    assert f"at most {MAX_BATCH_CASES} cases" in error["msg"]
    assert f"got {MAX_BATCH_CASES + 1}" in error["msg"]


# 7. Strict JSON types: a boolean is no number, a number no boolean, text no number.


@pytest.mark.parametrize(
    ("path", "value", "loc"),
    [
        (("load", "speed_rpm"), True, ["body", "load", "speed_rpm"]),
        (("load", "torque_nm"), "5", ["body", "load", "torque_nm"]),
        (("cycle", "accel_s"), False, ["body", "cycle", "accel_s"]),
        (("high_dynamics",), "yes", ["body", "high_dynamics"]),
        (("high_dynamics",), 1, ["body", "high_dynamics"]),
        (("high_dynamics",), "true", ["body", "high_dynamics"]),
        (("models",), [25], ["body", "models", 0]),
    ],
)
def test_json_types_are_strict(
    client: TestClient, path: tuple[str, ...], value: Any, loc: list[str | int]
) -> None:
    body: dict[str, Any] = {**worked_example.request(), "models": ["FHA-25C-50-L"]}
    target = body
    for key in path[:-1]:
        target = target[key]
    target[path[-1]] = value
    error = only_error(client.post("/api/v1/selections", json=body))
    assert error["loc"] == loc
    assert error["type"] in {"float_type", "bool_type", "string_type"}


def test_integers_stay_numbers(client: TestClient) -> None:
    """Existing clients send 40 for 40.0: strictness must not refuse a JSON integer."""
    body = {**worked_example.request(), "models": ["FHA-25C-50-L"], "high_dynamics": False}
    assert client.post("/api/v1/selections", json=body).status_code == 201
    tools = client.post(
        "/api/v1/tools/sensor-temperature", json={"sensor": "KTY84-130", "resistance_ohm": 1000}
    )
    assert tools.status_code == 200, tools.text
    batch = client.post("/api/v1/selections/batch", json={"cases": [body], "top": True})
    assert only_error(batch)["loc"] == ["body", "top"]


@pytest.mark.parametrize(
    ("valid_until", "rule"),
    [
        (1893456000, "YYYY-MM-DD"),
        ("9999-12-31", "at most 731 days after today"),
        ("2030-02-30", "calendar date"),
        ("20300101", "YYYY-MM-DD"),
        ("2030-01-01T00:00:00", "YYYY-MM-DD"),
    ],
)
def test_valid_until_is_a_date_string_within_two_years(
    api: SalesApi, valid_until: Any, rule: str
) -> None:
    selection_id = api.selection(["FHA-25C-50-L"])["id"]
    body = api.quote_body(selection_id, valid_until=valid_until)
    error = only_error(api.post("/api/v1/quotes", json=body))
    assert error["loc"] == ["body", "valid_until"]
    assert rule in error["msg"]
    assert api.get("/api/v1/quotes").json()["total"] == 0


def test_quote_decimals_and_dates_as_documented_still_work(api: SalesApi) -> None:
    selection_id = api.selection(["FHA-25C-50-L"])["id"]
    for discount in ("7.5", 10):
        body = api.quote_body(selection_id, discount_percent=discount)
        assert api.post("/api/v1/quotes", json=body).status_code == 201
    refused = api.post("/api/v1/quotes", json=api.quote_body(selection_id, discount_percent=True))
    assert only_error(refused)["loc"] == ["body", "discount_percent"]


# 8. Control characters and bidirectional overrides in text that reaches documents.

HOSTILE_TEXT = ["\x1b[31mred", "bell\x07", "\u202egnp.exe", "a\u2066b", "c1\x85x", "del\x7f"]


@pytest.mark.parametrize("text", HOSTILE_TEXT)
@pytest.mark.parametrize(
    ("where", "loc"),
    [
        ({"customer": {"name": "{}"}}, ["customer", "name"]),
        ({"customer": {"name": "Muster GmbH", "address": "{}"}}, ["customer", "address"]),
        ({"customer": {"name": "Muster GmbH", "reference": "{}"}}, ["customer", "reference"]),
        ({"notes": "{}"}, ["notes"]),
        ({"price_list": "{}"}, ["price_list"]),
    ],
)
def test_quote_text_refuses_controls_and_bidi(
    api: SalesApi, text: str, where: dict[str, Any], loc: list[str]
) -> None:
    selection_id = api.selection(["FHA-25C-50-L"])["id"]

    def fill(value: Any) -> Any:
        if isinstance(value, dict):
            return {k: fill(v) for k, v in value.items()}
        return text if value == "{}" else value

    body = api.quote_body(selection_id, **fill(where))
    error = only_error(api.post("/api/v1/quotes", json=body))
    assert error["loc"] == ["body", *loc]
    assert "control characters" in error["msg"]
    assert "found U+" in error["msg"]
    assert api.get("/api/v1/quotes").json()["total"] == 0


def test_line_breaks_only_where_multi_line_text_is_allowed(api: SalesApi) -> None:
    selection_id = api.selection(["FHA-25C-50-L"])["id"]
    multi = api.quote_body(
        selection_id,
        customer={"name": "Muster GmbH", "address": "Hauptstr. 1\r\n12345\tMusterstadt"},
        notes="line 1\nline 2\rline 3",
    )
    created = api.post("/api/v1/quotes", json=multi)
    assert created.status_code == 201, created.text
    assert created.json()["customer"]["address"] == "Hauptstr. 1\r\n12345\tMusterstadt"
    one_line = api.quote_body(selection_id, customer={"name": "Muster\nGmbH"})
    error = only_error(api.post("/api/v1/quotes", json=one_line))
    assert error["loc"] == ["body", "customer", "name"]
    assert "one line" in error["msg"]
    model = {**worked_example.request(), "models": ["FHA-25C-50-L\t"]}
    error = only_error(api.client.post("/api/v1/selections", json=model))
    assert error["loc"] == ["body", "models"]


@pytest.mark.parametrize(
    ("column", "text", "rule"),
    [
        ("notes", "\u202eevil", "control characters other than tab and line breaks"),
        ("source", "\x1b[2J", "control characters other than tab and line breaks"),
        ("model", "CHA-99A\u202e-50", "one line"),
        ("feedback", "enc\nder", "one line"),
    ],
)
def test_catalogue_text_refuses_controls_and_bidi(
    api: SalesApi, column: str, text: str, rule: str
) -> None:
    before = version(api)
    response = admin(api, "post", "/api/v1/actuators", json={**NEW, column: text})
    error = only_error(response)
    assert error["loc"] == ["body", column]
    assert rule in error["msg"]
    assert version(api) == before


# 3. Damaged, encrypted and exotic ZIP members of a catalogue import.

CSV_MEMBER = "families.csv"
CSV_TEXT = b"name,description,temperature_sensors,source\nX,,,s\n"


def one_member_zip() -> bytearray:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=zipfile.ZIP_STORED) as archive:
        archive.writestr(CSV_MEMBER, CSV_TEXT)
    return bytearray(buffer.getvalue())


def patched(body: bytearray, *, local: int, central: int, value: int) -> bytes:
    """Set a 16-bit field of the member's local header and its central directory entry."""
    struct.pack_into("<H", body, body.index(b"PK\x03\x04") + local, value)
    struct.pack_into("<H", body, body.index(b"PK\x01\x02") + central, value)
    return bytes(body)


def bad_crc() -> bytes:
    body = one_member_zip()
    at = body.index(CSV_TEXT)
    body[at] ^= 0x01  # one flipped bit in the stored data: the CRC-32 no longer matches
    return bytes(body)


@pytest.mark.parametrize(
    ("body", "rule"),
    [
        (bad_crc(), "is damaged in the archive"),
        (patched(one_member_zip(), local=6, central=8, value=0x1), "is encrypted"),
        (patched(one_member_zip(), local=8, central=10, value=99), "compression method 99"),
        (patched(one_member_zip(), local=8, central=10, value=6), "compression method 6"),
    ],
    ids=["bad-crc", "encrypted", "aes-method-99", "implode-method-6"],
)
def test_unreadable_zip_members_are_named(api: SalesApi, body: bytes, rule: str) -> None:
    before = version(api)
    error = only_error(import_(api, body, "application/zip"))
    assert error["loc"] == ["body", CSV_MEMBER, 0]
    assert error["file"] == CSV_MEMBER
    assert rule in error["msg"]
    assert version(api) == before


def test_damaged_archive_directory_is_named(api: SalesApi) -> None:
    body = one_member_zip()
    at = body.index(b"PK\x05\x06")
    struct.pack_into("<I", body, at + 16, 2**31)  # central directory offset beyond the file
    error = only_error(import_(api, bytes(body), "application/zip"))
    assert error["loc"] == ["body", CSV_MEMBER, 0]
    assert "is damaged in the archive" in error["msg"]
    truncated = bytes(one_member_zip()[:40])
    error = only_error(import_(api, truncated, "application/zip"))
    assert error["loc"] == ["body", "(upload)", 0]
    assert "not a ZIP archive" in error["msg"]


# 4. CSV files with CR-only line ends and with an enormous cell.


def test_cr_only_catalogue_files_read_as_lines(api: SalesApi) -> None:
    """Excel for Mac writes CR-only "CSV (Macintosh)": read as lines, not refused."""
    files = export_zip(api)
    assert all("\r" not in text for text in files.values())
    mac = {name: text.replace("\n", "\r") for name, text in files.items()}
    response = import_(api, zipped(mac), "application/zip", dry_run=True)
    assert response.status_code == 200, response.text
    assert unchanged(response.json()["files"])


def test_cr_only_price_list_reads_as_lines(api: SalesApi) -> None:
    text = (
        "price_list,is_example,item_kind,item_code,description,unit_price,currency,"
        "valid_from,valid_to,source\r"
        "CR list,false,actuator,FHA-25C-50-L,one,100.00,EUR,2026-01-01,,test\r"
        "CR list,false,actuator,FHA-14C-100,two,200.00,EUR,2026-01-01,,test\r"
    )
    response = admin(
        api,
        "post",
        "/api/v1/price-lists/import",
        params={"dry_run": "true"},
        content=text.encode(),
        headers={"Content-Type": "text/csv"},
    )
    assert response.status_code == 200, response.text
    assert response.json()["price_lists"]["CR list"]["inserted"] == 2


def test_an_enormous_price_cell_is_named(api: SalesApi) -> None:
    text = (
        "price_list,is_example,item_kind,item_code,description,unit_price,currency,"
        "valid_from,valid_to,source\n"
        "Big,false,actuator,FHA-25C-50-L,one,100.00,EUR,2026-01-01,,test\n"
        f"Big,false,actuator,FHA-14C-100,{'x' * 200_000},200.00,EUR,2026-01-01,,test\n"
    )
    response = admin(
        api,
        "post",
        "/api/v1/price-lists/import",
        content=text.encode(),
        headers={"Content-Type": "text/csv"},
    )
    error = only_error(response)
    assert error["loc"] == ["body", "prices.csv", 3]
    assert "longer than 131072 characters" in error["msg"]
    assert "Big" not in {p["name"] for p in api.get("/api/v1/price-lists", "admin").json()}


def test_an_enormous_catalogue_cell_is_named(api: SalesApi) -> None:
    files = export_zip(api)
    lines = files["families.csv"].splitlines(keepends=True)
    lines.insert(2, f"Huge,{'x' * 200_000},,s\n")
    files["families.csv"] = "".join(lines)
    before = version(api)
    errors = import_(api, zipped(files), "application/zip").json()["detail"]
    assert [e["loc"] for e in errors] == [["body", "families.csv", 3]]
    assert "longer than 131072 characters" in errors[0]["msg"]
    assert version(api) == before


# 5 and 6. Export quotes every line break and neutralises formulas; import undoes both.

AWKWARD_CONTROLLER: dict[str, Any] = {
    "manufacturer": "ACME",
    "type": "X-1",
    "variant": "-A",
    "cha_chm": "tested",
    "correction": '=HYPERLINK("http://example.invalid","click")',
    "source": "bare CR\rbare LF\nCRLF\r\nend",
}
AWKWARD_ACTUATOR: dict[str, Any] = {
    **NEW,
    "supply_voltage": "-5 V",
    "feedback": "@SUM(A1)",
    "notes": "'quoted, and a tab\there",
    "source": "+49 30 1234\rsecond line",
}


def test_awkward_cells_round_trip_through_export_and_import(api: SalesApi) -> None:
    created = admin(api, "post", "/api/v1/controllers", json=AWKWARD_CONTROLLER)
    assert created.status_code == 201, created.text
    row = created.json()["source_row"]
    assert created.json()["source"] == AWKWARD_CONTROLLER["source"]
    assert admin(api, "post", "/api/v1/actuators", json=AWKWARD_ACTUATOR).status_code == 201
    before = version(api)

    files = export_zip(api)
    controllers = files["controllers.csv"]
    assert '"bare CR\rbare LF\nCRLF\r\nend"' in controllers  # every line break quoted
    assert ",'-A," in controllers
    assert '"\'=HYPERLINK(""http://example.invalid"",""click"")"' in controllers
    actuators = files["actuators.csv"]
    assert "'-5 V" in actuators
    assert "'@SUM(A1)" in actuators
    assert "''quoted" in actuators
    assert '"\'+49 30 1234\rsecond line"' in actuators
    assert "\n-40," in files["kty84_130.csv"]  # numbers are not text: no quote mark

    dry = import_(api, zipped(files), "application/zip", dry_run=True)
    assert dry.status_code == 200, dry.text
    assert unchanged(dry.json()["files"])
    done = import_(api, zipped(files), "application/zip")
    assert done.status_code == 200, done.text
    assert unchanged(done.json()["files"])
    assert version(api) == before
    stored = api.get(f"/api/v1/controllers/{row}", role=None).json()
    assert (stored["variant"], stored["correction"], stored["source"]) == (
        "-A",
        AWKWARD_CONTROLLER["correction"],
        AWKWARD_CONTROLLER["source"],
    )
    actuator = api.get("/api/v1/actuators/CHA-99A-50", role=None).json()
    for column in ("supply_voltage", "feedback", "notes", "source"):
        assert actuator[column] == AWKWARD_ACTUATOR[column], column


def test_json_export_carries_text_as_it_is(api: SalesApi) -> None:
    assert admin(api, "post", "/api/v1/actuators", json=AWKWARD_ACTUATOR).status_code == 201
    exported = admin(api, "get", "/api/v1/catalogue/export", params={"format": "json"}).json()
    (row,) = [a for a in exported["actuators"] if a["model"] == "CHA-99A-50"]
    assert row["feedback"] == "@SUM(A1)"
    assert row["notes"] == "'quoted, and a tab\there"


def test_zone_source_follows_the_free_text_rule(api: SalesApi) -> None:
    path = "/api/v1/actuators/FHA-25C-50-L/zone"
    multi = admin(api, "put", path, json={**ZONE, "source": "read from\nFig. 517.1"})
    assert multi.status_code == 200, multi.text
    assert multi.json()["continuous_duty_zone_source"] == "read from\nFig. 517.1"
    error = only_error(admin(api, "put", path, json={**ZONE, "source": "\u202eevil"}))
    assert error["loc"] == ["body", "source"]
    assert "found U+202E" in error["msg"]


@pytest.mark.parametrize("value", [1e-300, 5e-324, 1e-10])
def test_vanishing_catalogue_numbers_are_refused(api: SalesApi, value: float) -> None:
    """T_max = 1e-300 made the peak-torque margin infinite, which no database stores."""
    response = admin(api, "post", "/api/v1/actuators", json={**NEW, "max_torque_nm": value})
    assert response.status_code == 422, response.text
    (entry,) = response.json()["detail"]
    assert entry["loc"] == ["body", "max_torque_nm"]
    assert "must be 0 or at least 1e-09 in size" in entry["msg"]


def test_the_smallest_allowed_catalogue_number_gives_finite_results(
    api: SalesApi,
) -> None:
    tiny = {**NEW, "max_torque_nm": 1e-9, "inertia_kgm2": 1e-9, "stall_torque_nm": 1e-9}
    assert admin(api, "post", "/api/v1/actuators", json=tiny).status_code == 201
    body = {**worked_example.request(), "models": [NEW["model"]]}
    response = api.client.post("/api/v1/selections", json=body)
    assert response.status_code == 201, response.text
    stored = api.client.get(f"/api/v1/selections/{response.json()['id']}")
    assert stored.json() == response.json()
