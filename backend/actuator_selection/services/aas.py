"""A stored selection as an IDTA 02021 "Sizing of Power Drive Trains" record (AAS, AASX).

IDTA 02021 version 1.0 (IDTA, ZVEI, AutomationML; submodel semanticId
``https://admin-shell.io/idta/PowerDriveTrainSizing/1/0``) is the Asset Administration
Shell submodel in which machine builders, component makers and sizing tools exchange a
drive sizing. This module writes one selection as that submodel, with the model classes
of the Eclipse BaSyx Python SDK (``basyx.aas.model``) and its JSON and AASX writers:

* ``SizingProjectInformation``: the project and client names the caller gives, this
  service as the sizing tool, the selection's time as created and changed (a stored
  selection never changes), its address and (in the AASX) its request as project links,
  the catalogue version in the description.
* ``ApplicationRequirements``: one ``RotativeSection`` at the actuator output, which is
  where the flowchart sizes (CHA p. 514): J_L, T_L (friction), T_G (the load torque that
  acts at standstill too), the output bearing's forces and levers where given, and the
  cycle as the motion file ``MotionSection1.csv`` (rows at the start and end of every piece
  of constant or linear acceleration, so the profile is exact between them). A mechanism
  is already reflected to the output there; ``TransformationMechanism`` names it with its
  efficiency, friction coefficient, feed constant and inclination, for information.
  ``OverallSystemRequirements`` says whether a brake is fitted.
* ``SizingResult``: the overall system's inertias and their ratio, the chosen candidate
  (the first of the ranking unless the caller names one) as main component with its
  utilisations (value/limit of its checks), RMS torque and the output bearing's L_10 life,
  the best controller of Table 521.1 for it as a second main component, every other
  suitable candidate as a further main component (its utilisations from the stored
  checks), and every check of the chosen candidate that did not pass or passed only
  approximately as a message. The emergency stop and the energy per cycle are written
  without a value ("no data": the chapter sizes neither, :data:`NO_DATA`).

The template's idShorts are kept as it spells them (``RotraryTable``,
``InternalMomentOfIntertia``, ``EnergyConsumtionPerCycle``). Where the template types a
physical quantity ``xs:long`` while its concept description is a real measure with a unit,
the real value is written as ``xs:double`` in the concept's unit (``docs/aas.md``).
"""

from __future__ import annotations

import io
import json
import math
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from typing import Any

from basyx.aas import model
from basyx.aas.adapter import aasx
from basyx.aas.adapter.json import json_serialization
from sqlalchemy.orm import Session

import actuator_selection
from actuator_selection.db.repositories import SelectionRepository
from actuator_selection.schemas.checks import CheckOut
from actuator_selection.schemas.quotes import StoredCandidate, StoredSelection
from actuator_selection.schemas.selections import SelectionRequest
from actuator_selection.services.aas_motion import MOTION_COLUMNS, motion_csv, motion_rows
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.errors import invalid, not_found
from actuator_selection.services.selections import candidate_detail, stored_answer_json
from actuator_selection.sizing.checks import utilisation
from actuator_selection.sizing.motion import pieces_of

SUBMODEL_SEMANTIC_ID = "https://admin-shell.io/idta/PowerDriveTrainSizing/1/0"
"""IDTA 02021 version 1.0, the submodel's semanticId."""

_IDTA = "https://admin-shell.io/idta/PowerDriveTrainSizing/"

_SEMANTIC_IDS: Mapping[str, str] = {
    # The template's own spelling, where it is not _IDTA + idShort + "/1/0".
    "SizingProjectInformation": _IDTA + "SizingProjectInformation1/0",
    "ContactInformation": "https://admin-shell.io/zvei/nameplate/1/0/ContactInformations/"
    "ContactInformation",
    "Time": "https://admin-shell.io/idta/TimeSeries/RelativePointInTime/1/1",
    "RotativeSection": _IDTA + "RotativeMotionPatternSection/1/0",
    "Environmental": _IDTA + "EnvironmentalRequirements/1/0",
    "InternalMomentOfIntertia": _IDTA + "InternalMomentOfInertia/1/0",
    "MovingPart": _IDTA + "RackMovingPart/1/0",
    "BrakePresent": "0173-1#02-BAE085#007",
    "ManufacturerName": "0173-1#02-AAO677#002",
    "ManufacturerArticleNumber": "0173-1#02-AAO676#003",
    "ManufacturerProductDesignation": "0173-1#02-AAW338#001",
    "ManufacturerOrderCode": "0173-1#02-AAO227#002",
}

MOTION_FILE = "/aasx/files/MotionSection1.csv"
"""Where the AASX holds the cycle's motion file."""

REQUEST_FILE = "/aasx/files/selection-request.json"
"""Where the AASX holds the selection request, this tool's own project data (a
``SizingProjectLink``), which an import sizes again (``services.aas_import``)."""

ACTUATOR_MANUFACTURER = "Harmonic Drive"
"""The maker of every actuator of the catalogue (its families' data sheets)."""

SHOWN_CANDIDATES = 10
"""Candidates an error names when the chosen model is none of them."""

SIZING_TOOL = f"actuator-selection {actuator_selection.__version__}"

_MECHANISMS: Mapping[str, str] = {
    "ball_screw": "SpindleDrive",
    "ball_screw_incline": "SpindleDrive",
    "rotary_table": "RotraryTable",
    "rotary": "RotraryTable",
    "belt": "BeltDrive",
    "rack_pinion": "RackDrive",
    "conveyor": "BeltConveyor",
}
"""The template's entity of each of the request's mechanisms (a lift has none)."""

_UTILISATIONS = (
    # (check, utilisation percentage idShort, idShort of the value the check compares)
    ("peak_torque", "MaxTorqueUtilizationPercentage", "MaxTorqueUtilization"),
    ("max_speed", "MaxRotationSpeedUtilizationPercentage", "MaxRotationSpeedUtilization"),
    ("drive_current", "MaxCurrentUtilizationPercentage", "MaxCurrentUtilization"),
    ("continuous_duty", "MaxThermalUtilizationPercentage", None),
)
"""The flowchart's checks the template has a utilisation for: T_max (Eq. 514.1), n_max,
the drive current (Eq. 521.1), the continuous duty zone (the actuator's thermal limit)."""

Localize = Callable[[str], str]


@dataclass(frozen=True, slots=True)
class SizingRecord:
    """A selection (one drive train) or a machine project (one per axis) as an Asset
    Administration Shell with its sizing submodels, and the files its AASX holds."""

    shell: model.AssetAdministrationShell
    submodels: tuple[model.Submodel, ...]
    files: Mapping[str, tuple[bytes, str]]
    """Path in the AASX → (content, media type): the motion files and the request."""

    def store(self) -> model.DictIdentifiableStore[model.Identifiable]:
        """The shell and the submodels, as BaSyx's writers take them."""
        return model.DictIdentifiableStore([self.shell, *self.submodels])


def semantic_id(id_short: str) -> model.ExternalReference:
    """The template's semanticId of an element of the submodel."""
    value = _SEMANTIC_IDS.get(id_short, f"{_IDTA}{id_short}/1/0")
    return model.ExternalReference((model.Key(model.KeyTypes.GLOBAL_REFERENCE, value),))


def _real(id_short: str, value: float | None) -> list[model.Property]:
    """A real measure in the concept's unit, or nothing where the value is unknown."""
    if value is None or not math.isfinite(value):
        return []
    return [
        model.Property(
            id_short,
            value_type=model.datatypes.Double,
            value=float(value),
            semantic_id=semantic_id(id_short),
        )
    ]


def _text(id_short: str, value: str) -> model.Property:
    return model.Property(
        id_short, value_type=model.datatypes.String, value=value, semantic_id=semantic_id(id_short)
    )


def _words(id_short: str, words: Mapping[str, str]) -> model.MultiLanguageProperty:
    return model.MultiLanguageProperty(
        id_short, value=model.MultiLanguageTextType(dict(words)), semantic_id=semantic_id(id_short)
    )


def _collection(
    id_short: str, elements: Iterable[model.SubmodelElement]
) -> model.SubmodelElementCollection:
    return model.SubmodelElementCollection(
        id_short, value=list(elements), semantic_id=semantic_id(id_short)
    )


def _entity(
    id_short: str,
    statements: Iterable[model.SubmodelElement],
    *,
    semantic: str | None = None,
    global_asset_id: str | None = None,
) -> model.Entity:
    kind = (
        model.EntityType.CO_MANAGED_ENTITY
        if global_asset_id is None
        else model.EntityType.SELF_MANAGED_ENTITY
    )
    return model.Entity(
        id_short,
        entity_type=kind,
        statement=list(statements),
        global_asset_id=global_asset_id,
        semantic_id=semantic_id(semantic or id_short),
    )


def _rotative_section(
    stored: StoredSelection, request: SelectionRequest, motion_file: str
) -> list[Any]:
    load, bearing = stored.load, request.output_load
    gravity = getattr(request.load, "gravity_torque_nm", None)
    metadata = [
        model.Property(
            name,
            value_type=model.datatypes.Long,
            value=column,
            semantic_id=semantic_id(name),
        )
        for column, (name, _) in enumerate(MOTION_COLUMNS, start=1)
    ]
    return [
        *_real("FrictionTorque", load.torque_nm),
        *(
            []
            if bearing is None
            else [
                *_real("LeverArmAxialForce", bearing.axial_lever_m),
                *_real("AxialForce", bearing.axial_force_n),
                *_real("LeverArmRadialForce", bearing.radial_lever_m),
                *_real("RadialForce", bearing.radial_force_n),
            ]
        ),
        *_real("MomentOfInertiaOfLoad", load.inertia_kgm2),
        *_real("LoadTorque", gravity),
        _collection("MetadataRotativeMotionFile", metadata),
        model.File(
            "MotionSectionFile",
            content_type="text/csv",
            value=motion_file,
            semantic_id=semantic_id("MotionSectionFile"),
        ),
    ]


def _feed_constant_m(mechanism: Mapping[str, Any]) -> float | None:
    """Travel per revolution of the mechanism's input [m/rev]: the lead, or π·D."""
    if "lead_m" in mechanism:
        return float(mechanism["lead_m"])
    if "lead_mm" in mechanism:
        return float(mechanism["lead_mm"]) / 1000
    for key in ("pulley_diameter_mm", "pinion_diameter_mm", "roller_diameter_mm"):
        if key in mechanism:
            return math.pi * float(mechanism[key]) / 1000
    return None


def _mechanism(urn: str, mechanism: Mapping[str, Any] | None) -> list[model.Entity]:
    kind = None if mechanism is None else _MECHANISMS.get(str(mechanism.get("type")))
    if mechanism is None or kind is None:
        return []
    incline = mechanism.get("incline_deg")
    pinion = mechanism.get("pinion_diameter_mm")
    statements = [
        *_real("Efficiency", mechanism.get("efficiency")),
        *_real("InclinationAngle", None if incline is None else math.radians(incline)),
        *_real("FrictionCoefficient", mechanism.get("friction_coefficient")),
        *_real("FeedConstant", _feed_constant_m(mechanism) if kind != "RotraryTable" else None),
        *_real("DiameterPinion", None if pinion is None else pinion / 1000),
    ]
    asset = f"{urn}:mechanism"
    return [_entity(kind, statements, global_asset_id=asset)]


def _check(detail_checks: list[CheckOut], name: str) -> CheckOut | None:
    return next((c for c in detail_checks if c.name == name), None)


def _service_life_h(checks: list[CheckOut]) -> float | None:
    """The output bearing's L_10 [h] as the ``bearing_life`` check's message gives it."""
    check = _check(checks, "bearing_life")
    life = (
        None
        if check is None or check.message_params is None
        else check.message_params.get("life_h")
    )
    return float(life) if isinstance(life, int | float) else None


@dataclass(frozen=True, slots=True)
class ChosenCandidate:
    """The chosen candidate in full, its check messages in each language."""

    checks: list[CheckOut]
    messages: Mapping[str, list[str]]
    reasons: Mapping[str, list[str]]
    """What keeps the verdict from "suitable", in each language."""
    detail: Any


def _actuator(
    id_short: str, family: str, model_name: str, statements: Iterable[model.SubmodelElement]
) -> model.Entity:
    return _entity(
        id_short,
        [
            _text("MainComponentType", "Servo actuator (motor and gear)"),
            _text("ManufacturerName", ACTUATOR_MANUFACTURER),
            _text("ManufacturerArticleNumber", model_name),
            _words("ManufacturerProductDesignation", {"en": f"{family} {model_name}"}),
            _text("ManufacturerOrderCode", model_name),
            *statements,
        ],
        semantic="MainComponent",
    )


def _utilisations(checks: Iterable[Any]) -> list[model.Property]:
    """The template's utilisations of the checks (:data:`_UTILISATIONS`): 100·value/limit
    and the value compared, where the check has them."""
    by_name = {c.name: c for c in checks}
    out: list[model.Property] = []
    for name, percent, absolute in _UTILISATIONS:
        check = by_name.get(name)
        if check is None:
            continue
        share = utilisation(check.value, check.limit)
        out += _real(percent, None if share is None else 100 * share)
        if absolute is not None:
            out += _real(absolute, check.value)
    return out


def _main_components(
    chosen: ChosenCandidate, others: Iterable[StoredCandidate], controller: tuple[str, str] | None
) -> list[model.Entity]:
    """The chosen actuator (01) with its controller (02: manufacturer and article), then
    every other suitable candidate of the selection (03, …) with the utilisations its
    stored checks give."""
    d = chosen.detail
    checks = chosen.checks
    actuator = _actuator(
        "MainComponent01",
        d.family,
        d.model,
        [
            *_utilisations(checks),
            *_real("CalculatedServiceLife", _service_life_h(checks)),
            *_real("MassInertiaRatio", getattr(_check(checks, "inertia_ratio"), "value", None)),
            *_real("RmsOfMotorTorque", d.rms_torque_nm),
        ],
    )
    components = [actuator]
    if controller is not None:
        manufacturer, article = controller
        components.append(
            _entity(
                "MainComponent02",
                [
                    _text("MainComponentType", "Drive controller"),
                    _text("ManufacturerName", manufacturer),
                    _text("ManufacturerArticleNumber", article),
                    _text("ManufacturerOrderCode", article),
                ],
                semantic="MainComponent",
            )
        )
    for candidate in others:
        ratio = next((c.value for c in candidate.checks if c.name == "inertia_ratio"), None)
        components.append(
            _actuator(
                f"MainComponent{len(components) + 1:02d}",
                candidate.family,
                candidate.model,
                [
                    *_utilisations(candidate.checks),
                    *_real("MassInertiaRatio", ratio),
                    *_real("RmsOfMotorTorque", candidate.rms_torque_nm),
                ],
            )
        )
    return components


NO_DATA = (
    "DecelerationForEmergencyStop",
    "CurrentForEmergencyStop",
    "DisplacementDuringEmergencyStop",
    "EnergyConsumtionPerCycle",
)
"""Elements of the overall system the service has no number for: the chapter sizes no
emergency stop (no stopping deceleration, current or distance) and no energy balance (no
losses, no regeneration). They are written without a value, "no data" (docs/aas.md)."""


def _no_data(id_short: str) -> model.Property:
    return model.Property(
        id_short,
        value_type=model.datatypes.Double,
        value=None,
        semantic_id=semantic_id(id_short),
        description=model.MultiLanguageTextType(
            {"en": "no data: not computed by this sizing", "de": "keine Daten: nicht berechnet"}
        ),
    )


def _messages(chosen: ChosenCandidate) -> model.SubmodelElementCollection:
    """Each check of the chosen candidate that failed, warned, lacked data or passed only
    approximately, its words in English and German (a check that does not apply is no
    message: decision 0025)."""
    entries = []
    for i, check in enumerate(chosen.checks):
        if check.status == "not_applicable" or (check.status == "pass" and not check.approximate):
            continue
        criticality = "error" if check.status == "fail" else "warning"
        text = {lang: words[i] for lang, words in chosen.messages.items()}
        entries.append((criticality, text))
    return _collection(
        "Messages",
        [
            model.SubmodelElementCollection(
                f"Message{n:02d}",
                value=[_text("CriticalityOfMessage", crit), _words("MessageText", text)],
                semantic_id=semantic_id("Message"),
            )
            for n, (crit, text) in enumerate(entries, start=1)
        ],
    )


def _best_controller(chosen: ChosenCandidate) -> tuple[str, str] | None:
    """The first controller Table 521.1 does not exclude for the chosen candidate."""
    controllers = [c for c in chosen.detail.controllers if c.level != "excluded"]
    if not controllers:
        return None
    c = controllers[0]
    return c.manufacturer, c.type if c.variant is None else f"{c.type} {c.variant}"


def chosen_of(details: Mapping[str, Any]) -> ChosenCandidate:
    first = next(iter(details.values()))
    return ChosenCandidate(
        checks=first.checks,
        messages={lang: [c.message for c in d.checks] for lang, d in details.items()},
        reasons={lang: d.reasons for lang, d in details.items()},
        detail=first,
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class SizingProject:
    """What SizingProjectInformation says of the sizing."""

    client_name: str
    name: str
    description: str
    link: str
    request_file: str
    created: Any
    changed: Any


def _information(p: SizingProject) -> model.SubmodelElementCollection:
    return _collection(
        "SizingProjectInformation",
        [
            _text("ClientName", p.client_name),
            _text("SizingProjectName", p.name),
            _words("SizingProjectDescription", {"en": p.description}),
            model.File(
                "SizingProjectLink01",
                content_type="application/json",
                value=p.link,
                semantic_id=semantic_id("SizingProjectLink"),
            ),
            model.File(
                "SizingProjectLink02",
                content_type="application/json",
                value=p.request_file,
                semantic_id=semantic_id("SizingProjectLink"),
            ),
            _text("SizingToolName", SIZING_TOOL),
            model.Property(
                "DateCreated",
                value_type=model.datatypes.DateTime,
                value=p.created,
                semantic_id=semantic_id("DateCreated"),
            ),
            model.Property(
                "DateChanged",
                value_type=model.datatypes.DateTime,
                value=p.changed,
                semantic_id=semantic_id("DateChanged"),
            ),
            _collection("ContactInformation", []),
        ],
    )


@dataclass(frozen=True, slots=True, kw_only=True)
class DriveTrain:
    """One drive train to write: a load case sized, its chosen actuator and controller."""

    id: str
    project: SizingProject
    stored: StoredSelection
    request: SelectionRequest
    chosen: ChosenCandidate
    controller: tuple[str, str] | None
    others: list[StoredCandidate]
    motion_file: str
    label: str
    """What the text statement names: the model, or the axis and its model."""
    energy_in_kwh: float | None = None
    """Energy drawn from the DC bus per cycle (a machine project's axis); None: no data."""


def drive_train(t: DriveTrain) -> model.Submodel:
    """The IDTA 02021 submodel of one drive train (module docstring)."""
    stored, request, chosen = t.stored, t.request, t.chosen
    first = chosen.detail
    requirements = _collection(
        "ApplicationRequirements",
        [
            _collection(
                "MotionPattern",
                [
                    _text(
                        "MotionPatternName",
                        "trapezoid" if stored.cycle.is_trapezoid else "segments",
                    ),
                    _collection(
                        "MotionPatternSections",
                        [
                            _collection(
                                "RotativeSection", _rotative_section(stored, request, t.motion_file)
                            )
                        ],
                    ),
                ],
            ),
            _collection(
                "OverallSystemRequirements",
                [_text("BrakePresent", "true" if request.brake else "false")],
            ),
        ],
    )
    mechanism = _mechanism(t.id.removesuffix(":sizing"), stored.mechanism)
    no_data = [n for n in NO_DATA if not (n == "EnergyConsumtionPerCycle" and t.energy_in_kwh)]
    overall = _entity(
        "OverallSystem",
        [
            *_real("ExternalMomentOfInertia", stored.load.inertia_kgm2),
            *_real("InternalMomentOfIntertia", first.actuator.inertia_kgm2),
            *_real(
                "MassInertiaRatio", getattr(_check(chosen.checks, "inertia_ratio"), "value", None)
            ),
            *_real("EnergyConsumtionPerCycle", t.energy_in_kwh),
            *[_no_data(name) for name in no_data],
        ],
    )
    result = _collection(
        "SizingResult",
        [
            overall,
            *_main_components(chosen, t.others, t.controller),
            _messages(chosen),
            _words(
                "TextStatement",
                {
                    lang: f"{t.label}: {first.verdict}"
                    + ("" if not reasons else " — " + "; ".join(reasons))
                    for lang, reasons in chosen.reasons.items()
                },
            ),
        ],
    )
    return model.Submodel(
        t.id,
        id_short="PowerDriveTrainSizing",
        semantic_id=model.ExternalReference(
            (model.Key(model.KeyTypes.GLOBAL_REFERENCE, SUBMODEL_SEMANTIC_ID),)
        ),
        administration=model.AdministrativeInformation(version="1", revision="0"),
        kind=model.ModellingKind.INSTANCE,
        submodel_element=[
            _information(t.project),
            requirements,
            *([_collection("TransformationMechanism", mechanism)] if mechanism else []),
            result,
        ],
    )


def sizing_record(
    session: Session,
    catalogue: CatalogueSnapshot,
    selection_id: str,
    *,
    localizers: Mapping[str, Localize],
    link: str,
    project_name: str | None = None,
    client_name: str = "",
    model_name: str | None = None,
) -> SizingRecord:
    """The IDTA 02021 record of a stored selection (module docstring); 404 when there is
    none, 409 when the catalogue has changed since (as the candidate's detail)."""
    answer = stored_answer_json(session, selection_id)
    stored_request = SelectionRepository(session).request(selection_id)
    if answer is None or stored_request is None:
        raise not_found(["path", "selection_id"], "unknown_selection", selection_id=selection_id)
    stored = StoredSelection.model_validate(answer)
    request = SelectionRequest.model_validate(stored_request[0])
    app = request.to_core()
    chosen_model = model_name or stored.candidates[0].model
    if all(c.model != chosen_model for c in stored.candidates):
        usable = [c.model for c in stored.candidates if c.verdict != "unsuitable"]
        raise invalid(
            ["query", "model"],
            "not_a_candidate" if usable else "no_usable_candidate",
            "not_a_candidate",
            model=chosen_model,
            selection_id=selection_id,
            **({"models": usable[:SHOWN_CANDIDATES]} if usable else {}),
        )
    chosen = chosen_of(
        {
            lang: candidate_detail(session, catalogue, selection_id, chosen_model, localize)
            for lang, localize in localizers.items()
        }
    )
    project = SizingProject(
        client_name=client_name,
        name=project_name or f"Selection {selection_id}",
        description=f"Harmonic Drive servo actuator selection {selection_id}, "
        f"catalogue version {stored.catalogue_version}",
        link=link,
        request_file=REQUEST_FILE,
        created=stored.created_at,
        changed=stored.created_at,
    )
    submodel = drive_train(
        DriveTrain(
            id=f"urn:actuator-selection:selection:{selection_id}:sizing",
            project=project,
            stored=stored,
            request=request,
            chosen=chosen,
            controller=_best_controller(chosen),
            others=[
                c for c in stored.candidates if c.verdict == "suitable" and c.model != chosen_model
            ],
            motion_file=MOTION_FILE,
            label=chosen_model,
        )
    )
    return SizingRecord(
        shell=shell_of(f"urn:actuator-selection:selection:{selection_id}", [submodel]),
        submodels=(submodel,),
        files={
            MOTION_FILE: (motion_csv(motion_rows(pieces_of(app.profile.motion))), "text/csv"),
            REQUEST_FILE: (json.dumps(stored_request[0]).encode(), "application/json"),
        },
    )


def shell_of(asset: str, submodels: Iterable[model.Submodel]) -> model.AssetAdministrationShell:
    return model.AssetAdministrationShell(
        model.AssetInformation(model.AssetKind.INSTANCE, global_asset_id=asset),
        f"{asset}:aas",
        id_short="SizingProject",
        submodel={model.ModelReference.from_referable(s) for s in submodels},
    )


class _Encoder(json_serialization.AASToJsonEncoder):
    """BaSyx's JSON encoder, without the empty ``specificAssetIds`` it writes for every
    entity (the metamodel wants the list absent or not empty)."""

    @classmethod
    def _entity_to_json(cls, obj: model.Entity) -> dict[str, object]:
        data = super()._entity_to_json(obj)
        if not data.get("specificAssetIds"):
            data.pop("specificAssetIds", None)
        return data


def record_json(record: SizingRecord) -> bytes:
    """The record as AAS JSON (shell and submodel; the motion file is the AASX's)."""
    return json_serialization.object_store_to_json(record.store(), encoder=_Encoder).encode()


def record_aasx(record: SizingRecord) -> bytes:
    """The record as an AASX package with its files (the motion files, the request); the model
    as XML, which BaSyx writes without the JSON encoder's empty lists."""
    files = aasx.DictSupplementaryFileContainer()  # type: ignore[no-untyped-call]
    for path, (content, media_type) in record.files.items():
        files.add_file(path, io.BytesIO(content), media_type)
    buffer = io.BytesIO()
    with aasx.AASXWriter(buffer) as writer:
        writer.write_aas(record.shell.id, record.store(), files)
    return buffer.getvalue()
