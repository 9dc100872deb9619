"""The core imports no web framework, ORM or validation library; the schemas no database."""

from __future__ import annotations

import json
import subprocess
import sys


def _modules_after_importing(package: str) -> set[str]:
    """``sys.modules`` of a fresh interpreter that imported every module of ``package``."""
    code = (
        f"import json, sys, pkgutil, importlib, {package} as package\n"
        f"for m in pkgutil.walk_packages(package.__path__, '{package}.'):\n"
        "    importlib.import_module(m.name)\n"
        "print(json.dumps(sorted(sys.modules)))"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    return set(json.loads(out))


def test_core_imports_only_the_standard_library() -> None:
    modules = _modules_after_importing("actuator_selection.core")
    assert "actuator_selection.sizing.selection" in modules  # the walk did import the core
    for forbidden in ("fastapi", "sqlalchemy", "pydantic", "starlette", "plotly"):
        assert forbidden not in modules, f"the core imported {forbidden}"


def test_schemas_import_no_database_layer() -> None:
    modules = _modules_after_importing("actuator_selection.schemas")
    assert "actuator_selection.schemas.admin" in modules  # the walk did import the schemas
    assert "actuator_selection.schemas.prices" in modules
    for forbidden in ("actuator_selection.db", "sqlalchemy"):
        assert forbidden not in modules, f"the schemas imported {forbidden}"


def test_the_core_imports_no_layer_above_it() -> None:
    """Imports point one way: the core (its packages too, ``sizing.motion``,
    ``sizing.thermal``, ``sizing.mechanisms``) never reaches the schemas, the database,
    the services or the HTTP layer."""
    modules = _modules_after_importing("actuator_selection.core")
    for split in ("motion.segments", "thermal.overload", "mechanisms.hoist"):
        assert f"actuator_selection.core.{split}" in modules  # the walk entered the packages
    layers = ("schemas", "db", "services", "api")
    above = sorted(m for m in modules if m.split(".")[1:2] and m.split(".")[1] in layers)
    assert above == [], f"the core imported {above}"


def test_the_schemas_packages_are_walked() -> None:
    modules = _modules_after_importing("actuator_selection.schemas")
    assert "actuator_selection.schemas.selections.answer" in modules
