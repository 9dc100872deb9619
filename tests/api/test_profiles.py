"""Measured motion profiles over the API (issue 30, item 2): the worked example sampled at
1 ms gives the chapter's figures, a profile is sized by reference in a selection and a
batch, and hostile files answer 422 naming the line and column."""

from __future__ import annotations

import io
import zipfile
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient
from tests import worked_example

API = "/api/v1"
CSV = {"Content-Type": "text/csv"}


def worked_example_positions(step_s: float = 0.001) -> tuple[list[float], list[float]]:
    """Fig. 516.2 with Table 516.1 (n_2 = 40 rpm, t_1 = t_2 = t_3 = 0.1 s, t_p = 1 s): the
    output angle [deg] sampled every ``step_s``, from the motion's own equations."""
    t = np.round(np.arange(0, round(1.3 / step_s) + 1) * step_s, 12)
    w = 40 * 6.0  # deg/s
    a = w / 0.1
    x = np.select(
        [t <= 0.1, t <= 0.2, t <= 0.3],
        [
            a * t * t / 2,
            a * 0.01 / 2 + w * (t - 0.1),
            a * 0.01 / 2 + w * 0.1 + w * (t - 0.2) - a * (t - 0.2) ** 2 / 2,
        ],
        a * 0.01 + w * 0.1,
    )
    return t.tolist(), x.tolist()


def idta_file(step_s: float = 0.001) -> bytes:
    """The worked example as an IDTA 02021 motion file (``;``, decimal point)."""
    t, x = worked_example_positions(step_s)
    rows = [f"{a!r};{b!r}" for a, b in zip(t, x, strict=True)]
    return ("Time [s];AngularPosition [deg]\n" + "\n".join(rows) + "\n").encode()


def upload(client: TestClient, content: bytes, **params: Any) -> Any:
    return client.post(f"{API}/profiles", content=content, headers=CSV, params=params)


def chapter_answer(client: TestClient) -> Any:
    response = client.post(f"{API}/selections", json=worked_example.request())
    assert response.status_code == 201, response.text
    return response.json()


def test_worked_example_sampled_at_1_ms_gives_the_chapters_figures(client: TestClient) -> None:
    response = upload(client, idta_file())
    assert response.status_code == 201, response.text
    profile = response.json()
    assert response.headers["Location"].endswith(profile["id"])
    assert profile["kind"] == "rotary"
    assert profile["fit"]["exact"]
    assert len(profile["cycle"]["segments"]) <= 12  # 4, and a step at each corner
    selection = client.post(
        f"{API}/selections",
        json={
            "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
            "cycle": {"profile_id": profile["id"]},
        },
    )
    assert selection.status_code == 201, selection.text
    sampled = selection.json()
    chapter = chapter_answer(client)
    assert sampled["mean_speed_rpm"] == pytest.approx(chapter["mean_speed_rpm"], rel=0.005)
    assert sampled["duty_cycle_percent"] == pytest.approx(chapter["duty_cycle_percent"], rel=0.005)
    by_model = {c["model"]: c for c in sampled["candidates"]}
    for expected in chapter["candidates"]:
        got = by_model[expected["model"]]
        for name in ("accel_torque_nm", "decel_torque_nm", "rms_torque_nm"):
            if expected[name] is None:
                assert got[name] is None
            else:
                assert got[name] == pytest.approx(expected[name], rel=0.005), name
    # The stored selection holds the segments it was sized with, not the reference.
    stored = client.get(f"{API}/selections/{sampled['id']}")
    assert stored.status_code == 200


def test_a_plain_csv_with_decimal_comma_and_units_chosen_on_upload(client: TestClient) -> None:
    content = b"Zeit;Drehzahl;Moment\n0,0;0;2\n0,1;40;2\n0,2;40;2\n0,3;0;2\n1,3;0;2\n"
    response = upload(client, content, velocity_unit="rpm", load_unit="N*m")
    assert response.status_code == 201, response.text
    profile = response.json()
    segments = profile["cycle"]["segments"]
    assert [(s["speed"], s["process_load"]) for s in segments] == [(40, 2), (40, 2), (0, 2), (0, 2)]
    assert [s["duration_s"] for s in segments] == pytest.approx([0.1, 0.1, 0.1, 1.0])
    assert profile["figures"]["samples"]["duty_cycle_percent"] == pytest.approx(300 / 13)


def test_the_motion_file_of_an_exported_record_uploads(client: TestClient) -> None:
    """The IDTA 02021 motion file this service writes (rows repeated at the time where the
    acceleration jumps) is a profile: the same cycle, the same figures."""
    chapter = chapter_answer(client)
    package = client.get(f"{API}/selections/{chapter['id']}/aas.aasx").content
    with zipfile.ZipFile(io.BytesIO(package)) as aasx:
        motion = aasx.read("aasx/files/MotionSection1.csv")
    response = upload(client, motion)
    assert response.status_code == 201, response.text
    profile = response.json()
    assert profile["fit"]["exact"]
    figures = profile["figures"]["segments"]
    assert figures["mean_speed"] == pytest.approx(chapter["mean_speed_rpm"], rel=1e-9)
    assert figures["duty_cycle_percent"] == pytest.approx(chapter["duty_cycle_percent"], rel=1e-9)
    # a repeated time with another speed is a jump, and refused
    jump = b"Time [s];AngularVelocity [rad/s]\n0;0\n0.1;1\n0.1;2\n0.2;0\n"
    refused = upload(client, jump)
    assert refused.status_code == 422
    assert refused.json()["detail"][0]["loc"] == ["body", 4, 1]


def test_the_profile_can_be_read_back(client: TestClient) -> None:
    created = upload(client, b"Time [s],Speed [rpm]\n0,0\n0.5,10\n1,0\n").json()
    again = client.get(f"{API}/profiles/{created['id']}")
    assert again.status_code == 200
    assert again.json() == created
    assert client.get(f"{API}/profiles/nope").status_code == 404


def test_the_limits_of_a_case_take_a_profile(client: TestClient) -> None:
    profile = upload(client, idta_file(0.01)).json()
    body = {
        "load": {"torque_nm": 5, "inertia_kgm2": 1.3},
        "cycle": {"profile_id": profile["id"]},
        "model": "FHA-25C-50-L",
    }
    response = client.post(f"{API}/selections/limits", json=body)
    assert response.status_code == 200, response.text


def test_a_batch_names_one_profile_per_case(client: TestClient) -> None:
    first = upload(client, idta_file(0.01)).json()
    second = upload(client, b"Time [s];Speed [rpm]\n0;0\n0.2;30\n0.6;30\n0.8;0\n2;0\n").json()
    cases = [
        {"load": {"torque_nm": 5, "inertia_kgm2": 1.3}, "cycle": {"profile_id": first["id"]}},
        {"load": {"torque_nm": 5, "inertia_kgm2": 1.3}, "cycle": {"profile_id": second["id"]}},
        worked_example.request(),
    ]
    response = client.post(f"{API}/selections/batch", json={"cases": cases, "top": 1})
    assert response.status_code == 200, response.text
    results = response.json()["results"]
    assert results[0]["mean_speed_rpm"] == pytest.approx(results[2]["mean_speed_rpm"], rel=0.005)
    assert results[1]["mean_speed_rpm"] == pytest.approx((30 * 0.2 + 30 * 0.4) / 2)


def test_a_reference_to_an_unknown_profile_or_the_wrong_kind_is_a_422(client: TestClient) -> None:
    linear = upload(client, b"Time [s];Velocity [m/s]\n0;0\n0.5;0.1\n1;0\n2;0\n")
    assert linear.status_code == 201, linear.text
    assert linear.json()["kind"] == "linear"
    for cycle, code in (
        ({"profile_id": "no-such-profile"}, "unknown_profile"),
        ({"profile_id": linear.json()["id"]}, "profile_kind"),
    ):
        response = client.post(
            f"{API}/selections",
            json={"load": {"torque_nm": 5, "inertia_kgm2": 1.3}, "cycle": cycle},
        )
        assert response.status_code == 422, response.text
        detail = response.json()["detail"][0]
        assert detail["code"] == code
        assert detail["loc"] == ["body", "cycle", "profile_id"]


def test_speeds_above_every_n_max_are_noted(client: TestClient) -> None:
    response = upload(client, b"Time [s];Speed [rpm]\n0;0\n0.1;5000\n0.2;0\n1;0\n")
    assert response.status_code == 201, response.text
    notes = response.json()["notes"]
    assert [n["code"] for n in notes] == ["profile_above_every_n_max"]
    assert notes[0]["params"]["peak_rpm"] == 5000


HOSTILE: list[tuple[str, bytes, dict[str, str], str, list[Any]]] = [
    (
        "bad number",
        b"Time [s];Speed [rpm]\n0;0\n0.1;x1\n0.2;0\n",
        {},
        "profile_not_a_number",
        ["body", 3, 2],
    ),
    (
        "NaN",
        b"Time [s];Speed [rpm]\n0;0\n0.1;NaN\n0.2;0\n",
        {},
        "profile_not_finite",
        ["body", 3, 2],
    ),
    (
        "time going back",
        b"Time [s];Speed [rpm]\n0;0\n0.2;1\n0.1;0\n0.3;0\n",
        {},
        "profile_time_not_increasing",
        ["body", 4, 1],
    ),
    ("binary", b"\x89PNG\r\n\x1a\n\x00\x00\x00", {}, "profile_binary", ["body", 1]),
    (
        "not UTF-8",
        b"Time [s];Speed [rpm]\n0;0\n\xff\xfe;0\n",
        {},
        "profile_binary",
        ["body", 3],
    ),
    (
        "wrong unit",
        b"Time [s];Speed [kg]\n0;0\n0.1;1\n0.2;0\n",
        {},
        "profile_unit_wrong",
        ["body", 1, 2],
    ),
    (
        "a frequency is no speed",
        b"Time [s];Speed [Hz]\n0;0\n0.1;1\n0.2;0\n",
        {},
        "profile_unit_wrong",
        ["body", 1, 2],
    ),
    (
        "a force on a rotary axis",
        b"Time [s];Speed [rpm];Force [N]\n0;0;1\n0.1;1;1\n0.2;0;1\n",
        {},
        "profile_unit_kinds",
        ["body", 1, 3],
    ),
    ("no unit", b"Time;Speed\n0;0\n0.1;1\n0.2;0\n", {}, "profile_unit_missing", ["body", 1, 2]),
    ("no time", b"Speed [rpm]\n0\n1\n0\n", {}, "profile_no_time_column", ["body", 1]),
    (
        "a row short of a cell",
        b"Time [s];Speed [rpm]\n0;0\n0.1\n0.2;0\n",
        {},
        "profile_cells",
        ["body", 3, 2],
    ),
    (
        "not closed",
        b"Time [s];Speed [rpm]\n0;0\n0.1;10\n0.2;10\n",
        {},
        "profile_not_closed",
        ["body"],
    ),
    ("empty", b"", {}, "profile_empty", ["body", 1]),
    ("too few", b"Time [s];Speed [rpm]\n0;0\n1;0\n", {}, "profile_too_few_samples", ["body", 1]),
]


@pytest.mark.parametrize(
    ("content", "params", "code", "loc"),
    [case[1:] for case in HOSTILE],
    ids=[case[0] for case in HOSTILE],
)
def test_hostile_files_answer_422_naming_line_and_column(
    client: TestClient, content: bytes, params: dict[str, str], code: str, loc: list[Any]
) -> None:
    response = upload(client, content, **params)
    assert response.status_code == 422, response.text
    detail = response.json()["detail"][0]
    assert detail["code"] == code
    assert detail["loc"] == loc


def test_a_huge_file_is_refused_before_it_is_read_whole(client: TestClient) -> None:
    row = b"0.123456789012;0.123456789012\n"
    content = b"Time [s];Speed [rpm]\n" + row * (33 * 1024 * 1024 // len(row))
    response = upload(client, content)
    assert response.status_code in (413, 422), response.text


def test_a_file_not_sent_as_csv_is_a_415(client: TestClient) -> None:
    response = client.post(
        f"{API}/profiles", content=b"{}", headers={"Content-Type": "application/json"}
    )
    assert response.status_code == 415


def test_a_bad_cell_deep_in_a_large_file_is_named_by_its_line(client: TestClient) -> None:
    rows = [f"{k * 0.001:.3f};{(k % 7):d}" for k in range(60_000)]
    rows[50_000] = "50.000;nan"
    content = ("Time [s];Speed [rpm]\n" + "\n".join(rows) + "\n").encode()
    response = upload(client, content)
    assert response.status_code == 422, response.text
    detail = response.json()["detail"][0]
    assert (detail["code"], detail["loc"]) == ("profile_not_finite", ["body", 50_002, 2])
