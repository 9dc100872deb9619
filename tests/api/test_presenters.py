"""Each answer's presenter against its contract, the pydantic model that documents it.

The selection and batch presenters build plain JSON data for speed; these tests run the
engine for real (the chapter's worked example on its own actuator and over the whole
starter catalogue, a case nothing fits, a mechanism with an output load, a cycle of
segments), validate each presenter's output against its model and require the model to
write back the same JSON. The presenters must also agree with one another: a candidate's
detail and its batch form state the same numbers as the selection's ranking.
"""

from __future__ import annotations

from datetime import UTC, datetime
from typing import Any

import orjson
import pytest
from sqlalchemy.orm import Session
from tests import worked_example

from actuator_selection.db.repositories import CatalogueRepository
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.batch import BatchResultOut
from actuator_selection.schemas.controllers import controllers_note
from actuator_selection.schemas.limits import LimitsOut
from actuator_selection.schemas.selections import SelectionOut, SelectionRequest
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot, DriveContext
from actuator_selection.services.presenters.batch import (
    batch_candidate_body,
    candidate_body,
    coded_summary,
    controllers_summary,
    result_body,
)
from actuator_selection.services.presenters.detail import candidate_detail
from actuator_selection.services.presenters.limits import limits_answer
from actuator_selection.services.presenters.selection import ANSWER_VERSION, DEFAULT_TOP, dump_json
from actuator_selection.services.selections import size_selection
from actuator_selection.sizing.inverse import limits
from actuator_selection.sizing.selection import evaluate, select

CASES: dict[str, dict[str, Any]] = {
    "worked_example": {**worked_example.request(), "models": ["FHA-25C-50-L"]},
    "whole_catalogue": worked_example.request(),
    "nothing_fits": {
        "load": {"speed_rpm": 40, "torque_nm": 5000, "inertia_kgm2": 1.3},
        "cycle": worked_example.request()["cycle"],
    },
    "ball_screw_with_output_load": {
        "load": {
            "type": "ball_screw",
            "speed_rpm": 60,
            "mass_kg": 200,
            "lead_m": 0.01,
            "friction_coefficient": 0.1,
            "efficiency": 0.9,
        },
        "cycle": {"accel_s": 0.2, "constant_s": 0.5, "decel_s": 0.2, "pause_s": 0.5},
        "brake": True,
        "drive": True,
        "output_load": {
            "axial_force_n": 500,
            "radial_force_n": 200,
            "radial_lever_m": 0.05,
            "axial_lever_m": 0,
        },
    },
    "segments": {
        "load": {"torque_nm": 2, "inertia_kgm2": 0.3},
        "cycle": {
            "segments": [
                {"speed": 30, "duration_s": 0.2, "jerk_share": 0.5},
                {"duration_s": 0.5, "process_load": 3},
                {"speed": 0, "duration_s": 0.2},
                {"duration_s": 1},
            ]
        },
    },
}


@pytest.fixture
def catalogue(session: Session) -> CatalogueSnapshot:
    return CatalogueCache().snapshot(session)


def _request(name: str) -> SelectionRequest:
    return SelectionRequest.model_validate(CASES[name])


def _selection_answer(request: SelectionRequest, catalogue: CatalogueSnapshot) -> bytes:
    app = request.to_core()
    now = datetime(2026, 11, 27, 10, 0, tzinfo=UTC)
    actuators = catalogue.actuators_of(request.models)
    return size_selection(request, app, actuators, catalogue, now).answer


@pytest.mark.parametrize("name", CASES)
def test_selection_presenter_writes_its_model(name: str, catalogue: CatalogueSnapshot) -> None:
    """The answer is SelectionOut, every value as the model writes it back, and it states
    every field: a stored answer of ANSWER_VERSION is read strictly."""
    answer = _selection_answer(_request(name), catalogue)
    parsed = SelectionOut.model_validate_json(answer)
    assert parsed.model_dump(mode="json", exclude_unset=True) == orjson.loads(answer)
    assert set(orjson.loads(answer)) == set(SelectionOut.model_fields)
    assert ANSWER_VERSION == 3
    if name == "nothing_fits":
        assert parsed.binding is not None
        assert all(c.verdict == "unsuitable" for c in parsed.candidates)
    if name == "whole_catalogue":
        assert parsed.total_candidates == len(catalogue.actuators_of(None)) > 50
        assert len(parsed.candidates) == DEFAULT_TOP < parsed.total_candidates
        assert parsed.next_cursor is not None


def _brief(check: dict[str, Any]) -> dict[str, Any]:
    """A full check (CheckOut) as the selection's ranking lists it (CheckBrief)."""
    out = {k: check[k] for k in ("name", "status", "value", "limit")}
    if check["approximate"]:
        out["approximate"] = True
    return out


OPEN = ("fail", "warn", "no_data")
"""The statuses of a candidate's reasons."""


@pytest.mark.parametrize("name", ["worked_example", "nothing_fits", "ball_screw_with_output_load"])
def test_detail_and_batch_presenters_agree_with_the_ranking(
    name: str, catalogue: CatalogueSnapshot, session: Session
) -> None:
    """A candidate's detail (CandidateDetailOut) and its batch form (BatchCandidateOut,
    in a BatchResultOut) from the engine's own candidate state the ranking's figures."""
    request = _request(name)
    app = request.to_core()
    ranking = orjson.loads(_selection_answer(request, catalogue))
    drives = DriveContext(catalogue)
    speed = app.profile.peak_speed_rpm
    selection = select(catalogue.actuators_of(request.models), app)
    bodies = []
    for ranked, candidate in zip(ranking["candidates"][:5], selection.candidates, strict=False):
        actuator = candidate.actuator
        assert ranked["model"] == actuator.model
        drive = drives.options(actuator, speed_rpm=speed)
        record = CatalogueRepository(session).actuator(actuator.model)
        assert record is not None
        detail = candidate_detail(
            selection_id=ranking["id"],
            catalogue_version=catalogue.version,
            candidate=evaluate(actuator, app),
            profile=app.profile,
            drive=drive,
            actuator=ActuatorOut.from_record(record),
        )
        figures = {k: v for k, v in ranked.items() if k not in ("checks", "drive_options")}
        assert detail.model_dump(mode="json", include=set(figures)) == figures
        checks = [c.model_dump(mode="json") for c in detail.checks]
        assert [_brief(c) for c in checks] == [
            {k: v for k, v in c.items() if k != "missing"} for c in ranked["checks"]
        ]
        body = candidate_body(
            candidate,
            include_checks=True,
            controllers=[c.model_dump(mode="json") for c in detail.controllers],
            controllers_summary=controllers_summary(drive.excluded, controllers_note(drive)),
        )
        assert body == detail.model_dump(
            mode="json",
            exclude={"selection_id", "catalogue_version", "actuator", "segment_torques"},
        )
        summary = controllers_summary(drive.excluded, controllers_note(drive))
        for include_messages in (True, False):
            batch = batch_candidate_body(
                candidate,
                include_checks=True,
                include_messages=include_messages,
                controllers=body["controllers"],
                controllers_summary=summary if include_messages else coded_summary(summary),
            )
            batch = orjson.loads(dump_json(batch))  # the checks may be their JSON
            bodies.append(batch)
            if include_messages:  # the detail's words and the names of the open checks
                assert batch == body | {"reason_checks": candidate.open_checks}
            else:  # the detail less its words
                assert batch == {
                    k: v for k, v in body.items() if k not in ("reasons", "controllers_note")
                } | {
                    "checks": [
                        {k: v for k, v in c.items() if k != "message"} for c in body["checks"]
                    ],
                    "reason_checks": candidate.open_checks,
                }
        assert candidate.open_checks == [c["name"] for c in checks if c["status"] in OPEN]
    result = result_body(id=None, case_id="order 1/10", selection=selection, candidates=bodies)
    parsed = BatchResultOut.model_validate(result)
    assert parsed.model_dump(mode="json", exclude_unset=True) == orjson.loads(dump_json(result))
    assert result["load"] == ranking["load"]


def test_limits_presenter_writes_its_model(catalogue: CatalogueSnapshot) -> None:
    """The limits of the worked example on its own actuator (``sizing/inverse.py``)."""
    app = _request("worked_example").to_core()
    (actuator,) = catalogue.actuators_of(["FHA-25C-50-L"])
    answer = limits_answer(
        model=actuator.model,
        catalogue_version=catalogue.version,
        app=app,
        found=limits(actuator, app),
    )
    assert isinstance(answer, LimitsOut)
    assert LimitsOut.model_validate_json(answer.model_dump_json()) == answer
    assert {limit.quantity for limit in answer.limits} == {
        "pause_s",
        "accel_s",
        "load_inertia_kgm2",
    }
