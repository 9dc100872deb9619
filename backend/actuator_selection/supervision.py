"""Worker processes of ``serve --workers N`` end when their supervisor does.

uvicorn's supervisor starts the workers (``multiprocessing``, spawn) and hands them the
listening socket. Killed with SIGKILL, it cannot stop them: they kept serving on the
port as orphans, and a new ``serve`` failed with "Address already in use". Each worker
therefore watches its parent (:func:`exit_with_supervisor`): once the parent process is
gone it shuts itself down as on SIGTERM (uvicorn closes the listening socket at once
and lets the requests under way finish), and exits hard after :data:`GRACE_S` if that
has not ended it.

The watch polls ``os.getppid()``, which changes when the parent dies (the orphan is
re-parented), on Linux and macOS alike; a single-process ``serve`` (no supervisor)
does not watch.
"""

from __future__ import annotations

import logging
import multiprocessing
import os
import signal
import threading
import time

POLL_S = 0.25
"""How often a worker looks for its supervisor [s]."""
GRACE_S = 10.0
"""How long the requests under way may take once the supervisor is gone [s]."""

log = logging.getLogger(__name__)


def exit_with_supervisor() -> threading.Thread | None:
    """In a worker process: watch the supervisor in a daemon thread (returned); in a
    process that no ``multiprocessing`` parent started: nothing (None)."""
    parent = multiprocessing.parent_process()
    if parent is None or parent.pid is None:
        return None
    watch = threading.Thread(
        target=_watch, args=(parent.pid,), name="supervisor-watch", daemon=True
    )
    watch.start()
    return watch


def _watch(supervisor_pid: int) -> None:
    while os.getppid() == supervisor_pid:
        time.sleep(POLL_S)
    log.warning(
        "worker %d: the supervisor (pid %d) is gone; shutting down", os.getpid(), supervisor_pid
    )
    os.kill(os.getpid(), signal.SIGTERM)  # uvicorn's graceful shutdown
    time.sleep(GRACE_S)
    log.error("worker %d: still running %g s after the supervisor; exiting", os.getpid(), GRACE_S)
    os._exit(1)
