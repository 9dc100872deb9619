"""Issue 28, item 1 on the page: the 15 kg belt axis (pulley 60 mm, 0.5 m/s) is not
"suitable" on CHA-14A-E-30, whose listed controllers all run on the 24 V bus: its row
says why, the drive's voltage against the controller's, with the numbers of the API."""

from __future__ import annotations

import math
from typing import Any

import pytest
from playwright.sync_api import Page, expect

from .test_engineer_page import fill_worked_example, four_digits, post_selection
from .test_engineer_segments import fill_segments

pytestmark = pytest.mark.browser

MOVES: list[dict[str, Any]] = [  # out and back at 0.5 m/s, in mm/s
    {"speed": 500, "duration_s": 0.2},
    {"duration_s": 0.4},
    {"speed": 0, "duration_s": 0.2},
    {"duration_s": 0.5},
    {"speed": -500, "duration_s": 0.2},
    {"duration_s": 0.4},
    {"speed": 0, "duration_s": 0.2},
    {"duration_s": 0.5},
]
N_2 = 0.5 / 0.030 * 60 / (2 * math.pi)  # v/r [rpm]


def test_the_belt_axis_on_a_24_v_actuator_is_unsuitable_and_the_row_names_the_voltage(
    page: Page,
) -> None:
    page.goto("/")
    page.get_by_label("Belt axis").check()
    for name, value in (
        ("mass_kg", "15"),
        ("pulley_diameter_mm", "60"),
        ("friction_coefficient", "0.05"),
        ("efficiency", "0.9"),
        ("incline_deg", "0"),
    ):
        page.locator(f"#f-belt-{name}").fill(value)
    page.get_by_label("Segments (several moves").check()
    fill_segments(page, MOVES)
    status, body = post_selection(page)
    assert status == 201, body
    assert body["load"]["speed_rpm"] == pytest.approx(N_2)
    small = next(c for c in body["candidates"] if c["model"] == "CHA-14A-E-30")
    assert small["verdict"] == "unsuitable"
    voltage = next(c for c in small["checks"] if c["name"] == "drive_voltage")
    # √((n·i·K_E + I·R)² + (ω·L·I)²) with the CHA-14A-E-30's constants, against 24 V/√2
    motor = N_2 * 30
    needed = math.hypot(motor * 3 / 1000 + 7.4 * 0.42, 2 * math.pi * 5 * motor / 60 * 0.35e-3 * 7.4)
    assert voltage["value"] == pytest.approx(needed, rel=1e-12)
    assert voltage["limit"] == pytest.approx(24 / math.sqrt(2), rel=1e-12)
    assert body["candidates"][0]["model"] != "CHA-14A-E-30"
    assert body["candidates"][0]["verdict"] == "suitable"

    row = page.locator('#ranking-table tr[data-model="CHA-14A-E-30"]')
    expect(row).to_contain_text("unsuitable")
    reason = row.locator('.reasons li[data-check="drive_voltage"]')
    expect(reason).to_contain_text("fail")
    expect(reason).to_contain_text(
        f"{four_digits(voltage['value'])}\u202fV, limit {four_digits(voltage['limit'])}\u202fV"
    )
    expect(row.locator(".reasons li")).to_have_count(1)  # the one quantity that binds


def test_the_cha_20a_bearing_life_takes_exponent_3_on_the_page(page: Page) -> None:
    """Issue 28, item 4 on the page: the CHA-20A's four-point contact ball bearing, 2 kN at
    20 mm, the worked example's cycle (n_av = 6.154 rpm), 200,000 h required: L_10 =
    170,300 h with B = 3 would be 269,800 h with the 10/3 of a roller bearing; C needed
    f_w·P_c·(L_h·60·n_av/10⁶)^(1/3) = 25,540 N > C = 24,200 N."""
    page.goto("/")
    fill_worked_example(page)
    page.locator("#f-models").fill("CHA-20A-50")
    page.locator("#f-ol").check()
    for name, value in (
        ("radial_force_n", "2000"),
        ("axial_force_n", "0"),
        ("radial_lever_m", "0.02"),
        ("axial_lever_m", "0"),
        ("required_life_h", "200000"),
    ):
        page.locator(f"#f-ol-{name}").fill(value)
    status, body = post_selection(page)
    assert status == 201, body
    (candidate,) = body["candidates"]
    life = next(c for c in candidate["checks"] if c["name"] == "bearing_life")
    n_av = 8 / 1.3  # Eq. 514.3 for the worked example's trapezoid
    p_c = 2000 + 2 * 2000 * (0.020 + 0.016) / 0.070
    assert life["value"] == pytest.approx(1.5 * p_c * (200000 * 60 * n_av / 1e6) ** (1 / 3))
    assert (life["status"], life["limit"]) == ("fail", 24200)
    page.wait_for_selector('#detail[data-detail="ready"]')
    row = page.locator('#checks-table tr[data-check="bearing_life"]')
    expect(row).to_have_attribute("data-status", "fail")
    expect(row).to_contain_text("four-point contact ball bearing: B = 3")


def test_a_check_that_does_not_apply_says_so_on_the_page(page: Page) -> None:
    """Decision 0025 on the page: the CHA manual rates its output bearing by C and C_0
    (Table 51.1), so CHA-25A-50's allowable-force checks are "not applicable" — shown as
    such in the checks table, and no reason in the ranking."""
    page.goto("/")
    page.get_by_role("button", name="English").click()
    fill_worked_example(page)
    page.locator("#f-models").fill("CHA-25A-50")
    page.locator("#f-ol").check()
    for name, value in (
        ("radial_force_n", "500"),
        ("axial_force_n", "0"),
        ("radial_lever_m", "0.02"),
        ("axial_lever_m", "0"),
    ):
        page.locator(f"#f-ol-{name}").fill(value)
    status, body = post_selection(page)
    assert status == 201, body
    (candidate,) = body["candidates"]
    force = next(c for c in candidate["checks"] if c["name"] == "bearing_radial_force")
    assert force == {
        "name": "bearing_radial_force",
        "status": "not_applicable",
        "value": None,
        "limit": None,
    }
    page.wait_for_selector('#detail[data-detail="ready"]')
    row = page.locator('#checks-table tr[data-check="bearing_radial_force"]')
    expect(row).to_have_attribute("data-status", "not_applicable")
    expect(row).to_contain_text("not applicable")
    expect(row).to_contain_text("by its load ratings C and C0")  # C₀ drawn as C<sub>0</sub>
    ranking = page.locator('#ranking-table tr[data-model="CHA-25A-50"]')
    expect(ranking.locator('.reasons li[data-check="bearing_radial_force"]')).to_have_count(0)
