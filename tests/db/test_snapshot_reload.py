"""The catalogue snapshot read after a change reuses what did not change and equals a
full read: a changed actuator, zone, interface or controller is never served stale."""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime

from sqlalchemy.orm import Session

from actuator_selection.db.admin import CatalogueAdminRepository, ZonePointIn
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.services.catalogue import CatalogueSnapshot

CHANGED = "FHA-25C-50-L"


def _read(session: Session, held: CatalogueSnapshot | None = None) -> CatalogueSnapshot:
    return CatalogueSnapshot.read(session, CatalogueVersionRepository(session).current(), held)


def test_an_incremental_read_equals_a_full_read_after_each_change(session: Session) -> None:
    held = _read(session)
    repository = CatalogueAdminRepository(session)
    record = CatalogueRepository(session).actuator(CHANGED)
    assert record is not None
    values = dict(record.values)
    changes: list[Callable[[], bool]] = [
        lambda: repository.save_actuator({**values, "max_torque_nm": 150.0}),
        lambda: repository.set_zone(
            CHANGED,
            [ZonePointIn(speed_rpm=0.0, torque_nm=60.0), ZonePointIn(speed_rpm=90, torque_nm=40)],
            source="test",
        ),
        lambda: repository.set_interface(CHANGED, None),
        lambda: repository.retire_controller(1, now=datetime.now(UTC)),
        lambda: repository.retire(CHANGED, now=datetime.now(UTC)),
    ]
    for change in changes:
        assert change()
        fresh = _read(session, held)
        full = _read(session)
        assert fresh.actuators == full.actuators
        assert fresh.controllers == full.controllers
        assert dict(fresh.interfaces) == dict(full.interfaces)
        unchanged = [a for a in held.actuators if a.model != CHANGED]
        reused = {id(a) for a in fresh.actuators}
        if fresh.controllers == held.controllers:  # only the changed actuator is built again
            assert all(id(a) in reused for a in unchanged)
        held = fresh
    assert CHANGED not in {a.model for a in held.actuators}
