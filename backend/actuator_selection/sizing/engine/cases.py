"""The load cases as the engine reads them: rows of their cycles' pieces and figures,
output loads and τ_th, and each case's operands by name (:func:`case_operands`)."""

from __future__ import annotations

import math
from bisect import bisect_right
from collections.abc import Callable, Sequence
from dataclasses import dataclass, fields
from operator import attrgetter
from typing import Any

import numpy as np

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.sizing.application import DEFAULT_BRAKE_SAFETY_FACTOR, Application
from actuator_selection.sizing.bearing import swing_deg
from actuator_selection.sizing.engine.arrays import BoolArray, FloatArray, IndexArray
from actuator_selection.sizing.motion import (
    CycleFigures,
    PieceArrays,
    cycle_figures,
    figures_of,
    piece_arrays,
    trapezoid_piece_arrays,
)
from actuator_selection.sizing.thermal import DEFAULT_THERMAL_TIME_CONSTANT_S

OUTPUT_LOAD_FIELDS = (
    "radial_force_n",
    "axial_force_n",
    "radial_lever_m",
    "axial_lever_m",
    "load_factor",
    "static_safety_min",
    "required_life_h",
)
"""The output load's fields, as :class:`Operands` and ``OutputLoad`` name them."""

REQUEST_FIELDS = (
    "gear_required_life_h",
    "momentary_torque_nm",
    "momentary_count",
    "min_natural_frequency_hz",
    "brake_safety_factor",
    "emergency_stops",
    "drop_torque_nm",
    "travel_mm_per_rad",
)
"""The request's further inputs (gear, stiffness, brake) and what the brake's drop reads
of the axis, as :class:`Operands` and ``Application`` name them; NaN where not given."""


def default_requests(size: int) -> FloatArray:
    """:data:`REQUEST_FIELDS` of ``size`` cases that name none: NaN, the brake's safety
    factor its default (``Application.brake_safety_factor``)."""
    requests = np.full((size, len(REQUEST_FIELDS)), math.nan)
    requests[:, REQUEST_FIELDS.index("brake_safety_factor")] = DEFAULT_BRAKE_SAFETY_FACTOR
    return requests


@dataclass(frozen=True, slots=True, eq=False)
class Cases:
    """The load cases as rows: their cycles' pieces and figures."""

    pieces: PieceArrays
    figures: CycleFigures
    load_inertia: FloatArray
    high_dynamics: BoolArray
    output_load: FloatArray
    """The output load per case (cases × :data:`OUTPUT_LOAD_FIELDS`); NaN where none."""
    thermal_time_constant: FloatArray
    """τ_th per case where the catalogue gives none: the case's, else the default."""
    thermal_assumed: BoolArray
    """Whether that τ_th is the assumed default."""
    requests: FloatArray
    """The further inputs per case (cases × :data:`REQUEST_FIELDS`); NaN where not given."""

    @property
    def size(self) -> int:
        return self.load_inertia.size

    @property
    def mean_speed(self) -> FloatArray:
        return self.figures.mean_speed_rpm

    def rows(self, start: int, stop: int) -> Cases:
        """The cases ``start:stop``."""
        if start == 0 and stop >= self.size:
            return self
        return self.take(slice(start, stop))

    def repeated_with(
        self, pieces: PieceArrays, load_inertia: FloatArray, requests: FloatArray
    ) -> Cases:
        """The first case once for each row of ``pieces``, its cycle, J_L and further inputs
        those rows' (a ratio study's values as columns), its other inputs repeated."""
        first = np.zeros(load_inertia.size, dtype=np.intp)
        return Cases(
            pieces=pieces,
            figures=cycle_figures(pieces),
            load_inertia=load_inertia,
            high_dynamics=self.high_dynamics[first],
            output_load=self.output_load[first],
            thermal_time_constant=self.thermal_time_constant[first],
            thermal_assumed=self.thermal_assumed[first],
            requests=requests,
        )

    def take(self, index: slice | IndexArray) -> Cases:
        """The cases at ``index`` (a slice, or row numbers, repeated as often as given)."""
        p, f = self.pieces, self.figures
        if isinstance(index, slice):

            def taken(a: Any) -> Any:
                return a[index]
        else:  # ``take`` along the rows: a table's rows gathered 9× faster than a[index]

            def taken(a: Any) -> Any:
                return a.take(index, axis=0)

        return Cases(
            pieces=PieceArrays(**{name: taken(getattr(p, name)) for name in _PIECE_FIELDS}),
            figures=CycleFigures(**{name: taken(getattr(f, name)) for name in _FIGURE_FIELDS}),
            load_inertia=taken(self.load_inertia),
            high_dynamics=taken(self.high_dynamics),
            output_load=taken(self.output_load),
            thermal_time_constant=taken(self.thermal_time_constant),
            thermal_assumed=taken(self.thermal_assumed),
            requests=taken(self.requests),
        )


_PIECE_FIELDS = tuple(x.name for x in fields(PieceArrays))
_FIGURE_FIELDS = tuple(x.name for x in fields(CycleFigures))


def cases_of(apps: Sequence[Application]) -> Cases:
    shorthand = [(a.pattern, a.load) for a in apps if a.pattern is not None and a.load]
    if len(shorthand) == len(apps):  # the chapter's trapezoids only: as columns
        # One table, its columns contiguous (an array per input cost seven numpy calls).
        table = np.array(
            [
                (
                    p.speed_rpm,
                    p.accel_s,
                    p.constant_s,
                    p.decel_s,
                    p.pause_s,
                    x.torque_nm,
                    x.inertia_kgm2,
                )
                for p, x in shorthand
            ],
            dtype=np.float64,
        ).reshape(len(shorthand), 7)
        speed, accel_s, constant_s, decel_s, pause_s, torque, inertia = np.ascontiguousarray(
            table.T
        )
        pieces = trapezoid_piece_arrays(
            speed_rpm=speed,
            accel_s=accel_s,
            constant_s=constant_s,
            decel_s=decel_s,
            pause_s=pause_s,
            torque_nm=torque,
            inertia_kgm2=inertia,
        )
    else:
        motions = [a.cycle for a in apps]
        pieces = piece_arrays(motions)
        inertia = np.array([m.load.inertia_kgm2 for m in motions], dtype=np.float64)
    # A profile already computed holds its cycle's figures (a single selection's).
    profiles = [p for p in (a.known_profile for a in apps) if p is not None]
    figures = figures_of(profiles) if len(profiles) == len(apps) else cycle_figures(pieces)
    # The case's other inputs in one table (one numpy call, not one per input): τ_th, its
    # being assumed, high dynamics, the output load's fields, the request's.
    loads = 3 + len(OUTPUT_LOAD_FIELDS)
    inputs = np.array([case_inputs(a) for a in apps], dtype=np.float64).reshape(
        len(apps), loads + len(REQUEST_FIELDS)
    )
    flags = inputs[:, 1:3] != 0.0
    return Cases(
        pieces=pieces,
        figures=figures,
        load_inertia=inertia,
        high_dynamics=flags[:, 1],
        output_load=inputs[:, 3:loads],
        thermal_time_constant=inputs[:, 0],
        thermal_assumed=flags[:, 0],
        requests=inputs[:, loads:],
    )


_NO_OUTPUT_LOAD = (math.nan,) * len(OUTPUT_LOAD_FIELDS)
_OUTPUT_LOAD_OF = attrgetter(*OUTPUT_LOAD_FIELDS)
_REQUEST_OF = attrgetter(*REQUEST_FIELDS)


def case_inputs(a: Application) -> list[float | bool]:
    """A case's row of :func:`cases_of`'s inputs (NaN where not given)."""
    tau = a.thermal_time_constant_s
    load = a.output_load
    return [
        DEFAULT_THERMAL_TIME_CONSTANT_S if tau is None else tau,
        tau is None,
        a.high_dynamics,
        *(
            _NO_OUTPUT_LOAD
            if load is None
            else [math.nan if v is None else v for v in _OUTPUT_LOAD_OF(load)]
        ),
        *[math.nan if v is None else v for v in _REQUEST_OF(a)],
    ]


def swing_of(cases: Cases) -> FloatArray:
    """Each case's swing (:func:`~actuator_selection.sizing.bearing.swing_deg`) where it has
    an output load, NaN elsewhere, as the rules read it."""
    loaded = ~np.isnan(cases.output_load[:, 0])
    if not loaded.any():
        return np.full(cases.size, math.nan)
    p = cases.pieces
    columns = zip(
        p.duration.T, p.start_rpm.T, p.end_rpm.T, p.accel_start.T, p.accel_end.T, strict=True
    )
    with np.errstate(all="ignore"):
        swing = swing_deg(columns, np.where)
    return np.asarray(np.where(loaded, swing, math.nan), dtype=np.float64)


def zone_limits(
    actuators: Sequence[Actuator], columns: IndexArray, mean_speed: FloatArray
) -> FloatArray:
    """The zone's edge at n_av (:func:`~actuator_selection.sizing.zones.torque_limit_nm`) per
    case × zone column; NaN beyond the zone."""
    limits = np.full((mean_speed.size, columns.size), math.nan)
    for k, j in enumerate(columns.tolist()):
        zone = actuators[j].zone
        assert zone is not None
        speeds = np.array([p.speed_rpm for p in zone.points], dtype=np.float64)
        torques = np.array([p.torque_nm for p in zone.points], dtype=np.float64)
        last = speeds.size - 1
        i = np.searchsorted(speeds, mean_speed, side="right")  # bisect_right
        limits[:, k] = _zone_edge(mean_speed, i, np.minimum(i, last), speeds, torques, last)
    return limits


def zone_limit_float(actuator: Actuator, mean_speed: float) -> float:
    """:func:`zone_limits` of one case (n_av ``mean_speed``) × one actuator as a Python
    float, on floats: the same IEEE operations (``bisect_right`` for ``searchsorted``, the
    points ``b − 1`` and ``b`` as there), no numpy call; NaN without a zone."""
    zone = actuator.zone
    if zone is None:
        return math.nan
    speeds = [float(p.speed_rpm) for p in zone.points]
    last = len(speeds) - 1
    i = bisect_right(speeds, mean_speed)
    if not (mean_speed >= 0 and mean_speed <= speeds[last]):  # beyond the zone (NaN too)
        return math.nan
    torques = [float(p.torque_nm) for p in zone.points]
    if i > last:
        return torques[last]
    speed_a, torque_a = speeds[i - 1], torques[i - 1]  # i ≥ 1: the first speed is 0
    share = (mean_speed - speed_a) / (speeds[i] - speed_a)  # speeds rise strictly
    return torque_a + share * (torques[i] - torque_a)


def _zone_edge(
    mean_speed: FloatArray,
    i: IndexArray,
    b: IndexArray,
    speeds: FloatArray,
    torques: FloatArray,
    last: Any,
) -> FloatArray:
    """The zone's edge at n_av, between its points ``b − 1`` and ``b`` (``i``: bisect_right
    of n_av in the speeds, ``last`` the last point), NaN beyond the zone; ``speeds`` and
    ``torques`` indexed by point number along their last axis."""

    def at(points: Any) -> Any:
        if speeds.ndim == 1:
            return speeds[points], torques[points]
        index = np.asarray(points)[:, np.newaxis]
        return (
            np.take_along_axis(speeds, index, axis=1)[:, 0],
            np.take_along_axis(torques, index, axis=1)[:, 0],
        )

    (speed_a, torque_a), (speed_b, torque_b) = at(b - 1), at(b)
    speed_last, torque_last = at(last)
    with np.errstate(all="ignore"):  # rows outside the zone are masked below
        share = (mean_speed - speed_a) / (speed_b - speed_a)
        edge = torque_a + share * (torque_b - torque_a)
    edge = np.where(i > last, torque_last, edge)
    inside = (mean_speed >= 0) & (mean_speed <= speed_last)
    return np.asarray(np.where(inside, edge, math.nan), dtype=np.float64)


@dataclass(frozen=True, slots=True, eq=False)
class ZoneTable:
    """The continuous-duty zones of a catalogue as one table, for the zone's edge of
    given (case, actuator) pairs (:meth:`edges`): each zone's points padded to the
    longest with speeds beyond every n_av."""

    row: IndexArray
    """Per actuator, its row of the table; −1: no zone."""
    speeds: FloatArray
    torques: FloatArray
    last: IndexArray
    """Per row, its last point."""

    def edges(self, columns: IndexArray, mean_speed: FloatArray) -> FloatArray:
        """:func:`zone_limits` of actuator ``columns[p]`` at ``mean_speed[p]``, pair by
        pair; NaN where the actuator has no zone."""
        rows = self.row[columns]
        has = rows >= 0
        out = np.full(columns.size, math.nan)
        if not has.any() or self.speeds.size == 0:
            return out
        r, speed = rows[has], mean_speed[has]
        speeds, torques, last = self.speeds[r], self.torques[r], self.last[r]
        i = (speeds <= speed[:, np.newaxis]).sum(axis=1)  # bisect_right
        out[has] = _zone_edge(speed, i, np.minimum(i, last), speeds, torques, last)
        return out


def zone_table(actuators: Sequence[Actuator]) -> ZoneTable:
    """The zones of ``actuators`` as a :class:`ZoneTable`."""
    zones = [(j, a.zone) for j, a in enumerate(actuators) if a.zone is not None]
    width = max((len(z.points) for _, z in zones), default=0)
    speeds = np.full((len(zones), width), math.inf)
    torques = np.full((len(zones), width), math.nan)
    row = np.full(len(actuators), -1, dtype=np.intp)
    last = np.zeros(len(zones), dtype=np.intp)
    for k, (j, zone) in enumerate(zones):
        n = len(zone.points)
        speeds[k, :n] = [p.speed_rpm for p in zone.points]
        torques[k, :n] = [p.torque_nm for p in zone.points]
        row[j], last[k] = k, n - 1
    return ZoneTable(row=row, speeds=speeds, torques=torques, last=last)


def case_operands(cases: Cases) -> dict[str, Any]:
    """The operands of each case by name, as columns (cases × 1): its speed, load and
    cycle figures, the output load and the swing (:func:`named_operands`)."""
    f, col = cases.figures, np.newaxis
    return named_operands(
        lambda name: getattr(f, name)[:, col],
        load_inertia=cases.load_inertia[:, col],
        high_dynamics=cases.high_dynamics[:, col],
        holding=cases.pieces.holding[:, col],
        output_load={
            name: cases.output_load[:, k, col] for k, name in enumerate(OUTPUT_LOAD_FIELDS)
        },
        swing=swing_of(cases)[:, col],
        requests={name: cases.requests[:, k, col] for k, name in enumerate(REQUEST_FIELDS)},
    )


def named_operands(
    figure: Callable[[str], Any],
    *,
    load_inertia: Any,
    high_dynamics: Any,
    holding: Any,
    output_load: dict[str, Any],
    swing: Any,
    requests: dict[str, Any],
) -> dict[str, Any]:
    """A case's operands by their names in :class:`~actuator_selection.sizing.checks.
    Operands` (:func:`~actuator_selection.sizing.engine.block.operands_of`), from its
    cycle's figures by :class:`~actuator_selection.sizing.motion.CycleFigures`' names
    (``figure``), its J_L, high dynamics, holding torque, output load and request's fields
    by name and swing: columns of arrays (:func:`case_operands`) or one case's floats
    (:mod:`~actuator_selection.sizing.engine.one_case`)."""
    return {
        "speed_rpm": figure("peak_speed_rpm"),
        "load_inertia_kgm2": load_inertia,
        "high_dynamics": high_dynamics,
        "mean_speed_rpm": figure("mean_speed_rpm"),
        "accel_torque_floor_nm": figure("accel_floor_nm"),
        "decel_torque_floor_nm": figure("decel_floor_nm"),
        "rms_torque_floor_nm": figure("rms_floor_nm"),
        "load_torque_nm": holding,
        "decel_s": figure("braking_s"),
        **output_load,
        "swing_deg": swing,
        "cycle_s": figure("cycle_s"),
        **requests,
    }
