"""The engine's array types, and the codes its arrays hold for statuses and verdicts."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import numpy.typing as npt

from actuator_selection.sizing.candidates import Verdict
from actuator_selection.sizing.checks import Status

FloatArray = npt.NDArray[np.float64]
BoolArray = npt.NDArray[np.bool_]
CodeArray = npt.NDArray[np.int8]
IndexArray = npt.NDArray[np.intp]

STATUS_BY_CODE = (Status.NOT_APPLICABLE, Status.PASS, Status.WARN, Status.NO_DATA, Status.FAIL)
"""Status codes of :attr:`BatchEvaluation.statuses`, ordered so that the largest code of
a candidate's checks decides its verdict (any fail, else any no data); a check that does
not apply is below every other, so it never decides a verdict."""

VERDICT_BY_CODE = (Verdict.SUITABLE, Verdict.UNCONFIRMED, Verdict.UNSUITABLE)
"""Verdict codes of :attr:`BatchEvaluation.verdicts`, in ranking order."""

NOT_APPLICABLE, PASS, WARN, NO_DATA, FAIL = (np.int8(c) for c in range(5))


def optional(values: Sequence[float | None]) -> FloatArray:
    """A column of floats, NaN for None (a value the catalogue does not publish)."""
    return np.array([math.nan if v is None else v for v in values], dtype=np.float64)
