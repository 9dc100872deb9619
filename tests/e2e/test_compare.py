"""The side-by-side comparison of 2–4 candidates on the engineer's page (issue 13).

The worked example (Table 516.1) against the whole catalogue; three candidates marked in
the ranking; every number the comparison shows (its ``data-value``) equals the one in the
POST /selections answer, the margin is (limit − value)/limit of those numbers and the
largest margin of each check is the one highlighted. A fifth mark is refused, the marks
survive filtering, a language switch relabels, unmarking removes a column, the permalink
carries the marks and a new selection clears them.
"""

from __future__ import annotations

from typing import Any, cast
from urllib.parse import parse_qs, urlsplit

import pytest
from playwright.sync_api import Page, expect

from .conftest import Traffic
from .test_engineer_page import assert_no_leaked_values, fill_worked_example, post_selection

pytestmark = pytest.mark.browser

FIGURES = ("accel_torque_nm", "constant_torque_nm", "decel_torque_nm", "rms_torque_nm")


def box(page: Page, model: str) -> Any:
    return page.locator(f'#ranking-table .compare-toggle[data-model="{model}"]')


def compared_models(page: Page) -> list[str]:
    return cast(
        list[str],
        page.locator("#compare-table thead th[data-model]").evaluate_all(
            "ths => ths.map(th => th.dataset.model)"
        ),
    )


def shown_value(page: Page, selector: str) -> float | None:
    """The full number a cell keeps in data-value; None for a cell without one ("–")."""
    cell = page.locator(selector)
    expect(cell).to_have_count(1)
    raw = cell.locator(".value").first.get_attribute("data-value")
    return None if raw is None else float(raw)


def margin(check: dict[str, Any]) -> float | None:
    value, limit = check["value"], check["limit"]
    if value is None or limit is None or not limit > 0:
        return None
    return float((limit - value) / limit * 100)


def assert_matches_answer(page: Page, answer: dict[str, Any], models: list[str]) -> None:
    """Every cell of the comparison against the answer, model by model and check by check."""
    assert compared_models(page) == models
    by_model = {c["model"]: c for c in answer["candidates"]}
    for model in models:
        c = by_model[model]
        cell = f'td[data-model="{model}"]'
        row = "#compare-table tr[data-row="
        expect(page.locator(f'{row}"family"] {cell}')).to_have_text(c["family"])
        assert shown_value(page, f'{row}"gear_ratio"] {cell}') == c["gear_ratio"]
        expect(page.locator(f'{row}"verdict"] {cell} .badge')).to_have_class(
            f"badge verdict-{c['verdict']}"
        )
        for field in FIGURES:
            assert shown_value(page, f'{row}"{field}"] {cell}') == c[field], field
        for check in c["checks"]:
            part = f'#compare-table tr[data-check="{check["name"]}"]'
            assert (
                shown_value(page, f'{part}[data-part="value"] td[data-model="{model}"]')
                == (check["value"])
            )
            assert (
                shown_value(page, f'{part}[data-part="limit"] td[data-model="{model}"]')
                == (check["limit"])
            )
            expected = margin(check)
            got = shown_value(page, f'{part}[data-part="margin"] td[data-model="{model}"]')
            assert got == (None if expected is None else pytest.approx(expected, rel=1e-12))
            status = page.locator(f'{part}[data-part="status"] td[data-model="{model}"]')
            expect(status).to_have_attribute("data-status", check["status"])
    # the largest margin of each check, and only it, is highlighted
    for rule in answer["check_rules"]:
        margins: dict[str, float] = {}
        for model in models:
            check = next((k for k in by_model[model]["checks"] if k["name"] == rule["name"]), None)
            found = None if check is None else margin(check)
            if found is not None:
                margins[model] = found
        best = (
            sorted(m for m, v in margins.items() if v == max(margins.values()))
            if len(margins) > 1
            else []
        )
        highlighted = page.locator(
            f'#compare-table tr[data-check="{rule["name"]}"][data-part="margin"] td[data-best]'
        ).evaluate_all("tds => tds.map(td => td.dataset.model)")
        assert sorted(highlighted) == best, rule["name"]


def test_three_candidates_side_by_side(page: Page, traffic: Traffic) -> None:
    page.goto("/")
    page.get_by_role("button", name="English").click()
    fill_worked_example(page)
    status, answer = post_selection(page)
    assert status == 201
    candidates = answer["candidates"]
    assert len(candidates) >= 5, "the whole catalogue answers with more than four candidates"
    # one of each verdict where there is one, else the next in the ranking
    marked: list[str] = []
    for verdict in ("suitable", "unconfirmed", "unsuitable"):
        found = next((c["model"] for c in candidates if c["verdict"] == verdict), None)
        if found:
            marked.append(found)
    for c in candidates:
        if len(marked) == 3:
            break
        if c["model"] not in marked:
            marked.append(c["model"])

    expect(page.locator("#compare-status")).to_contain_text("Mark 2 to 4")
    # keyboard: the mark is a checkbox named by its model
    first = page.get_by_role("checkbox", name=f"Compare {marked[0]}")
    first.focus()
    page.keyboard.press("Space")
    expect(first).to_be_checked()
    expect(page.locator("#compare-more")).to_contain_text(marked[0])
    for model in marked[1:]:
        box(page, model).check()
    expect(page.locator("#compare-status")).to_have_text(
        "3 of at most 4 actuators marked for comparison."
    )
    # marking did not choose another candidate
    assert page.locator("#detail").get_attribute("data-model") == candidates[0]["model"]
    expect(page.locator("#compare-table caption")).to_contain_text("side by side")
    assert_matches_answer(page, answer, marked)

    # the marks survive the verdict filter and travel in the permalink
    page.locator('.filter-button[data-filter="suitable"]').click()
    page.locator('.filter-button[data-filter="all"]').click()
    assert compared_models(page) == marked
    permalink = page.locator("#permalink").input_value()
    assert parse_qs(urlsplit(permalink).query)["compare"] == [",".join(marked)]

    # a fourth is taken, a fifth refused with a polite message
    others = [c["model"] for c in candidates if c["model"] not in marked]
    box(page, others[0]).check()
    assert compared_models(page) == [*marked, others[0]]
    box(page, others[1]).click()
    expect(box(page, others[1])).not_to_be_checked()
    refusal = page.locator("#compare-status")
    expect(refusal).to_contain_text(f"{others[1]} not marked: at most 4")
    expect(refusal).to_have_attribute("role", "status")
    expect(refusal).to_be_visible()
    assert compared_models(page) == [*marked, others[0]]

    # switching the language relabels (units as the chapter prints them in German)
    speed_value = '#compare-table tr[data-check="max_speed"][data-part="value"] td >> nth=0'
    expect(page.locator(speed_value)).to_contain_text("rpm")
    page.get_by_role("button", name="Deutsch").click()
    expect(page.locator("#compare-heading")).to_have_text("Vergleich")
    expect(page.locator("#compare-table thead th").first).to_have_text("Größe")
    expect(page.locator("#compare-table")).to_contain_text("Reserve")
    expect(page.locator(speed_value)).to_contain_text("min⁻¹")
    expect(page.get_by_role("checkbox", name=f"{marked[0]} vergleichen")).to_be_checked()
    assert compared_models(page) == [*marked, others[0]]

    # unmarking removes the column: the ranking's box, then the column's own button
    box(page, others[0]).uncheck()
    assert compared_models(page) == marked
    page.get_by_role("button", name=f"{marked[1]} aus dem Vergleich nehmen").click()
    assert compared_models(page) == [marked[0], marked[2]]
    expect(box(page, marked[1])).not_to_be_checked()
    assert_matches_answer(page, answer, [marked[0], marked[2]])
    assert_no_leaked_values(page)

    # the permalink reopens the comparison
    kept = page.locator("#permalink").input_value()
    page.goto(kept)
    page.wait_for_selector("#compare-table")
    assert compared_models(page) == [marked[0], marked[2]]

    # a new selection clears the marks
    status, _ = post_selection(page)
    assert status == 201
    expect(page.locator("#compare")).to_have_count(0)
    expect(page.locator("#ranking-table .compare-toggle:checked")).to_have_count(0)
    assert "compare=" not in page.locator("#permalink").input_value()
    assert traffic.console_errors == []
