"""A selection request read from an IDTA 02021 sizing record (AASX or AAS JSON).

A record this service wrote carries its selection request as the sizing tool's own
project file (``SizingProjectLink``, "resource for storing data of a sizing
application", :data:`services.aas.REQUEST_FILE`): that request is sized again, so the
answer is the one exported. Any other record describes one axis by its
``ApplicationRequirements``: the first ``RotativeSection`` gives J_L
(``MomentOfInertiaOfLoad``), T_L (``FrictionTorque``) and T_G (``LoadTorque``) at the
actuator output, and its motion file (``MotionSectionFile``, IDTA 02021 §2.2.2: ``;``
between columns, headings ``idShort [unit]``) the cycle: each pair of rows at different
times is a segment at constant acceleration from the one speed to the other. A record
whose first section is a ``LinearSection`` describes a linear axis: its ``LoadMass``,
``FrictionForce``, ``CounterMass`` and ``LoadSideForce`` (the process force of every
segment) through the record's ``TransformationMechanism`` (``SpindleDrive``,
``BeltDrive`` or ``RackDrive``: ``FeedConstant``, ``Efficiency``, ``InclinationAngle``,
``FrictionCoefficient``), and its motion file's ``LinearVelocity [m/s]`` the cycle.
"""

from __future__ import annotations

import io
import itertools
import json
import math
import zipfile
from collections.abc import Iterable
from typing import Any

from basyx.aas import model
from basyx.aas.adapter import aasx
from basyx.aas.adapter.json import read_aas_json_file

from actuator_selection.services.aas import REQUEST_FILE, SUBMODEL_SEMANTIC_ID
from actuator_selection.services.errors import UseCaseError, invalid
from actuator_selection.services.profile_csv import ColumnUnits, read_profile

Store = model.DictIdentifiableStore[model.Identifiable]

_SECTION = ("ApplicationRequirements", "MotionPattern", "MotionPatternSections")


def _unreadable(reason: str) -> UseCaseError:
    return invalid(["body"], "aas_unreadable", reason=reason)


MAX_UNPACKED_BYTES = 64 * 1024 * 1024
"""What an AASX may hold unpacked [bytes]: a sizing record is kilobytes, a motion file of
200 segments too; the bound keeps a small zip that unpacks to gigabytes out."""

_UNREADABLE = (
    ValueError,  # JSON, the model's constraints, OPC (pyecma376-2)
    KeyError,
    TypeError,
    AttributeError,
    IndexError,
    SyntaxError,  # lxml's XMLSyntaxError
    OSError,
    zipfile.BadZipFile,
)
"""What BaSyx's readers raise on a record they cannot read (``failsafe=False``)."""


def _unpacked_bytes(content: bytes) -> int:
    """What the zip ``content`` says its parts hold unpacked [bytes]."""
    try:
        with zipfile.ZipFile(io.BytesIO(content)) as package:
            return sum(i.file_size for i in package.infolist())
    except _UNREADABLE as exc:
        raise _unreadable(f"{type(exc).__name__}: {exc}"[:300]) from None


def _read(content: bytes) -> tuple[Store, aasx.DictSupplementaryFileContainer]:
    """The model and the package's files (none for JSON) by BaSyx's readers."""
    store: Store = model.DictIdentifiableStore()
    files = aasx.DictSupplementaryFileContainer()  # type: ignore[no-untyped-call]
    packed = zipfile.is_zipfile(io.BytesIO(content))
    unpacked = _unpacked_bytes(content) if packed else 0
    if unpacked > MAX_UNPACKED_BYTES:
        raise invalid(["body"], "aas_too_large", size=unpacked, max=MAX_UNPACKED_BYTES)
    try:
        if packed:
            with aasx.AASXReader(io.BytesIO(content), failsafe=False) as reader:
                reader.read_into(store, files)
        else:
            store = read_aas_json_file(io.StringIO(content.decode("utf-8")), failsafe=False)
    except _UNREADABLE as exc:
        raise _unreadable(f"{type(exc).__name__}: {exc}"[:300]) from None
    return store, files


def _sizing_submodel(store: Store) -> model.Submodel:
    for obj in store:
        semantic = obj.semantic_id if isinstance(obj, model.Submodel) else None
        if semantic is not None and any(k.value == SUBMODEL_SEMANTIC_ID for k in semantic.key):
            assert isinstance(obj, model.Submodel)
            return obj
    raise invalid(["body"], "aas_no_sizing_submodel", semantic_id=SUBMODEL_SEMANTIC_ID)


def _children(element: model.Referable) -> Iterable[model.SubmodelElement]:
    if isinstance(element, model.Submodel):
        return element.submodel_element
    if isinstance(element, model.SubmodelElementCollection):
        return element.value
    if isinstance(element, model.Entity):
        return element.statement
    return ()


def _child(element: model.Referable, id_short: str) -> model.SubmodelElement | None:
    """The child ``id_short``, or the first numbered one (``RotativeSection01``)."""
    children = list(_children(element))
    exact = next((c for c in children if c.id_short == id_short), None)
    if exact is not None:
        return exact
    return next(
        (
            c
            for c in children
            if c.id_short is not None
            and c.id_short.startswith(id_short)
            and c.id_short[len(id_short) :].isdigit()
        ),
        None,
    )


def _path(root: model.Referable, names: Iterable[str]) -> model.SubmodelElement:
    element: model.Referable = root
    walked: list[str] = []
    for name in names:
        walked.append(name)
        found = _child(element, name)
        if found is None:
            raise invalid(["body"], "aas_missing_element", path="/".join(walked))
        element = found
    assert isinstance(element, model.SubmodelElement)
    return element


def _file(files: aasx.DictSupplementaryFileContainer, name: str) -> bytes | None:
    if name not in files:
        return None
    buffer = io.BytesIO()
    files.write_file(name, buffer)
    return buffer.getvalue()


def _native_request(
    submodel: model.Submodel, files: aasx.DictSupplementaryFileContainer
) -> dict[str, Any] | None:
    """The request this service wrote into the record, if it is one of its records."""
    information = _child(submodel, "SizingProjectInformation")
    for element in [] if information is None else _children(information):
        if isinstance(element, model.File) and element.value == REQUEST_FILE:
            content = _file(files, REQUEST_FILE)
            if content is None:
                return None
            try:
                request = json.loads(content)
            except ValueError as exc:
                raise _unreadable(f"{REQUEST_FILE}: {exc}"[:300]) from None
            return request if isinstance(request, dict) else None
    return None


def _real(section: model.Referable, id_short: str) -> float | None:
    element = _child(section, id_short)
    if not isinstance(element, model.Property) or element.value is None:
        return None
    try:
        value = float(element.value)
    except (TypeError, ValueError):
        raise invalid(["body"], "aas_not_a_number", path=id_short) from None
    if not math.isfinite(value):
        raise invalid(["body"], "aas_not_a_number", path=id_short)
    return value


def _cycle(csv_bytes: bytes, name: str, kind: str) -> dict[str, Any]:
    """The segments of the motion file, read as a measured profile is read
    (``services/profile_csv.py``: the headings' units, a time repeated where the
    acceleration jumps): one segment per pair of rows, at constant acceleration from the
    one speed to the other (rpm on a rotary axis, mm/s on a linear one)."""
    try:
        samples = read_profile([csv_bytes], ColumnUnits())
    except UseCaseError as exc:
        raise invalid(["body"], "aas_motion_file", path=name, reason=exc.message[:300]) from None
    if samples.from_positions or samples.kind != kind:
        reason = f"no {'angular' if kind == 'rotary' else 'linear'} velocity column"
        raise invalid(["body"], "aas_motion_file", path=name, reason=reason)
    times, speeds = samples.time_s.tolist(), samples.motion.tolist()
    segments = [
        {"speed": n1, "duration_s": t1 - t0}
        for (t0, t1), n1 in zip(itertools.pairwise(times), speeds[1:], strict=True)
    ]
    return {"start_speed": speeds[0], "segments": segments}


def _motion_file(
    section: model.SubmodelElement, files: aasx.DictSupplementaryFileContainer
) -> tuple[bytes, str]:
    where = section.id_short
    motion = _child(section, "MotionSectionFile")
    if not isinstance(motion, model.File) or not motion.value:
        raise invalid(["body"], "aas_missing_element", path=f"{where}/MotionSectionFile")
    csv_bytes = _file(files, motion.value)
    if csv_bytes is None:
        raise invalid(["body"], "aas_motion_file", path=motion.value, reason="not in the package")
    return csv_bytes, motion.value


def _required(section: model.Referable, id_short: str) -> float:
    value = _real(section, id_short)
    if value is None:
        raise invalid(["body"], "aas_missing_element", path=f"{section.id_short}/{id_short}")
    return value


_LINEAR_MECHANISMS = {
    # the template's entity: (the request's type, its length field, FeedConstant [m/rev] → it)
    "SpindleDrive": ("ball_screw_incline", "lead_mm", 1000.0),
    "BeltDrive": ("belt", "pulley_diameter_mm", 1000.0 / math.pi),
    "RackDrive": ("rack_pinion", "pinion_diameter_mm", 1000.0 / math.pi),
}
"""The transformation mechanisms a linear section is read through: a spindle's feed
constant is its lead, a belt's or a rack's is π·D (IDTA 02021, ``FeedConstant``)."""


def _linear_request(
    submodel: model.Submodel,
    section: model.SubmodelElement,
    files: aasx.DictSupplementaryFileContainer,
) -> dict[str, Any]:
    """A linear axis: the section's mass and forces through the record's transformation
    mechanism, the motion file's ``LinearVelocity`` [m/s] as the cycle in mm/s."""
    mechanisms = _child(submodel, "TransformationMechanism")
    entity = next(
        (
            e
            for e in ([] if mechanisms is None else _children(mechanisms))
            if e.id_short in _LINEAR_MECHANISMS
        ),
        None,
    )
    if entity is None:
        raise invalid(
            ["body"],
            "aas_missing_element",
            path="TransformationMechanism/" + " | ".join(_LINEAR_MECHANISMS),
        )
    kind, length_field, per_feed = _LINEAR_MECHANISMS[str(entity.id_short)]
    incline = _real(entity, "InclinationAngle")
    mechanism: dict[str, Any] = {
        "type": kind,
        "mass_kg": _required(section, "LoadMass"),
        length_field: _required(entity, "FeedConstant") * per_feed,
        "efficiency": _required(entity, "Efficiency"),
        "friction_coefficient": _real(entity, "FrictionCoefficient") or 0.0,
        "incline_deg": 0.0 if incline is None else math.degrees(incline),
        "counterweight_kg": _real(section, "CounterMass") or 0.0,
        "friction_force_n": _real(section, "FrictionForce") or 0.0,
    }
    csv_bytes, name = _motion_file(section, files)
    cycle = _cycle(csv_bytes, name, "linear")
    process = _real(section, "LoadSideForce")
    if process:
        for segment in cycle["segments"]:
            segment["process_load"] = process
    return {"load": mechanism, "cycle": cycle}


def request_from_record(content: bytes) -> dict[str, Any]:
    """The selection request of an IDTA 02021 record (module docstring); 422 naming what
    the record lacks."""
    store, files = _read(content)
    submodel = _sizing_submodel(store)
    native = _native_request(submodel, files)
    if native is not None:
        return native
    sections = _path(submodel, _SECTION)
    section = _child(sections, "RotativeSection")
    if section is None:
        linear = _child(sections, "LinearSection")
        if linear is None:
            raise invalid(
                ["body"],
                "aas_missing_element",
                path="/".join((*_SECTION, "RotativeSection | LinearSection")),
            )
        return _linear_request(submodel, linear, files)
    csv_bytes, name = _motion_file(section, files)
    inertia = _required(section, "MomentOfInertiaOfLoad")
    load: dict[str, Any] = {
        "torque_nm": _real(section, "FrictionTorque") or 0.0,
        "inertia_kgm2": inertia,
        "gravity_torque_nm": _real(section, "LoadTorque") or 0.0,
    }
    return {"load": load, "cycle": _cycle(csv_bytes, name, "rotary")}
