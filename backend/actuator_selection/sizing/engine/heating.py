"""The winding's heating over a block's repeating cycle: the gains g = 1 − e^(−t/τ_th) of
each piece and of the cycle (:class:`HeatingGains` for a block of cases × actuators,
:class:`CellGains` for one cell's floats), and the heating piece after piece with its
peak over the repeating cycle (:func:`heated_over`, :func:`periodic_peak`), the same code
on arrays and on floats (:mod:`~actuator_selection.sizing.engine.formulas`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from typing import Any, Protocol

import numpy as np

from actuator_selection.sizing.engine.arrays import BoolArray, FloatArray, IndexArray
from actuator_selection.sizing.engine.cases import Cases
from actuator_selection.sizing.engine.catalogue import CatalogueArrays, CellFloats
from actuator_selection.sizing.engine.formulas import ARRAY_MATH, Math
from actuator_selection.sizing.engine.one_case import CaseFloats
from actuator_selection.sizing.motion import heating_gain, heating_gain_array


class Gains(Protocol):
    """The heating gains of a block (:class:`HeatingGains`) or a cell (:class:`CellGains`)."""

    def piece(self, k: int) -> Any:
        """The gains of piece ``k``."""

    def cycle(self) -> Any:
        """The gains of the whole cycle."""


class HeatingGains:
    """g = 1 − e^(−t/τ_th) of each piece and of the whole cycle for a block, case ×
    actuator (:meth:`~actuator_selection.sizing.motion.Profile.heating_gains`).

    τ_th is the actuator's catalogue value where published, else the case's (given or
    assumed). The gains are computed with ``math.expm1`` on Python floats
    (:func:`~actuator_selection.sizing.motion.heating_gain`, on arrays
    :func:`~actuator_selection.sizing.motion.heating_gain_array`), as Python's floats
    compute them: numpy's ``expm1`` may differ from the C library's in the last bit. Only
    the distinct τ_th values are computed: the case's, and each published one (the
    catalogue's :attr:`~CatalogueArrays.published_taus`, found once per catalogue).
    """

    def __init__(self, cat: CatalogueArrays, cases: Cases) -> None:
        values = cat.published_taus
        durations, cycles = cases.pieces.duration, cases.figures.cycle_s
        count = durations.shape[1]
        if cases.size == 1:  # one case (a selection's): its few gains straight from floats,
            row, cycle = durations[0].tolist(), float(cycles[0])  # one table: the pieces',
            taus = [float(cases.thermal_time_constant[0]), *values]  # then the cycle's
            table = np.array([_gains([*row, cycle], tau) for tau in taus], dtype=np.float64)
            pieces, whole = table[:, :count], table[:, count]
        else:  # per case, gains for its own τ_th (row 0) and each published τ_th (1, 2, …)
            columns = [cases.thermal_time_constant, *(np.full(cases.size, v) for v in values)]
            gains = [_case_gains(durations, cycles, tau) for tau in columns]
            pieces = np.array([piece for piece, _ in gains], dtype=np.float64)
            whole = np.array([cycle for _, cycle in gains], dtype=np.float64)
        self._pieces = pieces.reshape(len(values) + 1, cases.size, count)
        self._cycle = whole.reshape(len(values) + 1, cases.size)
        self._index = cat.tau_column
        self._mixed = bool(values)
        case_tau = cases.thermal_time_constant[:, np.newaxis]
        unpublished = cat.tau_unpublished
        self.time_constant: FloatArray = np.where(unpublished, case_tau, cat.thermal_time_constant)
        self.assumed: BoolArray = unpublished & cases.thermal_assumed[:, np.newaxis]
        # Each piece's gains, cases × pieces × actuators (× 1 where no actuator publishes
        # τ_th), picked once: the heating's two passes and the speed's read them.
        if self._mixed:
            self._piece: FloatArray = self._pieces[self._index].transpose(1, 2, 0)
        else:
            self._piece = self._pieces[0][:, :, np.newaxis]

    def piece(self, k: int) -> FloatArray:
        """The gains of piece ``k``, cases × actuators (or cases × 1)."""
        gains: FloatArray = self._piece[:, k]
        return gains

    def cycle(self) -> FloatArray:
        """The gains of the whole cycle, cases × actuators (or cases × 1)."""
        if not self._mixed:
            column: FloatArray = self._cycle[0][:, np.newaxis]
            return column
        return self._cycle[self._index].T


class CellGains:
    """:class:`HeatingGains` of one case × one actuator, as floats: the gains at the
    actuator's τ_th (published, else the case's), by :func:`heating_gain` as there;
    ``cat`` the actuator's :meth:`~CatalogueArrays.cell_floats`."""

    def __init__(self, cat: CellFloats, case: CaseFloats) -> None:
        published = cat.tau
        tau = case.thermal_time_constant if published is None else published
        self._pieces = _gains(case.duration, tau)
        self._cycle = heating_gain(case.cycle_s, tau)
        self.time_constant = tau
        self.assumed = published is None and case.thermal_assumed

    def piece(self, k: int) -> float:
        return self._pieces[k]

    def cycle(self) -> float:
        return self._cycle


def _gains(durations: list[float], tau: float) -> list[float]:
    return [heating_gain(t, tau) for t in durations]


def _distinct_rows(key: FloatArray) -> tuple[FloatArray, IndexArray]:
    """The distinct rows of ``key`` and where each row is among them: grouped by a sum of
    the columns weighted (a sort of floats, not of rows), the grouping then checked row by
    row; sorted as rows where two rows share a sum."""
    with np.errstate(all="ignore"):
        projection = np.zeros(key.shape[0])
        for k in range(key.shape[1]):
            projection = projection + key[:, k] * (1.0 + k / 7.0)
    _, first, where = np.unique(projection, return_index=True, return_inverse=True)
    distinct = key[first]
    if np.array_equal(distinct[where], key):
        return distinct, where.ravel()
    rows = np.ascontiguousarray(key)
    view = rows.view(np.dtype((np.void, rows.itemsize * rows.shape[1]))).ravel()
    _, first, where = np.unique(view, return_index=True, return_inverse=True)
    return rows[first], where.ravel()


def _case_gains(
    durations: FloatArray, cycles: FloatArray, taus: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Per case, the gains of its pieces and of its cycle at its τ_th, each computed once
    per distinct (pieces' durations, cycle, τ_th): cases repeat where the engine runs on
    pairs (:mod:`~actuator_selection.sizing.engine.pairs`), one row per pair."""
    key = np.column_stack([durations, cycles, taus])
    where: IndexArray = np.zeros(key.shape[0], dtype=np.intp)
    if key.shape[0] > 1:
        if (key == key[0]).all():  # one case repeated (pairs of a trapezoid: often)
            key = key[:1]
        else:
            key, where = _distinct_rows(key)
    gains = heating_gain_array(key[:, :-1], key[:, -1:])  # the pieces', then the cycle's
    return gains[:, :-1][where], gains[:, -1][where]


def heated_over(
    heat: Any,
    sources: Iterable[Any],
    gains: Gains,
    first: int = 0,
    peak: Any = None,
    math_: Math = ARRAY_MATH,
) -> tuple[Any, Any]:
    """The winding's heating over the pieces ``first``, ``first + 1``, … whose heat
    sources are ``sources`` (piece by piece: :func:`by_piece` of arrays, or one cell's
    floats): x ← x + (s − x)·g piece by piece
    (:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm`), and the peak
    of x over the pieces' ends where ``peak`` is given (else None)."""
    if math_ is ARRAY_MATH:
        return _heated_arrays(heat, sources, gains, first, peak)
    where = math_.where
    for j, source in enumerate(sources):
        heat = heat + (source - heat) * gains.piece(first + j)
        if peak is not None:
            peak = where(heat > peak, heat, peak)
    return heat, peak


def _heated_arrays(
    heat: Any, sources: Iterable[Any], gains: Gains, first: int, peak: Any
) -> tuple[Any, Any]:
    """:func:`heated_over` on arrays, each piece's new x written into the array of its
    s − x ((s − x)·g + x: the same sum) and the peak updated in an array of its own where
    the shapes allow (np.where's three temporaries a piece were a tenth of a columns
    batch's heating): the same values."""
    own_peak = False
    for j, source in enumerate(sources):
        gain = gains.piece(first + j)
        new = np.subtract(source, heat)
        if np.broadcast_shapes(new.shape, np.shape(gain)) == new.shape:
            np.multiply(new, gain, out=new)
            np.add(new, heat, out=new)
        else:
            new = heat + new * gain
        heat = new
        if peak is None:
            continue
        if not own_peak and np.broadcast_shapes(np.shape(peak), heat.shape) == heat.shape:
            peak, own_peak = np.array(np.broadcast_to(peak, heat.shape)), True
        if own_peak and peak.shape == heat.shape:
            np.copyto(peak, heat, where=heat > peak)
        else:
            peak, own_peak = np.where(heat > peak, heat, peak), False
    return heat, peak


def by_piece(sources: FloatArray) -> FloatArray:
    """``sources`` (… × cases × pieces × …) piece by piece, as :func:`heated_over` reads
    them: iterating the result gives ``sources[..., j, :]``."""
    return np.moveaxis(sources, -2, 0)


def periodic_peak(
    heat: Any,
    groups: Callable[[], Iterable[tuple[int, Iterable[Any]]]],
    gains: Gains,
    fallback: Any,
    math_: Math = ARRAY_MATH,
) -> Any:
    """The peak of the heating over a repeating cycle: the periodic start x_0 = B/(1 − A)
    from the first pass's ``heat`` (B; ``fallback`` where the cycle's gain is 0), then
    a second pass over the pieces' heat sources (``groups``: (first piece, sources))."""
    where = math_.where
    cycle_gain = gains.cycle()
    start = where(cycle_gain > 0, heat / where(cycle_gain > 0, cycle_gain, 1.0), fallback)
    peak = heat = start
    for first, sources in groups():
        heat, peak = heated_over(heat, sources, gains, first, peak, math_)
    return peak
