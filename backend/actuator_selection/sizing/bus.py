"""Several axes on one DC bus: each axis's power over the machine cycle, their sum, and
what absorbs the energy the axes give back (issue 31, part 2).

Per axis, over its cycle (:mod:`~actuator_selection.sizing.motion` pieces, the torque of
Eq. 514.1 with the actuator's own inertia J_A, as the flowchart takes it):

- mechanical power at the output, P_mech = T·ω (ω = 2π·n/60, both signed in the same
  sense, so P_mech < 0 where the load drives the actuator);
- the no-load loss: Eq. 522.2 gives the current the actuator draws at no load,
  I_NLR = I_NLS + K_INL·|n|, and Eq. 522.3, T = k_T·(I − I_NLR), says that this current
  makes no output torque: it covers the actuator's own friction and iron losses, a torque
  T_NL = k_T·I_NLR that opposes the motion. Its power P_NL = k_T·I_NLR·|ω| ≥ 0;
- the winding current from the torque, Eq. 522.3 solved for I: the motor makes the output
  torque and the no-load torque, T_m = T + sgn(n)·k_T·I_NLR, so I = |T_m|/k_T (at
  standstill, I = |T|/k_T: nothing turns, so the starting current I_NLS has no work to
  do; the holding current is taken as the torque's);
- the copper loss from that current and the catalogue's line-to-line resistance,
  P_cu = 1.5·R_LL·I² (below);
- electrical power at the drive's DC side, P_el = P_mech + P_NL + P_cu: motoring where
  P_el > 0, regenerating where P_el < 0. The inverter's own losses are not modelled (no
  public data): the bus sees the motor's terminals.

Copper loss from a line-to-line resistance. A catalogue gives R between two terminals,
R_LL, and the current I per line (A rms). In a star winding two phases lie between two
terminals, R_LL = 2·R_ph, and the phase current is the line current, so
P_cu = 3·R_ph·I² = 1.5·R_LL·I². In a delta winding the terminal sees one phase parallel
to the other two, R_LL = R_ph·2R_ph/(3R_ph) = (2/3)·R_ph, and the phase current is
I/√3, so P_cu = 3·R_ph·I²/3 = R_ph·I² = 1.5·R_LL·I² again: the formula holds whatever
the connection. It is the stator winding loss of IEC 60034-2-1:2014 (Rotating electrical
machines, Part 2-1: losses and efficiency from tests), P_s = 1.5·I²·R_ll. R is taken at
the catalogue's temperature (the winding's rise is not modelled).

Within a piece T is linear in time and n is linear or quadratic (a jerk ramp), and n
keeps its sign, so every power above is a polynomial in time of degree ≤ 4 (I² = T_m²/k_T²
needs no absolute value). The bus sums the axes, each shifted by its offset, exactly at
the union of all piece boundaries, and integrates, bounds and splits each stretch
exactly (roots of the polynomial), not on a grid.

What absorbs the energy fed back (regeneration):

- the bus capacitance takes E = ½·C·(U_max² − U_nom²) per pulse, the energy between the
  nominal bus voltage and the highest the drives allow (the capacitor's energy ½·C·U²);
  U_nom of the bus class (Table 521.1); C and U_max from the drives' data sheets, which
  the catalogue does not hold: without them the result says "no data";
- a braking resistor: the peak power it must take (the largest regenerative power), its
  continuous power (the regenerative energy per cycle over the cycle time), the energy
  of one pulse, and its resistance: at the chopper's switching voltage U_ch the resistor
  takes P = U_ch²/R, so R ≤ U_ch²/P_peak (Ohm's law); the lower end is the chopper's
  minimum resistance from the drive's data sheet.

Random phasing (axes not synchronised):

- worst-case alignment: max over all offsets of the peak of Σ P_i(t − o_i) is Σ max P_i
  exactly (each axis's own peak can be brought to one instant), and the same for the
  regenerative peak; a bound that a machine may reach, stated as such;
- a statistical figure: at a random instant with independent phases uniform over the
  cycle, the bus power is a sum of independent terms, so its mean is Σ μ_i and its
  variance Σ σ_i² (exact, from the polynomials); μ + 3σ is its 99.87 % quantile under the
  normal approximation (central limit theorem), a figure for the supply, not a bound.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from numpy.polynomial import Polynomial

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError, MissingDataError
from actuator_selection.sizing.electrical import line_resistance_from_phase_ohm
from actuator_selection.sizing.motion import Piece, Profile
from actuator_selection.sizing.units import RAD_PER_S_PER_RPM

COPPER_LOSS_FACTOR = 1.5
"""P_cu = 1.5·R_LL·I² for a three-phase winding, star or delta (module docstring,
IEC 60034-2-1:2014 stator winding loss P_s = 1.5·I²·R_ll)."""

SIGMAS = 3.0
"""The statistical figure μ + 3σ (module docstring)."""

_ROOT_IMAG = 1e-9
"""Imaginary part below which a root of a stretch's polynomial counts as real (relative)."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Motor:
    """What the power of one axis needs of its actuator (catalogue values at the output).

    ``torque_constant_nm_per_a`` k_T and ``resistance_line_ohm`` R_LL give the copper loss,
    ``no_load_starting_current_a`` I_NLS and ``no_load_current_constant_a_per_rpm`` K_INL
    the no-load loss (Eq. 522.2); where one is not published that loss is left out and the
    axis says so (``copper_loss_published``, ``no_load_loss_published``).
    """

    inertia_kgm2: float
    torque_constant_nm_per_a: float | None = None
    resistance_line_ohm: float | None = None
    no_load_starting_current_a: float | None = None
    no_load_current_constant_a_per_rpm: float | None = None

    @property
    def copper_loss_published(self) -> bool:
        return self.torque_constant_nm_per_a is not None and self.resistance_line_ohm is not None

    @property
    def no_load_loss_published(self) -> bool:
        return (
            self.torque_constant_nm_per_a is not None
            and self.no_load_starting_current_a is not None
            and self.no_load_current_constant_a_per_rpm is not None
        )


def motor_of(actuator: Actuator) -> Motor:
    """The :class:`Motor` of a catalogue actuator; "no data" (422) where J_A is not published (its
    torque over the cycle, Eq. 514.1, needs it).

    R_LL is the catalogue's line-to-line value, else 2·R_ph from the phase value
    (:func:`~actuator_selection.sizing.electrical.line_resistance_from_phase_ohm`, a star
    winding); K_INL is the 80 °C value where published, else the 30 °C one: the power of a
    running machine is that of the warm actuator, as the continuous check takes it
    (:func:`~actuator_selection.sizing.electrical.no_load_torque_slope_nm_per_rpm`).
    """
    if actuator.inertia_kgm2 is None:
        raise MissingDataError(
            "model", code="no_inertia_for_power", params={"model": actuator.model}
        )
    r_line = actuator.resistance_line_ohm
    if r_line is None and actuator.resistance_phase_ohm is not None:
        r_line = line_resistance_from_phase_ohm(actuator.resistance_phase_ohm)
    k_80 = actuator.no_load_current_constant_80c_a_per_rpm
    return Motor(
        inertia_kgm2=actuator.inertia_kgm2,
        torque_constant_nm_per_a=actuator.torque_constant_nm_per_a,
        resistance_line_ohm=r_line,
        no_load_starting_current_a=actuator.no_load_starting_current_a,
        no_load_current_constant_a_per_rpm=(
            k_80 if k_80 is not None else actuator.no_load_current_constant_30c_a_per_rpm
        ),
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class PiecePower:
    """The powers of one piece as polynomials in the time τ ∈ [0, duration] from its start
    [W]; ``current`` the winding current's square I² [A²] (None without k_T)."""

    start_s: float
    duration_s: float
    mechanical: Polynomial
    no_load: Polynomial
    copper: Polynomial
    electrical: Polynomial


def _zero() -> Polynomial:
    return Polynomial([0.0])


def piece_power(piece: Piece, start_s: float, motor: Motor) -> PiecePower:
    """The powers of one piece (module docstring) as polynomials in τ."""
    d = piece.duration_s
    a0, a1 = piece.accel_start, piece.accel_end
    slope = (a1 - a0) / d if d > 0 else 0.0
    alpha = Polynomial([a0, slope])  # rad/s²
    omega = Polynomial([piece.start_rpm * RAD_PER_S_PER_RPM, a0, slope / 2.0])  # rad/s
    torque = piece.static_nm + (motor.inertia_kgm2 + piece.inertia_kgm2) * alpha  # Eq. 514.1
    mechanical = torque * omega
    s = piece.direction
    k_t = motor.torque_constant_nm_per_a
    no_load_torque = _zero()  # sgn(n)·k_T·I_NLR, opposing the motion (Eq. 522.2, 522.3)
    if motor.no_load_loss_published and s != 0:
        assert k_t is not None
        i_nls = motor.no_load_starting_current_a or 0.0
        k_inl = motor.no_load_current_constant_a_per_rpm or 0.0
        # |n| = s·n within a piece (the speed keeps its sign); n = ω/(2π/60)
        no_load_torque = s * k_t * (i_nls + k_inl * s * omega / RAD_PER_S_PER_RPM)
    no_load = no_load_torque * omega
    copper = _zero()
    if motor.copper_loss_published:
        assert k_t is not None
        assert motor.resistance_line_ohm is not None
        current = (torque + no_load_torque) / k_t  # Eq. 522.3 solved for I (signed)
        copper = COPPER_LOSS_FACTOR * motor.resistance_line_ohm * current * current
    return PiecePower(
        start_s=start_s,
        duration_s=d,
        mechanical=mechanical,
        no_load=no_load,
        copper=copper,
        electrical=mechanical + no_load + copper,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class Stretch:
    """A stretch of time on which a power is one polynomial in x = t − start [W]."""

    start_s: float
    duration_s: float
    power: Polynomial


def _real_roots_inside(p: Polynomial, length: float) -> list[float]:
    """The real roots of ``p`` strictly inside (0, length), sorted."""
    q = p.trim()
    if q.degree() < 1:
        return []
    scale = max(1.0, length)
    out = []
    for r in q.roots():
        real, imag = float(np.real(r)), float(np.imag(r))
        if abs(imag) <= _ROOT_IMAG * scale and 0.0 < real < length:
            out.append(real)
    return sorted(out)


def _integral(p: Polynomial, a: float, b: float) -> float:
    q = p.integ()
    return float(q(b) - q(a))


def _extremes(p: Polynomial, length: float) -> tuple[float, float]:
    """The least and the largest value of ``p`` on [0, length] (ends and stationary points)."""
    xs = [0.0, length, *_real_roots_inside(p.deriv(), length)]
    values = [float(p(x)) for x in xs]
    return min(values), max(values)


def _negative_parts(p: Polynomial, length: float) -> list[tuple[float, float, float]]:
    """The sub-intervals of [0, length] where ``p`` < 0, each as (start, end, ∫p) with ∫p < 0."""
    cuts = [0.0, *_real_roots_inside(p, length), length]
    out = []
    for a, b in itertools.pairwise(cuts):
        if b <= a:
            continue
        if p((a + b) / 2.0) < 0:
            out.append((a, b, _integral(p, a, b)))
    return out


@dataclass(frozen=True, slots=True, kw_only=True)
class PowerFigures:
    """Figures of one power over the cycle [W, J, s]."""

    cycle_s: float
    peak_w: float
    """The largest power drawn (motoring); ≤ 0 where it never draws."""
    mean_w: float
    """∫P dt/t_0: the net mean, what the supply gives when the regenerated energy is stored
    and used again."""
    mean_supply_w: float
    """∫max(P, 0) dt/t_0: what the supply gives when the regenerated energy is burnt."""
    energy_in_j: float
    """∫max(P, 0) dt per cycle."""
    regen_energy_j: float
    """∫max(−P, 0) dt per cycle: the energy fed back into the bus."""
    least_w: float
    """The least power over the cycle (negative where it regenerates)."""
    regen_peak_w: float
    """The largest power fed back (max of −P), 0 where none is."""
    regen_pulse_energy_j: float
    """The largest energy of one pulse of regeneration (a run of P < 0, around the cycle's
    end where it wraps), 0 where none is."""
    regen_pulses: int
    regen_pulse_energies_j: tuple[float, ...]
    """The energy of each pulse, in the order of the cycle."""
    variance_w2: float
    """Variance of P at a random instant of the cycle [W²]."""


def figures_of(stretches: Sequence[Stretch], cycle_s: float) -> PowerFigures:
    """The figures of a power given as consecutive stretches covering one cycle."""
    total = positive = square = 0.0
    peak, least = -math.inf, math.inf
    pulses: list[list[float]] = []  # [start, end, energy] of each run of P < 0
    for st in stretches:
        if st.duration_s <= 0:
            continue
        total += _integral(st.power, 0.0, st.duration_s)
        square += _integral(st.power * st.power, 0.0, st.duration_s)
        low, high = _extremes(st.power, st.duration_s)
        peak, least = max(peak, high), min(least, low)
        negative = 0.0
        for a, b, e in _negative_parts(st.power, st.duration_s):
            negative += e
            start, end = st.start_s + a, st.start_s + b
            if pulses and math.isclose(pulses[-1][1], start, rel_tol=0.0, abs_tol=1e-9 * cycle_s):
                pulses[-1][1] = end
                pulses[-1][2] += -e
            else:
                pulses.append([start, end, -e])
        positive += _integral(st.power, 0.0, st.duration_s) - negative
    if (
        len(pulses) > 1
        and math.isclose(pulses[0][0], 0.0, abs_tol=1e-9 * cycle_s)
        and math.isclose(pulses[-1][1], cycle_s, rel_tol=1e-12)
    ):  # a pulse across the cycle's end is one pulse
        pulses[0][2] += pulses[-1][2]
        pulses.pop()
    regen = positive - total
    mean = total / cycle_s
    return PowerFigures(
        cycle_s=cycle_s,
        peak_w=peak,
        mean_w=mean,
        mean_supply_w=positive / cycle_s,
        energy_in_j=positive,
        regen_energy_j=regen,
        least_w=least,
        regen_peak_w=max(-least, 0.0),
        regen_pulse_energy_j=max((p[2] for p in pulses), default=0.0),
        regen_pulses=len(pulses),
        regen_pulse_energies_j=tuple(p[2] for p in pulses),
        variance_w2=max(square / cycle_s - mean * mean, 0.0),
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class AxisPower:
    """The power of one axis over its cycle."""

    cycle_s: float
    pieces: tuple[PiecePower, ...]
    copper_loss_published: bool
    no_load_loss_published: bool

    @property
    def boundaries_s(self) -> tuple[float, ...]:
        """The times of the piece boundaries within the cycle (0 included, t_0 not)."""
        return tuple(p.start_s for p in self.pieces)

    def energies_j(self) -> dict[str, float]:
        """∫ over the cycle of each power: mechanical, no_load, copper, electrical [J]."""
        out = dict.fromkeys(("mechanical", "no_load", "copper", "electrical"), 0.0)
        for p in self.pieces:
            for name in out:
                out[name] += _integral(getattr(p, name), 0.0, p.duration_s)
        return out

    def stretches(self, what: str = "electrical") -> list[Stretch]:
        return [
            Stretch(start_s=p.start_s, duration_s=p.duration_s, power=getattr(p, what))
            for p in self.pieces
            if p.duration_s > 0
        ]

    def figures(self) -> PowerFigures:
        """The figures of the electrical power P_el."""
        return figures_of(self.stretches(), self.cycle_s)

    def at(self, local_s: float) -> PiecePower:
        """The piece that holds the cycle time ``local_s`` (0 ≤ local_s < t_0)."""
        best = self.pieces[0]
        for p in self.pieces:
            if p.duration_s > 0 and p.start_s <= local_s:
                best = p
        return best


def axis_power(profile: Profile, motor: Motor) -> AxisPower:
    """The powers of one axis over its cycle (module docstring)."""
    pieces, clock = [], 0.0
    for piece in profile.pieces:
        pieces.append(piece_power(piece, clock, motor))
        clock += piece.duration_s
    return AxisPower(
        cycle_s=profile.cycle_s,
        pieces=tuple(pieces),
        copper_loss_published=motor.copper_loss_published,
        no_load_loss_published=motor.no_load_loss_published,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class BusSample:
    """The bus and each axis on one stretch of the machine cycle."""

    start_s: float
    duration_s: float
    axes: tuple[Polynomial, ...]
    """Each axis's electrical power on the stretch, in x = t − start."""
    total: Polynomial


@dataclass(frozen=True, slots=True, kw_only=True)
class PhasingFigures:
    """Random phasing: the worst-case alignment and the statistical figure (module
    docstring)."""

    worst_peak_w: float
    worst_regen_peak_w: float
    mean_w: float
    std_w: float
    statistical_peak_w: float
    """μ + 3σ of the bus power at a random instant (normal approximation)."""
    statistical_regen_w: float
    """max(0, −(μ − 3σ)): the regenerative power at the same quantile."""


@dataclass(frozen=True, slots=True, kw_only=True)
class Bus:
    """Several axes on one bus, synchronised with their offsets."""

    cycle_s: float
    axes: tuple[AxisPower, ...]
    offsets_s: tuple[float, ...]
    stretches: tuple[BusSample, ...]
    figures: PowerFigures
    axis_figures: tuple[PowerFigures, ...]
    phasing: PhasingFigures


def _shift(p: Polynomial, by: float) -> Polynomial:
    """p(x + by) as a polynomial in x."""
    return p(Polynomial([by, 1.0])) if by != 0 else p


def machine_bus(axes: Sequence[AxisPower], offsets_s: Sequence[float]) -> Bus:
    """The bus of ``axes`` run synchronised on one machine cycle, axis k starting
    ``offsets_s[k]`` after the machine cycle does (module docstring).

    Every axis's cycle is the machine cycle t_0 (within 10⁻⁹ relative); the bus is
    sampled at the union of all piece boundaries, each shifted by its axis's offset
    modulo t_0, so that every axis is one polynomial on every stretch.
    """
    if not axes:
        raise InvalidInputError("axes", "a machine needs at least one axis")
    if len(offsets_s) != len(axes):
        raise InvalidInputError("offsets_s", "one offset per axis")
    cycle = axes[0].cycle_s
    for k, a in enumerate(axes):
        if not math.isclose(a.cycle_s, cycle, rel_tol=1e-9):
            raise InvalidInputError(
                f"axes.{k}.cycle",
                code="axis_cycle_differs",
                params={"cycle_s": round(a.cycle_s, 9), "machine_s": round(cycle, 9)},
            )
    for k, o in enumerate(offsets_s):
        if not math.isfinite(o) or o < 0:
            raise InvalidInputError(f"axes.{k}.offset_s", "must be a finite number ≥ 0")
    offsets = tuple(float(o) % cycle for o in offsets_s)
    tol = 1e-12 * cycle
    cuts = {0.0, cycle}
    for a, o in zip(axes, offsets, strict=True):
        for b in a.boundaries_s:
            cuts.add((b + o) % cycle)
    ordered = sorted(cuts)
    times = [ordered[0]]
    for t in ordered[1:]:
        if t - times[-1] > tol:
            times.append(t)
    times[-1] = cycle
    samples = []
    for start, end in itertools.pairwise(times):
        length = end - start
        mid = (start + end) / 2.0
        polys = []
        for a, o in zip(axes, offsets, strict=True):
            local_mid = (mid - o) % cycle
            piece = a.at(local_mid)
            # the stretch starts at local time local_mid − length/2 of the axis
            local_start = local_mid - length / 2.0
            polys.append(_shift(piece.electrical, local_start - piece.start_s))
        total = polys[0]
        for q in polys[1:]:
            total = total + q
        samples.append(BusSample(start_s=start, duration_s=length, axes=tuple(polys), total=total))
    stretches = [
        Stretch(start_s=s.start_s, duration_s=s.duration_s, power=s.total) for s in samples
    ]
    figures = figures_of(stretches, cycle)
    axis_figures = tuple(a.figures() for a in axes)
    return Bus(
        cycle_s=cycle,
        axes=tuple(axes),
        offsets_s=offsets,
        stretches=tuple(samples),
        figures=figures,
        axis_figures=axis_figures,
        phasing=phasing(axis_figures),
    )


def phasing(axis_figures: Sequence[PowerFigures]) -> PhasingFigures:
    """Random phasing from each axis's own figures (module docstring)."""
    mean = sum(f.mean_w for f in axis_figures)
    std = math.sqrt(sum(f.variance_w2 for f in axis_figures))
    worst_regen = -sum(f.least_w for f in axis_figures)
    return PhasingFigures(
        worst_peak_w=sum(f.peak_w for f in axis_figures),
        worst_regen_peak_w=max(worst_regen, 0.0),
        mean_w=mean,
        std_w=std,
        statistical_peak_w=mean + SIGMAS * std,
        statistical_regen_w=max(0.0, -(mean - SIGMAS * std)),
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class Capacitor:
    """What the bus capacitance absorbs per pulse, E = ½·C·(U_max² − U_nom²) [J]; None
    where C or U_max is not given (no data)."""

    capacitance_f: float | None
    nominal_voltage_v: float
    max_voltage_v: float | None
    energy_j: float | None
    absorbs_every_pulse: bool | None
    reference: str = "E = ½·C·(U_max² − U_nom²), the capacitor's energy ½·C·U²"


def capacitor(
    *,
    capacitance_f: float | None,
    nominal_voltage_v: float,
    max_voltage_v: float | None,
    pulse_energy_j: float,
) -> Capacitor:
    """The bus capacitance against the largest regenerative pulse."""
    if capacitance_f is None or max_voltage_v is None:
        return Capacitor(
            capacitance_f=capacitance_f,
            nominal_voltage_v=nominal_voltage_v,
            max_voltage_v=max_voltage_v,
            energy_j=None,
            absorbs_every_pulse=None,
        )
    if max_voltage_v <= nominal_voltage_v:
        raise InvalidInputError(
            "bus.max_voltage_v",
            code="bus_voltage_not_above_nominal",
            params={"nominal_v": nominal_voltage_v},
        )
    energy = 0.5 * capacitance_f * (max_voltage_v**2 - nominal_voltage_v**2)
    return Capacitor(
        capacitance_f=capacitance_f,
        nominal_voltage_v=nominal_voltage_v,
        max_voltage_v=max_voltage_v,
        energy_j=energy,
        absorbs_every_pulse=pulse_energy_j <= energy,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class BrakingResistor:
    """The braking resistor the regeneration needs (module docstring) [W, J, Ω]."""

    needed: bool
    peak_power_w: float
    continuous_power_w: float
    pulse_energy_j: float
    """The energy of the largest pulse that the resistor must take (less what the
    capacitance absorbs, where that is known)."""
    chopper_voltage_v: float | None
    max_resistance_ohm: float | None
    """R ≤ U_ch²/P_peak; None without U_ch (no data)."""
    reference: str = "P = U_ch²/R (Ohm's law): R ≤ U_ch²/P_peak"


def braking_resistor(
    figures: PowerFigures, cap: Capacitor, chopper_voltage_v: float | None
) -> BrakingResistor:
    """The braking resistor for the bus figures: not needed where nothing regenerates or
    where the capacitance is known to absorb every pulse."""
    absorbed = cap.energy_j if cap.energy_j is not None else 0.0
    pulse = max(figures.regen_pulse_energy_j - absorbed, 0.0)
    needed = figures.regen_energy_j > 0 and not cap.absorbs_every_pulse
    peak = figures.regen_peak_w if needed else 0.0
    # every pulse's energy beyond what the capacitance absorbs, per cycle
    continuous = (
        sum(max(e - absorbed, 0.0) for e in figures.regen_pulse_energies_j) / figures.cycle_s
        if needed
        else 0.0
    )
    r_max = None
    if chopper_voltage_v is not None and needed and peak > 0:
        r_max = chopper_voltage_v**2 / peak
    return BrakingResistor(
        needed=needed,
        peak_power_w=peak,
        continuous_power_w=continuous,
        pulse_energy_j=pulse if needed else 0.0,
        chopper_voltage_v=chopper_voltage_v,
        max_resistance_ohm=r_max,
    )


def sample_curve(bus: Bus, points_per_stretch: int = 8) -> tuple[list[float], list[list[float]]]:
    """Times and each axis's electrical power at them, for a chart: every stretch's ends and
    ``points_per_stretch`` points inside (the figures above come from the polynomials, not
    from these samples)."""
    times: list[float] = []
    values: list[list[float]] = [[] for _ in bus.axes]
    for s in bus.stretches:
        xs = np.linspace(0.0, s.duration_s, points_per_stretch + 2)
        for x in xs:
            times.append(float(s.start_s + x))
            for k, p in enumerate(s.axes):
                values[k].append(float(p(x)))
    return times, values
