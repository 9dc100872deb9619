"""A batch's answer (``BatchSelectionOut``): per case its figures and best candidates.

A batch candidate (``BatchCandidateOut``) is a candidate's detail less what the stored
selection adds (:mod:`.detail` builds the detail from :func:`candidate_body` too); it is
built as plain JSON data, because a pydantic model per candidate and check would cost
more than the engineering of the whole batch (the tests validate it against the models).
"""

from __future__ import annotations

import math
from typing import Any, NamedTuple

import numpy as np
import orjson

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.phrases.check_messages import Phrase, Wording, codes_only, jsonable_params
from actuator_selection.schemas.checks import Localize, english, message_code
from actuator_selection.services.presenters.batch_messages import (
    Given,
    Shape,
    filled,
    message_shapes,
    message_words,
    text_json,
)
from actuator_selection.services.presenters.selection import dump_json, json_items, resolved_load
from actuator_selection.sizing.checks import Brief, Operands, Rule
from actuator_selection.sizing.engine import STATUS_BY_CODE
from actuator_selection.sizing.engine.arrays import PASS
from actuator_selection.sizing.engine.detail import DecidedCells
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
    return figures_body(
        candidate.actuator,
        VALUE_OF[candidate.verdict],
        (t.accel_torque_nm, t.constant_torque_nm, t.decel_torque_nm, t.rms_torque_nm)
        if t
        else None,
    )


def figures_body(
    a: Actuator,
    verdict: str,
    torques: tuple[float, float | None, float, float] | None,
) -> dict[str, Any]:
    """A candidate's actuator, ``verdict`` and ``torques`` (T_1, T_2, T_3, T_rms; None
    without J_A), as every form of it begins (:func:`_figures` of a candidate)."""
    accel, constant, decel, rms = torques or (None, None, None, None)
    return {
        **actuator_body(a),
        "verdict": verdict,
        "accel_torque_nm": _number(accel),
        "constant_torque_nm": _number(constant),
        "decel_torque_nm": _number(decel),
        "rms_torque_nm": _number(rms),
    }


def actuator_body(a: Actuator) -> dict[str, Any]:
    """The actuator's members of a candidate, as :func:`figures_body` begins."""
    return {"model": a.model, "family": a.family, "gear_ratio": float(a.gear_ratio)}


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


class CodedChecks:
    """A batch candidate's ``checks`` as :func:`coded_check_body` gives them, written as
    JSON from the engine's arrays (:meth:`of`): the checks of every candidate detailed
    with one set of decisions (a :class:`~actuator_selection.sizing.engine.detail.
    DecidedCells`) at once, rule by rule (:func:`coded_checks_json`), with no object
    per check. One writer serves a slice of a batch: it keeps what it wrote for the
    decisions it was asked about."""

    def __init__(self) -> None:
        self._written: dict[int, tuple[DecidedCells, list[bytes]]] = {}

    def of(self, candidate: Candidate) -> Any:
        """``candidate``'s checks: their JSON (``orjson.Fragment``), or, where its checks
        are built, one dict each (:func:`coded_check_body`)."""
        found = candidate.decided()
        if found is None:
            with codes_only():  # the checks' messages as codes and params, no English
                return [coded_check_body(*named) for named in candidate.briefs()]
        decided: DecidedCells = found[0]
        cell: int = found[1]
        written = self._written.get(id(decided))
        if written is None:
            written = self._written[id(decided)] = (decided, coded_checks_json(decided).checks)
        return orjson.Fragment(written[1][cell])


def coded_checks_json(decided: DecidedCells, words: Wording | None = None) -> CellChecks:
    """Each cell's ``checks`` of ``decided`` as JSON, in the cells' order: the text
    :func:`dump_json` writes of a list of :func:`coded_check_body` of each check (with
    ``words``, of :func:`check_body` in ``words``' language: each check's ``message``
    too), written for every cell at once: orjson writes each array of numbers, and one
    template of the cell's whole array takes each cell's members, rule by rule
    (:func:`_rule_checks`), the messages' codes and params among them.
    The messages' codes and params come from the same words: a rule's ``no_data``
    message once per requirement, a :class:`~actuator_selection.sizing.checks.Said`
    or :class:`~actuator_selection.sizing.checks.Variants` message from the arrays, any
    other message cell by cell in codes only; their words likewise
    (:func:`~.batch_messages.message_words`)."""
    columns = decided.columns
    cells = columns.statuses.shape[1]
    operands: list[Operands] = []  # over the cells, computed once if a rule needs them
    parts: list[bytes | None] = [b"["]
    members: list[list[bytes]] = []
    messages: list[list[bytes]] = []
    with np.errstate(all="ignore"):  # margin_percent, utilisation; the messages' terms
        for k, rule in enumerate(decided.rules):
            if k:
                parts.append(b",")
            given = Given(columns.values[k], columns.limits[k])
            if words is not None:
                messages.append(message_words(decided, k, operands, cells, given, words))
            its_parts, its_members = _rule_checks(
                decided, k, rule, operands, cells, given, messages[k] if messages else None
            )
            parts += its_parts
            members += its_members
    parts.append(b"]")
    return CellChecks(filled(parts, members, cells), messages)


class CellChecks(NamedTuple):
    """:func:`coded_checks_json` of a set of cells: each cell's checks, and each rule's
    message of each cell in words (a JSON string; none without words)."""

    checks: list[bytes]
    messages: list[list[bytes]]

    def reasons(self, not_passing: list[list[int]]) -> list[bytes]:
        """Each cell's ``reasons`` as JSON: the words of its checks that do not pass
        (``not_passing``, the rules' indexes of each cell), in the rules' order, each
        text once (as :attr:`~actuator_selection.sizing.candidates.Candidate.reasons`
        has them: two checks may lack the same value). Each text is compared in the
        answer's language, where a candidate compares the English texts: the two could
        differ only if two messages of one candidate read alike in one language and not
        in the other."""
        written = self.messages
        return [
            b"[" + b",".join(dict.fromkeys([written[k][j] for k in open_rules])) + b"]"
            for j, open_rules in enumerate(not_passing)
        ]


def worded_reasons(decided: DecidedCells, words: Wording) -> list[bytes]:
    """Each cell's ``reasons`` (:meth:`CellChecks.reasons`) where its checks are not
    asked for: only the checks that do not pass are worded."""
    columns = decided.columns
    cells = columns.statuses.shape[1]
    operands: list[Operands] = []
    messages: list[list[bytes]] = []
    with np.errstate(all="ignore"):  # the messages' terms
        for k in range(len(decided.rules)):
            open_cells = columns.statuses[k] > PASS
            if open_cells.any():
                given = Given(columns.values[k], columns.limits[k])
                messages.append(
                    message_words(decided, k, operands, cells, given, words, open_cells)
                )
            else:
                messages.append([])  # no cell's reason
    return CellChecks([], messages).reasons(decided.not_passing)


def _rule_checks(
    decided: DecidedCells,
    k: int,
    rule: Rule,
    operands: list[Operands],
    cells: int,
    given: Given,
    words: list[bytes] | None,
) -> tuple[list[bytes | None], list[list[bytes]]]:
    """Rule ``k``'s check of each cell of ``decided`` (:func:`coded_checks_json`) as a
    template's parts (None: a member) and the members over the cells: the check's own
    members, its message's words (``words``; None: without), and its message's code and
    params, filled per cell where the cells' messages take more than one shape
    (:func:`message_shapes`); ``given`` the values' and limits' JSON, shared with the
    messages' params that say them."""
    columns = decided.columns
    values, limits = columns.values[k], columns.limits[k]
    rated = ~np.isnan(values) & ~np.isnan(limits) & (limits > 0)  # sizing.checks.rule
    margin = np.where(rated, (limits - values) / limits * 100.0, math.nan)
    share = np.where(rated, values / limits, math.nan)
    shapes = message_shapes(decided, k, operands, cells, given)
    if len(shapes) == 1 and isinstance(shapes[0][0], slice):  # every cell, one shape
        _, said, members = shapes[0]
    else:
        said, members = [None], [_messages(shapes, cells)]
    worded: list[bytes | None] = []
    if words is not None:
        worded = [b',"message":', None]
        members = [words, *members]
    parts = [
        b'{"name":' + text_json(rule.name) + b',"status":',
        None,
        b',"value":',
        None,
        b',"limit":',
        None,
        b',"unit":' + text_json(rule.unit) + b',"reference":' + text_json(rule.reference),
        *worded,
        b',"message_code":',
        *said,
        b',"approximate":',
        None,
        b',"margin_percent":',
        None,
        b',"utilisation":',
        None,
        b"}",
    ]
    return parts, [
        _STATUS_JSON[columns.statuses[k]].tolist(),
        *given.items(),
        *members,
        _TRUTH_JSON[columns.approximate[k].view(np.int8)].tolist(),
        json_items(margin),
        json_items(share),
    ]


def _messages(shapes: list[Shape], cells: int) -> list[bytes]:
    """Each cell's message (its code, then ``,"message_params":`` and the params) as
    JSON, each shape's cells filled from its template."""
    out = np.empty(cells, dtype=object)
    for where, parts, members in shapes:
        out[where] = filled(parts, members, len(out[where]))
    found: list[bytes] = out.tolist()
    return found


_STATUS_JSON = np.array([dump_json(s.value) for s in STATUS_BY_CODE], dtype=object)
"""The API's status names as JSON strings, by status code."""
_TRUTH_JSON = np.array([b"false", b"true"], dtype=object)


def batch_candidate_body(
    candidate: Candidate,
    *,
    include_checks: bool,
    include_messages: bool,
    controllers: list[dict[str, Any]] | None,
    controllers_summary: dict[str, Any],
    localize: Localize = english,
    coded: CodedChecks | None = None,
) -> dict[str, Any]:
    """A batch candidate (``BatchCandidateOut``): with ``include_messages``, the detail's
    candidate in words (:func:`candidate_body`, the answer as it was before messages were
    asked for); without, the same less every text: no ``reasons``, no check's
    ``message``, no ``controllers_note`` (``controllers_summary`` as
    :func:`coded_summary` gives it), their codes and params given, the checks written by
    ``coded`` (a writer of the batch's slice; None: one of this candidate's own). Either
    way ``reason_checks`` names the checks that do not pass."""
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
    return coded_candidate_body(
        _figures(candidate),
        candidate.open_checks,
        (coded or CodedChecks()).of(candidate) if include_checks else None,
        controllers,
        controllers_summary,
    )


def coded_candidate_body(
    figures: dict[str, Any],
    reason_checks: list[str],
    checks: Any,
    controllers: list[dict[str, Any]] | None,
    summary: dict[str, Any],
) -> dict[str, Any]:
    """A batch candidate without words (:func:`batch_candidate_body`) from its parts:
    ``figures`` (:func:`figures_body`), the checks that do not pass, ``checks`` (None:
    not asked for), ``controllers`` (None: not asked for) and :func:`coded_summary`."""
    figures["reason_checks"] = reason_checks
    if checks is not None:
        figures["checks"] = checks
    if controllers is not None:
        figures["controllers"] = controllers
    figures.update(summary)
    return figures


def members_json(body: dict[str, Any], *, comma: bool = False) -> bytes:
    """The members of ``body`` as :func:`dump_json` writes them inside its braces
    (``comma``: each after a comma, so that none is nothing)."""
    inner = dump_json(body)[1:-1]
    return b"," + inner if comma and inner else inner


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
    return case_body(
        id=id,
        case_id=case_id,
        load=resolved_load(selection.profile),
        figures=(selection.cycle_time_s, selection.mean_speed_rpm, selection.duty_cycle_percent),
        candidates=candidates,
    )


def case_body(
    *,
    id: str | None,
    case_id: str | None,
    load: dict[str, float],
    figures: tuple[float, float, float],
    candidates: list[dict[str, Any]],
) -> dict[str, Any]:
    """One entry of ``results`` from its parts: ``figures`` the cycle time, mean speed
    and duty cycle (:func:`result_body` of a selection)."""
    cycle_time_s, mean_speed_rpm, duty_cycle_percent = figures
    return {
        "id": id,
        "case_id": case_id,
        "load": load,
        "cycle_time_s": cycle_time_s,
        "mean_speed_rpm": mean_speed_rpm,
        "duty_cycle_percent": duty_cycle_percent,
        "candidates": candidates,
    }
