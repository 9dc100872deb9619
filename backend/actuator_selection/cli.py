"""Command line: ``python -m actuator_selection {migrate,seed,serve}``."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from actuator_selection.cli_keys import register as register_sales_commands
from actuator_selection.config import SEED_DIR, get_settings


def _migrate(args: argparse.Namespace) -> int:
    from actuator_selection.db.migrate import upgrade

    upgrade(url=args.database_url)
    print("database migrated to the newest revision")
    return 0


def _seed(args: argparse.Namespace) -> int:
    from actuator_selection.core.csvio import CatalogueFileError
    from actuator_selection.db.engine import begin_write, make_engine, make_session_factory
    from actuator_selection.db.repositories import CatalogueVersionRepository
    from actuator_selection.db.seed import load_seed

    engine = make_engine(args.database_url)
    try:
        with make_session_factory(engine).begin() as session:
            begin_write(session)
            if args.if_empty and CatalogueVersionRepository(session).current() > 0:
                print("seed: the catalogue has been written before; left as it is (--if-empty)")
                return 0
            report = load_seed(session, Path(args.directory))
    except CatalogueFileError as exc:
        print(f"seed: nothing loaded, {len(exc.problems)} problem(s):", file=sys.stderr)
        for problem in exc.problems:
            print(f"  {problem}", file=sys.stderr)
        return 1
    finally:
        engine.dispose()
    print(f"seed: catalogue rows {report}")
    return 0


def _serve(args: argparse.Namespace) -> int:
    import os

    import uvicorn

    # Each worker process builds its app from the environment, so the URL given here
    # travels there (``--database-url`` before the command, else $DATABASE_URL).
    os.environ["DATABASE_URL"] = args.database_url
    get_settings.cache_clear()
    uvicorn.run(
        "actuator_selection.main:serve_app",
        factory=True,
        host=args.host,
        port=args.port,
        workers=args.workers,
        log_level="info",
    )
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
    serve.set_defaults(run=_serve)
    args = parser.parse_args(argv)
    status: int = args.run(args)
    return status
