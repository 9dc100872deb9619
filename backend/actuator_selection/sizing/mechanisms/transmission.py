"""A ratio (a gearbox or a belt reduction) between the actuator and any mechanism."""

from __future__ import annotations

from dataclasses import dataclass

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.loads import _check, _check_result, _square
from actuator_selection.sizing.mechanisms.linear import _check_efficiency, _nonnegative

# --- a ratio between the actuator and the mechanism ---------------------------------------


@dataclass(frozen=True, slots=True, kw_only=True)
class Transmission:
    """A gearbox or belt reduction between the actuator output and a mechanism.

    Parameters
    ----------
    ratio
        i [-], > 0: actuator output speed over mechanism shaft speed (i > 1 reduces).
    inertia_kgm2
        J_tr [kgm²], ≥ 0, of the transmission referred to the actuator side.
    efficiency
        η_tr [-], 0 < η ≤ 1.
    """

    ratio: float
    inertia_kgm2: float = 0.0
    efficiency: float = 1.0

    def __post_init__(self) -> None:
        _check("ratio", self.ratio, positive=True, rule=N_("output speed over mechanism speed"))
        _nonnegative("inertia_kgm2", self.inertia_kgm2, N_("a moment of inertia"))
        _check_efficiency("efficiency", self.efficiency, what=N_("transmission"))


def with_transmission(load: AxisLoad, transmission: Transmission) -> AxisLoad:
    """``load`` seen through a ratio i (first principles: ω_out = i·ω_mech, P = T·ω).

    J_L = J_tr + J_mech/i²,  T_F = T_F,mech/i,  T_G = T_G,mech/i,
    speed factor × i, force factor / i,  η = η_tr·η_mech.

    One η by power flow for the whole chain is the vendor convention of
    :mod:`~actuator_selection.sizing.axis`; it applies η_tr to J_tr·α as well (on the safe
    side by J_tr·α·(1/η_tr − 1) while driving).

    The vertical belt axis of :func:`belt_axis` behind a 5:1 belt reduction (0.0001 kgm²,
    η 0.95): J_L = 0.0001 + 0.003125/25 = 0.000225 kgm², T_G = 1.22625/5 = 0.24525 Nm:

    >>> from actuator_selection.sizing.mechanisms.belt import BeltDrive, belt_axis
    >>> belt = belt_axis(BeltDrive(mass_kg=5, pulley_diameter_m=0.05,
    ...                            friction_coefficient=0.1, efficiency=0.9, incline_deg=90))
    >>> axis = with_transmission(belt, Transmission(ratio=5, inertia_kgm2=0.0001,
    ...                                             efficiency=0.95))
    >>> round(axis.inertia_kgm2, 7), round(axis.gravity_torque_nm, 5), round(axis.efficiency, 3)
    (0.000225, 0.24525, 0.855)
    >>> round(axis.speed_rpm_per_unit, 6)  # 5·60/(2π·25)
    1.909859
    """
    i = transmission.ratio
    i_squared = _square(i)
    if i_squared == 0:
        raise InvalidInputError("ratio", code="ratio_too_small")
    reflected = load.inertia_kgm2 / i_squared
    inertia = transmission.inertia_kgm2 + reflected
    friction = load.friction_torque_nm / i
    gravity = load.gravity_torque_nm / i
    speed = load.speed_rpm_per_unit * i
    force = load.torque_nm_per_force_unit / i
    efficiency = transmission.efficiency * load.efficiency
    for value, what in (
        (inertia, "J_L = J_tr + J/i²"),
        (friction, "T_F/i"),
        (gravity, "T_G/i"),
        (speed, N_("the speed factor × i")),
        (force, N_("the force factor / i")),
    ):
        _check_result("ratio", value, what=what)
    for before, after in (
        (load.inertia_kgm2, reflected),
        (load.friction_torque_nm, friction),
        (load.gravity_torque_nm, gravity),
        (load.torque_nm_per_force_unit, force),
    ):
        if before != 0 and after == 0:
            raise InvalidInputError("ratio", code="ratio_too_large")
    if efficiency == 0:
        raise InvalidInputError("efficiency", code="efficiency_product_zero")
    return AxisLoad(
        inertia_kgm2=inertia,
        friction_torque_nm=friction,
        gravity_torque_nm=gravity,
        efficiency=efficiency,
        speed_rpm_per_unit=speed,
        torque_nm_per_force_unit=force,
        speed_unit=load.speed_unit,
        force_unit=load.force_unit,
    )
