"""Measured motion profiles: read a file, fit the segments, store them, size by reference.

``POST /profiles`` reads the file (``services/profile_csv.py``), turns its samples into
the segments the flowchart sizes (``sizing/sampled.py``), stores the answer and returns it:
the cycle as ``POST /selections`` takes it, the figures of the samples beside those of the
segments, how far the segments lie from the samples, a preview of the samples for the
cycle chart, and notes (a rotary profile faster than every actuator's n_max). A selection
or a batch case names the profile by ``cycle: {"profile_id": …}``; :func:`with_profiles`
puts the stored segments in its place before sizing, so that the stored selection holds
the cycle it was sized with.
"""

from __future__ import annotations

import itertools
import math
import uuid
from collections.abc import Iterable, Sequence
from datetime import datetime
from typing import Any, TypeVar

import numpy as np
from pydantic import ValidationError
from sqlalchemy.orm import Session

from actuator_selection.db.repositories import ProfileRepository
from actuator_selection.errors import DomainError
from actuator_selection.schemas.mechanisms import RotaryIn
from actuator_selection.schemas.selections import (
    ProfileCycleIn,
    SegmentsCycleIn,
    SelectionRequest,
)
from actuator_selection.schemas.selections.loads import _LoadIn
from actuator_selection.services.errors import UseCaseError, entry, invalid, invalid_rule
from actuator_selection.services.profile_csv import ColumnUnits, read_profile
from actuator_selection.sizing.sampled import (
    DEFAULT_TOLERANCE,
    SampledFigures,
    fit_segments,
    speeds_from_positions,
)

PREVIEW_POINTS = 2000
"""Samples shown in the cycle chart's preview at most (each the extreme of its stretch)."""

UNITS = {"rotary": ("rpm", "Nm"), "linear": ("mm/s", "N")}
"""The speed and load units of a profile of each kind."""

Request = TypeVar("Request", bound=SelectionRequest)


def _figures(f: SampledFigures) -> dict[str, Any]:
    return {
        "cycle_time_s": f.cycle_s,
        "mean_speed": f.mean_speed,
        "duty_cycle_percent": f.duty_cycle_percent,
        "peak_speed": f.peak_speed,
        "peak_accel": f.peak_accel,
        "rms_load": f.rms_load,
        "peak_load": f.peak_load,
    }


def _preview(time_s: np.ndarray, speed: np.ndarray) -> dict[str, list[float]]:
    """At most :data:`PREVIEW_POINTS` samples: in each of half as many stretches, its
    least and its largest speed, in time order (the envelope the eye sees)."""
    n = time_s.size
    if n <= PREVIEW_POINTS:
        return {"time_s": time_s.tolist(), "speed": speed.tolist()}
    edges = np.linspace(0, n, PREVIEW_POINTS // 2 + 1).astype(np.intp)
    picks: list[int] = []
    for a, b in itertools.pairwise(edges):
        lo, hi = a + int(np.argmin(speed[a:b])), a + int(np.argmax(speed[a:b]))
        picks += sorted({lo, hi})
    picks[-1] = n - 1
    index = np.array(picks)
    return {"time_s": time_s[index].tolist(), "speed": speed[index].tolist()}


def read_and_fit(
    chunks: Iterable[bytes],
    units: ColumnUnits,
    *,
    tolerance: float = DEFAULT_TOLERANCE,
    max_speeds_rpm: Sequence[float] = (),
) -> dict[str, Any]:
    """The answer of ``POST /profiles`` for the file ``chunks`` (without id and time)."""
    samples = read_profile(chunks, units)
    time_s, motion, load = samples.time_s, samples.motion, samples.load
    speed = speeds_from_positions(time_s, motion) if samples.from_positions else motion
    if samples.from_positions and samples.kind == "rotary":
        speed = speed * 60.0  # rev/s → rpm
    if not np.all(np.isfinite(speed)):
        raise invalid(["body"], "profile_speed_overflow")
    try:
        cycle = fit_segments(time_s, speed, load, tolerance=tolerance)
    except DomainError as exc:
        raise invalid_rule(["body"], exc, "profile") from None
    segments = [
        {"speed": end, "duration_s": duration, "process_load": process}
        for duration, end, process in cycle.segments
    ]
    body = {"start_speed": cycle.start_speed, "segments": segments}
    try:
        SegmentsCycleIn.model_validate(body)
    except ValidationError as exc:
        first = exc.errors()[0]
        where = ".".join(str(p) for p in first["loc"])
        raise invalid(["body"], "profile_out_of_bounds", where=where, rule=first["msg"]) from None
    speed_unit, load_unit = UNITS[samples.kind]
    notes = []
    fastest = max((s for s in max_speeds_rpm if math.isfinite(s)), default=math.nan)
    if samples.kind == "rotary" and cycle.samples.peak_speed > fastest:
        notes.append(
            entry(
                ["profile"],
                "profile_above_every_n_max",
                "profile_above_every_n_max",
                peak_rpm=round(cycle.samples.peak_speed, 6),
                max_rpm=fastest,
            )
        )
    return {
        "kind": samples.kind,
        "speed_unit": speed_unit,
        "load_unit": load_unit,
        "samples": samples.lines,
        "columns": samples.columns,
        "ignored_columns": samples.ignored,
        "from_positions": samples.from_positions,
        "cycle": body,
        "figures": {"samples": _figures(cycle.samples), "segments": _figures(cycle.fitted)},
        "fit": {
            "tolerance_percent": tolerance * 100.0,
            "exact": cycle.exact,
            "speed_deviation": cycle.deviation,
            "load_deviation": cycle.load_deviation if load is not None else None,
        },
        "preview": _preview(time_s, speed),
        "notes": notes,
    }


def store_profile(session: Session, answer: dict[str, Any], now: datetime) -> dict[str, Any]:
    """Store the profile ``answer``; the answer with its new id and time."""
    profile_id = str(uuid.uuid4())
    stored = {"id": profile_id, "created_at": now.isoformat(), **answer}
    ProfileRepository(session).add(profile_id, now, answer["kind"], stored)
    return stored


def stored_profile(session: Session, profile_id: str) -> dict[str, Any] | None:
    """The stored answer of a profile, or None."""
    return ProfileRepository(session).answers([profile_id]).get(profile_id)


def _kind_of(body: SelectionRequest) -> str:
    return "rotary" if isinstance(body.load, _LoadIn | RotaryIn) else "linear"


def with_profiles(
    session: Session, bodies: Sequence[Request], loc: Sequence[Sequence[str | int]]
) -> list[Request]:
    """``bodies`` with each profile reference replaced by the profile's stored segments;
    a 422 naming each reference (at ``loc[i]``) to an unknown profile or to one of the
    other kind (a rotary profile on a linear axis)."""
    wanted = {b.cycle.profile_id for b in bodies if isinstance(b.cycle, ProfileCycleIn)}
    if not wanted:
        return list(bodies)
    stored = ProfileRepository(session).answers(wanted)
    errors = []
    out = []
    for body, where in zip(bodies, loc, strict=True):
        cycle = body.cycle
        if not isinstance(cycle, ProfileCycleIn):
            out.append(body)
            continue
        at = [*where, "cycle", "profile_id"]
        answer = stored.get(cycle.profile_id)
        if answer is None:
            errors.append(entry(at, "unknown_profile", "unknown_profile", id=cycle.profile_id))
            continue
        if answer["kind"] != _kind_of(body):
            errors.append(
                entry(
                    at,
                    "profile_kind",
                    "profile_kind",
                    kind=answer["kind"],
                    load=getattr(body.load, "type", "direct"),
                )
            )
            continue
        segments = SegmentsCycleIn.model_validate(answer["cycle"])
        out.append(body.model_copy(update={"cycle": segments}))
    if errors:
        raise UseCaseError(errors)
    return out
