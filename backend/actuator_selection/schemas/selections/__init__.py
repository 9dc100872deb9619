"""The selection contract: what ERP systems and the web page send and receive.

Field names are part of the public API (issue "Selection engine end to end"); keep them.
"""

from __future__ import annotations

from actuator_selection.schemas.selections.answer import (
    RANKING_RULE,
    BindingChangeOut,
    BindingCheckOut,
    BindingOut,
    BindingTransmissionOut,
    CandidateDetailOut,
    CandidateFigures,
    CandidateOut,
    CandidatePageOut,
    CheckBrief,
    CheckRuleOut,
    ControllerRef,
    DriveOptionGroup,
    ResolvedLoad,
    SegmentOut,
    SegmentTorqueOut,
    SelectionOut,
    VerdictCounts,
    VoltageBrief,
)
from actuator_selection.schemas.selections.cycles import (
    AnyCycleIn,
    CycleIn,
    ProfileCycleIn,
    SegmentIn,
    SegmentsCycleIn,
)
from actuator_selection.schemas.selections.loads import (
    LOAD_TYPES,
    BallScrewLoad,
    DirectLoad,
    Friction,
    Inertia,
    LoadIn,
    Mass,
    RotaryTableLoad,
    SpeedRpm,
)
from actuator_selection.schemas.selections.request import (
    WORKED_EXAMPLE,
    GearIn,
    ModelName,
    SelectionRequest,
)

__all__ = [
    "LOAD_TYPES",
    "RANKING_RULE",
    "WORKED_EXAMPLE",
    "AnyCycleIn",
    "BallScrewLoad",
    "BindingChangeOut",
    "BindingCheckOut",
    "BindingOut",
    "BindingTransmissionOut",
    "CandidateDetailOut",
    "CandidateFigures",
    "CandidateOut",
    "CandidatePageOut",
    "CheckBrief",
    "CheckRuleOut",
    "ControllerRef",
    "CycleIn",
    "DirectLoad",
    "DriveOptionGroup",
    "Friction",
    "GearIn",
    "Inertia",
    "LoadIn",
    "Mass",
    "ModelName",
    "ProfileCycleIn",
    "ResolvedLoad",
    "RotaryTableLoad",
    "SegmentIn",
    "SegmentOut",
    "SegmentTorqueOut",
    "SegmentsCycleIn",
    "SelectionOut",
    "SelectionRequest",
    "SpeedRpm",
    "VerdictCounts",
    "VoltageBrief",
]
