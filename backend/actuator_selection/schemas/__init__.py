"""The API contract: pydantic request and response models (never the ORM tables)."""
