"""The catalogue's values are declared once: the engine's record, the file's columns and
the seed's derivations agree with the declarations (catalogue/fields.py)."""

from __future__ import annotations

import dataclasses
import re
import typing
from pathlib import Path

import pytest

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.csvio import read
from actuator_selection.catalogue.fields import (
    ACTUATOR_FIELDS,
    DERIVED_ACTUATOR_ATTRIBUTES,
    ENGINE_FIELDS,
    OPERAND_FIELDS,
    CatalogueField,
    Kind,
    Source,
)
from actuator_selection.catalogue.files import ACTUATORS
from actuator_selection.sizing.checks import Operands
from actuator_selection.sizing.engine.catalogue import CATALOGUE_OPERANDS

SEED = Path(__file__).resolve().parents[2] / "seed_data"


def _stored_type(field: CatalogueField) -> object:
    """The Python type of a stored value: required, or None where the catalogue has none."""
    kind = float if field.kind is Kind.NUMBER else str
    return kind if field.required else kind | None


def test_the_engines_record_holds_every_engine_field_and_no_other() -> None:
    """Actuator is generated from the declarations; a value declared for the checks and
    missing from it, or an attribute it has that no declaration (nor a derivation)
    explains, fails."""
    attributes = {f.name: f for f in dataclasses.fields(Actuator)}
    declared = {f.name for f in ENGINE_FIELDS}
    assert sorted(declared - attributes.keys()) == [], "declared engine=True, not on Actuator"
    assert sorted(attributes.keys() - declared - DERIVED_ACTUATOR_ATTRIBUTES.keys()) == [], (
        "on Actuator, but declared nowhere in ACTUATOR_FIELDS (engine=True)"
    )


@pytest.mark.parametrize("field", ENGINE_FIELDS, ids=lambda f: f.name)
def test_the_engines_record_types_each_value_as_declared(field: CatalogueField) -> None:
    hints = typing.get_type_hints(Actuator)
    assert hints[field.name] == _stored_type(field)
    default = {f.name: f.default for f in dataclasses.fields(Actuator)}[field.name]
    assert default is (dataclasses.MISSING if field.required else None)


def test_each_operand_a_field_feeds_is_an_operand_the_engine_builds_once() -> None:
    names = [f.operand_name for f in OPERAND_FIELDS]
    assert len(set(CATALOGUE_OPERANDS)) == len(CATALOGUE_OPERANDS)
    assert set(names) <= set(Operands._fields)
    assert set(names) <= set(CATALOGUE_OPERANDS)
    assert all(f.kind is Kind.NUMBER for f in OPERAND_FIELDS)


def test_names_and_headers_are_unique_and_carry_no_spaces() -> None:
    names = [f.name for f in ACTUATOR_FIELDS]
    headers = [f.header for f in ACTUATOR_FIELDS]
    assert len(set(names)) == len(names)
    assert len(set(headers)) == len(headers)
    assert all(re.fullmatch(r"[a-z][a-z0-9_]*", n) for n in (*names, *headers))


def test_the_file_has_a_column_per_value_in_declared_order() -> None:
    assert [c.name for c in ACTUATORS.columns] == [f.header for f in ACTUATOR_FIELDS]
    assert [c.attribute for c in ACTUATORS.columns] == [f.name for f in ACTUATOR_FIELDS]
    header = (SEED / ACTUATORS.file).read_text(encoding="utf-8").splitlines()[0]
    assert header.split(",") == [f.header for f in ACTUATOR_FIELDS]


def test_a_published_unit_other_than_the_stored_one_has_its_own_header() -> None:
    """kN in the file, N stored: the header names the published unit, the name the stored
    one, and the scale converts (house style: the unit is in every name)."""
    for field in ACTUATOR_FIELDS:
        assert (field.scale != 1.0) == (field.csv is not None), field.name


def test_only_values_declared_derivable_are_derived_in_the_seed() -> None:
    """A row's derivation names the values it derived; each must be declared
    PUBLISHED_OR_DERIVED (the others are published or empty, never worked out)."""
    records, problems = read(ACTUATORS, SEED)
    assert not problems
    derivable = {f.name for f in ACTUATOR_FIELDS if f.source is Source.PUBLISHED_OR_DERIVED}
    values = [f for f in ACTUATOR_FIELDS if f.source is not Source.ROW]
    named: set[str] = set()
    for record in records:
        text = record.values["derivation"] or ""
        named |= {
            f.name for f in values if re.search(rf"\b({f.name}|{f.header})\b", text) is not None
        }
    assert named, "the seed derives at least the CHA's rated speed"
    assert named <= derivable, f"derived but declared published only: {named - derivable}"


def test_row_bookkeeping_is_text_and_the_engine_never_reads_it() -> None:
    for field in ACTUATOR_FIELDS:
        if field.source is Source.ROW:
            assert field.kind is Kind.TEXT, field.name
            assert not field.engine, field.name
