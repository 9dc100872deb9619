"""The flowchart's check messages: a stable code and parameters beside the English text.

A rule's message (:attr:`~actuator_selection.core.checks.Rule.message`) is a
:class:`Phrase`: a ``str`` holding the English text, as the checks have always said it,
that also carries :attr:`Phrase.code` (a name in :data:`CHECK_MESSAGES`, part of the
API contract: add codes, never rename or reuse one) and :attr:`Phrase.params`, the
values the template is filled with. The templates are ``str.format`` strings with
format specs (``{value:.4g}``) and the msgids of the gettext catalogs: the API renders
them in the request's language (``api/messages.py``, :func:`render` with a language's
number format and translations).

A parameter is a number (in the unit its name or the check gives), a :class:`Text`
(English words, translated where rendered), a nested :class:`Phrase` (a clause of its
own code and params), a list of such (written joined by ", "; a tuple, alternatives,
by " / "), or None (a clause left out: rendered as nothing).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any, Final

from actuator_selection.core.messages import N_, Text


class Phrase(str):
    """English text with the code and params it was rendered from (:func:`phrase`)."""

    code: str
    params: Mapping[str, Any]

    def __new__(cls, code: str, params: Mapping[str, Any]) -> Phrase:
        # str.format in C: a Phrase among the params formats as its English text; a clause
        # left out (None) and a list need writing out first (most params are numbers).
        fields = params
        for value in params.values():
            if value is None or isinstance(value, _WRITTEN_OUT):
                fields = {k: _english(v) for k, v in params.items()}
                break
        text = str.__new__(cls, CHECK_MESSAGES[code].format_map(fields))
        text.code = code
        text.params = params
        return text

    def __reduce__(self) -> tuple[Any, ...]:
        return (Phrase, (self.code, dict(self.params)))


_WRITTEN_OUT = (list, tuple)
"""Parameter types that :func:`_english` writes out (and None); any other value goes to
``str.format`` as it is."""


def _english(value: Any) -> Any:
    """A parameter as the English text shows it: a list as its items joined by ", ", a
    clause left out (None) as nothing."""
    if value is None:
        return ""
    if isinstance(value, list | tuple):
        return _separator(value).join(str(v) for v in value)
    return value


def _separator(items: list[Any] | tuple[Any, ...]) -> str:
    """A list's items are joined by ", ", a tuple's (alternatives: "CHA / CHM") by " / "."""
    return " / " if isinstance(items, tuple) else ", "


def phrase(code: str, **params: Any) -> Phrase:
    """The message ``code`` filled with ``params``; it reads as the English text."""
    return Phrase(code, params)


NumberFormat = Callable[[float, str], str]
"""A number as a language writes it, from the value and its format spec."""


class _Renderer:
    """``str.format`` whose fields are numbers, words and clauses in one language."""

    def __init__(self, translate: Callable[[str], str], number: NumberFormat | None) -> None:
        self._translate = translate
        self._number = number

    def format_field(self, value: Any, format_spec: str) -> str:
        if type(value) is float and self._number is not None:  # most fields: first
            return self._number(value, format_spec)
        if value is None:
            return ""
        if isinstance(value, Phrase):
            return self.render(value)
        if isinstance(value, Text):
            return self._translate(value)
        if isinstance(value, list | tuple):
            return _separator(value).join(self.format_field(v, "") for v in value)
        if isinstance(value, int) and not isinstance(value, bool) and not format_spec:
            return str(value)  # a count
        if (
            self._number is not None
            and isinstance(value, int | float)
            and not isinstance(value, bool)
        ):
            return self._number(float(value), format_spec)
        return str(format(value, format_spec))

    def render(self, message: Phrase) -> str:
        # str.format_map in C, each field written by format_field through _Field.__format__
        # (string.Formatter would parse the template in Python on every call).
        fields = {k: _Field(self, v) for k, v in message.params.items()}
        return self._translate(CHECK_MESSAGES[message.code]).format_map(fields)


class _Field:
    """One parameter of a message, written by its renderer in the template's format spec."""

    __slots__ = ("_renderer", "_value")

    def __init__(self, renderer: _Renderer, value: Any) -> None:
        self._renderer, self._value = renderer, value

    def __format__(self, format_spec: str) -> str:
        return self._renderer.format_field(self._value, format_spec)


def renderer(
    *, translate: Callable[[str], str], number: NumberFormat | None = None
) -> Callable[[str], str]:
    """A message with its template and words passed through ``translate`` and its
    numbers written by ``number`` (``format(value, spec)`` where None); a message that
    is no :class:`Phrase` (a rule written elsewhere) stays as it is."""
    phrases = _Renderer(translate, number)

    def render(message: str) -> str:
        return phrases.render(message) if isinstance(message, Phrase) else message

    return render


def jsonable_params(message: str) -> dict[str, Any] | None:
    """The params of ``message`` as JSON carries them: clauses as ``{"code", "params"}``,
    words as their English text, ±∞ and NaN as text; None for a message without a code."""
    if not isinstance(message, Phrase):
        return None
    return {k: _jsonable(v) for k, v in message.params.items()}


def _jsonable(value: Any) -> Any:
    kind = type(value)
    if kind is float:  # most params: a finite number, as it is
        return value if value - value == 0.0 else repr(value)  # inf − inf, NaN − NaN: NaN
    if isinstance(value, Phrase):
        return {"code": value.code, "params": jsonable_params(value)}
    if isinstance(value, list | tuple):
        return [_jsonable(v) for v in value]
    if isinstance(value, str):
        return str(value)
    if isinstance(value, float):
        return value if math.isfinite(value) else repr(value)
    return value


CHECK_MESSAGES: Final[Mapping[str, str]] = {
    # Shared
    "no_data": N_("no data: the catalogue gives no {what} for this actuator"),
    "fail_for_any_inertia": N_(
        "{message}, at its least for any J_A ≥ 0 (the catalogue gives no J_A for this actuator)"
    ),
    # 1. max_speed
    "max_speed.pass": N_("load speed n_2 = {value:.4g} rpm ≤ n_max = {limit:.4g} rpm"),
    "max_speed.fail": N_("load speed n_2 = {value:.4g} rpm exceeds n_max = {limit:.4g} rpm"),
    # 2. inertia_ratio
    "inertia_ratio.pass": N_("load inertia J_L = {value:.4g} kgm² ≤ 3·J_A = {limit:.4g} kgm²"),
    "inertia_ratio.fail": N_(
        "load inertia J_L = {value:.4g} kgm² exceeds 3·J_A = {limit:.4g} kgm²: the limit is "
        "binding for a highly dynamic application"
    ),
    "inertia_ratio.warn": N_(
        "load inertia J_L = {value:.4g} kgm² exceeds 3·J_A = {limit:.4g} kgm²: recommended "
        "for highly dynamic applications only"
    ),
    # 3., 4. peak_torque, decel_torque
    "peak_torque.pass": N_("acceleration torque T_1 = {value:.4g} Nm ≤ T_max = {limit:.4g} Nm"),
    "peak_torque.fail": N_(
        "acceleration torque T_1 = {value:.4g} Nm exceeds T_max = {limit:.4g} Nm"
    ),
    "decel_torque.pass": N_("deceleration torque |T_3| = {value:.4g} Nm ≤ T_max = {limit:.4g} Nm"),
    "decel_torque.fail": N_(
        "deceleration torque |T_3| = {value:.4g} Nm exceeds T_max = {limit:.4g} Nm"
    ),
    # 5. continuous_duty
    "continuous_duty.beyond_zone": N_(
        "operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) lies "
        "beyond the continuous-duty zone, which ends at {zone_max_speed_rpm:.4g} rpm"
    ),
    "continuous_duty.pass": N_(
        "operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) lies "
        "inside the continuous-duty zone (limit {limit:.4g} Nm at n_av)"
    ),
    "continuous_duty.fail": N_(
        "operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) lies "
        "above the continuous-duty zone (limit {limit:.4g} Nm at n_av)"
    ),
    # Retired (continuous_duty's words while it also bounded the speed): kept so that the
    # answers stored with them still render; continuous_speed checks the speed now.
    "continuous_duty.approximate_pass": N_(
        "approximate: operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} "
        "Nm) within {what} = {limit:.4g} Nm up to the {speed_what} {speed_rpm:.4g} rpm (no "
        "continuous-duty zone published; continuous operation above that speed is not "
        "allowed)"
    ),
    "continuous_duty.approximate_fail": N_(
        "approximate: operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} "
        "Nm) outside {what} = {limit:.4g} Nm up to the {speed_what} {speed_rpm:.4g} rpm (no "
        "continuous-duty zone published; continuous operation above that speed is not "
        "allowed)"
    ),
    "continuous_duty.current_pass": N_(
        "approximate: operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) "
        "within the continuous torque at n_av, T_0 − k_T·K_INL·n_av = {stall_torque_nm:.4g} Nm − "
        "{slope_nm_per_rpm:.4g} Nm/rpm · {mean_speed_rpm:.4g} rpm = {limit:.4g} Nm (the no-load "
        "current of Eq. 522.2 takes its share of the continuous stall current, Eq. 522.3; no "
        "continuous-duty zone published)"
    ),
    "continuous_duty.current_fail": N_(
        "approximate: operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) "
        "exceeds the continuous torque at n_av, T_0 − k_T·K_INL·n_av = {stall_torque_nm:.4g} Nm "
        "− {slope_nm_per_rpm:.4g} Nm/rpm · {mean_speed_rpm:.4g} rpm = {limit:.4g} Nm (the "
        "no-load current of Eq. 522.2 takes its share of the continuous stall current, "
        "Eq. 522.3; no continuous-duty zone published)"
    ),
    "continuous_duty.rectangle_pass": N_(
        "approximate: operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) "
        "within {what} = {limit:.4g} Nm (no continuous-duty zone published: the limit is taken "
        "as constant with speed; the speed is checked on its own)"
    ),
    "continuous_duty.rectangle_fail": N_(
        "approximate: operating point (n_av = {mean_speed_rpm:.4g} rpm, T_rms = {value:.4g} Nm) "
        "exceeds {what} = {limit:.4g} Nm (no continuous-duty zone published: the limit is "
        "taken as constant with speed; the speed is checked on its own)"
    ),
    # 6. thermal_peak
    "thermal_peak.beyond_zone": N_(
        "winding heating over the repeating cycle peaks at {value:.4g} Nm as a torque, with "
        "n_av = {mean_speed_rpm:.4g} rpm beyond the continuous-duty zone, which ends at "
        "{zone_max_speed_rpm:.4g} rpm ({model})"
    ),
    "thermal_peak.pass": N_(
        "winding heating over the repeating cycle peaks at {value:.4g} Nm as a torque ≤ the "
        "continuous limit {limit:.4g} Nm ({model})"
    ),
    "thermal_peak.fail": N_(
        "winding heating over the repeating cycle peaks at {value:.4g} Nm as a torque exceeds "
        "the continuous limit {limit:.4g} Nm ({model})"
    ),
    "thermal_peak.current_pass": N_(
        "winding current over the repeating cycle peaks at {value:.4g} Nm as a torque, the "
        "no-load current of Eq. 522.2 counted as the torque k_T·K_INL·|n| = "
        "{slope_nm_per_rpm:.4g} Nm/rpm · |n| it takes (Eq. 522.3), ≤ T_0 = {limit:.4g} Nm "
        "({model})"
    ),
    "thermal_peak.current_fail": N_(
        "winding current over the repeating cycle peaks at {value:.4g} Nm as a torque, the "
        "no-load current of Eq. 522.2 counted as the torque k_T·K_INL·|n| = "
        "{slope_nm_per_rpm:.4g} Nm/rpm · |n| it takes (Eq. 522.3), exceeds T_0 = "
        "{limit:.4g} Nm ({model})"
    ),
    "thermal_peak.model": N_(
        "first-order thermal model, τ_th = {tau_s:.4g} s{assumed}; cycle t_0 = {cycle_s:.4g} s "
        "= {ratio:.3g}·τ_th, {regime}"
    ),
    "thermal_peak.assumed": N_(" assumed: not published for this actuator"),
    "thermal_peak.short": N_("short against τ_th: T_rms = {rms_torque_nm:.4g} Nm governs"),
    "thermal_peak.long": N_(
        "not short against τ_th: its long segments govern, not T_rms = {rms_torque_nm:.4g} Nm"
    ),
    # 7. continuous_speed
    "continuous_speed.pass": N_(
        "speed the winding's heating follows n_th = {value:.4g} rpm (cycle mean n_av = "
        "{mean_speed_rpm:.4g} rpm; {model}) ≤ the {speed_what} {limit:.4g} rpm"
    ),
    "continuous_speed.fail": N_(
        "speed the winding's heating follows n_th = {value:.4g} rpm (cycle mean n_av = "
        "{mean_speed_rpm:.4g} rpm; {model}) exceeds the {speed_what} {limit:.4g} rpm: "
        "continuous operation above it is not allowed"
    ),
    "continuous_speed.model": N_(
        "first-order thermal model, τ_th = {tau_s:.4g} s{assumed}; a segment long against "
        "τ_th counts with its own speed, whatever n_av"
    ),
    # brake_holding
    "brake_holding.pass": N_(
        "load torque at standstill T_L = {value:.4g} Nm ≤ the brake's holding torque = "
        "{limit:.4g} Nm"
    ),
    "brake_holding.fail": N_(
        "load torque at standstill T_L = {value:.4g} Nm exceeds the brake's holding torque = "
        "{limit:.4g} Nm"
    ),
    # drive_current
    "drive_current.pass": N_(
        "peak motor current I = max(T_1, |T_3|)/k_T + I_NLR = {value:.4g} A ≤ I_max = "
        "{limit:.4g} A{no_load}{rms}{braking}"
    ),
    "drive_current.fail": N_(
        "peak motor current I = max(T_1, |T_3|)/k_T + I_NLR = {value:.4g} A exceeds I_max = "
        "{limit:.4g} A{no_load}{rms}{braking}"
    ),
    "drive_current.no_load_unknown": N_(
        " (approximate: the catalogue gives no no-load current, left out)"
    ),
    "drive_current.no_load": N_(" (I_NLR = {no_load_current_a:.3g} A at n_2, K_INL at 30 °C)"),
    "drive_current.rms": N_("; rms current ≤ {rms_current_a:.4g} A"),
    "drive_current.braking": N_("; braking returns up to {energy_j:.4g} J per cycle to the drive"),
    # drive_voltage
    "drive_voltage.pass": N_(
        "U = √((n·i·K_E + I_max·R)² + (ω·L·I_max)²) = {value:.4g} V_rms at n_2 = "
        "{speed_rpm:.4g} rpm ≤ {limit:.4g} V_rms from a {dc_bus_voltage_v:g} V DC bus "
        "(space-vector modulation); Eq. 521.2 as printed (no inductive drop) gives "
        "{printed_v:.4g} V_rms"
    ),
    "drive_voltage.fail": N_(
        "U = √((n·i·K_E + I_max·R)² + (ω·L·I_max)²) = {value:.4g} V_rms at n_2 = "
        "{speed_rpm:.4g} rpm exceeds {limit:.4g} V_rms from a {dc_bus_voltage_v:g} V DC bus "
        "(space-vector modulation); Eq. 521.2 as printed (no inductive drop) gives "
        "{printed_v:.4g} V_rms"
    ),
    # bearing_moment
    "bearing_moment.pass": N_(
        "tilting moment M = F_r·(L_r + R) + F_a·L_a = {value:.4g} Nm ≤ {what} = {limit:.4g} Nm "
        "(R = {offset_mm:.3g} mm)"
    ),
    "bearing_moment.fail": N_(
        "tilting moment M = F_r·(L_r + R) + F_a·L_a = {value:.4g} Nm exceeds {what} = "
        "{limit:.4g} Nm (R = {offset_mm:.3g} mm)"
    ),
    # bearing_static_safety
    "bearing_static_safety.pass": N_(
        "static safety factor f_s = C_0/P_0 = {limit:.4g} N / {p_0_n:.4g} N = {f_s:.3g} ≥ the "
        "required {f_s_min:.3g} (P_0 = F_r + 2M/d_p + 0.44·F_a)"
    ),
    "bearing_static_safety.fail": N_(
        "static safety factor f_s = C_0/P_0 = {limit:.4g} N / {p_0_n:.4g} N = {f_s:.3g} below "
        "the required {f_s_min:.3g} (P_0 = F_r + 2M/d_p + 0.44·F_a)"
    ),
    # bearing_life
    "bearing_life.pass": N_(
        "output bearing life L_10 = 10⁶/(60·n_av)·(C/(f_w·P_c))^B = {life_h:.4g} h at "
        "n_av = {mean_speed_rpm:.4g} rpm ≥ the required {required_life_h:.4g} h (P_c = "
        "{p_c_n:.4g} N, f_w = {load_factor:.3g}; C needed {value:.4g} N, C = {limit:.4g} N; "
        "{bearing})"
    ),
    "bearing_life.fail": N_(
        "output bearing life L_10 = 10⁶/(60·n_av)·(C/(f_w·P_c))^B = {life_h:.4g} h at "
        "n_av = {mean_speed_rpm:.4g} rpm below the required {required_life_h:.4g} h (P_c = "
        "{p_c_n:.4g} N, f_w = {load_factor:.3g}; C needed {value:.4g} N, C = {limit:.4g} N; "
        "{bearing})"
    ),
    "bearing_fretting.pass": N_(
        "the output swings {limit:.3g}° per cycle, at least {value:.3g}°: no fretting of the "
        "output bearing to fear from oscillating motion"
    ),
    "bearing_fretting.still": N_("the output does not move: no oscillating motion"),
    "bearing_fretting.warn": N_(
        "the output swings only {limit:.3g}° per cycle, below {value:.3g}°: the manufacturer "
        "warns of fretting of the output bearing under such oscillating motion (the rolling "
        "elements rock on a short track and the lubricant is not renewed); move it through a "
        "larger angle now and then, or ask the manufacturer"
    ),
    "bearing_life.ball": N_("four-point contact ball bearing: B = 3"),
    "bearing_life.roller": N_("cross roller bearing: B = 10/3"),
    "bearing_life.unknown": N_(
        "approximate: the bearing's type is not published, so the stricter of B = 3 (ball) "
        "and B = 10/3 (roller)"
    ),
    # Table 521.1: one criterion of one controller (core/compatibility.py)
    "criterion.no_data": N_("no data: {criterion} unknown"),
    "criterion.excluded": N_("{criterion} {options}: not supported (no mark in {reference})"),
    "criterion.tested": N_("{criterion} {option}: practically tested (●)"),
    "criterion.possible": N_("{criterion} {option}: theoretically possible (○)"),
    # What a candidate's controller list rests on (schemas/controllers.py)
    "controllers_note.none": N_("no controller of Table 521.1 supports this actuator"),
    "controllers_note.supported": N_(
        "{count} controllers support this actuator ({excluded} excluded)"
    ),
    "controllers_note.unconfirmed": N_(
        "{count} controllers are not excluded ({excluded} are), but the catalogue has no "
        "data for: {missing}; those criteria stay unconfirmed"
    ),
    # U_OUT of Eq. 521.2 against a DC bus class (core/electrical.py, core/drive.py)
    "output_voltage.pass": N_(
        "U_OUT = {required_voltage_v:.4g} V_rms ≤ {available_voltage_v:.4g} V_rms available "
        "from a {dc_bus_voltage_v:g} V DC bus ({modulation} modulation)"
    ),
    "output_voltage.fail": N_(
        "U_OUT = {required_voltage_v:.4g} V_rms exceeds {available_voltage_v:.4g} V_rms "
        "available from a {dc_bus_voltage_v:g} V DC bus ({modulation} modulation)"
    ),
    "controller_voltage.at_speed": N_("{output} at n_2 = {speed_rpm:.4g} rpm{at_max_speed}"),
    "controller_voltage.reaches": N_(
        "; at n_max = {max_speed_rpm:.4g} rpm U_OUT = {max_speed_voltage_v:.4g} V_rms, so "
        "this bus reaches n_max"
    ),
    "controller_voltage.does_not_reach": N_(
        "; at n_max = {max_speed_rpm:.4g} rpm U_OUT = {max_speed_voltage_v:.4g} V_rms, so "
        "this bus does not reach n_max"
    ),
    "controller_voltage.no_constants": N_(
        "no data: the catalogue gives no motor K_E (V_rms per 1000 rpm), I_max, line-to-line "
        "R and L, and pole pairs p"
    ),
    "controller_voltage.no_bus_class": N_("no data: the actuator's DC bus class is not published"),
    "controller_voltage.no_shared_bus": N_(
        "no data: the controller and the actuator share no DC bus class"
    ),
    # The output bearing of a selection (schemas/output_load.py)
    "output_bearing.not_checked": N_("not checked: no output_load given"),
    "output_bearing.no_life": N_(
        "tilting moment and static safety checked; life not checked: no required_life_h"
    ),
    "output_bearing.checked": N_("tilting moment, static safety and L_10 life checked"),
    # Why a limit of the inverse solve has no value (core/inverse.py); {check}: the
    # message of a check that fails there
    "limit.none.min": N_(
        "none in the range searched: even at {value:.6g} {unit}, the longest searched, a "
        "check still fails: {check}"
    ),
    "limit.none.max": N_(
        "none in the range searched: already at {value:.6g} {unit}, the smallest, a check "
        "fails: {check}"
    ),
    "limit.accel_no_ramp": N_(
        "t_1 is solved for a cycle that starts with an acceleration from standstill; this "
        "cycle's first segment is none"
    ),
    # A check of a stored lean answer, written from its numbers (schemas/quotes.py); the
    # check's name stands beside it wherever it is shown
    "stored.pass": N_("{value:.4g} {unit} ≤ {limit:.4g} {unit}"),
    "stored.fail": N_("{value:.4g} {unit} exceeds {limit:.4g} {unit}"),
}
"""Code → English template of every check message (and of the clauses they hold)."""

CHECK_WORDS: Final = (
    N_("the allowable dynamic tilting moment M_dyn"),
    N_("the allowable moment load"),
    N_("allowable continuous torque"),
    N_("continuous stall torque T_0"),
    N_("allowable continuous speed"),
    N_("rated speed"),
)
"""Words the check messages take as params (:class:`Text`); a requirement's ``what``
(``core/checks.py``) is marked where it is written."""
