"""The OpenAPI document is one a client generator can code against (``http/openapi.py``).

Checked on the document itself: readable unique operationIds, one error schema for
every error answer, the bearer security scheme where keys are read, an example for
every request body that validates against the body's schema. Checked against the
app: the examples are accepted (2xx), and the operations documented as needing a
key answer 401 without one and 403 for a key of another role.
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator
from datetime import UTC, datetime
from typing import Any

import jsonschema_rs
import pytest
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.app import create_app
from actuator_selection.config import Settings
from actuator_selection.http.openapi import ERROR_SCHEMA, SECURITY_SCHEME

__all__ = ["api", "sales_api_with"]  # fixtures

ERROR_REF = f"#/components/schemas/{ERROR_SCHEMA}"
METHODS = ("get", "put", "post", "delete", "patch")
REQUIRED: list[dict[str, list[str]]] = [{SECURITY_SCHEME: []}]
OPTIONAL: list[dict[str, list[str]]] = [{}, {SECURITY_SCHEME: []}]

PATH_VALUES = {
    "model": "FHA-25C-50-L",
    "row": "1",
    "name": "EXAMPLE — not real prices",
}
"""Path parameters that name existing resources of the seeded catalogue."""


def _document() -> dict[str, Any]:
    app = create_app(Settings(database_url="sqlite://"))
    try:
        return app.openapi()
    finally:
        app.state.engine.dispose()


DOCUMENT = _document()


def operations() -> Iterator[tuple[str, str, dict[str, Any]]]:
    """(path, method, operation) of every documented operation."""
    for path, item in DOCUMENT["paths"].items():
        for method in METHODS:
            if method in item:
                yield path, method, item[method]


OPERATIONS = list(operations())
IDS = [op["operationId"] for _, _, op in OPERATIONS]


def by_id(operation_id: str) -> tuple[str, str, dict[str, Any]]:
    return next(o for o in OPERATIONS if o[2]["operationId"] == operation_id)


def test_operation_ids_are_unique_snake_case_names() -> None:
    assert len(IDS) == len(set(IDS))
    for operation_id in IDS:
        assert re.fullmatch(r"[a-z][a-z0-9]*(_[a-z0-9]+)*", operation_id), operation_id
    assert {"create_selection", "get_selection", "list_actuators", "create_batch"} <= set(IDS)


def test_fastapi_s_validation_schema_is_gone() -> None:
    text = json.dumps(DOCUMENT)
    assert "HTTPValidationError" not in text
    assert "#/components/schemas/ValidationError" not in text
    error = DOCUMENT["components"]["schemas"][ERROR_SCHEMA]
    assert error["required"] == ["detail"]


@pytest.mark.parametrize(("path", "method", "op"), OPERATIONS, ids=IDS)
def test_every_error_answer_has_the_error_schema(
    path: str, method: str, op: dict[str, Any]
) -> None:
    responses = op["responses"]
    errors = {int(s): r for s, r in responses.items() if int(s) >= 400}
    assert {422, 503} <= set(errors), "422 and 503 are possible everywhere"
    for status, response in errors.items():
        assert set(response["content"]) == {"application/json"}, status
        assert response["content"]["application/json"]["schema"] == {"$ref": ERROR_REF}, status
        assert response["description"], status
    assert "Retry-After" in errors[503]["headers"]
    if "{" in path:
        assert 404 in errors
    if "requestBody" in op:
        assert 413 in errors
    if 401 in errors:
        assert "WWW-Authenticate" in errors[401]["headers"]


def test_bearer_security_scheme() -> None:
    schemes = DOCUMENT["components"]["securitySchemes"]
    assert schemes[SECURITY_SCHEME]["type"] == "http"
    assert schemes[SECURITY_SCHEME]["scheme"] == "bearer"


ROLE_TAGS = {"catalogue management", "prices", "quotes"}
"""The operations of these tags need an admin or sales key (``http/auth.py``)."""


@pytest.mark.parametrize(("path", "method", "op"), OPERATIONS, ids=IDS)
def test_security_is_documented_where_keys_are_read(
    path: str, method: str, op: dict[str, Any]
) -> None:
    statuses = {int(s) for s in op["responses"]}
    if op["operationId"] in ("health", "readiness"):  # open even with REQUIRE_API_KEY
        assert "security" not in op
        assert 401 not in statuses
    elif op["operationId"] in ("quote_document", "quote_document_pdf"):  # key or signed link
        assert op["security"] == OPTIONAL
        assert {401, 403} <= statuses
    elif ROLE_TAGS & set(op["tags"]):
        assert op["security"] == REQUIRED
        assert {401, 403} <= statuses
    else:  # anonymous allowed unless REQUIRE_API_KEY; a bad key is a 401
        assert op["security"] == OPTIONAL
        assert 401 in statuses
        assert 403 not in statuses


def _path(path: str, values: dict[str, str] | None = None) -> str:
    values = {**PATH_VALUES, **(values or {})}
    return re.sub(r"\{(\w+)\}", lambda m: values.get(m.group(1), "x"), path)


REQUIRED_OPS = [o for o in OPERATIONS if o[2].get("security") == REQUIRED]


@pytest.mark.parametrize(
    ("path", "method", "op"), REQUIRED_OPS, ids=[o[2]["operationId"] for o in REQUIRED_OPS]
)
def test_required_key_is_enforced(
    api: SalesApi, path: str, method: str, op: dict[str, Any]
) -> None:
    """Without a key 401; with a key of a role the operation does not admit, 403."""
    url = _path(path)
    anonymous = api.client.request(method, url)
    assert anonymous.status_code == 401, anonymous.text
    assert anonymous.json()["detail"][0]["loc"] == ["header", "Authorization"]
    other = "sales" if "catalogue management" in op["tags"] or "import" in path else "admin"
    if op["operationId"] in ("list_price_lists", "get_price_list"):
        return  # both roles read prices
    wrong = api.client.request(method, url, headers=api.headers(other))
    assert wrong.status_code == 403, (other, wrong.text)


def _body_examples() -> Iterator[tuple[str, str, Any, dict[str, Any]]]:
    for _, _, op in OPERATIONS:
        for media_type, body in op.get("requestBody", {}).get("content", {}).items():
            yield op["operationId"], media_type, body.get("example"), body["schema"]


BODIES = list(_body_examples())


@pytest.mark.parametrize(
    ("operation_id", "media_type", "example", "schema"),
    BODIES,
    ids=[f"{b[0]}-{b[1]}" for b in BODIES],
)
def test_every_json_body_has_an_example_of_its_schema(
    operation_id: str, media_type: str, example: Any, schema: dict[str, Any]
) -> None:
    if media_type == "application/zip":
        return  # binary: no example to show
    assert example is not None, f"{operation_id} {media_type}: no example"
    if media_type != "application/json":
        assert isinstance(example, str)
        return
    rooted = {**schema, "components": DOCUMENT["components"]}
    validator = jsonschema_rs.validator_for(rooted)
    problems = [f"{e.instance_path}: {e.message}" for e in validator.iter_errors(example)]
    assert not problems, problems


def example(operation_id: str, media_type: str | None = None) -> Any:
    _, _, op = by_id(operation_id)
    media_type = media_type or "application/json"
    return op["requestBody"]["content"][media_type]["example"]


@pytest.mark.parametrize(
    "operation_id",
    [
        "create_selection",
        "create_batch",
        "controller_voltage",
        "sensor_temperature",
        "overload_duration",
        "output_torque",
    ],
)
def test_open_examples_are_accepted(api: SalesApi, operation_id: str) -> None:
    path, method, _ = by_id(operation_id)
    response = api.client.request(method, path, json=example(operation_id))
    assert response.status_code in (200, 201), response.text[:1000]


@pytest.mark.parametrize(
    "operation_id",
    [
        "create_actuator",
        "replace_actuator",
        "set_zone",
        "set_interface",
        "create_controller",
        "replace_controller",
    ],
)
def test_admin_examples_are_accepted(api: SalesApi, operation_id: str) -> None:
    path, method, _ = by_id(operation_id)
    response = api.client.request(
        method, _path(path), json=example(operation_id), headers=api.headers("admin")
    )
    assert response.status_code in (200, 201), response.text[:1000]


def test_import_examples_are_accepted(api: SalesApi) -> None:
    catalogue = api.client.post(
        "/api/v1/catalogue/import?dry_run=true",
        content=json.dumps(example("import_catalogue")),
        headers=api.headers("admin", **{"Content-Type": "application/json"}),
    )
    assert catalogue.status_code == 200, catalogue.text[:1000]
    prices = api.client.post(
        "/api/v1/price-lists/import?dry_run=true",
        content=example("import_prices", "text/csv").encode(),
        headers=api.headers("admin", **{"Content-Type": "text/csv"}),
    )
    assert prices.status_code == 200, prices.text[:1000]


def test_quote_examples_are_accepted(api: SalesApi) -> None:
    """The quote example, for a stored selection and on a day before its ``valid_until``."""
    body = example("create_quote")
    api.clock.current = datetime.fromisoformat(body["valid_until"]).replace(tzinfo=UTC)
    selection = api.selection()
    created = api.post("/api/v1/quotes", json={**body, "selection_id": selection["id"]})
    assert created.status_code == 201, created.text[:1000]
    number = created.json()["number"]
    moved = api.post(f"/api/v1/quotes/{number}/status", json=example("change_status"))
    assert moved.status_code == 200, moved.text[:1000]


def test_document_is_built_once_and_completed_once() -> None:
    app = create_app(Settings(database_url="sqlite://"))
    try:
        first = app.openapi()
        assert app.openapi() is first
        op = first["paths"]["/api/v1/selections"]["post"]
        assert op["security"] == OPTIONAL
    finally:
        app.state.engine.dispose()


def test_the_document_names_its_server() -> None:
    # Relative by default: a generated client calls the host it read the document from.
    assert [s["url"] for s in DOCUMENT["servers"]] == ["/"]
    app = create_app(
        Settings(database_url="sqlite://", public_base_url="https://actuators.example.com/x/")
    )
    try:
        assert [s["url"] for s in app.openapi()["servers"]] == ["https://actuators.example.com/x"]
    finally:
        app.state.engine.dispose()


def test_request_schemas_leave_out_only_what_the_server_requires() -> None:
    selection = DOCUMENT["components"]["schemas"]["SelectionRequest"]
    assert selection["required"] == ["load", "cycle"]
    high_dynamics = selection["properties"]["high_dynamics"]
    assert "default" not in high_dynamics
    assert high_dynamics["description"].endswith("omitted: true")


CREATED = sorted(op["operationId"] for _, _, op in OPERATIONS if "201" in op["responses"])


def test_the_created_answers_are_known() -> None:
    assert CREATED == [
        "create_actuator",
        "create_batch",
        "create_controller",
        "create_profile",
        "create_project",
        "create_quote",
        "create_selection",
        "create_selection_from_aas",
    ]


@pytest.mark.parametrize("operation_id", CREATED)
def test_every_201_names_what_it_created(api: SalesApi, operation_id: str) -> None:
    """Each 201's ``Location`` is documented, and a GET of it answers what was created."""
    path, method, op = by_id(operation_id)
    assert "Location" in op["responses"]["201"]["headers"]
    body = example(operation_id, "text/csv" if operation_id == "create_profile" else None)
    role = {"create_actuator": "admin", "create_controller": "admin"}.get(operation_id)
    if operation_id == "create_batch":
        body = {**body, "store": True}
    if operation_id == "create_quote":
        role = "sales"
        api.clock.current = datetime.fromisoformat(body["valid_until"]).replace(tzinfo=UTC)
        body = {**body, "selection_id": api.selection()["id"]}
    if operation_id == "create_selection_from_aas":  # an AASX record this service wrote
        package = api.client.get(f"/api/v1/selections/{api.selection()['id']}/aas.aasx")
        created = api.client.request(
            method,
            _path(path),
            content=package.content,
            headers={"Content-Type": package.headers["Content-Type"]},
        )
    elif operation_id == "create_profile":  # a CSV file, the example of its request body
        created = api.client.request(
            method, _path(path), content=body, headers={"Content-Type": "text/csv"}
        )
    else:
        created = api.client.request(method, _path(path), json=body, headers=api.headers(role))
    assert created.status_code == 201, created.text[:1000]
    location = created.headers["Location"]
    assert location.startswith("/api/v1/")
    found = api.client.get(location, headers=api.headers(role))
    assert found.status_code == 200, found.text[:1000]
    answer = created.json()
    if operation_id == "create_batch":
        assert location == f"/api/v1/selections/{answer['results'][0]['id']}"
    else:
        assert found.json() == answer


def test_a_quotes_total_is_named_net_and_the_old_name_deprecated(api: SalesApi) -> None:
    fields = DOCUMENT["components"]["schemas"]["QuoteOut"]["properties"]
    assert fields["total"]["deprecated"] is True
    assert "net_total" in fields["total"]["description"]
    assert not any(f.get("deprecated") for name, f in fields.items() if name != "total")
    selection = api.selection()
    body = {**example("create_quote"), "selection_id": selection["id"]}
    api.clock.current = datetime.fromisoformat(body["valid_until"]).replace(tzinfo=UTC)
    quote = api.post("/api/v1/quotes", json=body).json()
    assert quote["total"] == quote["net_total"]
    assert quote["gross_total"] is not None


@pytest.mark.parametrize(
    ("path", "status"), [("/api/v1/health", "ok"), ("/api/v1/health/ready", "ready")]
)
def test_health_answers_are_documented(api: SalesApi, path: str, status: str) -> None:
    """A proxy or a generated client reads the documented shape, and the answer keeps it."""
    ok = DOCUMENT["paths"][path]["get"]["responses"]["200"]["content"]["application/json"]
    schema = DOCUMENT["components"]["schemas"][ok["schema"]["$ref"].rsplit("/", 1)[1]]
    assert schema["required"] == ["status"]
    assert schema["properties"]["status"]["const"] == status
    assert schema["additionalProperties"] is False
    assert api.client.get(path).json() == {"status": status}
