"""The values of the second audit of public copies, as GET /actuators/{model} shows them.

Each expected number is the one printed in the public document the row cites (CHA
Engineering Data 1018854; Harmonic Drive LLC FHA-C and FHA-C mini manuals); a value no
public source gives is ``null``. Harmonic Drive AG's FHA-25C-50-L (the chapter's row) and
the LLC's FHA-25C-50 are different product rows: nothing moves from one to the other.
"""

from __future__ import annotations

from typing import Any

import pytest
from fastapi.testclient import TestClient

NEW_VALUES = (
    "continuous_speed_rpm",
    "rated_speed_rpm",
    "brake_holding_torque_nm",
    "output_bearing_pitch_diameter_m",
    "output_bearing_offset_m",
    "output_bearing_dynamic_load_rating_n",
    "output_bearing_static_load_rating_n",
    "output_bearing_dynamic_tilting_moment_nm",
    "output_bearing_static_tilting_moment_nm",
    "output_bearing_radial_load_n",
    "output_bearing_axial_load_n",
    "output_bearing_moment_load_nm",
    "output_bearing_moment_stiffness_nm_per_rad",
)

PUBLISHED: dict[str, dict[str, float | None]] = {
    # CHA 12/2015 Table 36.1 (n_N 3500 rpm) and 36.3 (T_Br); 8/2018 Table 55.1 (bearing)
    "CHA-25A-50": {
        "rated_speed_rpm": 70,
        "brake_holding_torque_nm": 90,
        "output_bearing_pitch_diameter_m": 0.088,
        "output_bearing_offset_m": 0.018,
        "output_bearing_dynamic_load_rating_n": 30000,
        "output_bearing_static_load_rating_n": 45000,
        "output_bearing_dynamic_tilting_moment_nm": 254,
        "output_bearing_static_tilting_moment_nm": 1050,
        "continuous_speed_rpm": None,
        "output_bearing_moment_load_nm": None,
    },
    # CHA 12/2015 Table 40.1 (n_N 3000 rpm) and 40.3; M_0 of size 40 not read
    "CHA-40A-160": {
        "rated_speed_rpm": 18.75,
        "brake_holding_torque_nm": 647,
        "output_bearing_dynamic_load_rating_n": 43300,
        "output_bearing_dynamic_tilting_moment_nm": 886,
        "output_bearing_static_tilting_moment_nm": None,
        "inertia_kgm2": 34.6,
    },
    # CHA 12/2015 Table 44.1 (n_N 2000 rpm) and 44.3
    "CHA-58A-50": {"rated_speed_rpm": 40, "brake_holding_torque_nm": 450},
    # CHA 12/2015 Table 19.1 (J_out, resolver) and 19.2 (T_Br); 8/2018 Table 20.1 (n_N 3500)
    "CHA-17A-E-50": {
        "inertia_kgm2": 0.264,
        "brake_holding_torque_nm": 25,
        "rated_speed_rpm": 70,
        "output_bearing_static_tilting_moment_nm": 276,
    },
    "CHA-17A-E-120": {"inertia_kgm2": 1.520, "brake_holding_torque_nm": 54},
    # CHA 12/2015 Table 12.1 (n_N 3500) and 14.2
    "CHA-14A-E-100": {
        "rated_speed_rpm": 35,
        "brake_holding_torque_nm": 28,
        "output_bearing_pitch_diameter_m": 0.049,
    },
    # FHA-C manual §2-4-6 (continuous), §1-4-2 (output bearing), §2-3 Table 1 (cross
    # roller bearing d_p, R, C, C_0, printed p. 20); brake not published for the absolute
    # system
    "FHA-25C-50": {
        "continuous_torque_nm": 35,
        "continuous_speed_rpm": 70,
        "output_bearing_pitch_diameter_m": 0.0962,
        "output_bearing_offset_m": 0.018,
        "output_bearing_dynamic_load_rating_n": 18000,
        "output_bearing_static_load_rating_n": 33300,
        "output_bearing_radial_load_n": 4900,
        "output_bearing_axial_load_n": 14700,
        "output_bearing_moment_load_nm": 370,
        "output_bearing_moment_stiffness_nm_per_rad": 490e3,
        "brake_holding_torque_nm": None,
        "rated_speed_rpm": None,
        "max_torque_nm": 150,
        "inertia_kgm2": 0.8,
    },
    "FHA-17C-100": {
        "continuous_torque_nm": 24,
        "continuous_speed_rpm": 35,
        "output_bearing_pitch_diameter_m": 0.077,
        "output_bearing_offset_m": 0.017,
        "output_bearing_dynamic_load_rating_n": 10800,
        "output_bearing_static_load_rating_n": 18700,
    },
    "FHA-32C-50": {
        "output_bearing_pitch_diameter_m": 0.1122,
        "output_bearing_offset_m": 0.0185,
        "output_bearing_dynamic_load_rating_n": 24100,
        "output_bearing_static_load_rating_n": 44300,
    },
    "FHA-40C-160": {
        "continuous_torque_nm": 300,
        "continuous_speed_rpm": 16,
        "output_bearing_pitch_diameter_m": 0.1488,
        "output_bearing_offset_m": 0.0265,
        "output_bearing_dynamic_load_rating_n": 44900,
        "output_bearing_static_load_rating_n": 88900,
        "output_bearing_radial_load_n": 14700,
        "output_bearing_axial_load_n": 39200,
        "output_bearing_moment_load_nm": 690,
        "output_bearing_moment_stiffness_nm_per_rad": 1400e3,
    },
    # FHA-C mini incremental manual p. 13; its allowable continuous speed is printed only
    # for the absolute version
    "FHA-8C-50": {
        "output_bearing_moment_load_nm": 15,
        "output_bearing_moment_stiffness_nm_per_rad": 20e3,
        "continuous_speed_rpm": None,
        "continuous_torque_nm": 1.5,
    },
    "FHA-14C-100": {
        "output_bearing_moment_load_nm": 75,
        "output_bearing_moment_stiffness_nm_per_rad": 80e3,
    },
}


def _actuator(client: TestClient, model: str) -> dict[str, Any]:
    response = client.get(f"/api/v1/actuators/{model}")
    assert response.status_code == 200
    body: dict[str, Any] = response.json()
    return body


@pytest.mark.parametrize("model", sorted(PUBLISHED))
def test_seeded_values_are_the_published_numbers(client: TestClient, model: str) -> None:
    body = _actuator(client, model)
    for field, expected in PUBLISHED[model].items():
        if expected is None:
            assert body[field] is None, field
        else:
            assert body[field] == pytest.approx(expected, rel=1e-12), field


def test_the_chapter_row_keeps_only_its_own_values(client: TestClient) -> None:
    """HD AG's FHA-25C-50-L takes nothing from the LLC's FHA-25C-50."""
    body = _actuator(client, "FHA-25C-50-L")
    assert all(body[field] is None for field in NEW_VALUES)
    assert (body["continuous_torque_nm"], body["derivation"]) == (None, None)
    assert body["source"].endswith("Table 516.3")


def test_every_new_value_names_its_document(client: TestClient) -> None:
    documents = {
        "CHA": ("Engineering Data AC Servo Actuators CHA", "1018854"),
        "FHA-C": ("Harmonic Drive LLC, FHA-C series AC Servo Actuator Manual", "§1-4-2"),
        "FHA-C mini": ("Harmonic Drive LLC, FHA-C mini series manual", "p. 13"),
    }
    rows = client.get("/api/v1/actuators").json()["actuators"]
    loaded = [r for r in rows if any(r[f] is not None for f in NEW_VALUES)]
    assert {r["family"] for r in loaded} == set(documents)
    for row in loaded:
        document, place = documents[row["family"]]
        assert document in row["source"], row["model"]
        assert place in row["source"], row["model"]
        if row["family"] == "CHA":
            assert "Table 55.1" in row["source"], row["model"]
        if row["output_bearing_radial_load_n"] is not None:
            # where the value was checked is kept beside the citation, not in it
            assert "manualshive.com" in row["read_at"], row["model"]
        if row["family"] == "FHA-C" and row["output_bearing_pitch_diameter_m"] is not None:
            assert '§2-3 "Verifying loads", Table 1' in row["source"], row["model"]
        if row["family"] == "FHA-C" and row["continuous_torque_nm"] is not None:
            assert "§2-4-6" in row["source"], row["model"]


def test_cha_rated_output_speed_is_marked_derived(client: TestClient) -> None:
    """Rated output speed = rated motor speed n_N / i, and the row says so."""
    cha = client.get("/api/v1/actuators", params={"family": "CHA"}).json()["actuators"]
    assert cha
    for row in cha:
        assert row["rated_speed_rpm"] is not None, row["model"]
        n_n = row["rated_speed_rpm"] * row["gear_ratio"]
        assert min(abs(n_n - n) for n in (2000, 2500, 3000, 3500)) < 0.01 * row["gear_ratio"]
        assert row["rated_speed_rpm"] <= row["max_speed_rpm"], row["model"]
        assert "derived" in row["derivation"], row["model"]
        assert "gear ratio" in row["derivation"], row["model"]
        assert "rated motor speed n_N" in row["source"], row["model"]
