"""Selections: size a load case against the catalogue, store it, read it back.

The answer lists every candidate lean: its verdict, torques and checks as numbers,
and, for candidates that are not unsuitable, its drive options grouped so that no
controller and no voltage check is written twice. The full detail of one candidate
(every check in words, every criterion of Table 521.1) is computed on request from
the stored load case (:func:`candidate_detail`).

The answer is built as plain JSON data (the response models of
``schemas.selections`` describe it, and the tests validate it against them): building
~1,000 model instances per selection cost more than the engineering.

A stored selection is its request, its catalogue version and its answer, the answer
gzip-compressed as it was sent (the starter catalogue's answer: 49 kB, 6.8 kB stored).
"""

from __future__ import annotations

import gzip
import uuid
from collections.abc import Callable, Iterable, Sequence
from contextlib import AbstractContextManager
from dataclasses import dataclass
from datetime import datetime
from typing import Any

import numpy as np
import numpy.typing as npt
import orjson
from sqlalchemy.orm import Session

from actuator_selection.core.actuators import Actuator
from actuator_selection.core.batch import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BatchEvaluation,
    FloatArray,
    evaluate_batch,
)
from actuator_selection.core.checks import Check, Rule
from actuator_selection.core.drive import shared_voltage_check
from actuator_selection.core.electrical import DcBusClass
from actuator_selection.core.errors import ConflictError, InvalidInputError, NotFoundError
from actuator_selection.core.inverse import shortest_accel, shortest_pause
from actuator_selection.core.selection import VALUE_OF, Application, Verdict, evaluate, select
from actuator_selection.db.repositories import (
    CatalogueRepository,
    NewSelection,
    SelectionRepository,
)
from actuator_selection.schemas.actuators import ActuatorOut
from actuator_selection.schemas.checks import Localize, english, message_code
from actuator_selection.schemas.output_load import output_bearing_note
from actuator_selection.schemas.selections import (
    RANKING_RULE,
    CandidateDetailOut,
    DirectLoad,
    SelectionRequest,
    resolved_load,
    segments_out,
)
from actuator_selection.services.catalogue import CatalogueCache, CatalogueSnapshot, DriveContext

JSON = dict[str, Any]


def _check_rules(rules: Sequence[Rule]) -> list[JSON]:
    """``check_rules`` of an answer: its checks in their order, with reference and unit."""
    return [{"name": r.name, "reference": r.reference, "unit": r.unit} for r in rules]


STORE_COMPRESSION = 1
"""gzip level of stored answers, compressed once for the row and for the answer to a
client that accepts gzip. The starter catalogue's whole answer: 49 kB of JSON, 6.8 kB
at level 1 in 0.08 ms (level 6: 5.6 kB in 0.35 ms)."""

Writer = Callable[[], AbstractContextManager[Session]]
"""Opens a short write transaction that commits when its block ends."""


@dataclass(frozen=True, slots=True)
class SizedSelection:
    """A selection computed for storing: the request and the answer, as JSON."""

    id: str
    created_at: datetime
    catalogue_version: int
    request: JSON
    answer: bytes
    """The answer's JSON."""
    answer_gzip: bytes
    """The same, gzip-compressed: stored, and sent to clients that accept gzip."""

    @property
    def row(self) -> NewSelection:
        """What is stored of it."""
        return NewSelection(
            id=self.id,
            created_at=self.created_at,
            catalogue_version=self.catalogue_version,
            request=self.request,
            answer_gzip=self.answer_gzip,
        )


DRIVE_OPTIONS_LISTED = 100
"""Drive options are listed for the first this many candidates of a ranking (and never for
an unsuitable one); below, the candidate's detail lists them. The starter catalogue's 64
are all within; a catalogue of thousands would otherwise spend most of its answer on
controller checks for actuators nobody picks."""


def dump_json(data: Any) -> bytes:
    """JSON of an answer built as plain data, as the API's models would write it (floats
    in their shortest round-trip form, UTC times with ``Z``), by orjson: a whole-catalogue
    answer of 6,400 candidates in a third of the time pydantic's encoder takes."""
    return orjson.dumps(data, option=orjson.OPT_UTC_Z | orjson.OPT_SERIALIZE_NUMPY)


def _or_none(column: FloatArray) -> Any:
    """The array's floats as (nested) lists, None where NaN (unknown)."""
    out = column.astype(object)
    out[np.isnan(column)] = None
    return out.tolist()


def _checks(ev: BatchEvaluation) -> list[Any]:
    """Each actuator's checks of the (single) case in ``ev``, as the answer lists them:
    what :meth:`~actuator_selection.core.checks.Rule.check` reports, less its words. As
    dicts up to :data:`CHECKS_AS_DICTS_UP_TO` actuators, beyond as their JSON; the text
    that :func:`dump_json` writes is the same (the tests compare the two)."""
    if ev.statuses.shape[1] <= CHECKS_AS_DICTS_UP_TO:
        return _checks_as_dicts(ev)
    return _checks_as_json(ev)


CHECKS_AS_DICTS_UP_TO = 256
"""Beyond this many actuators a selection writes its checks' JSON rule by rule
(:func:`_checks_as_json`: a few numpy operations per rule for every actuator at once),
rather than a dict per check. Building and writing the checks, with the served collector
thresholds (2026-11-24): 64 actuators 0.19 ms as dicts against 0.22 ms as JSON, 256
actuators 0.70 against 0.69 ms, 1,024 2.8 against 2.4 ms, 6,400 25 against 16 ms (and
the whole selection over 6,400 actuators 60 → 37 ms, measured in turn)."""


def _checks_as_dicts(ev: BatchEvaluation) -> list[list[JSON]]:
    """The checks as dicts (NaN → None in numpy), the actuators' lists at once."""
    names = ev.check_names
    statuses = _STATUS_NAMES[ev.statuses[0]].tolist()
    values, limits = _or_none(ev.values[0]), _or_none(ev.limits[0])
    rows: list[list[JSON]] = [
        [
            {"name": name, "status": st, "value": v, "limit": li}
            for name, st, v, li in zip(names, status, value, limit, strict=True)
        ]
        for status, value, limit in zip(statuses, values, limits, strict=True)
    ]
    for j, k in zip(*np.nonzero(ev.approximate[0]), strict=True):
        rows[j][k]["approximate"] = True
    missing = ev.first_missing[0]
    for j, k in zip(*np.nonzero(missing >= 0), strict=True):
        rows[j][k]["missing"] = ev.missing_what[k][missing[j, k]]
    return rows


def _checks_as_json(ev: BatchEvaluation) -> list[orjson.Fragment]:
    """The checks as JSON, one ``orjson.Fragment`` per actuator, which :func:`dump_json`
    writes as it is: rule by rule for every actuator at once, orjson writes the values
    and the limits (NaN as null), numpy's string functions join them with the rule's
    name, the statuses and the optional members into check objects, and each actuator's
    are joined into its array."""
    columns = []  # per rule, each actuator's check object
    for k, name in enumerate(ev.check_names):
        check: Any = b'{"name":' + orjson.dumps(name) + b',"status":'
        check = np.strings.add(check, _STATUS_JSON[ev.statuses[0][:, k]])
        check = np.strings.add(np.strings.add(check, b',"value":'), _json_items(ev.values[0][:, k]))
        check = np.strings.add(np.strings.add(check, b',"limit":'), _json_items(ev.limits[0][:, k]))
        approximate = ev.approximate[0][:, k]
        if approximate.any():
            check = np.where(approximate, np.strings.add(check, b',"approximate":true'), check)
        first = ev.first_missing[0][:, k]
        if (first >= 0).any():
            members = [b',"missing":' + orjson.dumps(what) for what in ev.missing_what[k]]
            check = np.strings.add(check, np.array([b"", *members], dtype=np.bytes_)[first + 1])
        columns.append(np.strings.add(check, b"}").tolist())
    return [orjson.Fragment(b"[" + b",".join(row) + b"]") for row in zip(*columns, strict=True)]


def _json_items(column: FloatArray) -> npt.NDArray[np.bytes_]:
    """Each float of ``column`` as orjson writes it (NaN as null), as byte strings."""
    written = orjson.dumps(np.ascontiguousarray(column), option=orjson.OPT_SERIALIZE_NUMPY)
    return np.array(written[1:-1].split(b","), dtype=np.bytes_)


_STATUS_NAMES = np.array([s.value for s in STATUS_BY_CODE], dtype=object)
"""The API's status names by status code (:data:`~actuator_selection.core.batch.
STATUS_BY_CODE`)."""
_STATUS_JSON = np.array([orjson.dumps(s.value) for s in STATUS_BY_CODE], dtype=np.bytes_)
"""The API's status names as JSON strings, by status code."""


class _DriveOptionGroups:
    """A selection's drive options: grouped per candidate, each controller numbered once.

    The grouping by match and shared DC bus classes is the catalogue's
    (:meth:`CatalogueSnapshot.match_groups`); here each group gets the candidate's
    voltage check (Eq. 521.2 at n_2), and groups whose checks come out equal merge.
    """

    def __init__(self, catalogue: CatalogueSnapshot) -> None:
        self._catalogue = catalogue
        self._numbers: dict[int, int] = {}
        """Index into the snapshot's controllers → index into the answer's."""
        self._lists: dict[tuple[tuple[int, int], ...], list[int]] = {}
        """A group's controllers (:attr:`MatchGroup.controllers`) → their numbers: the
        actuators of one interface share their groups."""

    def groups(self, actuator: Actuator, speed_rpm: float) -> list[JSON]:
        """``actuator``'s drive options at n_2 = ``speed_rpm``, best first."""
        interface = self._catalogue.interfaces[actuator.model]
        voltages: dict[tuple[DcBusClass, ...], JSON] = {}
        merged: dict[tuple[Any, ...], JSON] = {}
        places: dict[tuple[Any, ...], tuple[tuple[int, int], ...]] = {}
        for g in self._catalogue.match_groups(interface):
            voltage = voltages.get(g.shared)
            if voltage is None:
                v = shared_voltage_check(
                    actuator=actuator,
                    interface=interface,
                    shared=g.shared,
                    speed_rpm=speed_rpm,
                    words=False,
                )
                voltage = voltages[g.shared] = {
                    "status": v.status.value,
                    "value": v.value,
                    "limit": v.limit,
                    "reference": v.reference,
                }
            key = (g.level, g.missing, *voltage.values())
            if key not in merged:
                merged[key] = {"level": g.level, "missing": list(g.missing), "voltage": voltage}
                places[key] = g.controllers
            else:  # merged groups: best first again
                places[key] = tuple(sorted((*places[key], *g.controllers)))
        for key, group in merged.items():
            group["controllers"] = self._numbered(places[key])
        return list(merged.values())

    def refs(self) -> list[JSON]:
        """The ``controllers`` of the answer, in the order they were numbered."""
        rows = self._catalogue.controllers
        return [
            {
                "manufacturer": c.manufacturer,
                "type": c.type,
                "variant": c.variant,
                "source_row": c.source_row,
            }
            for c in (rows[i] for i in self._numbers)
        ]

    def _numbered(self, controllers: tuple[tuple[int, int], ...]) -> list[int]:
        """The answer's numbers of ``controllers`` (place, index), numbering those not
        numbered yet in the order they come."""
        found = self._lists.get(controllers)
        if found is None:
            numbers = self._numbers
            found = self._lists[controllers] = [
                numbers.setdefault(i, len(numbers)) for _, i in controllers
            ]
        return found


SCALAR_UP_TO = 24
"""A selection of at most this many actuators runs the scalar flowchart
(:func:`~actuator_selection.core.selection.select`), a larger one the vectorised
(:func:`~actuator_selection.core.batch.evaluate_batch`). Both run the same rules to the
same numbers, bit for bit (tests/core/test_batch.py; tests/api/test_selections.py
compares the answers); each is the cheaper at its size. A numpy operation costs 1–2 µs
whatever its size, so the vectorised flowchart costs about the same for one actuator as
for 64, while the scalar one costs ~45 µs an actuator. Ranked candidates with their
checks, best of 15 (2026-11-24): one model 0.12 ms against 1.15 ms, 24 actuators 1.11
against 1.27 ms, 32 actuators 1.43 against 1.27 ms."""


@dataclass(frozen=True, slots=True)
class _Ranked:
    """The candidates of one case, best first, as the answer lists them."""

    actuators: list[Actuator]
    verdicts: list[Verdict]
    torques: list[tuple[float | None, float | None, float | None, float | None]]
    """T_1, T_2, T_3, T_rms; None without J_A (T_2 also where the cycle never runs
    steadily)."""
    checks: list[Any]
    """Per candidate, its checks: a list of dicts, or their JSON (``orjson.Fragment``)."""
    check_dicts: Callable[[], list[list[JSON]]]
    """Per candidate, its checks as dicts (made when asked: :func:`_binding`)."""


def _ranked_vector(
    actuators: Sequence[Actuator], app: Application, catalogue: CatalogueSnapshot
) -> _Ranked:
    ev = evaluate_batch(actuators, [app], arrays=catalogue.arrays(tuple(actuators)))
    torques = (ev.accel_torque_nm[0], ev.decel_torque_nm[0], ev.rms_torque_nm[0])
    if any(np.isinf(t).any() for t in torques):
        # Finite inputs that overflow a torque: the scalar flowchart names the input (422).
        select(actuators, app)
    order = np.array(ev.ranking(0), dtype=np.intp)
    checks = _checks(ev)
    places = order.tolist()

    def check_dicts() -> list[list[JSON]]:
        rows = checks if len(checks) <= CHECKS_AS_DICTS_UP_TO else _checks_as_dicts(ev)
        return [rows[j] for j in places]

    return _Ranked(
        actuators=[actuators[j] for j in places],
        verdicts=[VERDICT_BY_CODE[v] for v in ev.verdicts[0][order].tolist()],
        torques=list(
            zip(
                _or_none(ev.accel_torque_nm[0][order]),
                _or_none(ev.constant_torque_nm[0][order]),
                _or_none(ev.decel_torque_nm[0][order]),
                _or_none(ev.rms_torque_nm[0][order]),
                strict=True,
            )
        ),
        checks=[checks[j] for j in places],
        check_dicts=check_dicts,
    )


def _ranked_scalar(actuators: Sequence[Actuator], app: Application) -> _Ranked:
    candidates = select(actuators, app).candidates
    return _Ranked(
        actuators=[c.actuator for c in candidates],
        verdicts=[c.verdict for c in candidates],
        torques=[
            (None, None, None, None)
            if (t := c.torques) is None
            else (t.accel_torque_nm, t.constant_torque_nm, t.decel_torque_nm, t.rms_torque_nm)
            for c in candidates
        ],
        checks=(checks := [[_check(k) for k in c.checks] for c in candidates]),
        check_dicts=lambda: checks,
    )


def _check(check: Check) -> JSON:
    """A check as :func:`_checks` lists it, from the scalar flowchart's."""
    out: JSON = {
        "name": check.name,
        "status": VALUE_OF[check.status],
        "value": check.value,
        "limit": check.limit,
    }
    if check.approximate:
        out["approximate"] = True
    if check.missing is not None:
        out["missing"] = check.missing
    return out


def _binding(ranked: _Ranked, app: Application) -> JSON | None:
    """What binds across the catalogue when every candidate is unsuitable (else None).

    Per check that fails anywhere: how many candidates fail it, and its nearest miss, the
    failing candidate with the smallest value/limit (for the speed: n_2 against the
    largest n_max), from the candidates' own checks. Then what the inverse solve
    (``core/inverse.py``) says of a longer pause and a longer t_1 for the nearest miss of
    all, the first candidate: the shortest value with which no check fails, or none (and
    the checks that fail at every value). A range of ratios or leads is not searched."""
    if not ranked.verdicts or any(v is not Verdict.UNSUITABLE for v in ranked.verdicts):
        return None
    failing: dict[str, list[tuple[float, JSON, str]]] = {}
    for actuator, checks in zip(ranked.actuators, ranked.check_dicts(), strict=True):
        for check in checks:
            if check["status"] != "fail":
                continue
            value, limit = check["value"], check["limit"]
            ratio = value / limit if value is not None and limit else float("inf")
            failing.setdefault(check["name"], []).append((ratio, check, actuator.model))
    kinds = []
    for name, misses in failing.items():
        ratio, nearest, model = min(misses, key=lambda miss: miss[0])
        kinds.append(
            {
                "name": name,
                "failing": len(misses),
                "value": nearest["value"],
                "limit": nearest["limit"],
                "model": model,
            }
        )
    kinds.sort(key=lambda kind: -kind["failing"])
    first = ranked.actuators[0]
    changes = []
    for solve in (shortest_accel, shortest_pause):
        try:
            limit = solve(first, app)
        except InvalidInputError:  # a pause where the cycle does not end at standstill
            continue
        changes.append(
            {
                "quantity": limit.quantity,
                "model": first.model,
                "value": limit.value,
                "unit": limit.unit,
                "limiting_checks": list(limit.limiting_checks),
                "reason_code": None if limit.reason is None else message_code(limit.reason),
            }
        )
    return {"candidates": len(ranked.actuators), "checks": kinds, "changes": changes}


def _candidates(
    actuators: Sequence[Actuator],
    app: Application,
    catalogue: CatalogueSnapshot,
    groups: _DriveOptionGroups,
) -> tuple[list[JSON], JSON | None]:
    """Every actuator's candidate for ``app``, ranked (``core.selection.ranking_key``),
    by the flowchart that is the cheaper for their number (:data:`SCALAR_UP_TO`); the
    candidate's detail runs the scalar one, with the checks in words."""
    speed = app.profile.peak_speed_rpm  # computed first: the batch takes its figures
    ranked = (
        _ranked_scalar(actuators, app)
        if len(actuators) <= SCALAR_UP_TO
        else _ranked_vector(actuators, app, catalogue)
    )
    excluded_by_model = catalogue.excluded_by_model()
    out: list[JSON] = [
        {
            "model": a.model,
            "family": a.family,
            "gear_ratio": a.gear_ratio,
            "verdict": VALUE_OF[verdict],
            "accel_torque_nm": t_1,
            "constant_torque_nm": t_2,
            "decel_torque_nm": t_3,
            "rms_torque_nm": t_rms,
            "checks": checks,
            "controllers_excluded": excluded_by_model[a.model],
            "drive_options": None,
        }
        for a, verdict, (t_1, t_2, t_3, t_rms), checks in zip(
            ranked.actuators, ranked.verdicts, ranked.torques, ranked.checks, strict=True
        )
    ]
    # Drive options for the first candidates that are not unsuitable (DRIVE_OPTIONS_LISTED).
    for place, verdict in enumerate(ranked.verdicts[:DRIVE_OPTIONS_LISTED]):
        if verdict is not Verdict.UNSUITABLE:
            out[place]["drive_options"] = groups.groups(ranked.actuators[place], speed)
    return out, _binding(ranked, app)


def size_selection(
    body: SelectionRequest,
    app: Application,
    actuators: Sequence[Actuator],
    catalogue: CatalogueSnapshot,
    created_at: datetime,
) -> SizedSelection:
    """The whole ranking of ``app`` over ``actuators`` as POST /selections answers it."""
    groups = _DriveOptionGroups(catalogue)
    candidates, binding = _candidates(actuators, app, catalogue, groups)
    profile = app.profile
    # The selection request's fields alone (a batch case's ``case_id`` is the batch's).
    request = body.model_dump(mode="json", include=set(SelectionRequest.model_fields))
    bearing = output_bearing_note(body.output_load)
    answer = {
        "id": str(uuid.uuid4()),
        "created_at": created_at,
        "catalogue_version": catalogue.version,
        "load": resolved_load(profile),
        "segments": segments_out(profile),
        "mechanism": None if isinstance(body.load, DirectLoad) else request["load"],
        "cycle": request["cycle"],
        "high_dynamics": body.high_dynamics,
        "brake": body.brake,
        "drive": body.drive,
        "output_load": request.get("output_load"),
        "output_bearing": bearing,
        "output_bearing_code": bearing.code,
        "models": body.models,
        "cycle_time_s": profile.cycle_s,
        "mean_speed_rpm": profile.mean_speed_rpm,
        "duty_cycle_percent": profile.duty_cycle_percent,
        "ranking": RANKING_RULE,
        "check_rules": _check_rules(app.rules),
        "controllers": groups.refs(),
        "candidates": candidates,
        "binding": binding,
    }
    encoded = dump_json(answer)
    return SizedSelection(
        id=answer["id"],
        created_at=created_at,
        catalogue_version=catalogue.version,
        request=request,
        answer=encoded,
        answer_gzip=gzip.compress(encoded, compresslevel=STORE_COMPRESSION, mtime=0),
    )


def store_selections(writer: Writer, sized: Iterable[SizedSelection]) -> None:
    """Store selections in one short write transaction, committed before this returns.

    The answers were compressed when they were sized (:attr:`SizedSelection.answer_gzip`),
    before the transaction begins: on SQLite the write lock is held for the inserts alone.
    """
    with writer() as session:
        repository = SelectionRepository(session)
        for s in sized:
            repository.add(s.row)


def create_selection(
    body: SelectionRequest,
    *,
    catalogue: CatalogueCache,
    reader: Writer,
    writer: Writer,
    now: datetime,
    check: Callable[[CatalogueSnapshot], None],
) -> SizedSelection:
    """Size ``body`` against the catalogue and store it; returns what was committed.

    The catalogue is the one this process holds in memory: no read precedes the sizing.
    Its version is checked where it matters, in the statement that stores the selection
    (:meth:`~actuator_selection.db.repositories.SelectionRepository.add_at_version`), so
    a request costs one short write transaction. When a catalogue change (from any
    process) has raised the version meanwhile, nothing was stored: the selection is
    sized again in that same transaction, against the catalogue at the version it pins,
    which no change can raise before it commits. So every stored selection is its
    catalogue version's answer, and a stream of catalogue changes cannot starve it.
    ``check`` refuses a request the catalogue cannot answer (unknown models), but never
    on the strength of the snapshot held alone: a model it lacks may have been created
    since (by any process), so the version is read first, and the catalogue with it
    when it has changed (:meth:`~CatalogueCache.refresh`). Only models the current
    catalogue lacks are refused.
    """
    held = catalogue.latest(reader)
    if not held.has_all(body.models):
        held = catalogue.refresh(reader)
    sized = _sized(body, held, now, check)
    with writer() as session:
        repository = SelectionRepository(session)
        if not repository.add_at_version(sized.row):
            sized = _sized(body, catalogue.pinned(session), now, check)
            stored = repository.add_at_version(sized.row)
            assert stored, "the version is pinned by this transaction"
    return sized


def _sized(
    body: SelectionRequest,
    catalogue: CatalogueSnapshot,
    now: datetime,
    check: Callable[[CatalogueSnapshot], None],
) -> SizedSelection:
    check(catalogue)
    return size_selection(body, body.to_core(), catalogue.actuators_of(body.models), catalogue, now)


def stored_answer(session: Session, selection_id: str) -> bytes:
    """The stored answer of a selection, gzip-compressed as stored."""
    stored = SelectionRepository(session).answer_gzip(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    return stored


def stored_answer_json(session: Session, selection_id: str) -> JSON | None:
    """The stored answer of a selection as JSON data, or None."""
    stored = SelectionRepository(session).answer_gzip(selection_id)
    return None if stored is None else orjson.loads(gzip.decompress(stored))


def stored_candidate(
    session: Session, catalogue: CatalogueSnapshot, selection_id: str, model: str, *, what: str
) -> tuple[SelectionRequest, Actuator]:
    """The stored load case of a selection and one of its candidates' actuator, for what
    is computed again from them (``what``: the detail, the limits).

    The flowchart is deterministic, so a candidate computed again is the stored answer's,
    as long as the catalogue is the one the selection used; after a catalogue change it
    would not be, and the caller is told to run the selection again (409).
    """
    stored = SelectionRepository(session).request(selection_id)
    if stored is None:
        raise NotFoundError("selection_id", f"no selection {selection_id!r}", where="path")
    request, version = stored
    if version != catalogue.version:
        raise ConflictError(
            "selection_id",
            f"the catalogue has changed since this selection (version {version}, now "
            f"{catalogue.version}); run the selection again for {what}",
            where="path",
        )
    body = SelectionRequest.model_validate(request)
    actuator = next((a for a in catalogue.actuators_of([model])), None)
    if actuator is None or (body.models is not None and model not in body.models):
        raise NotFoundError(
            "model", f"{model!r} is no candidate of selection {selection_id!r}", where="path"
        )
    return body, actuator


def candidate_detail(
    session: Session,
    catalogue: CatalogueSnapshot,
    selection_id: str,
    model: str,
    localize: Localize = english,
) -> CandidateDetailOut:
    """One candidate of a stored selection in full, computed again from its load case
    (:func:`stored_candidate`), its check messages in words by ``localize``."""
    body, actuator = stored_candidate(session, catalogue, selection_id, model, what="the detail")
    record = CatalogueRepository(session).actuator(model)
    if record is None:  # pragma: no cover - the snapshot and the table agree
        raise NotFoundError("model", f"no actuator {model!r}", where="path")
    version = catalogue.version
    app = body.to_core()
    return CandidateDetailOut.build(
        selection_id=selection_id,
        catalogue_version=version,
        candidate=evaluate(actuator, app),
        profile=app.profile,
        drive=DriveContext(catalogue).options(actuator, speed_rpm=app.profile.peak_speed_rpm),
        actuator=ActuatorOut.from_record(record),
        localize=localize,
    )
