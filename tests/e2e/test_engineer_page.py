"""The engineer's web page in a real browser: form → API → tables and charts.

Reference values come from the chapter (Table 516.1 with the FHA-25C-50-L of
Table 516.3) and from first principles (Eq. 514.1–514.4, 515.6), computed here
by hand rather than read back from the service.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal
from pathlib import Path
from typing import Any, cast
from urllib.parse import quote

import pytest
from playwright.sync_api import Browser, Page, Response, Route, ViewportSize, expect

from .conftest import DESKTOP, PHONE, Traffic

pytestmark = pytest.mark.browser

# ---------------------------------------------------------------- reference values

G = 9.81  # [m/s²], as Eq. 515.6 states it

# Table 516.1 (load, speed pattern) and Table 516.3 (FHA-25C-50-L)
N_2 = 40.0  # [rpm]
T_L = 5.0  # [Nm]
J_L = 1.3  # [kgm²]
T1_S, T2_S, T3_S, TP_S = 0.1, 0.1, 0.1, 1.0  # [s]
FHA = "FHA-25C-50-L"
J_A = 0.86  # [kgm²]
T_MAX = 151.0  # [Nm]
N_MAX = 90.0  # [rpm]

T_0_S = T1_S + T2_S + T3_S + TP_S
ACCEL = 2 * math.pi / 60 * (J_A + J_L) * N_2  # [Nm·s], the inertia term of Eq. 514.1
EXPECTED_T1 = T_L + ACCEL / T1_S  # Eq. 514.1 → 95.48 Nm
EXPECTED_T3 = T_L - ACCEL / T3_S  # braking: T_L minus the inertia term → −85.48 Nm
EXPECTED_TRMS = math.sqrt(
    (EXPECTED_T1**2 * T1_S + T_L**2 * T2_S + EXPECTED_T3**2 * T3_S) / T_0_S
)  # Eq. 514.2 → 35.57 Nm
EXPECTED_NAV = (N_2 / 2 * T1_S + N_2 * T2_S + N_2 / 2 * T3_S) / T_0_S  # Eq. 514.3 → 6.154 rpm
EXPECTED_ED = (T1_S + T2_S + T3_S) / T_0_S * 100  # Eq. 514.4 → 23.08 %

TRACES_JS = """id => {
  const gd = document.getElementById(id);
  return (gd.data || []).map(t => ({
    uid: t.uid ?? null,
    name: t.name ?? null,
    x: Array.from(t.x ?? [], Number),
    y: Array.from(t.y ?? [], Number),
  }));
}"""
# the texts written on the plot: its annotations, and its traces of text (the phases' and
# steps' labels, the approximate zone's value: text traces, which plotly.js draws once)
ANNOTATIONS_JS = """id => {
  const gd = document.getElementById(id);
  return [
    ...(gd.layout.annotations || []).map(a => String(a.text)),
    ...(gd.data || []).filter(t => t.mode === "text").flatMap(t => Array.from(t.text, String)),
  ];
}"""


def shown(text: str) -> float:
    """The number in a displayed text: "−85,48 Nm" → -85.48 (minus sign, decimal comma)."""
    match = re.search(r"[−-]?\d+(?:[.,]\d+)?(?:e[−-]?\d+)?", text)
    assert match, f"no number in {text!r}"
    return float(match.group(0).replace("−", "-").replace(",", "."))


SELECTIONS_URL = re.compile(r"/api/v1/selections(\?[^/]*)?$")
"""POST /selections's URL, with the page's query (``?top=``) or without."""


def fill_worked_example(page: Page) -> None:
    """Type Table 516.1 into the form, field by field."""
    page.locator("#f-speed").fill("40")
    page.locator("#f-direct-torque_nm").fill("5")
    page.locator("#f-direct-inertia_kgm2").fill("1.3")
    fill_cycle(page, "0.1", "0.1", "0.1", "1")


def fill_cycle(page: Page, t1: str, t2: str, t3: str, tp: str) -> None:
    for field, value in (("#f-t1", t1), ("#f-t2", t2), ("#f-t3", t3), ("#f-tp", tp)):
        page.locator(field).fill(value)


def submit(page: Page) -> Response:
    """Press the submit button; the answer of ``POST /selections`` as soon as it is in."""
    with page.expect_response(
        lambda r: SELECTIONS_URL.search(r.url) is not None and r.request.method == "POST"
    ) as info:
        page.locator("#submit").click()
    return info.value


def post_selection(page: Page) -> tuple[int, dict[str, Any]]:
    """Press the submit button; the API's status and body once the page shows them."""
    response = submit(page)
    body = cast(dict[str, Any], response.json())
    if response.status == 201:
        page.wait_for_function(
            "id => (document.querySelector('#permalink')?.value ?? '').includes(id)",
            arg=body["id"],
        )
        wait_for_charts(page)
    return response.status, body


def assert_no_leaked_values(page: Page) -> None:
    """No JavaScript artefact reached the screen."""
    text = page.locator("body").inner_text()
    for artefact in ("[object", "undefined", "NaN", "Traceback"):
        assert artefact not in text, artefact


def wait_for_charts(page: Page, model: str | None = None) -> None:
    """Both plotly charts drawn (for ``model`` when given)."""
    which = f'[data-model="{model}"]' if model else ""
    for chart in ("#chart-cycle", "#chart-diagram"):
        page.wait_for_selector(f'{chart}[data-state="ready"]{which}')


def choose(page: Page, model: str, *, by_keyboard: bool = False) -> None:
    """Pick a candidate by clicking its row, or by its model button and Enter."""
    row = page.locator(f'#ranking-table tr[data-model="{model}"]')
    if by_keyboard:
        row.locator(".model-button").focus()
        page.keyboard.press("Enter")
    else:
        row.locator('td[data-field="rms"]').click()
    page.wait_for_selector(f'#detail[data-model="{model}"]')
    wait_for_charts(page, model)


def traces(page: Page, chart_id: str) -> dict[str, dict[str, Any]]:
    """The chart's plotly traces by uid, read from the graph div's ``.data``."""
    data = cast(list[dict[str, Any]], page.evaluate(TRACES_JS, chart_id))
    return {str(t["uid"]): t for t in data}


def plot_annotations(page: Page, chart_id: str) -> list[str]:
    """The texts written on the chart's plot (annotations and labels)."""
    return cast(list[str], page.evaluate(ANNOTATIONS_JS, chart_id))


def four_digits(value: float) -> str:
    """``value`` as the page writes it in English: 4 significant digits, no exponent."""
    text = format(Decimal(f"{value:.4g}"), "f")
    text = text.rstrip("0").rstrip(".") if "." in text else text
    return text.replace("-", "−")


def detail_url(selection_id: str, model: str) -> str:
    """The path of a candidate's detail, as the page asks for it."""
    return f"/api/v1/selections/{selection_id}/candidates/{quote(model, safe='')}"


def is_detail(url: str) -> bool:
    return re.search(r"/api/v1/selections/[^/]+/candidates/[^/]+$", url) is not None


def expanded_drive_options(selection: dict[str, Any], candidate: dict[str, Any]) -> list[str]:
    """The controllers of a lean candidate's drive options, by name, in the answer's order."""
    names = []
    for group in candidate["drive_options"]:
        for index in group["controllers"]:
            ref = selection["controllers"][index]
            names.append(
                " ".join(str(ref[k]) for k in ("manufacturer", "type", "variant") if ref[k])
            )
    return names


def row_value(page: Page, model: str, field: str) -> str:
    return page.locator(
        f'#ranking-table tr[data-model="{model}"] td[data-field="{field}"]'
    ).inner_text()


# ---------------------------------------------------------------- tests


def test_worked_example_gives_the_chapters_numbers(page: Page, traffic: Traffic) -> None:
    page.goto("/")
    expect(page.locator("#results-body")).to_contain_text("No calculation yet")
    fill_worked_example(page)
    expect(page.locator("#cycle-sum")).to_have_text("1.3")  # the input echo t_1+t_2+t_3+t_p
    status, _ = post_selection(page)
    assert status == 201

    # the selection-wide figures of Eq. 514.3 and 514.4 and t_0
    assert shown(page.locator("#sum-cycle-time .value").inner_text()) == pytest.approx(T_0_S)
    expect(page.locator("#sum-mean-speed .value")).to_have_text("6.154\u202frpm")
    expect(page.locator("#sum-duty .value")).to_have_text("23.08\u202f%")
    assert shown(page.locator("#sum-mean-speed .value").inner_text()) == pytest.approx(
        EXPECTED_NAV, rel=1e-3
    )

    # the chapter's actuator, chosen by clicking its row
    choose(page, FHA)
    expect(page.locator(f'#ranking-table tr[data-model="{FHA}"]')).to_have_attribute(
        "aria-current", "true"
    )
    assert row_value(page, FHA, "accel") == "95.48"
    assert row_value(page, FHA, "decel") == "−85.48"
    assert row_value(page, FHA, "rms") == "35.57"
    for selector, expected in (
        ("#fig-t1", EXPECTED_T1),
        ("#fig-t3", EXPECTED_T3),
        ("#fig-trms", EXPECTED_TRMS),
        ("#fig-nav", EXPECTED_NAV),
        ("#fig-ed", EXPECTED_ED),
    ):
        assert shown(page.locator(f"{selector} .value").inner_text()) == pytest.approx(
            expected, rel=1e-3
        ), selector
    expect(page.locator("#fig-t1 .value")).to_have_text("95.48\u202fNm")
    expect(page.locator("#fig-t3 .value")).to_have_text("−85.48\u202fNm")

    # every check with value, limit, status and the chapter's reference
    checks = page.locator("#checks-table tbody tr")
    # the chapter's five, the winding's thermal_peak, the continuous speed and drive_voltage
    expect(checks).to_have_count(8)
    continuous_speed = page.locator('#checks-table tr[data-check="continuous_speed"]')
    expect(continuous_speed).to_have_attribute("data-status", "no_data")
    thermal = page.locator('#checks-table tr[data-check="thermal_peak"]')
    expect(thermal).to_have_attribute("data-status", "no_data")
    expect(thermal).to_contain_text("520.1")
    peak = page.locator('#checks-table tr[data-check="peak_torque"]')
    expect(peak).to_contain_text("95.48\u202fNm")
    expect(peak).to_contain_text("151\u202fNm")
    expect(peak).to_contain_text("pass")
    expect(peak).to_contain_text("Eq. 514.1")
    # no zone and no continuous torque in the catalogue: "no data", verdict unconfirmed
    duty = page.locator('#checks-table tr[data-check="continuous_duty"]')
    expect(duty).to_have_attribute("data-status", "no_data")
    expect(duty).to_contain_text("no data")
    expect(duty).to_contain_text("Fig. 517.1")
    expect(page.locator("#detail-heading")).to_contain_text("unconfirmed")
    # the ranking says it from the lean answer: status and the catalogue value missing
    fha_reasons = page.locator(f'#ranking-table tr[data-model="{FHA}"] .reasons')
    expect(fha_reasons).to_contain_text("no data")
    expect(fha_reasons).to_contain_text(
        "not in the catalogue: continuous-duty zone or continuous torque"
    )
    # the margin (limit − value)/limit, and the server's message from the candidate's detail
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
    expect(peak.locator("td").nth(3)).to_have_text(
        f"{four_digits((T_MAX - EXPECTED_T1) / T_MAX * 100)}\u202f%"
    )
    expect(peak).to_contain_text("acceleration torque T1 = 95.48 Nm ≤ Tmax = 151 Nm")
    expect(page.locator(".detail-reasons")).to_contain_text(
        "no data: the catalogue gives no continuous-duty zone or continuous torque "
        "for this actuator"
    )

    # Fig. 516.2: the speed pattern and the torques over one period
    cycle = traces(page, "chart-cycle")
    speed = cycle["cycle-speed"]
    assert speed["x"] == pytest.approx([0, T1_S, T1_S + T2_S, T1_S + T2_S + T3_S, T_0_S])
    assert speed["y"] == pytest.approx([0, N_2, N_2, 0, 0])
    torque = cycle["cycle-torque"]["y"]
    assert max(torque) == pytest.approx(EXPECTED_T1, abs=0.005)
    assert min(torque) == pytest.approx(EXPECTED_T3, abs=0.005)
    assert T_L in torque
    assert torque[-1] == 0  # standstill in the pause
    assert cycle["cycle-rms"]["y"][0] == pytest.approx(EXPECTED_TRMS, abs=0.005)

    # Fig. 517.1: operating point, peaks, limits; no zone data for this actuator
    diagram = traces(page, "chart-diagram")
    operating = diagram["operating-point"]
    assert operating["x"][0] == pytest.approx(EXPECTED_NAV, abs=0.005)
    assert operating["y"][0] == pytest.approx(EXPECTED_TRMS, abs=0.005)
    assert (diagram["peak-accel"]["x"][0], diagram["peak-accel"]["y"][0]) == pytest.approx(
        (N_2, EXPECTED_T1), abs=0.005
    )
    assert (diagram["peak-decel"]["x"][0], diagram["peak-decel"]["y"][0]) == pytest.approx(
        (N_2, abs(EXPECTED_T3)), abs=0.005
    )
    assert set(diagram["t-max"]["y"]) == {T_MAX}
    assert set(diagram["n-max"]["x"]) == {N_MAX}
    assert "zone" not in diagram
    assert "zone-approx" not in diagram
    assert any("no data" in text for text in plot_annotations(page, "chart-diagram"))
    assert_no_leaked_values(page)
    assert not traffic.console_errors


def test_best_candidate_is_chosen_and_its_approximate_zone_drawn(page: Page) -> None:
    page.goto("/")
    fill_worked_example(page)
    _, body = post_selection(page)
    best = body["candidates"][0]
    assert best["verdict"] == "suitable"
    expect(page.locator("#detail")).to_have_attribute("data-model", best["model"])
    first_row = page.locator("#ranking-table tbody tr").first
    expect(first_row).to_have_attribute("aria-current", "true")
    expect(first_row).to_contain_text("suitable")

    catalogue = page.request.get(f"/api/v1/actuators/{best['model']}").json()
    assert catalogue["continuous_duty_zone"] is None
    stall = catalogue["stall_torque_nm"] or catalogue["continuous_torque_nm"]
    # the rectangle the continuous_duty check compares with: up to the allowable
    # continuous speed, else the rated speed, never up to n_max (a peak speed)
    edge = catalogue["continuous_speed_rpm"] or catalogue["rated_speed_rpm"]
    assert edge < catalogue["max_speed_rpm"]
    zone = traces(page, "chart-diagram")["zone-approx"]
    assert max(zone["y"]) == pytest.approx(stall)
    assert max(zone["x"]) == pytest.approx(edge)
    # where k_T and K_INL are published, the edge falls with speed as the winding current
    # does: T_0 − k_T·K_INL(80 °C)·n at the speed limit (_continuous_limit of
    # sizing/checks/rules/thermal.py)
    k_t = catalogue["torque_constant_nm_per_a"]
    k_inl = catalogue["no_load_current_constant_80c_a_per_rpm"]
    falls = catalogue["stall_torque_nm"] and k_t and k_inl
    assert zone["y"][2] == pytest.approx(stall - k_t * k_inl * edge if falls else stall)
    assert any("approximate" in text for text in plot_annotations(page, "chart-diagram"))
    # the approximate check is shown as approximate, with ≈ before its limit
    duty = page.locator('#checks-table tr[data-check="continuous_duty"]')
    expect(duty).to_contain_text("approximate")
    expect(duty).to_contain_text("≈")

    # verdict filter: only the unsuitable rows, each with its reason in words
    page.locator('.filter-button[data-filter="unsuitable"]').click()
    visible = page.locator("#ranking-table tbody tr:visible")
    unsuitable = [c for c in body["candidates"] if c["verdict"] == "unsuitable"]
    expect(visible).to_have_count(len(unsuitable))
    first_reason = visible.first.locator(".reasons li").first
    expect(first_reason).to_contain_text("fail")
    failed = next(c for c in unsuitable[0]["checks"] if c["status"] != "pass")
    unit = next(r["unit"] for r in body["check_rules"] if r["name"] == failed["name"])
    expect(first_reason).to_have_attribute("data-check", failed["name"])
    approx = "≈ " if failed.get("approximate") else ""
    expect(first_reason).to_contain_text(
        f"{four_digits(failed['value'])}\u202f{unit}, limit {approx}"
        f"{four_digits(failed['limit'])}\u202f{unit}"
    )


def test_plotly_is_warmed_up_out_of_sight_until_the_user_starts(page: Page) -> None:
    """Left untouched after plotly.js has run, the page draws both charts once off screen
    and throws them away; the user's own charts are drawn as ever. A user who has
    already clicked is not held up by it: the warm-up is skipped."""
    page.goto("/")
    expect(page.locator("html")).to_have_attribute("data-charts-warm", "done")
    expect(page.locator(".chart-warmup")).to_have_count(0)
    expect(page.locator(".js-plotly-plot")).to_have_count(0)  # nothing drawn is left
    fill_worked_example(page)
    _, body = post_selection(page)
    best = body["candidates"][0]
    expect(page.locator("#chart-cycle")).to_have_attribute("data-model", best["model"])
    assert max(traces(page, "chart-diagram")["peak-accel"]["y"]) == pytest.approx(
        best["accel_torque_nm"]
    )

    # plotly.js held back until the user has clicked into the form: no warm-up
    other = page.context.new_page()
    _clicked_before_plotly(other)
    fill_worked_example(other)
    post_selection(other)
    other.close()


def _clicked_before_plotly(page: Page) -> None:
    """Open the page with plotly.js held back until the user has clicked into the form:
    the warm-up gives way to the click and is skipped."""
    held: list[Route] = []
    page.route("**/vendor/plotly-basic-*.js", lambda route: held.append(route))
    page.goto("/", wait_until="commit")
    expect(page.locator("#results-body .notice")).to_be_attached()  # the page's script ran
    page.locator("#f-speed").click()
    assert len(held) == 1
    held[0].continue_()
    expect(page.locator("html")).to_have_attribute("data-charts-warm", "skipped")


def test_plotly_is_warmed_up_while_the_first_answer_is_awaited(page: Page) -> None:
    """A user who submits before the warm-up could run (it gives way to the first click)
    has the small warm-up figure drawn while the answer is on its way, off screen and
    thrown away; the charts are then drawn as ever."""
    _clicked_before_plotly(page)
    fill_worked_example(page)

    answers: list[Route] = []
    page.route(
        SELECTIONS_URL,
        lambda route: (
            answers.append(route) if route.request.method == "POST" else route.continue_()
        ),
    )
    page.locator("#submit").click()
    expect(page.locator("html")).to_have_attribute("data-charts-warm-submit", "done")
    expect(page.locator(".chart-warmup")).to_have_count(0)
    expect(page.locator(".js-plotly-plot")).to_have_count(0)  # nothing drawn is left
    assert len(answers) == 1
    answers[0].continue_()
    wait_for_charts(page)
    assert traces(page, "chart-diagram")["peak-accel"]["y"]


def test_rotary_table_shows_the_converted_load(page: Page) -> None:
    mass, diameter, mu, radius = 50.0, 0.4, 0.02, 0.15
    expected_inertia = mass / 8 * diameter**2  # Eq. 515.6 → 1.0 kgm²
    expected_torque = mu * mass * G * radius  # Eq. 515.6 → 1.4715 Nm
    page.goto("/")
    page.get_by_label("Rotary motion (rotary table)").check()
    expect(page.locator("#mech-rotary_table")).to_be_visible()
    expect(page.locator("#f-direct-torque_nm")).to_be_hidden()
    page.locator("#f-speed").fill("40")
    page.locator("#f-rotary_table-mass_kg").fill("50")
    page.locator("#f-rotary_table-diameter_m").fill("0.4")
    page.locator("#f-rotary_table-friction_coefficient").fill("0.02")
    page.locator("#f-rotary_table-friction_radius_m").fill("0.15")
    fill_cycle(page, "0.1", "0.1", "0.1", "1")
    status, body = post_selection(page)
    assert status == 201
    assert body["mechanism"]["type"] == "rotary_table"

    torque = page.locator("#resolved-rotary_table-torque")
    inertia = page.locator("#resolved-rotary_table-inertia")
    assert float(torque.get_attribute("data-value") or "nan") == pytest.approx(expected_torque)
    assert float(inertia.get_attribute("data-value") or "nan") == pytest.approx(expected_inertia)
    assert shown(torque.inner_text()) == pytest.approx(expected_torque, rel=1e-3)
    assert shown(inertia.inner_text()) == pytest.approx(expected_inertia, rel=1e-3)
    box = page.locator("#mech-rotary_table .resolved-values")
    assert "null" not in box.inner_text()  # issue 13: "null" after J_L
    expect(torque).to_have_text("1.472\u202fNm")
    expect(inertia).to_have_text("1\u202fkgm²")
    assert shown(page.locator("#sum-torque .value").inner_text()) == pytest.approx(
        expected_torque, rel=1e-3
    )
    expect(page.locator("#sum-mechanism")).to_contain_text("rotary table")

    # editing the input marks the result as belonging to the previous input
    page.locator("#f-rotary_table-mass_kg").fill("60")
    expect(page.locator("#results-body .notice-warn")).to_contain_text("inputs have changed")


def test_api_errors_appear_at_their_fields(page: Page) -> None:
    page.goto("/")
    page.get_by_label("Linear horizontal motion (ball screw)").check()
    page.locator("#f-speed").fill("40")
    page.locator("#f-ball_screw-mass_kg").fill("20")
    page.locator("#f-ball_screw-lead_m").fill("0.01")
    page.locator("#f-ball_screw-friction_coefficient").fill(
        "11"
    )  # HTML allows it, the API's bound is μ ≤ 10
    page.locator("#f-ball_screw-efficiency").fill("1.5")  # η ≤ 1
    fill_cycle(page, "0", "0.1", "0.1", "1")  # t_1 = 0: HTML min=0 allows it, the API not
    status, body = post_selection(page)
    assert status == 422
    locs = {tuple(e["loc"]) for e in body["detail"]}
    assert ("body", "load", "friction_coefficient") in locs

    for field, error, text in (
        (
            "#f-ball_screw-friction_coefficient",
            "#err-f-ball_screw-friction_coefficient",
            "less than or equal to 10",
        ),
        ("#f-ball_screw-efficiency", "#err-f-ball_screw-efficiency", "less than or equal to 1"),
        ("#f-t1", "#err-t1", "greater than or equal to 0.0001"),
    ):
        expect(page.locator(error)).to_be_visible()
        expect(page.locator(error)).to_contain_text(text)
        expect(page.locator(field)).to_have_attribute("aria-invalid", "true")
    expect(page.locator("#err-f-ball_screw-lead_m")).to_be_hidden()
    expect(page.locator("#form-status")).to_contain_text("3 input(s) rejected")
    # the first rejected field gets the focus; no result is lost or left blank
    expect(page.locator("#f-ball_screw-friction_coefficient")).to_be_focused()
    expect(page.locator("#results-body")).to_contain_text("No calculation yet")
    expect(page.locator("body")).not_to_contain_text("Traceback")

    # correcting a field clears its message; an unknown model is named at its field
    page.locator("#f-ball_screw-friction_coefficient").fill("0.1")
    expect(page.locator("#err-f-ball_screw-friction_coefficient")).to_be_hidden()
    page.locator("#f-ball_screw-efficiency").fill("0.9")
    page.locator("#f-t1").fill("0.1")
    page.locator("#f-models").fill("FHA-25C-50-L, NO-SUCH-MODEL")
    status, body = post_selection(page)
    assert status == 422
    assert body["detail"][0]["loc"] == ["body", "models", 1]
    expect(page.locator("#err-models")).to_contain_text("unknown actuator model 'NO-SUCH-MODEL'")
    expect(page.locator("#f-models")).to_have_attribute("aria-invalid", "true")

    # and with the models restricted correctly the API has the final, positive word
    page.locator("#f-models").fill("FHA-25C-50-L CHA-25A-50")
    status, body = post_selection(page)
    assert status == 201
    expect(page.locator("#ranking-table tbody tr")).to_have_count(2)
    expect(page.locator("#err-models")).to_be_hidden()


def test_permalink_reopens_the_selection(page: Page, browser: Browser, base_url: str) -> None:
    page.goto("/")
    page.get_by_label("Rotary motion (rotary table)").check()
    page.locator("#f-speed").fill("30")
    page.locator("#f-rotary_table-mass_kg").fill("50")
    page.locator("#f-rotary_table-diameter_m").fill("0.4")
    page.locator("#f-rotary_table-friction_coefficient").fill("0.02")
    page.locator("#f-rotary_table-friction_radius_m").fill("0.15")
    fill_cycle(page, "0.2", "0.5", "0.25", "2")
    page.locator("#f-hd").uncheck()
    _, body = post_selection(page)
    selection_id = body["id"]
    assert f"selection={selection_id}" in page.url
    second = body["candidates"][1]["model"]
    choose(page, second, by_keyboard=True)
    link = page.locator("#permalink").input_value()
    assert link.startswith(base_url)
    assert f"selection={selection_id}" in link
    assert page.url == link
    page.context.grant_permissions(["clipboard-read", "clipboard-write"], origin=base_url)
    page.locator("#copy-link").click()
    expect(page.locator("#copy-status")).to_have_text("Link copied.")
    assert page.evaluate("navigator.clipboard.readText()") == link

    colleague = browser.new_context(viewport=DESKTOP, locale="en-US")
    try:
        other = colleague.new_page()
        other.goto(link)
        wait_for_charts(other, second)
        expect(other.locator("#detail")).to_have_attribute("data-model", second)
        expect(other.locator('input[name="load-kind"][value="rotary_table"]')).to_be_checked()
        for field, value in (
            ("#f-speed", 30),
            ("#f-rotary_table-mass_kg", 50),
            ("#f-rotary_table-diameter_m", 0.4),
            ("#f-rotary_table-friction_coefficient", 0.02),
            ("#f-rotary_table-friction_radius_m", 0.15),
            ("#f-t1", 0.2),
            ("#f-t2", 0.5),
            ("#f-t3", 0.25),
            ("#f-tp", 2),
        ):
            assert float(other.locator(field).input_value()) == pytest.approx(value), field
        expect(other.locator("#f-hd")).not_to_be_checked()
        expect(other.locator("#sum-high-dynamics")).to_contain_text("no")
        expect(other.locator("#ranking-table tbody tr")).to_have_count(len(body["candidates"]))
        assert traces(other, "chart-cycle")["cycle-speed"]["x"][-1] == pytest.approx(2.95)

        # the bare link chooses the best candidate
        other.goto(f"{base_url}/?selection={selection_id}")
        wait_for_charts(other, body["candidates"][0]["model"])

        # an unknown selection says so instead of showing a blank page
        other.goto(f"{base_url}/?selection=00000000-0000-0000-0000-000000000000")
        expect(other.locator("#results-alert")).to_contain_text("Stored selection not found")
        expect(other.locator("#results-body")).to_contain_text("No calculation yet")
    finally:
        colleague.close()


def test_language_switch_is_remembered(page: Page) -> None:
    page.goto("/")
    expect(page.locator("html")).to_have_attribute("lang", "en")
    expect(page.get_by_label("Load rotation speed")).to_be_visible()
    page.get_by_role("button", name="Deutsch").click()
    expect(page.locator("html")).to_have_attribute("lang", "de")
    expect(page.get_by_role("button", name="Deutsch")).to_have_attribute("aria-pressed", "true")
    expect(page.locator('label[for="f-speed"]')).to_contain_text("Drehzahl der Last")
    expect(page.locator("#u-speed")).to_have_text("min⁻¹")
    expect(page.locator("#submit")).to_have_text("Antriebe auswählen")

    fill_worked_example(page)
    expect(page.locator("#cycle-sum")).to_have_text("1,3")
    post_selection(page)
    expect(page.locator("#sum-mean-speed .value")).to_have_text("6,154\u202fmin⁻¹")
    expect(page.locator("#sum-duty .value")).to_have_text("23,08\u202f%")
    choose(page, FHA)
    assert row_value(page, FHA, "accel") == "95,48"
    assert row_value(page, FHA, "decel") == "−85,48"
    duty = page.locator('#checks-table tr[data-check="continuous_duty"]')
    expect(duty).to_contain_text("keine Daten")
    expect(duty).to_contain_text("Abb. 517.1")
    expect(page.locator('#checks-table tr[data-check="peak_torque"]')).to_contain_text("erfüllt")
    expect(page.locator("#detail-heading")).to_contain_text("nicht bestätigt")
    assert page.evaluate("document.getElementById('chart-diagram').layout.separators") == ",."
    # issue 13: the screen reader's result sentence follows a switch of language
    expect(page.locator("#results-status")).to_contain_text(f"Gewählt: {FHA}")
    page.get_by_role("button", name="English").click()
    expect(page.locator("#results-status")).to_contain_text(f"Chosen: {FHA}")
    page.get_by_role("button", name="Deutsch").click()
    expect(page.locator("#results-status")).to_contain_text(f"Gewählt: {FHA}")
    assert any("keine Daten" in text for text in plot_annotations(page, "chart-diagram"))

    # remembered: a reload (the permalink) comes back in German, charts included
    page.reload()
    wait_for_charts(page, FHA)
    expect(page.locator("html")).to_have_attribute("lang", "de")
    expect(page.locator('label[for="f-speed"]')).to_contain_text("Drehzahl der Last")
    expect(page.locator("#sum-duty .value")).to_have_text("23,08\u202f%")
    page.get_by_role("button", name="English").click()
    expect(page.locator("#sum-duty .value")).to_have_text("23.08\u202f%")
    expect(page.locator('#checks-table tr[data-check="continuous_duty"]')).to_contain_text(
        "no data"
    )
    assert page.evaluate("localStorage.getItem('actuator-selection.lang')") == "en"


def test_controllers_of_the_api_are_listed(page: Page) -> None:
    page.goto("/")
    page.locator("#example").click()
    _, body = post_selection(page)
    with page.expect_response(lambda r: r.url.endswith(detail_url(body["id"], FHA))) as info:
        choose(page, FHA)
    assert info.value.status == 200
    detail = cast(dict[str, Any], info.value.json())
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
    rows = page.locator("#controllers-table tbody tr")
    expect(rows).to_have_count(len(detail["controllers"]))
    assert detail["controllers"], "the worked example's actuator has controllers to list"
    for i, controller in enumerate(detail["controllers"]):
        name = " ".join(
            str(controller[k]) for k in ("manufacturer", "type", "variant") if controller.get(k)
        )
        expect(rows.nth(i).locator(".controller-name")).to_have_text(name)
        expect(rows.nth(i)).to_have_attribute("data-level", controller["level"])
        # every criterion of Table 521.1, with the server's words on it
        criteria = rows.nth(i).locator(".criterion")
        expect(criteria).to_have_count(len(controller["criteria"]))
        titles = [criteria.nth(j).get_attribute("title") for j in range(criteria.count())]
        assert sorted(str(t) for t in titles) == sorted(
            c["message"] for c in controller["criteria"]
        )
        if controller["voltage"]["status"] != "pass":
            expect(rows.nth(i).locator(".voltage")).to_contain_text(
                re.sub(r"([A-Za-z])_([A-Za-z0-9]+)", r"\1\2", controller["voltage"]["message"])
            )
    expect(page.locator(".controllers")).to_contain_text(detail["controllers_note"])
    expect(page.locator(".controllers-summary")).to_contain_text(
        f"{detail['controllers_excluded']} excluded"
    )
    # the lean answer lists the same controllers in the same order: the panel shows
    # them so before the detail arrives
    candidate = next(c for c in body["candidates"] if c["model"] == FHA)
    assert expanded_drive_options(body, candidate) == [
        " ".join(str(c[k]) for k in ("manufacturer", "type", "variant") if c.get(k))
        for c in detail["controllers"]
    ]


def test_controller_levels_in_german_and_absent_controllers(page: Page) -> None:
    refs: list[dict[str, Any]] = [
        {"manufacturer": "SIEMENS", "type": "SINAMICS S120", "variant": None, "source_row": 5},
        {"manufacturer": "Beckhoff", "type": "AX 5000", "variant": "AX5101", "source_row": 9},
    ]
    voltage = {"status": "pass", "value": 100.0, "limit": 400.0, "reference": "Eq. 521.2"}
    models: list[str] = []

    def rewrite_selection(route: Route) -> None:
        response = route.fetch()
        body = response.json()
        body["controllers"] = refs
        body["candidates"][0]["drive_options"] = [
            {"level": "tested", "missing": [], "controllers": [0], "voltage": voltage},
            {"level": "possible", "missing": [], "controllers": [1], "voltage": voltage},
        ]
        body["candidates"][1]["drive_options"] = None  # as for an unsuitable candidate
        models.extend(c["model"] for c in body["candidates"][:2])
        # status and body only: the original headers name a gzip encoding
        route.fulfill(status=response.status, json=body)

    def rewrite_detail(route: Route) -> None:
        response = route.fetch()
        detail = response.json()
        if detail["model"] == models[0]:
            detail["controllers"] = [
                {**refs[0], "level": "tested", "missing": [], "excluded_by": [], "criteria": []},
                {**refs[1], "level": "possible", "missing": [], "excluded_by": [], "criteria": []},
            ]
        else:  # a detail that lists no controllers: the panel shows none
            for key in ("controllers", "controllers_excluded", "controllers_note"):
                detail.pop(key, None)
        route.fulfill(status=response.status, json=detail)

    page.route(SELECTIONS_URL, rewrite_selection)
    page.route(re.compile(r"/api/v1/selections/[^/]+/candidates/[^/]+$"), rewrite_detail)
    page.goto("/")
    page.get_by_role("button", name="Deutsch").click()
    page.locator("#example").click()
    _, body = post_selection(page)
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
    rows = page.locator("#controllers-table tbody tr")
    expect(rows).to_have_count(2)
    expect(rows.nth(0)).to_contain_text("SIEMENS SINAMICS S120")
    expect(rows.nth(0)).to_contain_text("praktisch erprobt")
    expect(rows.nth(1)).to_contain_text("Beckhoff AX 5000 AX5101")
    expect(rows.nth(1)).to_contain_text("theoretisch machbar")

    choose(page, body["candidates"][1]["model"])
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
    expect(page.locator(".controllers")).to_have_count(0)  # absent field: nothing shown


def test_the_panel_shows_the_lean_candidate_until_its_detail_arrives(page: Page) -> None:
    held: list[Route] = []
    page.route(
        re.compile(r"/api/v1/selections/[^/]+/candidates/[^/]+$"), lambda route: held.append(route)
    )
    page.goto("/")
    page.locator("#example").click()
    body = cast(dict[str, Any], submit(page).json())
    best = body["candidates"][0]
    expect(page.locator("#detail")).to_have_attribute("data-model", best["model"])
    expect(page.locator("#detail")).to_have_attribute("data-detail", "loading")
    expect(page.locator("#detail-status")).to_contain_text("Loading the server's messages")
    assert len(held) == 1
    assert held[0].request.url.endswith(detail_url(body["id"], best["model"]))

    # the checks as numbers, in the rule's unit, with the rule's reference and the margin
    rules = {r["name"]: r for r in body["check_rules"]}
    rows = page.locator("#checks-table tbody tr")
    expect(rows).to_have_count(len(best["checks"]))
    for check in best["checks"]:
        row = page.locator(f'#checks-table tr[data-check="{check["name"]}"]')
        unit = rules[check["name"]]["unit"]
        cells = row.locator("td")
        expect(cells.nth(0)).to_have_text(f"{four_digits(check['value'])}\u202f{unit}")
        expect(cells.nth(1)).to_contain_text(f"{four_digits(check['limit'])}\u202f{unit}")
        margin = (check["limit"] - check["value"]) / check["limit"] * 100
        expect(cells.nth(3)).to_have_text(f"{four_digits(margin)}\u202f%")
        expect(row.locator("th .ref")).to_have_text(rules[check["name"]]["reference"])
        expect(cells.nth(4)).to_contain_text("loading")  # the message comes with the detail
    # the controllers of the lean drive options, the criteria lacking data marked
    names = expanded_drive_options(body, best)
    controllers = page.locator("#controllers-table tbody tr")
    expect(controllers).to_have_count(len(names))
    expect(controllers.locator(".controller-name")).to_have_text(names)
    missing = best["drive_options"][0]["missing"]
    expect(controllers.first.locator(".criterion")).to_have_count(len(missing))
    expect(page.locator(".controllers .api-message")).to_have_count(0)
    # the cycle needs no catalogue data; the diagram waits for the detail's
    page.wait_for_selector('#chart-cycle[data-state="ready"]')
    expect(page.locator("#chart-diagram")).to_have_attribute("data-state", "loading")

    for route in held:
        route.continue_()
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
    wait_for_charts(page, best["model"])
    expect(page.locator("#detail-status")).to_be_empty()
    expect(page.locator("#checks-table tbody td.message").first).to_contain_text(
        "load speed n2 = 40"
    )
    expect(controllers.first.locator(".criterion")).to_have_count(4)
    expect(page.locator(".controllers .api-message").first).to_be_visible()
    assert "zone-approx" in traces(page, "chart-diagram")  # the detail's catalogue data


def test_the_panels_parts_below_the_charts_follow_the_charts(page: Page) -> None:
    """The segments' table and the controllers, below the charts, are built once the charts
    are drawn (the detail in): nothing drawn before them moves."""
    held: dict[str, list[Route]] = {"cycle": [], "diagram": []}
    figure = re.compile(r"/api/v1/selections/[^/]+/candidates/[^/]+/(cycle|diagram)")

    def hold(route: Route) -> None:
        match = figure.search(route.request.url)
        assert match is not None
        held[match.group(1)].append(route)

    page.route(figure, hold)
    page.goto("/")
    page.locator("#example").click()
    body = cast(dict[str, Any], submit(page).json())
    best = body["candidates"][0]
    expect(page.locator("#detail")).to_have_attribute("data-detail", "ready")
    while not held["cycle"]:
        page.wait_for_timeout(20)
    for route in held["cycle"]:
        route.continue_()
    page.wait_for_selector('#chart-cycle[data-state="ready"]')
    expect(page.locator("#checks-table tbody tr")).to_have_count(len(best["checks"]))
    assert page.locator("#controllers-table").count() == 0
    for route in held["diagram"]:
        route.continue_()
    wait_for_charts(page, best["model"])
    expect(page.locator("#controllers-table tbody tr").first).to_be_visible()
    expect(page.locator("#detail")).not_to_have_attribute("data-below", "later")


def test_the_ranking_draws_its_first_rows_and_the_rest_after_the_charts(page: Page) -> None:
    """The whole catalogue's ranking comes with its first rows; the others follow once the
    charts are drawn, or as soon as the user reaches for the ranking (its scroll box, its
    filter), drawn as filtered then and in the answer's order."""
    held: list[Route] = []
    detail = re.compile(r"/api/v1/selections/[^/]+/candidates/[^/]+$")
    page.route(detail, lambda route: held.append(route))  # the diagram waits for the detail
    page.goto("/")
    first = int(
        page.evaluate("async () => (await import('/pages/engineer/results.js')).FIRST_ROWS")
    )
    page.locator("#example").click()
    body = cast(dict[str, Any], submit(page).json())
    models = [c["model"] for c in body["candidates"]]
    assert len(models) > first
    table = page.locator("#ranking-table")
    rows = table.locator("tbody tr")
    page.wait_for_selector('#chart-cycle[data-state="ready"]')
    expect(table).to_have_attribute("data-rows", "partial")
    expect(rows).to_have_count(first)
    assert rows.evaluate_all("rs => rs.map(r => r.dataset.model)") == models[:first]

    # the filter draws the rest, hidden as it says
    page.locator('.filter-button[data-filter="unsuitable"]').click()
    expect(table).to_have_attribute("data-rows", "complete")
    assert rows.evaluate_all("rs => rs.map(r => r.dataset.model)") == models
    unsuitable = [c["model"] for c in body["candidates"] if c["verdict"] == "unsuitable"]
    shown = "rs => rs.filter(r => !r.hidden).map(r => r.dataset.model)"
    assert rows.evaluate_all(shown) == unsuitable
    assert rows.nth(len(models) - 1).locator(".rank").inner_text() == str(len(models))
    for route in held:
        route.continue_()
    wait_for_charts(page, models[0])

    # the pointer on the ranking's box draws the rest at once
    page.unroute(detail)
    held.clear()
    page.route(detail, lambda route: held.append(route))
    page.goto("/")
    page.locator("#example").click()
    page.locator("#submit").click()
    page.wait_for_selector('#chart-cycle[data-state="ready"]')
    expect(table).to_have_attribute("data-rows", "partial")
    page.locator(".ranking-card .table-scroll").hover()
    expect(table).to_have_attribute("data-rows", "complete")
    expect(rows).to_have_count(len(models))
    expect(page.locator("#chart-diagram")).to_have_attribute("data-state", "loading")
    for route in held:
        route.continue_()

    # left alone, the rest follows the charts
    page.unroute(detail)
    page.goto("/")
    fill_worked_example(page)
    post_selection(page)
    expect(table).to_have_attribute("data-rows", "complete")
    assert rows.evaluate_all("rs => rs.map(r => r.dataset.model)") == models


def test_a_detail_that_fails_leaves_the_lean_panel_and_says_so(
    page: Page, traffic: Traffic
) -> None:
    mode = {"fail": "conflict"}

    def detail(route: Route) -> None:
        if mode["fail"] == "conflict":
            route.fulfill(
                status=409,
                json={
                    "detail": [
                        {
                            "loc": ["path", "selection_id"],
                            "msg": "the catalogue has changed since this selection",
                            "type": "ConflictError",
                        }
                    ]
                },
            )
        elif mode["fail"] == "network":
            route.abort()
        else:
            route.continue_()

    page.route(re.compile(r"/api/v1/selections/[^/]+/candidates/[^/]+$"), detail)
    page.goto("/")
    fill_worked_example(page)
    _, body = post_selection(page)  # both charts drawn all the same
    choose(page, FHA)
    panel = page.locator("#detail")
    expect(panel).to_have_attribute("data-detail", "failed")
    status = page.locator("#detail-status")
    expect(status).to_contain_text("Details unavailable")
    expect(status).to_contain_text("the catalogue has changed since this selection")
    # the selection's numbers stay, the missing catalogue value in the API's words
    peak = page.locator('#checks-table tr[data-check="peak_torque"]')
    expect(peak).to_contain_text("95.48\u202fNm")
    expect(peak).to_contain_text("151\u202fNm")
    expect(peak.locator("td.message")).to_have_text("–")
    duty = page.locator('#checks-table tr[data-check="continuous_duty"]')
    expect(duty.locator("td.message")).to_contain_text(
        "not in the catalogue: continuous-duty zone or continuous torque"
    )
    expect(page.locator(".detail-reasons")).to_contain_text("continuous-duty zone")
    # the diagram is drawn without the catalogue's limits, and says so
    diagram = traces(page, "chart-diagram")
    assert not {"t-max", "n-max"} & set(diagram)
    assert "operating-point" in diagram
    assert any("catalogue data" in a for a in plot_annotations(page, "chart-diagram"))
    page.get_by_role("button", name="Deutsch").click()
    expect(status).to_contain_text("Einzelheiten nicht verfügbar")
    expect(status).to_contain_text("der Katalog wurde seit dieser Auswahl geändert")
    page.get_by_role("button", name="English").click()

    # a server out of reach may come back: choosing the candidate again asks again
    best = body["candidates"][0]["model"]
    other = next(c["model"] for c in body["candidates"][1:] if c["model"] != FHA)
    mode["fail"] = "network"
    choose(page, other)
    expect(status).to_contain_text("server not reachable")
    mode["fail"] = ""
    choose(page, FHA)  # a 409 stays: not asked again
    expect(panel).to_have_attribute("data-detail", "failed")
    choose(page, other)
    expect(panel).to_have_attribute("data-detail", "ready")
    expect(page.locator('#checks-table tr[data-check="max_speed"] td.message')).to_contain_text(
        "load speed n2 = 40 rpm"
    )
    asked = [u for u in traffic.requests if is_detail(u)]
    assert sum(u.endswith(detail_url(body["id"], best)) for u in asked) == 1
    assert sum(u.endswith(detail_url(body["id"], FHA)) for u in asked) == 1
    assert sum(u.endswith(detail_url(body["id"], other)) for u in asked) == 2
    assert not [e for e in traffic.console_errors if "409" not in e and "FAILED" not in e]


def test_keyboard_and_screen_reader_affordances(page: Page) -> None:
    page.goto("/")
    page.keyboard.press("Tab")
    expect(page.locator(".skip-link")).to_be_focused()
    unlabelled = page.evaluate(
        """() => [...document.querySelectorAll('#selection-form input')]
              .filter(el => el.labels.length === 0 && !el.getAttribute('aria-label'))
              .map(el => el.id)"""
    )
    assert unlabelled == []
    expect(page.locator("#results-status")).to_have_attribute("role", "status")
    expect(page.locator("#form-status")).to_have_attribute("role", "alert")

    page.locator("#example").focus()
    page.keyboard.press("Enter")
    page.locator("#f-tp").focus()
    with page.expect_response(SELECTIONS_URL):
        page.keyboard.press("Enter")  # Enter in a field submits the form
    wait_for_charts(page)
    expect(page.locator("#results-status")).to_contain_text("suitable")
    # rank, compare mark, model, verdict · checks, T_1, T_3, T_rms, reason
    expect(page.locator("#ranking-table thead th")).to_have_count(8)
    expect(page.locator("#checks-table thead th")).to_have_count(6)
    # a row's check marks are one image to a screen reader, named by every check's finding
    # in the order of the answer; each mark keeps its finding as a tooltip
    marks = page.locator(f'#ranking-table tr[data-model="{FHA}"] .marks')
    expect(marks).to_have_attribute("role", "img")
    titles = marks.locator(".mark").evaluate_all("ms => ms.map(m => m.title)")
    # the six of the flowchart, the continuous speed and the drive's voltage
    assert len(titles) == 8
    assert marks.get_attribute("aria-label") == "; ".join(titles)
    assert titles[2].startswith("T1 ≤ Tmax: pass (95.48\u202fNm / 151\u202fNm")
    assert "no data" in titles[4]
    choose(page, FHA, by_keyboard=True)
    expect(page.locator(f'#ranking-table tr[data-model="{FHA}"] .model-button')).to_have_attribute(
        "aria-pressed", "true"
    )
    expect(page.locator("#results-status")).to_contain_text(FHA)


def test_no_request_leaves_the_origin(page: Page, base_url: str, traffic: Traffic) -> None:
    page.goto("/")
    page.locator("#example").click()
    _, body = post_selection(page)
    choose(page, FHA)
    page.get_by_role("button", name="Deutsch").click()
    wait_for_charts(page, FHA)
    assert traffic.requests, "no request recorded"
    foreign = [url for url in traffic.requests if not url.startswith(f"{base_url}/")]
    assert foreign == []
    assert any(re.search(r"/vendor/plotly-basic-[\d.]+\.min\.js$", url) for url in traffic.requests)
    assert page.evaluate("typeof window.Plotly.react") == "function"
    # the catalogue data comes with each candidate's detail, asked once per candidate
    best = body["candidates"][0]["model"]
    choose(page, best)
    choose(page, FHA)
    details = sorted(url.removeprefix(base_url) for url in traffic.requests if is_detail(url))
    assert details == sorted([detail_url(body["id"], best), detail_url(body["id"], FHA)])
    assert not [url for url in traffic.requests if "/api/v1/actuators/" in url]
    assert not traffic.console_errors


def test_figures_module_words_the_api_diagram_and_says_no_data(page: Page) -> None:
    """figures.js is pure: the diagram is the API's (its zone cases are tested with
    documents/figures.py), fitted to a narrow chart and captioned from its ``layout.meta``."""
    page.goto("/")
    result = cast(
        dict[str, Any],
        page.evaluate(
            """async () => {
      const f = await import('/pages/engineer/figures.js');
      const sel = {cycle: {accel_s: 0.1, constant_s: 0.1, decel_s: 0.1, pause_s: 1},
                   cycle_time_s: 1.3, load: {speed_rpm: 40, torque_nm: 5, inertia_kgm2: 1.3},
                   mean_speed_rpm: 6.15, duty_cycle_percent: 23.08};
      const cand = {model: 'X', accel_torque_nm: 95.48, constant_torque_nm: 5,
                    decel_torque_nm: -85.48, rms_torque_nm: 35.57,
                    checks: [{name: 'continuous_duty', status: 'pass'}]};
      const name = 'a name long enough to be wrapped on a phone';
      const figure = {data: [{uid: 'zone-approx', name}],
                      layout: {meta: {zone: 'approximate', what: 'allowable continuous torque',
                                      torque: 2.9, speed_what: 'rated speed', speed: 60}}};
      const before = JSON.stringify(figure);
      const narrow = f.fitFigure(figure, {narrow: true});
      const unchanged = JSON.stringify(figure) === before;
      const approxCaption = f.diagramCaption(sel, cand, {max_torque_nm: 8.3}, figure, 'en');
      const noneCaption = f.diagramCaption(sel, cand, null, null, 'en');
      return {narrow, approxCaption, noneCaption, unchanged};
    }"""
        ),
    )
    assert result["unchanged"], "figure functions must not change their inputs"
    assert "<br>" in result["narrow"]["data"][0]["name"]
    assert result["narrow"]["layout"]["legend"]["orientation"] == "v"
    assert "rated speed = 60" in result["approxCaption"]
    assert "no data" in result["noneCaption"]


@pytest.mark.parametrize("viewport", [DESKTOP, PHONE], ids=["1280px", "375px"])
def test_layout_fits_and_screenshots(
    viewport: ViewportSize, browser: Browser, base_url: str, screenshot_dir: Path
) -> None:
    width = viewport["width"]
    context = browser.new_context(viewport=viewport, locale="en-US", base_url=base_url)
    try:
        view = context.new_page()
        view.goto("/")
        view.locator("#example").click()
        post_selection(view)
        # nothing wider than the window: no sideways scrolling of the whole page,
        # neither for the best candidate (approximate zone, many controllers) nor FHA's
        assert view.evaluate("document.documentElement.scrollWidth") <= width
        assert_no_leaked_values(view)
        choose(view, FHA)
        assert view.evaluate("document.documentElement.scrollWidth") <= width
        for chart in ("#chart-cycle", "#chart-diagram"):
            view.locator(chart).scroll_into_view_if_needed()
            box = view.locator(chart).bounding_box()
            assert box is not None
            assert box["width"] > 250
            assert box["height"] > 250
            assert box["x"] >= 0
            assert box["x"] + box["width"] <= width
        # the chapter's numbers are readable at this width
        expect(view.locator(f'#ranking-table tr[data-model="{FHA}"]')).to_contain_text("95.48")
        view.evaluate("window.scrollTo(0, 0)")
        view.screenshot(path=str(screenshot_dir / f"page-{width}.png"), full_page=True)
        view.locator("#detail").screenshot(path=str(screenshot_dir / f"detail-{width}.png"))
        view.locator(".ranking-card").screenshot(path=str(screenshot_dir / f"ranking-{width}.png"))
    finally:
        context.close()


@pytest.mark.parametrize("viewport", [DESKTOP, PHONE], ids=["1280px", "375px"])
@pytest.mark.parametrize("locale", ["en-US", "de-DE"])
def test_the_charts_are_drawn_with_the_legends_margin_given(
    viewport: ViewportSize, locale: str, browser: Browser, base_url: str
) -> None:
    """The legend below each chart needs a bottom margin larger than the API's figure
    gives; the page gives the one plotly.js would push it to (figures.js ``legendMargin``),
    so plotly.js draws the chart once, without moving the margin and drawing again."""
    context = browser.new_context(viewport=viewport, locale=locale, base_url=base_url)
    try:
        view = context.new_page()
        view.goto("/")
        view.locator("#example").click()
        post_selection(view)
        margins = view.evaluate(
            """() => ['chart-cycle', 'chart-diagram'].map(id => {
              const gd = document.getElementById(id);
              return [gd.layout.margin.b, gd._fullLayout._size.b];
            })"""
        )
        for given, drawn in margins:
            assert drawn > 48  # the API's figure's margin: the legend pushes it
            assert given == drawn
    finally:
        context.close()


def test_the_quotes_link_carries_the_selection_and_the_actuator(page: Page) -> None:
    page.goto("/")
    fill_worked_example(page)
    status, body = post_selection(page)
    assert status == 201
    choose(page, FHA)
    expect(page.locator(".sales-link")).to_have_attribute(
        "href", f"/sales.html?selection={body['id']}&model={FHA}"
    )


def test_a_brake_is_checked_when_the_box_is_ticked(page: Page) -> None:
    """The brake option sends ``brake``; CHA-25A-50's brake (90 Nm) holds T_L = 5 Nm."""
    page.goto("/")
    fill_worked_example(page)
    page.locator("#f-models").fill("CHA-25A-50")
    page.locator("#f-brake").check()
    status, body = post_selection(page)
    assert status == 201
    assert body["brake"] is True
    choose(page, "CHA-25A-50")
    brake = page.locator('#checks-table tr[data-check="brake_holding"]')
    expect(brake).to_have_count(1)
    expect(brake).to_contain_text("90")
    page.wait_for_selector('#detail[data-detail="ready"]')
    expect(brake).to_contain_text("holding torque = 90 Nm")


def test_the_servers_field_errors_come_in_the_pages_language(page: Page) -> None:
    """The page asks in its language (Accept-Language): a German page shows the API's
    German message at the field, marked as German, with the unit of the bound."""
    page.goto("/")
    page.get_by_role("button", name="Deutsch").click()
    fill_worked_example(page)
    page.locator("#f-t1").fill("0")  # HTML allows it, the API's bound is t_1 ≥ 0.0001 s
    with page.expect_response(lambda r: SELECTIONS_URL.search(r.url) is not None) as info:
        page.locator("#submit").click()
    answer = info.value
    assert answer.status == 422
    assert answer.headers["content-language"] == "de"
    error = page.locator("#err-t1 .error-line")
    expect(error).to_have_attribute("lang", "de")
    expect(error).to_contain_text("0,0001 s")
    expect(error).not_to_contain_text("greater than")
    # and in English once the page is English
    page.get_by_role("button", name="English").click()
    with page.expect_response(lambda r: SELECTIONS_URL.search(r.url) is not None):
        page.locator("#submit").click()
    expect(page.locator("#err-t1 .error-line")).to_contain_text("0.0001 s")
    expect(page.locator("#err-t1 .error-line")).to_have_attribute("lang", "en")


def test_the_ranking_rule_in_the_pages_words(page: Page) -> None:
    """The page words the answer's ranking rule itself: in English the same rule as the
    API's `ranking` (so the two cannot drift apart), in German in German."""
    page.goto("/")
    fill_worked_example(page)
    status, body = post_selection(page)
    assert status == 201
    rule = page.locator(".ranking-rule")
    rule.locator("summary").click()
    shown = " ".join(rule.locator("span").first.inner_text().split())
    assert shown == body["ranking"].replace("T_max", "Tmax").replace("J_A", "JA")
    page.get_by_role("button", name="Deutsch").click()
    page.locator(".ranking-rule summary").click()
    expect(page.locator(".ranking-rule")).to_contain_text("geeignete zuerst")
    expect(page.locator(".ranking-rule")).not_to_contain_text("suitable first")


def test_the_output_bearing_line_follows_the_answers_code_in_german(page: Page) -> None:
    """The answer says whether the output bearing was checked by a code beside its English
    text (a stored answer is the same in every language); the page words the code."""
    page.goto("/")
    page.get_by_role("button", name="Deutsch").click()
    fill_worked_example(page)
    page.locator("#f-ol").check()
    form = page.locator("#output-load")
    for name, value in (
        ("radial_force_n", "1000"),
        ("axial_force_n", "500"),
        ("radial_lever_m", "0.05"),
        ("axial_lever_m", "0.02"),
        ("required_life_h", "20000"),
    ):
        form.locator(f'[data-path="output_load.{name}"]').fill(value)
    status, body = post_selection(page)
    assert status == 201, body
    assert body["output_bearing_code"] == "output_bearing.checked"
    expect(page.locator("#sum-output-bearing")).to_contain_text(
        "Kippmoment, statische Tragsicherheit und Lebensdauer L_10 geprüft"
    )
