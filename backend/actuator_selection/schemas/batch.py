"""The batch selection contract: thousands of load cases in one request (ERP integration).

Each case is a :class:`~actuator_selection.schemas.selections.SelectionRequest`; each
candidate has the names and values of a single selection's
:class:`~actuator_selection.schemas.selections.CandidateOut`, less the detail lists the
request leaves out (``include_checks``, ``include_controllers``). The response models
document the contract (OpenAPI); the endpoint writes the same JSON from plain dicts
(``services/presenters/batch.py``, validated against these models in the tests), because
building a pydantic model per candidate and check would cost more than the engineering
of the whole batch.
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import ConfigDict, Field, field_validator

from actuator_selection.schemas.checks import CheckOut
from actuator_selection.schemas.common import ResponseModel, StrictModel
from actuator_selection.schemas.controllers import DriveOptionOut
from actuator_selection.schemas.selections import (
    RANKING_RULE,
    WORKED_EXAMPLE,
    CandidateFigures,
    ResolvedLoad,
    SelectionRequest,
)

MAX_BATCH_CASES = 20_000
"""Load cases per request: two ERP planning runs of 10,000; ~1–2 s of work, ~120 MB of
answer with checks (``include_checks``) at the default top 3."""
MAX_TOP = 10
"""Candidates per case at most: a short list to choose from, not the catalogue."""
MAX_BATCH_CANDIDATES = 60_000
"""Candidates per response (cases × top): ~2 kB each with checks, so ≤ ~120 MB."""
MAX_CANDIDATES_WITH_CONTROLLERS = 1_000
"""Candidates per response with ``include_controllers``: each lists every controller of
Table 521.1 not excluded, with its criteria and voltage check (~10–30 kB, ~1 ms each)."""
MAX_STORED_CASES = 50
"""Cases per request with ``store: true``: each is a whole selection of the catalogue with
the drive options of every actuator, as POST /selections stores it (measured ~1.1 MB of
JSON and ~0.14 s a case on the starter catalogue), all written in one transaction."""


MAX_CASE_ID_LENGTH = 100
"""Characters of a case's ``case_id``: room for an ERP's order and position numbers."""


CaseId = Annotated[str, Field(min_length=1, max_length=MAX_CASE_ID_LENGTH)]
"""The client's own id of a load case (one line of text)."""


class BatchCaseIn(SelectionRequest):
    """A load case of a batch: a selection request, and the client's own name for it."""

    case_id: CaseId | None = Field(
        default=None,
        description="the client's own id of the case (an order position, say), echoed as "
        "its result's `case_id`; not stored with a selection",
    )


class BatchSelectionRequest(StrictModel):
    """Many load cases sized against the catalogue in one request."""

    model_config = ConfigDict(
        json_schema_extra={
            "examples": [
                {
                    "cases": [
                        WORKED_EXAMPLE,
                        {
                            "load": {
                                "type": "ball_screw",
                                "speed_rpm": 60,
                                "mass_kg": 200,
                                "lead_m": 0.01,
                                "friction_coefficient": 0.1,
                                "efficiency": 0.9,
                            },
                            "cycle": {
                                "accel_s": 0.2,
                                "constant_s": 0.5,
                                "decel_s": 0.2,
                                "pause_s": 0.5,
                            },
                        },
                    ],
                    "top": 3,
                    "include_checks": False,
                }
            ]
        }
    )

    cases: list[BatchCaseIn] = Field(
        min_length=1,
        max_length=MAX_BATCH_CASES,
        description=f"load cases, each exactly as for POST /selections; at most {MAX_BATCH_CASES}",
    )
    top: int = Field(
        default=3,
        ge=1,
        le=MAX_TOP,
        description=f"best candidates returned per case; cases × top ≤ {MAX_BATCH_CANDIDATES}",
    )
    include_checks: bool = Field(
        default=True,
        description="false leaves each candidate's `checks` out (`reasons` stay)",
    )
    include_messages: bool = Field(
        default=False,
        description="true adds the words: each check's `message`, each candidate's `reasons` "
        "and `controllers_note`, in the answer's language (Accept-Language), as a single "
        "selection words them. False (the default) gives the messages as codes and "
        "parameters only (`message_code`, `message_params`, `reason_checks`, "
        "`controllers_note_code`, `controllers_note_params`), from which a client words "
        "them in any language: a batch's words cost more than its engineering",
    )
    include_controllers: bool = Field(
        default=False,
        description="true adds each candidate's `controllers` list (Table 521.1, Eq. 521.2) "
        f"as a single selection gives it; cases × top ≤ {MAX_CANDIDATES_WITH_CONTROLLERS}. "
        "`controllers_excluded` and `controllers_note` are always given",
    )
    store: bool = Field(
        default=False,
        description="true stores each case as a selection (GET /selections/{id}) and returns "
        f"its id; at most {MAX_STORED_CASES} cases",
    )

    @field_validator("cases", mode="before")
    @classmethod
    def _count_first(cls, value: Any) -> Any:
        # Before each case is validated: 20,001 cases took ~3.4 s of validation to be
        # refused by max_length, which pydantic checks only after the items.
        if isinstance(value, list) and len(value) > MAX_BATCH_CASES:
            raise ValueError(
                f"at most {MAX_BATCH_CASES} cases per request, got {len(value)}: "
                "send the rest in further requests"
            )
        return value


class BatchCheckOut(CheckOut):
    """A check as a single selection gives it; its ``message`` only with include_messages."""

    message: str | None = Field(  # type: ignore[assignment]
        default=None,
        description="the check in words, in the answer's language (Content-Language); left "
        "out unless include_messages (`message_code` and `message_params` word it)",
    )


class BatchCandidateOut(CandidateFigures):
    """A candidate as a single selection's detail gives it (CandidateDetailOut); its detail
    lists only if asked for, its words only with include_messages."""

    reasons: list[str] | None = Field(
        default=None,
        description="messages of the checks that did not pass; left out unless "
        "include_messages (`reason_checks` names the checks)",
    )
    reason_checks: list[str] = Field(
        description="names of the checks that fail, warn or lack data, in the flowchart's "
        "order: the checks `reasons` words (two may share one message)"
    )
    checks: list[BatchCheckOut] | None = Field(
        default=None, description="the flowchart's checks; left out unless include_checks"
    )
    controllers: list[DriveOptionOut] | None = Field(
        default=None,
        description="controllers of Table 521.1 not excluded, best first, each with its "
        "output-voltage check (Eq. 521.2) at n_2; left out unless include_controllers",
    )
    controllers_excluded: int = Field(description="how many controllers Table 521.1 excludes")
    controllers_note: str | None = Field(
        default=None,
        description="what the controller list rests on, in words; left out unless include_messages",
    )
    controllers_note_code: str | None = Field(
        default=None, description="stable code of `controllers_note`, as in a candidate's detail"
    )
    controllers_note_params: dict[str, Any] | None = Field(
        default=None, description="the values `controllers_note` names, as in the detail"
    )


class BatchResultOut(ResponseModel):
    """One load case: its cycle figures and its best candidates, ranked."""

    id: str | None = Field(description="the stored selection (store: true), else null")
    case_id: str | None = Field(description="the case's `case_id` as sent, else null")
    load: ResolvedLoad
    cycle_time_s: float = Field(description="t_0 = t_1 + t_2 + t_3 + t_p [s]")
    mean_speed_rpm: float = Field(description="n_av (Eq. 514.3) [rpm]")
    duty_cycle_percent: float = Field(description="ED (Eq. 514.4) [%]")
    candidates: list[BatchCandidateOut] = Field(description="the best `top` candidates")


class BatchSelectionOut(ResponseModel):
    """The results of a batch, in the order of the cases sent."""

    catalogue_version: int = Field(description="version of the catalogue the batch used")
    ranking: str = Field(default=RANKING_RULE, description="how candidates are ordered")
    results: list[BatchResultOut]
