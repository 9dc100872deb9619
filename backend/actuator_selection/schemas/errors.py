"""The one error shape of every error answer (see ``http/errors.py``), for the OpenAPI document."""

from __future__ import annotations

from typing import Any

from pydantic import BaseModel, ConfigDict, Field


class ErrorDetail(BaseModel):
    """One problem: where it is, what rule it breaks in words, the rule's name for programs,
    and the rule's stable code with its parameters (for a client that words the message
    itself). ``msg`` is in the language of ``Accept-Language`` (en, de; default en).

    Catalogue and price file problems add ``file``, ``line`` and ``column``.
    """

    model_config = ConfigDict(
        extra="allow",
        json_schema_extra={
            "examples": [
                {
                    "loc": ["body", "cycle", "accel_s"],
                    "msg": "Input should be greater than or equal to 0.0001 s",
                    "type": "greater_than_equal",
                    "code": "greater_than_equal",
                    "params": {"ge": 0.0001, "unit": "s"},
                }
            ]
        },
    )

    loc: list[str | int] = Field(
        description='where: ["body", <field>, ...], ["path", <name>], ["query", <name>], '
        '["header", <name>], or ["request"] for the request as a whole; body locations name '
        "the body's fields (and list indices) only"
    )
    msg: str = Field(description="the rule broken, in words")
    type: str = Field(description="the rule's name, for programs (e.g. not_found, unauthorized)")
    code: str = Field(
        description="the rule's stable code, the key of its message template: pydantic's "
        "type for field errors (greater_than_equal, missing …), the rule of a domain error "
        "(cycle_not_closed, must_be_positive …), else the same as type"
    )
    params: dict[str, Any] = Field(
        description="the values the message names, the same in every language (e.g. "
        '{"ge": 0.0001, "unit": "s"}); words among them are English'
    )
    file: str | None = Field(default=None, description="catalogue or price file problems: the file")
    line: int | None = Field(default=None, description="… its line (0: the file as a whole)")
    column: str | None = Field(default=None, description="… its column, if one")


class ErrorOut(BaseModel):
    """Every error answer, whatever its status: a list of problems."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "detail": [
                        {
                            "loc": ["body", "load", "torque_nm"],
                            "msg": "Input should be greater than or equal to 0 Nm",
                            "type": "greater_than_equal",
                            "code": "greater_than_equal",
                            "params": {"ge": 0, "unit": "Nm"},
                        }
                    ]
                }
            ]
        }
    )

    detail: list[ErrorDetail] = Field(description="one entry per problem")
