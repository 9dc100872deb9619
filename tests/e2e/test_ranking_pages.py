"""The page asks for the ranking's first candidates and reads the rest on "show more".

The engineer's page posts ``?top=25``: the answer lists 25 of the starter catalogue's
candidates with the whole ranking's counts, and "Show 25 more" reads the next pages by the
answer's cursor until the table holds the whole ranking in its order. A permalink to an
actuator beyond the first 25 reads the ranking whole and shows that actuator.
"""

from __future__ import annotations

import json

import httpx
import pytest
from playwright.sync_api import Page, expect

from .test_engineer_page import fill_worked_example, post_selection, wait_for_charts

pytestmark = pytest.mark.browser


def _whole_ranking(base_url: str, selection_id: str) -> list[str]:
    response = httpx.get(
        f"{base_url}/api/v1/selections/{selection_id}/candidates",
        params={"format": "jsonl"},
        timeout=30,
    )
    return [json.loads(line)["model"] for line in response.text.splitlines()]


def _table_models(page: Page) -> list[str]:
    models: list[str] = page.locator("#ranking-table tbody tr").evaluate_all(
        "rows => rows.map(r => r.dataset.model)"
    )
    return models


def test_the_page_shows_the_first_candidates_and_loads_more(page: Page, base_url: str) -> None:
    page.goto("/")
    fill_worked_example(page)
    status, body = post_selection(page)
    assert status == 201, body
    assert len(body["candidates"]) == 25
    total = body["total_candidates"]
    assert total > 50  # the starter catalogue: three pages
    rows = page.locator("#ranking-table tbody tr")
    page.locator(".ranking-card .table-scroll").hover()  # the first rows' rest comes
    expect(rows).to_have_count(25)
    more = page.locator("#ranking-more")
    expect(more).to_contain_text(f"25 of {total}")
    expect(page.locator('.filter-button[data-filter="all"] .count')).to_have_text(f"({total})")
    counts = body["verdict_counts"]
    for verdict, n in counts.items():
        expect(page.locator(f'.filter-button[data-filter="{verdict}"] .count')).to_have_text(
            f"({n})"
        )

    page.locator("#ranking-more-button").click()
    expect(rows).to_have_count(50)
    expect(more).to_contain_text(f"50 of {total}")
    page.locator("#ranking-more-button").click()
    expect(rows).to_have_count(total)
    expect(page.locator("#ranking-more-button")).to_have_count(0)
    assert _table_models(page) == _whole_ranking(base_url, body["id"])


def test_a_permalink_beyond_the_first_candidates_shows_its_actuator(
    page: Page, base_url: str
) -> None:
    page.goto("/")
    fill_worked_example(page)
    status, body = post_selection(page)
    assert status == 201, body
    ranking = _whole_ranking(base_url, body["id"])
    far = ranking[40]
    assert far not in {c["model"] for c in body["candidates"]}
    page.goto(f"/?selection={body['id']}&model={far}")
    wait_for_charts(page, far)
    expect(page.locator(f'#ranking-table tbody tr[data-model="{far}"]')).to_have_count(1)
