"""The one error shape of every error answer (see ``api/errors.py``), for the OpenAPI document."""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field


class ErrorDetail(BaseModel):
    """One problem: where it is, what rule it breaks in words, the rule's name for programs.

    Catalogue and price file problems add ``file``, ``line`` and ``column``.
    """

    model_config = ConfigDict(
        extra="allow",
        json_schema_extra={
            "examples": [
                {
                    "loc": ["body", "cycle", "accel_s"],
                    "msg": "Input should be greater than or equal to 0.0001",
                    "type": "greater_than_equal",
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
                            "msg": "Input should be greater than or equal to 0",
                            "type": "greater_than_equal",
                        }
                    ]
                }
            ]
        }
    )

    detail: list[ErrorDetail] = Field(description="one entry per problem")
