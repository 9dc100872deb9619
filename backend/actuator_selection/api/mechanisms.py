"""The kinds of load a selection takes and their fields (``schemas/mechanism_spec.py``)."""

from __future__ import annotations

from functools import cache

from fastapi import APIRouter

from actuator_selection.schemas.mechanism_spec import MechanismsOut, mechanism_spec

router = APIRouter(tags=["selections"])


@cache
def _spec() -> MechanismsOut:
    return mechanism_spec()


@router.get("/mechanisms")
def list_mechanisms() -> MechanismsOut:
    """Every kind of `load` with its fields: name, symbol, unit, bounds, default, whether
    text with a unit is accepted, and the message keys of its words. The page builds its
    load form from this (as the module generated from it)."""
    return _spec()
