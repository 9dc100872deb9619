"""Issue 32's targets, each declared once: a bench prints its measure beside the target
and whether this run meets it, and ``make bench`` ends with the issue's table, each
target with what this run measured (``python -m bench.targets FILE``).

Every measure is a ratio to a reference timed in the same run, or an absolute figure of
the same run where the issue sets one (milliseconds of a selection, megabytes, seconds).
"""

from __future__ import annotations

import json
import os
import sys
from dataclasses import dataclass
from pathlib import Path

RESULTS = "BENCH_RESULTS"
"""The environment variable naming a file (JSON lines) that each bench's verdicts are
added to (:meth:`Target.judged`), for the table :func:`main` prints; ``make bench``
sets it."""


@dataclass(frozen=True, slots=True)
class Target:
    """A bound on one measure: at most ``limit`` (at least, with ``at_least``)."""

    limit: float
    unit: str
    at_least: bool = False

    def met(self, measured: float) -> bool:
        """Whether ``measured`` is within the bound (a NaN never is)."""
        return measured >= self.limit if self.at_least else measured <= self.limit

    def verdict(self, measured: float) -> str:
        """``target ≥ 0.7×: not met`` for the figure ``measured``."""
        bound = "≥" if self.at_least else "≤"
        state = "met" if self.met(measured) else "not met"
        return f"target {bound} {self.limit:g}{self.unit}: {state}"

    def judged(self, measured: float, reference: str = "") -> str:
        """:meth:`verdict`, the measure also added to the file :data:`RESULTS` names (if
        set), with the ``reference`` it was measured against (``/health 148 req/s``)."""
        where = os.environ.get(RESULTS)
        if where:
            names = [n for n, t in declared().items() if t is self]
            if not names:
                raise ValueError(f"{self} is not one of issue 32's targets (bench/targets.py)")
            (name,) = names
            line = {"target": name, "measured": measured, "reference": reference}
            with Path(where).open("a", encoding="utf-8") as out:
                out.write(json.dumps(line) + "\n")
        return self.verdict(measured)


WHOLE_CATALOGUE = Target(0.7, "×", at_least=True)
"""Whole-catalogue ``POST /selections`` ÷ ``GET /health``, requests per second
(median of the rounds; ``bench.http``)."""

ONE_MODEL = Target(0.9, "×", at_least=True)
"""One-model ``POST /selections`` ÷ ``GET /health``, the same."""

BATCH_PER_CASE = Target(5, "×")
"""``POST /selections/batch``, 10,000 cases × the catalogue, with checks: the server's
CPU time ÷ the numpy reference's (median of the rounds; ``bench.http``,
``bench.batch``)."""

BATCH_COLUMNS = Target(2.5, "×")
"""``POST /selections/batch/columns``, 10,000 cases with checks: wall time (best of 3)
÷ the numpy reference's (best of 3)."""

SELECTION_6400 = Target(20, " ms")
"""One whole-catalogue selection over 6,400 actuators, server side (``bench.selection``)."""

SELECTION_64000 = Target(100, " ms")
"""The same over 64,000 actuators."""

RELOAD_64000 = Target(1, " s")
"""A process's reload after a catalogue change at 64,000 actuators (``bench.catalogue``)."""

PEAK_RSS_64000 = Target(400, " MB")
"""The server's peak resident memory with 64,000 actuators."""

PAGE = Target(5, "×")
"""The engineer's page, cold load to both charts ÷ the bare page (median;
``bench.page``)."""

PAGE_SLOWED = Target(2500, " ms")
"""The same with the CPU slowed 4×: to both charts, since navigation start (median)."""


def declared() -> dict[str, Target]:
    """Every target of this module, by name, in the order declared (the issue's)."""
    return {n: t for n, t in globals().items() if isinstance(t, Target)}


def summary(lines: list[str]) -> list[str]:
    """The issue's table from the results' ``lines`` (:meth:`Target.judged`): each
    target, what this run measured of it (each time, with its reference) and whether
    the last measure meets it; a target no bench measured says so."""
    found: dict[str, list[dict[str, object]]] = {}
    for line in lines:
        if line.strip():
            result = json.loads(line)
            found.setdefault(str(result["target"]), []).append(result)
    out = []
    for name, target in declared().items():
        results = found.get(name, [])
        label = name.lower().replace("_", " ")  # WHOLE_CATALOGUE: "whole catalogue"
        if not results:
            out.append(f"{label:<16} not measured in this run")
            continue
        measured = [float(str(r["measured"])) for r in results]
        figures = ", ".join(
            _figure(m) + target.unit + (f" ({r['reference']})" if r["reference"] else "")
            for m, r in zip(measured, results, strict=True)
        )
        out.append(f"{label:<16} {figures}; {target.verdict(measured[-1])}")
    return out


def _figure(measured: float) -> str:
    """``0.48``, ``13.3``, ``2,977``: three figures, or whole units from 100 on."""
    return f"{measured:,.0f}" if abs(measured) >= 100 else f"{measured:.3g}"


def main() -> None:
    """Print :func:`summary` of the results file named on the command line."""
    if len(sys.argv) != 2:
        sys.exit("usage: python -m bench.targets RESULTS_FILE")
    where = Path(sys.argv[1])
    lines = where.read_text(encoding="utf-8").splitlines() if where.is_file() else []
    print("Issue 32's targets, as this run measured them:")
    for row in summary(lines):
        print(f"  {row}")


if __name__ == "__main__":
    main()
