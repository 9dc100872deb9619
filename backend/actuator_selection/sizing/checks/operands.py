"""What the rules compute from: :class:`Operands`, one name per quantity.

Two kinds of operand, each declared in one home:

- the catalogue's **published** values: a field of the registry
  (:mod:`actuator_selection.catalogue.fields`) with an ``operand`` is an operand under
  :attr:`~actuator_selection.catalogue.fields.CatalogueField.operand_name`
  (:data:`PUBLISHED`), NaN where not published: adding one is its declaration, this module
  does not change (docs/decisions/0027-operands-from-the-registry.md);
- what is **worked out**: the load case's and the cycle's quantities, the cycle's torques on
  each actuator, and the catalogue values derived from others, typed below
  (:class:`Computed`) beside their meaning.

The engine (:mod:`actuator_selection.sizing.engine`) builds them in one place
(:func:`~actuator_selection.sizing.engine.block.operands_of`), by name.

mypy sees :class:`Computed`'s fields typed; a published value (``q.max_speed_rpm``) is read
through ``__getattr__`` as :data:`Real`: its name is checked when the rule runs (every rule
runs in the tests) and against the registry by ``tests/sizing/test_operands.py``.

>>> "max_speed_rpm" in Operands._fields and "mean_speed_rpm" in Operands._fields
True
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Final, NamedTuple

from actuator_selection.catalogue.fields import OPERAND_FIELDS

Real = Any
"""A float64 array of the engine's (a float where one cell is worded)."""
Truth = Any
"""A bool array of the engine's (a bool where one cell is worded)."""


class Computed(NamedTuple):
    """The operands worked out: the load case, the cycle, the cycle's torques on each
    actuator, and the catalogue values derived from others.

    In the engine, case quantities are columns (cases × 1), catalogue values rows
    (actuators), cycle torques cases × actuators; one cell's are floats (the words of
    its checks). Unpublished catalogue values are NaN.
    """

    speed_rpm: Real
    """Load speed n_2 [rpm] (Table 516.1): the highest |speed| of the cycle."""
    load_inertia_kgm2: Real
    """Load moment of inertia J_L [kgm²]."""
    high_dynamics: Truth
    """Whether the application is highly dynamic (Table 515.1, footnote 1)."""
    mean_speed_rpm: Real
    """Average output speed n_av [rpm] (Eq. 514.3)."""
    accel_torque_nm: Real
    """Acceleration torque T_1 [Nm] (Eq. 514.1); NaN without J_A."""
    decel_torque_nm: Real
    """Deceleration torque T_3 [Nm] (Eq. 514.1), negative while braking; NaN without J_A."""
    rms_torque_nm: Real
    """RMS torque T_rms [Nm] (Eq. 514.2); NaN without J_A."""
    has_zone: Truth
    """Whether a continuous-duty zone is published (Fig. 517.1)."""
    zone_torque_nm: Real
    """The zone's edge at n_av [Nm]; NaN without a zone or beyond its last speed."""
    zone_max_speed_rpm: Real
    """The highest speed the zone covers [rpm]; NaN without a zone."""
    accel_torque_floor_nm: Real
    """The least T_1 over every J_A ≥ 0 [Nm] (:class:`~actuator_selection.sizing.cycle.
    TorqueFloors`): what fails without J_A."""
    decel_torque_floor_nm: Real
    """The least |T_3| over every J_A ≥ 0 [Nm]."""
    rms_torque_floor_nm: Real
    """The least T_rms over every J_A ≥ 0 [Nm]."""
    load_torque_nm: Real
    """The torque held at standstill [Nm]: |T_G| + T_F of the axis (for the chapter's load,
    T_L, taken as acting at standstill for the brake)."""
    decel_s: Real
    """Deceleration time t_3 [s] (Table 516.1), for the energy braking returns."""
    inductance_line_h: Real
    """Winding inductance line-to-line L [H]."""
    dc_bus_voltage_v: Real
    """The highest nominal DC bus voltage the actuator runs on (its Table 521.1 bus
    classes) [V]; NaN where no bus class is published."""
    radial_force_n: Real
    """External radial force F_r on the output flange [N]; NaN without an output load."""
    axial_force_n: Real
    """External axial force F_a [N]; NaN without an output load."""
    radial_lever_m: Real
    """L_r [m]: where F_r acts, from the output flange."""
    axial_lever_m: Real
    """L_a [m]: the distance of F_a from the axis."""
    load_factor: Real
    """f_w of the bearing life formula [-]."""
    static_safety_min: Real
    """The least static safety factor f_s the application needs [-]."""
    required_life_h: Real
    """The bearing life L_10 the application needs [h]; NaN where not asked."""
    swing_deg: Real
    """The cycle's swing [°] (:func:`~actuator_selection.sizing.bearing.swing_deg`); NaN
    without an output load (the output bearing is not checked)."""
    bearing_life_exponent: Real
    """Life exponent B of the output bearing's type: 3 for a ball, 10/3 for a roller
    bearing (:func:`~actuator_selection.sizing.bearing.life_exponent`); NaN where the type is
    not published."""
    cycle_s: Real
    """Cycle time t_0 [s] (Table 516.1: t_1 + t_2 + t_3 + t_p)."""
    thermal_time_constant_s: Real
    """The winding's thermal time constant τ_th [s]: the catalogue's, else the
    application's, else :data:`~actuator_selection.sizing.thermal.
    DEFAULT_THERMAL_TIME_CONSTANT_S`."""
    thermal_time_constant_assumed: Truth
    """Whether τ_th is that assumed default (neither catalogue nor application gives one)."""
    thermal_torque_nm: Real
    """The peak of the winding's heating over the repeating cycle as a torque, √max x [Nm]
    (:meth:`~actuator_selection.sizing.motion.Profile.thermal_torque_nm`); NaN without J_A."""
    thermal_speed_rpm: Real
    """n_th: the speed the winding's speed-dependent heating follows, at its peak over the
    repeating cycle, never below n_av [rpm] (:meth:`~actuator_selection.sizing.motion.
    Profile.thermal_speed_rpm`, with τ_th as for :attr:`thermal_torque_nm`)."""
    no_load_torque_slope_nm_per_rpm: Real
    """k_T·K_INL [Nm/rpm]: the torque that the speed-dependent no-load current K_INL·n of
    Eq. 522.2 takes from the continuous stall current, per rpm (Eq. 522.3); K_INL at
    80 °C where published (the warm actuator of continuous duty), else at 30 °C; NaN
    where k_T or K_INL is not published (:func:`no_load_torque_slope`)."""
    gear_torque_cube_nm3: Real
    """Σ|n_i|·t_i·|T_i|³ / Σ|n_i|·t_i [Nm³]: the cube of the gear's average output torque
    T_av (a piece at its mean |n|, a ramp at n/2, a held pause weighing zero; |T_i| the
    larger of its ends' magnitudes); NaN without J_A or where the cycle does not move."""
    gear_required_life_h: Real
    """The wave generator life the application needs [h]; NaN where not asked."""
    momentary_torque_nm: Real
    """A momentary peak torque at the output [Nm]; NaN where not asked."""
    momentary_count: Real
    """How often it occurs [-]; NaN where not asked."""
    min_natural_frequency_hz: Real
    """The least natural frequency the application needs [Hz]; NaN where not asked."""
    brake_safety_factor: Real
    """S of the brake's holding check [-]."""
    emergency_stops: Real
    """Emergency stops expected over the life [-]; NaN where not asked."""
    drop_torque_nm: Real
    """The torque that turns the output while the brake closes [Nm]: the axis's |T_G|;
    NaN for the chapter's shorthand (then :attr:`load_torque_nm`, its T_L)."""
    travel_mm_per_rad: Real
    """The load's travel per radian of the output [mm/rad] of a linear axis; NaN for a
    rotary load."""
    gear_life_basis: Real
    """10 where L_n is an L_10, 50 where an L_50; NaN where not published."""


PUBLISHED: Final = tuple(name for f in OPERAND_FIELDS if (name := f.operand_name) is not None)
"""The catalogue's values the rules read as published, by operand name (the registry's
fields with an ``operand``, in the registry's order)."""

if TYPE_CHECKING:

    class Operands(Computed):
        """What the rules compute from (:class:`Computed`, then :data:`PUBLISHED`)."""

        def __getattr__(self, name: str) -> Real:
            """A published catalogue value by its operand name (:data:`PUBLISHED`)."""

        def _replace(self, **changes: Real) -> Operands:
            """A copy with ``changes``, by name (published values too)."""

else:
    Operands = NamedTuple(
        "Operands", [*((name, Any) for name in Computed._fields), *((n, Any) for n in PUBLISHED)]
    )
    Operands.__doc__ = """What the rules compute from: the worked-out operands
    (:class:`Computed`), then the catalogue's published values (:data:`PUBLISHED`).

    Immutable like the frozen dataclasses of the core; a named tuple, so that one
    cell's operands are cut from the arrays by position (:meth:`_make`)."""
    Operands.__module__ = __name__
