"""All tables; importing this package registers every model on ``Base.metadata``."""

from actuator_selection.db.models.base import Base
from actuator_selection.db.models.catalogue import (
    ActuatorFamilyRow,
    ActuatorRow,
    CatalogueStateRow,
    ZonePointRow,
)
from actuator_selection.db.models.controllers import (
    ActuatorInterfaceRow,
    ControllerRow,
    DcBusClassRow,
    SensorFittingRow,
    SensorPointRow,
)
from actuator_selection.db.models.jobs import BatchJobChunkRow, BatchJobResultRow, BatchJobRow
from actuator_selection.db.models.profiles import ProfileRow
from actuator_selection.db.models.projects import ProjectRow
from actuator_selection.db.models.sales import (
    ApiKeyRow,
    PriceListRow,
    PriceRow,
    QuoteCounterRow,
    QuoteItemRow,
    QuoteRow,
)
from actuator_selection.db.models.selections import SelectionRow

__all__ = [
    "ActuatorFamilyRow",
    "ActuatorInterfaceRow",
    "ActuatorRow",
    "ApiKeyRow",
    "Base",
    "BatchJobChunkRow",
    "BatchJobResultRow",
    "BatchJobRow",
    "CatalogueStateRow",
    "ControllerRow",
    "DcBusClassRow",
    "PriceListRow",
    "PriceRow",
    "ProfileRow",
    "ProjectRow",
    "QuoteCounterRow",
    "QuoteItemRow",
    "QuoteRow",
    "SelectionRow",
    "SensorFittingRow",
    "SensorPointRow",
    "ZonePointRow",
]
