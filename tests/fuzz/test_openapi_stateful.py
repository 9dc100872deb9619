"""A longer, stateful fuzz run: sequences of calls that follow the schema's links (``make fuzz``).

Not part of ``make test``: it is skipped unless ``FUZZ_STATEFUL=1`` (the ``fuzz`` target
sets it). Schemathesis infers links between operations from the OpenAPI document (a
created actuator's ``model`` goes into ``GET/PUT/DELETE /actuators/{model}``, a stored
selection's ``id`` into its candidates, reports and a quote, a quote's ``number`` into
its status and documents) and walks chains of them, so that requests reach state a
single request cannot: a quote of a retired actuator, a zone of a new one, a report of a
selection whose catalogue changed. Every answer is checked as in the bounded run
(``test_openapi_fuzz.py``): no 5xx, and a body in the documented schema.

Each scenario runs in the test's rolled-back transaction on SQLite or PostgreSQL, with an
admin key for catalogue management and a sales key for quotes and prices.
``FUZZ_MAX_EXAMPLES`` (default 100) is the number of scenarios, ``FUZZ_MAX_STEPS`` (default
20) the calls in each; ``FUZZ_RANDOM=1`` draws new ones each run.
"""

from __future__ import annotations

import os
from typing import Any, ClassVar

import pytest
from hypothesis import settings
from schemathesis.core.transport import Response
from tests.fuzz.test_openapi_fuzz import CHECKS, FUZZ_SETTINGS, SCHEMA, FuzzApi, FuzzCase, fuzz_api

__all__ = ["fuzz_api"]

pytestmark = pytest.mark.skipif(
    os.environ.get("FUZZ_STATEFUL") != "1", reason="a long run: `make fuzz` (FUZZ_STATEFUL=1)"
)

MAX_EXAMPLES = int(os.environ.get("FUZZ_MAX_EXAMPLES", "100"))
MAX_STEPS = int(os.environ.get("FUZZ_MAX_STEPS", "20"))
SALES_TAGS = frozenset({"quotes"})
"""Operations called with the sales key; every other one with the admin key."""


class Workflow(SCHEMA.as_state_machine()):  # type: ignore[misc]
    """The schema's state machine, calling the app in-process with a key per operation."""

    api: ClassVar[FuzzApi]

    def call(self, case: FuzzCase, **kwargs: Any) -> Response:
        kwargs = case.as_transport_kwargs(base_url="http://testserver")
        assert not kwargs.pop("cookies", None)
        if "data" in kwargs:
            kwargs["content"] = kwargs.pop("data")
        tags = set(case.operation.tags or ())
        role = "sales" if tags & SALES_TAGS else "admin"
        kwargs["headers"] = {**kwargs.get("headers", {}), "Authorization": self.api.bearer(role)}
        return Response.from_any(self.api.client.request(**kwargs))

    def validate_response(self, response: Response, case: FuzzCase, **kwargs: Any) -> None:
        case.validate_response(response, checks=CHECKS, recorder=self.recorder)


def test_stateful(fuzz_api: FuzzApi) -> None:
    """Chains of linked calls on the seeded catalogue: no 5xx, answers as documented."""
    Workflow.api = fuzz_api
    Workflow.TestCase.settings = settings(
        FUZZ_SETTINGS, max_examples=MAX_EXAMPLES, stateful_step_count=MAX_STEPS
    )
    Workflow.TestCase().runTest()
