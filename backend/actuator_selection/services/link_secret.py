"""The server secret that signs document links (``db/sales.py``, ``ApiKeyRepository``).

Links used to be keyed with the API key's stored hash, so whoever could read that
column (a database dump, a read-only SQL role) could mint a link for any key. The MAC
is now keyed with a secret that is not in the database:

- ``LINK_SIGNING_SECRET`` when set (at least :data:`MIN_SECRET_LENGTH` characters):
  set it, the same on every host, when replicas run on several hosts without a shared
  ``DATA_DIR``;
- otherwise ``<DATA_DIR>/link-signing.key``, 32 random bytes written once, readable by
  the service's user alone. Every worker process and every restart reads the same file;
  when several processes start at once, the first one to publish the file wins (it is
  written aside and linked into place, so nobody reads a half-written secret).

Changing the secret invalidates every link signed with the old one.
"""

from __future__ import annotations

import contextlib
import os
import secrets
from pathlib import Path

from actuator_selection.config import Settings

SECRET_FILE = "link-signing.key"
MIN_SECRET_LENGTH = 32
"""Characters of ``LINK_SIGNING_SECRET`` at least (the generated one: 64 hex digits)."""


class LinkSecretError(RuntimeError):
    """No usable secret: the message says what to set."""


def link_secret(settings: Settings) -> bytes:
    """The secret that signs document links (see the module docstring)."""
    if settings.link_signing_secret is not None:
        value = settings.link_signing_secret.get_secret_value()
        if len(value) < MIN_SECRET_LENGTH:
            raise LinkSecretError(
                f"LINK_SIGNING_SECRET must be at least {MIN_SECRET_LENGTH} characters"
            )
        return value.encode("utf-8")
    path = Path(settings.data_dir) / SECRET_FILE
    try:
        if not path.exists():
            _publish(path)
        value = path.read_text(encoding="ascii").strip()
    except OSError as exc:
        raise LinkSecretError(
            f"cannot read or create {path} ({exc}): make DATA_DIR writable for the "
            "service or set LINK_SIGNING_SECRET"
        ) from exc
    if len(value) < MIN_SECRET_LENGTH:
        raise LinkSecretError(f"{path} holds no usable secret: delete it to have one made")
    return value.encode("ascii")


def _publish(path: Path) -> None:
    """Write a new secret to ``path`` unless another process has published one first."""
    path.parent.mkdir(parents=True, exist_ok=True)
    draft = path.with_name(f".{path.name}.{os.getpid()}.{secrets.token_hex(4)}")
    descriptor = os.open(draft, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    try:
        with os.fdopen(descriptor, "w", encoding="ascii") as draft_file:
            draft_file.write(secrets.token_hex(32) + "\n")
            draft_file.flush()
            os.fsync(draft_file.fileno())
        with contextlib.suppress(FileExistsError):  # another process published first
            os.link(draft, path)  # atomic: the whole file or none
    finally:
        draft.unlink(missing_ok=True)
