"""Fields of the core's frozen dataclasses that may be computed when first read.

The engine (:mod:`actuator_selection.sizing.engine`) details thousands of
candidates per request, and most of that work is building the checks and writing their
words, which an answer without the checks never shows. A field made deferrable here
holds either its value or a :class:`Deferred` that computes it; reading the field
computes it once and keeps it. The class stays a frozen dataclass to everything else:
its fields, ``==``, ``hash``, ``repr`` and pickling read the computed value.

>>> from dataclasses import dataclass
>>> @dataclass(frozen=True, slots=True)
... class Box:
...     content: str
>>> class Later(Deferred):
...     def resolve(self) -> str:
...         return "computed"
>>> _ = defer_field(Box, "content")
>>> Box(Later()) == Box("computed")
True
"""

from __future__ import annotations

from typing import Any


class Deferred:
    """A field's value, not computed yet."""

    __slots__ = ()

    def resolve(self) -> Any:
        """The value."""
        raise NotImplementedError


def defer_field(cls: type, name: str) -> Any:
    """Let the field ``name`` of the slots dataclass ``cls`` hold a :class:`Deferred`,
    resolved when first read; returns the field's slot (to read what it holds as is)."""
    slot: Any = vars(cls)[name]

    def read(obj: Any) -> Any:
        value = slot.__get__(obj, cls)
        if isinstance(value, Deferred):
            value = value.resolve()
            slot.__set__(obj, value)
        return value

    # The dataclass's __init__ and a frozen instance's own writes go through the setter;
    # a frozen dataclass's __setattr__ still refuses every other write.
    setattr(cls, name, property(read, slot.__set__))
    return slot
