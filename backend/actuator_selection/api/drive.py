"""Drive options (Table 521.1 matching + Eq. 521.2) for the candidates of a request.

The controller catalogue, bus classes and actuator interfaces are read once per
request. Matching depends only on the actuator's interface, and a whole catalogue
has a handful of distinct interfaces, so it is computed once per interface.
"""

from __future__ import annotations

from collections.abc import Iterable

from sqlalchemy.orm import Session

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.compatibility import (
    ActuatorInterface,
    CompatibilityResult,
    match_controllers,
)
from actuator_selection.core.drive import DriveOptions, drive_options
from actuator_selection.db.controllers import ProtectionRepository


class DriveContext:
    """The controller data of one request."""

    def __init__(self, session: Session, models: Iterable[str] | None = None) -> None:
        repo = ProtectionRepository(session)
        self._controllers = [r.controller for r in repo.controllers()]
        self._buses = repo.bus_classes()
        self._interfaces = repo.interfaces(None if models is None else list(models))
        self._matching: dict[ActuatorInterface, CompatibilityResult] = {}

    def _matching_for(self, interface: ActuatorInterface) -> CompatibilityResult:
        """Every controller matched against ``interface`` (Table 521.1), computed once."""
        found = self._matching.get(interface)
        if found is None:
            found = self._matching[interface] = match_controllers(
                actuator=interface, controllers=self._controllers
            )
        return found

    def options(self, actuator: Actuator, *, speed_rpm: float) -> DriveOptions:
        """Controllers not excluded for ``actuator``, with the voltage check at ``speed_rpm``."""
        interface = self._interfaces[actuator.model].interface
        return drive_options(
            actuator=actuator,
            interface=interface,
            matching=self._matching_for(interface),
            buses=self._buses,
            speed_rpm=speed_rpm,
        )
