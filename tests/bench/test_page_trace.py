"""``bench.page`` reads the page's main-thread time from Chromium's trace as documented."""

from __future__ import annotations

import math
from typing import Any

import pytest
from bench.page import MainThread

PID, MAIN, OTHER = 7, 1, 2


def task(ts: float, dur: float, tdur: float, tid: int = MAIN, pid: int = PID) -> dict[str, Any]:
    """A top-level task (µs, as the trace has them)."""
    return {
        "ph": "X",
        "cat": "toplevel",
        "name": "RunTask",
        "pid": pid,
        "tid": tid,
        "ts": ts,
        "dur": dur,
        "tdur": tdur,
    }


def mark(name: str, ts: float, pid: int = PID) -> dict[str, Any]:
    return {"ph": "R", "cat": "blink.user_timing", "name": name, "pid": pid, "tid": MAIN, "ts": ts}


THREADS = [
    {"ph": "M", "name": "thread_name", "pid": PID, "tid": MAIN, "args": {"name": "CrRendererMain"}},
    {"ph": "M", "name": "thread_name", "pid": PID, "tid": OTHER, "args": {"name": "Compositor"}},
    {"ph": "M", "name": "thread_name", "pid": 8, "tid": MAIN, "args": {"name": "CrRendererMain"}},
]


def test_outermost_main_thread_tasks_up_to_the_mark_are_counted() -> None:
    events = [
        *THREADS,
        task(0, 10_000, 4_000),
        task(2_000, 1_000, 900),  # nested in the one before: counted with it
        task(20_000, 5_000, 5_000, tid=OTHER),  # another thread
        task(20_000, 5_000, 5_000, pid=8),  # another renderer
        mark("bench:submitted", 30_000),
        task(30_000, 10_000, 6_000),
        task(50_000, 20_000, 8_000),  # the mark falls in its first quarter
        mark("bench:charts-drawn", 55_000),
        task(80_000, 1_000, 1_000),  # after the mark
    ]
    main = MainThread.of({"traceEvents": events})
    assert main.cpu_ms == pytest.approx(4 + 6 + 2)
    assert main.task_ms == pytest.approx(10 + 10 + 5)
    assert main.cpu_after_submit_ms == pytest.approx(6 + 2)


def test_without_a_submit_mark_the_time_after_it_is_not_a_number() -> None:
    events = [*THREADS, task(0, 1_000, 500), mark("bench:charts-drawn", 2_000)]
    main = MainThread.of({"traceEvents": events})
    assert main.cpu_ms == pytest.approx(0.5)
    assert math.isnan(main.cpu_after_submit_ms)
