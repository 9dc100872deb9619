"""IDTA 02021 records, the parts issue 30 left open: every suitable candidate as a main
component, the emergency stop and the energy per cycle as "no data", and a linear axis
with its transformation mechanism imported from a record another AAS tool wrote."""

from __future__ import annotations

import io
import math
import re

import pytest
from basyx.aas import model
from basyx.aas.adapter import aasx
from basyx.aas.adapter.json import read_aas_json_file
from fastapi.testclient import TestClient
from tests.api.test_aas import TEMPLATE, _by_path, _read_aasx, _selection, _value

AASX = {"Content-Type": "application/asset-administration-shell-package"}


def test_every_suitable_candidate_is_a_main_component(client: TestClient) -> None:
    answer = _selection(client)
    sm, _ = _read_aasx(client, answer["id"])
    e = _by_path(sm)
    chosen = answer["candidates"][0]["model"]
    suitable = [c for c in answer["candidates"] if c["verdict"] == "suitable"]
    assert len(suitable) > 1  # the worked example has several
    components = sorted(p for p in e if re.fullmatch(r"/SizingResult/MainComponent\d{2}", p))
    actuators = [
        _value(e, f"{p}/ManufacturerArticleNumber")
        for p in components
        if _value(e, f"{p}/MainComponentType") == "Servo actuator (motor and gear)"
    ]
    assert actuators[0] == chosen
    assert sorted(actuators[1:]) == sorted(c["model"] for c in suitable if c["model"] != chosen)
    # each with the utilisations of its stored checks
    for p in components[2:]:
        model_name = _value(e, f"{p}/ManufacturerArticleNumber")
        candidate = next(c for c in answer["candidates"] if c["model"] == model_name)
        peak = next(c for c in candidate["checks"] if c["name"] == "peak_torque")
        assert _value(e, f"{p}/MaxTorqueUtilizationPercentage") == pytest.approx(
            100 * peak["value"] / peak["limit"], rel=1e-12
        )
        assert _value(e, f"{p}/RmsOfMotorTorque") == candidate["rms_torque_nm"]


def test_emergency_stop_and_energy_per_cycle_say_no_data(client: TestClient) -> None:
    answer = _selection(client)
    sm, _ = _read_aasx(client, answer["id"])
    e = _by_path(sm)
    for name in (
        "DecelerationForEmergencyStop",
        "CurrentForEmergencyStop",
        "DisplacementDuringEmergencyStop",
        "EnergyConsumtionPerCycle",
    ):
        element = e[f"/SizingResult/OverallSystem/{name}"]
        assert isinstance(element, model.Property)
        assert element.value is None  # never a number the service did not compute
        assert element.description is not None
        assert element.description["en"].startswith("no data")


def _linear_record(csv_text: str) -> bytes:
    """A spindle axis as another AAS tool writes it: the IDTA template read by BaSyx, its
    LinearSection and SpindleDrive filled in, the other sections and mechanisms dropped."""
    store = read_aas_json_file(str(TEMPLATE), failsafe=False)
    sm = next(o for o in store if isinstance(o, model.Submodel))
    sm.kind = model.ModellingKind.INSTANCE
    sections = sm.get_referable(
        ["ApplicationRequirements", "MotionPattern", "MotionPatternSections"]
    )
    assert isinstance(sections, model.SubmodelElementCollection)
    sections.remove_referable("RotativeSection")
    section = sections.get_referable("LinearSection")
    mechanisms = sm.get_referable("TransformationMechanism")
    assert isinstance(mechanisms, model.SubmodelElementCollection)
    for other in [m for m in mechanisms.value if m.id_short != "SpindleDrive"]:
        mechanisms.value.remove(other)
    spindle = mechanisms.get_referable("SpindleDrive")

    def fill(parent: model.Referable, id_short: str, value: float) -> None:
        prop = parent.get_referable(id_short)  # type: ignore[attr-defined]
        assert isinstance(prop, model.Property)
        prop.value_type = model.datatypes.Double
        prop.value = value

    fill(section, "LoadMass", 40.0)
    fill(section, "FrictionForce", 20.0)
    fill(spindle, "FeedConstant", 0.01)  # a 10 mm lead [m/rev]
    fill(spindle, "Efficiency", 0.9)
    fill(spindle, "InclinationAngle", 0.0)
    motion = section.get_referable("MotionSectionFile")  # type: ignore[attr-defined]
    assert isinstance(motion, model.File)
    motion.value = "/aasx/files/Linear1.csv"
    files = aasx.DictSupplementaryFileContainer()  # type: ignore[no-untyped-call]
    files.add_file("/aasx/files/Linear1.csv", io.BytesIO(csv_text.encode()), "text/csv")
    shell = next(o for o in store if isinstance(o, model.AssetAdministrationShell))
    buffer = io.BytesIO()
    with aasx.AASXWriter(buffer) as writer:
        writer.write_aas(shell.id, store, files)
    return buffer.getvalue()


def test_a_linear_section_imports_through_its_spindle(client: TestClient) -> None:
    # 0 → 0.2 m/s in 0.1 s, 0.3 s at speed, to 0 in 0.1 s, 0.5 s at rest
    csv_text = (
        "Time [s];Position [m];LinearVelocity [m/s];LinearAcceleration [m/s²]\n"
        "0.0;0;0;0\n0.1;0;0.2;0\n0.4;0;0.2;0\n0.5;0;0;0\n1.0;0;0;0\n"
    )
    response = client.post(
        "/api/v1/selections/from-aas", content=_linear_record(csv_text), headers=AASX
    )
    assert response.status_code == 201, response.text
    imported = response.json()
    direct = client.post(
        "/api/v1/selections",
        json={
            "load": {
                "type": "ball_screw_incline",
                "mass_kg": 40.0,
                "lead_mm": 10.0,
                "friction_coefficient": 0.0,
                "efficiency": 0.9,
                "incline_deg": 0.0,
                "friction_force_n": 20.0,
            },
            "cycle": {
                "segments": [
                    {"speed": 200, "duration_s": 0.1},
                    {"speed": 200, "duration_s": 0.3},
                    {"speed": 0, "duration_s": 0.1},
                    {"speed": 0, "duration_s": 0.5},
                ]
            },
        },
    )
    assert direct.status_code == 201, direct.text
    expected = {c["model"]: c for c in direct.json()["candidates"]}
    assert imported["mean_speed_rpm"] == pytest.approx(direct.json()["mean_speed_rpm"], rel=1e-12)
    assert imported["mean_speed_rpm"] == pytest.approx(0.2 * 0.4 / 1.0 / 0.01 * 60, rel=1e-12)
    for c in imported["candidates"]:
        assert c["verdict"] == expected[c["model"]]["verdict"]
        assert c["rms_torque_nm"] == pytest.approx(expected[c["model"]]["rms_torque_nm"], rel=1e-9)
    assert not math.isnan(imported["cycle_time_s"])


def test_a_linear_section_without_a_mechanism_names_it(client: TestClient) -> None:
    csv_text = "Time [s];LinearVelocity [m/s]\n0;0\n0.1;0.2\n0.2;0\n"
    record = _linear_record(csv_text)
    # the same record without its spindle: nothing reaches the actuator output
    store_bytes = record
    store = aasx.DictSupplementaryFileContainer()  # type: ignore[no-untyped-call]
    objects = model.DictIdentifiableStore()  # type: ignore[var-annotated]
    with aasx.AASXReader(io.BytesIO(store_bytes)) as reader:
        reader.read_into(objects, store)
    sm = next(o for o in objects if isinstance(o, model.Submodel))
    mechanisms = sm.get_referable("TransformationMechanism")
    assert isinstance(mechanisms, model.SubmodelElementCollection)
    mechanisms.remove_referable("SpindleDrive")
    shell = next(o for o in objects if isinstance(o, model.AssetAdministrationShell))
    buffer = io.BytesIO()
    with aasx.AASXWriter(buffer) as writer:
        writer.write_aas(shell.id, objects, store)
    response = client.post("/api/v1/selections/from-aas", content=buffer.getvalue(), headers=AASX)
    assert response.status_code == 422, response.text
    detail = response.json()["detail"][0]
    assert detail["code"] == "aas_missing_element"
    assert "SpindleDrive" in detail["msg"]
