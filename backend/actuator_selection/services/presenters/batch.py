"""A batch's answer (``BatchSelectionOut``): per case its figures and best candidates.

A batch candidate (``BatchCandidateOut``) is a candidate's detail less what the stored
selection adds (:mod:`.detail` builds the detail from :func:`candidate_body` too); it is
built as plain JSON data, because a pydantic model per candidate and check would cost
more than the engineering of the whole batch (the tests validate it against the models).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
import orjson

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.phrases.check_messages import Phrase, codes_only, jsonable, jsonable_params
from actuator_selection.schemas.checks import Localize, english, message_code
from actuator_selection.services.presenters.selection import (
    dump_json,
    json_items,
    resolved_load,
)
from actuator_selection.sizing.checks import Brief, Operands, Rule, Status
from actuator_selection.sizing.checks.rule import Pick, Said, Term, Variants
from actuator_selection.sizing.engine import STATUS_BY_CODE
from actuator_selection.sizing.engine.arrays import NO_DATA
from actuator_selection.sizing.engine.codes import ARRAY_OPS
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
            written = self._written[id(decided)] = (decided, coded_checks_json(decided))
        return orjson.Fragment(written[1][cell])


def coded_checks_json(decided: DecidedCells) -> list[bytes]:
    """Each cell's ``checks`` of ``decided`` as JSON, in the cells' order: the text
    :func:`dump_json` writes of :func:`coded_check_body` of each check, the cell's
    checks of :func:`coded_check_columns` in an array."""
    return [b"[" + b",".join(row) + b"]" for row in zip(*coded_check_columns(decided), strict=True)]


def coded_check_columns(decided: DecidedCells) -> list[list[bytes]]:
    """Each rule's check of each cell of ``decided`` as JSON (a list per rule, in the
    cells' order): the text :func:`dump_json` writes of :func:`coded_check_body`, written
    rule by rule for every cell at once: orjson writes each array of numbers, and one
    template per rule and shape of its message (:func:`_message_shapes`) takes each
    cell's members, the message's code and params among them.
    The messages' codes and params come from the same words: a rule's ``no_data``
    message once per requirement, a :class:`~actuator_selection.sizing.checks.Said`
    or :class:`~actuator_selection.sizing.checks.Variants` message from the arrays, any
    other message cell by cell in codes only."""
    columns = decided.columns
    cells = columns.statuses.shape[1]
    operands: list[Operands] = []  # over the cells, computed once if a rule needs them
    written = []
    for k, rule in enumerate(decided.rules):
        values, limits = columns.values[k], columns.limits[k]
        with np.errstate(all="ignore"):  # margin_percent, utilisation (sizing.checks.rule)
            rated = ~np.isnan(values) & ~np.isnan(limits) & (limits > 0)
            margin = np.where(rated, (limits - values) / limits * 100.0, math.nan)
            share = np.where(rated, values / limits, math.nan)
        head = (
            b'{"name":',
            dump_json(rule.name),
            b',"status":',
            None,
            b',"value":',
            None,
            b',"limit":',
            None,
            b',"unit":',
            dump_json(rule.unit),
            b',"reference":',
            dump_json(rule.reference),
            b',"message_code":',
        )
        tail = (b',"approximate":', None, b',"margin_percent":', None, b',"utilisation":', None)
        statuses = _STATUS_JSON[columns.statuses[k]]
        truths = _TRUTH_JSON[columns.approximate[k].view(np.int8)]
        # the values' and limits' JSON, shared with the messages' params that say them
        given = (_object_array(json_items(values)), _object_array(json_items(limits)))
        shapes = _message_shapes(decided, k, operands, cells, given)
        out = None if len(shapes) == 1 else np.empty(cells, dtype=object)
        for where, parts, members in shapes:
            said = statuses[where].tolist()
            filled = _filled(
                _template(*head, *parts, *tail, b"}"),
                [
                    said,
                    given[0][where].tolist(),
                    given[1][where].tolist(),
                    *members,
                    truths[where].tolist(),
                    json_items(margin[where]),
                    json_items(share[where]),
                ],
                len(said),
            )
            if out is None:
                written.append(filled)
            else:
                out[where] = filled
        if out is not None:
            written.append(out.tolist())
    return written


def _object_array(items: list[bytes]) -> npt.NDArray[np.object_]:
    out = np.empty(len(items), dtype=object)
    out[:] = items
    return out


def _template(*parts: bytes | None) -> bytes:
    """A bytes template of ``parts``: each None a member (``%b``), the rest as they are."""
    return b"".join(b"%b" if p is None else p.replace(b"%", b"%%") for p in parts)


def _filled(template: bytes, members: list[list[bytes]], cells: int) -> list[bytes]:
    """``template`` filled with each cell's ``members``."""
    if not members:
        return [template % ()] * cells
    return list(map(template.__mod__, zip(*members, strict=True)))


_STATUS_JSON = np.array([dump_json(s.value) for s in STATUS_BY_CODE], dtype=object)
"""The API's status names as JSON strings, by status code."""
_TRUTH_JSON = np.array([b"false", b"true"], dtype=object)
_WORDED = np.array([s in (Status.PASS, Status.FAIL, Status.WARN) for s in STATUS_BY_CODE])
"""By status code, whether a rule's own message words it (not no data, not not applicable)."""


Shape = tuple[Any, list[bytes | None], list[list[bytes]]]
"""Cells whose message is written by one template: which cells (a mask over them, or
a slice of all), the template's parts (None: a member) and each member over those cells."""


def _message_shapes(
    decided: DecidedCells,
    k: int,
    operands: list[Operands],
    cells: int,
    given: tuple[npt.NDArray[np.object_], npt.NDArray[np.object_]],
) -> list[Shape]:
    """Rule ``k``'s ``message_code`` and ``message_params`` members of each cell (the
    code's JSON, then ``,"message_params":`` and the params' JSON), by shape: the cells
    whose message is declared (:class:`~actuator_selection.sizing.checks.Said`,
    :class:`~actuator_selection.sizing.checks.Variants`) by the clauses each says
    (:func:`_said_shapes`), every other one (no data, not applicable, a message that is
    a plain function) as its written text (:func:`_message_json`)."""
    rule = decided.rules[k]
    columns = decided.columns
    statuses, first = columns.statuses[k], columns.first_missing[k]
    shapes: list[Shape] = []
    worded = np.zeros(cells, dtype=np.bool_)
    if isinstance(rule.message, Said | Variants):
        worded = _WORDED[statuses] & (first < 0)  # a floor's failure wraps the message
        if worded.any():
            if not operands:
                operands.append(decided.operand_columns())
            value, limit = columns.values[k], columns.limits[k]
            cell = _Cells(operands[0], statuses, value, limit, worded, {}, given)
            shapes = [(c.mask, parts, its) for c, parts, its in _said_shapes(rule.message, cell)]
    if worded.all():
        if len(shapes) == 1:  # every cell: no mask to apply
            return [(slice(None), shapes[0][1], shapes[0][2])]
        return shapes
    out = np.full(cells, b"", dtype=object)
    left = ~worded
    no_data = statuses == NO_DATA
    if no_data.any():
        said = [_message_json(rule.no_data_message(r)) for r in range(len(rule.requires))]
        out[no_data] = np.array(said, dtype=object)[first[no_data]]
    other = left & ~no_data
    if other.any():  # any other message: worded cell by cell, in codes only
        values, limits = columns.values[k].tolist(), columns.limits[k].tolist()
        with codes_only():
            for j in np.flatnonzero(other).tolist():
                missing = int(first[j])
                message = rule.words(
                    decided.operands_of(j),
                    STATUS_BY_CODE[statuses[j]],
                    values[j],
                    limits[j],
                    None if missing < 0 else missing,
                )
                out[j] = _message_json(message)
    if not worded.any():
        return [(slice(None), [None], [out.tolist()])]
    return [*shapes, (left, [None], [out[left].tolist()])]


def _message_json(message: str) -> bytes:
    """A message's ``message_code`` and ``message_params`` members, the first one's name
    left out (as :func:`_messages` writes them)."""
    code = message.code if isinstance(message, Phrase) else None
    return dump_json(code) + b',"message_params":' + dump_json(jsonable_params(message))


@dataclass(frozen=True, slots=True)
class _Cells:
    """The cells of one rule whose declared message is written: the operands, statuses,
    values and limits of every cell detailed, which of them (``mask``), and the terms
    computed over every cell (by the term's identity: each computed once a rule)."""

    q: Operands
    statuses: npt.NDArray[np.int8]
    values: npt.NDArray[np.float64]
    limits: npt.NDArray[np.float64]
    mask: npt.NDArray[np.bool_]
    terms: dict[int, tuple[Any, npt.NDArray[Any]]]
    given: tuple[npt.NDArray[np.object_], npt.NDArray[np.object_]]
    """The JSON of :attr:`values` and of :attr:`limits` over every cell: a term that
    gives one of them as it is (``given_value``) is written from it."""

    def term(self, term: Term) -> npt.NDArray[Any]:
        """``term`` over the cells of :attr:`mask`."""
        return self._computed(term)[1][self.mask]

    def _computed(self, term: Term) -> tuple[Any, npt.NDArray[Any]]:
        found = self.terms.get(id(term))
        if found is None:
            with np.errstate(all="ignore"):
                computed = term(self.q, ARRAY_OPS, self.values, self.limits)
            found = self.terms[id(term)] = (
                computed,
                np.broadcast_to(computed, self.mask.shape),
            )
        return found

    def items(self, term: Term) -> list[bytes]:
        """``term`` over the cells of :attr:`mask` as a param's JSON (:func:`_param_items`)."""
        computed, column = self._computed(term)
        written = (
            self.given[0]
            if computed is self.values
            else self.given[1]
            if computed is self.limits
            else None
        )
        found = column[self.mask]
        if written is None or not np.isfinite(found).all():
            return _param_items(found)
        shared: list[bytes] = written[self.mask].tolist()  # finite: the same text
        return shared

    def codes(self, message: Said) -> list[bytes]:
        """``message``'s code of each cell, as JSON."""
        codes = np.array([dump_json(c) for c in message.codes], dtype=object)
        found: list[bytes] = codes[_STATUS_INDEX[self.statuses[self.mask]]].tolist()
        return found

    def within(self, where: npt.NDArray[np.bool_]) -> _Cells:
        """The cells of :attr:`mask` where ``where`` (over those cells) holds."""
        mask = self.mask.copy()
        mask[self.mask] = where
        return _Cells(self.q, self.statuses, self.values, self.limits, mask, self.terms, self.given)


@dataclass(frozen=True, slots=True)
class _Chosen:
    """A :class:`~actuator_selection.sizing.checks.Said` clause with each of its params'
    :class:`~actuator_selection.sizing.checks.Pick` decided (``params``)."""

    said: Said
    params: list[Any]


def _said_shapes(
    message: Said | Variants, cells: _Cells
) -> list[tuple[_Cells, list[bytes | None], list[list[bytes]]]]:
    """:func:`_message_json` of a declared message over ``cells`` (each decided pass,
    fail or warn) by shape: the cells that take the same variant and the same branch of
    each :class:`~actuator_selection.sizing.checks.Pick`, with one template's parts
    (None: a member) and the members over those cells, from the arrays."""
    if isinstance(message, Said):
        out = []
        for c, chosen in _chosen(message, cells):
            parts, members = _object_parts(chosen, c)
            out.append((c, [None, b',"message_params":', *parts], [c.codes(message), *members]))
        return out
    out = []
    left = np.ones(int(np.count_nonzero(cells.mask)), dtype=np.bool_)
    for condition, variant in message.cases:
        holds = left if condition is None else left & cells.term(condition)
        if holds.any():
            out += _said_shapes(variant, cells.within(holds))
        left &= ~holds
    return out


def _chosen(message: Said, cells: _Cells) -> list[tuple[_Cells, _Chosen]]:
    """``message`` over ``cells``, split where a param's :class:`~actuator_selection.
    sizing.checks.Pick` (or a clause's) takes another branch."""
    leaves: list[tuple[_Cells, list[Any]]] = [(cells, [])]
    for _, param in message.params:
        leaves = [(c2, [*params, p]) for c, params in leaves for c2, p in _param_chosen(param, c)]
    return [(c, _Chosen(message, params)) for c, params in leaves]


def _param_chosen(param: Any, cells: _Cells) -> list[tuple[_Cells, Any]]:
    """``param`` over ``cells``, each :class:`~actuator_selection.sizing.checks.Pick`
    decided: the cells of each branch taken, with what it says there."""
    if isinstance(param, Said):
        return list(_chosen(param, cells))
    if isinstance(param, Pick):
        holds = cells.term(param.condition).astype(np.bool_)
        out = []
        for where, branch in ((holds, param.if_true), (~holds, param.if_false)):
            if where.any():
                out += _param_chosen(branch, cells.within(where))
        return out
    return [(cells, param)]


def _object_parts(chosen: _Chosen, cells: _Cells) -> tuple[list[bytes | None], list[list[bytes]]]:
    """The params of ``chosen`` over ``cells`` as one JSON object's template parts (None:
    a member) and members, as :func:`~actuator_selection.phrases.check_messages.
    jsonable_params` has them written."""
    parts: list[bytes | None] = [b"{"]
    members: list[list[bytes]] = []
    for n, ((name, _), param) in enumerate(zip(chosen.said.params, chosen.params, strict=True)):
        parts.append((b"," if n else b"") + dump_json(name) + b":")
        if isinstance(param, _Chosen):  # a clause: its code and params
            inner, its = _object_parts(param, cells)
            parts += [b'{"code":', None, b',"params":', *inner, b"}"]
            members += [cells.codes(param.said), *its]
        elif callable(param):
            parts.append(None)
            members.append(cells.items(param))
        else:
            parts.append(dump_json(jsonable(param)))  # a constant: words, a clause or None
    parts.append(b"}")
    return parts, members


_STATUS_INDEX = np.array([list(Status).index(s) for s in STATUS_BY_CODE], dtype=np.intp)
"""By status code, the status's place in :class:`Status` (:attr:`Said.codes`' order)."""


def _param_items(column: npt.NDArray[Any]) -> list[bytes]:
    """Each item of ``column`` as :func:`~actuator_selection.phrases.check_messages.
    jsonable_params` has it written: numbers as they are, a float that is NaN or infinite
    as its ``repr`` (a string)."""
    out = json_items(column)
    if column.dtype.kind == "f":
        odd = ~np.isfinite(column)
        if odd.any():
            for j, x in zip(np.flatnonzero(odd).tolist(), column[odd].tolist(), strict=True):
                out[j] = dump_json(repr(x))
    return out


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
