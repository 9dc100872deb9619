"""A stored machine project as IDTA 02021 records (issue 31): one PowerDriveTrainSizing
submodel per axis under one shell, since the template describes one drive train (one
motion pattern, one transformation mechanism). Each axis's submodel is written as a
selection's is (``services/aas.py``): its load and cycle (its own motion file), its
mechanism, its chosen actuator as the first main component and its chosen controller
(Table 521.1) as the second, the checks that did not pass as messages; and, from the
project's bus sizing, the energy the axis draws from the DC bus per cycle
(EnergyConsumtionPerCycle, kWh), which a single selection cannot give.
"""

from __future__ import annotations

import gzip
import json
from collections.abc import Mapping

import orjson
from basyx.aas import model
from sqlalchemy.orm import Session

from actuator_selection.db.projects import ProjectRepository
from actuator_selection.errors import ConflictError
from actuator_selection.schemas.projects import ProjectRequest
from actuator_selection.schemas.quotes import StoredSelection
from actuator_selection.services.aas import (
    DriveTrain,
    Localize,
    SizingProject,
    SizingRecord,
    chosen_of,
    drive_train,
    shell_of,
)
from actuator_selection.services.aas_motion import motion_csv, motion_rows
from actuator_selection.services.catalogue import CatalogueSnapshot
from actuator_selection.services.errors import not_found
from actuator_selection.services.selections import detail_of, size_selection
from actuator_selection.sizing.motion import pieces_of

PROJECT_REQUEST_FILE = "/aasx/files/project-request.json"
"""Where a machine project's AASX holds the project request (a ``SizingProjectLink``)."""

J_PER_KWH = 3.6e6
"""Joules in a kilowatt-hour: the template's unit of EnergyConsumtionPerCycle."""


def project_record(
    session: Session,
    catalogue: CatalogueSnapshot,
    project_id: str,
    *,
    localizers: Mapping[str, Localize],
    link: str,
    client_name: str = "",
) -> SizingRecord:
    """The IDTA 02021 record of a stored machine project: one PowerDriveTrainSizing
    submodel per axis (the template describes one drive train), each with the axis's load
    and cycle (its own motion file), its chosen actuator and controller, and the energy it
    draws from the DC bus per cycle; 404 when there is none, 409 when the catalogue has
    changed since it was sized."""
    found = ProjectRepository(session).get(project_id)
    if found is None:
        raise not_found(["path", "project_id"], "unknown_project", project_id=project_id)
    if found.catalogue_version != catalogue.version:
        raise ConflictError(
            "project_id",
            f"the catalogue has changed since this project was sized (version "
            f"{found.catalogue_version}, now {catalogue.version}); size it again for its record",
            where="path",
        )
    request = ProjectRequest.model_validate(found.request)
    answer = orjson.loads(gzip.decompress(found.answer_gzip))
    rows = {c.source_row: c for c in catalogue.controllers}
    submodels: list[model.Submodel] = []
    files: dict[str, tuple[bytes, str]] = {}
    for k, (axis, sized) in enumerate(zip(request.axes, answer["axes"], strict=True), start=1):
        actuator = catalogue.actuators_of([sized["model"]])[0]
        app = axis.to_core()
        one = size_selection(axis, app, (actuator,), catalogue, found.updated_at)
        stored = StoredSelection.model_validate(orjson.loads(one.answer))
        key = f"{project_id}:axis:{k}"
        chosen = chosen_of(
            {
                lang: detail_of(session, catalogue, axis, actuator, key, localize)
                for lang, localize in localizers.items()
            }
        )
        row = (sized.get("controller") or {}).get("source_row")
        c = rows.get(row) if row is not None else None
        name = sized["name"] or str(k)
        motion_file = f"/aasx/files/MotionSection-axis{k}.csv"
        submodels.append(
            drive_train(
                DriveTrain(
                    id=f"urn:actuator-selection:project:{key}:sizing",
                    project=SizingProject(
                        client_name=client_name,
                        name=f"{request.name}: axis {name}",
                        description=f"Machine project {project_id}, axis {k} of "
                        f"{len(request.axes)} ({name}) on a {request.bus.bus_class.value} DC "
                        f"bus, catalogue version {found.catalogue_version}",
                        link=link,
                        request_file=PROJECT_REQUEST_FILE,
                        created=found.created_at,
                        changed=found.updated_at,
                    ),
                    stored=stored,
                    request=axis,
                    chosen=chosen,
                    controller=None
                    if c is None
                    else (c.manufacturer, c.type if c.variant is None else f"{c.type} {c.variant}"),
                    others=[],
                    motion_file=motion_file,
                    label=f"axis {name}, {actuator.model}",
                    energy_in_kwh=sized["power"]["energy_in_j"] / J_PER_KWH,
                )
            )
        )
        files[motion_file] = (motion_csv(motion_rows(pieces_of(app.profile.motion))), "text/csv")
    files[PROJECT_REQUEST_FILE] = (json.dumps(found.request).encode(), "application/json")
    return SizingRecord(
        shell=shell_of(f"urn:actuator-selection:project:{project_id}", submodels),
        submodels=tuple(submodels),
        files=files,
    )
