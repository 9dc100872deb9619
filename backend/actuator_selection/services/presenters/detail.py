"""A candidate's detail (``CandidateDetailOut``): one candidate of a stored selection in
full, its checks in words, every controller of Table 521.1 not excluded with its criteria
and voltage check, the actuator's catalogue entry and the torque along each segment.

The candidate's part is the batch candidate's (:func:`.batch.candidate_body`), with
everything included; the detail adds what the stored selection gives.
"""

from __future__ import annotations

from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.checks import Localize, english
from actuator_selection.schemas.controllers import DriveOptionBodies, controllers_note
from actuator_selection.schemas.selections import CandidateDetailOut
from actuator_selection.services.presenters.batch import candidate_body, controllers_summary
from actuator_selection.sizing.drive import DriveOptions
from actuator_selection.sizing.motion import Profile
from actuator_selection.sizing.selection import Candidate


def candidate_detail(
    *,
    selection_id: str,
    catalogue_version: int,
    candidate: Candidate,
    profile: Profile,
    drive: DriveOptions,
    actuator: ActuatorOut,
    localize: Localize = english,
) -> CandidateDetailOut:
    """The detail of one candidate with its drive options, its messages in words by
    ``localize``."""
    j_a = candidate.actuator.inertia_kgm2
    body = candidate_body(
        candidate,
        include_checks=True,
        controllers=[
            o.model_dump(mode="json") for o in DriveOptionBodies(localize).controllers(drive)
        ],
        controllers_summary=controllers_summary(drive.excluded, controllers_note(drive), localize),
        localize=localize,
    )
    return CandidateDetailOut.model_validate(
        {
            "selection_id": selection_id,
            "catalogue_version": catalogue_version,
            **body,
            "actuator": actuator,
            "segment_torques": [
                {
                    "segment": st.segment,
                    "times_s": list(st.times_s),
                    "torques_nm": list(st.torques_nm),
                }
                for st in ([] if j_a is None else profile.segment_torques(j_a))
            ],
        }
    )
