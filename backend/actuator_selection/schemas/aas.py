"""The query of an IDTA 02021 sizing record (``GET /selections/{id}/aas``)."""

from __future__ import annotations

from pydantic import Field, field_validator

from actuator_selection.schemas.common import StrictModel

XML_NONCHARACTERS_RULE = "must not contain U+FFFE or U+FFFF, which an AASX (XML) cannot hold"


class AasRecordQuery(StrictModel):
    """Names the record carries, and the chosen candidate; text by the one text rule."""

    project_name: str | None = Field(
        default=None, max_length=200, description="SizingProjectName (default: the selection)"
    )
    client_name: str = Field(default="", max_length=200, description="ClientName")
    model: str | None = Field(
        default=None,
        max_length=60,
        description="the chosen candidate (default: the first of the ranking)",
    )

    @field_validator("project_name", "client_name", "model")
    @classmethod
    def _xml_characters(cls, value: str | None) -> str | None:
        if value is not None and ("\ufffe" in value or "\uffff" in value):
            raise ValueError(XML_NONCHARACTERS_RULE)
        return value
