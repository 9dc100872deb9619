"""The engine: the selection flowchart as arrays of load cases × actuators, one engine
for one actuator and for 64,000.

- :mod:`~actuator_selection.sizing.engine.catalogue`: the catalogue as columns, each value
  by its operand's name (:data:`CATALOGUE_OPERANDS`, built in one function);
- :mod:`~actuator_selection.sizing.engine.cases`: the load cases as rows;
- :mod:`~actuator_selection.sizing.engine.block`: one block of cells: torques, heating,
  the operands (built by name in one place);
- :mod:`~actuator_selection.sizing.engine.codes`: the rules' status codes for a block,
  every rule at once;
- :mod:`~actuator_selection.sizing.engine.evaluation`: blocks into the whole evaluation, the
  ranking, and the views: :func:`select` (1 × N), :func:`evaluate` (1 × 1);
- :mod:`~actuator_selection.sizing.engine.detail`: a candidate's checks in words, from the
  arrays' decisions;
- :mod:`~actuator_selection.sizing.engine.columns`: the columns input format.
"""

from __future__ import annotations

from actuator_selection.sizing.engine.arrays import (
    STATUS_BY_CODE,
    VERDICT_BY_CODE,
    BoolArray,
    CodeArray,
    FloatArray,
    IndexArray,
)
from actuator_selection.sizing.engine.block import CHECK_NAMES
from actuator_selection.sizing.engine.catalogue import (
    CATALOGUE_OPERANDS,
    CatalogueArrays,
    catalogue_arrays,
)
from actuator_selection.sizing.engine.codes import ARRAY_OPS
from actuator_selection.sizing.engine.columns import (
    CheckTable,
    RankedTable,
    TrapezoidColumns,
    rank_columns,
)
from actuator_selection.sizing.engine.evaluation import (
    BatchEvaluation,
    RankedCells,
    case_verdicts,
    evaluate,
    evaluate_batch,
    evaluate_cases,
    evaluate_each,
    rank_batch,
    ranked_cells,
    select,
    select_batch,
)

__all__ = [
    "ARRAY_OPS",
    "CATALOGUE_OPERANDS",
    "CHECK_NAMES",
    "STATUS_BY_CODE",
    "VERDICT_BY_CODE",
    "BatchEvaluation",
    "BoolArray",
    "CatalogueArrays",
    "CheckTable",
    "CodeArray",
    "FloatArray",
    "IndexArray",
    "RankedCells",
    "RankedTable",
    "TrapezoidColumns",
    "case_verdicts",
    "catalogue_arrays",
    "evaluate",
    "evaluate_batch",
    "evaluate_cases",
    "evaluate_each",
    "rank_batch",
    "rank_columns",
    "ranked_cells",
    "select",
    "select_batch",
]
