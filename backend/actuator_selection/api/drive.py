"""Drive options (Table 521.1 matching + Eq. 521.2) for the candidates of a request.

The controller catalogue, bus classes and actuator interfaces are read once per
request; matching depends only on the actuator, so it is computed once per model.
"""

from __future__ import annotations

from collections.abc import Iterable

from sqlalchemy.orm import Session

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.drive import DriveOptions, drive_options
from actuator_selection.db.controllers import ProtectionRepository


class DriveContext:
    """The controller data of one request."""

    def __init__(self, session: Session, models: Iterable[str] | None = None) -> None:
        repo = ProtectionRepository(session)
        self._controllers = [r.controller for r in repo.controllers()]
        self._buses = repo.bus_classes()
        self._interfaces = repo.interfaces(None if models is None else list(models))

    def options(self, actuator: Actuator, *, speed_rpm: float) -> DriveOptions:
        """Controllers not excluded for ``actuator``, with the voltage check at ``speed_rpm``."""
        return drive_options(
            actuator=actuator,
            interface=self._interfaces[actuator.model].interface,
            controllers=self._controllers,
            buses=self._buses,
            speed_rpm=speed_rpm,
        )
