"""Quote arithmetic: exact decimals, cents rounded half up, figures that add up."""

from __future__ import annotations

from decimal import Decimal

import pytest

from actuator_selection.errors import InvalidInputError
from actuator_selection.sales.money import (
    MAX_AMOUNT,
    QuoteLine,
    check_currency,
    check_percent,
    line_total,
    parse_amount,
    quote_totals,
    to_cents,
)


def d(text: str) -> Decimal:
    return Decimal(text)


@pytest.mark.parametrize(
    ("amount", "cents"),
    [
        ("0.005", "0.01"),  # half up, not half even (which gives 0.00)
        ("0.015", "0.02"),
        ("0.025", "0.03"),  # half even would give 0.02
        ("2.675", "2.68"),  # as a binary float 2.675 is 2.67499…; here it is exact
        ("0.0049999", "0.00"),
        ("-0.005", "-0.01"),
        ("1234.5", "1234.50"),
    ],
)
def test_to_cents_rounds_half_up(amount: str, cents: str) -> None:
    assert to_cents(d(amount)) == d(cents)
    assert str(to_cents(d(amount))) == cents


def test_line_total_multiplies_exactly() -> None:
    # 0.1 + 0.2 and friends: exact in Decimal.
    assert line_total(QuoteLine(unit_price=d("0.10"), quantity=3)) == d("0.30")
    assert line_total(QuoteLine(unit_price=d("19.99"), quantity=1000)) == d("19990.00")


def test_totals_add_up_and_round_the_discount_once() -> None:
    lines = [
        QuoteLine(unit_price=d("2950.00"), quantity=2),
        QuoteLine(unit_price=d("1840.00"), quantity=2),
    ]
    t = quote_totals(lines, discount_percent=d("7.5"))
    assert t.line_totals == (d("5900.00"), d("3680.00"))
    assert (t.subtotal, t.discount_amount, t.total) == (d("9580.00"), d("718.50"), d("8861.50"))
    assert t.discount_percent == d("7.50")
    # 8850.00 × 33.33 % = 2949.705 → 2949.71 (half up); total = subtotal − discount exactly.
    t = quote_totals([QuoteLine(unit_price=d("2950.00"), quantity=3)], discount_percent=d("33.33"))
    assert (t.discount_amount, t.total) == (d("2949.71"), d("5900.29"))
    assert t.subtotal - t.discount_amount == t.total


@pytest.mark.parametrize("percent", ["0", "100", "0.01", "99.99"])
def test_discount_bounds_are_inclusive(percent: str) -> None:
    t = quote_totals([QuoteLine(unit_price=d("10.00"), quantity=1)], discount_percent=d(percent))
    assert d("0.00") <= t.total <= d("10.00")
    if percent == "100":
        assert t.total == d("0.00")


@pytest.mark.parametrize("percent", ["-0.01", "100.01", "5.555", "NaN", "Infinity"])
def test_bad_discount_is_refused(percent: str) -> None:
    with pytest.raises(InvalidInputError) as caught:
        check_percent(d(percent))
    assert caught.value.field == "discount_percent"


@pytest.mark.parametrize(
    ("text", "rule", "code"),
    [
        ("-1", "≥ 0", "amount_negative"),
        ("1.001", "2 decimal places", "cents"),
        ("1e3", "such as 1234.50", "decimal_format"),
        ("NaN", "such as 1234.50", "decimal_format"),
        ("1,000.00", "such as 1234.50", "decimal_format"),
        ("", "such as 1234.50", "decimal_format"),
        (str(MAX_AMOUNT + 1), "≤", "amount_max"),
    ],
)
def test_bad_amounts_are_refused(text: str, rule: str, code: str) -> None:
    with pytest.raises(InvalidInputError) as caught:
        parse_amount(text, field="unit_price")
    assert caught.value.field == "unit_price"
    assert rule in caught.value.message
    assert caught.value.code == code  # the rule by name, for the API's words


def test_amount_text_keeps_cents() -> None:
    assert str(parse_amount(" 12 ")) == "12.00"
    assert str(parse_amount("0.5")) == "0.50"


@pytest.mark.parametrize("quantity", [0, -1, 1_000_001])
def test_quantity_must_be_a_positive_count(quantity: int) -> None:
    with pytest.raises(InvalidInputError):
        QuoteLine(unit_price=d("1.00"), quantity=quantity)


def test_unit_price_must_be_whole_cents() -> None:
    with pytest.raises(InvalidInputError):
        QuoteLine(unit_price=d("1.001"), quantity=1)


def test_subtotal_bound() -> None:
    with pytest.raises(InvalidInputError):
        quote_totals([QuoteLine(unit_price=MAX_AMOUNT, quantity=2)], discount_percent=d("0"))


@pytest.mark.parametrize("code", ["EUR", "USD", "CHF", "JPY"])
def test_currency_codes(code: str) -> None:
    assert check_currency(code) == code


@pytest.mark.parametrize("code", ["eur", "EURO", "EU", "€", "E1R", ""])
def test_bad_currency_codes(code: str) -> None:
    with pytest.raises(InvalidInputError):
        check_currency(code)
