"""The catalogue snapshot read after a change reuses what did not change and equals a
full read: a changed actuator, zone, interface or controller is never served stale."""

from __future__ import annotations

from collections.abc import Callable
from datetime import UTC, datetime

import numpy as np
from sqlalchemy.orm import Session

from actuator_selection.catalogue.csvio import Record
from actuator_selection.catalogue.files import ACTUATORS, CATALOGUE_SPECS, INTERFACES
from actuator_selection.db.admin import CatalogueAdminRepository, ZonePointIn
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.db.seed import CatalogueFiles
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.sizing.engine import catalogue_arrays

CHANGED = "FHA-25C-50-L"


def _read(session: Session, held: CatalogueSnapshot | None = None) -> CatalogueSnapshot:
    return CatalogueSnapshot.read(session, CatalogueVersionRepository(session).current(), held)


def _imported(session: Session, change: Callable[[str, dict[str, object]], None]) -> bool:
    """Import the catalogue as exported, each row passed through ``change(file, values)``."""
    exported = CatalogueAdminRepository(session).export()
    for file, rows in exported.items():
        for values in rows:
            change(file, values)
    files = CatalogueFiles(
        {s.file: [Record(line=0, values=v) for v in exported[s.file]] for s in CATALOGUE_SPECS}
    )
    return CatalogueAdminRepository(session).import_catalogue(files, dry_run=False).changed


def _torque_by_import(file: str, values: dict[str, object]) -> None:
    if file == ACTUATORS.file and values["model"] == CHANGED:
        values["max_torque_nm"] = 152.0


def _interface_by_import(file: str, values: dict[str, object]) -> None:
    if file == INTERFACES.file and values["actuator_model"] == CHANGED:
        values["temperature_sensors"] = None


def test_an_incremental_read_equals_a_full_read_after_each_change(session: Session) -> None:
    held = _read(session)
    held.arrays(held.actuators)  # the whole catalogue's arrays, which the next read splices
    repository = CatalogueAdminRepository(session)
    record = CatalogueRepository(session).actuator(CHANGED)
    assert record is not None
    values = dict(record.values)
    changes: list[Callable[[], bool]] = [
        lambda: _imported(session, _torque_by_import),
        lambda: _imported(session, _interface_by_import),
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
        read, retired = CatalogueRepository(session).engine_actuators(since=held.version)
        assert read.keys() | retired <= {CHANGED}  # only what changed is read again
        fresh = _read(session, held)
        full = _read(session)
        assert fresh.actuators == full.actuators
        spliced, built = fresh.arrays(fresh.actuators), catalogue_arrays(full.actuators)
        assert spliced.operands.keys() == built.operands.keys()
        for name, column in built.operands.items():
            assert np.array_equal(spliced.operands[name], column, equal_nan=True), name
        assert np.array_equal(spliced.rank_position, built.rank_position)
        assert np.array_equal(spliced.heating_slope, built.heating_slope, equal_nan=True)
        assert fresh.controllers == full.controllers
        assert dict(fresh.interfaces) == dict(full.interfaces)
        unchanged = [a for a in held.actuators if a.model != CHANGED]
        reused = {id(a) for a in fresh.actuators}
        if fresh.controllers == held.controllers:  # only the changed actuator is built again
            assert all(id(a) in reused for a in unchanged)
        held = fresh
    assert CHANGED not in {a.model for a in held.actuators}
