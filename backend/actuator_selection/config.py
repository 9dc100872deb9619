"""Settings from the environment: database, address, API keys, request and database limits,
the seller and the default terms of quotes."""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal
from functools import lru_cache
from pathlib import Path

from pydantic import Field, SecretStr
from pydantic_settings import BaseSettings, SettingsConfigDict

from actuator_selection.sales.quote_terms import QuoteDefaults, SellerParty

REPO_ROOT = Path(__file__).resolve().parents[2]
"""The checkout this package lives in: ``backend/actuator_selection`` → repository root."""

DEFAULT_DATABASE_URL = f"sqlite:///{REPO_ROOT / 'var' / 'actuator_selection.sqlite3'}"
SEED_DIR = REPO_ROOT / "seed_data"
FRONTEND_DIR = REPO_ROOT / "frontend"

PLACEHOLDER_SELLER_NAME = "Your company"
"""The default ``SELLER_NAME``: a quote document made with it carries a warning banner."""


@dataclass(frozen=True, slots=True, kw_only=True)
class EngineLimits:
    """How long the database may make a request wait, and how many connections it holds
    (what :func:`~actuator_selection.db.engine.make_engine` is given).

    Parameters
    ----------
    lock_timeout_s
        Longest wait for a lock [s]: SQLite's busy timeout, PostgreSQL's ``lock_timeout``.
    statement_timeout_s
        Longest statement [s] (PostgreSQL ``statement_timeout``).
    pool_size
        Connections kept open; as many again may be opened under load.
    pool_timeout_s
        Longest wait for a free connection [s], then ``sqlalchemy.exc.TimeoutError`` (503).
    connect_timeout_s
        Longest wait for a new PostgreSQL connection [s] (libpq ``connect_timeout``;
        whole seconds, at least 2), then the database counts as unreachable (503).
    """

    lock_timeout_s: float = 5.0
    statement_timeout_s: float = 60.0
    pool_size: int = 8
    pool_timeout_s: float = 10.0
    connect_timeout_s: int = 5


class Settings(BaseSettings):
    """Service settings; every field can be set by the environment variable of its name."""

    model_config = SettingsConfigDict(env_prefix="", case_sensitive=False, extra="ignore")

    database_url: str = DEFAULT_DATABASE_URL
    host: str = "127.0.0.1"
    port: int = 8000
    workers: int = Field(default=1, ge=1, le=64)
    """Server processes of ``serve``; several share the load of one host's cores."""
    public_base_url: str | None = Field(default=None, pattern=r"^https?://[^\s?#]+$")
    """The service's address as its clients reach it (``https://actuators.example.com``,
    behind a proxy perhaps with a path), given as the OpenAPI document's ``servers``;
    unset: ``/``, the host the document was read from."""
    require_api_key: bool = False
    """When true, every endpoint needs an API key; otherwise catalogue reads and
    selections are open and only admin and sales operations need one."""
    max_key_failures: int = Field(default=10, ge=1)
    """Wrong API keys a client address may send in a burst; then 429 with Retry-After
    for any request with a key until the allowance refills (``http/throttle.py``)."""
    key_failure_window_s: float = Field(default=60.0, gt=0)
    """The time [s] in which the allowance of wrong keys refills completely."""
    cors_allow_origins: str = ""
    """Origins whose pages may call the API from a browser (CORS), comma-separated
    (``https://tools.example.com,https://erp.example.com``) or ``*``; empty: none, the
    service's own pages need no CORS (``http/methods.py``)."""

    data_dir: Path = REPO_ROOT / "var"
    """Files the service keeps beside the database: the document links' signing secret
    (``services/link_secret.py``); shared by every worker and replica that should accept
    each other's links."""
    link_signing_secret: SecretStr | None = None
    """The secret that signs document links (at least 32 characters); unset: one made
    once in ``DATA_DIR``. Changing it invalidates every link."""

    max_body_bytes: int = Field(default=1 << 20, ge=1024)
    """Largest request body [bytes] (413 above); 1 MiB holds any single request."""
    max_bulk_body_bytes: int = Field(default=32 << 20, ge=1024)
    """Largest body [bytes] of the bulk endpoints: batch selection, catalogue and price
    imports (20,000 batch cases are about 5 MB of JSON)."""
    max_job_body_bytes: int = Field(default=256 << 20, ge=1024)
    """Largest body [bytes] of a batch job (POST /batch-jobs): a million load cases as
    JSON lines are about 130 MB."""
    job_chunk_cases: int = Field(default=2000, ge=1, le=20_000)
    """Load cases per chunk of a batch job: the unit a worker computes and writes at once
    (2,000 cases with checks: about 1 s and 20 MB of JSON, 2 MB stored)."""
    job_stalled_after_s: float = Field(default=10.0, gt=0)
    """A worker that has not reported for this long [s] is taken for dead, and the chunk
    it was computing is run again by another (it reports every third of this)."""
    keep_alive_s: int = Field(default=75, ge=1)
    """How long the server keeps an idle keep-alive connection open [s]. Longer than a
    proxy's own (nginx's upstream ``keepalive_timeout``, 60 s, deploy/nginx.conf), so that
    the server never closes a connection as the proxy or a client sends on it: that
    request would fail without an answer (uvicorn's default is 5 s)."""
    body_timeout_s: float = Field(default=10.0, gt=0)
    """Longest time to receive a request's whole body [s], then 408; a request is admitted
    (``MAX_CONCURRENT_REQUESTS``) only once its body is in, so a slow client holds no place.
    10 s carries 1 MiB at 1 Mbit/s; raise it for bulk uploads over slow links."""
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
    db_connect_timeout_s: int = Field(default=5, ge=2)
    """Longest wait for a new PostgreSQL connection [s] (libpq connect_timeout), then 503:
    a database host that does not answer cannot make requests hang."""

    # The seller block of quote documents. The defaults are placeholders that read as
    # such: set them for the company that sends the quotes.
    seller_name: str = Field(default=PLACEHOLDER_SELLER_NAME, min_length=1, max_length=200)
    seller_address: str = Field(
        default="Your street 1\n12345 Your town\nYour country", min_length=1, max_length=2000
    )
    """Several lines: write ``\\n`` between them in the environment variable."""
    seller_vat_id: str = Field(default="XX000000000", min_length=1, max_length=40)
    """The seller's VAT identification number (e.g. DE123456789)."""
    seller_email: str = Field(default="sales@example.com", min_length=1, max_length=200)
    seller_phone: str | None = Field(default=None, max_length=60)

    # Default terms of a new quote (a request may state its own).
    quote_vat_percent: Decimal = Field(default=Decimal("19"), ge=0, le=100, decimal_places=2)
    """VAT rate [%] of a quote whose request gives no ``vat_percent`` (19: Germany's
    standard rate)."""
    quote_payment_terms_en: str = Field(
        default="Payable within 30 days of the invoice date without deduction.", min_length=1
    )
    quote_payment_terms_de: str = Field(
        default="Zahlbar innerhalb von 30 Tagen ab Rechnungsdatum ohne Abzug.", min_length=1
    )
    quote_delivery_terms_en: str = Field(
        default="FCA seller's works (Incoterms® 2020), packing included.", min_length=1
    )
    quote_delivery_terms_de: str = Field(
        default="FCA Werk des Verkäufers (Incoterms® 2020), einschließlich Verpackung.",
        min_length=1,
    )
    """The seller's standard terms in each language of the quote document: a quote whose
    request states no terms shows these, in the document's language."""

    def cors_origins(self) -> list[str]:
        """``cors_allow_origins`` as a list."""
        return [o.strip() for o in self.cors_allow_origins.split(",") if o.strip()]

    def seller(self) -> SellerParty:
        """The seller block and standard terms that a new quote stores."""
        return SellerParty(
            name=self.seller_name,
            address=self.seller_address.replace("\\n", "\n"),
            vat_id=self.seller_vat_id,
            email=self.seller_email,
            phone=self.seller_phone,
            payment_terms={"en": self.quote_payment_terms_en, "de": self.quote_payment_terms_de},
            delivery_terms={
                "en": self.quote_delivery_terms_en,
                "de": self.quote_delivery_terms_de,
            },
        )

    def quote_defaults(self) -> QuoteDefaults:
        """The VAT rate and seller of a quote whose request gives none."""
        return QuoteDefaults(vat_percent=self.quote_vat_percent, seller=self.seller())

    def engine_limits(self) -> EngineLimits:
        """The database limits that go with the admission limits."""
        return EngineLimits(
            lock_timeout_s=self.db_lock_timeout_s,
            statement_timeout_s=self.db_statement_timeout_s,
            pool_size=self.max_concurrent_requests,
            pool_timeout_s=self.db_lock_timeout_s,
            connect_timeout_s=self.db_connect_timeout_s,
        )


@lru_cache
def get_settings() -> Settings:
    """The process-wide settings, read once."""
    return Settings()
