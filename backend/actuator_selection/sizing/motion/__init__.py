"""Motion cycles as segments: several moves, reversals, dwells, S-curves (issue "Real axes").

The chapter's cycle (Fig. 516.2) is one trapezoid: accelerate in t_1, run for t_2, brake
in t_3, pause for t_p. Machines move in several steps, both ways, with jerk-limited
ramps, and hold weights at standstill. A :class:`Motion` is a closed list of
:class:`Segment` (each a duration with its start and end speed at the output, a share
of jerk-limited ramp, and a process torque) driving an
:class:`~actuator_selection.sizing.axis.AxisLoad`. The CHA manual sums the RMS torque
over n segments; so does this module:

    T_rms = √( Σ_k ∫ T_k(t)² dt / t_0 ),   n_av = Σ_k ∫ |n_k(t)| dt / t_0,

with the torque of each piece from :mod:`~actuator_selection.sizing.axis` (Eq. 514.1 with
the load's friction, gravity, process torque and efficiency). Within a piece the
acceleration is constant or varies linearly (a jerk ramp), so the torque varies linearly
and ∫T² dt = t·(T_a² + T_a·T_b + T_b²)/3 exactly.

The chapter's trapezoid is the shorthand :func:`trapezoid`: its four segments give the
chapter's T_1, T_2, T_3, n_av and ED operation for operation (Eq. 514.1, 514.3, 514.4),
and T_rms of Eq. 514.2 with squares taken as ``x * x``.

What the flowchart reads from a cycle, per actuator (J_A):

- ``accel_torque_nm`` T_1: of the torques at every piece's ends while the speed does not
  fall in magnitude (accelerating, running, standing), the one of largest magnitude,
  signed; in the trapezoid the chapter's T_1;
- ``decel_torque_nm`` T_3: the same over the braking pieces (speed falling in magnitude);
  0 where the cycle never brakes; in the trapezoid the chapter's T_3;
- ``constant_torque_nm`` T_2: the same over pieces at constant nonzero speed; None
  where the cycle has none; in the trapezoid T_L.

Worked example (Table 516.1 with the FHA-25C-50-L's J_A = 0.86 kgm²):

>>> from actuator_selection.sizing.axis import AxisLoad
>>> m = trapezoid(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0,
...               load=AxisLoad(inertia_kgm2=1.3, friction_torque_nm=5))
>>> profile = profile_of(m)
>>> t = profile.torques(0.86)
>>> round(t.accel_torque_nm, 2), round(t.decel_torque_nm, 2), round(t.rms_torque_nm, 2)
(95.48, -85.48, 35.57)
>>> round(profile.mean_speed_rpm, 2), round(profile.duty_cycle_percent, 2)
(6.15, 23.08)
"""

from __future__ import annotations

from actuator_selection.sizing.motion.figures import (
    TRAPEZOID_BRAKING,
    TRAPEZOID_CONSTANT,
    CycleFigures,
    PieceArrays,
    cycle_figures,
    figure_rows,
    figures_of,
    piece_arrays,
    profile_from,
    profile_of,
    trapezoid_piece_arrays,
    trapezoid_piece_floats,
    trapezoid_profile,
)
from actuator_selection.sizing.motion.profile import (
    CycleTorques,
    Profile,
    SegmentTorque,
    heating_gain,
    heating_gain_array,
    mean_abs_speed_rpm,
)
from actuator_selection.sizing.motion.segments import (
    MAX_SEGMENTS,
    BoolArray,
    FloatArray,
    Motion,
    Piece,
    Segment,
    pieces_of,
    trapezoid,
)

__all__ = [
    "MAX_SEGMENTS",
    "TRAPEZOID_BRAKING",
    "TRAPEZOID_CONSTANT",
    "BoolArray",
    "CycleFigures",
    "CycleTorques",
    "FloatArray",
    "Motion",
    "Piece",
    "PieceArrays",
    "Profile",
    "Segment",
    "SegmentTorque",
    "cycle_figures",
    "figure_rows",
    "figures_of",
    "heating_gain",
    "heating_gain_array",
    "mean_abs_speed_rpm",
    "piece_arrays",
    "pieces_of",
    "profile_from",
    "profile_of",
    "trapezoid",
    "trapezoid_piece_arrays",
    "trapezoid_piece_floats",
    "trapezoid_profile",
]
