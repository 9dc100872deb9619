"""The inverse solve as a use case: the limits of a load case for one catalogue actuator."""

from __future__ import annotations

from sqlalchemy.orm import Session

from actuator_selection.errors import InvalidInputError
from actuator_selection.schemas.checks import Localize, english
from actuator_selection.schemas.limits import LimitsOut, LimitsRequest
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.presenters.limits import limits_answer
from actuator_selection.services.selections import stored_candidate
from actuator_selection.sizing.inverse import limits


def solve_limits(
    body: LimitsRequest, catalogue: CatalogueSnapshot, localize: Localize = english
) -> LimitsOut:
    """Shortest pause, shortest t_1 and largest J_L for ``body.model`` (``sizing/inverse.py``)."""
    actuator = next(iter(catalogue.actuators_of([body.model])), None)
    if actuator is None:
        raise InvalidInputError("model", f"unknown actuator model {body.model!r}")
    app = body.to_core()
    return limits_answer(
        model=actuator.model,
        catalogue_version=catalogue.version,
        app=app,
        found=limits(actuator, app),
        localize=localize,
    )


def stored_limits(
    session: Session,
    catalogue: CatalogueSnapshot,
    selection_id: str,
    model: str,
    localize: Localize = english,
) -> LimitsOut:
    """The limits of a stored selection's load case for one of its candidates."""
    body, actuator = stored_candidate(session, catalogue, selection_id, model, what="the limits")
    app = body.to_core()
    return limits_answer(
        model=actuator.model,
        catalogue_version=catalogue.version,
        app=app,
        found=limits(actuator, app),
        localize=localize,
    )
