"""How long the winding stands an overload: the first-order thermal model in place of Fig.
520.1's unpublished values.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from actuator_selection.errors import InvalidInputError, OutOfRangeError
from actuator_selection.sizing.thermal.sensors import _require_finite

# --------------------------------------------------------------------------- overload

DEFAULT_THERMAL_TIME_CONSTANT_S = 600.0
"""τ_th [s] assumed where neither the catalogue nor the request gives one: 10 min.

No public Harmonic Drive document we found publishes a winding thermal time constant
for the CHA, FHA-C or FHA-C mini (``shared/reference/public-catalogue-data.md``, "Not
published as numbers anywhere we found"), so this is an assumption, not catalogue data,
and a check that uses it says ``approximate``. Why 10 min:

- a smaller τ_th is the safe side: every time to shutdown τ_th·ln((k² − p²)/(k² − 1))
  is proportional to it, and the peak of the cycle's heating grows as τ_th shrinks
  (tests/sizing/test_thermal_validity.py checks both);
- it must still let the chapter's own rule stand where the manufacturer applies it: the
  continuous-duty diagram of the worked example is drawn for a duty cycle of one minute
  ("ED = 1 min.", Fig. 517.1; the reading of that note is unconfirmed), and T_rms over a
  cycle only stands for cycles short against τ_th; at τ_th = 10 × 1 min a one-minute
  cycle's heating peak lies within a few per cent of T_rms, at smaller τ_th it would not;
- the issue that asked for this check expects shutdown after 10–40 min at 1.45·T_0
  (τ_th ≈ 15–62 min in this model); a drive maker's generic I²t default for servomotors
  is 540 s (Beckhoff, object 32C8:01 "Motor thermal time constant"). 600 s is at the
  short end of these, so the check is strict rather than lenient.

Give the actuator's real τ_th (the catalogue column ``thermal_time_constant_s``, or
the request's ``thermal_time_constant_s``) where it is known.
"""


def _check_overload_inputs(
    overload_factor: float,
    thermal_time_constant_s: float,
    preload_factor: float,
    max_overload_factor: float | None,
) -> None:
    _require_finite("overload_factor", overload_factor)
    _require_finite("thermal_time_constant_s", thermal_time_constant_s)
    _require_finite("preload_factor", preload_factor)
    if overload_factor < 0:
        raise InvalidInputError("overload_factor", "must be ≥ 0: k = I/I_s is a ratio of currents")
    if thermal_time_constant_s <= 0:
        raise InvalidInputError(
            "thermal_time_constant_s", "must be > 0: τ_th divides the time in the thermal model"
        )
    if preload_factor < 0:
        raise InvalidInputError("preload_factor", "must be ≥ 0: p = I_prev/I_s")
    if preload_factor > 1:
        raise InvalidInputError(
            "preload_factor",
            "must be ≤ 1: a steady preload above the stall current I_s would hold the "
            "winding above its limit, which is no state to start an overload from",
        )
    if max_overload_factor is not None and overload_factor > max_overload_factor:
        raise OutOfRangeError(
            "overload_factor",
            f"k = {overload_factor:g} exceeds I_max/I_s = {max_overload_factor:g}: "
            "Fig. 520.1 holds for I ≤ I_max",
        )


def overload_duration_s(
    *,
    overload_factor: float,
    thermal_time_constant_s: float,
    preload_factor: float = 0.0,
    max_overload_factor: float | None = None,
) -> float | None:
    """Time until the winding reaches its limit at overload k = I/I_s [s] (Fig. 520.1).

    The figure's values are not published; the first-order thermal model of the
    winding (temperature rise ∝ I², limit reached at I_s in steady state) gives,
    from the steady state of a previous current p·I_s,

        t = τ_th · ln((k² − p²) / (k² − 1)),   k > 1, 0 ≤ p ≤ 1,

    and from cold (p = 0) t = τ_th · ln(k² / (k² − 1)). For k ≤ 1 the limit is
    never reached and None is returned. p = 1 means the winding is already at its
    limit: t = 0 for any k > 1. p > 1 is refused (see :class:`InvalidInputError`).

    Parameters
    ----------
    overload_factor
        k = I/I_s [-], ratio of the actual effective current to the continuous stall current.
    thermal_time_constant_s
        τ_th [s], the winding's thermal time constant.
    preload_factor
        p = I_prev/I_s [-] of the current the winding carried long enough to settle; 0 = cold.
    max_overload_factor
        I_max/I_s [-]; when given, k above it is an :class:`OutOfRangeError` (I ≤ I_max).

    >>> round(overload_duration_s(overload_factor=2.0, thermal_time_constant_s=600), 1)
    172.6
    >>> overload_duration_s(overload_factor=1.0, thermal_time_constant_s=600) is None
    True
    """
    _check_overload_inputs(
        overload_factor, thermal_time_constant_s, preload_factor, max_overload_factor
    )
    if overload_factor <= 1.0:
        return None
    k2 = overload_factor * overload_factor
    p2 = preload_factor * preload_factor
    return thermal_time_constant_s * math.log((k2 - p2) / (k2 - 1.0))


def finite_overload_duration_s(
    *,
    overload_factor: float,
    thermal_time_constant_s: float,
    preload_factor: float = 0.0,
    max_overload_factor: float | None = None,
) -> float:
    """As :func:`overload_duration_s`, but k ≤ 1 is an :class:`InvalidInputError`.

    For callers that need a number: at k ≤ 1 there is no shutdown to time.

    >>> finite_overload_duration_s(overload_factor=0.8, thermal_time_constant_s=600)
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: overload_factor: must be > 1 for a \
duration: at k = 0.8 ≤ 1 the winding never reaches its limit (Fig. 520.1)
    """
    duration = overload_duration_s(
        overload_factor=overload_factor,
        thermal_time_constant_s=thermal_time_constant_s,
        preload_factor=preload_factor,
        max_overload_factor=max_overload_factor,
    )
    if duration is None:
        raise InvalidInputError(
            "overload_factor",
            f"must be > 1 for a duration: at k = {overload_factor:g} ≤ 1 the winding never "
            "reaches its limit (Fig. 520.1)",
        )
    return duration


@dataclass(frozen=True, slots=True, kw_only=True)
class OverloadPoint:
    """One point of the overload curve: k [-] and the time to shutdown [s]."""

    overload_factor: float
    duration_s: float


def overload_curve(
    *,
    thermal_time_constant_s: float,
    max_overload_factor: float,
    preload_factor: float = 0.0,
    points: int = 50,
) -> tuple[OverloadPoint, ...]:
    """The overload characteristic of Fig. 520.1 from the thermal model, for a chart.

    ``points`` equally spaced factors k_j = 1 + (k_max − 1)·j/points, j = 1…points:
    the curve starts just above 1 (where t grows without bound) and ends at
    k_max = I_max/I_s.

    >>> c = overload_curve(thermal_time_constant_s=600, max_overload_factor=3, points=4)
    >>> [(p.overload_factor, round(p.duration_s, 1)) for p in c]
    [(1.5, 352.7), (2.0, 172.6), (2.5, 104.6), (3.0, 70.7)]
    """
    _require_finite("max_overload_factor", max_overload_factor)
    if max_overload_factor <= 1:
        raise InvalidInputError(
            "max_overload_factor",
            "must be > 1: with I_max ≤ I_s there is no overload to draw",
        )
    if points < 1:
        raise InvalidInputError("points", "must be ≥ 1")
    curve = []
    for j in range(1, points + 1):
        k = 1.0 + (max_overload_factor - 1.0) * j / points
        curve.append(
            OverloadPoint(
                overload_factor=k,
                duration_s=finite_overload_duration_s(
                    overload_factor=k,
                    thermal_time_constant_s=thermal_time_constant_s,
                    preload_factor=preload_factor,
                ),
            )
        )
    return tuple(curve)
