"""A stored selection's whole ranking, as a client reads it: the answer lists the first
``top`` candidates (``DEFAULT_TOP`` unless asked), the rest stream from its cursor."""

from __future__ import annotations

import json
from typing import Any

from fastapi.testclient import TestClient


def whole_ranking(client: TestClient, answer: dict[str, Any]) -> list[dict[str, Any]]:
    """Every candidate of the selection ``answer``, best first: the answer's own, then
    ``GET /selections/{id}/candidates?format=jsonl`` from its ``next_cursor`` on."""
    candidates = list(answer["candidates"])
    if answer["next_cursor"] is not None:
        response = client.get(
            f"/api/v1/selections/{answer['id']}/candidates",
            params={"cursor": answer["next_cursor"], "format": "jsonl"},
        )
        assert response.status_code == 200, response.text
        candidates += [json.loads(line) for line in response.text.splitlines()]
    assert len(candidates) == answer["total_candidates"]
    return candidates
