"""The text rule (``StrictModel._text_rule``) is compiled into each model's schema for
its text fields only: a number, a flag or a nested model costs no call of it (a batch
of 10,000 cases has ~10⁵ numbers). The rule's errors are the hostile-input tests'."""

from __future__ import annotations

from actuator_selection.app import create_app  # noqa: F401  (every schema imported)
from actuator_selection.schemas.batch import BatchCaseIn
from actuator_selection.schemas.common import StrictModel, _text_fields


def _models(base: type[StrictModel]) -> list[type[StrictModel]]:
    found = []
    for sub in base.__subclasses__():
        found += [sub, *_models(sub)]
    return found


def test_every_strict_model_runs_the_text_rule_on_its_text_fields_only() -> None:
    models = [m for m in _models(StrictModel) if m.__pydantic_complete__]
    assert len(models) > 30
    for model in models:
        rule = model.__pydantic_decorators__.field_validators["_text_rule"]
        assert set(rule.info.fields) == _text_fields(model), model


def test_a_batch_case_checks_its_text_and_not_its_numbers() -> None:
    rule = BatchCaseIn.__pydantic_decorators__.field_validators["_text_rule"]
    assert "case_id" in rule.info.fields
    assert not {"load", "cycle", "high_dynamics", "top"} & set(rule.info.fields)
