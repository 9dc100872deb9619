"""The ratio study's floors (``sizing/ratio_floors.py``) on the catalogue as the service
reads it, the drive's bus voltage derived from the controllers (so that the
``drive_voltage`` check, which the sizing tests' catalogue cannot decide, binds and is
bounded), on SQLite and PostgreSQL: the first ``top`` of a ranked study, which leaves
off the grid the actuators its floors show cannot be listed, equal the first ``top`` of
the whole study (``top`` = every actuator: no floor used), each number the same; on the
starter catalogue and on 10 × its copies (640 actuators, as ``python -m bench.ratio``
measures; the floors first on every ``COARSE``-th value, as from ~2,000 actuators;
whether those left off fit asked at one value for hundreds at once)."""

from __future__ import annotations

from typing import Any

import pytest
from bench.ratio import CASES
from bench.selection import copied_catalogue
from sqlalchemy.orm import Session

from actuator_selection.schemas.ratio import RatioStudyRequest
from actuator_selection.services.catalogue import CatalogueCache
from actuator_selection.services.ratio import study
from actuator_selection.sizing import ratio, ratio_floors

WORKED: dict[str, Any] = {
    "load": {"speed_rpm": 4, "torque_nm": 5, "inertia_kgm2": 1.3},
    "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
}
STUDIES = {
    **{name: body for name, body in CASES.items() if body["ratio_study"]["variable"] == "ratio"},
    "fast load, ratio 0.5–5": WORKED
    | {
        "load": WORKED["load"] | {"speed_rpm": 40},
        "ratio_study": {"variable": "ratio", "min": 0.5, "max": 5},
    },
}


@pytest.mark.parametrize("name", list(STUDIES))
@pytest.mark.parametrize("copies", [1, 10])
@pytest.mark.parametrize("top", [1, 7, 100])
@pytest.mark.parametrize(
    ("fine_cells", "at_once"),
    [(ratio_floors.FINE_CELLS, ratio.AT_ONCE_LEAST), (0, 0)],
    ids=["as chosen", "coarse floors first, fits at once"],
)
def test_a_ranked_study_lists_the_whole_study_s_first(
    session: Session,
    name: str,
    copies: int,
    top: int,
    fine_cells: int,
    at_once: int,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(ratio_floors, "FINE_CELLS", fine_cells)
    monkeypatch.setattr(ratio, "AT_ONCE_LEAST", at_once)
    catalogue = copied_catalogue(CatalogueCache().snapshot(session), copies)
    request = RatioStudyRequest.model_validate(STUDIES[name])
    total = len(catalogue.actuators)
    whole = study(request, catalogue, top=total)
    first = study(request, catalogue, top=top)
    assert len(whole.actuators) == total
    assert first.actuators == whole.actuators[:top]
    assert (first.total_actuators, first.fitting_actuators) == (total, whole.fitting_actuators)
    assert whole.fitting_actuators == sum(1 for a in whole.actuators if a.intervals)
    # the checks the floors bound bind at some actuator's best value
    binding = {a.best_binding for a in whole.actuators}
    assert {"drive_voltage", "thermal_peak"} <= binding or name.startswith("fast")
