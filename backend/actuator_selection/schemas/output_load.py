"""The optional external load on the output flange (output bearing checks) and the drive
option, as a selection request and its answer carry them."""

from __future__ import annotations

from typing import Any

from pydantic import Field

from actuator_selection.phrases.check_messages import Phrase, phrase
from actuator_selection.schemas.common import StrictModel
from actuator_selection.sizing.bearing import NORMAL_LOAD_FACTOR, NORMAL_STATIC_SAFETY, OutputLoad

MAX_FORCE_N = 1e7
"""Larger than any output bearing of the catalogue carries (C_0 ≤ 171 kN)."""
MAX_LEVER_M = 100.0
MAX_LIFE_H = 1e7


class OutputLoadIn(StrictModel):
    """An external load on the output flange (FHA-C manual ch. 2, Fig. 1; CHA §4.3)."""

    radial_force_n: float = Field(ge=0, le=MAX_FORCE_N, description="F_r [N]")
    axial_force_n: float = Field(ge=0, le=MAX_FORCE_N, description="F_a [N]")
    radial_lever_m: float = Field(
        ge=0,
        le=MAX_LEVER_M,
        description="L_r [m]: where F_r acts, measured from the output flange (the bearing's "
        "offset R is added to reach its centre plane)",
    )
    axial_lever_m: float = Field(
        ge=0, le=MAX_LEVER_M, description="L_a [m]: the distance of F_a from the axis"
    )
    load_factor: float = Field(
        default=NORMAL_LOAD_FACTOR,
        ge=1,
        le=3,
        description="f_w of the bearing life: 1–1.2 smooth, 1.2–1.5 normal, 1.5–3 with shock "
        "or vibration (FHA-C manual formula (7)); default the upper end of normal",
    )
    static_safety_min: float = Field(
        default=NORMAL_STATIC_SAFETY,
        ge=1,
        le=10,
        description="the least static safety factor f_s: 1.5 normal, 2 with shock or "
        "vibration, 3 for precise positioning (FHA-C manual formula (10))",
    )
    required_life_h: float | None = Field(
        default=None,
        gt=0,
        le=MAX_LIFE_H,
        description="the output bearing's L_10 life the application needs [h]; omitted: "
        "the life is not checked",
    )

    def to_core(self) -> OutputLoad:
        """The output load as the core sees it."""
        return OutputLoad(
            radial_force_n=self.radial_force_n,
            axial_force_n=self.axial_force_n,
            radial_lever_m=self.radial_lever_m,
            axial_lever_m=self.axial_lever_m,
            load_factor=self.load_factor,
            static_safety_min=self.static_safety_min,
            required_life_h=self.required_life_h,
        )


OUTPUT_LOAD_FIELD: Any = Field(
    default=None,
    description="an external load on the output flange: checks the output bearing's "
    "tilting moment, static safety and (with required_life_h) L_10 life; omitted: the "
    "output bearing is not checked",
)
DRIVE_FIELD: Any = Field(
    default=False,
    description="size the drive's current too: peak motor current against I_max (Eq. 522.2, "
    "522.3) with the energy braking returns; the output voltage with the inductive drop "
    "against the best controller listed for the actuator (Eq. 521.2, Table 521.1) is "
    "checked with or without it",
)


def output_load_core(value: OutputLoadIn | None) -> OutputLoad | None:
    """The request's output load for the core, or None."""
    return None if value is None else value.to_core()


def output_bearing_note(value: OutputLoadIn | None) -> Phrase:
    """What the answer says about the output bearing: English text with its code
    (``output_bearing.not_checked``, ``.no_life``, ``.checked``), which a page words in
    its own language."""
    if value is None:
        return phrase("output_bearing.not_checked")
    if value.required_life_h is None:
        return phrase("output_bearing.no_life")
    return phrase("output_bearing.checked")
