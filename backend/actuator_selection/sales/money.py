"""Quote arithmetic in exact decimals: line totals, subtotal, discount, total.

Money is :class:`decimal.Decimal` from the price list to the response, never a
binary float. The rounding rule, stated once (``ROUNDING_RULE``):

1. each line total ``unit_price × quantity`` is rounded to cents, half up;
2. the subtotal is the sum of the rounded line totals (exact, no rounding);
3. the discount ``subtotal × percent / 100`` is rounded to cents, half up;
4. the total is ``subtotal − discount`` (exact).

So every figure printed on a quote is a whole number of cents and the printed
figures add up exactly. All currencies are kept to two decimal places.

>>> t = quote_totals(
...     [QuoteLine(unit_price=Decimal("1234.50"), quantity=2),
...      QuoteLine(unit_price=Decimal("99.99"), quantity=3)],
...     discount_percent=Decimal("7.5"))
>>> t.line_totals
(Decimal('2469.00'), Decimal('299.97'))
>>> t.subtotal, t.discount_amount, t.total
(Decimal('2768.97'), Decimal('207.67'), Decimal('2561.30'))
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from decimal import ROUND_HALF_UP, Decimal

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_

CENT = Decimal("0.01")
"""Smallest unit kept: every money amount is a whole number of cents."""
HUNDRED = Decimal(100)
MAX_AMOUNT = Decimal("999999999999.99")
"""Largest amount a price, line or total may reach (fits ``Numeric(14, 2)``)."""
MAX_QUANTITY = 1_000_000
"""Largest quantity of one quote line."""

ROUNDING_RULE = N_(
    "each line total (unit price × quantity) is rounded to cents, half up; the subtotal is "
    "their sum; the discount (subtotal × percent / 100) is rounded to cents, half up; "
    "total = subtotal − discount"
)

_CURRENCY = re.compile(r"[A-Z]{3}")
PLAIN_DECIMAL = re.compile(r"-?[0-9]+(\.[0-9]+)?")
"""Plain decimal notation of money and percentages: the ASCII digits 0–9 (``Decimal``
itself reads any script's digits, "١٢" as 12), no exponent, no NaN or infinity, no
thousands separators."""


def to_cents(amount: Decimal) -> Decimal:
    """``amount`` rounded to cents, half up (ties away from zero).

    >>> to_cents(Decimal("2.345")), to_cents(Decimal("2.344")), to_cents(Decimal("-2.345"))
    (Decimal('2.35'), Decimal('2.34'), Decimal('-2.35'))
    """
    return amount.quantize(CENT, rounding=ROUND_HALF_UP)


def parse_amount(text: str, *, field: str = "amount") -> Decimal:
    """A money amount from text: ≥ 0, finite, at most two decimal places, ≤ ``MAX_AMOUNT``.

    >>> parse_amount("1234.5")
    Decimal('1234.50')
    >>> parse_amount("-1")
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: amount: must be ≥ 0
    >>> parse_amount("0.001")
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: amount: must have at most 2 decimal places
    >>> parse_amount("9" * 5000)
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: amount: must be ≤ 999999999999.99
    """
    text = text.strip()
    if not PLAIN_DECIMAL.fullmatch(text):
        raise InvalidInputError(field, code="decimal_format")
    return check_amount(Decimal(text), field=field)


def check_amount(value: Decimal, *, field: str = "amount") -> Decimal:
    """``value`` as a whole number of cents, or :class:`InvalidInputError` naming the rule."""
    if not value.is_finite():
        raise InvalidInputError(field, code="decimal_finite")
    if value < 0:
        raise InvalidInputError(field, code="amount_negative")
    # The size first: quantizing a number of more than 28 digits ("9" × 5000 in a price
    # file) raises decimal.InvalidOperation instead of answering.
    if value > MAX_AMOUNT:
        raise InvalidInputError(field, code="amount_max", params={"max": MAX_AMOUNT})
    if value != value.quantize(CENT, rounding=ROUND_HALF_UP):
        raise InvalidInputError(field, code="cents")
    return value.quantize(CENT)


def check_percent(value: Decimal, *, field: str = "discount_percent") -> Decimal:
    """A percentage 0–100 with at most two decimal places.

    >>> check_percent(Decimal("12.5"))
    Decimal('12.50')
    >>> check_percent(Decimal("100.01"))
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: discount_percent: must be between 0 and 100
    """
    if not value.is_finite() or value < 0 or value > HUNDRED:
        raise InvalidInputError(field, code="percent_range")
    if value != value.quantize(CENT, rounding=ROUND_HALF_UP):
        raise InvalidInputError(field, code="cents")
    return value.quantize(CENT)


def check_currency(code: str, *, field: str = "currency") -> str:
    """An ISO 4217 alphabetic code: three capital letters (the form, not the registry).

    >>> check_currency("EUR")
    'EUR'
    >>> check_currency("eur")
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: currency: must be an ISO 4217 code of three capital letters such as EUR, got 'eur'
    """  # noqa: E501
    if not _CURRENCY.fullmatch(code):
        raise InvalidInputError(field, code="currency_code", params={"value": code})
    return code


def amount_cell(text: str) -> Decimal:
    """A price list cell's money amount (:class:`~actuator_selection.catalogue.csvio.Column`
    ``convert``): a decimal number ≥ 0 with at most two decimal places."""
    try:
        return parse_amount(text)
    except InvalidInputError as exc:
        raise ValueError(
            f"{exc.message} (a decimal amount ≥ 0 with at most 2 decimal places)"
        ) from None


def currency_cell(text: str) -> str:
    """A price list cell's currency (a ``convert`` likewise): an ISO 4217 code of three
    capital letters."""
    try:
        return check_currency(text)
    except InvalidInputError:
        raise ValueError("must be an ISO 4217 code of three capital letters such as EUR") from None


@dataclass(frozen=True, slots=True, kw_only=True)
class QuoteLine:
    """One priced line: unit price [currency, whole cents] and quantity [pieces, ≥ 1]."""

    unit_price: Decimal
    quantity: int

    def __post_init__(self) -> None:
        check_amount(self.unit_price, field="unit_price")
        if isinstance(self.quantity, bool) or not 1 <= self.quantity <= MAX_QUANTITY:
            raise InvalidInputError("quantity", code="quantity_range", params={"max": MAX_QUANTITY})


@dataclass(frozen=True, slots=True, kw_only=True)
class QuoteTotals:
    """The figures of a quote, each a whole number of cents."""

    line_totals: tuple[Decimal, ...]
    subtotal: Decimal
    discount_percent: Decimal
    discount_amount: Decimal
    total: Decimal


def line_total(line: QuoteLine) -> Decimal:
    """``unit_price × quantity`` rounded to cents, half up.

    >>> line_total(QuoteLine(unit_price=Decimal("0.10"), quantity=3))
    Decimal('0.30')
    """
    return to_cents(line.unit_price * line.quantity)


def quote_totals(lines: Sequence[QuoteLine], *, discount_percent: Decimal) -> QuoteTotals:
    """Line totals, subtotal, discount and total by ``ROUNDING_RULE``.

    A discount that lands on half a cent rounds up (the customer pays half a cent less):

    >>> t = quote_totals([QuoteLine(unit_price=Decimal("0.50"), quantity=1)],
    ...                  discount_percent=Decimal("1"))
    >>> t.discount_amount, t.total
    (Decimal('0.01'), Decimal('0.49'))
    >>> quote_totals([], discount_percent=Decimal(0)).total
    Decimal('0.00')
    """
    percent = check_percent(discount_percent)
    totals = tuple(line_total(line) for line in lines)
    subtotal = sum(totals, Decimal("0.00"))
    if subtotal > MAX_AMOUNT:
        raise InvalidInputError("items", code="subtotal_max", params={"max": MAX_AMOUNT})
    discount = to_cents(subtotal * percent / HUNDRED)
    return QuoteTotals(
        line_totals=totals,
        subtotal=subtotal,
        discount_percent=percent,
        discount_amount=discount,
        total=subtotal - discount,
    )
