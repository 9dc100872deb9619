"""The quick start leads to a first quote (issue 29, item 8): the commands of the Makefile's
``run`` target, run as they stand on a new database, serve an app in which a sales key
(``keys create``) makes a quote at once, and the quote says it is an example.

Before, ``make run`` left no price list ("There is no price list yet") and every quote
document said "placeholder seller".
"""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import httpx
import pytest

from actuator_selection.cli import EXAMPLE_SELLER, _example_seller
from actuator_selection.config import REPO_ROOT, Settings

from .conftest import START_TIMEOUT_S, free_port, quote_body, stored_selection

Command = list[str]


def run_recipe() -> list[Command]:
    """The commands of ``make run`` after its ``install`` prerequisite, with this Python."""
    makefile = (REPO_ROOT / "Makefile").read_text(encoding="utf-8")
    recipe = re.search(r"^run:.*\n((?:\t.*\n)+)", makefile, re.MULTILINE)
    assert recipe, "no run target in the Makefile"
    commands = []
    for line in recipe.group(1).splitlines():
        words = shlex.split(line.strip())
        assert words[0] == "$(BIN)/python", line
        commands.append([sys.executable, *words[1:]])
    assert [c[3] for c in commands] == ["migrate", "seed", "serve"], commands
    return commands


@pytest.fixture
def environment(backend: str, new_database: Callable[[str], str]) -> dict[str, str]:
    """A new database and no seller settings, as on a fresh checkout."""
    env = {k: v for k, v in os.environ.items() if not k.upper().startswith("SELLER_")}
    port = free_port()
    return {**env, "DATABASE_URL": new_database(backend), "HOST": "127.0.0.1", "PORT": str(port)}


def run(command: Command, env: dict[str, str]) -> str:
    done = subprocess.run(command, cwd=REPO_ROOT, env=env, capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


@pytest.fixture
def served(environment: dict[str, str], tmp_path: Path) -> Iterator[tuple[str, str, str]]:
    """``make run`` as it stands: (the server's URL, the setup's output, a sales key)."""
    *setup, serve = run_recipe()
    said = "".join(run(command, environment) for command in setup)
    keys_create = ["keys", "create", "--role", "sales", "--name", "Quick start"]
    created = run([sys.executable, "-m", "actuator_selection", *keys_create], environment)
    key = created.strip().splitlines()[-1]
    log = tmp_path / "serve.log"
    with log.open("wb") as out:
        process = subprocess.Popen(serve, cwd=REPO_ROOT, env=environment, stdout=out, stderr=out)
    url = f"http://127.0.0.1:{environment['PORT']}"
    try:
        deadline = time.monotonic() + START_TIMEOUT_S
        while True:
            assert process.poll() is None, log.read_text(errors="replace")
            assert time.monotonic() < deadline, log.read_text(errors="replace")
            try:
                if httpx.get(f"{url}/api/v1/health", timeout=1).status_code == 200:
                    break
            except httpx.TransportError:
                time.sleep(0.05)
        yield url, said + log.read_text(errors="replace"), key
    finally:
        process.terminate()
        process.wait(10)


def test_make_run_on_a_new_database_leads_to_a_first_quote_marked_as_example(
    served: tuple[str, str, str], environment: dict[str, str]
) -> None:
    url, said, key = served
    # it says what it did, and that the prices and the seller are examples
    assert "EXAMPLE price list" in said
    assert "EXAMPLE seller" in said
    with httpx.Client(
        base_url=url, headers={"Authorization": f"Bearer {key}"}, timeout=60
    ) as client:
        lists = client.get("/api/v1/price-lists")
        assert lists.status_code == 200, lists.text
        assert [(p["name"], p["is_example"]) for p in lists.json()] == [
            (quote_body("x")["price_list"], True)
        ]
        created = client.post("/api/v1/quotes", json=quote_body(stored_selection(client)))
        assert created.status_code == 201, created.text
        quote = created.json()
        assert quote["price_list"]["is_example"] is True
        document = client.get(f"/api/v1/quotes/{quote['number']}/document?lang=en")
        assert document.status_code == 200, document.text
        html = document.text
    assert EXAMPLE_SELLER["SELLER_NAME"] in html  # the seller block says it is an example
    assert "EXAMPLE PRICES" in html
    assert "placeholder values" not in html

    # a second start leaves the prices as they are (a real list imported since would stay)
    again = run(run_recipe()[1], environment)
    assert "left as it is" in again
    assert "EXAMPLE price list" not in again


def test_a_seller_setting_of_ones_own_keeps_the_example_seller_out(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    for name in list(os.environ):
        if name.upper().startswith("SELLER_"):
            monkeypatch.delenv(name)
    monkeypatch.setenv("seller_name", "Muster Antriebe GmbH")  # read case-insensitively
    assert not _example_seller()
    assert "SELLER_ADDRESS" not in os.environ  # no seller half example, half one's own
    monkeypatch.delenv("seller_name")
    assert _example_seller()
    assert Settings().seller().name == EXAMPLE_SELLER["SELLER_NAME"]
    assert Settings().seller().address.splitlines()[0] == "Example street 1"
    for name in EXAMPLE_SELLER:
        monkeypatch.delenv(name)
