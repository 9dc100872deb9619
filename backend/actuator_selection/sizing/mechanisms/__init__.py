"""Mechanisms resolved to the actuator output (issue "Real axes").

Each mechanism here gives one :class:`~actuator_selection.sizing.axis.AxisLoad`: the load
inertia J_L, the friction torque T_F, the signed gravity torque T_G and the efficiency η
at the shaft that drives it, with the factors that turn its load speed (mm/s for a linear
axis, rpm for a rotary one) into output rpm and its process force (N or Nm) into output
torque. :func:`with_transmission` puts a ratio (a gearbox or a belt reduction) between the
actuator and any of them.

The chapter's two mechanisms keep their equations (:mod:`~actuator_selection.sizing.loads`,
Eq. 515.4 and 515.6). The others follow from first principles, written once for every
linear axis: a mass moving at v [m/s] while the driving shaft turns at ω [rad/s] with
v = r·ω (r [m/rad]: P/2π for a screw, D/2 for a pulley, pinion, roller or drum) has

    kinetic energy  ½·m·v² = ½·(m·r²)·ω²         →  J = m·r²     (reflected inertia)
    power           F·v = (F·r)·ω                →  T = F·r      (reflected force)

so a weight m·g on an incline θ gives T_G = m·g·sin θ·r, guide friction μ·m·g·cos θ gives
T_F = μ·m·g·cos θ·r, and a process force of 1 N gives r Nm. The efficiency η is not
folded into these torques: :class:`~actuator_selection.sizing.axis.AxisLoad` applies it by
the direction of power flow, T = T_load/η when the actuator drives and T = T_load·η when
the load drives back, to friction, gravity, process and inertia torque alike (the
convention of the sizing tools engineers know, see :mod:`~actuator_selection.sizing.axis`).
Only the chapter's ball screw keeps Eq. 515.4, which divides T_F by η and so carries
η = 1 on.

Linear axes speak mm/s and N: ``speed_rpm_per_unit`` = 1/(1000·r·2π/60) output rpm per
mm/s, ``torque_nm_per_force_unit`` = r Nm per N. A counterweight hangs on a rope over a
pulley of its own (pulley and rope neglected) and moves as far as the load: it adds its
mass to the inertia and takes m_c·g·r from the gravity torque whatever the incline.
"""

from __future__ import annotations

from actuator_selection.sizing.mechanisms.ball_screw import (
    InclinedBallScrew,
    inclined_ball_screw_axis,
)
from actuator_selection.sizing.mechanisms.belt import BeltDrive, belt_axis
from actuator_selection.sizing.mechanisms.chapter import chapter_ball_screw_axis, rotary_table_axis
from actuator_selection.sizing.mechanisms.conveyor import Conveyor, conveyor_axis
from actuator_selection.sizing.mechanisms.hoist import Hoist, hoist_axis
from actuator_selection.sizing.mechanisms.linear import (
    MAX_INCLINE_DEG,
    MM_PER_M,
    mm_to_m,
    rpm_per_mm_per_s,
)
from actuator_selection.sizing.mechanisms.rack_pinion import RackPinion, rack_pinion_axis
from actuator_selection.sizing.mechanisms.transmission import Transmission, with_transmission

__all__ = [
    "MAX_INCLINE_DEG",
    "MM_PER_M",
    "BeltDrive",
    "Conveyor",
    "Hoist",
    "InclinedBallScrew",
    "RackPinion",
    "Transmission",
    "belt_axis",
    "chapter_ball_screw_axis",
    "conveyor_axis",
    "hoist_axis",
    "inclined_ball_screw_axis",
    "mm_to_m",
    "rack_pinion_axis",
    "rotary_table_axis",
    "rpm_per_mm_per_s",
    "with_transmission",
]
