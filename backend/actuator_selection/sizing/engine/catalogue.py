"""The catalogue as the engine reads it: each actuator a column, each value by the name
of its :class:`~actuator_selection.sizing.checks.Operands` field.

:func:`catalogue_arrays` builds every column once per catalogue (the service keeps it
with its catalogue snapshot): the values the rules read as published from the field
registry (each field's ``operand``), the derived ones from :data:`DERIVED_OPERANDS`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from dataclasses import field as dataclasses_field
from typing import Final, NamedTuple

import numpy as np
import numpy.typing as npt

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.catalogue.fields import OPERAND_FIELDS
from actuator_selection.sizing.bearing import life_exponent
from actuator_selection.sizing.checks import Rule
from actuator_selection.sizing.checks.rules.gear import life_basis
from actuator_selection.sizing.electrical import no_load_torque_slope_nm_per_rpm
from actuator_selection.sizing.engine.arrays import (
    BoolArray,
    CodeArray,
    FloatArray,
    IndexArray,
    optional,
)


def _no_load_torque_slope(a: Actuator) -> float | None:
    return no_load_torque_slope_nm_per_rpm(
        torque_constant_nm_per_a=a.torque_constant_nm_per_a,
        constant_30c_a_per_rpm=a.no_load_current_constant_30c_a_per_rpm,
        constant_80c_a_per_rpm=a.no_load_current_constant_80c_a_per_rpm,
    )


def _milli(value: float | None) -> float | None:
    return None if value is None else value / 1000.0


DERIVED_OPERANDS: Final[dict[str, Callable[[Actuator], float | None]]] = {
    "zone_max_speed_rpm": lambda a: None if a.zone is None else a.zone.max_speed_rpm,
    "inductance_line_h": lambda a: _milli(a.inductance_line_mh),
    "dc_bus_voltage_v": lambda a: a.dc_bus_voltage_v,
    "bearing_life_exponent": lambda a: life_exponent(a.text("output_bearing_type")),
    "no_load_torque_slope_nm_per_rpm": _no_load_torque_slope,
    "gear_life_basis": lambda a: life_basis(a.text("gear_life_basis")),
}
"""The catalogue operands (fields of :class:`~actuator_selection.sizing.checks.Operands`)
that are worked out from an actuator rather than read as published: None where the
catalogue does not publish what they need (NaN in the arrays). The published ones come
from the registry (:data:`~actuator_selection.catalogue.fields.OPERAND_FIELDS`);
``has_zone`` and the zone's edge at n_av come from the zone itself."""

PUBLISHED_OPERANDS: Final = tuple(
    (name, f.name) for f in OPERAND_FIELDS if (name := f.operand_name) is not None
)
"""(operand, catalogue field) of each value the rules read as published."""

CATALOGUE_OPERANDS: Final = (*(name for name, _ in PUBLISHED_OPERANDS), *DERIVED_OPERANDS)
"""Every catalogue operand's name, the published ones first."""


@dataclass(frozen=True, slots=True, eq=False)
class Lacking:
    """Where the catalogue misses the requirements of a set of rules (:func:`~actuator_selection.
    sizing.engine.codes.lacking`): a fact about the actuators, the same for every case."""

    first_missing: CodeArray
    """Per rule × 1 × actuator, the index of the first requirement the catalogue does not
    meet; −1: none."""
    others_missing: BoolArray
    """Per rule × 1 × actuator, whether any requirement after the first is unmet."""
    everywhere: tuple[bool, ...]
    """Per rule, whether it lacks data for every actuator and cannot fail on its
    :attr:`~actuator_selection.sizing.checks.Rule.lower_bound`: its status is ``no_data``
    in every cell where it applies, its limit not computed (a one-model selection's
    checks are often so)."""
    somewhere: tuple[bool, ...]
    """Per rule, whether it lacks data for any actuator: else nothing is masked."""
    floors: tuple[int, ...]
    """The rules that may fail on their lower bound: where only their first requirement
    (J_A) is missing."""
    cell: tuple[list[int], list[bool]] = ([], [])
    """For one actuator: :attr:`first_missing` and :attr:`others_missing` rule by rule, as
    Python values (a block of one cell decides on floats); else empty."""


class CellFloats(NamedTuple):
    """A catalogue of one actuator as a block of one cell reads it, beyond its operands
    (:meth:`CatalogueArrays.operand_floats`): Python floats, read once
    (:meth:`CatalogueArrays.cell_floats`) rather than by ``.item()`` per request."""

    inertia: float
    """J_A [kgm²]; NaN where not published."""
    heating_slope: float
    """:attr:`CatalogueArrays.heating_slope`'s."""
    tau: float | None
    """τ_th where published, else None (the case's then)."""


@dataclass(frozen=True, slots=True, eq=False)
class CatalogueArrays:
    """The actuators as columns; NaN where the catalogue gives no value."""

    operands: dict[str, FloatArray | BoolArray]
    """The catalogue's operands by name (:data:`CATALOGUE_OPERANDS`, and ``has_zone``)."""
    thermal_time_constant: FloatArray
    """τ_th where the catalogue publishes it, else NaN (the case's then)."""
    heating_slope: FloatArray
    """k_T·K_INL where the heating follows the winding current (no zone, T_0 published:
    :meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm`), else NaN."""
    zone_columns: IndexArray
    """The columns of the actuators with a continuous-duty zone."""
    rank_position: npt.NDArray[np.int32]
    """Each actuator's place in the static order (T_max, J_A, model) that breaks ties."""
    model_rank: IndexArray
    """Each actuator's place in the order of the models' names (the ratio study's ties)."""
    columns: dict[str, FloatArray | BoolArray] = dataclasses_field(default_factory=dict)
    """Every column as read from the actuators (the operands and the fields they are
    ranked and heated by), what the next catalogue's arrays copy from."""
    lacking: dict[tuple[Rule, ...], Lacking] = dataclasses_field(default_factory=dict)
    """Per rule set, where the catalogue misses its requirements (``codes.lacking``),
    filled when the rules are first evaluated against these actuators."""
    floats: dict[str, float | bool] = dataclasses_field(default_factory=dict)
    """One actuator's :attr:`operands` as Python floats and bools
    (:meth:`operand_floats`), filled when first read."""
    cell: list[CellFloats] = dataclasses_field(default_factory=list)
    """:meth:`cell_floats`, once read (a catalogue of one actuator)."""
    published_taus: tuple[float, ...] = dataclasses_field(init=False)
    """The distinct τ_th that the actuators publish, ascending."""
    tau_column: IndexArray = dataclasses_field(init=False)
    """Per actuator, its τ_th's place: 0 the case's (none published), k the k-th of
    :attr:`published_taus`."""
    tau_unpublished: BoolArray = dataclasses_field(init=False)
    """Where no τ_th is published (the case's then)."""
    on_current: bool = dataclasses_field(init=False)
    """Whether any actuator's heating follows the winding current (:attr:`heating_slope`)."""
    inertia_unknown: bool = dataclasses_field(init=False)
    """Whether any actuator lacks J_A (its torques are NaN)."""

    def __post_init__(self) -> None:
        # Facts about the actuators the block reads for every request: worked out once
        # with the arrays (the snapshot keeps them), not per block (np.unique, isnan).
        published = self.thermal_time_constant
        unpublished = np.isnan(published)
        distinct, where = np.unique(published[~unpublished], return_inverse=True)
        column = np.zeros(published.shape, dtype=np.intp)
        column[~unpublished] = where.ravel() + 1
        values: list[float] = distinct.tolist()
        fixed = object.__setattr__
        fixed(self, "published_taus", tuple(values))
        fixed(self, "tau_column", column)
        fixed(self, "tau_unpublished", unpublished)
        fixed(self, "on_current", not bool(np.isnan(self.heating_slope).all()))
        fixed(self, "inertia_unknown", bool(np.isnan(self.inertia).any()))

    @property
    def inertia(self) -> FloatArray:
        """J_A per actuator [kgm²]; NaN where not published."""
        inertia = self.operands["inertia_kgm2"]
        assert inertia.dtype == np.float64
        return inertia.astype(np.float64, copy=False)

    def operand_floats(self) -> dict[str, float | bool]:
        """The :attr:`operands` of a catalogue of one actuator as Python floats and bools
        (the engine's block of one cell), read once."""
        if not self.floats:
            self.floats.update({name: v.item() for name, v in self.operands.items()})
        return self.floats

    def cell_floats(self) -> CellFloats:
        """A catalogue of one actuator's :class:`CellFloats`, read once."""
        if not self.cell:
            unpublished = bool(self.tau_unpublished.item())
            self.cell.append(
                CellFloats(
                    inertia=float(self.inertia.item()),
                    heating_slope=float(self.heating_slope.item()),
                    tau=None if unpublished else float(self.thermal_time_constant.item()),
                )
            )
        return self.cell[0]

    @property
    def size(self) -> int:
        """The number of actuators."""
        return self.inertia.size


def _columns(actuators: Sequence[Actuator]) -> dict[str, FloatArray | BoolArray]:
    """The columns read from the actuators one by one: the operands, ``has_zone``, and
    τ_th and the ranking's T_max and J_A under their field names."""
    columns: dict[str, FloatArray | BoolArray] = {
        name: optional([getattr(a, field) for a in actuators]) for name, field in PUBLISHED_OPERANDS
    }
    columns.update(
        (name, optional([value(a) for a in actuators])) for name, value in DERIVED_OPERANDS.items()
    )
    columns["has_zone"] = np.array([a.zone is not None for a in actuators], dtype=np.bool_)
    for name in ("thermal_time_constant_s", "max_torque_nm", "inertia_kgm2"):
        columns[f"field:{name}"] = optional([getattr(a, name) for a in actuators])
    return columns


Columns = dict[str, FloatArray | BoolArray]


def _spliced(actuators: Sequence[Actuator], held: tuple[Sequence[Actuator], Columns]) -> Columns:
    """:func:`_columns` of ``actuators``, taken from ``held`` (the columns of earlier
    actuators) for each actuator that is the same object there, read for the others."""
    before, columns = held
    at = {id(a): j for j, a in enumerate(before)}
    take = np.array([at.get(id(a), -1) for a in actuators], dtype=np.intp)
    fresh = np.flatnonzero(take < 0)
    kept = np.flatnonzero(take >= 0)
    read = _columns([actuators[int(i)] for i in fresh])
    out: dict[str, FloatArray | BoolArray] = {}
    for name, column in columns.items():
        joined = np.empty_like(column, shape=len(actuators))
        joined[kept] = column[take[kept]]
        joined[fresh] = read[name]
        out[name] = joined
    return out


def catalogue_arrays(
    actuators: Sequence[Actuator],
    previous: tuple[Sequence[Actuator], CatalogueArrays] | None = None,
) -> CatalogueArrays:
    """The actuators as the engine reads them (:data:`CATALOGUE_OPERANDS`, by name); build
    once per catalogue and pass to the engine to spare it per request.

    ``previous``: the arrays of earlier actuators (the catalogue before a change); an
    actuator that is the same object there is not read again, its values are copied.
    """
    if previous is None:
        columns = _columns(actuators)
    else:
        columns = _spliced(actuators, (previous[0], previous[1].columns))
    has_zone = columns["has_zone"].astype(np.bool_, copy=False)
    # ranking_key after the verdict: T_max, then J_A (unknown last), then the model name;
    # lexsort is stable, so equal keys keep their column order.
    models = np.array([a.model for a in actuators], dtype=np.str_)
    torque = np.nan_to_num(columns["field:max_torque_nm"], nan=math.inf)
    inertia = np.nan_to_num(columns["field:inertia_kgm2"], nan=math.inf)
    order = np.lexsort((models, inertia, torque))
    rank_position = np.empty(len(actuators), dtype=np.int32)
    rank_position[order] = np.arange(len(actuators), dtype=np.int32)
    _names, model_rank = np.unique(models, return_inverse=True)
    operands = {k: v for k, v in columns.items() if not k.startswith("field:")}
    slope = operands["no_load_torque_slope_nm_per_rpm"]
    on_current = ~has_zone & ~np.isnan(operands["stall_torque_nm"])
    return CatalogueArrays(
        operands=operands,
        thermal_time_constant=columns["field:thermal_time_constant_s"].astype(np.float64),
        heating_slope=np.where(on_current, slope, math.nan),
        zone_columns=np.flatnonzero(has_zone),
        rank_position=rank_position,
        model_rank=model_rank.reshape(-1),
        columns=columns,
    )
