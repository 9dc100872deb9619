"""The load kinds and their fields, declared once on the request models
(``schemas/mechanism_spec.py``): served as ``GET /api/v1/mechanisms`` and written into the
page's ``frontend/pages/engineer/mechanism-spec.js``, which must not go stale."""

from __future__ import annotations

from pathlib import Path
from typing import get_args

from fastapi.testclient import TestClient
from pydantic import BaseModel, TypeAdapter, ValidationError

from actuator_selection.schemas.mechanism_spec import mechanism_spec, module_text
from actuator_selection.schemas.selections import LOAD_TYPES, LoadIn

PAGE_MODULE = Path(__file__).resolve().parents[2] / "frontend/pages/engineer/mechanism-spec.js"


def _models() -> dict[str, type[BaseModel]]:
    members = [get_args(m)[0] for m in get_args(get_args(LoadIn)[0])]
    return {get_args(m.model_fields["type"].annotation)[0]: m for m in members}


def test_the_page_module_is_generated_from_the_models() -> None:
    """Stale after a change to a load model: run `make mechanisms`."""
    assert PAGE_MODULE.read_text(encoding="utf-8") == module_text()


def test_the_api_lists_every_load_kind_with_its_fields(client: TestClient) -> None:
    answer = client.get("/api/v1/mechanisms")
    assert answer.status_code == 200
    body = answer.json()
    assert body == mechanism_spec().model_dump(mode="json")
    kinds = {k["type"]: k for k in body["kinds"]}
    assert list(kinds) == list(LOAD_TYPES)
    for kind, model in _models().items():
        own = [n for n in model.model_fields if n not in {"type", "speed", "speed_rpm"}]
        own = [n for n in own if n != "transmission"]
        assert [f["name"] for f in kinds[kind]["fields"]] == own, kind
        assert kinds[kind]["transmission"] == ("transmission" in model.model_fields)


def test_units_bounds_and_defaults_are_the_models() -> None:
    kinds = {k.type: k for k in mechanism_spec().kinds}
    belt = {f.name: f for f in kinds["belt"].fields}
    assert (belt["pulley_diameter_mm"].unit, belt["pulley_diameter_mm"].units) == ("mm", True)
    assert belt["pulley_diameter_mm"].minimum == 0.001
    assert belt["incline_deg"].default == 0.0
    assert not belt["incline_deg"].required
    assert belt["friction_coefficient"].unit == "–"
    assert not belt["friction_coefficient"].units
    screw = {f.name: f for f in kinds["ball_screw"].fields}
    assert (screw["lead_m"].unit, screw["lead_m"].units) == ("m", False)
    assert kinds["belt"].linear
    assert not kinds["rotary"].linear
    assert not kinds["direct"].linear
    assert kinds["rotary"].speed_field == "speed"
    assert kinds["direct"].speed_field == "speed_rpm"


def _refused(kind: str, name: str, value: float) -> bool:
    """Whether the load ``kind`` with ``name`` = ``value`` is refused at that field."""
    try:
        TypeAdapter(LoadIn).validate_python({"type": kind, name: value})
    except ValidationError as exc:
        return any(e["loc"][-1] == name for e in exc.errors())
    return False


def test_the_stated_bounds_are_the_ones_the_request_enforces() -> None:
    """Just past a stated bound is refused at that field; the bound itself is not."""
    for kind in mechanism_spec().kinds:
        for spec in kind.fields:
            if spec.maximum is not None:
                assert not _refused(kind.type, spec.name, spec.maximum), (kind.type, spec.name)
                assert _refused(kind.type, spec.name, spec.maximum * 1.5 + 1), spec.name
            if spec.minimum is not None:
                below = spec.minimum - abs(spec.minimum) - 1
                assert _refused(kind.type, spec.name, below), (kind.type, spec.name)
                at_minimum = _refused(kind.type, spec.name, spec.minimum)
                assert at_minimum == spec.exclusive_minimum, (kind.type, spec.name)
