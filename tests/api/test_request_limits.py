"""Request bodies: a stated size limit (413), a larger one for bulk endpoints, bad JSON (400)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Any

import pytest
from tests.api._sales_fixtures import WORKED_EXAMPLE, SalesApi, sales_api_with

from actuator_selection.config import Settings

__all__ = ["sales_api_with"]

SMALL = 2048
"""A body limit [bytes] that the worked example fits and a padded body does not."""


def _padded(size: int) -> bytes:
    """A selection body of about ``size`` bytes (the padding is an unknown field)."""
    return b'{"padding": "' + b"x" * size + b'"}'


def _body_too_large(response: Any, limit: int) -> None:
    assert response.status_code == 413, response.text[:300]
    (entry,) = response.json()["detail"]
    assert entry["loc"] == ["body"]
    assert entry["type"] == "body_too_large"
    assert f"larger than {limit} bytes" in entry["msg"]


def test_the_default_body_limit_is_a_mebibyte() -> None:
    assert Settings().max_body_bytes == 1 << 20
    assert Settings().max_bulk_body_bytes > Settings().max_body_bytes


@pytest.fixture
def small(sales_api_with: Callable[..., SalesApi]) -> SalesApi:
    """The app with a 2 KiB body limit and a 64 KiB bulk limit."""
    return sales_api_with(max_body_bytes=SMALL, max_bulk_body_bytes=32 * SMALL)


def test_a_body_over_the_limit_is_413_naming_the_limit(small: SalesApi) -> None:
    response = small.client.post(
        "/api/v1/selections",
        content=_padded(2 * SMALL),
        headers={"content-type": "application/json"},
    )
    _body_too_large(response, SMALL)


def test_a_chunked_body_over_the_limit_is_413_too(small: SalesApi) -> None:
    def chunks() -> Iterator[bytes]:
        yield b'{"padding": "'
        for _ in range(4):
            yield b"x" * SMALL
        yield b'"}'

    response = small.client.post(
        "/api/v1/selections", content=chunks(), headers={"content-type": "application/json"}
    )
    _body_too_large(response, SMALL)


def test_a_body_within_the_limit_is_served(small: SalesApi) -> None:
    assert small.client.post("/api/v1/selections", json=WORKED_EXAMPLE).status_code == 201


def test_the_batch_takes_bodies_over_the_default_limit_up_to_the_bulk_limit(
    small: SalesApi,
) -> None:
    cases = [WORKED_EXAMPLE] * 40  # ≈ 7 KB: over 2 KiB, under 64 KiB
    response = small.client.post("/api/v1/selections/batch", json={"cases": cases, "top": 1})
    assert response.status_code == 200, response.text
    assert len(response.json()["results"]) == 40
    too_many = {"cases": [WORKED_EXAMPLE] * 1000, "top": 1}  # ≈ 180 KB
    _body_too_large(small.client.post("/api/v1/selections/batch", json=too_many), 32 * SMALL)


@pytest.mark.parametrize(
    "body",
    [
        b"[" * 100_000 + b"]" * 100_000,
        b'{"load": ' * 20_000 + b"1" + b"}" * 20_000,
    ],
    ids=["arrays", "objects"],
)
def test_json_nested_past_the_parser_is_400_in_the_error_shape(client: Any, body: bytes) -> None:
    response = client.post(
        "/api/v1/selections", content=body, headers={"content-type": "application/json"}
    )
    assert response.status_code == 400
    assert response.json()["detail"] == [
        {
            "loc": ["body"],
            "msg": "the body could not be parsed as JSON (malformed, or nested too deeply)",
            "type": "json_invalid",
            "code": "json_invalid",
            "params": {},
        }
    ]
