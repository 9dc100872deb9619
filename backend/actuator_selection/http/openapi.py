"""The OpenAPI document for client generators, completed in one place.

FastAPI's document is post-processed once (:func:`install`):

- every operation documents its error answers with the one error schema
  (``schemas.errors.ErrorOut``, the shape ``http/errors.py`` writes) in place of
  FastAPI's ``HTTPValidationError``: 422 and 503 everywhere (a ``%00`` in any query
  is a 422, overload a 503 with ``Retry-After``), 401 where an API key is read (and
  429 with ``Retry-After`` after too many wrong keys, ``http/throttle.py``), 403
  where a role is needed, 404 where the path names a resource, 409 where a write can
  conflict, 400 and 413 where a body is taken, 415 where a JSON body is taken (a body
  in another media type or encoding, ``http/media_types.py``) or the decorator says so;
- a ``201 Created`` documents its ``Location`` header (each endpoint sets it);
- the ``HTTPBearer`` security scheme (``Authorization: Bearer <key>``, ``http/auth.py``):
  required on operations that need a role, optional (``[{}, {"HTTPBearer": []}]``)
  where anonymous callers are let in;
- request bodies carry an example: the first of their model's ``examples``, or
  :data:`BODY_EXAMPLES` for the bodies the routers describe by hand;
- the schemas a request body uses say what may be left out by ``required`` alone
  (:func:`_defaults_in_words`): a field's ``default`` moves into its description,
  because generators read a ``default`` as "always present" (openapi-typescript's
  default ``defaultNonNullable`` types such a field as required, and a client could
  not send the README's example without ``high_dynamics``);
- ``servers``: the API's base URL (:func:`servers`: ``/`` unless ``PUBLIC_BASE_URL`` names one).

Which operation reads a key or needs a role is read from its dependencies
(:func:`~actuator_selection.http.auth.get_principal`, the ``require_role`` marker),
so a new route is documented rightly without touching this module.
"""

from __future__ import annotations

import copy
import json
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from typing import Any

from fastapi import FastAPI
from fastapi.dependencies.models import Dependant
from fastapi.routing import APIRoute, iter_route_contexts

from actuator_selection.catalogue.csvio import to_json_values
from actuator_selection.catalogue.files import CATALOGUE_SPECS, JSON_KEYS
from actuator_selection.config import SEED_DIR
from actuator_selection.db.seed import read_catalogue
from actuator_selection.http.auth import ROLES_ATTRIBUTE, get_principal
from actuator_selection.http.deps import SAFE_METHODS, is_reads_only
from actuator_selection.schemas.errors import ErrorOut

ERROR_SCHEMA = ErrorOut.__name__
SECURITY_SCHEME = "HTTPBearer"
_ERROR_REF = {"$ref": f"#/components/schemas/{ERROR_SCHEMA}"}
_FASTAPI_ERROR_SCHEMAS = ("HTTPValidationError", "ValidationError")
_REF = re.compile(r'"#/components/schemas/([^"]+)"')

ERROR_DESCRIPTIONS: dict[int, str] = {
    400: "the body could not be parsed as JSON (malformed, or nested too deeply)",
    401: "no API key where one is required, or an unknown, revoked or malformed key",
    403: "the API key lacks the role this needs",
    404: "the resource the path names does not exist",
    409: "the request conflicts with the resource's state, or a concurrent change wrote "
    "the same record first (nothing was changed; send it again)",
    413: "the body is larger than the limit",
    415: "a Content-Type that is not accepted here (JSON bodies: application/json in UTF-8)",
    422: "a parameter or body value breaks a rule; `loc` names it",
    429: "too many wrong API keys from this address; retry after `Retry-After` s",
    503: "overloaded or the database is busy; nothing was changed, retry after `Retry-After` s",
}
_HEADERS: dict[int, dict[str, Any]] = {
    401: {
        "WWW-Authenticate": {
            "description": 'the challenge: Bearer realm="actuator-selection"',
            "schema": {"type": "string"},
        }
    },
    429: {
        "Retry-After": {
            "description": "seconds until a key is looked up again for this address",
            "schema": {"type": "integer", "minimum": 1},
        }
    },
    503: {
        "Retry-After": {
            "description": "seconds to wait before sending the request again",
            "schema": {"type": "integer", "minimum": 1},
        }
    },
}

_WORKED_ACTUATOR = "FHA-25C-50-L"
BODY_EXAMPLES: dict[str, dict[str, Any]] = {
    "create_actuator": {
        "model": "FHA-25C-50-X",
        "family": "FHA-C",
        "gear_ratio": 50,
        "max_torque_nm": 151,
        "max_speed_rpm": 90,
        "inertia_kgm2": 0.86,
        "notes": "an example entry",
        "source": "Engineering Data for Harmonic Drive Servo Actuators, Table 516.3",
    },
    "replace_actuator": {
        "model": _WORKED_ACTUATOR,
        "family": "FHA-C",
        "gear_ratio": 50,
        "max_torque_nm": 151,
        "max_speed_rpm": 90,
        "inertia_kgm2": 0.86,
        "source": "Engineering Data for Harmonic Drive Servo Actuators, Table 516.3",
    },
    "set_interface": {
        "dc_bus_classes": "320vdc 560vdc",
        "temperature_sensors": ["ptc"],
        "feedback_systems": "",
        "derivation": "the -L variant carries the PTC (Table 518.1)",
        "source": "Engineering Data for Harmonic Drive Servo Actuators, Table 518.1",
    },
    "create_controller": {
        "manufacturer": "EXAMPLE",
        "type": "Servo 1",
        "fha_c": "tested",
        "bus_560vdc": "possible",
        "sensor_kty84_130": "tested",
        "feedback_endat": "tested",
        "source": "an example row",
    },
    "replace_controller": {
        "source_row": 1,
        "manufacturer": "SIEMENS",
        "type": "SIMODRIVE 611D",
        "fha_c": "tested",
        "bus_560vdc": "tested",
        "sensor_kty84_130": "tested",
        "feedback_resolver_2pole": "tested",
        "feedback_endat": "tested",
        "source": "Engineering Data for Harmonic Drive Servo Actuators, Table 521.1",
    },
}
"""Examples of the JSON bodies the routers document by hand (``openapi_extra``), by
operationId; each validates against its body schema (``tests/api/test_openapi.py``)."""

CSV_EXAMPLE = (
    "price_list,is_example,item_kind,item_code,description,unit_price,currency,"
    "valid_from,valid_to,source\n"
    f"EXAMPLE,true,actuator,{_WORKED_ACTUATOR},Servo actuator {_WORKED_ACTUATOR},2780.00,EUR,"
    "2025-01-01,2025-12-31,an example price\n"
)


def catalogue_example() -> dict[str, list[dict[str, Any]]]:
    """A whole catalogue in the JSON form of an import, small: the starter catalogue's
    rows for the worked example's actuator (its family, interface and sensors, one
    controller row, the shared tables). Importing it for real retires every other
    actuator; try it with ``?dry_run=true``."""
    files = read_catalogue(SEED_DIR)
    document = {
        JSON_KEYS[spec.file]: [to_json_values(spec, r.values) for r in files[spec]]
        for spec in CATALOGUE_SPECS
    }
    family = "FHA-C"
    keep: dict[str, Callable[[dict[str, Any]], bool]] = {
        "families": lambda row: row.get("name") == family,
        "actuators": lambda row: row.get("model") == _WORKED_ACTUATOR,
        "actuator_interfaces": lambda row: row.get("actuator_model") == _WORKED_ACTUATOR,
        "zone_points": lambda row: row.get("model") == _WORKED_ACTUATOR,
        "controllers": lambda row: row.get("source_row") == 1,
        "temperature_sensors": lambda row: row.get("family") == family,
    }
    return {
        key: [row for row in rows if key not in keep or keep[key](row)]
        for key, rows in document.items()
    }


def servers(public_base_url: str | None) -> list[dict[str, str]]:
    """The document's ``servers``: the configured base URL, else ``/`` (relative: the host
    the document was read from). Paths start with ``/api/v1`` below it."""
    if public_base_url:
        return [{"url": public_base_url.rstrip("/"), "description": "PUBLIC_BASE_URL"}]
    return [{"url": "/", "description": "the host this document was read from"}]


def operation_id(route: APIRoute) -> str:
    """The operationId of ``route``: its endpoint's name (``create_selection``).

    For ``generate_unique_id_function``; uniqueness is checked when the document is built.
    """
    return route.name


@dataclass(frozen=True)
class _Operation:
    """What the document needs to know of a route beyond FastAPI's own output."""

    reads_key: bool
    """The key is read (401 for a bad one)."""
    roles: tuple[str, ...] | None
    """The roles a ``require_role`` dependency admits; None: no such dependency."""
    authorizes_itself: bool
    """The endpoint reads the key itself and checks the role in its body (403 too)."""
    writes: bool
    """A write that can conflict (409)."""
    json_body: bool
    """A body FastAPI parses (400 for unparsable JSON)."""


def _calls(dependant: Dependant) -> Iterator[Callable[..., Any]]:
    for sub in dependant.dependencies:
        if sub.call is not None:
            yield sub.call
        yield from _calls(sub)


def _operations(app: FastAPI) -> dict[tuple[str, str], _Operation]:
    """Each documented route's :class:`_Operation`, by (path, method)."""
    found: dict[tuple[str, str], _Operation] = {}
    for context in iter_route_contexts(app.routes):
        route = context.original_route
        dependant = getattr(context, "dependant", None)
        if not isinstance(route, APIRoute) or not context.include_in_schema or dependant is None:
            continue
        calls = list(_calls(dependant))
        roles = next(
            (getattr(c, ROLES_ATTRIBUTE) for c in calls if hasattr(c, ROLES_ATTRIBUTE)), None
        )
        top = [d.call for d in dependant.dependencies]
        reads_only = is_reads_only(route.endpoint)
        for method in route.methods or ():
            found[(str(context.path_format), method.lower())] = _Operation(
                reads_key=get_principal in calls,
                roles=roles,
                authorizes_itself=get_principal in top,
                writes=method not in SAFE_METHODS and not reads_only,
                json_body=bool(dependant.body_params),
            )
    return found


def _statuses(path: str, op: dict[str, Any], info: _Operation) -> set[int]:
    statuses = {422, 503}
    statuses |= {int(s) for s in op.get("responses", {}) if s.isdigit() and int(s) >= 400}
    if info.reads_key:
        statuses |= {401, 429}
    if info.roles is not None or info.authorizes_itself:
        statuses.add(403)
    if "{" in path:
        statuses.add(404)
    if info.writes:
        statuses.add(409)
    if "requestBody" in op:
        statuses.add(413)
    if info.json_body:
        statuses |= {400, 415}
    return statuses


def _document_errors(path: str, op: dict[str, Any], info: _Operation) -> None:
    responses: dict[str, Any] = op.setdefault("responses", {})
    for status in sorted(_statuses(path, op, info)):
        given = responses.get(str(status), {})
        description = given.get("description")
        if not description or description == "Validation Error":
            description = ERROR_DESCRIPTIONS.get(status, f"HTTP {status}")
        entry: dict[str, Any] = {
            "description": description,
            "content": {"application/json": {"schema": dict(_ERROR_REF)}},
        }
        if status in _HEADERS:
            entry["headers"] = copy.deepcopy(_HEADERS[status])
        responses[str(status)] = entry
    op["responses"] = dict(sorted(responses.items()))


def _document_created(op: dict[str, Any]) -> None:
    created = op.get("responses", {}).get("201")
    if created is not None:
        created.setdefault("headers", {})["Location"] = {
            "description": "the path of the resource created (of a batch: its first case's)",
            "schema": {"type": "string"},
        }


def _document_security(op: dict[str, Any], info: _Operation) -> None:
    if not info.reads_key:
        return
    required = info.roles is not None
    op["security"] = [{SECURITY_SCHEME: []}] if required else [{}, {SECURITY_SCHEME: []}]


def _schema_example(schema: dict[str, Any], components: dict[str, Any]) -> Any:
    ref = schema.get("$ref", "")
    target = components.get(ref.rsplit("/", 1)[-1], {}) if ref else schema
    examples = target.get("examples")
    return examples[0] if isinstance(examples, list) and examples else None


def _document_examples(op: dict[str, Any], components: dict[str, Any]) -> None:
    content = op.get("requestBody", {}).get("content", {})
    for media_type, body in content.items():
        if "example" in body or "examples" in body:
            continue
        operation = op.get("operationId", "")
        example: Any = None
        if media_type == "application/json":
            example = BODY_EXAMPLES.get(operation)
            if example is None and operation == "import_catalogue":
                example = catalogue_example()
            if example is None:
                example = _schema_example(body.get("schema", {}), components)
        elif media_type == "text/csv":
            example = CSV_EXAMPLE
        if example is not None:
            body["example"] = copy.deepcopy(example)


def _refs(node: Any) -> set[str]:
    return set(_REF.findall(json.dumps(node)))


def _reachable(names: set[str], schemas: dict[str, Any]) -> set[str]:
    seen: set[str] = set()
    todo = list(names)
    while todo:
        name = todo.pop()
        if name not in seen and name in schemas:
            seen.add(name)
            todo.extend(_refs(schemas[name]))
    return seen


def _defaults_in_words(document: dict[str, Any], schemas: dict[str, Any]) -> None:
    """Every schema a request body reaches keeps its fields' defaults in words only.

    pydantic's validation-mode schema is right (a defaulted field is not ``required``),
    but a ``default`` beside it is read by generators as a value the answer always
    carries. Schemas also echoed in answers (a cycle's segments) lose it too: their
    fields are then typed optional, which is true of the request and safe for the answer.
    """
    bodies = [
        op.get("requestBody", {})
        for item in document.get("paths", {}).values()
        for op in item.values()
        if isinstance(op, dict)
    ]
    for name in sorted(_reachable(_refs(bodies), schemas)):
        for field in schemas[name].get("properties", {}).values():
            if isinstance(field, dict) and "default" in field:
                omitted = json.dumps(field.pop("default"), ensure_ascii=False)
                said = field.get("description", "").rstrip(". ")
                field["description"] = f"{said}; omitted: {omitted}".lstrip("; ")


def _unused(document: dict[str, Any], name: str) -> bool:
    return f'"#/components/schemas/{name}"' not in json.dumps(document)


def complete(document: dict[str, Any], app: FastAPI) -> dict[str, Any]:
    """``document`` (FastAPI's, for ``app``) completed as the module docstring says."""
    components = document.setdefault("components", {})
    schemas = components.setdefault("schemas", {})
    error_schema = ErrorOut.model_json_schema(ref_template="#/components/schemas/{model}")
    schemas.update(error_schema.pop("$defs", {}))
    schemas[ERROR_SCHEMA] = error_schema
    components.setdefault("securitySchemes", {})[SECURITY_SCHEME] = {
        "type": "http",
        "scheme": "bearer",
        "description": "an API key: `Authorization: Bearer <key>` (roles admin and sales)",
    }
    operations = _operations(app)
    seen: dict[str, str] = {}
    for path, item in document.get("paths", {}).items():
        for method, op in item.items():
            info = operations.get((path, method))
            if info is None:
                continue
            name = op.get("operationId", "")
            if name in seen:
                raise RuntimeError(f"operationId {name!r} of {method} {path} is {seen[name]}'s too")
            seen[name] = f"{method} {path}"
            _document_errors(path, op, info)
            _document_created(op)
            _document_security(op, info)
            _document_examples(op, schemas)
    for name in _FASTAPI_ERROR_SCHEMAS:
        if name in schemas and _unused(document, name):
            del schemas[name]
    _defaults_in_words(document, schemas)
    return document


def install(app: FastAPI) -> None:
    """Have ``app.openapi()`` answer the completed document.

    FastAPI builds its document once (again only when routes are added) and caches
    it; each new one is completed here, in place, once.
    """
    build = app.openapi
    completed: list[dict[str, Any]] = []

    def openapi() -> dict[str, Any]:
        document = build()
        if not completed or completed[0] is not document:
            completed[:] = [complete(document, app)]
        return document

    app.openapi = openapi  # type: ignore[method-assign]
