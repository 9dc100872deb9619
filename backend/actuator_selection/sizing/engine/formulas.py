"""The block's element-wise formulas, written once for numpy's arrays and for one cell's
Python floats (:data:`ARRAY_MATH`, :data:`FLOAT_MATH`), as the cycle's figures are
(:mod:`actuator_selection.sizing.motion.figures`' ``_piece_terms``).

Why floats: a one-model selection is a block of one case × one actuator, where each numpy
call costs its fixed overhead (a microsecond or more) for one number; on floats the same
formulas cost a few Python operations. The same IEEE operations in the same order on
doubles (no fused multiply-add, squares as ``x * x``, ``math.sqrt`` and ``np.sqrt``
correctly rounded) give the same results bit for bit. Where numpy, its floating-point
errors ignored, gives ±∞ or NaN and Python's floats raise (a division by zero, the root
of a negative number), :data:`FLOAT_MATH` gives numpy's result (:func:`float_divide`,
:func:`float_sqrt`); the tests pin the two to each other on such inputs.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from actuator_selection.sizing.checks import FLOAT_OPS


def float_divide(a: float, b: float) -> float:
    """``a / b`` as numpy divides (its errors ignored): ±∞ for a non-zero ``a`` over a
    signed zero, NaN for 0/0 or NaN/0, where Python raises ``ZeroDivisionError``."""
    if b:  # non-zero, or NaN (truthy): Python's quotient is the IEEE one
        return a / b
    if a != a or a == 0.0:
        return math.nan
    return math.copysign(math.inf, a) * math.copysign(1.0, b)


def float_sqrt(x: float) -> float:
    """√x as ``np.sqrt`` computes it: NaN below zero (where ``math.sqrt`` raises), −0.0
    for −0.0, NaN for NaN."""
    return math.sqrt(x) if x >= 0.0 else x if x != x else math.nan


def float_maximum(a: float, b: float) -> float:
    """``np.maximum`` on two floats: NaN if either is, else the larger, ``b`` on a tie
    (``np.maximum(0.0, -0.0)`` is −0.0)."""
    return a if a > b or a != a else b


@dataclass(frozen=True, slots=True)
class Math:
    """The operations the block's formulas need beyond arithmetic, comparison and
    ``abs``: on arrays (:data:`ARRAY_MATH`) or on one cell's floats (:data:`FLOAT_MATH`)."""

    where: Callable[[Any, Any, Any], Any]
    maximum: Callable[[Any, Any], Any]
    sqrt: Callable[[Any], Any]
    divide: Callable[[Any, Any], Any]
    isnan: Callable[[Any], Any]


ARRAY_MATH = Math(
    where=np.where, maximum=np.maximum, sqrt=np.sqrt, divide=np.divide, isnan=np.isnan
)
"""On numpy arrays, called with numpy's floating-point errors ignored."""

FLOAT_MATH = Math(
    where=FLOAT_OPS.where,
    maximum=float_maximum,
    sqrt=float_sqrt,
    divide=float_divide,
    isnan=math.isnan,
)
"""On Python floats, with numpy's results where Python would raise."""


def mean_square(t0: Any, t1: Any, constant: Any, m: Math) -> Any:
    """A piece's mean T² from its end torques ``t0``, ``t1``
    (:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm`): T_a² where the
    torque is ``constant``, else (T_a² + T_a·T_b + T_b²)/3."""
    return m.where(constant, t0 * t0, (t0 * t0 + t0 * t1 + t1 * t1) / 3.0)


def heated_square(square: Any, slope: Any, speed: Any, m: Math) -> Any:
    """A piece's mean T² as the winding's heating counts it: (√m + k_T·K_INL·|n̄|)² where
    the ``slope`` k_T·K_INL is published, else m; ``speed`` the piece's mean |n|."""
    torque = m.sqrt(square) + slope * speed
    return m.where(m.isnan(slope), square, torque * torque)


def gear_weight(start_rpm: Any, end_rpm: Any, duration: Any) -> Any:
    """A piece's weight in the gear's T_av: its mean |n| times its duration."""
    return (abs(start_rpm) + abs(end_rpm)) / 2.0 * duration


def faster(peak: Any, mean: Any, m: Math) -> Any:
    """The speed the heating follows: its peak, never below n_av."""
    return m.where(peak > mean, peak, mean)
