"""The catalogue a selection reads, held in memory by version, and its drive options.

Drive options are Table 521.1 matching + Eq. 521.2 for the candidates of a request.
Matching depends only on the actuator's interface and the controllers, and a whole
catalogue has a handful of distinct interfaces, so it is computed once per interface
and catalogue version, and kept with the snapshot.
"""

from __future__ import annotations

import threading
from collections.abc import Callable, Iterable, Mapping, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass, field, replace
from types import MappingProxyType
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt
from sqlalchemy.orm import Session

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.controllers import ActuatorInterface, Controller
from actuator_selection.db.controllers import ProtectionRepository
from actuator_selection.db.repositories import CatalogueRepository, CatalogueVersionRepository
from actuator_selection.sizing.compatibility import (
    CompatibilityResult,
    MatchVerdict,
    match_controllers,
)
from actuator_selection.sizing.drive import DriveOptions, drive_options, shared_bus_classes
from actuator_selection.sizing.electrical import DcBusClass
from actuator_selection.sizing.engine import CatalogueArrays, catalogue_arrays


@dataclass(frozen=True, slots=True)
class MatchGroup:
    """Controllers that match an interface alike (Table 521.1) and share the same DC bus
    classes with it, so that they share one voltage check for any actuator of it."""

    level: str
    missing: tuple[str, ...]
    shared: tuple[DcBusClass, ...]
    controllers: tuple[tuple[int, int], ...]
    """Each controller's place in the matching's best-first order, and its index into
    :attr:`CatalogueSnapshot.controllers`, best first."""


class DriveGroups(NamedTuple):
    """An actuator's drive option groups (:meth:`CatalogueSnapshot.drive_groups`)."""

    interface: ActuatorInterface
    groups: tuple[MatchGroup, ...]
    shared: list[tuple[DcBusClass, ...]]
    """The groups' distinct shared bus classes, in the groups' order."""
    where: list[int]
    """Each group's place in :attr:`shared`."""


@dataclass(frozen=True, slots=True)
class ActuatorColumns:
    """A list of actuators as columns, each indexed by a ranking's order at once: what an
    answer and a stored ranking name of each actuator (the record, its model, family and
    gear ratio, and how many controllers Table 521.1 excludes for it). Reading 64,000
    attributes one by one cost more than the engine's whole evaluation."""

    actuator: npt.NDArray[np.object_]
    model: npt.NDArray[np.object_]
    family: npt.NDArray[np.object_]
    gear_ratio: npt.NDArray[np.object_]
    excluded: npt.NDArray[np.int64]


def _objects(values: Sequence[Any]) -> npt.NDArray[np.object_]:
    """``values`` as a one-dimensional object array (numpy would unpack tuples)."""
    out = np.empty(len(values), dtype=object)
    out[:] = values
    return out


@dataclass(frozen=True, slots=True, kw_only=True)
class CatalogueSnapshot:
    """Everything a selection reads from the catalogue, at one catalogue version."""

    version: int
    actuators: tuple[Actuator, ...]
    """Active actuators, ordered by model."""
    controllers: tuple[Controller, ...]
    buses: tuple[DcBusClass, ...]
    interfaces: Mapping[str, ActuatorInterface]
    _matching: dict[ActuatorInterface, CompatibilityResult] = field(
        default_factory=dict, repr=False, compare=False
    )
    """Table 521.1 matched per distinct interface, filled as requests ask for it."""
    _excluded: dict[ActuatorInterface, int] = field(default_factory=dict, repr=False, compare=False)
    """How many controllers each interface's matching excludes."""
    _groups: dict[ActuatorInterface, tuple[MatchGroup, ...]] = field(
        default_factory=dict, repr=False, compare=False
    )
    """The controllers not excluded per interface, grouped (:meth:`match_groups`)."""
    _arrays: dict[tuple[str, ...], CatalogueArrays] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )
    """The engine's catalogue arrays, per list of models asked for."""
    _columns: dict[tuple[str, ...], ActuatorColumns] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )
    """:meth:`columns`, per list of models asked for."""
    _excluded_by_model: dict[str, int] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )
    _drive_groups: dict[str, DriveGroups] = field(
        default_factory=dict, init=False, repr=False, compare=False
    )
    """:meth:`drive_groups`, by model."""
    _by_model: Mapping[str, Actuator] = field(default_factory=dict, repr=False, compare=False)
    """:attr:`actuators` by model, in the same order: what the next version's read reuses
    for every actuator not changed since."""

    def excluded_by_model(self) -> Mapping[str, int]:
        """:meth:`excluded` of every actuator's interface, by model, built once."""
        found = self._excluded_by_model
        if not found:
            interfaces = self.interfaces
            # A handful of distinct interfaces, each (per read) one object.
            distinct = {id(i): i for i in interfaces.values()}
            by_interface = {key: self.excluded(i) for key, i in distinct.items()}
            found.update((m, by_interface[id(interfaces[m])]) for m in self._by_model)
        return found

    def _key(self, actuators: Sequence[Actuator]) -> tuple[str, ...]:
        """The models of ``actuators``: the key of what is built once per list of them
        (the whole catalogue's read from the index, not from 64,000 records)."""
        if actuators is self.actuators:
            return tuple(self._by_model)
        return tuple([a.model for a in actuators])

    def arrays(self, actuators: tuple[Actuator, ...]) -> CatalogueArrays:
        """:func:`~actuator_selection.sizing.engine.catalogue_arrays` of ``actuators`` (the
        whole catalogue or a ``models`` subset of it), built once per version."""
        key = self._key(actuators)
        found = self._arrays.get(key)
        if found is None:
            if len(self._arrays) > 256:  # subsets named by requests: keep it bounded
                self._arrays.clear()
            found = self._arrays.setdefault(key, catalogue_arrays(actuators))
        return found

    def columns(self, actuators: tuple[Actuator, ...]) -> ActuatorColumns:
        """:class:`ActuatorColumns` of ``actuators`` (the whole catalogue or a ``models``
        subset of it), built once per version."""
        key = self._key(actuators)
        found = self._columns.get(key)
        if found is None:
            if len(self._columns) > 256:  # subsets named by requests: keep it bounded
                self._columns.clear()
            excluded = self.excluded_by_model()
            found = self._columns.setdefault(
                key,
                ActuatorColumns(
                    actuator=_objects(actuators),
                    model=_objects(key),
                    family=_objects([a.family for a in actuators]),
                    gear_ratio=_objects([a.gear_ratio for a in actuators]),
                    excluded=np.array([excluded[m] for m in key], dtype=np.int64),
                ),
            )
        return found

    def match_groups(self, interface: ActuatorInterface) -> tuple[MatchGroup, ...]:
        """The controllers not excluded for ``interface``, best first, grouped by level,
        missing criteria and shared DC bus classes; computed once per version."""
        found = self._groups.get(interface)
        if found is None:
            index = {c: i for i, c in enumerate(self.controllers)}
            groups: dict[
                tuple[str, tuple[str, ...], tuple[DcBusClass, ...]], list[tuple[int, int]]
            ] = {}
            for place, m in enumerate(self.matching(interface).matches):
                if m.verdict is MatchVerdict.EXCLUDED:
                    continue
                shared = shared_bus_classes(
                    interface=interface, controller=m.controller, buses=self.buses
                )
                missing = tuple(r.criterion.value for r in m.no_data)
                groups.setdefault((m.verdict.value, missing, shared), []).append(
                    (place, index[m.controller])
                )
            found = self._groups.setdefault(
                interface,
                tuple(
                    MatchGroup(level, missing, shared, tuple(ids))
                    for (level, missing, shared), ids in groups.items()
                ),
            )
        return found

    def drive_groups(self, model: str) -> DriveGroups:
        """``model``'s interface and :meth:`match_groups`, with their distinct shared bus
        classes (in order) and each group's place among them; built once per version:
        hashing the interface and the bus classes (enums, in Python) per candidate cost a
        whole-catalogue selection's drive options a fifth of their instructions."""
        found = self._drive_groups.get(model)
        if found is None:
            interface = self.interfaces[model]
            groups = self.match_groups(interface)
            shared = list(dict.fromkeys(g.shared for g in groups))
            where = [shared.index(g.shared) for g in groups]
            found = self._drive_groups.setdefault(
                model, DriveGroups(interface, groups, shared, where)
            )
        return found

    def excluded(self, interface: ActuatorInterface) -> int:
        """How many controllers Table 521.1 excludes for ``interface``."""
        found = self._excluded.get(interface)
        if found is None:
            matches = self.matching(interface).matches
            found = self._excluded.setdefault(
                interface, sum(m.verdict is MatchVerdict.EXCLUDED for m in matches)
            )
        return found

    def matching(self, interface: ActuatorInterface) -> CompatibilityResult:
        """Every controller matched against ``interface`` (Table 521.1), computed once per
        catalogue version: it depends on the catalogue alone. Threads that race on a new
        interface compute the same result; the dict keeps one."""
        found = self._matching.get(interface)
        if found is None:
            found = self._matching.setdefault(
                interface, match_controllers(actuator=interface, controllers=self.controllers)
            )
        return found

    @classmethod
    def read(
        cls, session: Session, version: int, held: CatalogueSnapshot | None = None
    ) -> CatalogueSnapshot:
        """Read the catalogue in ``session``'s transaction (pinned at ``version``).

        With ``held`` (the snapshot of an earlier version) the read is incremental: only
        the actuators changed since ``held``'s version are read and built
        (``ActuatorRow.changed_version``); every other one is ``held``'s object again (so
        is the matching, when the controllers and bus classes are the same), and so are
        its columns in the engine's arrays of the whole catalogue.
        """
        repo = ProtectionRepository(session)
        buses = tuple(repo.bus_classes())
        controllers = tuple(r.controller for r in repo.controllers())
        since = held.version if held is not None and held.version < version else None
        base = held if since is not None else None
        changed_interfaces = {
            model: r.interface for model, r in repo.interfaces(None, since=since).items()
        }
        interfaces = dict(base.interfaces) if base is not None else {}
        interfaces.update(changed_interfaces)
        same = held is not None and held.controllers == controllers and held.buses == buses
        # A catalogue has a handful of distinct interfaces: each matched once, and kept
        # while the controllers and bus classes are the same.
        matching = dict(held._matching) if same and held is not None else {}
        for interface in set((changed_interfaces if same else interfaces).values()):
            if interface not in matching:
                matching[interface] = match_controllers(actuator=interface, controllers=controllers)
        changed, retired = CatalogueRepository(session).engine_actuators(since)
        # The held actuators (in model order), less those changed or retired since; with
        # other controllers or bus classes each is built again from its stored values.
        by_model = dict(base._by_model) if base is not None else {}
        for model in retired:
            by_model.pop(model, None)
        if not same:
            by_model = {m: replace(a, dc_bus_voltage_v=None) for m, a in by_model.items()}
            changed = {**by_model, **changed}
        for model, actuator in changed.items():
            its = interfaces.get(model)
            by_model[model] = with_bus_voltage(
                actuator, its, buses, None if its is None else matching[its]
            )
        if changed.keys() - (base._by_model.keys() if base is not None else set()):
            # new models: ordered again (the held ones are in order, a run for the sort)
            by_model = {m: by_model[m] for m in sorted(by_model)}
        fresh = cls(
            version=version,
            actuators=tuple(by_model.values()),
            controllers=controllers,
            buses=buses,
            interfaces=MappingProxyType(interfaces),
            _matching=matching,
            _by_model=by_model,
        )
        if held is not None and since is not None:
            whole = held._arrays.get(tuple(held._by_model))
            if whole is not None:  # the whole catalogue's, built from those held
                fresh._arrays[tuple(by_model)] = catalogue_arrays(
                    fresh.actuators, (held.actuators, whole)
                )
        return fresh

    def has_all(self, models: Iterable[str] | None) -> bool:
        """True when every one of ``models`` is an active actuator here (None: the
        whole catalogue, always true)."""
        return models is None or all(m in self._by_model for m in models)

    def actuators_of(self, models: Iterable[str] | None) -> list[Actuator]:
        """The active actuators, or those of ``models`` that exist, ordered by model."""
        if models is None:
            return list(self.actuators)
        held = self._by_model
        return [held[m] for m in sorted(set(models)) if m in held]


def with_bus_voltage(
    actuator: Actuator,
    interface: ActuatorInterface | None,
    buses: Sequence[DcBusClass],
    matching: CompatibilityResult | None,
) -> Actuator:
    """``actuator`` with :attr:`~Actuator.dc_bus_voltage_v`: the highest nominal voltage of
    the DC bus classes (Table 521.1) that it shares with a controller listed for it, one
    ``matching`` does not exclude; None where there is none.

    So the selection's ``drive_voltage`` check compares the voltage the axis needs with
    the best output voltage any listed controller delivers: it fails exactly when every
    listed controller's own voltage check (:mod:`actuator_selection.sizing.drive`, the same
    formula, the best bus each shares) fails, and lacks data where no controller is
    listed on a bus class the actuator runs on.
    """
    if interface is None or interface.bus_classes is None or matching is None:
        return actuator
    voltages = [
        b.nominal_voltage_v
        for m in matching.matches
        if m.verdict is not MatchVerdict.EXCLUDED
        for b in shared_bus_classes(interface=interface, controller=m.controller, buses=buses)
    ]
    if not voltages:
        return actuator
    return replace(actuator, dc_bus_voltage_v=max(voltages))


class CatalogueCache:
    """The catalogue in memory, keyed by its version and checked on every request.

    A request reads the version (one indexed row, no lock); when it is the one held,
    the catalogue is not read again (the tables cost 7–8 ms a request), and the
    snapshot held is that version's data, read whole. Every catalogue change raises
    the version, so each process of a deployment sees a change at its next request,
    whichever process or replica made it.

    A selection that is stored reads no version first: it is sized against the snapshot
    held and stored by a statement that checks the version itself (:meth:`latest`,
    :meth:`pinned`, ``services.selections.create_selection``).

    Only when the version differs is the catalogue read, after pinning the version
    (``CatalogueVersionRepository.pin``: on PostgreSQL a share lock, so that the rows
    read are the version's own). The pin is kept off the common path: a row lock
    writes to the row, so the read transaction would have to wait for a WAL flush at
    its commit (measured 4.3 ms against 0.5 ms for the plain read).
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._held: CatalogueSnapshot | None = None

    def latest(self, reader: Callable[[], AbstractContextManager[Session]]) -> CatalogueSnapshot:
        """The snapshot held, without a query; read in a transaction of ``reader`` when
        none is held yet. For writers that check the version where they store
        (:func:`~actuator_selection.services.selections.create_selection`)."""
        held = self._held
        return held if held is not None else self.refresh(reader)

    def refresh(self, reader: Callable[[], AbstractContextManager[Session]]) -> CatalogueSnapshot:
        """:meth:`snapshot` in a transaction of its own (``reader``)."""
        with reader() as session:
            return self.snapshot(session)

    def pinned(self, session: Session) -> CatalogueSnapshot:
        """The catalogue at the version ``session``'s transaction pins: no change can
        raise it before that transaction ends (``CatalogueVersionRepository.pin``; on
        SQLite a writer's transaction excludes every other writer anyway)."""
        version = CatalogueVersionRepository(session).pin()
        held = self._held
        if held is not None and held.version == version:
            return held
        return self._keep(CatalogueSnapshot.read(session, version, held))

    def _keep(self, fresh: CatalogueSnapshot) -> CatalogueSnapshot:
        with self._lock:
            if self._held is None or self._held.version < fresh.version:
                self._held = fresh
        return fresh

    def snapshot(self, session: Session) -> CatalogueSnapshot:
        """The catalogue at the version ``session``'s transaction reads."""
        versions = CatalogueVersionRepository(session)
        held = self._held
        if held is not None and held.version == versions.current():
            return held
        version = versions.pin()
        if held is not None and held.version == version:
            return held
        return self._keep(CatalogueSnapshot.read(session, version, held))


class DriveContext:
    """The drive options of one request's candidates."""

    def __init__(self, snapshot: CatalogueSnapshot) -> None:
        self._snapshot = snapshot

    def options(self, actuator: Actuator, *, speed_rpm: float) -> DriveOptions:
        """Controllers not excluded for ``actuator``, with the voltage check at ``speed_rpm``."""
        snapshot = self._snapshot
        interface = snapshot.interfaces[actuator.model]
        return drive_options(
            actuator=actuator,
            interface=interface,
            matching=snapshot.matching(interface),
            buses=snapshot.buses,
            speed_rpm=speed_rpm,
        )

    def excluded(self, actuator: Actuator) -> int:
        """How many controllers Table 521.1 excludes for ``actuator``."""
        return self._snapshot.excluded(self._snapshot.interfaces[actuator.model])
