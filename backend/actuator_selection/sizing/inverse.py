"""Inverse sizing: how far a load case may go for one actuator (issue "Real axes").

For a chosen actuator and load case, the shortest pause, the shortest acceleration time
and the largest load inertia with which no check of the flowchart fails, each found from
the same rules (the engine, :func:`~actuator_selection.sizing.engine.evaluate_cases`) by
bisection, and answered with the check that fails just beyond it (the limiting check).

"No check fails" is the flowchart's verdict ``suitable`` or ``unconfirmed``: a check that
lacks catalogue data cannot be passed by any value, so the limit is stated with the
verdict at the limit, and an ``unconfirmed`` one says which data is missing.

The search assumes what the physics gives in the usable range: a longer pause only lowers
T_rms and n_av (monotone); a larger J_L only raises T_1, |T_3|, T_rms and J_L/J_A
(monotone); a longer t_1 lowers T_1 and, where the acceleration dominates, T_rms (checked
at both ends of the range; where it is not monotone the bound is one where the checks
change, found to the stated tolerance).

The chapter's worked example on the FHA-25C-50-L (Table 516.1/516.3, J_A = 0.86 kgm²,
T_max = 151 Nm): T_1 = 5 + (0.86 + J_L)·(2π/60·40)/0.1 ≤ 151 gives J_L ≤ 2.6256 kgm²,
and J_L ≤ 3·J_A = 2.58 kgm² binds first:

>>> from actuator_selection.catalogue.actuators import Actuator
>>> from actuator_selection.sizing.cycle import Load, SpeedPattern
>>> from actuator_selection.sizing.selection import Application
>>> fha = Actuator(model="FHA-25C-50-L", family="FHA-C", gear_ratio=50,
...                max_torque_nm=151, max_speed_rpm=90, inertia_kgm2=0.86)
>>> app = Application(
...     pattern=SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1),
...     load=Load(torque_nm=5, inertia_kgm2=1.3))
>>> limit = largest_load_inertia(fha, app)
>>> round(limit.value, 6), limit.limiting_checks
(2.58, ('inertia_ratio',))
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.check_messages import phrase
from actuator_selection.sizing.checks import Check, Rule, Status
from actuator_selection.sizing.engine import case_verdicts, catalogue_arrays, evaluate_cases
from actuator_selection.sizing.selection import Application, Candidate, Verdict

RELATIVE_TOLERANCE = 1e-9
"""Bisection stops when the bracket is this small relative to the bound."""
MAX_PAUSE_S = 86_400.0
"""The longest pause searched: a day (the API's bound on a duration)."""
MIN_ACCEL_S = 1e-4
"""The shortest acceleration time searched (the API's bound on a ramp)."""
MAX_ACCEL_S = 86_400.0
MAX_LOAD_INERTIA_KGM2 = 1e6
"""The largest load inertia searched (the API's bound)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Limit:
    """How far one quantity of the load case may go with one actuator."""

    quantity: str
    """``pause_s``, ``accel_s`` or ``load_inertia_kgm2``."""
    bound: str
    """``min`` (the shortest pause or ramp) or ``max`` (the largest inertia)."""
    value: float | None
    """The bound; None where no value in the searched range lets every check pass."""
    unit: str
    limiting_checks: tuple[str, ...]
    """The checks that fail just beyond the bound (at the end of the range where there is
    no bound); empty where the range's end is reached with every check passing."""
    messages: tuple[str, ...]
    """Those checks' messages just beyond the bound."""
    verdict: Verdict | None
    """The flowchart's verdict at the bound (``unconfirmed``: a check lacks data)."""
    note: str
    reason: str | None = None
    """Why ``value`` is None, in words with a code (a check message's
    :class:`~actuator_selection.phrases.check_messages.Phrase`): ``limit.none.min``,
    ``limit.none.max`` or ``limit.accel_no_ramp``."""


Vary = Callable[[Application, float], Application]


def _fails(candidate: Candidate) -> tuple[Check, ...]:
    if candidate.verdict is not Verdict.UNSUITABLE:  # no check fails: none built
        return ()
    return tuple(c for c in candidate.checks if c.status is Status.FAIL)


class _Probe:
    """One probe of a search: its load case and verdict, decided from the engine's status
    codes (:func:`~actuator_selection.sizing.engine.case_verdicts`); its candidate, with
    the checks in words, is evaluated only where the answer reads it (the ends of the
    bisection), so the probes between cost no words."""

    __slots__ = ("_candidate", "_evaluate", "app", "verdict")

    def __init__(
        self,
        app: Application,
        verdict: Verdict | None,
        evaluate: Callable[[Sequence[Application]], list[Candidate]],
    ) -> None:
        self.app = app
        self._evaluate = evaluate
        self._candidate: Candidate | None = None
        if verdict is None:  # a torque overflowed: the candidate names the input
            verdict = self.candidate.verdict
        self.verdict: Verdict = verdict

    @property
    def fails(self) -> bool:
        """Whether a check fails (the verdict ``unsuitable``)."""
        return self.verdict is Verdict.UNSUITABLE

    @property
    def candidate(self) -> Candidate:
        if self._candidate is None:
            (self._candidate,) = self._evaluate([self.app])
        return self._candidate


_LEVELS = 4
"""The bisection's steps decided per engine call: every midpoint the next this many
steps could take (2⁴ − 1 = 15 cases) is evaluated at once, then the steps are taken
one by one as before, each on its own midpoint's candidate: the same midpoints and the
same outcome as one evaluation per step, at a fraction of the engine's calls."""


def _open(ok_side: float, bad_side: float) -> float | None:
    """The next midpoint of the bracket [bad, ok], or None where the bisection stops (the
    bracket within the tolerance, or no float between its ends)."""
    if not abs(ok_side - bad_side) > RELATIVE_TOLERANCE * max(abs(ok_side), abs(bad_side)):
        return None
    middle = (ok_side + bad_side) / 2
    return None if middle in (ok_side, bad_side) else middle


def _bisect(
    evaluate: Callable[[Sequence[Application]], list[_Probe]],
    vary: Callable[[float], Application],
    ok_side: float,
    bad_side: float,
) -> tuple[float, _Probe, _Probe]:
    """Narrow [bad, ok] to the tolerance; the ok end, its candidate and the bad end's
    (:data:`_LEVELS` steps per engine call)."""
    ok, bad = evaluate([vary(ok_side), vary(bad_side)])
    while True:
        midpoints: dict[tuple[float, float], float] = {}
        brackets = [(ok_side, bad_side)]
        for _ in range(_LEVELS):  # the brackets the next steps may reach, breadth first
            reached = []
            for o, b in brackets:
                middle = _open(o, b)
                if middle is not None:
                    midpoints[(o, b)] = middle
                    reached += [(middle, b), (o, middle)]
            brackets = reached
        if not midpoints:
            return ok_side, ok, bad
        found = dict(zip(midpoints, evaluate([vary(m) for m in midpoints.values()]), strict=True))
        while (ok_side, bad_side) in found:
            middle, candidate = midpoints[(ok_side, bad_side)], found[(ok_side, bad_side)]
            if candidate.fails:
                bad_side, bad = middle, candidate
            else:
                ok_side, ok = middle, candidate


def _doubling(start: float, first: float, end: float) -> list[float]:
    """The probes of a search stepping up from ``start`` by factors of 2: ``first``, then
    each twice the last, the last one ``end``."""
    probes = [first]
    while probes[-1] < end:
        probes.append(min(probes[-1] * 2, end))
    return probes


def _search(
    actuator: Actuator,
    vary: Callable[[float], Application],
    *,
    quantity: str,
    unit: str,
    bound: str,
    start: float,
    end: float,
    rules: Sequence[Rule] | None,
) -> Limit:
    """The bound between ``start`` (where the search begins: the best end for a ``min``,
    0 for a ``max``) and ``end`` (the range's far end), stepping by factors of 2."""
    arrays = catalogue_arrays((actuator,))  # the actuator as the engine reads it, once

    def candidates(apps: Sequence[Application]) -> list[Candidate]:
        return evaluate_cases(actuator, apps, rules=rules, arrays=arrays)

    def evaluate(apps: Sequence[Application]) -> list[_Probe]:
        verdicts = case_verdicts(actuator, apps, rules=rules, arrays=arrays)
        return [_Probe(app, v, candidates) for app, v in zip(apps, verdicts, strict=True)]

    (at_start,) = evaluate([vary(start)])
    if bound == "min":
        if not at_start.fails:
            return Limit(
                quantity=quantity,
                bound=bound,
                value=start,
                unit=unit,
                limiting_checks=(),
                messages=(),
                verdict=at_start.verdict,
                note="every check passes at the shortest value searched",
            )
        # step up from the failing start until no check fails (every step evaluated at once)
        bad_side = start
        probes = _doubling(start, max(start * 2, start + 1e-3), end)
        for probe, candidate in zip(probes, evaluate([vary(p) for p in probes]), strict=True):
            if not candidate.fails:
                break
            bad_side = probe
            if probe >= end:
                return _none_in_range(quantity, unit, bound, end, candidate.candidate)
        value, ok, bad = _bisect(evaluate, vary, probe, bad_side)
    else:
        if at_start.fails:
            return _none_in_range(quantity, unit, bound, start, at_start.candidate)
        ok_side = start
        probes = _doubling(start, max(start * 2, 1e-3), end)
        for probe, candidate in zip(probes, evaluate([vary(p) for p in probes]), strict=True):
            if candidate.fails:
                break
            ok_side = probe
            if probe >= end:
                return Limit(
                    quantity=quantity,
                    bound=bound,
                    value=end,
                    unit=unit,
                    limiting_checks=(),
                    messages=(),
                    verdict=candidate.verdict,
                    note=f"every check passes up to the largest value searched ({end:g} {unit})",
                )
        value, ok, bad = _bisect(evaluate, vary, ok_side, probe)
    failing = _fails(bad.candidate)
    return Limit(
        quantity=quantity,
        bound=bound,
        value=value,
        unit=unit,
        limiting_checks=tuple(c.name for c in failing),
        messages=tuple(c.message for c in failing),
        verdict=ok.verdict,
        note=f"found by bisection over the flowchart to {RELATIVE_TOLERANCE:g} relative",
    )


def _none_in_range(
    quantity: str, unit: str, bound: str, where: float, candidate: Candidate
) -> Limit:
    failing = _fails(candidate)
    return Limit(
        quantity=quantity,
        bound=bound,
        value=None,
        unit=unit,
        limiting_checks=tuple(c.name for c in failing),
        messages=tuple(c.message for c in failing),
        verdict=candidate.verdict,
        note=f"a check fails at every value searched (still at {where:g} {unit})",
        reason=phrase(
            f"limit.none.{bound}",
            value=float(where),
            unit=unit,
            check=failing[0].message if failing else "",
        ),
    )


def shortest_pause(
    actuator: Actuator, app: Application, *, rules: Sequence[Rule] | None = None
) -> Limit:
    """The shortest pause t_p with which no check fails: t_p of the chapter's cycle, or the
    last segment of a cycle of segments where that is a standstill."""
    if app.pattern is not None:
        pattern = app.pattern

        def vary(t: float) -> Application:
            return dataclasses.replace(app, pattern=dataclasses.replace(pattern, pause_s=t))

    else:
        motion = app.cycle
        last = motion.segments[-1]
        if last.start_rpm != 0 or last.end_rpm != 0:
            raise InvalidInputError(
                "cycle.segments",
                "the shortest pause is solved for a cycle that ends at standstill: make the "
                "last segment a dwell at speed 0",
            )

        def vary(t: float) -> Application:
            dwell = dataclasses.replace(last, duration_s=t)
            segments = (*motion.segments[:-1], dwell)
            return dataclasses.replace(app, motion=dataclasses.replace(motion, segments=segments))

    return _search(
        actuator,
        vary,
        quantity="pause_s",
        unit="s",
        bound="min",
        start=0.0,
        end=MAX_PAUSE_S,
        rules=rules,
    )


def shortest_accel(
    actuator: Actuator, app: Application, *, rules: Sequence[Rule] | None = None
) -> Limit:
    """The shortest acceleration time t_1 (t_3 as given) with which no check fails: t_1 of
    the chapter's cycle, or the first segment of a cycle of segments where that is an
    acceleration from standstill (a mechanism's trapezoid); else no value, and why."""
    if app.pattern is not None:
        pattern = app.pattern

        def vary(t: float) -> Application:
            return dataclasses.replace(app, pattern=dataclasses.replace(pattern, accel_s=t))

    else:
        motion = app.cycle
        first = motion.segments[0]
        if first.start_rpm != 0 or first.end_rpm == 0:
            return Limit(
                quantity="accel_s",
                bound="min",
                value=None,
                unit="s",
                limiting_checks=(),
                messages=(),
                verdict=None,
                note="the cycle does not start with an acceleration from standstill",
                reason=phrase("limit.accel_no_ramp"),
            )

        def vary(t: float) -> Application:
            ramp = dataclasses.replace(first, duration_s=t)
            segments = (ramp, *motion.segments[1:])
            return dataclasses.replace(app, motion=dataclasses.replace(motion, segments=segments))

    return _search(
        actuator,
        vary,
        quantity="accel_s",
        unit="s",
        bound="min",
        start=MIN_ACCEL_S,
        end=MAX_ACCEL_S,
        rules=rules,
    )


def largest_load_inertia(
    actuator: Actuator, app: Application, *, rules: Sequence[Rule] | None = None
) -> Limit:
    """The largest load inertia J_L at the output with which no check fails."""
    if app.load is not None:
        load = app.load

        def vary(j: float) -> Application:
            return dataclasses.replace(app, load=dataclasses.replace(load, inertia_kgm2=j))

    else:
        motion = app.cycle

        def vary(j: float) -> Application:
            axis = dataclasses.replace(motion.load, inertia_kgm2=j)
            return dataclasses.replace(app, motion=dataclasses.replace(motion, load=axis))

    return _search(
        actuator,
        vary,
        quantity="load_inertia_kgm2",
        unit="kgm²",
        bound="max",
        start=0.0,
        end=MAX_LOAD_INERTIA_KGM2,
        rules=rules,
    )


def limits(
    actuator: Actuator, app: Application, *, rules: Sequence[Rule] | None = None
) -> tuple[Limit, ...]:
    """The shortest pause, the shortest t_1 (without a value, and why, where the cycle has
    none) and the largest J_L."""
    found = [shortest_pause(actuator, app, rules=rules)]
    found.append(shortest_accel(actuator, app, rules=rules))
    found.append(largest_load_inertia(actuator, app, rules=rules))
    if any(math.isnan(x.value) for x in found if x.value is not None):
        raise InvalidInputError("load", "gives no finite limit")  # pragma: no cover
    return tuple(found)
