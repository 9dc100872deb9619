"""The rules the core's input checks enforce: a stable code for each, and its English text.

A :class:`~actuator_selection.errors.DomainError` raised with ``code=`` takes its
message from :data:`MESSAGES`: the template there, filled with the error's ``params``
(``str.format`` fields such as ``{value}``). The API answers with the code and the
params beside the text and renders the text in the request's language from the gettext
catalogs under ``locale/`` (``i18n/localize.py``), where the templates are the msgids.

Parameters that are words rather than numbers (the reason a bound exists, the kind of
mechanism) are :class:`Text`: the API translates them too. Every string marked with
:func:`N_` is extracted into the catalogs by ``pybabel extract`` (``babel.cfg``).
Codes are part of the API contract: add new ones, never rename or reuse one.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any, Final


class Text(str):
    """A parameter in words (English), translated where the message is rendered."""

    __slots__ = ()


def listed(values: Sequence[object], shown: Callable[[Any], str] = str) -> str:
    """A list as a message shows it: words quoted, other values as ``shown`` writes them,
    no value as a dash.

    >>> listed(["EUR", "USD"]), listed([3, 7]), listed([])
    ("'EUR', 'USD'", '3, 7', '–')
    """
    return ", ".join(f"'{v}'" if isinstance(v, str) else shown(v) for v in values) or "–"


def N_(text: str) -> Text:  # noqa: N802 (gettext's name for "mark for translation")
    """Marks ``text`` for the catalogs; the translation happens when the message is rendered."""
    return Text(text)


MESSAGES: Final[Mapping[str, str]] = {
    # Any number
    "not_finite": N_("must be a finite number, got {value}"),
    "must_be_positive": N_("must be > 0: {rule}"),
    "must_be_nonnegative": N_("must be ≥ 0: {rule}"),
    "positive": N_("must be > 0"),
    "result_overflow": N_(
        "gives {what} beyond any floating-point number: no real drive has such a load and cycle"
    ),
    "mechanism_overflow": N_(
        "gives {what} beyond any floating-point number: no real mechanism has such values"
    ),
    # Efficiencies
    "efficiency_range": N_("must be > 0 and ≤ 1"),
    "efficiency_positive": N_("must be > 0: η of {what} divides the torque the actuator gives"),
    "efficiency_above_one": N_("must be ≤ 1: no {what} returns more than it takes"),
    "efficiency_product_zero": N_("η_tr·η is 0: no power reaches the load"),
    # Segments and cycles (sizing/motion, schemas/selections.py)
    "duration_zero_with_speed_change": N_(
        "must be > 0 where the speed changes: Δω/t is the acceleration"
    ),
    "speed_sign_change": N_(
        "must not change sign within a segment: brake to 0 in one segment and accelerate "
        "the other way in the next"
    ),
    "share_range": N_("must be between 0 and 1: a share of t"),
    "segments_empty": N_("must hold at least one segment"),
    "segments_too_many": N_("must hold at most {max} segments"),
    "speed_jump": N_("must equal the end speed of the segment before: speed cannot jump"),
    "cycle_not_closed": N_("the cycle must end at the speed it starts at: it repeats"),
    "cycle_zero_duration": N_("the cycle must last longer than 0 s"),
    # Measured profiles (sizing/sampled.py)
    "profile_not_closed": N_(
        "the profile must end at the speed it starts at (it repeats): it starts at "
        "{first} and ends at {last}"
    ),
    "profile_too_many_reversals": N_(
        "the profile changes direction {count} times; a cycle holds at most {max} segments"
    ),
    "profile_not_resolved": N_("names a profile that was not read"),
    # Several axes on one DC bus (sizing/bus.py)
    "axis_cycle_differs": N_(
        "the axis's cycle lasts {cycle_s} s, the machine's {machine_s} s: all axes of a "
        "project run on one machine cycle"
    ),
    "bus_voltage_not_above_nominal": N_(
        "must be above the bus class's nominal voltage of {nominal_v} V"
    ),
    "no_inertia_for_power": N_(
        "no data: {model} publishes no J_A, so its torque over the cycle (Eq. 514.1) and "
        "its power cannot be computed"
    ),
    "speed_required": N_("is required with the t_1…t_p cycle"),
    "speed_with_segments": N_("must be left out with segments: they give the speeds"),
    "duration_or_accel": N_("give either duration_s or accel"),
    "accel_without_speed_change": N_("needs a change of speed; give duration_s for a run"),
    # Mechanisms (sizing/mechanisms)
    "radius_vanishes": N_("is so small that m·r² vanishes: no real axis"),
    "incline_range": N_(
        "must be between −90° and 90°: positive motion lifts the load for θ > 0, lowers it "
        "for θ < 0; beyond vertical, reverse the axis instead"
    ),
    "ratio_too_small": N_("is so small that J/i² has no value: no real gear"),
    "ratio_too_large": N_("is so large that the load vanishes behind it (underflow): no real gear"),
    # The ratio study (sizing/ratio.py, services/ratio.py)
    "study_variable_missing": N_(
        "the load of type {type} has no {variable}: choose one it has, or ratio"
    ),
    "study_series_out_of_range": N_("has no value between min and max"),
    "study_range": N_("must be > 0 and below max"),
    # Money and quotes (sales/money.py, sales/quote_status.py)
    "decimal_format": N_("must be a decimal number such as 1234.50"),
    "decimal_finite": N_("must be a finite decimal number"),
    "amount_negative": N_("must be ≥ 0"),
    "cents": N_("must have at most 2 decimal places"),
    "amount_max": N_("must be ≤ {max}"),
    "subtotal_max": N_("the subtotal must be ≤ {max}"),
    "percent_range": N_("must be between 0 and 100"),
    "currency_code": N_(
        "must be an ISO 4217 code of three capital letters such as EUR, got '{value}'"
    ),
    "quantity_range": N_("must be a whole number from 1 to {max}"),
    "quote_expired": N_("the quote expired after {valid_until} and cannot move to '{target}'"),
    "quote_transition": N_(
        "a quote in status '{status}' cannot move to '{target}'; allowed: {allowed}"
    ),
    "quote_final": N_("a quote in status '{status}' is final and cannot move to '{target}'"),
}
"""Code → English template of every rule the core raises with a code."""


def english(template: str, params: Mapping[str, Any]) -> str:
    """``template`` filled with ``params`` in English, lists as :func:`listed` writes them."""
    return template.format_map(
        {k: listed(v) if isinstance(v, list | tuple) else v for k, v in params.items()}
    )
