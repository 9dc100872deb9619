"""TypeScript types generated from the OpenAPI document (openapi-typescript with its
default settings, pinned in package.json) take the documentation's request examples as
they are: the README's worked example and docs/api.md's, read from their code blocks and
typed as the generated request body of the operation they are sent to, compiled with
``tsc --strict``. ``tests/api/test_generated_client.py`` does the same for Python.

The same generated types are checked in as ``types/api.d.ts``, which the page's
JavaScript imports in JSDoc (``@typedef {import(…)}``) where it reads the API's answers,
so that ``tsc -p jsconfig.json`` (``make jslint``) holds the page to the answers' models.
They must be what ``/openapi.json`` generates today: ``make api-types`` (this module run
as a script) writes them again.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path
from typing import Any

import pytest

from actuator_selection.app import create_app
from actuator_selection.config import REPO_ROOT, Settings

pytestmark = pytest.mark.node

BIN = REPO_ROOT / "node_modules" / ".bin"
API_TYPES = REPO_ROOT / "types" / "api.d.ts"
"""The page's types of the API, generated from ``/openapi.json`` (``make api-types``)."""
DOCUMENTS = (REPO_ROOT / "README.md", REPO_ROOT / "docs" / "api.md")
_BLOCK = re.compile(r"^```sh\n(.*?)^```", re.DOTALL | re.MULTILINE)
_POST = re.compile(r"curl\b.*?-X POST https?://[^/\s]+(/\S+?)['\s\\]")
_BODY = re.compile(r"-d '(.*?)'", re.DOTALL)


def request_examples(path: Path) -> list[tuple[str, Any]]:
    """(API path, JSON body) of every ``curl -X POST … -d '…'`` in ``path``'s sh blocks."""
    found: list[tuple[str, Any]] = []
    for block in _BLOCK.findall(path.read_text(encoding="utf-8")):
        target, body = _POST.search(block), _BODY.search(block)
        if target and body:
            found.append((target.group(1), json.loads(body.group(1))))
    return found


def test_the_readme_has_its_worked_example() -> None:
    """The examples are found: the README's worked example is a selection request."""
    examples = request_examples(REPO_ROOT / "README.md")
    assert any(path == "/api/v1/selections" and "load" in body for path, body in examples)


def _compile(directory: Path) -> subprocess.CompletedProcess[str]:
    command = [str(BIN / "tsc"), "--strict", "--noEmit", "--target", "es2022"]
    command += ["--module", "esnext", "--moduleResolution", "bundler", "examples.ts"]
    return subprocess.run(
        command, cwd=directory, capture_output=True, text=True, check=False, timeout=300
    )


def generate_types(directory: Path, output: str = "api.ts") -> Path:
    """The API's TypeScript types, as openapi-typescript (default settings) generates them
    from ``/openapi.json``, written to ``directory / output``."""
    app = create_app(Settings(database_url="sqlite://"))
    try:
        (directory / "openapi.json").write_text(json.dumps(app.openapi()), encoding="utf-8")
    finally:
        app.state.engine.dispose()
    command = [str(BIN / "openapi-typescript"), "openapi.json", "--output", output]
    generated = subprocess.run(
        command, cwd=directory, capture_output=True, text=True, check=False, timeout=300
    )
    assert generated.returncode == 0, generated.stdout + generated.stderr
    return directory / output


def test_the_pages_api_types_are_generated_from_openapi_today(tmp_path: Path) -> None:
    """``types/api.d.ts`` is what ``/openapi.json`` generates now: a model changed without
    ``make api-types`` fails here, before the page can drift from the answers."""
    fresh = generate_types(tmp_path, "api.d.ts").read_text(encoding="utf-8")
    assert API_TYPES.read_text(encoding="utf-8") == fresh, (
        "types/api.d.ts is stale against /openapi.json: run `make api-types`"
    )
    assert "SelectionOut: {" in fresh


@pytest.mark.slow
def test_generated_types_take_the_documented_requests(tmp_path: Path) -> None:
    generate_types(tmp_path)

    examples = [e for document in DOCUMENTS for e in request_examples(document)]
    assert len(examples) >= 2
    lines = [
        'import type { paths } from "./api";',
        "type Body<P extends keyof paths> = paths[P] extends {",
        '  post: { requestBody: { content: { "application/json": infer B } } };',
        "}",
        "  ? B",
        "  : never;",
    ]
    for i, (path, body) in enumerate(examples):
        lines.append(f"export const example{i}: Body<{json.dumps(path)}> = {json.dumps(body)};")
    (tmp_path / "examples.ts").write_text("\n".join(lines) + "\n", encoding="utf-8")
    compiled = _compile(tmp_path)
    assert compiled.returncode == 0, compiled.stdout + compiled.stderr

    # The check has teeth: a field the schema lacks is refused.
    lines.append('export const wrong: Body<"/api/v1/selections"> = { load: 1, cycle: 2 };')
    (tmp_path / "examples.ts").write_text("\n".join(lines) + "\n", encoding="utf-8")
    refused = _compile(tmp_path)
    assert refused.returncode != 0
    assert "examples.ts" in refused.stdout


if __name__ == "__main__":  # make api-types
    import shutil
    import tempfile

    with tempfile.TemporaryDirectory() as directory:
        shutil.copyfile(generate_types(Path(directory), "api.d.ts"), API_TYPES)
    print(f"wrote {API_TYPES.relative_to(REPO_ROOT)}")
