"""The files on the engineer's page, in a real browser (issue 30): a measured profile
uploaded shows its cycle chart before sizing and sizes as the chapter's cycle; the IDTA
02021 export link beside the reports downloads an AASX, and that AASX uploaded on the form
opens the same selection's answer."""

from __future__ import annotations

import zipfile
from io import BytesIO
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

import pytest
from bench.profile import cam_table
from playwright.sync_api import Page, expect
from tests.api.test_profiles import idta_file

from .test_engineer_page import fill_worked_example, post_selection, traces

pytestmark = pytest.mark.browser


def test_a_profile_upload_shows_its_chart_and_sizes(page: Page, tmp_path: Path) -> None:
    page.goto("/")
    page.locator("#f-direct-torque_nm").fill("5")
    page.locator("#f-direct-inertia_kgm2").fill("1.3")
    file = tmp_path / "worked-example.csv"
    file.write_bytes(idta_file())
    with page.expect_response("**/api/v1/profiles") as uploaded:
        page.locator("#profile-file").set_input_files(str(file))
    assert uploaded.value.status == 201
    expect(page.locator("#profile-summary")).to_contain_text("1301 samples read")
    page.wait_for_function("document.querySelector('#profile-chart')?.data?.length === 2")
    chart = page.evaluate("document.querySelector('#profile-chart').data.map(t => t.y.length)")
    assert chart[0] == 1301  # the samples (fewer than the preview's bound)
    # the segments are in the editor and the cycle form is "segments"
    expect(page.locator('input[name="cycle-mode"][value="segments"]')).to_be_checked()
    assert page.locator("#segment-list > li").count() >= 4
    status, body = post_selection(page)
    assert status == 201, body
    assert body["mean_speed_rpm"] == pytest.approx(80 / 13, rel=0.005)  # Eq. 514.3
    assert traces(page, "chart-cycle")


def test_units_chosen_on_the_form_go_with_the_upload(page: Page, tmp_path: Path) -> None:
    """A plain CSV whose headings carry no unit: the units a person picks beside the file
    input are sent with it (``?velocity_unit=…``), and the profile is read with them."""
    page.goto("/")
    page.locator("#profile-velocity-unit").select_option("rpm")
    page.locator("#profile-load-unit").select_option("N*m")
    file = tmp_path / "plain.csv"
    file.write_bytes(b"Zeit;Drehzahl;Moment\n0,0;0;2\n0,1;40;2\n0,2;40;2\n0,3;0;2\n1,3;0;2\n")
    with page.expect_response("**/api/v1/profiles*") as uploaded:
        page.locator("#profile-file").set_input_files(str(file))
    assert uploaded.value.status == 201
    query = parse_qs(urlsplit(uploaded.value.url).query)
    assert query == {"velocity_unit": ["rpm"], "load_unit": ["N*m"]}
    expect(page.locator("#profile-summary")).to_contain_text("5 samples read")
    expect(page.locator('input[name="cycle-mode"][value="segments"]')).to_be_checked()


def test_a_bad_profile_names_the_line(page: Page, tmp_path: Path) -> None:
    page.goto("/")
    file = tmp_path / "bad.csv"
    file.write_bytes(b"Time [s];Speed [rpm]\n0;0\n0.1;x\n0.2;0\n")
    page.locator("#profile-file").set_input_files(str(file))
    expect(page.locator("#err-profile")).to_contain_text("line 3, column 2")


def test_the_idta_export_link_and_the_aas_upload(page: Page, tmp_path: Path) -> None:
    page.goto("/")
    fill_worked_example(page)
    status, body = post_selection(page)
    assert status == 201
    link = page.locator("#report-aas")
    expect(link).to_have_text("Export (IDTA 02021)")
    with page.expect_download() as download:
        link.click()
    saved = tmp_path / "record.aasx"
    download.value.save_as(saved)
    with zipfile.ZipFile(BytesIO(saved.read_bytes())) as package:
        assert "aasx/files/MotionSection1.csv" in package.namelist()
    page.goto("/")
    with page.expect_response("**/api/v1/selections/from-aas") as imported:
        page.locator("#aas-file").set_input_files(str(saved))
    assert imported.value.status == 201
    page.wait_for_url("**/?selection=*")
    new_id = page.url.split("selection=")[1].split("&")[0]
    assert new_id != body["id"]
    again = page.request.get(f"/api/v1/selections/{new_id}").json()
    # the same verdicts and numbers (the page asks for its first rows; the import for more)
    assert again["candidates"][: len(body["candidates"])] == body["candidates"]
    assert (again["total_candidates"], again["verdict_counts"]) == (
        body["total_candidates"],
        body["verdict_counts"],
    )
    expect(page.locator("#permalink")).to_have_value(page.url)


def test_a_100000_sample_trace_uploads_with_its_chart(page: Page, tmp_path: Path) -> None:
    """The issue's measure: 100,000 samples (timed in bench/profile.py, not here)."""
    page.goto("/")
    file = tmp_path / "cam.csv"
    file.write_bytes(cam_table())
    with page.expect_response("**/api/v1/profiles") as uploaded:
        page.locator("#profile-file").set_input_files(str(file))
    assert uploaded.value.status == 201
    expect(page.locator("#profile-summary")).to_contain_text("100000 samples read, 100 segments")
    page.wait_for_function("document.querySelector('#profile-chart')?.data?.length === 2")
    points = page.evaluate("document.querySelector('#profile-chart').data[0].x.length")
    assert 0 < points <= 2000  # the preview, not every sample
