"""A machine project as IDTA 02021 records (issue 31): one PowerDriveTrainSizing submodel
per axis, read back with the BaSyx SDK (JSON and AASX) and validated against the template
as a selection's record is (tests/api/test_aas.py)."""

from __future__ import annotations

import copy
import csv
import io
from typing import Any

import aas_submodel_validate
import pytest
from basyx.aas import model
from basyx.aas.adapter import aasx
from basyx.aas.adapter.json import object_store_to_json, read_aas_json_file
from fastapi.testclient import TestClient
from tests.api._sales_fixtures import SalesApi, api, sales_api_with
from tests.api.test_aas import SUBMODEL_SEMANTIC_ID, TEMPLATE, _allowed_deviation, _by_path
from tests.api.test_projects import API, PICK_AND_PLACE_CELL, created

__all__ = ["api", "sales_api_with"]


def _project(client: TestClient) -> dict[str, Any]:
    """The three-axis cell with the first controller the project lists for each axis that
    has one on its bus."""
    first = created(client, PICK_AND_PLACE_CELL)
    body = copy.deepcopy(PICK_AND_PLACE_CELL)
    for axis, sized in zip(body["axes"], first["axes"], strict=True):
        axis["model"] = sized["model"]
        if sized["controllers"]:
            axis["controller"] = sized["controllers"][0]["source_row"]
    answer: dict[str, Any] = client.put(f"{API}/{first['id']}", json=body).json()
    return answer


def _submodels(store: model.DictIdentifiableStore[model.Identifiable]) -> list[model.Submodel]:
    submodels = sorted((o for o in store if isinstance(o, model.Submodel)), key=lambda s: s.id)
    for sm in submodels:
        assert sm.semantic_id is not None
        assert sm.semantic_id.key[0].value == SUBMODEL_SEMANTIC_ID
    return submodels


def _value(sm: model.Submodel, path: str) -> Any:
    element = _by_path(sm)["/" + path.replace(".", "/")]
    assert isinstance(element, model.Property | model.File | model.MultiLanguageProperty)
    return element.value


def test_every_axis_is_a_drive_train_with_its_actuator_and_controller(
    client: TestClient,
) -> None:
    project = _project(client)
    response = client.get(f"{API}/{project['id']}/aas")
    assert response.status_code == 200, response.text
    store = read_aas_json_file(io.StringIO(response.text), failsafe=False)
    shells = [o for o in store if isinstance(o, model.AssetAdministrationShell)]
    assert len(shells) == 1
    submodels = _submodels(store)
    assert len(submodels) == len(project["axes"])
    assert {r.key[0].value for r in shells[0].submodel} == {s.id for s in submodels}
    controllers = {c["source_row"]: c for a in project["axes"] for c in a["controllers"]}
    for k, (sm, axis) in enumerate(zip(submodels, project["axes"], strict=True), start=1):
        assert sm.id.endswith(f":axis:{k}:sizing")
        name = _value(sm, "SizingProjectInformation.SizingProjectName")
        assert name == f"{project['request']['name']}: axis {axis['name']}"
        article = _value(sm, "SizingResult.MainComponent01.ManufacturerArticleNumber")
        assert article == axis["model"]
        # the axis's own load: J_L as the axis's selection resolves it
        inertia = _value(sm, "SizingResult.OverallSystem.ExternalMomentOfInertia")
        assert inertia > 0
        motion = _value(
            sm,
            "ApplicationRequirements.MotionPattern.MotionPatternSections.RotativeSection"
            ".MotionSectionFile",
        )
        assert motion == f"/aasx/files/MotionSection-axis{k}.csv"
        energy = _value(sm, "SizingResult.OverallSystem.EnergyConsumtionPerCycle")
        assert energy * 3.6e6 == axis["power"]["energy_in_j"]
        elements = _by_path(sm)
        if axis["controller"] is None:
            assert "/SizingResult/MainComponent02/ManufacturerName" not in elements
        else:
            chosen = controllers[axis["controller"]["source_row"]]
            maker = _value(sm, "SizingResult.MainComponent02.ManufacturerName")
            assert chosen["name"].startswith(maker)
            assert (
                _value(sm, "SizingResult.MainComponent02.ManufacturerArticleNumber")
                in (chosen["name"])
            )
    assert any(a["controller"] is not None for a in project["axes"])

    report = aas_submodel_validate.validate(response.content, format="json", template=str(TEMPLATE))
    assert report.judged
    assert report.submodels_judged == len(project["axes"])
    assert report.unmatched == []
    unexpected = [f for f in report.findings if not _allowed_deviation(f)]
    assert unexpected == [], [f.violation.message for f in unexpected]


def test_the_aasx_holds_the_same_records_and_a_motion_file_per_axis(client: TestClient) -> None:
    project = _project(client)
    from_json = read_aas_json_file(
        io.StringIO(client.get(f"{API}/{project['id']}/aas").text), failsafe=False
    )
    response = client.get(f"{API}/{project['id']}/aas.aasx")
    assert response.status_code == 200, response.text
    assert f"project-{project['id']}.aasx" in response.headers["content-disposition"]
    store: model.DictIdentifiableStore[model.Identifiable] = model.DictIdentifiableStore()
    files = aasx.DictSupplementaryFileContainer()  # type: ignore[no-untyped-call]
    with aasx.AASXReader(io.BytesIO(response.content), failsafe=False) as reader:
        reader.read_into(store, files)
    assert object_store_to_json(model.DictIdentifiableStore(_submodels(store))) == (
        object_store_to_json(model.DictIdentifiableStore(_submodels(from_json)))
    )
    n = len(project["axes"])
    assert set(files) == {
        *(f"/aasx/files/MotionSection-axis{k}.csv" for k in range(1, n + 1)),
        "/aasx/files/project-request.json",
    }
    for k in range(1, n + 1):
        buffer = io.BytesIO()
        files.write_file(f"/aasx/files/MotionSection-axis{k}.csv", buffer)
        rows = list(csv.reader(io.StringIO(buffer.getvalue().decode()), delimiter=";"))
        # the motion file spans the axis's own cycle (2.4 s for each axis of the cell)
        assert float(rows[-1][0]) == pytest.approx(project["cycle_time_s"], rel=1e-12)


def test_unknown_project_is_404(client: TestClient) -> None:
    assert client.get(f"{API}/no-such/aas").status_code == 404
    assert client.get(f"{API}/no-such/aas.aasx").status_code == 404


def test_after_a_catalogue_change_the_record_is_a_conflict_until_sized_again(
    api: SalesApi,
) -> None:
    """As a selection's record (its candidate's detail, computed again, answers 409 after a
    catalogue change): the project's record is computed again from the stored load cases,
    so only with the catalogue the project was sized with; sized again, it is the record."""
    project = _project(api.client)
    model_name = project["axes"][0]["model"]
    exported = api.get("/api/v1/catalogue/export", role="admin", params={"format": "json"})
    (row,) = [r for r in exported.json()["actuators"] if r["model"] == model_name]
    changed = api.client.put(
        f"/api/v1/actuators/{model_name}",
        json={**row, "max_torque_nm": row["max_torque_nm"] * 0.9},
        headers=api.headers("admin"),
    )
    assert changed.status_code == 200, changed.text
    for path in ("aas", "aas.aasx"):
        response = api.client.get(f"{API}/{project['id']}/{path}")
        assert response.status_code == 409, (path, response.text)
        (error,) = response.json()["detail"]
        assert error["loc"] == ["path", "project_id"]
        assert "size it again" in error["msg"]
    # the stored project stays as it was sized
    assert api.client.get(f"{API}/{project['id']}").json() == project
    sized = api.client.post(f"{API}/{project['id']}/size")
    assert sized.status_code == 200, sized.text
    assert sized.json()["catalogue_version"] > project["catalogue_version"]
    for path in ("aas", "aas.aasx"):
        assert api.client.get(f"{API}/{project['id']}/{path}").status_code == 200, path
