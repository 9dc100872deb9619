"""Issue 32's targets, each declared once: a bench prints its measure beside the target
and whether this run meets it (``make bench`` then reads as the issue's table).

Every measure is a ratio to a reference timed in the same run, or an absolute figure of
the same run where the issue sets one (milliseconds of a selection, megabytes, seconds).
"""

from __future__ import annotations

from dataclasses import dataclass


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
