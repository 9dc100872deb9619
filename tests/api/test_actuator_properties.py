"""The API's actuator is derived from the declared catalogue values (catalogue/fields.py):
a property per value, described by its symbol, words and unit, showing the stored value;
the words of every value are in both languages."""

from __future__ import annotations

from pathlib import Path

import pytest
from fastapi.testclient import TestClient

from actuator_selection.catalogue.csvio import read
from actuator_selection.catalogue.fields import ACTUATOR_FIELDS, CatalogueField
from actuator_selection.catalogue.files import ACTUATORS
from actuator_selection.i18n.localize import translations
from actuator_selection.phrases.messages import Text

SEED = Path(__file__).resolve().parents[2] / "seed_data"
BESIDES = ["continuous_duty_zone", "continuous_duty_zone_source", "output_turns_opposite_to_motor"]
"""The actuator's properties that are not values of actuators.csv."""


def test_the_actuator_schema_has_a_property_per_value(client: TestClient) -> None:
    schema = client.get("/openapi.json").json()["components"]["schemas"]["ActuatorOut"]
    properties = schema["properties"]
    assert [p for p in properties if p not in BESIDES] == [f.name for f in ACTUATOR_FIELDS]
    for field in ACTUATOR_FIELDS:
        assert properties[field.name]["description"] == field.description
        nullable = {"type": "null"} in properties[field.name].get("anyOf", [])
        assert nullable == (not field.required), field.name
    assert set(schema["required"]) == set(properties) - {"output_turns_opposite_to_motor"}


def test_an_actuator_shows_every_value_as_the_file_gives_it(client: TestClient) -> None:
    """Each value of the seed's row, in its stored unit (kN → N), reaches GET /actuators."""
    records, problems = read(ACTUATORS, SEED)
    assert not problems
    row = next(r.values for r in records if r.values["model"] == "CHA-20A-30")
    shown = client.get("/api/v1/actuators/CHA-20A-30").json()
    assert {f.name: shown[f.name] for f in ACTUATOR_FIELDS} == row
    assert shown["output_bearing_dynamic_tilting_moment_nm"] == 172  # CHA 8/2018 Table 55.1


@pytest.mark.parametrize("field", ACTUATOR_FIELDS, ids=lambda f: f.name)
def test_every_value_has_words_in_both_languages(field: CatalogueField) -> None:
    assert isinstance(field.label, Text), "mark the words with N_ so that they are extracted"
    assert translations("de").get(field.label), f"no German for {field.label!r}: make messages"
