"""The flowchart's outcome for one actuator (:class:`Candidate`, its :class:`Verdict`), for
many (:class:`Selection`), and the order candidates are ranked in (:func:`ranking_key`)."""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum
from typing import Any

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.checks import Brief, Check, DeferredChecks, Rule, Status
from actuator_selection.sizing.deferred import defer_field
from actuator_selection.sizing.motion import CycleTorques, Profile


class Verdict(StrEnum):
    """Outcome for one actuator: suitable only when every check has data and none fails."""

    SUITABLE = "suitable"
    UNCONFIRMED = "unconfirmed"
    UNSUITABLE = "unsuitable"


VALUE_OF: dict[Status | Verdict, str] = {e: e.value for e in (*Status, *Verdict)}
"""Each status's and verdict's value, for answers written as plain data: a dict lookup
is several times cheaper than an enum's ``.value``."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Candidate:
    """The flowchart's result for one actuator."""

    actuator: Actuator
    verdict: Verdict
    torques: CycleTorques | None
    checks: tuple[Check, ...]

    @property
    def reasons(self) -> tuple[str, ...]:
        """Messages of the checks that fail, lack data or warn, in flowchart order, each
        once (``continuous_duty`` and ``thermal_peak`` lack the same catalogue value)."""
        held = _CHECKS.__get__(self, Candidate)
        if isinstance(held, DeferredChecks):  # a batch's candidate, checks unread: these alone
            return tuple(dict.fromkeys(held.reasons()))
        return tuple(dict.fromkeys(c.message for c in self.checks if c.status.open))

    def briefs(self) -> list[tuple[Check | Rule, Brief]]:
        """Each check as a :data:`~actuator_selection.sizing.checks.Brief` beside what
        names it (its :class:`Check` or, for a batch's candidate whose checks are unread,
        its rule: each has ``name``, ``unit`` and ``reference``), without building the
        checks that are not built yet."""
        held = _CHECKS.__get__(self, Candidate)
        if isinstance(held, DeferredChecks):
            return list(held.briefs())
        return [(c, (c.status, c.value, c.limit, c.approximate, c.message)) for c in self.checks]

    def decided(self) -> tuple[Any, int] | None:
        """The engine's decisions of the cells detailed with this candidate (the engine's
        ``DecidedCells``, which this module does not import: the engine imports it), and
        its cell among them (:meth:`~actuator_selection.sizing.checks.DeferredChecks.
        decided`); None where its checks are built (they are then read one by one)."""
        held = _CHECKS.__get__(self, Candidate)
        if isinstance(held, DeferredChecks):
            return held.decided()
        return None

    @property
    def open_checks(self) -> list[str]:
        """The names of the checks that fail, lack data or warn, in flowchart order: what
        :attr:`reasons` words (each check once; two may share a message)."""
        held = _CHECKS.__get__(self, Candidate)
        if isinstance(held, DeferredChecks):  # a batch's candidate, checks unread: from codes
            return held.open_names()
        return [c.name for c in self.checks if c.status.open]

    @property
    def worst_overload(self) -> float:
        """The largest :attr:`~actuator_selection.sizing.checks.Check.overload` of its
        checks: 0 unless a check failed, else how far the worst one is over its limit."""
        return max((c.overload for c in self.checks), default=0.0)


_CHECKS: Any = defer_field(Candidate, "checks")
"""A candidate's checks may be :class:`~actuator_selection.sizing.checks.DeferredChecks`
(the engine's), built when first read."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Selection:
    """The flowchart over many actuators, ranked (see :func:`rank`)."""

    mean_speed_rpm: float
    duty_cycle_percent: float
    cycle_time_s: float
    candidates: tuple[Candidate, ...]
    profile: Profile
    """The cycle as the flowchart saw it (peak speed, load, pieces)."""


_VERDICT_ORDER = {Verdict.SUITABLE: 0, Verdict.UNCONFIRMED: 1, Verdict.UNSUITABLE: 2}


def ranking_key(candidate: Candidate) -> tuple[int, float, float, float, str]:
    """Sort key: verdict (suitable, unconfirmed, unsuitable), then, among the unsuitable,
    the nearest miss (the smallest :attr:`Candidate.worst_overload`), then the smallest
    actuator (:func:`size_key`). When nothing fits, the actuator that misses least comes
    first, not the smallest one, which misses most."""
    return (
        _VERDICT_ORDER[candidate.verdict],
        candidate.worst_overload,
        *size_key(candidate.actuator),
    )


def size_key(a: Actuator) -> tuple[float, float, str]:
    """The smallest actuator first: the lowest peak torque T_max, then the lowest inertia
    J_A, so that the least actuator that does the job comes first. Unknown values sort
    last, and the model name breaks ties so that the order is total and repeatable."""
    inf = float("inf")
    return (
        a.max_torque_nm if a.max_torque_nm is not None else inf,
        a.inertia_kgm2 if a.inertia_kgm2 is not None else inf,
        a.model,
    )
