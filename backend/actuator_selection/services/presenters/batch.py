"""A batch's answer (``BatchSelectionOut``): per case its figures and best candidates.

A batch candidate (``BatchCandidateOut``) is a candidate's detail less what the stored
selection adds (:mod:`.detail` builds the detail from :func:`candidate_body` too); it is
built as plain JSON data, because a pydantic model per candidate and check would cost
more than the engineering of the whole batch (the tests validate it against the models).
"""

from __future__ import annotations

from typing import Any

from actuator_selection.i18n.check_messages import Phrase, codes_only, jsonable_params
from actuator_selection.schemas.checks import Localize, english, message_code
from actuator_selection.services.presenters.selection import resolved_load
from actuator_selection.sizing.checks import Brief, Rule
from actuator_selection.sizing.selection import VALUE_OF, Candidate, Check, Selection


def _number(x: float | None) -> float | None:
    # What a pydantic float field makes of a value: an int becomes a float.
    return None if x is None else float(x)


def check_body(
    check: Check, localize: Localize = english, worded: dict[int, str] | None = None
) -> dict[str, Any]:
    """A check in full (``CheckOut``), its message in words by ``localize``: what
    ``CheckOut.from_core(check, localize).model_dump(mode="json")`` gives, without building
    the model. ``worded`` collects the words by the message's identity, for the
    candidate's reasons (the same messages) to be worded once."""
    value, limit, message = check.value, check.limit, check.message
    margin, utilisation = check.margin_percent, check.utilisation
    words = localize(message)
    if worded is not None:
        worded[id(message)] = words
    return {
        "name": check.name,
        "status": VALUE_OF[check.status],
        "value": None if value is None else float(value),
        "limit": None if limit is None else float(limit),
        "unit": check.unit,
        "reference": check.reference,
        "message": words,
        "message_code": message_code(message),
        "message_params": jsonable_params(message),
        "approximate": check.approximate,
        "margin_percent": None if margin is None else float(margin),
        "utilisation": None if utilisation is None else float(utilisation),
    }


def _figures(candidate: Candidate) -> dict[str, Any]:
    """A candidate's actuator, verdict and torques, as every form of it begins."""
    t = candidate.torques
    a = candidate.actuator
    return {
        "model": a.model,
        "family": a.family,
        "gear_ratio": float(a.gear_ratio),
        "verdict": VALUE_OF[candidate.verdict],
        "accel_torque_nm": _number(t.accel_torque_nm) if t else None,
        "constant_torque_nm": _number(t.constant_torque_nm) if t else None,
        "decel_torque_nm": _number(t.decel_torque_nm) if t else None,
        "rms_torque_nm": _number(t.rms_torque_nm) if t else None,
    }


def candidate_body(
    candidate: Candidate,
    *,
    include_checks: bool,
    controllers: list[dict[str, Any]] | None,
    controllers_summary: dict[str, Any],
    localize: Localize = english,
) -> dict[str, Any]:
    """A candidate in full (``BatchCandidateOut``; the detail's figures, reasons, checks
    and controllers), its words by ``localize``; ``checks`` and ``controllers`` only when
    given; ``controllers_summary`` from :func:`controllers_summary`."""
    # The checks first: a batch candidate's reasons then come from the checks built, and
    # their words from the checks' (a reason is a check's message, worded once).
    worded: dict[int, str] = {}
    checks = [check_body(c, localize, worded) for c in candidate.checks] if include_checks else None
    body = _figures(candidate)
    body["reasons"] = [worded.get(id(r)) or localize(r) for r in candidate.reasons]
    if checks is not None:
        body["checks"] = checks
    if controllers is not None:
        body["controllers"] = controllers
    body.update(controllers_summary)
    return body


def coded_check_body(named: Check | Rule, brief: Brief) -> dict[str, Any]:
    """A check as :func:`check_body` gives it, less ``message``: its words are left to the
    client (``message_code`` and ``message_params``), or asked for (``include_messages``).
    ``named`` and ``brief`` as :meth:`~actuator_selection.sizing.candidates.Candidate.
    briefs` gives them."""
    status, value, limit, approximate, message = brief
    if value is not None:
        value = float(value)
    if limit is not None:
        limit = float(limit)
    # margin_percent and utilisation (sizing.checks.rule), without the properties' calls
    margin = share = None
    if value is not None and limit is not None and limit > 0:
        margin, share = (limit - value) / limit * 100.0, value / limit
    return {
        "name": named.name,
        "status": VALUE_OF[status],
        "value": value,
        "limit": limit,
        "unit": named.unit,
        "reference": named.reference,
        "message_code": message.code if isinstance(message, Phrase) else None,
        "message_params": jsonable_params(message),
        "approximate": approximate,
        "margin_percent": margin,
        "utilisation": share,
    }


def batch_candidate_body(
    candidate: Candidate,
    *,
    include_checks: bool,
    include_messages: bool,
    controllers: list[dict[str, Any]] | None,
    controllers_summary: dict[str, Any],
    localize: Localize = english,
) -> dict[str, Any]:
    """A batch candidate (``BatchCandidateOut``): with ``include_messages``, the detail's
    candidate in words (:func:`candidate_body`, the answer as it was before messages were
    asked for); without, the same less every text: no ``reasons``, no check's
    ``message``, no ``controllers_note`` (``controllers_summary`` as
    :func:`coded_summary` gives it), their codes and params given. Either way
    ``reason_checks`` names the checks that do not pass."""
    if include_messages:
        body = candidate_body(
            candidate,
            include_checks=include_checks,
            controllers=controllers,
            controllers_summary=controllers_summary,
            localize=localize,
        )
        body["reason_checks"] = candidate.open_checks
        return body
    body = _figures(candidate)
    body["reason_checks"] = candidate.open_checks
    if include_checks:
        with codes_only():  # the checks' messages as codes and params, no English written
            body["checks"] = [coded_check_body(*named) for named in candidate.briefs()]
    if controllers is not None:
        body["controllers"] = controllers
    body.update(controllers_summary)
    return body


def coded_summary(summary: dict[str, Any]) -> dict[str, Any]:
    """:func:`controllers_summary` less its words (``controllers_note``)."""
    return {k: v for k, v in summary.items() if k != "controllers_note"}


def controllers_summary(excluded: int, note: str, localize: Localize = english) -> dict[str, Any]:
    """A candidate's ``controllers_excluded`` and ``controllers_note`` (with its code and
    params): the same for every case of a model (Table 521.1 matches actuators, not loads)."""
    return {
        "controllers_excluded": excluded,
        "controllers_note": localize(note),
        "controllers_note_code": message_code(note),
        "controllers_note_params": jsonable_params(note),
    }


def result_body(
    *,
    id: str | None,
    case_id: str | None,
    selection: Selection,
    candidates: list[dict[str, Any]],
) -> dict[str, Any]:
    """One entry of ``results`` (:class:`BatchResultOut`) as a JSON-ready dict."""
    return {
        "id": id,
        "case_id": case_id,
        "load": resolved_load(selection.profile),
        "cycle_time_s": selection.cycle_time_s,
        "mean_speed_rpm": selection.mean_speed_rpm,
        "duty_cycle_percent": selection.duty_cycle_percent,
        "candidates": candidates,
    }
