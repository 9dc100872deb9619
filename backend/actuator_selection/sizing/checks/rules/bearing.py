"""The output bearing's checks: tilting moment, static safety, L_10 life and fretting
(CHA §4.3; FHA-C manual ch. 2), where an output load is given."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Final

from actuator_selection.phrases.check_messages import check_words, phrase
from actuator_selection.phrases.messages import N_
from actuator_selection.sizing import bearing
from actuator_selection.sizing.checks.rule import (
    FLOAT_OPS,
    Operands,
    Ops,
    Real,
    Requirement,
    Rule,
    Status,
    Truth,
    larger,
    outcome,
    published,
)

if TYPE_CHECKING:
    from actuator_selection.sizing.application import Application

_DYNAMIC_TILTING = N_("the allowable dynamic tilting moment M_dyn")
_MOMENT_LOAD = N_("the allowable moment load")

WORDS: Final = {
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
    # bearing_radial_force, bearing_axial_force
    "bearing_radial_force.pass": N_(
        "radial force F_r = {value:.4g} N ≤ the output bearing's allowable radial load "
        "{limit:.4g} N"
    ),
    "bearing_radial_force.fail": N_(
        "radial force F_r = {value:.4g} N exceeds the output bearing's allowable radial load "
        "{limit:.4g} N"
    ),
    "bearing_axial_force.pass": N_(
        "axial force F_a = {value:.4g} N ≤ the output bearing's allowable axial load {limit:.4g} N"
    ),
    "bearing_axial_force.fail": N_(
        "axial force F_a = {value:.4g} N exceeds the output bearing's allowable axial load "
        "{limit:.4g} N"
    ),
    "bearing_force.by_ratings": N_(
        "the catalogue rates this output bearing by its load ratings C and C_0 (static "
        "safety, L_10 life), not by allowable forces"
    ),
    "bearing_life.ball": N_("four-point contact ball bearing: B = 3"),
    "bearing_life.roller": N_("cross roller bearing: B = 10/3"),
    "bearing_life.unknown": N_(
        "approximate: the bearing's type is not published, so the stricter of B = 3 (ball) "
        "and B = 10/3 (roller)"
    ),
}
"""This module's check messages: code → English template (the gettext msgid)."""

check_words(WORDS, words=(_DYNAMIC_TILTING, _MOMENT_LOAD))


# --- output bearing: tilting moment, static safety, L_10 life (CHA §4.3; FHA-C ch. 2) -------


def _moment(q: Operands) -> Real:
    return bearing.tilting_moment_nm(
        radial_force_n=q.radial_force_n,
        axial_force_n=q.axial_force_n,
        radial_lever_m=q.radial_lever_m,
        axial_lever_m=q.axial_lever_m,
        offset_m=q.bearing_offset_m,
    )


def _moment_limit(q: Operands, xp: Ops) -> Real:
    """The allowable moment load (FHA-C, FHA-C mini), else the CHA's M_dyn(max)."""
    return xp.where(
        xp.isnan(q.bearing_moment_load_nm),
        q.bearing_dynamic_tilting_moment_nm,
        q.bearing_moment_load_nm,
    )


def _moment_message(q: Operands, status: Status, moment: float, limit: float) -> str:
    what = _DYNAMIC_TILTING if math.isnan(q.bearing_moment_load_nm) else _MOMENT_LOAD
    return phrase(
        f"bearing_moment.{outcome(status)}",
        value=moment,
        limit=limit,
        what=what,
        offset_mm=q.bearing_offset_m * 1000,
    )


def loaded(app: Application) -> bool:
    """Whether an output load is given: the output bearing is checked."""
    return app.output_load is not None


def life_asked(app: Application) -> bool:
    """Whether the output bearing's life is checked."""
    load = app.output_load
    return load is not None and load.required_life_h is not None


BEARING_MOMENT = Rule(
    name="bearing_moment",
    when=loaded,
    reference="CHA §4.3; FHA-C manual ch. 2, formula (1)",
    unit="Nm",
    value=lambda q, xp: _moment(q),
    limit=_moment_limit,
    requires=(
        published("bearing_offset_m", N_("output bearing offset R")),
        Requirement(
            any_of=("bearing_moment_load_nm", "bearing_dynamic_tilting_moment_nm"),
            what=N_("allowable tilting moment of the output bearing"),
        ),
    ),
    message=_moment_message,
)
"""M = F_r·(L_r + R) + F_a·L_a ≤ the allowable moment (FHA-C "permissible moment
capacity"; CHA M_dyn(max), the moving bearing's limit, stricter than the static M_0,
which the static safety factor covers)."""


def _static_load(q: Operands) -> Real:
    return bearing.static_equivalent_load_n(
        radial_force_n=q.radial_force_n,
        axial_force_n=q.axial_force_n,
        moment_nm=_moment(q),
        pitch_diameter_m=q.bearing_pitch_diameter_m,
    )


def _static_message(q: Operands, status: Status, needed: float, c_0: float) -> str:
    p_0 = _static_load(q)
    f_s = c_0 / p_0 if p_0 > 0 else math.inf
    return phrase(
        f"bearing_static_safety.{outcome(status)}",
        value=needed,
        limit=c_0,
        p_0_n=float(p_0),
        f_s=float(f_s),
        f_s_min=q.static_safety_min,
    )


BEARING_STATIC = Rule(
    name="bearing_static_safety",
    when=loaded,
    reference="CHA §4.3; FHA-C manual ch. 2, formulas (9), (10)",
    unit="N",
    value=lambda q, xp: q.static_safety_min * _static_load(q),
    limit=lambda q, xp: q.bearing_static_load_rating_n,
    requires=(
        published("bearing_pitch_diameter_m", N_("output bearing pitch circle diameter d_p")),
        published("bearing_offset_m", N_("output bearing offset R")),
        published("bearing_static_load_rating_n", N_("output bearing static load rating C_0")),
    ),
    message=_static_message,
)
"""f_s = C_0/P_0 ≥ f_s,min, checked as f_s,min·P_0 ≤ C_0 [N] (no division by a load that
may be 0): the static capacity the application needs against the one it has."""


def _dynamic_load(q: Operands, xp: Ops) -> Real:
    return bearing.dynamic_equivalent_load_n(
        radial_force_n=q.radial_force_n,
        axial_force_n=q.axial_force_n,
        moment_nm=_moment(q),
        pitch_diameter_m=q.bearing_pitch_diameter_m,
        xp=xp,
    )


def _life_factor(q: Operands, xp: Ops) -> Real:
    """(L_h·60·n_av/10⁶)^(1/B) with B of the bearing's type (3 ball, 10/3 roller); where
    the type is not published, the larger of the two, the safe side. Both powers depend
    on the case alone (``xp.pow`` runs on case columns); the type picks one per actuator."""
    life, speed = q.required_life_h, q.mean_speed_rpm
    roller = bearing.life_revolutions_factor(
        required_life_h=life,
        mean_speed_rpm=speed,
        xp=xp,
        exponent_inverse=bearing.LIFE_EXPONENT_INVERSE,
    )
    ball = bearing.life_revolutions_factor(
        required_life_h=life,
        mean_speed_rpm=speed,
        xp=xp,
        exponent_inverse=bearing.BALL_LIFE_EXPONENT_INVERSE,
    )
    exponent = q.bearing_life_exponent
    by_type = xp.where(exponent == bearing.BALL_LIFE_EXPONENT, ball, roller)
    return xp.where(xp.isnan(exponent), larger(ball, roller, xp), by_type)


def _required_rating(q: Operands, xp: Ops) -> Real:
    """C_req = f_w·P_c·(L_h·60·n_av/10⁶)^(1/B): formula (7) solved for C."""
    return q.load_factor * _dynamic_load(q, xp) * _life_factor(q, xp)


def _life_message(q: Operands, status: Status, needed: float, c: float) -> str:
    p_c = _dynamic_load(q, FLOAT_OPS)
    exponent = q.bearing_life_exponent

    def life(b: float) -> float:
        return bearing.l10_life_h(
            dynamic_load_rating_n=c,
            load_factor=q.load_factor,
            equivalent_load_n=p_c,
            mean_speed_rpm=q.mean_speed_rpm,
            exponent=b,
        )

    if math.isnan(exponent):
        life_h = min(life(bearing.BALL_LIFE_EXPONENT), life(bearing.LIFE_EXPONENT))
        kind = "unknown"
    else:
        life_h = life(exponent)
        kind = "ball" if exponent == bearing.BALL_LIFE_EXPONENT else "roller"
    return phrase(
        f"bearing_life.{outcome(status)}",
        value=needed,
        limit=c,
        life_h=float(life_h),
        mean_speed_rpm=q.mean_speed_rpm,
        required_life_h=q.required_life_h,
        p_c_n=float(p_c),
        load_factor=q.load_factor,
        bearing=phrase(f"bearing_life.{kind}"),
    )


# --- output bearing: fretting under oscillating motion (CHA manual, p. 69) ------------------


def _fretting_message(q: Operands, status: Status, needed: float, swing: float) -> str:
    if status is Status.NOT_APPLICABLE:
        return phrase("bearing_fretting.still")
    kind = "pass" if status is Status.PASS else "warn"  # it never fails (never binding)
    return phrase(f"bearing_fretting.{kind}", value=needed, limit=swing)


# --- bearing_radial_force, bearing_axial_force: F ≤ the allowable load (FHA-C) ------------


def _force_rule(name: str, force: str, allowable: str, what: str) -> Rule:
    """F ≤ the allowable load, for a bearing its catalogue rates by allowable forces (FHA-C
    manual §1-4-2, allowable radial and axial load). Where the catalogue rates it by its
    load ratings instead (CHA manual 1018854 12/2015, output bearing Table 51.1: C, C_0,
    M_dyn(max), M_0, and no allowable force; its §4.3 checks those), the premise does not
    hold: not applicable (the load ratings' checks judge the forces). Read from the row:
    an allowable force published, or no C_0 either (then the force is what is missing:
    no data) — docs/decisions/0025-not-applicable.md."""

    def by_forces(q: Operands, xp: Ops) -> Truth:
        return xp.not_(xp.isnan(getattr(q, allowable))) | xp.isnan(q.bearing_static_load_rating_n)

    def message(q: Operands, status: Status, value: float, limit: float) -> str:
        if status is Status.NOT_APPLICABLE:
            return phrase("bearing_force.by_ratings")
        return phrase(f"{name}.{outcome(status)}", value=value, limit=limit)

    return Rule(
        name=name,
        when=loaded,
        reference="FHA-C manual §1-4-2; CHA 1018854 12/2015 Table 51.1",
        unit="N",
        value=lambda q, xp: abs(getattr(q, force)),
        limit=lambda q, xp: getattr(q, allowable),
        requires=(published(allowable, what),),
        applies=by_forces,
        message=message,
    )


BEARING_RADIAL_FORCE = _force_rule(
    "bearing_radial_force",
    "radial_force_n",
    "bearing_radial_load_n",
    N_("allowable radial load on the output bearing"),
)
"""|F_r| ≤ the allowable radial load (FHA-C), issue 28 item 4; not applicable to a
bearing rated by C and C_0 (CHA)."""

BEARING_AXIAL_FORCE = _force_rule(
    "bearing_axial_force",
    "axial_force_n",
    "bearing_axial_load_n",
    N_("allowable axial load on the output bearing"),
)
"""|F_a| ≤ the allowable axial load (FHA-C), issue 28 item 4; not applicable to a
bearing rated by C and C_0 (CHA)."""


BEARING_FRETTING = Rule(
    name="bearing_fretting",
    when=loaded,
    reference="CHA manual 1018854 12/2015, p. 69",
    unit="°",
    value=lambda q, xp: q.swing_deg * 0.0 + bearing.FRETTING_SWING_DEG,
    limit=lambda q, xp: q.swing_deg,
    requires=(),
    applies=lambda q, xp: q.swing_deg > 0.0,
    binding=lambda q, xp: q.swing_deg < 0.0,  # never: a warning, the verdict stands
    message=_fretting_message,
)
"""The cycle's swing (:func:`~actuator_selection.sizing.bearing.swing_deg`) of at least
:data:`~actuator_selection.sizing.bearing.FRETTING_SWING_DEG` = 5°, checked as 5° ≤ the
swing; a smaller swing warns (the CHA manual warns of fretting under oscillating motion
below 5°, issue 28 item 4) and never fails: the manual gives no life for it. A cycle that
does not move is not applicable: there is no oscillating motion. The swing is the range
of the output's angle over the cycle, so one small move repeated in one direction warns
as well: on the safe side, as the chapter's cycle does not say whether it returns."""


BEARING_LIFE = Rule(
    name="bearing_life",
    when=life_asked,
    reference="CHA §4.3, Table 69.3, Table 70.4; FHA-C manual ch. 2, formulas (5)–(7); ISO 281",
    unit="N",
    value=_required_rating,
    limit=lambda q, xp: q.bearing_dynamic_load_rating_n,
    requires=(
        published("bearing_pitch_diameter_m", N_("output bearing pitch circle diameter d_p")),
        published("bearing_offset_m", N_("output bearing offset R")),
        published("bearing_dynamic_load_rating_n", N_("output bearing dynamic load rating C")),
    ),
    approximate=lambda q, xp: xp.isnan(q.bearing_life_exponent),
    message=_life_message,
)
"""L_10 at the cycle's mean speed n_av ≥ the required life, checked as the dynamic load
rating that life needs, f_w·P_c·(L_h·60·n_av/10⁶)^(1/B), against C [N]; the message
gives L_10 in hours. B is the bearing type's life exponent (ISO 281: 3 for ball, 10/3 for
roller bearings; CHA manual 1018854 12/2015, p. 69, Table 69.3): 3 for the four-point
contact ball bearings of the CHA-14A, -17A and -20A, 10/3 for the cross roller bearings.
Where the catalogue gives no type, the stricter of the two (the larger C needed), and
the check is approximate (issue 28, item 4)."""
