"""Settings from the environment: database, address, API keys, request and database limits."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from pydantic import Field
from pydantic_settings import BaseSettings, SettingsConfigDict

from actuator_selection.db.engine import EngineLimits

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
    workers: int = Field(default=1, ge=1, le=64)
    """Server processes of ``serve``; several share the load of one host's cores."""
    require_api_key: bool = False
    """When true, every endpoint needs an API key; otherwise catalogue reads and
    selections are open and only admin and sales operations need one."""

    max_body_bytes: int = Field(default=1 << 20, ge=1024)
    """Largest request body [bytes] (413 above); 1 MiB holds any single request."""
    max_bulk_body_bytes: int = Field(default=32 << 20, ge=1024)
    """Largest body [bytes] of the bulk endpoints: batch selection, catalogue and price
    imports (20,000 batch cases are about 5 MB of JSON)."""
    max_concurrent_requests: int = Field(default=8, ge=1, le=64)
    """API requests worked on at once per process; the database pool holds as many
    connections again as spare, so none waits for a connection."""
    max_queued_requests: int = Field(default=128, ge=0)
    """API requests that may wait for a free place; beyond that 503 at once."""
    queue_timeout_s: float = Field(default=30.0, gt=0)
    """Longest wait for a free place [s], then 503 with Retry-After."""
    db_lock_timeout_s: float = Field(default=5.0, gt=0)
    """Longest wait for a database lock [s] (SQLite busy timeout, PostgreSQL lock_timeout)."""
    db_statement_timeout_s: float = Field(default=60.0, gt=0)
    """Longest database statement [s] (PostgreSQL statement_timeout)."""

    def engine_limits(self) -> EngineLimits:
        """The database limits that go with the admission limits."""
        return EngineLimits(
            lock_timeout_s=self.db_lock_timeout_s,
            statement_timeout_s=self.db_statement_timeout_s,
            pool_size=self.max_concurrent_requests,
            pool_timeout_s=self.db_lock_timeout_s,
        )


@lru_cache
def get_settings() -> Settings:
    """The process-wide settings, read once."""
    return Settings()
