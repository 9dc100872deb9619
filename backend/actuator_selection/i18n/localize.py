"""Error messages in the request's language: negotiation, catalogs, templates, rendering.

Every entry of an error answer carries ``code`` (a stable name of the rule, for programs)
and ``params`` (the values the message names, e.g. ``{"ge": 0.0001, "unit": "s"}``)
beside ``msg``; ``msg`` is the rule's template rendered in the language that
``Accept-Language`` asks for (:data:`LANGUAGES`, English by default). Numbers follow the
language (``0,0001`` in German) and units the chapter (``min⁻¹`` where English says
``rpm``); ``params`` are the same in every language.

The templates are English ``str.format`` strings; they are the msgids of the gettext
catalogs in ``actuator_selection/i18n/locale/<lang>/LC_MESSAGES/messages.po``, which also
hold the page's and the documents' labels as keyed words (:func:`words`,
``docs/i18n.md``). The catalogs are read as they are when first needed (no compiled
``.mo``: nothing to build, nothing to go stale). ``pybabel extract`` collects every
template marked with ``N_`` (``babel.cfg``, README "Messages in the user's language").

A message without a template (free text from a use case) keeps its English text; its
``code`` is its ``type`` and its ``params`` are empty.
"""

from __future__ import annotations

import functools
import itertools
import math
import re
from collections.abc import Iterable, Mapping, Sequence
from decimal import Decimal
from pathlib import Path
from typing import Any, Final

from babel import Locale
from babel.messages.catalog import Catalog
from babel.messages.pofile import read_po
from babel.numbers import format_decimal, format_scientific
from werkzeug.datastructures import LanguageAccept
from werkzeug.http import parse_accept_header

from actuator_selection.phrases import check_messages
from actuator_selection.phrases.check_messages import CHECK_MESSAGES, CHECK_WORDS
from actuator_selection.phrases.messages import MESSAGES as DOMAIN_MESSAGES
from actuator_selection.phrases.messages import N_, Text, listed
from actuator_selection.schemas.mechanisms import MECHANISM_TYPES
from actuator_selection.schemas.quantities import QUANTITY_MESSAGES
from actuator_selection.schemas.quotes import DECIMAL_TEXT_RULE, PROJECT_OR_SELECTION
from actuator_selection.schemas.selections import LOAD_TYPES
from actuator_selection.services.messages import CONTROLLER_RULE, PRICE_KINDS, USE_CASE_MESSAGES
from actuator_selection.sizing.checks import ALL_RULES

LANGUAGES: Final = ("en", "de")
"""The languages of the messages; the first is the default."""

DEFAULT_LANGUAGE: Final = LANGUAGES[0]

LOCALE_DIR: Final = Path(__file__).resolve().parent / "locale"
"""``<lang>/LC_MESSAGES/messages.po`` for each language but English (the msgids)."""

DOMAIN: Final = "messages"


def negotiate(accept_language: str | None) -> str:
    """The language of :data:`LANGUAGES` that ``Accept-Language`` prefers, else English.

    Quality values order the header (werkzeug parses it); Babel matches each tag to the
    languages offered, a region falling back to its language (``de-CH`` → ``de``).

    >>> negotiate("de-DE"), negotiate("fr, de;q=0.5"), negotiate("fr"), negotiate(None)
    ('de', 'de', 'en', 'en')
    >>> negotiate("de;q=0.8, en;q=0.9"), negotiate("en-GB, de;q=0.1"), negotiate("de;q=0")
    ('en', 'en', 'en')
    """
    if not accept_language:
        return DEFAULT_LANGUAGE
    accepted = parse_accept_header(accept_language, LanguageAccept)
    preferred = [tag for tag, quality in accepted if quality > 0 and tag != "*"]
    locale = Locale.negotiate(preferred, LANGUAGES, sep="-")
    return locale.language if locale is not None else DEFAULT_LANGUAGE


def catalog_path(language: str) -> Path:
    """The ``.po`` file of ``language``."""
    return LOCALE_DIR / language / "LC_MESSAGES" / f"{DOMAIN}.po"


SOURCE_CATALOG: Final = "de"
"""The catalog whose msgids (English) also declare the keyed words (:func:`words`)."""

PLOTLY: Final = "plotly"
"""The context of plotly.js's own words (msgid its English; ``i18n/page_words.py``)."""


@functools.cache
def catalog(language: str) -> Catalog:
    """``language``'s catalog as it is written (read once)."""
    with catalog_path(language).open("rb") as file:
        return read_po(file, locale=language, domain=DOMAIN)


@functools.cache
def translations(language: str) -> Mapping[str, str]:
    """msgid → translation of ``language``'s catalog (empty for English, the msgids), of
    the messages without a context (the templates marked with ``N_``)."""
    if language == DEFAULT_LANGUAGE:
        return {}
    return {
        str(m.id): str(m.string)
        for m in catalog(language)
        if m.id and isinstance(m.id, str) and m.string and not m.fuzzy and not m.context
    }


@functools.cache
def words(language: str) -> Mapping[str, str]:
    """Key (msgctxt) → text in ``language`` of the keyed words: the page's
    (``frontend/lib/messages.js`` is exported from them) and the documents'. English is
    the msgid, another language its catalog's translation.

    >>> words("en")["document.heading"], words("de")["document.heading"]
    ('Quotation', 'Angebot')
    """
    if language == DEFAULT_LANGUAGE:
        source = catalog(SOURCE_CATALOG)
        return {
            m.context: str(m.id)
            for m in source
            if m.context and m.context != PLOTLY and isinstance(m.id, str)
        }
    return {
        m.context: str(m.string)
        for m in catalog(language)
        if m.context
        and m.context != PLOTLY
        and isinstance(m.string, str)
        and m.string
        and not m.fuzzy
    }


REFERENCE_KEY: Final = "ref."
"""The keyed words of a reference (``ref.Table`` → ``Tabelle``): which words of a stored
reference are translated is what the catalogue holds under this prefix, nothing else."""


@functools.cache
def reference_pattern() -> str:
    """The regular expression (valid in Python and in JavaScript) matching each word or
    phrase of a reference that the catalogue translates (:data:`REFERENCE_KEY`), the
    longest first, standing alone (``p.`` in ``p. 68``, not in ``Sp. 68``).

    The one rule for the page (exported to ``frontend/lib/messages.js``) and the documents.

    >>> import re
    >>> re.findall(reference_pattern(), "FHA-C manual ch. 2, formula (1); Table 515.1, p. 18")
    ['manual', 'ch.', 'formula', 'Table', 'p.']
    >>> re.findall(reference_pattern(), "Fig. 520.1 (model); Eq. 514.2; Tables")
    ['Fig.', 'model', 'Eq.']
    """
    keys = (key for key in words(DEFAULT_LANGUAGE) if key.startswith(REFERENCE_KEY))
    phrases = sorted((key.removeprefix(REFERENCE_KEY) for key in keys), key=lambda p: (-len(p), p))
    # Escapes both languages read alike (Python's re.escape also escapes spaces, which
    # JavaScript's unicode mode refuses).
    escaped = (re.sub(r"[.*+?^${}()|[\]\\]", r"\\\g<0>", phrase) for phrase in phrases)
    return r"(?<![\w.])(?:" + "|".join(escaped) + r")(?![\w])"


def word(key: str, language: str) -> str:
    """The keyed word ``key`` in ``language`` (:func:`words`); KeyError where the catalog
    has none (a test holds every key the code and the page use against the catalog)."""
    return words(language)[key]


def translate(text: str, language: str) -> str:
    """``text`` in ``language``; the English text where the catalog has none."""
    return translations(language).get(text, text)


# --- templates ------------------------------------------------------------------------

UNIT_KEY: Final = "unit"
"""The parameter naming a unit ("rpm", "s", "kgm²"); shown as the language writes it."""

UNIT_LABELS: Final = (N_("rpm"),)
"""Units written differently in another language (German: min⁻¹ as in the chapter)."""

_UNIT_SUFFIXES: Final = (
    ("_kgm2", "kgm²"),
    ("_rpm", "rpm"),
    ("_nm", "Nm"),
    ("_mm", "mm"),
    ("_kg", "kg"),
    ("_deg", "°"),
    ("_ohm", "Ω"),
    ("_mh", "mH"),
    ("_percent", "%"),
    ("_s", "s"),
    ("_n", "N"),
    ("_m", "m"),
    ("_v", "V"),
    ("_a", "A"),
    ("_c", "°C"),
)
"""A field's unit from its name (house style: units in names, ``accel_s``, ``torque_nm``)."""

BOUND_MESSAGES: Final[Mapping[str, tuple[str, str]]] = {
    "greater_than": (
        N_("Input should be greater than {gt}"),
        N_("Input should be greater than {gt} {unit}"),
    ),
    "greater_than_equal": (
        N_("Input should be greater than or equal to {ge}"),
        N_("Input should be greater than or equal to {ge} {unit}"),
    ),
    "less_than": (
        N_("Input should be less than {lt}"),
        N_("Input should be less than {lt} {unit}"),
    ),
    "less_than_equal": (
        N_("Input should be less than or equal to {le}"),
        N_("Input should be less than or equal to {le} {unit}"),
    ),
}
"""pydantic's bounds: without and with the field's unit."""

CONVERTED_SUFFIX: Final = N_("{bound}: '{given}' is {converted} {unit}")
"""A bound broken by a value given with a unit (``schemas.quantities.InUnit``)."""

PYDANTIC_MESSAGES: Final[Mapping[str, str]] = {
    "missing": N_("Field required"),
    "extra_forbidden": N_("Extra inputs are not permitted"),
    "float_parsing": N_("Input should be a valid number, unable to parse string as a number"),
    "float_type": N_("Input should be a valid number"),
    "int_type": N_("Input should be a valid integer"),
    "int_parsing": N_("Input should be a valid integer, unable to parse string as an integer"),
    "int_from_float": N_("Input should be a valid integer, got a number with a fractional part"),
    "bool_type": N_("Input should be a valid boolean"),
    "bool_parsing": N_("Input should be a valid boolean, unable to interpret input"),
    "string_type": N_("Input should be a valid string"),
    "list_type": N_("Input should be a valid list"),
    "dict_type": N_("Input should be a valid dictionary"),
    "model_type": N_("Input should be a valid dictionary or instance of {class_name}"),
    "model_attributes_type": N_(
        "Input should be a valid dictionary or object to extract fields from"
    ),
    "finite_number": N_("Input should be a finite number"),
    "literal_error": N_("Input should be one of {expected}"),
    "enum": N_("Input should be one of {expected}"),
    "string_too_short": N_("String should have at least {min_length} characters"),
    "string_too_long": N_("String should have at most {max_length} characters"),
    "too_short": N_("Should have at least {min_length} items, not {actual_length}"),
    "too_long": N_("Should have at most {max_length} items, not {actual_length}"),
    "json_invalid": N_("Invalid JSON: {error}"),
    "union_tag_invalid": N_(
        "Input tag '{tag}' found using {discriminator} does not match any of the "
        "expected tags: {expected_tags}"
    ),
    "union_tag_not_found": N_("Unable to extract tag using discriminator {discriminator}"),
    "load_type": N_("type must be one of {expected}"),
    "mechanism_type": N_("type must be one of {expected}"),
    "cycle_form": N_("cycle must be the t_1…t_p pattern, a list of segments or a profile's id"),
    "decimal_text": DECIMAL_TEXT_RULE,
    "quote_source": PROJECT_OR_SELECTION,
}
"""pydantic's error types (and the schemas' own) → template over their ``ctx``."""

_FIXED_PARAMS: Final[Mapping[str, Mapping[str, Any]]] = {
    "load_type": {"expected": list(LOAD_TYPES)},
    "mechanism_type": {"expected": list(MECHANISM_TYPES)},
}
"""Parameters of the schemas' custom errors, whose ``ctx`` pydantic leaves empty."""

SERVICE_MESSAGES: Final[Mapping[str, str]] = {
    "route_not_found": N_("no such resource: {path}"),
    "method_not_allowed": N_("method {method} is not allowed here; allowed: {allowed}"),
    "json_invalid": N_("the body could not be parsed as JSON (malformed, or nested too deeply)"),
    "body_too_large": N_("the request body is larger than {limit} bytes; send less per request"),
    "body_too_large_no_limit": N_(
        "the request body is larger than the limit; send less per request"
    ),
    "request_timeout": N_(
        "the request body did not arrive within {timeout_s} s; send it in one go"
    ),
    "database_unreachable": N_(
        "the database is unreachable; nothing was changed, retry after {retry_after_s} s"
    ),
    "service_unavailable": N_("{reason}; nothing was changed, retry after {retry_after_s} s"),
    "write_conflict": N_(
        "a concurrent change wrote the same record first; nothing was changed by this "
        "request, send it again"
    ),
    "internal_error": N_("internal error; it has been logged"),
    "unauthorized": N_("a valid API key is required: send Authorization: Bearer <key>"),
    "forbidden": N_("this API key has the role '{role}'; this needs {roles}"),
    "unsupported_media_type": N_("Content-Type {given} is not accepted here; send {accepted}"),
    "media_type_missing": N_("the body has no Content-Type; send {accepted}"),
    "unsupported_charset": N_("the body is encoded as {charset}; send it as UTF-8"),
    "too_many_failed_keys": N_(
        "too many wrong API keys from this address; retry after {retry_after_s} s"
    ),
    **USE_CASE_MESSAGES,
}
"""The service's own messages by code: the routers' (``api/``) and the use cases'
(``services/messages.py``)."""

REASONS: Final = (N_("the database is busy"), N_("the service is at capacity"))
"""The reasons of a 503 (``service_unavailable``)."""


def all_templates() -> dict[str, str]:
    """Every template the error answers render, by ``<group>:<code>`` (for the tests)."""
    templates = {f"domain:{c}": t for c, t in DOMAIN_MESSAGES.items()}
    templates |= {f"service:{c}": t for c, t in SERVICE_MESSAGES.items()}
    templates |= {f"pydantic:{c}": t for c, t in PYDANTIC_MESSAGES.items()}
    for code, (plain, with_unit) in BOUND_MESSAGES.items():
        templates |= {f"pydantic:{code}": plain, f"pydantic:{code}+unit": with_unit}
    templates |= {f"quantity:{t}:{r}": m for (t, r), m in QUANTITY_MESSAGES.items()}
    templates["converted"] = CONVERTED_SUFFIX
    templates |= {f"unit:{u}": u for u in UNIT_LABELS}
    templates |= {f"reason:{r}": r for r in REASONS}
    templates |= {f"word:{w}": w for w in (*PRICE_KINDS.values(), CONTROLLER_RULE)}
    return templates


# --- rendering ------------------------------------------------------------------------


LARGEST_PLAIN_NUMBER: Final = 1e15
"""Numbers of this size and beyond are shown in scientific notation (``1E30``): written
out, 1e30 is 31 digits, and Babel cannot write a number of more digits than the decimal
context's 28 (it raised, and a message about a value of 1e30 kg became a 500)."""


def _number(value: float | Decimal, language: str) -> str:
    """``value`` as ``language`` writes it: ``0,0001`` in German, ``1.5E26`` when large.

    >>> _number(0.0001, "de"), _number(1e30, "en"), _number(1.5e26, "de")
    ('0,0001', '1E30', '1,5E26')
    """
    if not math.isfinite(value):
        return repr(value)
    if abs(float(value)) >= LARGEST_PLAIN_NUMBER:
        return str(format_scientific(value, locale=language, decimal_quantization=False))
    return str(
        format_decimal(value, locale=language, decimal_quantization=False, group_separator=False)
    )


def _shown(key: str, value: Any, language: str) -> str:
    """One parameter as the message shows it in ``language``."""
    if isinstance(value, Text) or (key == UNIT_KEY and isinstance(value, str)):
        return translate(value, language)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float | Decimal):
        return _number(value, language)
    if isinstance(value, list | tuple):
        return listed(value, lambda v: _shown(key, v, language))
    return str(value)


def render(template: str, params: Mapping[str, Any], language: str) -> str:
    """``template`` in ``language``, filled with ``params``."""
    shown = {k: _shown(k, v, language) for k, v in params.items()}
    return translate(template, language).format_map(shown)


def jsonable(params: Mapping[str, Any]) -> dict[str, Any]:
    """``params`` as JSON can carry them: words as plain text, ±∞ and NaN as text, other
    objects (an exception in pydantic's ``ctx``) by their text."""

    def one(value: Any) -> Any:
        if isinstance(value, str):
            return str(value)
        if isinstance(value, float) and not math.isfinite(value):
            return repr(value)
        if value is None or isinstance(value, bool | int | float):
            return value
        if isinstance(value, list | tuple):
            return [one(v) for v in value]
        return str(value)

    return {k: one(v) for k, v in params.items()}


def unit_of(loc: Iterable[str | int]) -> str | None:
    """The unit of the field ``loc`` ends at, from its name; None where it has none.

    >>> unit_of(["body", "cycle", "accel_s"]), unit_of(["body", "load", "speed_rpm"])
    ('s', 'rpm')
    >>> unit_of(["body", "cycle", "segments", 0, "jerk_share"]) is None
    True
    """
    names = [part for part in loc if isinstance(part, str)]
    if not names:
        return None
    name = names[-1]
    return next((unit for suffix, unit in _UNIT_SUFFIXES if name.endswith(suffix)), None)


_QUOTED = re.compile(r"'((?:[^'\\]|\\.)*)'|(-?\d+(?:\.\d+)?)")


def _choices(expected: str) -> list[str]:
    """The values pydantic lists in ``ctx["expected"]``: "'a', 'b' or 'c'" → a, b, c."""
    return [quoted or number for quoted, number in _QUOTED.findall(expected)]


def pydantic_message(
    loc: Sequence[str | int], error: Mapping[str, Any], language: str
) -> tuple[str, dict[str, Any], str]:
    """``code``, ``params`` and ``msg`` in ``language`` of one of pydantic's errors.

    ``code`` is pydantic's ``type`` and ``params`` its ``ctx`` (bounds gain the field's
    unit, choices become a list). An error without a template here (a ``value_error``
    a validator words itself) keeps pydantic's English text and has no params.
    """
    code = str(error["type"])
    params: dict[str, Any] = {**_FIXED_PARAMS.get(code, {}), **(error.get("ctx") or {})}
    if code in ("literal_error", "enum") and isinstance(params.get("expected"), str):
        params["expected"] = _choices(params["expected"])
    template: str | None
    if code in BOUND_MESSAGES:
        plain, with_unit = BOUND_MESSAGES[code]
        unit = params.get(UNIT_KEY) or unit_of(loc)
        template = plain
        if unit is not None:
            params[UNIT_KEY] = unit
            template = with_unit
        if "given" in params:  # a value given with a unit, converted to the field's unit
            bound = render(template, params, language)
            return code, params, render(CONVERTED_SUFFIX, {**params, "bound": bound}, language)
    elif (code, params.get("rule")) in QUANTITY_MESSAGES:
        template = QUANTITY_MESSAGES[code, params["rule"]]
    else:
        template = PYDANTIC_MESSAGES.get(code)
    if template is None:
        return code, {}, str(error["msg"])
    return code, params, render(template, params, language)


def localized(entry: Mapping[str, Any], language: str) -> dict[str, Any]:
    """An error entry as it is sent: ``msg`` in ``language`` where the entry has a template
    (the private key ``_template``), ``code`` (its ``type`` where it has none) and
    ``params`` as JSON."""
    out = {k: v for k, v in entry.items() if k != "_template"}
    params = entry.get("params") or {}
    template = entry.get("_template")
    if isinstance(template, str):
        out["msg"] = render(template, params, language)
    out["code"] = entry.get("code") or entry.get("type")
    out["params"] = jsonable(params)
    return out


# --- the flowchart's check messages ---------------------------------------------------


def check_templates() -> dict[str, str]:
    """Every template and word of the check messages (``phrases/check_messages.py``) and the
    catalogue values the rules name where data is missing, by ``<group>:<code>`` (for the
    tests). Their templates carry format specs (``{value:.4g}``), which
    :func:`render_check` follows."""
    templates = {f"check:{c}": t for c, t in CHECK_MESSAGES.items()}
    templates |= {f"check_word:{w}": w for w in CHECK_WORDS}
    for rule in ALL_RULES:
        templates |= {f"check_word:{need.what}": need.what for need in rule.requires}
    return templates


def _spec_number(language: str) -> check_messages.NumberFormat:
    """Numbers of a check message as ``language`` writes them: rounded by the template's
    format spec as English rounds them, then written by Babel (decimal comma in German)."""

    def number(value: float, spec: str) -> str:
        english = format(value, spec)
        if language == DEFAULT_LANGUAGE:
            return english
        if not math.isfinite(value):
            return _not_finite(value, english)
        return _decimal_in(english, language)

    return number


def _spec_numbers(language: str) -> check_messages.NumberFormats:
    """:func:`_spec_number` over many values with one spec (a batch's column): the same
    texts, in one call for all of them."""

    def numbers(values: list[float], spec: str) -> list[str]:
        english = list(map(format, values, itertools.repeat(spec)))
        if language == DEFAULT_LANGUAGE:
            return english
        return [
            _decimal_in(text, language) if value - value == 0.0 else _not_finite(value, text)
            for value, text in zip(values, english, strict=True)
        ]  # value − value is NaN for ±∞ and NaN, 0 for every finite value

    return numbers


def _not_finite(value: float, english: str) -> str:
    """±∞ as a sign and ∞ in every language; NaN as English writes it."""
    return "∞" if value > 0 else "−∞" if value < 0 else english


@functools.lru_cache(maxsize=1 << 16)
def _decimal_in(english: str, language: str) -> str:
    """A number written in English (digits rounded by a format spec) as ``language``
    writes it (Babel). Kept per number: a batch writes the same limits thousands of times,
    and Babel takes ~20 µs a number."""
    return str(
        format_decimal(
            Decimal(english),
            locale=_locale(language),
            decimal_quantization=False,
            group_separator=False,
        )
    )


_locale = functools.cache(Locale.parse)
"""A language's Babel locale, parsed once."""


def render_check(message: str, language: str) -> str:
    """A check's message (or a candidate's reason) in ``language``; the English text where
    the language is English or the message has no code."""
    if language == DEFAULT_LANGUAGE:
        return message
    return _check_renderer(language)(message)


@functools.cache
def _check_renderer(language: str) -> check_messages.Renderer:
    """The check messages' renderer of ``language``, made once."""
    return check_messages.renderer(
        translate=functools.partial(translate, language=language),
        number=_spec_number(language),
        numbers=_spec_numbers(language),
    )


class Localizer(check_messages.Wording):
    """:func:`render_check` in one language (a schema's ``localize``), with the renderer
    that words its messages (:attr:`phrases`): a batch writes many cells' words at once
    from a message's template."""

    __slots__ = ("language",)

    def __init__(self, language: str) -> None:
        super().__init__(
            check_messages.ENGLISH if language == DEFAULT_LANGUAGE else _check_renderer(language)
        )
        self.language = language

    def __call__(self, message: str) -> str:
        return render_check(message, self.language)


def localizer(language: str) -> Localizer:
    """:func:`render_check` in ``language``, for the schemas' ``localize``."""
    return Localizer(language)
