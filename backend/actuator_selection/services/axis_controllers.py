"""The servo controller of a project's axis (issue 31): which controllers of Table 521.1 an
axis may take on the project's DC bus, the one chosen checked against them, and what the
bus summary reads of the chosen ones.

An axis may take a controller that Table 521.1 does not exclude for its actuator (the
matching a selection lists as the candidate's drive options) and that has a mark for the
project's DC bus class, where the actuator itself runs on that class. The chosen one's
output voltage is Eq. 521.2 at the axis's peak speed against that bus class alone (a
selection compares with the best bus class the two share).
"""

from __future__ import annotations

from typing import Any

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.errors import invalid
from actuator_selection.services.messages import PROJECT_CONTROLLER_RULE
from actuator_selection.sizing.compatibility import ControllerMatch, MatchVerdict, match_controller
from actuator_selection.sizing.drive import shared_voltage_check
from actuator_selection.sizing.electrical import DcBusClass

JSON = dict[str, Any]

SHOWN_ROWS = 12
"""The Table 521.1 rows an answer names when the chosen controller is not one of them."""

_WORST_VOLTAGE = ("fail", "warn", "no_data", "pass")
"""Output-voltage statuses, worst first, for the bus summary."""


def choices(catalogue: CatalogueSnapshot, actuator: Actuator, bus: DcBusClass) -> list[JSON]:
    """The controllers ``actuator`` may take on ``bus`` (``ControllerChoice``), best first."""
    interface = catalogue.interfaces.get(actuator.model)
    if interface is None or (
        interface.bus_classes is not None and bus.bus_class not in interface.bus_classes
    ):
        return []
    return [
        _choice(m, mark.value)
        for m in catalogue.matching(interface).matches
        if m.verdict is not MatchVerdict.EXCLUDED
        and m.controller.source_row is not None
        and (mark := m.controller.level(bus.bus_class)) is not None
    ]


def _choice(match: ControllerMatch, mark: str) -> JSON:
    return {
        "source_row": match.controller.source_row,
        "name": match.controller.name,
        "level": match.verdict.value,
        "bus_mark": mark,
    }


def chosen(
    *,
    row: int | None,
    loc: list[str | int],
    catalogue: CatalogueSnapshot,
    actuator: Actuator,
    bus: DcBusClass,
    listed: list[JSON],
    speed_rpm: float,
) -> JSON | None:
    """The axis's controller in Table 521.1 ``row`` (``AxisControllerOut``) with its output
    voltage on ``bus`` at ``speed_rpm``; None without one; 422 at ``loc`` where it is not
    one of ``listed`` (:func:`choices`), naming the rule and the rows that are."""
    if row is None:
        return None
    found = next((c for c in listed if c["source_row"] == row), None)
    interface = catalogue.interfaces.get(actuator.model)
    if found is None:
        controller = next((c for c in catalogue.controllers if c.source_row == row), None)
        if controller is None:
            raise invalid(loc, "unknown_controller", row=row)
        reasons = (
            [
                r.message
                for r in match_controller(controller=controller, actuator=interface).excluded_by
            ]
            if interface is not None
            else []
        )
        raise invalid(
            loc,
            "controller_not_compatible" if reasons else "controller_not_listed",
            "controller_not_compatible",
            controller=controller.name,
            row=row,
            model=actuator.model,
            rule=PROJECT_CONTROLLER_RULE,
            rows=sorted(c["source_row"] for c in listed)[:SHOWN_ROWS],
            **({"reasons": "; ".join(reasons)} if reasons else {}),
        )
    assert interface is not None  # listed only where the actuator has an interface
    v = shared_voltage_check(
        actuator=actuator, interface=interface, shared=(bus,), speed_rpm=speed_rpm, words=False
    )
    voltage = {"status": v.status.value, "value": v.value, "limit": v.limit}
    return {**found, "voltage": {**voltage, "reference": v.reference}}


def bus_summary(controllers: list[JSON | None]) -> JSON:
    """What the bus summary reads of the axes' chosen controllers: the weakest bus mark
    and the worst output-voltage status (None where no axis has a controller)."""
    taken = [c for c in controllers if c is not None]
    if not taken:
        return {"controllers_bus_mark": None, "voltage_status": None}
    marks = {c["bus_mark"] for c in taken}
    statuses = {c["voltage"]["status"] for c in taken}
    return {
        "controllers_bus_mark": "possible" if "possible" in marks else "tested",
        "voltage_status": next(s for s in _WORST_VOLTAGE if s in statuses),
    }
