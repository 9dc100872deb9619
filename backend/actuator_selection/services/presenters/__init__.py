"""Presenters: the engine's results turned into the API's answers, one module per answer.

Each answer has one presenter and one contract, the pydantic response model that
documents it in OpenAPI (and so the page's generated types, ``types/api.d.ts``):

============================  ==========================  ===========================
answer                        presenter                   contract
============================  ==========================  ===========================
POST /selections, GET …/{id}  :mod:`.selection`           ``SelectionOut``
GET …/candidates/{model}      :mod:`.detail`              ``CandidateDetailOut``
POST /selections/batch        :mod:`.batch`               ``BatchResultOut``
POST /selections/limits, …    :mod:`.limits`              ``LimitsOut``
POST, PUT, GET /projects/…    :mod:`.project`             ``ProjectOut``
============================  ==========================  ===========================

The selection and batch presenters build plain JSON data rather than model instances
(~1,000 model instances per selection cost more than the engineering);
``tests/api/test_presenters.py`` validates each presenter's output against its model
with the engine's real results (the chapter's worked example, the whole catalogue) and
requires the model to write back the same JSON. Stored selections are this presenter's
output at :data:`~.selection.ANSWER_VERSION`; older ones were upgraded once by a
migration (``migrations/versions/*_0010_selection_answer_version.py``).
"""
