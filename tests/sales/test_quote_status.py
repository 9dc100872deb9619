"""The quote's status flow: draft → sent → accepted | rejected; expired by date."""

from __future__ import annotations

from datetime import date, timedelta

import pytest

from actuator_selection.sales.quote_status import (
    STORED_STATUSES,
    IllegalTransitionError,
    QuoteStatus,
    allowed_transitions,
    effective_status,
    transition,
)

S = QuoteStatus
UNTIL = date(2026, 12, 31)
VALID = UNTIL  # the last valid day is still valid
PAST = UNTIL + timedelta(days=1)

LEGAL = {(S.DRAFT, S.SENT), (S.SENT, S.ACCEPTED), (S.SENT, S.REJECTED)}


@pytest.mark.parametrize("current", STORED_STATUSES)
@pytest.mark.parametrize("target", list(QuoteStatus))
def test_exactly_the_flow_is_legal_while_valid(current: QuoteStatus, target: QuoteStatus) -> None:
    if (current, target) in LEGAL:
        assert transition(current, target, valid_until=UNTIL, today=VALID) is target
    else:
        with pytest.raises(IllegalTransitionError) as caught:
            transition(current, target, valid_until=UNTIL, today=VALID)
        assert caught.value.current is current
        assert str(target) in caught.value.message


@pytest.mark.parametrize("current", STORED_STATUSES)
@pytest.mark.parametrize("target", list(QuoteStatus))
def test_nothing_moves_once_expired(current: QuoteStatus, target: QuoteStatus) -> None:
    if current in (S.ACCEPTED, S.REJECTED):
        assert effective_status(current, valid_until=UNTIL, today=PAST) is current
    else:
        assert effective_status(current, valid_until=UNTIL, today=PAST) is S.EXPIRED
    with pytest.raises(IllegalTransitionError):
        transition(current, target, valid_until=UNTIL, today=PAST)


def test_expired_message_names_the_date() -> None:
    with pytest.raises(IllegalTransitionError) as caught:
        transition(S.SENT, S.ACCEPTED, valid_until=UNTIL, today=PAST)
    assert caught.value.current is S.EXPIRED
    assert "2026-12-31" in caught.value.message


def test_allowed_transitions_follow_the_date() -> None:
    assert allowed_transitions(S.DRAFT, valid_until=UNTIL, today=VALID) == (S.SENT,)
    assert allowed_transitions(S.SENT, valid_until=UNTIL, today=VALID) == (S.ACCEPTED, S.REJECTED)
    assert allowed_transitions(S.SENT, valid_until=UNTIL, today=PAST) == ()
    assert allowed_transitions(S.ACCEPTED, valid_until=UNTIL, today=VALID) == ()


def test_expired_is_never_stored() -> None:
    assert S.EXPIRED not in STORED_STATUSES
