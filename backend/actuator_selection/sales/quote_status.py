"""The life of a quote: draft → sent → accepted or rejected; expired after its validity.

``expired`` is never stored: a draft or sent quote whose last valid day
(``valid_until``, inclusive) lies before today *is* expired, whatever the
stored status says, and can then no longer change. Accepted and rejected are
final. Every other move is illegal.

>>> effective_status(QuoteStatus.SENT, valid_until=date(2026, 12, 31), today=date(2027, 1, 1))
<QuoteStatus.EXPIRED: 'expired'>
>>> transition(QuoteStatus.SENT, QuoteStatus.ACCEPTED,
...            valid_until=date(2026, 12, 31), today=date(2026, 12, 31))
<QuoteStatus.ACCEPTED: 'accepted'>
>>> transition(QuoteStatus.DRAFT, QuoteStatus.ACCEPTED,
...            valid_until=date(2026, 12, 31), today=date(2026, 12, 1))
Traceback (most recent call last):
...
actuator_selection.sales.quote_status.IllegalTransitionError: status: a quote in status 'draft' cannot move to 'accepted'; allowed: 'sent'
"""  # noqa: E501

from __future__ import annotations

from datetime import date
from enum import StrEnum

from actuator_selection.errors import ConflictError


class QuoteStatus(StrEnum):
    """Where a quote stands."""

    DRAFT = "draft"
    SENT = "sent"
    ACCEPTED = "accepted"
    REJECTED = "rejected"
    EXPIRED = "expired"


STORED_STATUSES = (
    QuoteStatus.DRAFT,
    QuoteStatus.SENT,
    QuoteStatus.ACCEPTED,
    QuoteStatus.REJECTED,
)
"""What the database holds; ``expired`` is computed."""

TRANSITIONS: dict[QuoteStatus, frozenset[QuoteStatus]] = {
    QuoteStatus.DRAFT: frozenset({QuoteStatus.SENT}),
    QuoteStatus.SENT: frozenset({QuoteStatus.ACCEPTED, QuoteStatus.REJECTED}),
    QuoteStatus.ACCEPTED: frozenset(),
    QuoteStatus.REJECTED: frozenset(),
    QuoteStatus.EXPIRED: frozenset(),
}
"""The legal moves from each status."""

_EXPIRING = frozenset({QuoteStatus.DRAFT, QuoteStatus.SENT})


class IllegalTransitionError(ConflictError):
    """A status change the flow does not allow (the API answers 409 Conflict); its rule by
    code (``quote_expired``, ``quote_transition``, ``quote_final``)."""

    def __init__(
        self, current: QuoteStatus, target: QuoteStatus, code: str, **params: object
    ) -> None:
        super().__init__(
            "status", code=code, params={"status": str(current), "target": str(target), **params}
        )
        self.current = current
        self.target = target


def effective_status(stored: QuoteStatus, *, valid_until: date, today: date) -> QuoteStatus:
    """The status as of ``today``: a draft or sent quote past ``valid_until`` is expired.

    >>> effective_status(QuoteStatus.DRAFT, valid_until=date(2026, 5, 1), today=date(2026, 5, 1))
    <QuoteStatus.DRAFT: 'draft'>
    >>> effective_status(QuoteStatus.ACCEPTED, valid_until=date(2026, 5, 1),
    ...                  today=date(2027, 1, 1))
    <QuoteStatus.ACCEPTED: 'accepted'>
    """
    if stored in _EXPIRING and today > valid_until:
        return QuoteStatus.EXPIRED
    return stored


def allowed_transitions(
    stored: QuoteStatus, *, valid_until: date, today: date
) -> tuple[QuoteStatus, ...]:
    """The statuses a quote may move to today, in the order of the flow."""
    now = effective_status(stored, valid_until=valid_until, today=today)
    return tuple(s for s in QuoteStatus if s in TRANSITIONS[now])


def transition(
    stored: QuoteStatus, target: QuoteStatus, *, valid_until: date, today: date
) -> QuoteStatus:
    """``target`` when the flow allows the move today; otherwise :class:`IllegalTransitionError`.

    >>> transition(QuoteStatus.SENT, QuoteStatus.ACCEPTED,
    ...            valid_until=date(2026, 12, 31), today=date(2027, 1, 1))
    Traceback (most recent call last):
    ...
    actuator_selection.sales.quote_status.IllegalTransitionError: status: the quote expired after 2026-12-31 and cannot move to 'accepted'
    """  # noqa: E501
    now = effective_status(stored, valid_until=valid_until, today=today)
    if target in TRANSITIONS[now]:
        return target
    if now is QuoteStatus.EXPIRED:
        raise IllegalTransitionError(
            now, target, "quote_expired", valid_until=valid_until.isoformat()
        )
    allowed = [str(s) for s in QuoteStatus if s in TRANSITIONS[now]]
    if not allowed:
        raise IllegalTransitionError(now, target, "quote_final")
    raise IllegalTransitionError(now, target, "quote_transition", allowed=allowed)
