"""POST /selections (and the batch) with the optional output load and drive sizing: the
bearing checks appear only with an output load, the drive checks only when asked, and
bad output load values are a 422 naming the field. Runs on the seeded catalogue."""

from __future__ import annotations

import math
from typing import Any

import pytest
from fastapi.testclient import TestClient

BODY: dict[str, Any] = {
    "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
    "models": ["CHA-25A-50", "FHA-14C-50", "FHA-25C-50"],
}
LOAD = {
    "radial_force_n": 1000,
    "axial_force_n": 500,
    "radial_lever_m": 0.05,
    "axial_lever_m": 0.02,
    "required_life_h": 20000,
}
BEARING = {"bearing_moment", "bearing_static_safety", "bearing_life"}
DRIVE = {"drive_current"}
"""The checks ``drive`` adds; the output voltage (drive_voltage) is checked always."""


def post(client: TestClient, body: dict[str, Any]) -> Any:
    return client.post("/api/v1/selections", json=body)


def detail(client: TestClient, selection: str, model: str) -> dict[str, Any]:
    response = client.get(f"/api/v1/selections/{selection}/candidates/{model}")
    assert response.status_code == 200
    result: dict[str, Any] = response.json()
    return result


def test_output_load_omitted_means_no_bearing_check(client: TestClient) -> None:
    response = post(client, BODY)
    assert response.status_code == 201
    answer = response.json()
    names = {r["name"] for r in answer["check_rules"]}
    assert not names & BEARING
    assert not names & DRIVE
    assert answer["output_load"] is None
    assert answer["output_bearing"] == "not checked: no output_load given"
    assert answer["output_bearing_code"] == "output_bearing.not_checked"
    for candidate in answer["candidates"]:
        assert not {c["name"] for c in candidate["checks"]} & BEARING


def test_output_load_and_drive_add_their_checks(client: TestClient) -> None:
    response = post(client, {**BODY, "output_load": LOAD, "drive": True})
    assert response.status_code == 201
    answer = response.json()
    names = [r["name"] for r in answer["check_rules"]]
    assert names[-8:] == [
        "drive_voltage",
        "drive_current",
        "bearing_moment",
        "bearing_static_safety",
        "bearing_radial_force",
        "bearing_axial_force",
        "bearing_fretting",
        "bearing_life",
    ]
    assert answer["output_bearing"] == "tilting moment, static safety and L_10 life checked"
    assert answer["output_bearing_code"] == "output_bearing.checked"
    assert answer["output_load"]["radial_force_n"] == 1000
    mini = {c["name"]: c for c in detail(client, answer["id"], "FHA-14C-50")["checks"]}
    # FHA-14C: R = 14 mm (FHA-C mini manual Table 1), moment capacity 75 Nm.
    assert mini["bearing_moment"]["value"] == pytest.approx(1000 * 0.064 + 500 * 0.02)
    assert mini["bearing_moment"]["limit"] == 75
    assert mini["bearing_moment"]["reference"].startswith("CHA §4.3; FHA-C manual ch. 2")
    # FHA-25C: R = 18 mm (FHA-C manual §2-3, Table 1), allowable moment 370 Nm (§1-4-2);
    # no pole pairs, no V_rms K_E: the drive voltage has no data.
    fha = {c["name"]: c for c in detail(client, answer["id"], "FHA-25C-50")["checks"]}
    assert fha["bearing_moment"]["value"] == pytest.approx(1000 * (0.05 + 0.018) + 500 * 0.02)
    assert fha["bearing_moment"]["limit"] == 370
    assert fha["bearing_moment"]["status"] == "pass"
    assert fha["drive_voltage"]["status"] == "no_data"
    cha = {c["name"]: c for c in detail(client, answer["id"], "CHA-25A-50")["checks"]}
    assert cha["drive_voltage"]["status"] in {"pass", "fail"}
    motor_rpm = 40 * 50
    full = math.hypot(motor_rpm * 0.037 + 4.0 * 3.7, 2 * math.pi * motor_rpm / 60 * 6 * 6e-3 * 4.0)
    assert cha["drive_voltage"]["value"] == pytest.approx(full, rel=1e-12)
    assert cha["drive_voltage"]["limit"] == pytest.approx(560 / math.sqrt(2))
    assert cha["drive_current"]["limit"] == 4.0


@pytest.mark.parametrize(
    ("field", "value"),
    [
        ("radial_force_n", -1),
        ("axial_lever_m", "far"),
        ("load_factor", 0.5),
        ("required_life_h", 0),
        ("unknown", 1),
    ],
)
def test_bad_output_load_is_a_422_naming_the_field(
    client: TestClient, field: str, value: Any
) -> None:
    response = post(client, {**BODY, "output_load": {**LOAD, field: value}})
    assert response.status_code == 422
    locs = [e["loc"] for e in response.json()["detail"]]
    assert ["body", "output_load", field] in locs


def test_missing_output_load_field_is_a_422(client: TestClient) -> None:
    load = {k: v for k, v in LOAD.items() if k != "radial_lever_m"}
    response = post(client, {**BODY, "output_load": load})
    assert response.status_code == 422
    assert ["body", "output_load", "radial_lever_m"] in [
        e["loc"] for e in response.json()["detail"]
    ]


def test_batch_groups_cases_by_their_checks(client: TestClient) -> None:
    cases = [BODY, {**BODY, "output_load": LOAD}, {**BODY, "drive": True}]
    response = client.post("/api/v1/selections/batch", json={"cases": cases, "top": 3})
    assert response.status_code == 200, response.text


@pytest.mark.slow
def test_cha_bearing_forces_are_not_applicable_single_batch_and_report(
    client: TestClient,
) -> None:
    """The CHA manual rates its output bearing by C, C_0, M_dyn and M_0 (1018854 12/2015,
    Table 51.1), the FHA-C manual by allowable radial and axial loads too (§1-4-2): the
    force checks do not apply to CHA (they passed at 0 ≤ 0 before, decision 0025), neither
    passing nor failing the verdict, in the answer, the detail, the batch (==) and the
    report; FHA-25C-50 is judged against its 4.9 kN and 14.7 kN."""
    body = {**BODY, "output_load": LOAD}
    response = post(client, body)
    assert response.status_code == 201, response.text
    answer = response.json()
    lean = {c["model"]: {k["name"]: k for k in c["checks"]} for c in answer["candidates"]}
    for name in ("bearing_radial_force", "bearing_axial_force"):
        assert lean["CHA-25A-50"][name] == {
            "name": name,
            "status": "not_applicable",
            "value": None,
            "limit": None,
        }
    fha = lean["FHA-25C-50"]
    assert (fha["bearing_radial_force"]["status"], fha["bearing_radial_force"]["limit"]) == (
        "pass",
        4900,
    )
    assert (fha["bearing_axial_force"]["value"], fha["bearing_axial_force"]["limit"]) == (
        500,
        14700,
    )
    cha = next(c for c in answer["candidates"] if c["model"] == "CHA-25A-50")
    others = {c["status"] for c in cha["checks"]} - {"not_applicable"}
    expected = (
        "unsuitable" if "fail" in others else "unconfirmed" if "no_data" in others else "suitable"
    )
    assert cha["verdict"] == expected
    detail_en = detail(client, answer["id"], "CHA-25A-50")
    said = {c["name"]: c for c in detail_en["checks"]}["bearing_radial_force"]["message"]
    assert "load ratings C and C_0" in said
    assert said not in detail_en["reasons"]
    german = client.get(
        f"/api/v1/selections/{answer['id']}/candidates/CHA-25A-50",
        headers={"Accept-Language": "de"},
    ).json()
    assert {c["name"]: c for c in german["checks"]}["bearing_radial_force"]["status"] == (
        "not_applicable"
    )
    # the batch answers the same checks, number for number
    batch = client.post(
        "/api/v1/selections/batch",
        json={"cases": [body], "top": 3, "include_messages": True},
    )
    assert batch.status_code == 200, batch.text
    (result,) = batch.json()["results"]
    for candidate in result["candidates"]:
        single = detail(client, answer["id"], candidate["model"])
        assert candidate["checks"] == single["checks"]
    report = client.get(f"/api/v1/selections/{answer['id']}/report.csv")
    assert report.status_code == 200
    assert "not_applicable" in report.text or "not applicable" in report.text
    for language in ("en", "de"):
        pdf = client.get(
            f"/api/v1/selections/{answer['id']}/report.pdf", headers={"Accept-Language": language}
        )
        assert pdf.status_code == 200, pdf.text


def test_a_stored_check_that_does_not_apply_is_no_reason_in_the_quote_document() -> None:
    """The quote document's row says "not applicable" ("nicht anwendbar"), and the check
    is not among the reasons a quote is unconfirmed."""
    from actuator_selection.documents.quote_document import _check_row
    from actuator_selection.documents.quote_document_text import DocumentText, Language
    from actuator_selection.schemas.quotes import StoredCheck

    check = StoredCheck(
        name="bearing_radial_force", status="not_applicable", value=None, limit=None, unit="N"
    )
    assert not check.open
    languages: tuple[tuple[Language, str], ...] = (
        ("en", "not applicable"),
        ("de", "nicht anwendbar"),
    )
    for language, word in languages:
        row = _check_row(check, DocumentText(language), language)
        assert row["status_label"] == word
    failed = StoredCheck(name="max_speed", status="fail", value=100, limit=90, unit="rpm")
    assert failed.open
