"""A Scene: one published table, the inputs the engines run with, and how each engine
produces the table in the published table's columns."""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable

import pandas as pd

from ..port import CORRECTED, PRINTED


@dataclass(frozen=True)
class Scene:
    name: str
    title: str
    table: str                                   # harness/published/<table>.csv
    columns: list[str]
    key: str | tuple[str, ...]                   # the column(s) naming a row
    inputs: str                                  # what the engines are run with, in words
    printed: Callable[[], pd.DataFrame]
    legacy: Callable[[], pd.DataFrame]
    port: Callable[[Any], pd.DataFrame]          # quirks restricted to each listing's own (&)
    notes: list[str] = field(default_factory=list)
    quirks: tuple = (PRINTED, CORRECTED)         # the port's (printed, corrected) switch sets
    rel_floor: float = 0.0                       # below it a non-matching cell is machine arithmetic ...
    floor_id: str | None = None                  # ... as this register entry shows (measured)

    @property
    def keys(self) -> tuple[str, ...]:
        return (self.key,) if isinstance(self.key, str) else tuple(self.key)

    @property
    def key_name(self) -> str:
        return "/".join(self.keys)

    @property
    def values(self) -> list[str]:
        """The numeric columns (every column but the key)."""
        return [c for c in self.columns if c not in self.keys]

    def run(self, engine: str) -> pd.DataFrame:
        if engine == "printed":
            return self.printed()
        if engine == "legacy":
            return self.legacy()
        if engine == "port_printed":          # each program with its own listing's quirks
            return self.port(self.quirks[0])
        if engine == "port_corrected":
            return self.port(self.quirks[1])
        raise ValueError(f"unknown engine {engine!r}")


