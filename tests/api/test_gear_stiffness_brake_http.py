"""Issue 28, items 7–9 over HTTP: gear ratings imported by an administrator (CSV) with
their source, then the gear, stiffness and brake checks in the candidate detail, the
batch (==) and the engineering report, each with its reference; hand calculations from
first principles.

THE GEAR RATINGS BELOW ARE TEST VALUES, MADE UP: no public document gives them for any
catalogue actuator (docs/catalogue-data/gear-ratings.csv).
"""

from __future__ import annotations

import csv
import io
import math
from typing import Any

import pytest
from tests.api._sales_fixtures import SalesApi, api, sales_api_with
from tests.api.test_admin import admin, export_zip, import_, zipped

__all__ = ["api", "sales_api_with"]

API = "/api/v1/selections"
TEST_RATINGS = {  # TEST VALUES, MADE UP (not catalogue data)
    "gear_average_torque_limit_nm": "60",
    "gear_repeated_peak_torque_nm": "120",
    "gear_momentary_peak_torque_nm": "200",
    "gear_momentary_peak_count": "1000",
    "gear_average_input_speed_limit_rpm": "3000",
    "gear_rated_torque_nm": "40",
    "gear_rated_life_h": "10000",
    "gear_life_basis": "L50",
}
N, T1, T2, T3, TP, T_L, J_L = 30.0, 0.2, 1.0, 0.2, 1.0, 40.0, 2.0
BODY: dict[str, Any] = {
    "load": {"speed_rpm": N, "torque_nm": T_L, "inertia_kgm2": J_L},
    "cycle": {"accel_s": T1, "constant_s": T2, "decel_s": T3, "pause_s": TP},
    "models": ["CHA-25A-50", "CHA-20A-50"],
    "brake": True,
    "emergency_stops": 150,
    "min_natural_frequency_hz": 15,
    "gear": {"required_life_h": 20000},
}


def import_test_ratings(api: SalesApi) -> None:
    files = export_zip(api)
    text = files["actuators.csv"]
    reader = csv.DictReader(io.StringIO(text))
    out = io.StringIO()
    writer = csv.DictWriter(out, fieldnames=reader.fieldnames or [], lineterminator="\n")
    writer.writeheader()
    for row in reader:
        if row["model"] == "CHA-25A-50":
            row |= TEST_RATINGS
            row["source"] += "; gear ratings: TEST VALUES, made up by tests/api (not published)"
        writer.writerow(row)
    files["actuators.csv"] = out.getvalue()
    response = import_(api, zipped(files), "application/zip")
    assert response.status_code == 200, response.text


def test_imported_ratings_are_checked_and_the_batch_agrees(api: SalesApi) -> None:
    import_test_ratings(api)
    row = api.get("/api/v1/actuators/CHA-25A-50", role=None).json()
    assert row["gear_rated_life_h"] == 10000
    assert row["torsional_stiffness_k1_nm_per_rad"] == 25000  # CHA manual p. 50
    assert row["brake_emergency_stop_count"] == 200
    assert row["brake_closing_time_s"] == pytest.approx(0.07)
    response = admin(api, "post", API, json=BODY)
    assert response.status_code == 201, response.text
    answer = response.json()
    detail = admin(api, "get", f"{API}/{answer['id']}/candidates/CHA-25A-50").json()
    checks = {c["name"]: c for c in detail["checks"]}
    # First principles: J_A of CHA-25A-50 from its catalogue row; Eq. 514.1, 514.3.
    j_a = row["inertia_kgm2"]
    alpha = N * 2 * math.pi / 60 / T1
    t_acc, t_dec = T_L + (j_a + J_L) * alpha, T_L - (j_a + J_L) * alpha
    w_ramp, w_run = N / 2 * T1, N * T2
    t_av = (w_ramp * (abs(t_acc) ** 3 + abs(t_dec) ** 3) + w_run * T_L**3) / (2 * w_ramp + w_run)
    t_av **= 1 / 3
    n_in = 50 * (2 * w_ramp + w_run) / (T1 + T2 + T3 + TP)
    assert checks["gear_average_torque"]["value"] == pytest.approx(t_av, rel=1e-12)
    assert checks["gear_average_torque"]["status"] == ("pass" if t_av <= 60 else "fail")
    assert checks["gear_input_speed"]["value"] == pytest.approx(n_in, rel=1e-12)
    life = 10000 * (40 / t_av) ** 3 * (2000 / n_in)
    assert checks["gear_life"]["status"] == ("pass" if life >= 20000 else "fail")
    assert f"L_50 = {life:.4g} h" in checks["gear_life"]["message"]
    assert "1019659" in checks["gear_life"]["reference"]
    f_n = math.sqrt(25000 / J_L) / (2 * math.pi)
    assert checks["natural_frequency"]["limit"] == pytest.approx(f_n, rel=1e-12)
    assert checks["natural_frequency"]["status"] == "pass"  # 17.8 Hz ≥ 15 Hz
    assert (
        checks["brake_emergency_stops"]["status"],
        checks["brake_emergency_stops"]["limit"],
    ) == (
        "pass",
        200,
    )
    # CHA-20A-50: no gear ratings, no emergency-stop count published: no data
    other = admin(api, "get", f"{API}/{answer['id']}/candidates/CHA-20A-50").json()
    other_checks = {c["name"]: c for c in other["checks"]}
    assert other_checks["gear_average_torque"]["status"] == "no_data"
    assert other_checks["brake_emergency_stops"]["status"] == "no_data"
    # the batch gives the same checks, number for number
    batch = admin(
        api, "post", f"{API}/batch", json={"cases": [BODY], "top": 2, "include_messages": True}
    )
    assert batch.status_code == 200, batch.text
    (result,) = batch.json()["results"]
    got = {c["model"]: c for c in result["candidates"]}
    assert got["CHA-25A-50"]["checks"] == detail["checks"]
    assert got["CHA-20A-50"]["checks"] == other["checks"]
    # the report lists them
    report = admin(api, "get", f"{API}/{answer['id']}/report.csv").text
    for name in ("gear_average_torque", "gear_life", "natural_frequency", "brake_emergency_stops"):
        assert name in report or checks[name]["reference"] in report, name


def test_without_asking_no_gear_check_runs(api: SalesApi) -> None:
    body = {k: v for k, v in BODY.items() if k not in ("gear", "min_natural_frequency_hz")}
    body.pop("emergency_stops")
    answer = admin(api, "post", API, json=body).json()
    detail = admin(api, "get", f"{API}/{answer['id']}/candidates/CHA-25A-50").json()
    names = {c["name"] for c in detail["checks"]}
    assert not names & {"gear_average_torque", "natural_frequency", "brake_emergency_stops"}


@pytest.mark.parametrize(
    ("change", "field"),
    [
        ({"brake_safety_factor": 0.5}, "brake_safety_factor"),
        ({"gear": {"momentary_torque_nm": 100}}, "momentary_count"),
        ({"min_natural_frequency_hz": -1}, "min_natural_frequency_hz"),
    ],
)
def test_bad_inputs_are_4xx_naming_the_field(
    api: SalesApi, change: dict[str, Any], field: str
) -> None:
    response = admin(api, "post", API, json=BODY | change)
    assert 400 <= response.status_code < 500, response.text
    assert field in response.text
