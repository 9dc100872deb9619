"""The core imports no web framework, ORM or validation library."""

from __future__ import annotations

import json
import subprocess
import sys


def test_core_imports_only_the_standard_library() -> None:
    code = (
        "import json, sys, pkgutil, importlib, actuator_selection.core as core\n"
        "for m in pkgutil.walk_packages(core.__path__, 'actuator_selection.core.'):\n"
        "    importlib.import_module(m.name)\n"
        "print(json.dumps(sorted(sys.modules)))"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    modules = set(json.loads(out))
    assert "actuator_selection.core.selection" in modules  # the walk did import the core
    for forbidden in ("fastapi", "sqlalchemy", "pydantic", "starlette", "plotly"):
        assert forbidden not in modules, f"the core imported {forbidden}"
