"""The error handlers: a write conflict is a 409 that says to retry, never a 500."""

from __future__ import annotations

from typing import Annotated, Any, Literal

import pytest
from fastapi import FastAPI
from fastapi.testclient import TestClient
from pydantic import BaseModel, Field, ValidationError
from sqlalchemy.exc import IntegrityError

from actuator_selection.http import errors


def test_a_write_conflict_is_409_and_says_to_retry() -> None:
    app = FastAPI()
    errors.install(app)

    @app.post("/conflict")
    def conflict() -> None:
        # What a unique index raises when a concurrent transaction committed the key first.
        raise IntegrityError("INSERT INTO controllers ...", {}, Exception("duplicate key"))

    @app.post("/broken")
    def broken() -> None:
        raise RuntimeError("a bug")

    client = TestClient(app, raise_server_exceptions=False)
    response = client.post("/conflict")
    assert response.status_code == 409
    (entry,) = response.json()["detail"]
    assert entry["type"] == "write_conflict"
    assert "send it again" in entry["msg"]
    assert client.post("/broken").status_code == 500  # other errors are not dressed as 409


@pytest.mark.parametrize(
    ("method", "path", "status", "loc", "type_"),
    [
        ("get", "/api/v1/actuators/NOPE", 404, ["path", "model"], "not_found"),
        ("get", "/api/v1/selections/nope", 404, ["path", "selection_id"], "not_found"),
        ("get", "/api/v1/controllers/999", 404, ["path", "row"], "not_found"),
        ("get", "/api/v1/no-such-route", 404, ["path"], "not_found"),
        ("delete", "/api/v1/health", 405, ["request"], "method_not_allowed"),
        ("get", "/api/v1/quotes", 401, ["header", "Authorization"], "unauthorized"),
        ("post", "/api/v1/selections", 422, ["body"], "missing"),
    ],
)
def test_every_error_has_the_one_shape(
    client: TestClient, method: str, path: str, status: int, loc: list[str], type_: str
) -> None:
    """Every 4xx answers ``{"detail": [{"loc", "msg", "type"}]}`` naming where and which rule."""
    response = getattr(client, method)(path)
    assert response.status_code == status
    entries = response.json()["detail"]
    assert isinstance(entries, list)
    assert all(set(e) >= {"loc", "msg", "type"} and e["msg"] for e in entries)
    assert (entries[0]["loc"], entries[0]["type"]) == (loc, type_)


class _Cat(BaseModel):
    kind: Literal["cat"]
    lives: int


class _Dog(BaseModel):
    kind: Literal["dog"]
    bark: str


class _Owner(BaseModel):
    pets: list[Annotated[_Cat | _Dog, Field(discriminator="kind")]]
    first: _Cat | _Dog = Field(default=None, discriminator="kind")  # type: ignore[assignment]
    by_name: dict[str, Annotated[_Cat | _Dog, Field(discriminator="kind")]] = {}
    either: int | str = 0


def _locs(value: dict[str, Any]) -> list[list[str | int]]:
    try:
        _Owner.model_validate(value)
    except ValidationError as exc:
        return [errors.field_loc(_Owner, e["loc"]) for e in exc.errors()]
    raise AssertionError("valid")


def test_field_loc_drops_the_tags_of_discriminated_unions() -> None:
    assert _locs({"pets": [{"kind": "dog", "bark": "woof"}, {"kind": "cat", "lives": "x"}]}) == [
        ["pets", 1, "lives"]
    ]
    assert _locs({"pets": [], "by_name": {"rex": {"kind": "dog"}}}) == [["by_name", "rex", "bark"]]
    assert _locs({"pets": [], "first": {"kind": "cat"}}) == [["first", "lives"]]


def test_field_loc_keeps_what_it_cannot_follow() -> None:
    # A plain union: pydantic names each member it tried; those are kept as they are.
    locs = _locs({"pets": [], "either": [1]})
    assert ["either", "int"] in locs
    assert errors.field_loc(_Owner, ["nope", 3]) == ["nope", 3]
