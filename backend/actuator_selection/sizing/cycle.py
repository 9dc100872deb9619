"""Torques, RMS torque, mean speed and duty cycle of a motion cycle (Eq. 514.1–514.4).

The chapter's equations as it prints them, for its one cycle. The flowchart computes
every cycle, this one included, as segments (:mod:`actuator_selection.sizing.motion`);
these functions stay as the chapter's own statement of the numbers, and the tests hold
the segment flowchart to them operation for operation (tests/sizing/test_motion.py).
:class:`SpeedPattern` and :class:`Load` are the chapter's shorthand for a load case.

The speed pattern of Fig. 516.2: accelerate from standstill to the load speed n_2
in t_1, run at n_2 for t_2, brake to standstill in t_3, pause for t_p. All values
refer to the output shaft of the actuator (chapter, note under Table 516.1).

Worked example of the chapter (Table 516.1 with the FHA-25C-50-L of Table 516.3):

>>> pattern = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
>>> t = cycle_torques(pattern=pattern, load=Load(torque_nm=5, inertia_kgm2=1.3),
...                   actuator_inertia_kgm2=0.86)
>>> round(t.accel_torque_nm, 2), round(t.decel_torque_nm, 2), round(t.rms_torque_nm, 2)
(95.48, -85.48, 35.57)
>>> round(mean_speed_rpm(pattern), 2), round(duty_cycle_percent(pattern), 2)
(6.15, 23.08)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.motion import CycleTorques, profile_of, trapezoid
from actuator_selection.sizing.units import rpm_to_rad_per_s


def _require_finite(field: str, value: float) -> None:
    if not math.isfinite(value):
        raise InvalidInputError(field, code="not_finite", params={"value": value})


def _require_finite_result(field: str, value: float, *, what: str) -> None:
    """Finite inputs can still overflow a product: a 422 naming the input, never ±∞ or a 500.

    (PostgreSQL's JSON refuses ``Infinity``; SQLite would store it and answer null.)
    """
    if not math.isfinite(value):
        raise InvalidInputError(field, code="result_overflow", params={"what": what})


@dataclass(frozen=True, slots=True, kw_only=True)
class SpeedPattern:
    """The cycle of Fig. 516.2 at the actuator output.

    Parameters
    ----------
    speed_rpm
        Load speed n_2 [rpm], > 0.
    accel_s
        Acceleration time t_1 [s], > 0 (it divides Eq. 514.1).
    constant_s
        Time at constant speed t_2 [s], ≥ 0.
    decel_s
        Deceleration time t_3 [s], > 0 (the braking torque divides by it).
    pause_s
        Standstill time t_p [s], ≥ 0.
    """

    speed_rpm: float
    accel_s: float
    constant_s: float
    decel_s: float
    pause_s: float

    def __post_init__(self) -> None:
        if (
            0.0 < self.speed_rpm < math.inf
            and 0.0 < self.accel_s < math.inf
            and 0.0 <= self.constant_s < math.inf
            and 0.0 < self.decel_s < math.inf
            and 0.0 <= self.pause_s < math.inf
        ):
            return  # every rule below holds (NaN fails each comparison)
        for name in ("speed_rpm", "accel_s", "constant_s", "decel_s", "pause_s"):
            _require_finite(name, getattr(self, name))
        if self.speed_rpm <= 0:
            raise InvalidInputError(
                "speed_rpm",
                code="must_be_positive",
                params={"rule": N_("n_2 is the speed the load reaches")},
            )
        if self.accel_s <= 0:
            raise InvalidInputError(
                "accel_s",
                code="must_be_positive",
                params={"rule": N_("the acceleration time t_1 divides Eq. 514.1")},
            )
        if self.decel_s <= 0:
            raise InvalidInputError(
                "decel_s",
                code="must_be_positive",
                params={"rule": N_("the deceleration time t_3 divides the braking torque")},
            )
        if self.constant_s < 0:
            raise InvalidInputError(
                "constant_s", code="must_be_nonnegative", params={"rule": N_("t_2 is a duration")}
            )
        if self.pause_s < 0:
            raise InvalidInputError(
                "pause_s", code="must_be_nonnegative", params={"rule": N_("t_p is a duration")}
            )

    @property
    def moving_s(self) -> float:
        """Time in motion t_1 + t_2 + t_3 [s]."""
        return self.accel_s + self.constant_s + self.decel_s

    @property
    def cycle_s(self) -> float:
        """Total cycle time t_0 = t_1 + t_2 + t_3 + t_p [s] (Table 516.1)."""
        return self.moving_s + self.pause_s


@dataclass(frozen=True, slots=True, kw_only=True)
class Load:
    """The load at the actuator output.

    Parameters
    ----------
    torque_nm
        Load torque T_L [Nm], ≥ 0: a friction-like torque that opposes the motion.
    inertia_kgm2
        Load moment of inertia J_L [kgm²], ≥ 0.
    """

    torque_nm: float
    inertia_kgm2: float

    def __post_init__(self) -> None:
        if 0.0 <= self.torque_nm < math.inf and 0.0 <= self.inertia_kgm2 < math.inf:
            return  # every rule below holds (NaN fails each comparison)
        _require_finite("torque_nm", self.torque_nm)
        _require_finite("inertia_kgm2", self.inertia_kgm2)
        if self.torque_nm < 0:
            raise InvalidInputError(
                "torque_nm",
                code="must_be_nonnegative",
                params={
                    "rule": N_("Eq. 514.1 treats T_L as a load torque that opposes the motion")
                },
            )
        if self.inertia_kgm2 < 0:
            raise InvalidInputError(
                "inertia_kgm2",
                code="must_be_nonnegative",
                params={"rule": N_("a moment of inertia")},
            )


def acceleration_torque_nm(
    *,
    load_torque_nm: float,
    actuator_inertia_kgm2: float,
    load_inertia_kgm2: float,
    speed_rpm: float,
    time_s: float,
) -> float:
    """Torque to change speed by n_2 in ``time_s`` against T_L (Eq. 514.1, first line).

    T_1 = T_L + (2π/60)·(J_A + J_L)·n_2 / t_1

    Parameters
    ----------
    load_torque_nm
        T_L [Nm].
    actuator_inertia_kgm2
        J_A [kgm²], the actuator's own inertia at the output.
    load_inertia_kgm2
        J_L [kgm²].
    speed_rpm
        n_2 [rpm].
    time_s
        The time of the speed change [s], t_1.

    >>> round(acceleration_torque_nm(load_torque_nm=5, actuator_inertia_kgm2=0.86,
    ...                              load_inertia_kgm2=1.3, speed_rpm=40, time_s=0.1), 3)
    95.478
    """
    angular_acceleration = rpm_to_rad_per_s(speed_rpm) / time_s
    return load_torque_nm + (actuator_inertia_kgm2 + load_inertia_kgm2) * angular_acceleration


def deceleration_torque_nm(
    *,
    load_torque_nm: float,
    actuator_inertia_kgm2: float,
    load_inertia_kgm2: float,
    speed_rpm: float,
    time_s: float,
) -> float:
    """Torque to brake from n_2 to standstill in t_3 (Eq. 514.1, third line, corrected).

    The chapter prints ``T_3 = T_L · (T_1 − T_L)``; the manufacturer's flowchart
    (CHA manual p. 64) and the physics give T_3 = T_L − (T_1 − T_L): the load
    torque helps to brake, the inertia torque reverses. That form assumes t_3 = t_1,
    as in the chapter's example. For any t_3 the same dynamics give

    T_3 = T_L − (2π/60)·(J_A + J_L)·n_2 / t_3,

    which equals the chapter's form when t_3 = t_1; this function uses it so that
    an asymmetric cycle is not silently sized with the acceleration time.

    >>> round(deceleration_torque_nm(load_torque_nm=5, actuator_inertia_kgm2=0.86,
    ...                              load_inertia_kgm2=1.3, speed_rpm=40, time_s=0.1), 3)
    -85.478
    """
    angular_deceleration = rpm_to_rad_per_s(speed_rpm) / time_s
    return load_torque_nm - (actuator_inertia_kgm2 + load_inertia_kgm2) * angular_deceleration


def rms_torque_nm(
    *,
    accel_torque_nm: float,
    constant_torque_nm: float,
    decel_torque_nm: float,
    pattern: SpeedPattern,
) -> float:
    """RMS torque over the whole cycle, zero torque in the pause (Eq. 514.2).

    T_rms = √((T_1²·t_1 + T_2²·t_2 + T_3²·t_3) / (t_1 + t_2 + t_3 + t_p))

    >>> p = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
    >>> round(rms_torque_nm(accel_torque_nm=95.478, constant_torque_nm=5,
    ...                     decel_torque_nm=-85.478, pattern=p), 2)
    35.57
    """
    energy = (
        accel_torque_nm * accel_torque_nm * pattern.accel_s
        + constant_torque_nm * constant_torque_nm * pattern.constant_s
        + decel_torque_nm * decel_torque_nm * pattern.decel_s
    )
    rms = math.sqrt(energy / pattern.cycle_s)
    _require_finite_result("load", rms, what="T_rms (Eq. 514.2)")
    return rms


def mean_speed_rpm(pattern: SpeedPattern) -> float:
    """Average output speed over the cycle n_av [rpm] (Eq. 514.3).

    n_av = (n_2/2·t_1 + n_2·t_2 + n_2/2·t_3) / (t_1 + t_2 + t_3 + t_p)

    >>> round(mean_speed_rpm(SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1,
    ...                                   decel_s=0.1, pause_s=1.0)), 4)
    6.1538
    """
    n_2 = pattern.speed_rpm
    travel = n_2 / 2 * pattern.accel_s + n_2 * pattern.constant_s + n_2 / 2 * pattern.decel_s
    mean = travel / pattern.cycle_s
    _require_finite_result("speed_rpm", mean, what="n_av (Eq. 514.3)")
    return mean


def duty_cycle_percent(pattern: SpeedPattern) -> float:
    """Share of the cycle in motion ED [%] (Eq. 514.4).

    >>> round(duty_cycle_percent(SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1,
    ...                                       decel_s=0.1, pause_s=1.0)), 2)
    23.08
    """
    return pattern.moving_s / pattern.cycle_s * 100.0


def cycle_torques(
    *, pattern: SpeedPattern, load: Load, actuator_inertia_kgm2: float
) -> CycleTorques:
    """T_1, T_2, T_3 and T_rms of one actuator driving ``load`` through ``pattern``
    (Eq. 514.1 and 514.2; T_2 = T_L): the pattern as the chapter's trapezoid of segments
    (:func:`~actuator_selection.sizing.motion.trapezoid`), whose torques the flowchart uses.

    >>> p = SpeedPattern(speed_rpm=40, accel_s=0.1, constant_s=0.1, decel_s=0.1, pause_s=1.0)
    >>> t = cycle_torques(pattern=p, load=Load(torque_nm=5, inertia_kgm2=1.3),
    ...                   actuator_inertia_kgm2=0.86)
    >>> t.accel_torque_nm == acceleration_torque_nm(load_torque_nm=5,
    ...     actuator_inertia_kgm2=0.86, load_inertia_kgm2=1.3, speed_rpm=40, time_s=0.1)
    True
    """
    motion = trapezoid(
        speed_rpm=pattern.speed_rpm,
        accel_s=pattern.accel_s,
        constant_s=pattern.constant_s,
        decel_s=pattern.decel_s,
        pause_s=pattern.pause_s,
        load=AxisLoad(inertia_kgm2=load.inertia_kgm2, friction_torque_nm=load.torque_nm),
    )
    return profile_of(motion).torques(actuator_inertia_kgm2)
