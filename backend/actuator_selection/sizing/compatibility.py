"""Which servo controllers drive an actuator (Table 521.1).

Table 521.1 (:mod:`actuator_selection.catalogue.controllers`) marks, per controller,
the actuator families it drives, the DC bus voltage classes, the temperature sensor
inputs and the motor feedback systems: ``●`` practically tested, ``○`` theoretically
possible, empty = not supported. An actuator matches a controller when every criterion
is supported; the criterion's level is the best mark among the options the actuator
offers (tested beats possible). A criterion the actuator has no data for is neither
confirmed nor excluded: the match says "no data" instead of guessing.

Worked example (Table 521.1, rows 1 and 26): a CHA with a KTY 84-130 and a
2-pole resolver on a ≥ 560 VDC bus is practically tested on the SIMODRIVE 611D;
the Unidrive has no KTY input.

>>> from actuator_selection.catalogue.controllers import (
...     BusClass, FeedbackSystem, ProductFamily, SupportLevel)
>>> from actuator_selection.catalogue.parts import TemperatureSensor
>>> t = TemperatureSensor.KTY84_130
>>> siemens = Controller(manufacturer="SIEMENS", type="SIMODRIVE 611D", source_row=1,
...     families={ProductFamily.CHA_CHM: SupportLevel.TESTED},
...     bus_classes={BusClass.V560: SupportLevel.TESTED},
...     temperature_sensors={t: SupportLevel.TESTED},
...     feedback_systems={FeedbackSystem.RESOLVER_2POLE: SupportLevel.TESTED})
>>> ct = Controller(manufacturer="Control Techniques", type="Unidrive", source_row=26,
...     families={ProductFamily.CHA_CHM: SupportLevel.TESTED},
...     bus_classes={BusClass.V560: SupportLevel.POSSIBLE},
...     feedback_systems={FeedbackSystem.RESOLVER_2POLE: SupportLevel.TESTED})
>>> cha = ActuatorInterface(family=ProductFamily.CHA_CHM, bus_classes=frozenset({BusClass.V560}),
...     temperature_sensors=frozenset({t}),
...     feedback_systems=frozenset({FeedbackSystem.RESOLVER_2POLE}))
>>> r = match_controllers(actuator=cha, controllers=[ct, siemens])
>>> [(m.controller.type, m.verdict.value) for m in r.matches]
[('SIMODRIVE 611D', 'tested'), ('Unidrive', 'excluded')]
>>> r.excluded[0].excluded_by[0].message
'temperature sensor KTY 84-130: not supported (no mark in Table 521.1)'
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from enum import StrEnum

from actuator_selection.catalogue.controllers import (
    LABELS,
    ActuatorInterface,
    Controller,
    Criterion,
    Option,
    SupportLevel,
)
from actuator_selection.phrases.check_messages import phrase
from actuator_selection.phrases.messages import N_

REFERENCE = N_("Table 521.1")


class CriterionStatus(StrEnum):
    """How one criterion of Table 521.1 came out for one controller."""

    TESTED = "tested"
    POSSIBLE = "possible"
    EXCLUDED = "excluded"
    NO_DATA = "no_data"


@dataclass(frozen=True, slots=True, kw_only=True)
class CriterionResult:
    """One criterion for one controller: its status and the option that decided it."""

    criterion: Criterion
    status: CriterionStatus
    option: Option | None
    message: str
    reference: str = REFERENCE


class MatchVerdict(StrEnum):
    """Outcome for one controller, best first."""

    TESTED = "tested"
    """Every criterion practically tested."""
    POSSIBLE = "possible"
    """Every criterion supported, at least one only theoretically possible."""
    UNCONFIRMED = "unconfirmed"
    """Nothing excludes the controller, but the actuator lacks data for a criterion."""
    EXCLUDED = "excluded"
    """At least one criterion is not supported."""


_VERDICT_ORDER = {
    MatchVerdict.TESTED: 0,
    MatchVerdict.POSSIBLE: 1,
    MatchVerdict.UNCONFIRMED: 2,
    MatchVerdict.EXCLUDED: 3,
}


@dataclass(frozen=True, slots=True, kw_only=True)
class ControllerMatch:
    """The matching of one controller against one actuator (Table 521.1)."""

    controller: Controller
    verdict: MatchVerdict
    criteria: tuple[CriterionResult, ...]

    @property
    def excluded_by(self) -> tuple[CriterionResult, ...]:
        """The criteria that exclude the controller (empty unless ``excluded``)."""
        return tuple(c for c in self.criteria if c.status is CriterionStatus.EXCLUDED)

    @property
    def no_data(self) -> tuple[CriterionResult, ...]:
        """The criteria the actuator has no data for."""
        return tuple(c for c in self.criteria if c.status is CriterionStatus.NO_DATA)


@dataclass(frozen=True, slots=True, kw_only=True)
class CompatibilityResult:
    """All controllers, ordered: fully tested first, then possible, unconfirmed, excluded."""

    matches: tuple[ControllerMatch, ...]

    @property
    def supported(self) -> tuple[ControllerMatch, ...]:
        """Controllers confirmed by every criterion (tested or possible)."""
        return tuple(
            m for m in self.matches if m.verdict in (MatchVerdict.TESTED, MatchVerdict.POSSIBLE)
        )

    @property
    def unconfirmed(self) -> tuple[ControllerMatch, ...]:
        """Controllers neither confirmed nor excluded, for lack of actuator data."""
        return tuple(m for m in self.matches if m.verdict is MatchVerdict.UNCONFIRMED)

    @property
    def excluded(self) -> tuple[ControllerMatch, ...]:
        """Controllers that a criterion excludes."""
        return tuple(m for m in self.matches if m.verdict is MatchVerdict.EXCLUDED)


def evaluate_criterion(
    *, controller: Controller, actuator: ActuatorInterface, criterion: Criterion
) -> CriterionResult:
    """The best mark among the actuator's options for one criterion (Table 521.1).

    Tested beats possible; no mark for any option excludes; an unknown option
    is ``no_data``.
    """
    label = LABELS[criterion]
    options = actuator.options(criterion)
    if options is None:
        return CriterionResult(
            criterion=criterion,
            status=CriterionStatus.NO_DATA,
            option=None,
            message=phrase("criterion.no_data", criterion=label),
        )
    best: tuple[SupportLevel, Option] | None = None
    for option in options:
        level = controller.level(option)
        if level is SupportLevel.TESTED:
            best = (level, option)
            break
        if level is SupportLevel.POSSIBLE and best is None:
            best = (level, option)
    if best is None:
        return CriterionResult(
            criterion=criterion,
            status=CriterionStatus.EXCLUDED,
            option=options[0] if len(options) == 1 else None,
            message=phrase(
                "criterion.excluded",
                criterion=label,
                options=tuple(LABELS[o] for o in options),
                reference=REFERENCE,
            ),
        )
    level, option = best
    return CriterionResult(
        criterion=criterion,
        status=CriterionStatus(level.value),
        option=option,
        message=phrase(f"criterion.{level.value}", criterion=label, option=LABELS[option]),
    )


def match_controller(*, controller: Controller, actuator: ActuatorInterface) -> ControllerMatch:
    """All four criteria of Table 521.1 for one controller, and the verdict."""
    results = tuple(
        evaluate_criterion(controller=controller, actuator=actuator, criterion=c) for c in Criterion
    )
    statuses = {r.status for r in results}
    if CriterionStatus.EXCLUDED in statuses:
        verdict = MatchVerdict.EXCLUDED
    elif CriterionStatus.NO_DATA in statuses:
        verdict = MatchVerdict.UNCONFIRMED
    elif CriterionStatus.POSSIBLE in statuses:
        verdict = MatchVerdict.POSSIBLE
    else:
        verdict = MatchVerdict.TESTED
    return ControllerMatch(controller=controller, verdict=verdict, criteria=results)


def ranking_key(match: ControllerMatch) -> tuple[int, int, int, bool, int, str]:
    """Sort key: verdict, then fewer "possible", then fewer "no data", then table order."""
    possible = sum(c.status is CriterionStatus.POSSIBLE for c in match.criteria)
    row = match.controller.source_row
    return (
        _VERDICT_ORDER[match.verdict],
        possible,
        len(match.no_data),
        row is None,
        row or 0,
        match.controller.name,
    )


def match_controllers(
    *, actuator: ActuatorInterface, controllers: Iterable[Controller]
) -> CompatibilityResult:
    """Match every controller of Table 521.1 against an actuator, fully tested first.

    See the module example.
    """
    matches = sorted(
        (match_controller(controller=c, actuator=actuator) for c in controllers),
        key=ranking_key,
    )
    return CompatibilityResult(matches=tuple(matches))
