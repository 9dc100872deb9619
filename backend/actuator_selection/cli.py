"""Command line: ``python -m actuator_selection {migrate,seed,serve,worker}``."""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from actuator_selection.cli_keys import register as register_sales_commands
from actuator_selection.config import SEED_DIR, get_settings

if TYPE_CHECKING:
    from sqlalchemy.orm import Session

EXAMPLE_PRICES = SEED_DIR / "example_prices.csv"
"""The example price list: invented prices, marked ``is_example`` (every quote made with
it carries the document's "EXAMPLE PRICES" banner). ``seed --examples`` loads it into a
database that has no price list yet."""

EXAMPLE_SELLER = {
    "SELLER_NAME": "Example Drives GmbH (EXAMPLE, not a real company)",
    "SELLER_ADDRESS": "Example street 1\\n12345 Example town\\nGermany",
    "SELLER_VAT_ID": "DE000000000",
    "SELLER_EMAIL": "sales@example.com",
}
"""The seller block ``serve --examples`` uses when none of these settings is given: marked
as an example in its name, which every quote document shows."""


def _migrate(args: argparse.Namespace) -> int:
    from actuator_selection.db.migrate import upgrade

    upgrade(url=args.database_url)
    print("database migrated to the newest revision")
    return 0


def _example_prices(session: Session) -> dict[str, int]:
    """Load the example price list when the database has no price list; {name: prices}."""
    from datetime import UTC, datetime

    from actuator_selection.db.sales import PriceRepository, parse_prices

    prices = PriceRepository(session)
    if prices.price_lists():
        return {}
    text = EXAMPLE_PRICES.read_bytes().decode("utf-8-sig")
    report = prices.replace(parse_prices(text, file=EXAMPLE_PRICES.name), now=datetime.now(UTC))
    return {name: changes.inserted for name, changes in report.items()}


def _seed(args: argparse.Namespace) -> int:
    from actuator_selection.catalogue.csvio import CatalogueFileError
    from actuator_selection.db.engine import begin_write, make_engine, make_session_factory
    from actuator_selection.db.repositories import CatalogueVersionRepository
    from actuator_selection.db.seed import load_seed

    engine = make_engine(args.database_url)
    report = None
    examples: dict[str, int] = {}
    try:
        with make_session_factory(engine).begin() as session:
            begin_write(session)
            if not (args.if_empty and CatalogueVersionRepository(session).current() > 0):
                report = load_seed(session, Path(args.directory))
            if args.examples:
                examples = _example_prices(session)
    except CatalogueFileError as exc:
        print(f"seed: nothing loaded, {len(exc.problems)} problem(s):", file=sys.stderr)
        for problem in exc.problems:
            print(f"  {problem}", file=sys.stderr)
        return 1
    finally:
        engine.dispose()
    if report is None:
        print("seed: the catalogue has been written before; left as it is (--if-empty)")
    else:
        print(f"seed: catalogue rows {report}")
    for name, count in examples.items():
        print(
            f"seed: no price list yet, so the EXAMPLE price list {name!r} was loaded "
            f"({count} invented prices, for trying quotes out; every quote made with it is "
            "marked as an example). Import real prices with "
            "`python -m actuator_selection prices import FILE`."
        )
    return 0


def _example_seller() -> bool:
    """Put the example seller into the environment unless a seller setting is given."""
    given = {name.upper() for name in os.environ}
    if given & EXAMPLE_SELLER.keys():
        return False
    os.environ.update(EXAMPLE_SELLER)
    return True


def _serve(args: argparse.Namespace) -> int:
    import uvicorn

    # Each worker process builds its app from the environment, so the URL given here
    # travels there (``--database-url`` before the command, else $DATABASE_URL).
    os.environ["DATABASE_URL"] = args.database_url
    if args.examples and _example_seller():
        print(
            f"serve: no seller settings, so quotes name the EXAMPLE seller "
            f"{EXAMPLE_SELLER['SELLER_NAME']!r}; set {', '.join(EXAMPLE_SELLER)} for real quotes",
            flush=True,
        )
    get_settings.cache_clear()
    uvicorn.run(
        "actuator_selection.app:serve_app",
        factory=True,
        host=args.host,
        port=args.port,
        workers=args.workers,
        timeout_keep_alive=get_settings().keep_alive_s,
        log_level="info",
    )
    return 0


def _worker(args: argparse.Namespace) -> int:
    import gc
    import logging

    from sqlalchemy.engine import make_url

    from actuator_selection.app import tune_process
    from actuator_selection.db.engine import make_engine, make_session_factory
    from actuator_selection.i18n.localize import localizer
    from actuator_selection.job_queue import run_worker

    if make_url(args.database_url).get_backend_name() != "postgresql":
        print(
            "worker: batch jobs need no worker on SQLite (the server computes them); "
            "workers share a PostgreSQL database's queue (--database-url postgresql://…)",
            file=sys.stderr,
        )
        return 2
    logging.basicConfig(level=logging.INFO, format="%(asctime)s %(name)s %(message)s")
    allocator = "tuned" if tune_process() else "as the C library has it"
    logging.getLogger("actuator_selection.worker").info(
        "worker: collector thresholds %s, allocator %s", gc.get_threshold(), allocator
    )
    settings = get_settings()
    engine = make_engine(args.database_url, settings.engine_limits())
    try:
        run_worker(
            args.database_url,
            make_session_factory(engine),
            localizer,
            concurrency=args.concurrency,
            stalled_after_s=settings.job_stalled_after_s,
        )
    finally:
        engine.dispose()
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    """Parse ``argv`` and run the command; returns the exit status."""
    settings = get_settings()
    parser = argparse.ArgumentParser(prog="python -m actuator_selection")
    parser.add_argument(
        "--database-url",
        default=settings.database_url,
        help="SQLAlchemy URL (default: $DATABASE_URL or the embedded SQLite file)",
    )
    commands = parser.add_subparsers(dest="command", required=True)
    register_sales_commands(commands)
    commands.add_parser("migrate", help="create or upgrade the database schema").set_defaults(
        run=_migrate
    )
    seed = commands.add_parser("seed", help="load the starter catalogue (idempotent)")
    seed.add_argument("--directory", default=str(SEED_DIR), help="folder of the CSV files")
    seed.add_argument(
        "--if-empty",
        action="store_true",
        help="seed only a catalogue never written before, so changes made through the "
        "admin API survive a restart",
    )
    seed.add_argument(
        "--examples",
        action="store_true",
        help="also load the EXAMPLE price list (invented prices, marked as such) when the "
        "database has no price list yet",
    )
    seed.set_defaults(run=_seed)
    serve = commands.add_parser("serve", help="serve the API and the web page")
    serve.add_argument("--host", default=settings.host)
    serve.add_argument("--port", type=int, default=settings.port)
    serve.add_argument(
        "--workers",
        type=int,
        default=settings.workers,
        help="server processes (default: $WORKERS or 1); each admits MAX_CONCURRENT_REQUESTS "
        "requests and holds a database pool of its own",
    )
    serve.add_argument(
        "--examples",
        action="store_true",
        help="without SELLER_* settings, quotes name an EXAMPLE seller (marked as such) "
        "instead of the placeholder one",
    )
    serve.set_defaults(run=_serve)
    worker = commands.add_parser(
        "worker", help="compute batch jobs' chunks from the PostgreSQL queue (any number, anywhere)"
    )
    worker.add_argument(
        "--concurrency", type=int, default=1, help="chunks computed at once (default 1)"
    )
    worker.set_defaults(run=_worker)
    args = parser.parse_args(argv)
    status: int = args.run(args)
    return status
