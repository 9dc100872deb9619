"""Controllers of Table 521.1, their matching against actuators, and drive options."""

from __future__ import annotations

from enum import StrEnum
from typing import Any, Literal

from pydantic import Field

from actuator_selection.catalogue.controllers import (
    LABELS,
    MARK_COLUMNS,
    ActuatorInterface,
    Controller,
)
from actuator_selection.catalogue.records import ControllerRecord, InterfaceRecord
from actuator_selection.phrases.check_messages import Phrase, jsonable_params, phrase
from actuator_selection.schemas.checks import CheckOut, Localize, english, message_code
from actuator_selection.schemas.common import ResponseModel
from actuator_selection.sizing.compatibility import ControllerMatch, CriterionResult
from actuator_selection.sizing.drive import DriveOption, DriveOptions
from actuator_selection.sizing.selection import Check

Level = Literal["tested", "possible"]


class ControllerOut(ResponseModel):
    """One row of Table 521.1: marks by column, ``tested`` = ●, ``possible`` = ○."""

    manufacturer: str
    type: str
    variant: str | None = Field(description="tells apart rows whose type name repeats")
    source_row: int | None
    marks: dict[str, Level]
    correction: str | None = Field(description="what was changed against the source row")
    source: str

    @classmethod
    def from_record(cls, record: ControllerRecord) -> ControllerOut:
        """The response body of one controller."""
        c = record.controller
        marks: dict[str, Level] = {}
        for _, option, column in MARK_COLUMNS:
            level = c.level(option)
            if level is not None:
                marks[column] = level.value
        return cls(
            manufacturer=c.manufacturer,
            type=c.type,
            variant=c.variant,
            source_row=c.source_row,
            marks=marks,
            correction=c.correction,
            source=record.source,
        )


class CriterionOut(ResponseModel):
    """One criterion of Table 521.1 for one actuator–controller pair."""

    criterion: str
    status: Literal["tested", "possible", "excluded", "no_data"]
    option: str | None
    message: str = Field(description="the criterion in words, in the answer's language")
    message_code: str | None = Field(
        default=None,
        description="stable code of the message (`criterion.tested`, `criterion.no_data`, …)",
    )
    message_params: dict[str, Any] | None = Field(
        default=None, description="the values the message names (words in English)"
    )
    reference: str

    @classmethod
    def from_core(cls, result: CriterionResult, localize: Localize = english) -> CriterionOut:
        """The response body of one criterion, its message in words by ``localize``."""
        return cls(
            criterion=result.criterion.value,
            status=result.status.value,
            option=None if result.option is None else str(result.option.value),
            message=localize(result.message),
            message_code=message_code(result.message),
            message_params=jsonable_params(result.message),
            reference=result.reference,
        )


class ControllerMatchOut(ResponseModel):
    """How one controller fits one actuator (Table 521.1)."""

    manufacturer: str
    type: str
    variant: str | None
    source_row: int | None
    level: Literal["tested", "possible", "unconfirmed", "excluded"] = Field(
        description="tested: every criterion practically tested; possible: some only "
        "theoretically; unconfirmed: nothing excludes it but the actuator lacks data; "
        "excluded: a criterion is not supported"
    )
    missing: list[str] = Field(description="criteria the actuator has no data for")
    excluded_by: list[str]
    criteria: list[CriterionOut]

    @classmethod
    def from_core(cls, match: ControllerMatch, localize: Localize = english) -> ControllerMatchOut:
        """The response body of one match, its criteria in words by ``localize``."""
        c: Controller = match.controller
        return cls(
            manufacturer=c.manufacturer,
            type=c.type,
            variant=c.variant,
            source_row=c.source_row,
            level=match.verdict.value,
            missing=[r.criterion.value for r in match.no_data],
            excluded_by=[r.criterion.value for r in match.excluded_by],
            criteria=[CriterionOut.from_core(r, localize) for r in match.criteria],
        )


class DriveOptionOut(ControllerMatchOut):
    """A controller not excluded for a candidate, with its output-voltage check (Eq. 521.2)."""

    voltage: CheckOut


class InterfaceOut(ResponseModel):
    """What matching knows of an actuator; ``null`` = no public source gives it."""

    family_column: str | None
    dc_bus_classes: list[str] | None
    temperature_sensors: list[str] | None
    feedback_systems: list[str] | None
    derivation: str | None
    source: str | None

    @classmethod
    def from_record(cls, record: InterfaceRecord) -> InterfaceOut:
        """The response body of an actuator's matching data."""
        i: ActuatorInterface = record.interface

        def names(options: frozenset[StrEnum] | None) -> list[str] | None:
            return None if options is None else sorted(o.value for o in options)

        return cls(
            family_column=None if i.family is None else i.family.value,
            dc_bus_classes=names(i.bus_classes),
            temperature_sensors=names(i.temperature_sensors),
            feedback_systems=names(i.feedback_systems),
            derivation=record.derivation,
            source=record.source,
        )


class ActuatorControllersOut(ResponseModel):
    """Every controller of Table 521.1 matched against one actuator, best first."""

    model: str
    interface: InterfaceOut
    controllers: list[ControllerMatchOut]


class DriveOptionBodies:
    """Builds the candidates' ``controllers`` lists of one selection, each distinct part once.

    The starter catalogue's candidates list ~850 drive options between them, made of a
    few dozen distinct controller matches (matching is per interface, see ``services.catalogue``)
    and about as many distinct voltage checks. Building every option from its core
    objects was the largest cost of a selection's response; response models are frozen,
    so one instance of each part can stand in every list that holds it.
    """

    def __init__(self, localize: Localize = english) -> None:
        self._localize = localize
        self._matches: dict[ControllerMatch, dict[str, Any]] = {}
        self._checks: dict[Check, CheckOut] = {}

    def controllers(self, drive: DriveOptions) -> list[DriveOptionOut]:
        """The ``controllers`` list of a candidate with these drive options."""
        return [self._option(o) for o in drive.options]

    def _option(self, option: DriveOption) -> DriveOptionOut:
        match = self._matches.get(option.match)
        if match is None:
            # DriveOptionOut is ControllerMatchOut plus ``voltage``: its fields, criteria
            # already CriterionOut instances, which validation then only checks by type.
            match = self._matches[option.match] = dict(
                ControllerMatchOut.from_core(option.match, self._localize)
            )
        voltage = self._checks.get(option.voltage)
        if voltage is None:
            voltage = self._checks[option.voltage] = CheckOut.from_core(
                option.voltage, self._localize
            )
        return DriveOptionOut(**match, voltage=voltage)


def controllers_note(drive: DriveOptions) -> Phrase:
    """One sentence on what the controller list rests on (English text with its code and
    params; the criteria it lacks data for named in words)."""
    if not drive.options:
        return phrase("controllers_note.none")
    missing = sorted({r.criterion for o in drive.options for r in o.match.no_data})
    if not missing:
        return phrase(
            "controllers_note.supported", count=len(drive.options), excluded=drive.excluded
        )
    return phrase(
        "controllers_note.unconfirmed",
        count=len(drive.options),
        excluded=drive.excluded,
        missing=[LABELS[c] for c in missing],
    )
