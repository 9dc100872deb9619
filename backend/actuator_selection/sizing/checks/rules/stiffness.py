"""The gear's torsional stiffness (issue 28, item 8): the load's natural frequency on it,
where the application names a least frequency (``Application.min_natural_frequency_hz``),
with the torsional deflection under the load torque and under T_1.

- Torsion angle, piecewise linear on the stiffness curve (Harmonic Drive AG, *Engineering
  Data AC Servo Actuators CHA*, 1018854 12/2015 V01, Eq. 68.1–68.4, p. 68):
  φ = T/K_1 for T ≤ T_1; φ = T_1/K_1 + (T − T_1)/K_2 for T_1 < T ≤ T_2;
  φ = T_1/K_1 + (T_2 − T_1)/K_2 + (T − T_2)/K_3 above T_2.
- Natural frequency of the load J_L on the gear with its input held (the component
  catalogues' convention, K_1: the small-angle stiffness), f_n = (1/2π)·√(K_1/J_L)
  (same document, §3.3.5, p. 50).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Final

from actuator_selection.phrases.check_messages import check_words, phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing.checks.operands import Operands, Real
from actuator_selection.sizing.checks.rule import Ops, Rule, Status, outcome, published

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

ARCMIN_PER_RAD: Final = 180.0 * 60.0 / math.pi

WORDS: Final = {
    "natural_frequency.pass": N_(
        "natural frequency of the load f_n = {limit:.4g} Hz ≥ the required {value:.4g} Hz; "
        "torsional deflection {deflection}"
    ),
    "natural_frequency.fail": N_(
        "natural frequency of the load f_n = {limit:.4g} Hz is below the required "
        "{value:.4g} Hz; torsional deflection {deflection}"
    ),
    "deflection": N_("{load:.3g} arcmin under T_L = {torque:.4g} Nm, {t1:.3g} arcmin under T_1"),
    "deflection_t1": N_(
        "{t1:.3g} arcmin under T_1 (under T_L = {torque:.4g} Nm: no data, the catalogue "
        "gives no K_2 or K_3)"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS)


def torsion_angle_rad(q: Operands, torque: float) -> float:
    """φ(T) [rad] on the piecewise-linear stiffness curve (CHA manual Eq. 68.1–68.4);
    NaN where the segment's K is not published (floats: one cell's words)."""
    t = abs(torque)
    t1, t2 = q.limit_torque_t1_nm, q.limit_torque_t2_nm
    k1, k2, k3 = q.stiffness_k1_nm_per_rad, q.stiffness_k2_nm_per_rad, q.stiffness_k3_nm_per_rad
    if t <= t1:
        return float(t / k1)
    if t <= t2 or math.isnan(t2):
        return float(t1 / k1 + (t - t1) / k2) if k2 > 0 else math.nan
    if not (k2 > 0 and k3 > 0):
        return math.nan
    return float(t1 / k1 + (t2 - t1) / k2 + (t - t2) / k3)


def natural_frequency_hz(q: Operands, xp: Ops) -> Real:
    """f_n = (1/2π)·√(K_1/J_L) [Hz]; infinite without a load inertia."""
    j = q.load_inertia_kgm2
    loaded = j > 0.0
    return xp.where(
        loaded,
        xp.sqrt(q.stiffness_k1_nm_per_rad / xp.where(loaded, j, 1.0)) / (2.0 * math.pi),
        math.inf,
    )


def _message(q: Operands, status: Status, value: float, limit: float) -> str:
    t1 = torsion_angle_rad(q, q.limit_torque_t1_nm) * ARCMIN_PER_RAD
    load = torsion_angle_rad(q, q.load_torque_nm) * ARCMIN_PER_RAD
    if math.isnan(load):
        deflection = phrase("deflection_t1", t1=t1, torque=q.load_torque_nm)
    else:
        deflection = phrase("deflection", load=load, torque=q.load_torque_nm, t1=t1)
    return phrase(
        f"natural_frequency.{outcome(status)}", value=value, limit=limit, deflection=deflection
    )


def frequency_asked(app: Application) -> bool:
    """Whether a least natural frequency is asked."""
    return app.min_natural_frequency_hz is not None


NATURAL_FREQUENCY = Rule(
    name="natural_frequency",
    when=frequency_asked,
    reference="CHA 1018854 12/2015 §3.3.5 p. 50, Eq. 68.1–68.4 p. 68",
    unit="Hz",
    value=lambda q, xp: q.min_natural_frequency_hz,
    limit=natural_frequency_hz,
    requires=(
        published("stiffness_k1_nm_per_rad", N_("torsional stiffness K_1")),
        published("limit_torque_t1_nm", N_("limit torque T_1 of the stiffness curve")),
    ),
    message=_message,
)
"""The required least frequency ≤ f_n = (1/2π)·√(K_1/J_L) [Hz], with the deflection under
T_L and under T_1 in its words."""
