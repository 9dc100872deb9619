"""Shared pieces of the API contract: strict models and the stated physical bounds.

Bounds reject magnitudes that no servo-actuator application has, so that absurd
input gets a clear 422 instead of overflowing a calculation. They are generous:
the largest catalogue actuator delivers under 2 kNm at under 300 rpm.
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict

MAX_SPEED_RPM = 100_000.0
"""n_2 bound [rpm]: ten times the fastest servo motor shaft."""
MAX_TORQUE_NM = 1_000_000.0
"""Torque bound [Nm]: 500 times the largest catalogue actuator's peak torque."""
MAX_INERTIA_KGM2 = 1_000_000.0
"""Inertia bound [kgm²]: a 100 t ring of 4.5 m radius."""
MIN_RAMP_S = 1e-4
"""Shortest t_1, t_3 [s]: 0.1 ms, below a servo controller's current-loop cycle times 2."""
MAX_TIME_S = 86_400.0
"""Longest single phase of a cycle [s]: one day."""
MAX_MASS_KG = 1_000_000.0
"""Moved mass bound [kg]: 1000 t."""
MAX_LENGTH_M = 100.0
"""Bound for leads, diameters and radii [m]."""
MAX_FRICTION_COEFFICIENT = 10.0
"""μ bound [-]: dry rubber on rubber stays below 2."""


class StrictModel(BaseModel):
    """Unknown fields are errors (a typo must not silently drop a value); no NaN or ±∞."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False, frozen=True)


class ResponseModel(BaseModel):
    """Base of response bodies."""

    model_config = ConfigDict(frozen=True)
