"""The document links' signing secret: made once in DATA_DIR, the same for every process
that starts at once, readable by the service alone; or LINK_SIGNING_SECRET."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest
from pydantic import SecretStr

from actuator_selection.config import REPO_ROOT, Settings
from actuator_selection.services.link_secret import SECRET_FILE, LinkSecretError, link_secret

PROCESSES = 8
_PRINT_SECRET = (
    "import sys; from pathlib import Path; "
    "from actuator_selection.config import Settings; "
    "from actuator_selection.services.link_secret import link_secret; "
    "print(link_secret(Settings(data_dir=Path(sys.argv[1]))).decode())"
)


def test_processes_starting_at_once_agree_on_one_secret(tmp_path: Path) -> None:
    """Worker processes start together on an empty DATA_DIR: each either publishes its
    secret or reads the one published first, so all sign alike."""
    data_dir = tmp_path / "data"
    processes = [
        subprocess.Popen(
            [sys.executable, "-c", _PRINT_SECRET, str(data_dir)],
            cwd=REPO_ROOT,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
        )
        for _ in range(PROCESSES)
    ]
    outputs = [p.communicate(timeout=60) for p in processes]
    assert all(p.returncode == 0 for p in processes), [err for _, err in outputs]
    secrets = {out.decode().strip() for out, _ in outputs}
    assert len(secrets) == 1
    (secret,) = secrets
    assert len(secret) == 64
    path = data_dir / SECRET_FILE
    assert path.read_text().strip() == secret
    assert stat.S_IMODE(path.stat().st_mode) == 0o600
    assert sorted(p.name for p in data_dir.iterdir()) == [SECRET_FILE]  # no drafts left
    assert link_secret(Settings(data_dir=data_dir)) == secret.encode()  # and after a restart


def test_the_environment_s_secret_comes_first(tmp_path: Path) -> None:
    given = "x" * 40
    settings = Settings(data_dir=tmp_path, link_signing_secret=SecretStr(given))
    assert link_secret(settings) == given.encode()
    assert not (tmp_path / SECRET_FILE).exists()


def test_a_short_secret_is_refused(tmp_path: Path) -> None:
    settings = Settings(data_dir=tmp_path, link_signing_secret=SecretStr("short"))
    with pytest.raises(LinkSecretError, match="at least 32 characters"):
        link_secret(settings)


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes anywhere")
def test_an_unwritable_data_dir_says_what_to_set(tmp_path: Path) -> None:
    tmp_path.chmod(0o500)
    try:
        with pytest.raises(LinkSecretError, match="LINK_SIGNING_SECRET"):
            link_secret(Settings(data_dir=tmp_path / "data"))
    finally:
        tmp_path.chmod(0o700)
