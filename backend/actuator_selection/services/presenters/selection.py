"""The selection's answer (``SelectionOut``): a ranking of candidates built from the engine.

The answer lists every candidate lean: its verdict, torques and checks as numbers,
and, for candidates that are not unsuitable, its drive options grouped so that no
controller and no voltage check is written twice. It is built as plain JSON data (the
contract is :class:`~actuator_selection.schemas.selections.SelectionOut`; the tests
validate this presenter's output against it): building ~1,000 model instances per
selection cost more than the engineering.
"""

from __future__ import annotations

import math
import threading
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from datetime import datetime
from typing import Any

import numpy as np
import numpy.typing as npt
import orjson
import zstandard

from actuator_selection.catalogue.actuators import Actuator
from actuator_selection.errors import InvalidInputError
from actuator_selection.schemas.checks import message_code
from actuator_selection.schemas.output_load import output_bearing_note
from actuator_selection.schemas.selections import (
    RANKING_RULE,
    DirectLoad,
    SelectionRequest,
)
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.sizing.axis import AxisLoad
from actuator_selection.sizing.checks import Check, Rule
from actuator_selection.sizing.drive import shared_voltage_checks
from actuator_selection.sizing.engine import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BatchEvaluation,
    FloatArray,
)
from actuator_selection.sizing.engine.arrays import FAIL
from actuator_selection.sizing.inverse import shortest_accel, shortest_pause
from actuator_selection.sizing.motion import Profile
from actuator_selection.sizing.selection import VALUE_OF, Application, Verdict

JSON = dict[str, Any]

ANSWER_VERSION = 3
"""The version of the answer this presenter writes, stored with each selection
(``selections.answer_version``). 0: the answer before the lean one (every check with
its words, every candidate with its controllers, up to 2026-11-23); 1: the lean answer
as first stored (2026-11-23, later fields absent); 2: every candidate listed, every
field present; 3: today's ``SelectionOut``, the ranking's first ``top`` candidates with
``total_candidates``, ``verdict_counts`` and ``next_cursor``, the rest stored beside it
(``selections.ranking_zstd``, :func:`ranking_rest`). The migration ``0010`` upgraded 0
and 1 to 2, ``0016`` 2 to 3; readers take 3 only.
Change the answer's shape: raise this, and add a migration that upgrades the rows."""

DEFAULT_TOP = 25
"""Candidates an answer lists unless the request asks for another number (``top``), and
a page of a stored ranking (``limit``): the page asks for as many (its first screen shows
12 rows, "show more" reads on by the answer's ``next_cursor``). The rest of the ranking
is stored beside the answer and read by cursor; exports read it whole
(``services.selections.stored_answer_json``). Listing all 64 of the starter catalogue
cost a whole-catalogue selection a quarter more instructions (14.9 M against 18.4–18.7 M
a request, issue 32); a catalogue of 6,400 answered whole wrote 5 MB."""

TOP_MAX = 1000
"""The most candidates an answer (``top``) or a page (``limit``) lists."""

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


def check_rules(rules: Sequence[Rule]) -> list[JSON]:
    """``check_rules`` of an answer: its checks in their order, with reference and unit."""
    return [{"name": r.name, "reference": r.reference, "unit": r.unit} for r in rules]


def or_none(column: FloatArray) -> Any:
    """The array's floats as (nested) lists, None where NaN (unknown)."""
    if column.size <= _LISTED_UP_TO and 1 <= column.ndim <= 2:
        items = column.tolist()  # a NaN is the one float not equal to itself
        if column.ndim == 1:
            return [None if x != x else x for x in items]
        return [[None if x != x else x for x in row] for row in items]
    out = column.astype(object)
    out[np.isnan(column)] = None
    return out.tolist()


_LISTED_UP_TO = 256
"""Up to this many floats :func:`or_none` lists them in Python: a one-model answer's few
torques and checks, where numpy's three calls cost more than the loop."""


def checks_of(ev: BatchEvaluation) -> list[Any]:
    """Each actuator's checks of the (single) case in ``ev``, as the answer lists them:
    what :meth:`~actuator_selection.sizing.checks.Rule.check` reports, less its words. As
    dicts up to :data:`CHECKS_AS_DICTS_UP_TO` actuators, beyond as their JSON; the text
    that :func:`dump_json` writes is the same (the tests compare the two)."""
    if ev.statuses.shape[1] <= CHECKS_AS_DICTS_UP_TO:
        return checks_as_dicts(ev)
    return checks_as_json(ev)


CHECKS_AS_DICTS_UP_TO = 256
"""Beyond this many actuators a selection writes its checks' JSON rule by rule
(:func:`checks_as_json`: a few numpy operations per rule for every actuator at once),
rather than a dict per check. Building and writing the checks, with the served collector
thresholds (2026-11-24): 64 actuators 0.19 ms as dicts against 0.22 ms as JSON, 256
actuators 0.70 against 0.69 ms, 1,024 2.8 against 2.4 ms, 6,400 25 against 16 ms (and
the whole selection over 6,400 actuators 60 → 37 ms, measured in turn)."""


def checks_as_dicts(ev: BatchEvaluation) -> list[list[JSON]]:
    """The checks as dicts (NaN → None in numpy), the actuators' lists at once."""
    return RankedChecks.of(ev, np.arange(ev.statuses.shape[1])).dicts(0, ev.statuses.shape[1])


@dataclass(frozen=True, slots=True)
class RankedChecks:
    """The checks of one case's candidates as the engine's arrays, one row per candidate in
    the ranking's order: what the answer lists (:meth:`dicts`) and what is stored of the
    ranking beyond it (:func:`ranking_columns`)."""

    names: Sequence[str]
    missing_what: Sequence[Sequence[str]]
    """Per check, the words of each requirement (``missing`` indexes them)."""
    statuses: npt.NDArray[np.integer[Any]]
    values: FloatArray
    limits: FloatArray
    approximate: npt.NDArray[np.bool_]
    first_missing: npt.NDArray[np.integer[Any]]
    """Per check, the index into ``missing_what`` of what is missing; −1: nothing."""

    @classmethod
    def of(
        cls,
        ev: BatchEvaluation,
        order: npt.NDArray[np.intp],
        in_order: Callable[[npt.NDArray[Any]], npt.NDArray[Any]] | None = None,
    ) -> RankedChecks:
        """The (single) case of ``ev``, its actuators in ``order`` (``in_order``: what
        takes an array's rows in that order, where the caller has one)."""
        take = (lambda rows: rows[order]) if in_order is None else in_order
        return cls(
            names=ev.check_names,
            missing_what=ev.missing_what,
            statuses=take(ev.statuses[0]),
            values=take(ev.values[0]),
            limits=take(ev.limits[0]),
            approximate=take(ev.approximate[0]),
            first_missing=take(ev.first_missing[0]),
        )

    def dicts(self, start: int, stop: int) -> list[list[JSON]]:
        """The checks of the candidates ranked ``start`` to ``stop`` (exclusive) as the
        answer lists them (NaN → None in numpy), the candidates' lists at once."""
        names = self.names
        statuses = _STATUS_NAMES[self.statuses[start:stop]].tolist()
        values, limits = or_none(self.values[start:stop]), or_none(self.limits[start:stop])
        rows: list[list[JSON]] = [
            [
                {"name": name, "status": st, "value": v, "limit": li}
                for name, st, v, li in zip(names, status, value, limit, strict=True)
            ]
            for status, value, limit in zip(statuses, values, limits, strict=True)
        ]
        # The flags where they are set: fewer than the checks, whatever their number.
        places = np.nonzero(self.approximate[start:stop])
        for j, k in zip(*(p.tolist() for p in places), strict=True):
            rows[j][k]["approximate"] = True
        missing = self.first_missing[start:stop]
        found = missing >= 0
        places = np.nonzero(found)
        for j, k, first in zip(*(p.tolist() for p in places), missing[found].tolist(), strict=True):
            rows[j][k]["missing"] = self.missing_what[k][first]
        return rows


def checks_as_json(ev: BatchEvaluation) -> list[orjson.Fragment]:
    """The checks as JSON, one ``orjson.Fragment`` per actuator, which :func:`dump_json`
    writes as it is: rule by rule for every actuator at once, orjson writes the values
    and the limits (NaN as null), numpy's string functions join them with the rule's
    name, the statuses and the optional members into check objects, and each actuator's
    are joined into its array."""
    columns = []  # per rule, each actuator's check object
    for k, name in enumerate(ev.check_names):
        check: Any = b'{"name":' + orjson.dumps(name) + b',"status":'
        check = np.strings.add(check, _STATUS_JSON[ev.statuses[0][:, k]])
        check = np.strings.add(np.strings.add(check, b',"value":'), _json_array(ev.values[0][:, k]))
        check = np.strings.add(np.strings.add(check, b',"limit":'), _json_array(ev.limits[0][:, k]))
        approximate = ev.approximate[0][:, k]
        if approximate.any():
            check = np.where(approximate, np.strings.add(check, b',"approximate":true'), check)
        first = ev.first_missing[0][:, k]
        if (first >= 0).any():
            members = [b',"missing":' + orjson.dumps(what) for what in ev.missing_what[k]]
            check = np.strings.add(check, np.array([b"", *members], dtype=np.bytes_)[first + 1])
        columns.append(np.strings.add(check, b"}").tolist())
    return [orjson.Fragment(b"[" + b",".join(row) + b"]") for row in zip(*columns, strict=True)]


def json_items(column: npt.NDArray[Any]) -> list[bytes]:
    """Each item of ``column`` (numbers or truths, one dimension) as orjson writes it (a
    float that is NaN or infinite as null), as byte strings."""
    if not column.size:
        return []
    written = orjson.dumps(np.ascontiguousarray(column), option=orjson.OPT_SERIALIZE_NUMPY)
    return written[1:-1].split(b",")


def _json_array(column: FloatArray) -> npt.NDArray[np.bytes_]:
    """:func:`json_items` as an array, for numpy's string functions."""
    return np.array(json_items(column), dtype=np.bytes_)


_STATUS_NAMES = np.array([s.value for s in STATUS_BY_CODE], dtype=object)
"""The API's status names by status code (:data:`~actuator_selection.sizing.engine.
STATUS_BY_CODE`)."""
_STATUS_JSON = np.array([orjson.dumps(s.value) for s in STATUS_BY_CODE], dtype=np.bytes_)
"""The API's status names as JSON strings, by status code."""


def check_entry(check: Check) -> JSON:
    """A check as :func:`checks_of` lists it, from the scalar flowchart's."""
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


class DriveOptionGroups:
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
        interface, match_groups, shared, where = self._catalogue.drive_groups(actuator.model)
        checks = shared_voltage_checks(
            actuator=actuator, interface=interface, shared=shared, speed_rpm=speed_rpm, words=False
        )
        voltages = [
            {"status": v.status.value, "value": v.value, "limit": v.limit, "reference": v.reference}
            for v in checks
        ]
        merged: dict[tuple[Any, ...], JSON] = {}
        places: dict[tuple[Any, ...], tuple[tuple[int, int], ...]] = {}
        for g, at in zip(match_groups, where, strict=True):
            voltage = voltages[at]
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


Torques = tuple[float | None, float | None, float | None, float | None]
"""T_1, T_2, T_3, T_rms of a candidate; None without J_A (T_2 also where the cycle never
runs steadily)."""


def candidates(
    actuators: Sequence[Actuator],
    verdicts: Sequence[Verdict],
    torques: Sequence[Torques],
    checks: Sequence[Any],
    *,
    catalogue: CatalogueSnapshot,
    groups: DriveOptionGroups,
    speed_rpm: float,
) -> list[JSON]:
    """The answer's ``candidates`` (``CandidateOut``), in the ranking's order: per
    candidate its actuator, verdict, torques and checks (dicts, or their JSON as
    ``orjson.Fragment``), and drive options at n_2 = ``speed_rpm`` for the first
    :data:`DRIVE_OPTIONS_LISTED` that are not unsuitable."""
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
            "checks": checks_,
            "controllers_excluded": excluded_by_model[a.model],
            "drive_options": None,
        }
        for a, verdict, (t_1, t_2, t_3, t_rms), checks_ in zip(
            actuators, verdicts, torques, checks, strict=True
        )
    ]
    for place, verdict in enumerate(verdicts[:DRIVE_OPTIONS_LISTED]):
        if verdict is not Verdict.UNSUITABLE:
            out[place]["drive_options"] = groups.groups(actuators[place], speed_rpm)
    return out


def binding_checks(models: Sequence[str], checks: RankedChecks) -> list[JSON]:
    """``binding.checks``: per check that fails anywhere, how many candidates fail it and
    its nearest miss, the failing candidate with the smallest value/limit (∞ without a
    value or a non-zero limit; for the speed: n_2 against the largest n_max), the first in
    the ranking's order on a tie; the checks in order of the most failing, then of where
    they first fail. ``models`` and ``checks`` in the ranking's order, read as arrays:
    6,400 unsuitable candidates' checks as dicts cost a quarter of a second."""
    failing = checks.statuses == FAIL  # candidates × checks
    values, limits = checks.values, checks.limits
    with np.errstate(all="ignore"):
        no_ratio = np.isnan(values) | np.isnan(limits) | (limits == 0)
        ratio = np.where(no_ratio, math.inf, values / np.where(no_ratio, 1.0, limits))
    counts = failing.sum(axis=0)
    first = failing.argmax(axis=0)  # where each check first fails
    kinds: list[JSON] = []
    for k in sorted(np.flatnonzero(counts).tolist(), key=lambda k: (first[k], k)):
        where = np.flatnonzero(failing[:, k])
        j = int(where[np.argmin(ratio[where, k])])  # the first of the least
        value, limit = float(values[j, k]), float(limits[j, k])
        kinds.append(
            {
                "name": checks.names[k],
                "failing": int(counts[k]),
                "value": None if math.isnan(value) else value,
                "limit": None if math.isnan(limit) else limit,
                "model": models[j],
            }
        )
    kinds.sort(key=lambda kind: -kind["failing"])
    return kinds


def binding(
    actuators: Sequence[Actuator],
    verdicts: Sequence[Verdict],
    checks: RankedChecks,
    app: Application,
) -> JSON | None:
    """``binding`` (``BindingOut``): what binds across the catalogue when every candidate
    is unsuitable (else None).

    What binds, check by check (:func:`binding_checks`, from the candidates' own checks,
    in the ranking's order). Then what the inverse solve (``sizing/inverse.py``) says of a
    longer pause and a longer t_1 for the nearest miss of all, the first candidate: the
    shortest value with which no check fails, or none (and the checks that fail at every
    value). The range of the load's own lead or diameter is added by the service
    (``services/ratio.guidance``)."""
    if not verdicts or any(v is not Verdict.UNSUITABLE for v in verdicts):
        return None
    kinds = binding_checks([a.model for a in actuators], checks)
    first = actuators[0]
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
    return {"candidates": len(actuators), "checks": kinds, "changes": changes}


def resolved_load(profile: Profile) -> dict[str, float]:
    """``load`` (``ResolvedLoad``) of a cycle: the load at the output."""
    return load_body(profile.load, profile.peak_speed_rpm)


def load_body(axis: AxisLoad, peak_speed_rpm: float) -> dict[str, float]:
    """``load`` (``ResolvedLoad``) of a cycle of peak speed ``peak_speed_rpm`` with the
    axis load ``axis`` (:func:`resolved_load` of its profile)."""
    return {
        "speed_rpm": peak_speed_rpm,
        "torque_nm": axis.friction_torque_nm,
        "inertia_kgm2": axis.inertia_kgm2,
        "gravity_torque_nm": axis.gravity_torque_nm,
        "efficiency": axis.efficiency,
    }


def load_columns(axes: Sequence[AxisLoad], peaks: npt.NDArray[np.float64]) -> list[list[bytes]]:
    """Each member of the cases' ``load`` (:func:`load_body` of each axis load and peak
    speed, in its order) as JSON over the cases: one array of numbers a member, written
    at once (:func:`json_items`), where every figure is a float, as from the API's
    models; else each case's figure as :func:`dump_json` writes it."""
    rows = [load_body(axis, peak) for axis, peak in zip(axes, peaks.tolist(), strict=True)]
    columns: list[list[bytes]] = []
    for key in LOAD_KEYS:
        figures = [row[key] for row in rows]
        if all(type(x) is float for x in figures):
            columns.append(json_items(np.array(figures, dtype=np.float64)))
        else:
            columns.append([dump_json(x) for x in figures])
    return columns


LOAD_KEYS = tuple(load_body(AxisLoad(inertia_kgm2=0.0, friction_torque_nm=0.0), 0.0))
"""The members of a case's ``load``, in :func:`load_body`'s order."""
LOAD_TEMPLATE = b"{" + b",".join(dump_json(k) + b":%b" for k in LOAD_KEYS) + b"}"
"""A case's ``load`` as JSON, each member's value a ``%b`` (:func:`load_columns`)."""


def segments_out(profile: Profile) -> list[dict[str, float]]:
    """``segments`` (``SegmentOut``): the cycle's segments at the output."""
    out, clock = [], 0.0
    for seg in profile.motion.segments:
        out.append(
            {
                "start_s": clock,
                "duration_s": seg.duration_s,
                "start_rpm": seg.start_rpm,
                "end_rpm": seg.end_rpm,
                "jerk_share": seg.jerk_share,
                "process_torque_nm": seg.process_torque_nm,
            }
        )
        clock += seg.duration_s
    return out


def selection_answer(
    *,
    id: str,
    created_at: datetime,
    catalogue_version: int,
    body: SelectionRequest,
    request: JSON,
    profile: Profile,
    rules: Sequence[Rule],
    controllers: list[JSON],
    candidates: list[JSON],
    total: int,
    counts: dict[str, int],
    next_cursor: str | None,
    binding: JSON | None,
) -> JSON:
    """The whole answer (``SelectionOut``) of the load case ``body`` (``request``: its
    fields as stored) over the cycle ``profile``, from the first :func:`candidates` of
    the ranking (of ``total``, ``counts`` by verdict; ``next_cursor`` reads on), the
    ``controllers`` they refer to (:meth:`DriveOptionGroups.refs`) and the
    :func:`binding`."""
    bearing = output_bearing_note(body.output_load)
    return {
        "id": id,
        "created_at": created_at,
        "catalogue_version": catalogue_version,
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
        "check_rules": check_rules(rules),
        "controllers": controllers,
        "candidates": candidates,
        "total_candidates": total,
        "verdict_counts": counts,
        "next_cursor": next_cursor,
        "binding": binding,
    }


VERDICT_NAMES = ("suitable", "unconfirmed", "unsuitable")
"""The verdicts in the ranking's order, as ``verdict_counts`` lists them."""


def verdict_counts(codes: npt.NDArray[np.integer[Any]]) -> dict[str, int]:
    """``verdict_counts``: how many candidates of the whole ranking have each verdict, from
    the engine's verdict codes (:data:`~actuator_selection.sizing.engine.VERDICT_BY_CODE`)."""
    counts = dict.fromkeys(VERDICT_NAMES, 0)
    tally = np.bincount(codes, minlength=len(VERDICT_BY_CODE)).tolist()
    for verdict, n in zip(VERDICT_BY_CODE, tally, strict=True):
        counts[VALUE_OF[verdict]] += n
    return counts


RANKING_COMPRESSION = 1
"""zstd level of the stored rest of a ranking (:func:`ranking_rest`)."""

_COMPRESSORS = threading.local()
"""Each thread's zstd compressor of rests (:func:`ranking_rest`), made once: not shared
between threads; a new one per selection cost 0.13 M instructions of 14.9 M."""


def _rest_compressor() -> zstandard.ZstdCompressor:
    found: zstandard.ZstdCompressor | None = getattr(_COMPRESSORS, "zstd", None)
    if found is None:
        found = _COMPRESSORS.zstd = zstandard.ZstdCompressor(level=RANKING_COMPRESSION)
    return found


RANKING_MAGIC = b"RNK1"
"""The first bytes of a stored rest of a ranking in columns (:func:`ranking_rest`); a rest
upgraded from an answer that listed every candidate (migration 0018) is JSON."""


def ranking_rest(
    *,
    start: int,
    model: list[str],
    family: list[str],
    gear_ratio: list[float | None],
    verdict: list[str],
    excluded: list[int],
    torques: Sequence[FloatArray],
    checks: RankedChecks,
) -> bytes:
    """The ranking from place ``start`` on, as stored to be paged later
    (:func:`ranked_candidates`), zstd-compressed: :data:`RANKING_MAGIC`, the length of a
    JSON header (4 bytes, little-endian), the header (the words: models, families,
    verdicts, check names, what checks miss, the status names by code; each array's name,
    dtype and shape), then the arrays' bytes (T_1, T_2, T_3, T_rms; each check's status,
    value, limit, approximate and missing), so that no float is written as text: 6,400
    candidates' floats as JSON text took longer than the whole ranking. ``torques`` and
    ``checks`` are the whole ranking's, in its order; the stored candidates' ``model``,
    ``family``, ``gear_ratio``, ``verdict`` (as answers write it) and ``excluded``
    (controllers Table 521.1 excludes) are theirs alone, in the same order."""
    arrays = {
        "torques": np.stack([t[start:] for t in torques]),
        "status": checks.statuses[start:],
        "value": checks.values[start:],
        "limit": checks.limits[start:],
        "approximate": checks.approximate[start:],
        "missing": checks.first_missing[start:],
    }
    header = {
        "start": start,
        "statuses": _STATUS_NAMES.tolist(),
        "checks": list(checks.names),
        "missing_what": [list(w) for w in checks.missing_what],
        "model": model,
        "family": family,
        "gear_ratio": gear_ratio,
        "verdict": verdict,
        "controllers_excluded": excluded,
        "arrays": [[name, a.dtype.str, list(a.shape)] for name, a in arrays.items()],
    }
    written = orjson.dumps(header)
    parts = [RANKING_MAGIC, len(written).to_bytes(4, "little"), written]
    parts += [np.ascontiguousarray(a).tobytes() for a in arrays.values()]
    return _rest_compressor().compress(b"".join(parts))


def ranked_candidates(stored: bytes, start: int, stop: int) -> list[JSON]:
    """The candidates ranked ``start`` to ``stop`` (exclusive) of a stored rest of a
    ranking (:func:`ranking_rest`), as ``CandidateOut`` (no drive options: the
    candidate's detail lists them). A rest upgraded from an answer that listed every
    candidate (migration 0018) holds them as they were (JSON, ``rows``)."""
    raw = zstandard.ZstdDecompressor().decompress(stored)
    if not raw.startswith(RANKING_MAGIC):
        data = orjson.loads(raw)
        first = data["start"]
        rows: list[JSON] = data["rows"][max(start - first, 0) : max(stop - first, 0)]
        return rows
    size = int.from_bytes(raw[4:8], "little")
    header = orjson.loads(raw[8 : 8 + size])
    arrays: dict[str, Any] = {}
    offset = 8 + size
    for name, dtype, shape in header["arrays"]:
        count = int(np.prod(shape))
        arrays[name] = np.frombuffer(raw, dtype=dtype, count=count, offset=offset).reshape(shape)
        offset += arrays[name].nbytes
    status_now = _STATUS_NAMES.tolist()
    recoded = np.array([status_now.index(s) for s in header["statuses"]], dtype=np.intp)
    checks = RankedChecks(
        names=header["checks"],
        missing_what=header["missing_what"],
        statuses=recoded[arrays["status"]],
        values=arrays["value"],
        limits=arrays["limit"],
        approximate=arrays["approximate"],
        first_missing=arrays["missing"],
    )
    first = header["start"]
    lo, hi = max(start - first, 0), min(max(stop - first, 0), len(header["model"]))
    listed = checks.dicts(lo, hi)
    torques = [or_none(t[lo:hi]) for t in arrays["torques"]]
    return [
        {
            "model": header["model"][j],
            "family": header["family"][j],
            "gear_ratio": header["gear_ratio"][j],
            "verdict": header["verdict"][j],
            "accel_torque_nm": torques[0][i],
            "constant_torque_nm": torques[1][i],
            "decel_torque_nm": torques[2][i],
            "rms_torque_nm": torques[3][i],
            "checks": listed[i],
            "controllers_excluded": header["controllers_excluded"][j],
            "drive_options": None,
        }
        for i, j in enumerate(range(lo, hi))
    ]
