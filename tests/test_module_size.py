"""Each backend module holds one idea: none grows past :data:`MAX_LINES` lines (issue 27).

A module that outgrows it is split by idea into a package whose ``__init__`` re-exports
what callers import (as ``sizing/motion``, ``sizing/thermal``, ``sizing/mechanisms`` and
``schemas/selections`` were)."""

from __future__ import annotations

from pathlib import Path

BACKEND = Path(__file__).resolve().parents[1] / "backend"
MAX_LINES = 700


def modules_over(limit: int, root: Path = BACKEND) -> dict[str, int]:
    """The Python modules under ``root`` longer than ``limit`` lines, with their length."""
    lengths = {
        str(p.relative_to(root)): len(p.read_text(encoding="utf-8").splitlines())
        for p in sorted(root.rglob("*.py"))
    }
    return {name: n for name, n in lengths.items() if n > limit}


def test_no_backend_module_is_over_700_lines() -> None:
    assert modules_over(MAX_LINES) == {}, "split these by idea (docs/architecture.md)"


def test_the_measure_sees_a_long_module(tmp_path: Path) -> None:
    (tmp_path / "long.py").write_text("x = 1\n" * (MAX_LINES + 1), encoding="utf-8")
    (tmp_path / "short.py").write_text("x = 1\n" * MAX_LINES, encoding="utf-8")
    assert modules_over(MAX_LINES, tmp_path) == {"long.py": MAX_LINES + 1}
