"""Command line for API keys and price lists.

``keys create --role admin|sales --name NAME`` prints the new key once (only its
hash is stored), ``keys list`` shows every key's public id, ``keys revoke ID``
revokes one; ``prices import FILE [--dry-run]`` loads a price list CSV atomically.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from datetime import UTC, datetime
from pathlib import Path

from sqlalchemy.orm import Session

from actuator_selection.catalogue.csvio import CatalogueFileError
from actuator_selection.db.engine import begin_write, make_engine, make_session_factory
from actuator_selection.db.sales import ROLES, ApiKeyRepository, PriceRepository, parse_prices


@contextmanager
def _transaction(url: str) -> Iterator[Session]:
    engine = make_engine(url)
    try:
        with make_session_factory(engine).begin() as session:
            yield begin_write(session)
    finally:
        engine.dispose()


def _create(args: argparse.Namespace) -> int:
    try:
        with _transaction(args.database_url) as session:
            record, key = ApiKeyRepository(session).create(
                name=args.name, role=args.role, now=datetime.now(UTC)
            )
    except ValueError as exc:
        print(f"keys: {exc}", file=sys.stderr)
        return 1
    print(f"created {record.role} key {record.prefix} ({record.name}); the key, shown only now:")
    print(key)
    return 0


def _list(args: argparse.Namespace) -> int:
    with _transaction(args.database_url) as session:
        keys = ApiKeyRepository(session).keys()
    if not keys:
        print("no API keys")
    for k in keys:
        state = f"revoked {k.revoked_at:%Y-%m-%d %H:%M}" if k.revoked_at else "active"
        print(f"{k.prefix}  {k.role:<5}  {state:<24}  {k.created_at:%Y-%m-%d}  {k.name}")
    return 0


def _revoke(args: argparse.Namespace) -> int:
    with _transaction(args.database_url) as session:
        record = ApiKeyRepository(session).revoke(args.id, now=datetime.now(UTC))
    if record is None:
        print(f"keys: no key {args.id!r} (see `keys list`)", file=sys.stderr)
        return 1
    print(f"revoked key {record.prefix} ({record.name})")
    return 0


def _import_prices(args: argparse.Namespace) -> int:
    path = Path(args.file)
    try:
        # Bytes, not read_text: universal newlines would turn a CR inside a quoted cell to LF.
        text = path.read_bytes().decode("utf-8-sig")
    except (OSError, UnicodeDecodeError) as exc:
        print(f"prices: cannot read {path}: {exc}", file=sys.stderr)
        return 1
    try:
        with _transaction(args.database_url) as session:
            report = PriceRepository(session).replace(
                parse_prices(text, file=path.name), now=datetime.now(UTC)
            )
            if args.dry_run:
                session.rollback()
    except CatalogueFileError as exc:
        print(f"prices: nothing loaded, {len(exc.problems)} problem(s):", file=sys.stderr)
        for problem in exc.problems:
            print(f"  {problem}", file=sys.stderr)
        return 1
    verb = "would change" if args.dry_run else "loaded"
    for name, c in report.items():
        print(
            f"prices {verb} {name!r}: inserted {c.inserted}, updated {c.updated}, "
            f"unchanged {c.unchanged}, removed {c.retired}"
        )
    return 0


def _command(parser: argparse.ArgumentParser, run: Callable[[argparse.Namespace], int]) -> None:
    parser.set_defaults(run=run)


def register(commands: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    """Add the ``keys`` and ``prices`` commands to the CLI's sub-commands."""
    keys = commands.add_parser("keys", help="API keys: create, list, revoke")
    key_commands = keys.add_subparsers(dest="keys_command", required=True)
    create = key_commands.add_parser("create", help="create a key and print it once")
    create.add_argument("--role", required=True, choices=ROLES)
    create.add_argument("--name", required=True, help="who or what uses the key")
    _command(create, _create)
    _command(key_commands.add_parser("list", help="every key's id, role and state"), _list)
    revoke = key_commands.add_parser("revoke", help="revoke a key by its id")
    revoke.add_argument("id", help="the key's id (its public prefix, see `keys list`)")
    _command(revoke, _revoke)

    prices = commands.add_parser("prices", help="price lists")
    price_commands = prices.add_subparsers(dest="prices_command", required=True)
    load = price_commands.add_parser("import", help="import a price list CSV atomically")
    load.add_argument("file", help="CSV file, e.g. seed_data/example_prices.csv")
    load.add_argument("--dry-run", action="store_true", help="report, change nothing")
    _command(load, _import_prices)
