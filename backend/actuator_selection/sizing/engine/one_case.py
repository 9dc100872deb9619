"""One load case as the engine's block of one cell reads it: Python floats and bools
(:class:`CaseFloats`), built straight from the application where it is the chapter's
trapezoid (a one-model selection's), its :class:`~actuator_selection.sizing.engine.cases.
Cases` arrays only where something asks for them (:class:`OneCase`).

Why: a block of one cell runs on floats (decision 0029); building the case's arrays only
to read them back as floats cost a one-model selection some twenty numpy calls. The
floats are those the arrays hold, bit for bit: the same conversions (``float64`` of each
input), the same IEEE operations (:func:`~actuator_selection.sizing.motion.
trapezoid_piece_floats`, :func:`~actuator_selection.sizing.bearing.swing_deg`), which
``tests/sizing/test_block_cell.py`` checks against :func:`case_floats` of the arrays.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Any

import numpy as np

from actuator_selection.sizing.application import Application
from actuator_selection.sizing.bearing import swing_deg
from actuator_selection.sizing.engine.cases import (
    OUTPUT_LOAD_FIELDS,
    REQUEST_FIELDS,
    Cases,
    case_inputs,
    case_operands,
    cases_of,
    named_operands,
)
from actuator_selection.sizing.motion import (
    TRAPEZOID_BRAKING,
    TRAPEZOID_CONSTANT,
    CycleFigures,
    trapezoid_piece_floats,
)

FIGURE_FIELDS = tuple(x.name for x in fields(CycleFigures))
"""The cycle's figures in :class:`~actuator_selection.sizing.motion.CycleFigures`' order."""
_CYCLE_S = FIGURE_FIELDS.index("cycle_s")
_MEAN_SPEED = FIGURE_FIELDS.index("mean_speed_rpm")


@dataclass(frozen=True, slots=True, eq=False)
class CaseFloats:
    """One case's row of :class:`~actuator_selection.sizing.engine.cases.Cases` as Python
    floats and bools: its pieces' columns (lists, piece by piece), its cycle's figures, τ_th
    and its operands by name (:func:`~actuator_selection.sizing.engine.cases.
    case_operands`' names)."""

    duration: list[float]
    start_rpm: list[float]
    end_rpm: list[float]
    accel_start: list[float]
    accel_end: list[float]
    static: list[float]
    inertia: list[float]
    braking: list[bool]
    constant_speed: list[bool]
    figures: tuple[float, ...]
    """The cycle's figures, in :data:`FIGURE_FIELDS`' order."""
    thermal_time_constant: float
    """τ_th where the catalogue gives none: the case's, else the default."""
    thermal_assumed: bool
    operands: dict[str, Any]
    """The case's operands by name, as floats and bools."""

    @property
    def cycle_s(self) -> float:
        return self.figures[_CYCLE_S]

    @property
    def mean_speed_rpm(self) -> float:
        return self.figures[_MEAN_SPEED]


def case_floats(cases: Cases) -> CaseFloats:
    """The floats of the one case of ``cases`` (its arrays read back)."""
    p, f = cases.pieces, cases.figures
    return CaseFloats(
        duration=p.duration[0].tolist(),
        start_rpm=p.start_rpm[0].tolist(),
        end_rpm=p.end_rpm[0].tolist(),
        accel_start=p.accel_start[0].tolist(),
        accel_end=p.accel_end[0].tolist(),
        static=p.static[0].tolist(),
        inertia=p.inertia[0].tolist(),
        braking=p.braking[0].tolist(),
        constant_speed=p.constant_speed[0].tolist(),
        figures=tuple(getattr(f, name).item() for name in FIGURE_FIELDS),
        thermal_time_constant=cases.thermal_time_constant.item(),
        thermal_assumed=cases.thermal_assumed.item(),
        operands={name: value.item() for name, value in case_operands(cases).items()},
    )


def _float_where(condition: Any, if_true: Any, if_false: Any) -> Any:
    return if_true if condition else if_false


_LOADS = 3 + len(OUTPUT_LOAD_FIELDS)
"""Where the output load's fields end in a row of :func:`~actuator_selection.sizing.
engine.cases.case_inputs` (τ_th, its being assumed, high dynamics, then the load's)."""


def trapezoid_floats(app: Application) -> CaseFloats | None:
    """:func:`case_floats` of ``cases_of([app])`` without its arrays, where ``app`` is the
    chapter's trapezoid with a load whose profile is known (the figures are the
    profile's, as :func:`~actuator_selection.sizing.motion.figures_of` reads them) and no
    ramp takes 0 s; else None."""
    pattern, load, profile = app.pattern, app.load, app.known_profile
    if pattern is None or not load or profile is None:
        return None
    torque = float(load.torque_nm)
    pieces = trapezoid_piece_floats(
        float(pattern.speed_rpm),
        float(pattern.accel_s),
        float(pattern.constant_s),
        float(pattern.decel_s),
        float(pattern.pause_s),
        torque,
        float(load.inertia_kgm2),
    )
    if pieces is None:
        return None
    duration, start_rpm, end_rpm, accel_start, accel_end, static, inertia = pieces
    figures = tuple(float(getattr(profile, name)) for name in FIGURE_FIELDS)
    row = [float(v) for v in case_inputs(app)]  # as the arrays' float64
    swing = math.nan
    if row[3] == row[3]:  # a radial force: loaded (cases.swing_of), the swing on floats
        columns = zip(duration, start_rpm, end_rpm, accel_start, accel_end, strict=True)
        swing = swing_deg(columns, _float_where)
    named = dict(zip(FIGURE_FIELDS, figures, strict=True))
    return CaseFloats(
        duration=list(duration),
        start_rpm=list(start_rpm),
        end_rpm=list(end_rpm),
        accel_start=list(accel_start),
        accel_end=list(accel_end),
        static=list(static),
        inertia=list(inertia),
        braking=list(TRAPEZOID_BRAKING),
        constant_speed=list(TRAPEZOID_CONSTANT),
        figures=figures,
        thermal_time_constant=row[0],
        thermal_assumed=row[1] != 0.0,
        operands=named_operands(
            named.__getitem__,
            load_inertia=inertia[0],
            high_dynamics=row[2] != 0.0,
            holding=torque,
            output_load=dict(zip(OUTPUT_LOAD_FIELDS, row[3:_LOADS], strict=True)),
            swing=swing,
            requests=dict(zip(REQUEST_FIELDS, row[_LOADS:], strict=True)),
        ),
    )


class OneCase:
    """One load case (a one-model selection's): its floats, what a block of one cell
    reads, and its :class:`~actuator_selection.sizing.engine.cases.Cases` built when first
    asked for (:attr:`cases`: a block of more actuators, a formula that raises on
    floats, the catalogue's first evaluation of a rule set)."""

    __slots__ = ("_app", "_cases", "_figures", "floats")

    size = 1

    def __init__(
        self, floats: CaseFloats, *, cases: Cases | None = None, app: Application | None = None
    ) -> None:
        assert cases is not None or app is not None
        self.floats = floats
        self._cases = cases
        self._app = app
        self._figures: CycleFigures | None = None if cases is None else cases.figures

    @classmethod
    def of(cls, app: Application) -> OneCase:
        """The case of ``app``: on floats straight from it where it is the chapter's
        trapezoid with its profile known (:func:`trapezoid_floats`), else from its arrays."""
        floats = trapezoid_floats(app)
        if floats is None:
            cases = cases_of([app])
            return cls(case_floats(cases), cases=cases)
        return cls(floats, app=app)

    @classmethod
    def of_cases(cls, cases: Cases) -> OneCase:
        """The one case of ``cases``, its floats read from its arrays."""
        return cls(case_floats(cases), cases=cases)

    @property
    def cases(self) -> Cases:
        """The case's arrays (``cases_of([app])``), built once."""
        if self._cases is None:
            assert self._app is not None
            self._cases = cases_of([self._app])
        return self._cases

    @property
    def figures(self) -> CycleFigures:
        """The cycle's figures as arrays of one case (those of :attr:`cases`), from the
        floats in one numpy call where the arrays are not built."""
        if self._figures is None:
            table = np.array(self.floats.figures, dtype=np.float64).reshape(-1, 1)
            self._figures = CycleFigures(*table)
        return self._figures
