"""Links that a browser opens without an Authorization header."""

from __future__ import annotations

from datetime import datetime

from pydantic import Field

from actuator_selection.schemas.common import ResponseModel


class DocumentLinkOut(ResponseModel):
    """A short-lived link to a document, signed for the key that asked for it."""

    url: str = Field(description="path of the document with its ``access`` token")
    expires_at: datetime = Field(description="when the link stops working (UTC)")
