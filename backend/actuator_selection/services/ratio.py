"""The ratio study as a use case: a load case's free transmission value over the
catalogue (``sizing/ratio.py``)."""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.schemas.mechanisms import BallScrewInclineIn, BeltIn, RackPinionIn
from actuator_selection.schemas.ratio import (
    DEFAULT_RANGE,
    MAX_VALUE,
    UNITS,
    CurveOut,
    IntervalOut,
    RatioActuatorOut,
    RatioStudyIn,
    RatioStudyOut,
    RatioStudyRequest,
)
from actuator_selection.schemas.selections import BallScrewLoad, SelectionRequest
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.sizing.application import Application
from actuator_selection.sizing.engine import FloatArray
from actuator_selection.sizing.engine.cases import Cases
from actuator_selection.sizing.linear_cases import linear_cases
from actuator_selection.sizing.mechanisms import Transmission
from actuator_selection.sizing.mechanisms.ball_screw import inclined_ball_screw_law
from actuator_selection.sizing.mechanisms.belt import belt_law
from actuator_selection.sizing.mechanisms.linear import LinearLaw
from actuator_selection.sizing.mechanisms.rack_pinion import rack_pinion_law
from actuator_selection.sizing.ratio import RatioResult, ranked_ratio_study
from actuator_selection.sizing.ratio_cases import (
    MONOTONE_SHARES,
    geared,
    geared_cases,
    geared_rms_floor,
    geared_torque_floor,
)


def varied(body: SelectionRequest, study: RatioStudyIn) -> Callable[[float], Application]:
    """The load case at a value of the free variable, built as a selection builds it."""
    if study.variable == "ratio":
        base = body.to_core()
        return lambda i: geared(
            base,
            Transmission(
                ratio=i,
                inertia_kgm2=study.transmission_inertia_kgm2,
                efficiency=study.transmission_efficiency,
            ),
        )
    load = body.load
    field: str = study.variable
    scale = 1.0
    if field == "lead_mm" and isinstance(load, BallScrewLoad):
        field, scale = "lead_m", 1e-3  # the chapter's ball screw takes its lead in m
    if field not in type(load).model_fields:
        raise InvalidInputError(
            "ratio_study.variable",
            code="study_variable_missing",
            params={"type": load.type, "variable": study.variable},
        )
    body.to_core()  # the load case as sent is valid

    def at(x: float) -> Application:
        return body.model_copy(
            update={"load": load.model_copy(update={field: x * scale})}
        ).to_core()

    return at


def columns_of(body: SelectionRequest, study: RatioStudyIn) -> Callable[[FloatArray], Cases] | None:
    """:func:`varied` at many values at once as the engine's cases, where it can be built
    as columns: an external ratio on the chapter's trapezoid; a screw's lead, a pinion's
    or a belt pulley's diameter (without a transmission of their own) on the
    trapezoid."""
    load = body.load
    linear = _linear_law(load, study.variable)
    if linear is not None:
        law, speed = linear
        return linear_cases(body.to_core(), law, speed, varied(body, study))
    if study.variable != "ratio":
        return None
    return geared_cases(
        body.to_core(), study.transmission_inertia_kgm2, study.transmission_efficiency
    )


def _linear_law(load: object, variable: str) -> tuple[LinearLaw, float] | None:
    """The linear axis of ``load`` as a function of ``variable`` and its load speed, where
    it is one on a trapezoid (a speed given) without a transmission of its own."""
    if not isinstance(load, BallScrewInclineIn | RackPinionIn | BeltIn):
        return None
    if load.transmission is not None or load.speed is None:
        return None
    if variable == "lead_mm" and isinstance(load, BallScrewInclineIn):
        return inclined_ball_screw_law(load.screw()), load.speed
    if variable == "pinion_diameter_mm" and isinstance(load, RackPinionIn):
        return rack_pinion_law(load.rack()), load.speed
    if variable == "pulley_diameter_mm" and isinstance(load, BeltIn):
        return belt_law(load.belt()), load.speed
    return None


Floor = Callable[[FloatArray, FloatArray], FloatArray]
"""A lower bound of a torque between neighbouring values of the study's variable."""


def floor_of(
    body: SelectionRequest,
    study: RatioStudyIn,
    geared_floor: Callable[[Application, float, float], Floor | None],
) -> Floor | None:
    """``geared_floor`` (:func:`~actuator_selection.sizing.ratio_cases.geared_torque_floor`
    of |T_1|, :func:`~actuator_selection.sizing.ratio_cases.geared_rms_floor` of T_rms)
    where :func:`columns_of` builds the cases of an external ratio; None otherwise."""
    if study.variable != "ratio":
        return None
    return geared_floor(
        body.to_core(), study.transmission_inertia_kgm2, study.transmission_efficiency
    )


def _out(result: RatioResult, curve: bool) -> RatioActuatorOut:
    # built without validating again (a model per actuator of a 6,400-actuator study cost
    # more than its search): the core's frozen results, checked by their types
    return RatioActuatorOut.model_construct(
        model=result.actuator.model,
        intervals=[
            IntervalOut.model_construct(
                low=i.low,
                high=i.high,
                low_binding=list(i.low_binding),
                high_binding=list(i.high_binding),
            )
            for i in result.intervals
        ],
        best=result.best,
        best_utilisation=result.best_utilisation,
        best_binding=result.best_binding,
        verdict=None if result.verdict is None else result.verdict.value,
        curve=CurveOut.model_construct(
            values=list(result.grid), utilisation=list(result.utilisation)
        )
        if curve
        else None,
    )


DEFAULT_TOP = 100
"""Actuators a study's answer lists unless the request asks for another number (``top``).
More than a selection lists (``presenters.selection.DEFAULT_TOP``): a study is not stored
and has no cursor to read the rest by; the starter catalogue's 64 all fit."""


def study(
    body: RatioStudyRequest, catalogue: CatalogueSnapshot, top: int = DEFAULT_TOP
) -> RatioStudyOut:
    """The ranking's first ``top`` actuators, those that fit first: each one's feasible
    intervals and best value."""
    spec: RatioStudyIn = body.ratio_study
    low, high = spec.bounds
    actuators = catalogue.actuators_of(body.models)
    found = ranked_ratio_study(
        actuators,
        varied(body, spec),
        low,
        high,
        top=top,
        series=spec.series,
        arrays=catalogue.arrays(tuple(actuators)),
        cases_at=columns_of(body, spec),
        monotone=MONOTONE_SHARES if spec.variable == "ratio" else None,
        torque_floor=floor_of(body, spec, geared_torque_floor),
        rms_floor=floor_of(body, spec, geared_rms_floor),
    )
    return RatioStudyOut(
        catalogue_version=catalogue.version,
        variable=spec.variable,
        unit=UNITS[spec.variable],
        min=low,
        max=high,
        series=spec.series,
        total_actuators=found.total,
        fitting_actuators=found.fitting,
        actuators=[_out(r, n < spec.curves) for n, r in enumerate(found.results)],
    )


GUIDED = 3
"""How many actuators the guidance names per free value."""
GUIDANCE_WIDENING = 10.0
"""The guidance searches the variable's default range widened this much both ways."""


def guidance(
    body: SelectionRequest, actuators: Sequence[Actuator], catalogue: CatalogueSnapshot
) -> list[dict[str, Any]]:
    """When nothing fits: for the load's own lead or diameter, the actuators that fit at
    some value of it (best utilisation first, at most :data:`GUIDED`), each with the
    interval that holds its best value ("a lead of 190–1000 mm makes CHA-32A-50 fit").
    The range is the variable's default range widened by :data:`GUIDANCE_WIDENING`. The
    engine reads ``catalogue``'s arrays of ``actuators`` (built once per version)."""
    arrays = catalogue.arrays(tuple(actuators))
    fields = type(body.load).model_fields
    found: list[dict[str, Any]] = []
    for variable, (low, high) in DEFAULT_RANGE.items():
        own = variable in fields or (variable == "lead_mm" and isinstance(body.load, BallScrewLoad))
        if variable == "ratio" or not own:
            continue
        spec = RatioStudyIn(
            variable=variable,  # type: ignore[arg-type]
            min=low / GUIDANCE_WIDENING,
            max=min(high * GUIDANCE_WIDENING, MAX_VALUE),
        )
        lower, upper = spec.bounds
        ranked = ranked_ratio_study(
            actuators, varied(body, spec), lower, upper, top=GUIDED, arrays=arrays
        )
        results = [r for r in ranked.results if r.best is not None]
        for result in results:
            assert result.best is not None
            best = result.best
            interval = next(
                (i for i in result.intervals if i.low <= best <= i.high), result.intervals[0]
            )
            found.append(
                {
                    "variable": variable,
                    "unit": UNITS[variable],
                    "model": result.actuator.model,
                    "low": interval.low,
                    "high": interval.high,
                    "best": best,
                    "best_utilisation": result.best_utilisation,
                }
            )
    return found
