"""What loading catalogue or price files changed: rows inserted, updated, unchanged, retired.

Plain counts, filled in by the loaders (``db/changes.py`` writes the rows and
counts them) and shown by the API's import answers.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from actuator_selection.catalogue.files import CATALOGUE_SPECS


@dataclass(slots=True)
class FileChanges:
    """What loading one file did (or, in a dry run, would do) to the stored rows.

    ``retired``: rows withdrawn: actuators and controllers are retired (soft
    delete, kept for the records that name them), other rows are removed.
    """

    inserted: int = 0
    updated: int = 0
    unchanged: int = 0
    retired: int = 0

    def count(self, *, is_new: bool, changed: bool, n: int = 1) -> None:
        """Count ``n`` rows as inserted, updated or unchanged."""
        if is_new:
            self.inserted += n
        elif changed:
            self.updated += n
        else:
            self.unchanged += n

    @property
    def changed(self) -> bool:
        """True when anything was inserted, updated or retired."""
        return bool(self.inserted or self.updated or self.retired)


@dataclass(slots=True)
class CatalogueChanges:
    """What a catalogue load changed, per file."""

    files: dict[str, FileChanges] = field(
        default_factory=lambda: {spec.file: FileChanges() for spec in CATALOGUE_SPECS}
    )

    @property
    def changed(self) -> bool:
        """True when anything was inserted, updated or retired."""
        return any(c.changed for c in self.files.values())
