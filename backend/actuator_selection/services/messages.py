"""The rules the use cases enforce: a stable code for each, and its English template.

An error a use case raises (:mod:`services.errors`) names its rule by code and the values
the rule's message names as params; the API renders the template in the request's
language from the gettext catalogs under ``locale/`` (``i18n/localize.py``), where the
templates are the msgids, and answers the code and params beside the text. Words among
the params (the kind of price) are :class:`~actuator_selection.phrases.messages.Text`, so
they are translated too. Codes are part of the API contract: add new ones, never rename
or reuse one.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Final

from actuator_selection.phrases.messages import N_, Text

USE_CASE_MESSAGES: Final[Mapping[str, str]] = {
    # Batches (services/batch.py)
    "too_many_candidates": N_(
        "cases × top must be ≤ {max}, got {cases} × {top}: ask for fewer candidates or send "
        "fewer cases"
    ),
    "too_many_with_controllers": N_(
        "with controllers, cases × top must be ≤ {max}, got {cases} × {top}: each candidate "
        "then lists every controller not excluded; leave include_controllers false or send "
        "fewer cases"
    ),
    "too_many_to_store": N_(
        "store: true takes at most {max} cases per request, got {cases}: send the rest in "
        "further requests"
    ),
    "length_mismatch": N_(
        "needs one value per load case: {cases}, as many as speed_rpm has, got {length}"
    ),
    # Batch jobs (services/jobs.py)
    "job_without_cases": N_("a batch job needs at least one load case, one JSON object a line"),
    "unknown_job": N_("no batch job '{job_id}'"),
    "job_finished": N_("the job is {state} already: only a queued or running job can be cancelled"),
    "job_not_done": N_("the job is {state}: its results can be read once it is done"),
    # The catalogue (services/catalogue_admin.py) and what names it
    "unknown_actuator": N_("unknown actuator model '{model}'"),
    "unknown_controller_row": N_("no controller in row {row}"),
    "path_mismatch": N_("must be '{value}', as in the path"),
    "actuator_retired": N_(
        "actuator '{model}' is retired; PUT /actuators/{model} brings it back first"
    ),
    "actuator_exists": N_(
        "actuator '{model}' exists (retired ones too); PUT /actuators/{model} replaces it"
    ),
    "controller_exists": N_(
        "controller row {row} exists (retired ones too); PUT /controllers/{row} replaces it"
    ),
    # Paged lists (api/actuators.py, services/selections.py)
    "invalid_cursor": N_(
        "not a cursor this list answered (next_cursor): ask for the first page without one"
    ),
    # Stored selections (documents/reports.py, services/quotes.py)
    "unknown_selection": N_("no stored selection '{selection_id}'"),
    "unknown_project": N_("no stored machine project '{project_id}'"),
    "project_axes": N_("the project has {axes} axes: give one entry for each, in its order"),
    # Quotes (services/quotes.py)
    "unknown_price_list": N_("no price list '{name}'"),
    "unknown_quote": N_("no quote '{number}'"),
    "idempotency_key_reused": N_(
        "this key was used for quote {number} with a different request body; use a new key "
        "for a new quote"
    ),
    "valid_until_past": N_("must be today ({today}) or later"),
    # Motion profiles (services/profile_csv.py, services/profiles.py)
    "profile_too_large": N_("line {line}: the file is larger than {max} bytes"),
    "profile_binary": N_("line {line}: is not text (UTF-8, no control characters)"),
    "profile_line_too_long": N_("line {line}: is longer than {max} characters"),
    "profile_empty": N_("line {line}: the file holds no heading line"),
    "profile_too_many_columns": N_("line {line}: has more than {max} columns"),
    "profile_column_twice": N_("line {line}, column {column}: '{heading}' names a column twice"),
    "profile_no_time_column": N_("line {line}: no time column (a heading such as 'Time [s]')"),
    "profile_no_motion_column": N_(
        "line {line}: no position or velocity column (a heading such as "
        "'AngularVelocity [rad/s]' or 'Position [mm]')"
    ),
    "profile_unit_missing": N_(
        "line {line}, column {column}: '{heading}' gives no unit; write it in the heading "
        "('{heading} [unit]') or choose it on upload"
    ),
    "profile_unit_wrong": N_(
        "line {line}, column {column}: '{unit}' of '{heading}' is no unit of {expected}"
    ),
    "profile_unit_kinds": N_(
        "line {line}, column {column}: '{unit}' of '{heading}' belongs to the other kind of "
        "axis (rotary: angles, rpm, Nm; linear: mm, mm/s, N)"
    ),
    "profile_too_many_samples": N_("line {line}: more than {max} rows of samples"),
    "profile_too_slow": N_("line {line}: reading took longer than {seconds} s"),
    "profile_cells": N_(
        "line {line}, column {column}: {count} cells where the heading has {width}"
    ),
    "profile_not_a_number": N_("line {line}, column {column}: '{text}' is not a number"),
    "profile_not_finite": N_("line {line}, column {column}: '{text}' is not a finite number"),
    "profile_time_not_increasing": N_(
        "line {line}, column {column}: the time {time} s does not follow the line before "
        "it: times must increase"
    ),
    "profile_too_few_samples": N_("line {line}: {count} rows of samples; a cycle needs {min}"),
    "profile_speed_overflow": N_("the positions imply speeds beyond any number"),
    "profile_out_of_bounds": N_("the profile's segments break a rule at {where}: {rule}"),
    "profile_above_every_n_max": N_(
        "the profile reaches {peak_rpm} rpm; no actuator of the catalogue runs faster "
        "than {max_rpm} rpm (n_max)"
    ),
    "unknown_profile": N_("no stored profile '{id}'"),
    "profile_kind": N_("a {kind} profile does not fit a load of type '{load}'"),
    # IDTA 02021 records (services/aas_import.py)
    "aas_unreadable": N_("is neither an AASX package nor AAS JSON that can be read: {reason}"),
    "aas_no_sizing_submodel": N_("holds no IDTA 02021 sizing submodel (semanticId {semantic_id})"),
    "aas_too_large": N_("unpacks to {size} bytes; an AASX may hold at most {max}"),
    "aas_missing_element": N_("the sizing record lacks {path}"),
    "aas_not_a_number": N_("{path} of the sizing record is not a finite number"),
    "aas_motion_file": N_("the motion file {path} cannot be read: {reason}"),
    "not_a_candidate": N_(
        "'{model}' is not a candidate of selection {selection_id}; its usable candidates "
        "include {models}"
    ),
    "no_usable_candidate": N_(
        "'{model}' is not a candidate of selection {selection_id}, which has no usable candidate"
    ),
    "unsuitable": N_("{model} is unsuitable for this load case and cannot be quoted: {reasons}"),
    "retired_not_quoted": N_(
        "{model} has been retired from the catalogue and can no longer be quoted"
    ),
    "no_price": N_("the price list '{price_list}' has no {kind} price for '{item}' valid on {day}"),
    "currency_mismatch": N_(
        "{item} is priced in {currencies}, not in {currency} (one currency per quote)"
    ),
    "currency_required": N_("{item} is priced in {currencies}: choose one"),
    "unknown_controller": N_(
        "Table 521.1 (and the catalogue) has no active controller in row {row}"
    ),
    "controller_not_compatible": N_(
        "{controller} (row {row}) is not a controller Table 521.1 matches for {model}: "
        "{reasons}. Rule: {rule}; rows listed for {model}: {rows}"
    ),
    "controller_not_listed": N_(
        "{controller} (row {row}) is not a controller Table 521.1 matches for {model}. "
        "Rule: {rule}; rows listed for {model}: {rows}"
    ),
}
"""Code → English template of every rule a use case raises."""

PRICE_KINDS: Final[Mapping[str, Text]] = {
    "actuator": N_("actuator"),
    "controller": N_("controller"),
}
"""The kinds of priced item, in words (the ``kind`` of ``no_price``)."""

CONTROLLER_RULE: Final = N_(
    "the controller must be one the selection lists for the actuator (family, DC bus "
    "class, temperature sensor and feedback not excluded)"
)
"""The rule a quoted controller follows (Table 521.1), in words."""

PROJECT_CONTROLLER_RULE: Final = N_(
    "the controller of an axis must be one Table 521.1 does not exclude for its actuator "
    "(family, temperature sensor and feedback) and marks for the project's DC bus class"
)
"""The rule a project's axis controller follows (Table 521.1), in words."""
