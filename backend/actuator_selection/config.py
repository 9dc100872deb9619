"""Settings from the environment (``DATABASE_URL``, ``HOST``, ``PORT``, ``REQUIRE_API_KEY``)."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from pydantic_settings import BaseSettings, SettingsConfigDict

REPO_ROOT = Path(__file__).resolve().parents[2]
"""The checkout this package lives in: ``backend/actuator_selection`` → repository root."""

DEFAULT_DATABASE_URL = f"sqlite:///{REPO_ROOT / 'var' / 'actuator_selection.sqlite3'}"
SEED_DIR = REPO_ROOT / "seed_data"
FRONTEND_DIR = REPO_ROOT / "frontend"


class Settings(BaseSettings):
    """Service settings; every field can be set by the environment variable of its name."""

    model_config = SettingsConfigDict(env_prefix="", case_sensitive=False, extra="ignore")

    database_url: str = DEFAULT_DATABASE_URL
    host: str = "127.0.0.1"
    port: int = 8000
    require_api_key: bool = False
    """When true, every endpoint needs an API key; otherwise catalogue reads and
    selections are open and only admin and sales operations need one."""


@lru_cache
def get_settings() -> Settings:
    """The process-wide settings, read once."""
    return Settings()
