"""API keys and roles: who may do what, and how a bad key is refused."""

from __future__ import annotations

import argparse
import hashlib
from collections.abc import Callable, Sequence

import pytest
from sqlalchemy import select
from sqlalchemy.orm import Session
from tests.api._sales_fixtures import SalesApi, api, sales_api_with

from actuator_selection.cli_keys import register
from actuator_selection.db.engine import make_engine
from actuator_selection.db.migrate import upgrade
from actuator_selection.db.models.sales import ApiKeyRow

__all__ = ["api", "sales_api_with"]

BAD_KEYS = {
    "unknown but well-formed": "asel_0123456789ab_" + "A" * 43,
    "malformed": "not-a-key",
}


def test_anonymous_reads_the_catalogue_and_selects_by_default(api: SalesApi) -> None:
    assert api.get("/api/v1/actuators", role=None).status_code == 200
    assert api.get("/api/v1/actuators/FHA-25C-50-L", role=None).status_code == 200
    api.selection(models=["FHA-25C-50-L"])
    me = api.get("/api/v1/auth/me", role=None).json()
    assert me["authenticated"] is False
    assert me["require_api_key"] is False


def test_require_api_key_closes_reads_and_selections(
    sales_api_with: Callable[..., SalesApi],
) -> None:
    api = sales_api_with(require_api_key=True)
    for path in ("/api/v1/actuators", "/api/v1/families", "/api/v1/auth/me"):
        refused = api.get(path, role=None)
        assert refused.status_code == 401, path
        assert refused.headers["www-authenticate"].startswith("Bearer")
    refused = api.client.post("/api/v1/selections", json={})
    assert refused.status_code == 401  # before the body is even looked at
    for role in ("admin", "sales"):
        assert api.get("/api/v1/actuators", role=role).status_code == 200
    created = api.post(
        "/api/v1/selections",
        role="sales",
        json={
            "load": {"speed_rpm": 40, "torque_nm": 5, "inertia_kgm2": 1.3},
            "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
            "models": ["FHA-25C-50-L"],
        },
    )
    assert created.status_code == 201
    me = api.get("/api/v1/auth/me", role="sales").json()
    assert (me["role"], me["key_id"], me["require_api_key"]) == (
        "sales",
        api.key_ids["sales"],
        True,
    )


def test_a_batch_is_refused_for_its_key_before_its_cases_are_validated(
    sales_api_with: Callable[..., SalesApi],
) -> None:
    """The per-case batch's cases are validated off the event loop by a dependency of
    its route (``api/batch.py``), after the key is checked, as FastAPI validates a body:
    a refused case is the 422 with a key and a 401 without one."""
    api = sales_api_with(require_api_key=True)
    case = {
        "load": {"speed_rpm": 40, "torque_nm": -5, "inertia_kgm2": 1.3},
        "cycle": {"accel_s": 0.1, "constant_s": 0.1, "decel_s": 0.1, "pause_s": 1.0},
    }
    body = {"cases": [case]}
    refused = api.client.post("/api/v1/selections/batch", json=body)
    assert refused.status_code == 401, refused.text
    invalid = api.post("/api/v1/selections/batch", role="sales", json=body)
    assert invalid.status_code == 422, invalid.text
    assert [e["loc"] for e in invalid.json()["detail"]] == [
        ["body", "cases", 0, "load", "torque_nm"]
    ]


def test_every_bad_key_gets_the_same_401(sales_api_with: Callable[..., SalesApi]) -> None:
    """Unknown, revoked, malformed: one body, one challenge, even on open endpoints
    (with an allowance of wrong keys that the 24 requests stay within)."""
    api = sales_api_with(max_key_failures=100)
    answers = []
    candidates: dict[str, str | bytes] = {
        **{name: f"Bearer {key}" for name, key in BAD_KEYS.items()},
        "not ASCII": "Bearer asel_ü".encode("latin-1"),
        "revoked": f"Bearer {api.keys['revoked']}",
        "wrong scheme": f"Basic {api.keys['sales']}",
        "empty bearer": "Bearer ",
        "a valid key with a character changed": f"Bearer {api.keys['sales'][:-1]}"
        + ("B" if api.keys["sales"][-1] != "B" else "C"),
    }
    for name, header in candidates.items():
        for path in ("/api/v1/actuators", "/api/v1/quotes", "/api/v1/price-lists"):
            raw = header if isinstance(header, bytes) else header.encode("ascii")
            response = api.client.get(path, headers=[(b"Authorization", raw)])
            assert response.status_code == 401, (name, path)
            answers.append((response.json(), response.headers["www-authenticate"]))
    assert len({(str(body), challenge) for body, challenge in answers}) == 1


@pytest.mark.parametrize(
    ("method", "path", "allowed"),
    [
        ("post", "/api/v1/actuators", "admin"),
        ("put", "/api/v1/actuators/FHA-25C-50-L", "admin"),
        ("delete", "/api/v1/actuators/FHA-25C-50-L", "admin"),
        ("put", "/api/v1/actuators/FHA-25C-50-L/zone", "admin"),
        ("post", "/api/v1/controllers", "admin"),
        ("put", "/api/v1/controllers/3", "admin"),
        ("delete", "/api/v1/controllers/3", "admin"),
        ("get", "/api/v1/catalogue/export", "admin"),
        ("post", "/api/v1/catalogue/import", "admin"),
        ("post", "/api/v1/price-lists/import", "admin"),
        ("get", "/api/v1/quotes", "sales"),
        ("post", "/api/v1/quotes", "sales"),
        ("get", "/api/v1/quotes/Q-2026-00001", "sales"),
        ("post", "/api/v1/quotes/Q-2026-00001/status", "sales"),
        ("get", "/api/v1/quotes/Q-2026-00001/document", "sales"),
    ],
)
def test_roles_guard_their_endpoints(api: SalesApi, method: str, path: str, allowed: str) -> None:
    call = getattr(api.client, method)
    anonymous = call(path)
    assert anonymous.status_code == 401
    assert anonymous.headers["www-authenticate"].startswith("Bearer")
    other = "sales" if allowed == "admin" else "admin"
    forbidden = call(path, headers=api.headers(other))
    assert forbidden.status_code == 403
    (entry,) = forbidden.json()["detail"]
    assert (entry["loc"], entry["type"]) == (["header", "Authorization"], "forbidden")
    assert allowed in entry["msg"]
    admitted = call(path, headers=api.headers(allowed))
    assert admitted.status_code not in (401, 403)


def test_price_lists_are_read_by_admin_and_sales_only(api: SalesApi) -> None:
    assert api.get("/api/v1/price-lists", role=None).status_code == 401
    for role in ("admin", "sales"):
        lists = api.get("/api/v1/price-lists", role=role)
        assert lists.status_code == 200
        assert any(pl["is_example"] for pl in lists.json())


def run_cli(url: str, argv: Sequence[str]) -> int:
    """The key commands as cli.py mounts them."""
    parser = argparse.ArgumentParser(prog="python -m actuator_selection")
    parser.add_argument("--database-url", default=url)
    register(parser.add_subparsers(dest="command", required=True))
    args = parser.parse_args(list(argv))
    status: int = args.run(args)
    return status


def test_cli_creates_lists_and_revokes_keys_stored_only_as_hashes(
    backend: str, new_database: Callable[[str], str], capsys: pytest.CaptureFixture[str]
) -> None:
    url = new_database(backend)
    upgrade(url=url)
    assert run_cli(url, ["keys", "create", "--role", "sales", "--name", "ERP Nord"]) == 0
    out = capsys.readouterr().out
    key = out.strip().splitlines()[-1]
    assert key.startswith("asel_")
    assert len(key) == len("asel_") + 12 + 1 + 43
    prefix = key.split("_")[1]

    engine = make_engine(url)
    try:
        with Session(engine) as session:
            row = session.scalars(select(ApiKeyRow)).one()
            assert row.prefix == prefix
            assert row.key_sha256 == hashlib.sha256(key.encode()).hexdigest()
            assert key not in {str(getattr(row, c.key)) for c in ApiKeyRow.__table__.columns}
            assert row.role == "sales"
    finally:
        engine.dispose()

    assert run_cli(url, ["keys", "list"]) == 0
    listing = capsys.readouterr().out
    assert prefix in listing
    assert "ERP Nord" in listing
    assert key not in listing
    assert "active" in listing

    assert run_cli(url, ["keys", "revoke", prefix]) == 0
    assert run_cli(url, ["keys", "list"]) == 0
    assert "revoked" in capsys.readouterr().out
    assert run_cli(url, ["keys", "revoke", "nope"]) == 1
    assert run_cli(url, ["keys", "create", "--role", "sales", "--name", "x" * 101]) == 1
    with pytest.raises(SystemExit):
        run_cli(url, ["keys", "create", "--role", "root", "--name", "x"])


def test_openapi_documents_the_sales_endpoints(api: SalesApi) -> None:
    spec = api.client.get("/openapi.json")
    assert spec.status_code == 200
    paths = spec.json()["paths"]
    for path in (
        "/api/v1/auth/me",
        "/api/v1/quotes",
        "/api/v1/quotes/{number}/document",
        "/api/v1/price-lists/import",
        "/api/v1/catalogue/import",
        "/api/v1/actuators/{model}/zone",
    ):
        assert path in paths, path
    create = paths["/api/v1/actuators"]["post"]["requestBody"]["content"]["application/json"]
    assert "max_torque_nm" in create["schema"]["properties"]


def test_wrong_keys_are_throttled_per_address(sales_api_with: Callable[..., SalesApi]) -> None:
    """After ``max_key_failures`` wrong keys, any request with a key from that address is
    429 with Retry-After (a right key too, so that guessing learns nothing); requests
    without a key are served as before."""
    api = sales_api_with(max_key_failures=3, key_failure_window_s=600)
    wrong = {"Authorization": f"Bearer {BAD_KEYS['unknown but well-formed']}"}
    for _ in range(3):
        assert api.client.get("/api/v1/auth/me", headers=wrong).status_code == 401
    for headers in (wrong, api.headers("sales"), {"Authorization": "Basic x"}):
        response = api.client.get("/api/v1/auth/me", headers={**headers, "Accept-Language": "de"})
        assert response.status_code == 429
        assert response.headers["Retry-After"] == "200"  # 600 s / 3: one wrong key back
        (entry,) = response.json()["detail"]
        assert entry["loc"] == ["header", "Authorization"]
        assert (entry["code"], entry["params"]) == ("too_many_failed_keys", {"retry_after_s": 200})
        assert entry["msg"] == (
            "zu viele falsche API-Schlüssel von dieser Adresse; nach 200 s erneut versuchen"
        )
    assert api.client.get("/api/v1/actuators").status_code == 200  # no key: not throttled
    documented = api.client.get("/openapi.json").json()["paths"]["/api/v1/auth/me"]["get"]
    assert "Retry-After" in documented["responses"]["429"]["headers"]
