"""The quirk-switch base: a listing's bugs, one named switch each.

Every thesis's switch set subclasses ``QuirkSwitches`` (``ali1977.quirks.Quirks``,
``rahman1996.quirks.CsspQuirks``, ``rahman1991.quirks.GscQuirks``): all on (``.all(True)``)
reproduces the legacy FORTRAN, all off computes what the thesis meant.  Each field names
its entry in ``harness/deviations.toml``.
"""
from __future__ import annotations

from dataclasses import dataclass, fields, replace


@dataclass(frozen=True)
class QuirkSwitches:
    """A frozen set of named boolean switches, one per bug of a listing."""

    @classmethod
    def names(cls) -> list[str]:
        return [f.name for f in fields(cls)]

    @classmethod
    def all(cls, value: bool):
        """Every switch on (the listing as printed) or off (corrected)."""
        return cls(**{name: value for name in cls.names()})

    def only(self, name: str, value: bool):
        """A copy with one quirk switched."""
        if name not in self.names():
            raise ValueError(f"unknown quirk {name!r}; known: {', '.join(self.names())}")
        return replace(self, **{name: value})

    def __and__(self, other):
        """The quirks on in both: a listing's own bugs, restricted to those switched on."""
        return type(self)(**{n: getattr(self, n) and getattr(other, n) for n in self.names()})

    def without(self, *names: str):
        """A copy with the named quirks off (a listing that does not have those bugs)."""
        for name in names:
            self = self.only(name, False)
        return self
