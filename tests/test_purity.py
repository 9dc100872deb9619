"""Imports point one way, from the edge inwards: edge → use cases → domain.

- **domain** (``sizing``, ``catalogue``, ``sales``, ``errors``, ``text`` and the words'
  codes ``phrases``): pure functions over frozen
  dataclasses; the standard library only, and numpy for the engine.
- **use cases** (``services``, ``documents``, ``db``, ``schemas``, ``i18n``,
  ``job_queue``, ``config``, ``supervision``): they compute with the domain, read and
  write the database, render the words and the documents; nothing here knows a route.
- **edge** (``app`` the application, which mounts ``api``'s routers on what ``http`` gives
  every route; ``cli``).

A module imports only its own layer and the layers inside it. The rule is read from each
module's source (every ``import``, lazy ones in functions too), so a new module is held
by it without being listed here.

Within a layer, the parts of the house (its top-level packages and modules) import one
way too: the engine reads the catalogue, never the catalogue the engine; the database
reads the settings, never the settings the database.
"""

from __future__ import annotations

import ast
import json
import subprocess
import sys
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "backend" / "actuator_selection"
NAME = "actuator_selection"

DOMAIN = ("sizing", "catalogue", "sales", "errors", "text", "phrases")
EDGE = ("app", "api", "http", "cli", "cli_keys", "__main__")
LAYERS = ("domain", "use cases", "edge")

EXCEPTIONS: dict[tuple[str, str], str] = {}
"""Known edges against the direction, each with its reason; none is added lightly."""


def _within(name: str, prefixes: tuple[str, ...]) -> bool:
    return any(name == p or name.startswith(p + ".") for p in prefixes)


def layer(module: str) -> int:
    """0 domain, 1 use cases, 2 edge, for a module named relative to the package."""
    if _within(module, DOMAIN):
        return 0
    if _within(module, EDGE):
        return 2
    return 1


def modules() -> dict[str, Path]:
    """Every module of the package by its name relative to the package (``sizing.cycle``)."""
    out = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = list(path.relative_to(PACKAGE).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        if parts:
            out[".".join(parts)] = path
    return out


def imports(module: str, path: Path) -> set[str]:
    """The absolute module names ``module``'s source imports (relative imports resolved)."""
    found: set[str] = set()
    package = module if path.name == "__init__.py" else module.rpartition(".")[0]
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = [NAME, *(package.split(".") if package else [])]
                base = ".".join(parts[: len(parts) + 1 - node.level])
                source = f"{base}.{node.module}" if node.module else base
            else:
                source = node.module or ""
            found.add(source)
            found.update(f"{source}.{alias.name}" for alias in node.names)
    return found


def house_edges() -> list[tuple[str, str]]:
    """(importer, imported) within the package, names relative to the package."""
    known = modules()
    edges = []
    for module, path in known.items():
        for name in imports(module, path):
            if name.startswith(NAME + "."):
                target = name[len(NAME) + 1 :]
                while target and target not in known:
                    target = target.rpartition(".")[0]
                if target and target != module:
                    edges.append((module, target))
    return sorted(set(edges))


def test_imports_point_from_the_edge_inwards() -> None:
    wrong = [
        f"{a} ({LAYERS[layer(a)]}) imports {b} ({LAYERS[layer(b)]})"
        for a, b in house_edges()
        if layer(b) > layer(a) and (a, b) not in EXCEPTIONS
    ]
    assert wrong == []


def test_the_exceptions_are_still_needed() -> None:
    assert set(EXCEPTIONS) <= set(house_edges())


def test_the_rule_sees_every_layer() -> None:
    """The walk found the packages, and a lazy import inside a function counts."""
    edges = house_edges()
    assert ("app", "api.selections") in edges
    assert ("services.selections", "sizing.selection") in edges
    assert ("cli", "db.engine") in edges  # imported inside a function
    assert {layer(m) for m in modules()} == {0, 1, 2}
    examples = ("sizing.checks.rules.gear", "documents.pdf", "api.quotes")
    assert [layer(m) for m in examples] == [0, 1, 2]


def test_the_domain_imports_only_the_standard_library_and_numpy() -> None:
    """Read from the source: every import of a domain module, lazy ones too."""
    allowed = set(sys.stdlib_module_names) | {"numpy", NAME}
    wrong = sorted(
        f"{module} imports {name}"
        for module, path in modules().items()
        if layer(module) == 0
        for name in imports(module, path)
        if name.split(".")[0] not in allowed
    )
    assert wrong == []


def _modules_after_importing(*packages: str) -> set[str]:
    """``sys.modules`` of a fresh interpreter that imported every module of ``packages``."""
    code = (
        "import json, sys, pkgutil, importlib\n"
        f"for name in {list(packages)!r}:\n"
        "    package = importlib.import_module(name)\n"
        "    for m in pkgutil.walk_packages(getattr(package, '__path__', []), name + '.'):\n"
        "        importlib.import_module(m.name)\n"
        "print(json.dumps(sorted(sys.modules)))"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout
    return set(json.loads(out))


def test_the_domain_loads_no_framework_when_run() -> None:
    """What importing the domain loads: no web framework, ORM, validation library or
    plotly, and no module of the layers above."""
    modules = _modules_after_importing(*(f"{NAME}.{d}" for d in DOMAIN))
    for split in ("sizing.motion.segments", "sizing.thermal.overload", "catalogue.fields"):
        assert f"{NAME}.{split}" in modules  # the walk entered the packages
    for forbidden in ("fastapi", "sqlalchemy", "pydantic", "starlette", "plotly", "babel"):
        assert forbidden not in modules, f"the domain imported {forbidden}"
    above = sorted(m for m in modules if m.startswith(NAME + ".") and layer(m[len(NAME) + 1 :]) > 0)
    assert above == [], f"the domain imported {above}"


def test_schemas_import_no_database_layer() -> None:
    modules = _modules_after_importing(f"{NAME}.schemas")
    assert f"{NAME}.schemas.admin" in modules  # the walk did import the schemas
    assert f"{NAME}.schemas.prices" in modules
    assert f"{NAME}.schemas.selections.answer" in modules  # and its packages
    for forbidden in (f"{NAME}.db", "sqlalchemy"):
        assert forbidden not in modules, f"the schemas imported {forbidden}"


def circles(edges: list[tuple[str, str]]) -> list[list[str]]:
    """The circles of ``edges``: each set of two or more modules that import one another,
    directly or through others (Tarjan's strongly connected components)."""
    graph: dict[str, list[str]] = {}
    for a, b in edges:
        graph.setdefault(a, []).append(b)
        graph.setdefault(b, [])
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(v: str) -> None:
        index[v] = low[v] = len(index)
        stack.append(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = stack[stack.index(v) :]
            del stack[stack.index(v) :]
            if len(component) > 1:
                found.append(sorted(component))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    return found


def test_no_modules_import_one_another() -> None:
    """A module that imports another which imports it back (directly or through others)
    splits one idea over both: neither can be read, tested or moved alone. Imports
    needed for types only count too: the reader follows them all the same."""
    assert circles(house_edges()) == []


AGAINST_THE_GRAIN: dict[tuple[str, str], str] = {}
"""Known imports from one part of the house back into a part that imports it, each with
its reason (as :data:`EXCEPTIONS`); none is added lightly."""


def part(module: str) -> str:
    """The part of the house ``module`` belongs to: its top-level package or module
    (``sizing``, ``config``)."""
    return module.split(".")[0]


def part_edges() -> list[tuple[str, str]]:
    """(importer, imported) between the parts of the house."""
    return sorted({(part(a), part(b)) for a, b in house_edges() if part(a) != part(b)})


def test_the_parts_of_the_house_import_one_way() -> None:
    """Two parts that import one another (``catalogue`` reading ``sizing``'s types while
    the engine reads the catalogue) are one part in two places: which comes first is
    nowhere written down, and neither can be read, tested or moved alone. The direction
    between the parts is what the circles of the modules cannot show: each module may
    import one way while their packages import both."""
    edges = [e for e in part_edges() if e not in AGAINST_THE_GRAIN]
    assert circles(edges) == []


def test_the_routers_import_not_the_application() -> None:
    """The application (``app``) mounts the routers on what ``http`` shares: neither
    ``http`` nor ``api`` imports it, and ``http`` imports no router."""
    edges = part_edges()
    assert ("app", "api") in edges
    assert ("app", "http") in edges
    assert not [e for e in edges if e[1] == "app" and e[0] not in ("cli", "__main__")]
    assert ("http", "api") not in edges


def test_the_parts_against_the_grain_are_still_so() -> None:
    edges = part_edges()
    assert all((b, a) in edges for a, b in AGAINST_THE_GRAIN)
    assert set(AGAINST_THE_GRAIN) <= set(edges)


def test_each_part_of_the_house_is_in_one_layer() -> None:
    """A package is read as one room: all its modules stand in one layer (the domain's
    words' codes are ``phrases``, not a corner of ``i18n`` that renders them)."""
    layers: dict[str, set[int]] = {}
    for module in modules():
        layers.setdefault(part(module), set()).add(layer(module))
    assert {p: ls for p, ls in layers.items() if len(ls) > 1} == {}


def test_the_parts_of_the_house() -> None:
    assert part("sizing.checks.rules.gear") == "sizing"
    assert part("config") == "config"
    assert part("phrases.check_messages") == "phrases"
    assert ("sizing", "catalogue") in part_edges()  # the engine reads the catalogue


def test_circles_finds_a_circle() -> None:
    edges = [("a", "b"), ("b", "c"), ("c", "a"), ("c", "d")]
    assert circles(edges) == [["a", "b", "c"]]
