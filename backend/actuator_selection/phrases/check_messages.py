"""The flowchart's check messages: a stable code and parameters beside the English text.

A rule's message (:attr:`~actuator_selection.sizing.checks.Rule.message`) is a
:class:`Phrase`: a ``str`` holding the English text, as the checks have always said it,
that also carries :attr:`Phrase.code` (a name in :data:`CHECK_MESSAGES`, part of the
API contract: add codes, never rename or reuse one; a rule's templates are written
beside the rule, in ``sizing/checks/rules/``, and added by :func:`check_words`) and
:attr:`Phrase.params`, the values the template is filled with. The templates are
``str.format`` strings with format specs (``{value:.4g}``) and the msgids of the gettext
catalogs: the API renders them in the request's language (``i18n/localize.py``,
:func:`render` with a language's number format and translations).

A parameter is a number (in the unit its name or the check gives), a :class:`Text`
(English words, translated where rendered), a nested :class:`Phrase` (a clause of its
own code and params), a list of such (written joined by ", "; a tuple, alternatives,
by " / "), or None (a clause left out: rendered as nothing).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Callable, Iterable, Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar
from typing import Any, Final

from actuator_selection.phrases.messages import N_, Text


class Phrase(str):
    """English text with the code and params it was rendered from (:func:`phrase`)."""

    code: str
    params: Mapping[str, Any]

    def __new__(cls, code: str, params: Mapping[str, Any]) -> Phrase:
        if _CODES_ONLY.get():  # the English text is not read (codes_only)
            text = str.__new__(cls)
            text.code = code
            text.params = params
            return text
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


_CODES_ONLY: ContextVar[bool] = ContextVar("codes_only", default=False)


@contextmanager
def codes_only() -> Iterator[None]:
    """Within it, a :class:`Phrase` carries its code and params only, its text empty: for
    an answer that gives the messages as codes and params and never reads their words (a
    batch without ``include_messages``: writing 240,000 checks' English text cost more
    than the engineering). Nothing made within it may outlive the answer it is made for."""
    token = _CODES_ONLY.set(True)
    try:
        yield
    finally:
        _CODES_ONLY.reset(token)


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

NumberFormats = Callable[[list[float], str], list[str]]
"""A :data:`NumberFormat` over many values with one format spec, in one call."""


class Renderer:
    """The check messages in one language: ``str.format`` whose fields are numbers, words
    and clauses, each written in that language. Called with a message, it renders a
    :class:`Phrase` and leaves any other text as it is; a batch that words many cells of
    one message at once reads a code's :meth:`template` and writes each field by
    :meth:`format_field` (``services/presenters/batch_messages.py``)."""

    def __init__(
        self,
        translate: Callable[[str], str],
        number: NumberFormat | None,
        numbers: NumberFormats | None = None,
    ) -> None:
        self._translate = translate
        self._number = number
        self._numbers = numbers

    def __call__(self, message: str) -> str:
        return self.render(message) if isinstance(message, Phrase) else message

    def template(self, code: str) -> str:
        """The template of the message ``code`` in this language."""
        return self._translate(CHECK_MESSAGES[code])

    def numbers(self, values: list[float], spec: str) -> list[str]:
        """Each of ``values`` (floats) as :meth:`format_field` writes it with ``spec``."""
        if self._number is None:
            return list(map(format, values, itertools.repeat(spec)))
        if self._numbers is not None:
            return self._numbers(values, spec)
        number = self._number
        return [number(v, spec) for v in values]

    def format_field(self, value: Any, format_spec: str) -> str:
        """One param of a message as this language writes it, by the template's spec."""
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
        """``message`` in this language."""
        # str.format_map in C, each field written by format_field through _Field.__format__
        # (string.Formatter would parse the template in Python on every call).
        fields = {k: _Field(self, v) for k, v in message.params.items()}
        return self.template(message.code).format_map(fields)


class _Field:
    """One parameter of a message, written by its renderer in the template's format spec."""

    __slots__ = ("_renderer", "_value")

    def __init__(self, renderer: Renderer, value: Any) -> None:
        self._renderer, self._value = renderer, value

    def __format__(self, format_spec: str) -> str:
        return self._renderer.format_field(self._value, format_spec)


def renderer(
    *,
    translate: Callable[[str], str],
    number: NumberFormat | None = None,
    numbers: NumberFormats | None = None,
) -> Renderer:
    """A message with its template and words passed through ``translate`` and its
    numbers written by ``number`` (``format(value, spec)`` where None; ``numbers``, the
    same over many values at once, where given); a message that is no :class:`Phrase`
    (a rule written elsewhere) stays as it is."""
    return Renderer(translate, number, numbers)


class Wording:
    """A language's words for the check messages: called with a message, its text (a
    schema's ``localize``, ``i18n.localize.Localizer``); its renderer (:attr:`phrases`)
    words many cells of one message at once (a batch's, from the engine's arrays)."""

    __slots__ = ("phrases",)

    def __init__(self, phrases: Renderer) -> None:
        self.phrases = phrases

    def __call__(self, message: str) -> str:
        return self.phrases(message)


ENGLISH: Final = Renderer(str, None)
"""The messages in English: each :class:`Phrase` as its own text reads (a test holds
the two to the same words)."""


def jsonable_params(message: str) -> dict[str, Any] | None:
    """The params of ``message`` as JSON carries them: clauses as ``{"code", "params"}``,
    words as their English text, ±∞ and NaN as text; None for a message without a code."""
    if not isinstance(message, Phrase):
        return None
    params = message.params
    out = dict(params)  # most params are finite numbers, kept as they are
    for k, v in params.items():
        if type(v) is not float or v - v != 0.0:  # inf − inf, NaN − NaN: NaN
            out[k] = jsonable(v)
    return out


def jsonable(value: Any) -> Any:
    """A param as JSON carries it (:func:`jsonable_params`)."""
    kind = type(value)
    if kind is float:  # most params: a finite number, as it is
        return value if value - value == 0.0 else repr(value)  # inf − inf, NaN − NaN: NaN
    if isinstance(value, Phrase):
        return {"code": value.code, "params": jsonable_params(value)}
    if isinstance(value, list | tuple):
        return [jsonable(v) for v in value]
    if isinstance(value, str):
        return str(value)
    if isinstance(value, float):
        return value if math.isfinite(value) else repr(value)
    return value


CHECK_MESSAGES: Final[dict[str, str]] = {}
"""Code → English template of every check message (and of the clauses they hold): each
rule's words beside the rule (``sizing/checks/rules/``), the rest below; each added once by
:func:`check_words`."""

CHECK_WORDS: Final[list[str]] = []
"""Words the check messages take as params (:class:`Text`), added beside the rules that
use them; a requirement's ``what`` is marked where it is written."""


def check_words(templates: Mapping[str, str], *, words: Iterable[str] = ()) -> None:
    """Add ``templates`` (code → English template, each marked ``N_`` for extraction) to
    :data:`CHECK_MESSAGES` and ``words`` to :data:`CHECK_WORDS`. A code is added once:
    codes are part of the API contract, never renamed or reused."""
    for code, template in templates.items():
        if code in CHECK_MESSAGES:
            raise ValueError(f"check message {code!r} is added twice")
        CHECK_MESSAGES[code] = template
    CHECK_WORDS.extend(words)


_OTHERS: Final = {
    # Table 521.1: one criterion of one controller (sizing/compatibility.py)
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
    # U_OUT of Eq. 521.2 against a DC bus class (sizing/electrical.py, sizing/drive.py)
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
    # Why a limit of the inverse solve has no value (sizing/inverse.py); {check}: the
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
    "stored.not_applicable": N_(
        "not applicable: the check's premise does not hold for this actuator or case"
    ),
}
"""The messages that are no rule's: of the controllers, the output bearing, the inverse
solve and stored answers (code → English template, the gettext msgid)."""

check_words(_OTHERS)
