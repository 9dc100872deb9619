"""The deployment as CI can check it without a Docker engine: docker-compose.yml validates
with `docker-compose config` and has the shape the README promises (PostgreSQL, migrations
once before the replicas, several replicas behind nginx); the image installs runtime
dependencies only, runs as a non-root user, and its healthcheck command passes against a
real server and fails without one."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tomllib
from pathlib import Path
from typing import Any

import pytest
import yaml
from tests.server.conftest import StartServer, free_port

from actuator_selection.documents.pdf import UNICODE_FONTS

ROOT = Path(__file__).resolve().parents[2]
DOCKERFILE = (ROOT / "Dockerfile").read_text()


def compose() -> dict[str, Any]:
    data: dict[str, Any] = yaml.safe_load((ROOT / "docker-compose.yml").read_text())
    return data


def test_compose_file_validates() -> None:
    tool = shutil.which("docker-compose")
    if tool is None:
        if os.environ.get("CI") == "true":
            pytest.fail("docker-compose is missing (.ci/run installs Debian's docker-compose)")
        pytest.skip("docker-compose not installed (apt-get install docker-compose)")
    result = subprocess.run(
        [tool, "-f", str(ROOT / "docker-compose.yml"), "config", "-q"],
        capture_output=True,
        text=True,
        timeout=60,
        check=False,
    )
    assert result.returncode == 0, result.stderr


def test_replicas_start_after_the_migrations_behind_a_proxy() -> None:
    services = compose()["services"]
    assert services["migrate"]["depends_on"]["db"]["condition"] == "service_healthy"
    assert "migrate" in " ".join(services["migrate"]["command"])
    app = services["app"]
    assert app["depends_on"]["migrate"]["condition"] == "service_completed_successfully"
    assert app["deploy"]["replicas"] >= 2
    assert int(app["environment"]["WORKERS"]) >= 2
    assert "ports" not in app  # reached through the proxy only
    proxy = services["proxy"]
    mounted = {v.split(":")[0] for v in proxy["volumes"]}
    assert "./deploy/nginx.conf" in mounted
    nginx = (ROOT / "deploy" / "nginx.conf").read_text()
    assert re.search(r"server\s+app:8000", nginx)
    assert "proxy_pass http://actuator_app" in nginx
    for service in ("db", "app", "proxy"):
        assert services[service]["restart"] == "unless-stopped"


def _packages(lock: str) -> dict[str, str]:
    """name → the requirement line with its hashes."""
    entries = re.split(r"\n(?=\S)", (ROOT / lock).read_text().strip())
    return {e.split("==")[0].lower(): e for e in entries if "==" in e}


def test_the_image_installs_the_runtime_lock_only() -> None:
    assert "requirements-runtime.lock" in DOCKERFILE
    assert "requirements.lock " not in DOCKERFILE.replace("\n", " ")
    runtime, full = _packages("requirements-runtime.lock"), _packages("requirements.lock")
    assert set(runtime) < set(full)
    for name, entry in runtime.items():  # the same versions and hashes as the tests ran
        assert entry == full[name], name
    assert {"fastapi", "uvicorn", "sqlalchemy", "psycopg", "alembic"} <= set(runtime)
    declared = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["dependencies"]
    for requirement in declared:  # every runtime dependency is in the image
        name = re.split(r"[<>=!~\[ ;]", requirement, maxsplit=1)[0].lower()
        assert name in runtime, f"{name}: run `make lock`"
    assert not {"pytest", "mypy", "ruff", "hypothesis", "schemathesis", "pypdf"} & set(runtime)


def test_the_image_leaves_the_test_tools_out() -> None:
    assert re.search(r"npm ci --omit=dev", DOCKERFILE)  # no axe-core in the image


def test_the_image_runs_as_a_non_root_user() -> None:
    users = re.findall(r"^USER\s+(\S+)", DOCKERFILE, re.MULTILINE)
    assert users
    assert users[-1] not in ("root", "0")
    assert re.search(r"useradd .*--uid 10001 .*app", DOCKERFILE)


def _healthcheck_command() -> list[str]:
    match = re.search(r"HEALTHCHECK .*?CMD (\[.*?\])\n", DOCKERFILE, re.DOTALL)
    assert match, "the image has a HEALTHCHECK"
    command: list[str] = yaml.safe_load(match.group(1))
    return command


@pytest.mark.parametrize("backend", ["sqlite"])
def test_the_healthcheck_passes_on_a_serving_app_and_fails_without_one(
    start_server: StartServer,
) -> None:
    server, _ = start_server()
    command = _healthcheck_command()
    assert command[0] == "python"
    run = [sys.executable, *command[1:]]
    healthy = subprocess.run(
        run, env=os.environ | {"PORT": str(server.port)}, timeout=10, check=False
    )
    assert healthy.returncode == 0
    down = subprocess.run(
        run,
        env=os.environ | {"PORT": str(free_port())},
        capture_output=True,
        timeout=10,
        check=False,
    )
    assert down.returncode != 0


def test_the_image_has_the_font_the_pdfs_look_for() -> None:
    """The PDFs set their text in DejaVu Sans where it is installed (every character of the
    chapter); the image installs Debian's package that puts it where they look."""
    assert re.search(r"apt-get install .*fonts-dejavu-core", DOCKERFILE)
    assert Path("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf") in UNICODE_FONTS
