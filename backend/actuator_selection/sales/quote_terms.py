"""Commercial terms of a quote: the seller, value-added tax, payment and delivery terms.

The VAT rule, stated once (``VAT_ROUNDING_RULE``) and printed on the document:

1. the net total is the quote's total after discount (``sales.money.ROUNDING_RULE``);
2. the VAT is ``net × rate / 100``, rounded **once** to cents, half up (on the net
   total, never line by line, so the printed figures add up);
3. the gross total is ``net + VAT`` (exact).

>>> t = tax_totals(Decimal("8861.50"), vat_percent=Decimal("19"))
>>> t.net, t.vat_percent, t.vat_amount, t.gross
(Decimal('8861.50'), Decimal('19.00'), Decimal('1683.69'), Decimal('10545.19'))

A VAT amount that lands on half a cent rounds up (away from zero):

>>> tax_totals(Decimal("0.50"), vat_percent=Decimal("1")).vat_amount
Decimal('0.01')
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import Decimal

from actuator_selection.errors import InvalidInputError
from actuator_selection.phrases.messages import N_
from actuator_selection.sales.money import (
    HUNDRED,
    MAX_AMOUNT,
    check_amount,
    check_percent,
    to_cents,
)

VAT_ROUNDING_RULE = N_(
    "VAT = net total × rate / 100, rounded once to cents, half up; gross total = net total + VAT"
)

LANGUAGES = ("en", "de")
"""The languages a quote document is written in; the first is the default."""


@dataclass(frozen=True, slots=True, kw_only=True)
class TaxTotals:
    """Net, VAT and gross of a quote [currency, whole cents]; ``vat_percent`` [%]."""

    net: Decimal
    vat_percent: Decimal
    vat_amount: Decimal
    gross: Decimal


def tax_totals(net: Decimal, *, vat_percent: Decimal) -> TaxTotals:
    """VAT and gross total of the net total ``net`` at ``vat_percent``, by ``VAT_ROUNDING_RULE``.

    Parameters
    ----------
    net
        The quote's total after discount [currency], a whole number of cents, ≥ 0.
    vat_percent
        The VAT rate [%], 0–100, at most two decimal places.

    >>> tax_totals(Decimal("100.00"), vat_percent=Decimal("0")).gross
    Decimal('100.00')
    >>> tax_totals(Decimal("100.00"), vat_percent=Decimal("101"))
    Traceback (most recent call last):
    ...
    actuator_selection.errors.InvalidInputError: vat_percent: must be between 0 and 100
    """
    rate = check_percent(vat_percent, field="vat_percent")
    amount = check_amount(net, field="total")
    vat = to_cents(amount * rate / HUNDRED)
    gross = amount + vat
    if gross > MAX_AMOUNT:
        raise InvalidInputError("vat_percent", f"the gross total must be ≤ {MAX_AMOUNT}")
    return TaxTotals(net=amount, vat_percent=rate, vat_amount=vat, gross=gross)


@dataclass(frozen=True, slots=True, kw_only=True)
class SellerParty:
    """Who makes the offer, as printed on the document's seller block.

    ``payment_terms`` and ``delivery_terms`` are the seller's standard terms by
    language (``LANGUAGES``): a quote that states none of its own shows these in the
    document's language.
    """

    name: str
    address: str
    vat_id: str
    email: str
    phone: str | None = None
    payment_terms: Mapping[str, str] = field(default_factory=dict)
    delivery_terms: Mapping[str, str] = field(default_factory=dict)

    def standard_terms(self, kind: str, language: str) -> str | None:
        """The standard ``kind`` (``payment`` or ``delivery``) terms in ``language``, else in
        the default language, else None.

        >>> s = SellerParty(name="S", address="A", vat_id="V", email="E",
        ...                 payment_terms={"en": "30 days net", "de": "30 Tage netto"})
        >>> s.standard_terms("payment", "de"), s.standard_terms("payment", "fr")
        ('30 Tage netto', '30 days net')
        >>> s.standard_terms("delivery", "de") is None
        True
        """
        texts = self.payment_terms if kind == "payment" else self.delivery_terms
        return texts.get(language) or texts.get(LANGUAGES[0])

    def to_json(self) -> dict[str, object]:
        """The seller as stored with a quote (a JSON object)."""
        return {
            "name": self.name,
            "address": self.address,
            "vat_id": self.vat_id,
            "email": self.email,
            "phone": self.phone,
            "payment_terms": dict(self.payment_terms),
            "delivery_terms": dict(self.delivery_terms),
        }

    @classmethod
    def from_json(cls, data: Mapping[str, object]) -> SellerParty:
        """A seller stored by :meth:`to_json`."""

        def texts(key: str) -> dict[str, str]:
            value = data.get(key)
            if not isinstance(value, Mapping):
                return {}
            return {str(k): str(v) for k, v in value.items()}

        phone = data.get("phone")
        return cls(
            name=str(data.get("name", "")),
            address=str(data.get("address", "")),
            vat_id=str(data.get("vat_id", "")),
            email=str(data.get("email", "")),
            phone=str(phone) if phone is not None else None,
            payment_terms=texts("payment_terms"),
            delivery_terms=texts("delivery_terms"),
        )


@dataclass(frozen=True, slots=True, kw_only=True)
class QuoteDefaults:
    """What a new quote takes when its request leaves it out: the VAT rate [%] and the
    seller (whose standard terms apply unless the request states its own)."""

    vat_percent: Decimal
    seller: SellerParty
