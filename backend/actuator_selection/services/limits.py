"""The inverse solve as a use case: the limits of a load case for one catalogue actuator."""

from __future__ import annotations

from actuator_selection.core.errors import InvalidInputError
from actuator_selection.core.inverse import limits
from actuator_selection.schemas.limits import LimitsOut, LimitsRequest
from actuator_selection.services.catalogue import CatalogueSnapshot


def solve_limits(body: LimitsRequest, catalogue: CatalogueSnapshot) -> LimitsOut:
    """Shortest pause, shortest t_1 and largest J_L for ``body.model`` (``core/inverse.py``)."""
    actuator = next(iter(catalogue.actuators_of([body.model])), None)
    if actuator is None:
        raise InvalidInputError("model", f"unknown actuator model {body.model!r}")
    app = body.to_core()
    return LimitsOut.build(
        model=actuator.model,
        catalogue_version=catalogue.version,
        app=app,
        found=limits(actuator, app),
    )
